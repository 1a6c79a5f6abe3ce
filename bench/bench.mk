# bench/bench.mk - the speed-for-accuracy benchmark (included by the top-level
# Makefile).  `make bench` measures every contender against the exact referee,
# times them, counts instructions with callgrind and writes bench/RESULTS.md
# and bench/pareto.png; `make test-bench` (part of `make test`) is the smoke run.
#
# The library is linked as $(STATIC), built with the flags a user gets
# (CFLAGS ?= -O2 plus REQ_CFLAGS), so the figures are the ones users see.

BENCH_DEPS := libgmp-dev libmpfr-dev gnuplot-nox libbox2d-dev valgrind g++
BENCH_TEST_DEPS := libgmp-dev libmpfr-dev libbox2d-dev g++
BENCH_DIR := $(B)/bench
BENCH_BIN := $(BENCH_DIR)/bench
BENCH_C := bench/bench.c bench/accuracy.c bench/contenders.c bench/timing.c bench/smoke.c \
  bench/approaches.c referee/referee.c referee/cases.c $(HARNESS_SRC)
BENCH_HDR := $(wildcard bench/*.h referee/*.h) $(HARNESS_HDR) $(LIB_HDR)
BENCH_OBJ := $(patsubst %.c,$(BENCH_DIR)/obj/%.o,$(BENCH_C)) $(BENCH_DIR)/obj/bench/box2d_contender.o
BENCH_CG := $(BENCH_DIR)/callgrind
BENCH_OUT := bench/RESULTS.md
BENCH_PNG := bench/pareto.png

.PHONY: check-deps-bench check-deps-test-bench test-bench

check-deps-bench:
	@sh scripts/deps.sh $(BENCH_DEPS)

check-deps-test-bench:
	@sh scripts/deps.sh $(BENCH_TEST_DEPS)

# Referee and generators come from referee/, the batch storage and checks
# and the pass/fail line from tests/harness/ (shared with the unit tests).
$(BENCH_DIR)/obj/%.o: %.c $(BENCH_HDR)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Wno-conversion -Ireferee -Itests/harness -Ibench -c $< -o $@

$(BENCH_DIR)/obj/bench/box2d_contender.o: bench/box2d_contender.cpp bench/box2d_contender.h $(LIB_HDR)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -std=c++17 -Wall -Wextra -ffp-contract=off $(SAN_FLAGS) -Iinclude -c $< -o $@

$(BENCH_BIN): $(BENCH_OBJ) $(STATIC)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $(BENCH_OBJ) $(STATIC) -lbox2d -lmpfr -lgmp -lm

# Instruction counts: the driver brackets each contender's pass with
# callgrind client requests (zero, dump); one dump file per contender.
bench: check-deps-bench
	@$(MAKE) --no-print-directory $(BENCH_BIN)
	@rm -rf $(BENCH_CG) && mkdir -p $(BENCH_CG)
	valgrind --tool=callgrind --callgrind-out-file=$(BENCH_CG)/cg.out $(BENCH_BIN) --callgrind \
	  2> $(BENCH_CG)/valgrind.log
	@for f in $(BENCH_CG)/cg.out.*; do \
	  awk '/^desc: Trigger: Client Request:/ {n = $$NF} /^(totals|summary):/ {t = $$2} END {print n, t}' $$f; \
	done > $(BENCH_DIR)/ir.txt
	$(BENCH_BIN) --results $(BENCH_OUT) --plot-data $(BENCH_DIR)/pareto.dat --ir $(BENCH_DIR)/ir.txt \
	  --flags "$(CFLAGS) $(REQ_CFLAGS)"
	gnuplot -e "datafile='$(BENCH_DIR)/pareto.dat'; outfile='$(BENCH_PNG)'" bench/pareto.gp
	@echo "bench: wrote $(BENCH_OUT) and $(BENCH_PNG)"

test-bench: check-deps-test-bench
	@$(MAKE) --no-print-directory $(BENCH_BIN)
	$(BENCH_BIN) --smoke

TEST_TARGETS += test-bench

# ---------------------------------------------------------- energy bias
# Is the energy error of e = 1 impacts a bias?  10^8 random impacts (about a
# minute): mean dE/E and its standard error, overall and with |n|^2 near a
# power of two.  Reported in bench/RESULTS.md and the README; not part of
# `make test` (it measures, it does not judge).
.PHONY: bench-energy
$(BENCH_DIR)/energy_bias: bench/energy_bias.c referee/rng.h $(STATIC)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Ireferee -o $@ $< $(STATIC) -lm

bench-energy: $(BENCH_DIR)/energy_bias
	$(BENCH_DIR)/energy_bias 100000000
