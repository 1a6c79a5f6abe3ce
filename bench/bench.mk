# SPDX-License-Identifier: MIT
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
  bench/approaches.c bench/ratio.c bench/rough.c bench/toi.c bench/quartic.c bench/toi_accel.c referee/referee.c referee/cases.c referee/ref_rough.c referee/cases_rough.c \
  referee/ref_toi_accel.c referee/cases_toi_accel.c \
  $(HARNESS_SRC)
# The library before the speed work (bench/old.h names the commit), for the
# before/after table: its own object, global symbols renamed old_*.
BENCH_OLD_REV := $(shell sed -n 's/^\#define BENCH_OLD_REV "\(.*\)"/\1/p' bench/old.h)
BENCH_OLD_DIR := $(BENCH_DIR)/old
BENCH_OLD_OBJ := $(BENCH_OLD_DIR)/old_lib.o
BENCH_OBJ := $(patsubst %.c,$(BENCH_DIR)/obj/%.o,$(BENCH_C)) $(BENCH_DIR)/obj/bench/box2d_contender.o $(BENCH_OLD_OBJ)
# Code size per call site of the C2D_INLINE front ends.
BENCH_SITES := $(BENCH_DIR)/callsite.txt
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
# Header dependencies: the .d files (DEPFLAGS), included at the end.
$(BENCH_DIR)/obj/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DEPFLAGS) -Wno-conversion -Ireferee -Itests/harness -Ibench -c $< -o $@

$(BENCH_DIR)/obj/bench/box2d_contender.o: bench/box2d_contender.cpp
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) $(DEPFLAGS) -std=c++17 -Wall -Wextra -ffp-contract=off $(SAN_FLAGS) -Iinclude -c $< -o $@

# `git archive` of lib/ and include/ at BENCH_OLD_REV, compiled with the
# library's flags (that commit has no run-time dispatch; C2D_NO_DISPATCH
# for good measure) and every global symbol it defines renamed old_*.
# Without git history bench/old_missing.c stands in (old_c2d_version() == 0)
# and the report leaves the before/after table out.
$(BENCH_OLD_OBJ): bench/old_missing.c bench/old.h
	@rm -rf $(BENCH_OLD_DIR) && mkdir -p $(BENCH_OLD_DIR)/src
	@if git archive --format=tar $(BENCH_OLD_REV) lib include 2>/dev/null | tar -x -C $(BENCH_OLD_DIR)/src 2>/dev/null && \
	    [ -f $(BENCH_OLD_DIR)/src/lib/collide2d.c ]; then \
	  echo "bench: the library as of $(BENCH_OLD_REV) (git archive), symbols renamed old_*"; \
	  echo "$(CC) $(CFLAGS) -std=c99 $(WARN) -ffp-contract=off -fno-math-errno -DC2D_NO_DISPATCH -c $(BENCH_OLD_DIR)/src/lib/collide2d.c"; \
	  $(CC) $(CFLAGS) -std=c99 $(WARN) -ffp-contract=off -fno-math-errno $(SAN_FLAGS) -DC2D_NO_DISPATCH \
	    -c $(BENCH_OLD_DIR)/src/lib/collide2d.c -o $(BENCH_OLD_DIR)/raw.o; \
	else \
	  echo "bench: no git history for $(BENCH_OLD_REV): the before/after table is left out"; \
	  $(CC) $(ALL_CFLAGS) -c bench/old_missing.c -o $(BENCH_OLD_DIR)/raw.o; \
	fi
	nm -g --defined-only $(BENCH_OLD_DIR)/raw.o | awk 'NF == 3 {print $$3, "old_" $$3}' > $(BENCH_OLD_DIR)/syms
	objcopy --redefine-syms=$(BENCH_OLD_DIR)/syms $(BENCH_OLD_DIR)/raw.o $@

# One call per function (bench/callsite.c), sizes from the object.
$(BENCH_SITES): bench/callsite.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DEPFLAGS) -MT $@ -c $< -o $(BENCH_DIR)/callsite.o
	nm -S --defined-only $(BENCH_DIR)/callsite.o > $@

$(BENCH_BIN): $(BENCH_OBJ) $(STATIC)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $(BENCH_OBJ) $(STATIC) -lbox2d -lmpfr -lgmp -lm

# Instruction counts: the driver brackets each contender's pass with
# callgrind client requests (zero, dump); one dump file per contender.
bench: check-deps-bench
	@$(MAKE) --no-print-directory $(BENCH_BIN) $(BENCH_SITES)
	@rm -rf $(BENCH_CG) && mkdir -p $(BENCH_CG)
	valgrind --tool=callgrind --callgrind-out-file=$(BENCH_CG)/cg.out $(BENCH_BIN) --callgrind \
	  2> $(BENCH_CG)/valgrind.log
	@for f in $(BENCH_CG)/cg.out.*; do \
	  awk '/^desc: Trigger: Client Request:/ {n = $$NF} /^(totals|summary):/ {t = $$2} END {print n, t}' $$f; \
	done > $(BENCH_DIR)/ir.txt
	$(BENCH_BIN) --results $(BENCH_OUT) --plot-data $(BENCH_DIR)/pareto.dat --ir $(BENCH_DIR)/ir.txt \
	  --sizes $(BENCH_SITES) --flags "$(CFLAGS) $(REQ_CFLAGS)"
	gnuplot -e "datafile='$(BENCH_DIR)/pareto.dat'; outfile='$(BENCH_PNG)'" bench/pareto.gp
	@echo "bench: wrote $(BENCH_OUT) and $(BENCH_PNG)"

test-bench: check-deps-test-bench
	@$(MAKE) --no-print-directory $(BENCH_BIN) $(BENCH_DIR)/world
	$(BENCH_BIN) --smoke
	@. tests/harness/tally.sh; c2d_tally_name=bench-world; \
	  c2d_check "a small periodic gas runs" sh -c '$(BENCH_DIR)/world 256 0.5 2 1 >/dev/null'; \
	  c2d_check "a bad argument exits 2" sh -c '$(BENCH_DIR)/world 1x 2>/dev/null; [ $$? -eq 2 ]'; \
	  c2d_summary

# ------------------------------------------------------------------ world
# Collisions per CPU second of the event-driven world (bench/world.c, its
# usage and the figures measured in its opening comment): make bench-world
# runs N = 1,024, 10,000 and 100,489 at eta 0.5 and 0.2 and writes the
# table bench/RESULTS-world.md (bench/world_table.sh).
.PHONY: bench-world
$(BENCH_DIR)/world: bench/world.c $(STATIC)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DEPFLAGS) -Ibench -Ireferee -o $@ $< $(STATIC) -lm

bench-world: $(BENCH_DIR)/world
	@sh bench/world_table.sh $(BENCH_DIR)/world bench/RESULTS-world.md

# Instructions per collision (callgrind, the timed part's own dump) at
# N = 1,024, eta 0.5 and 0.2: make bench-world-ir (needs valgrind).
.PHONY: bench-world-ir
bench-world-ir: $(BENCH_DIR)/world
	@for eta in 0.5 0.2; do \
	  rm -f $(BENCH_DIR)/world.cg.*; \
	  line=$$(valgrind --tool=callgrind --callgrind-out-file=$(BENCH_DIR)/world.cg.%p $(BENCH_DIR)/world 1024 $$eta 20 5 2>/dev/null) || exit 1; \
	  n=$$(echo "$$line" | sed -n 's/.*: \([0-9]*\) collisions.*/\1/p'); \
	  ir=$$(sed -n 's/^summary: //p' $(BENCH_DIR)/world.cg.*.1); \
	  echo "world: N = 1024 eta = $$eta: $$ir instructions over $$n collisions: $$((ir / n)) per collision"; \
	done

TEST_TARGETS += test-bench

# ------------------------------------------------------------------ sphere
# Pool balls as spheres (bench/sphere.c): accuracy of the library and of a
# plain transcription against the MPFR referee, and instructions per call
# of each under callgrind, and of the float variant and the cushion in both
# formats (printed; the figures are quoted in
# bench/RESULTS-sphere.md, the README and docs/API.md).
.PHONY: bench-sphere
BENCH_SPHERE_N := 100000
$(BENCH_DIR)/sphere: bench/sphere.c referee/cases_sphere.c referee/cases.c referee/ref_sphere.c $(STATIC)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DEPFLAGS) -Wno-conversion -Ireferee -o $@ bench/sphere.c referee/cases_sphere.c referee/cases.c referee/ref_sphere.c $(STATIC) -lmpfr -lgmp -lm

bench-sphere: $(BENCH_DIR)/sphere
	$(BENCH_DIR)/sphere accuracy $(BENCH_SPHERE_N)
	@for w in lib:c2d_collide_balls plain:sphere_plain libf:c2d_collide_ballsf cushion:c2d_collide_cushion \
	  cushionf:c2d_collide_cushionf; do f=$${w#*:}; w=$${w%%:*}; \
	  valgrind --tool=callgrind --callgrind-out-file=$(BENCH_DIR)/sphere.$$w.cg --toggle-collect=$$f \
	    $(BENCH_DIR)/sphere $$w $(BENCH_SPHERE_N) >/dev/null 2>&1 || exit 1; \
	  ir=$$(sed -n 's/^summary: //p' $(BENCH_DIR)/sphere.$$w.cg); \
	  echo "$$w: $$ir instructions over $(BENCH_SPHERE_N) calls: $$((ir / $(BENCH_SPHERE_N))) per call"; \
	done


# ---------------------------------------------------------- energy bias
# Is the energy error of e = 1 impacts a bias?  10^8 random impacts (about a
# minute): mean dE/E and its standard error, overall and with |n|^2 near a
# power of two.  Printed only (bench/RESULTS.md does not hold it); the figures
# are quoted in docs/ACCURACY.md ("Energy bias"); not part of `make test` (it
# measures, it does not judge).
.PHONY: bench-energy
$(BENCH_DIR)/energy_bias: bench/energy_bias.c $(STATIC)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DEPFLAGS) -Ireferee -o $@ $< $(STATIC) -lm

bench-energy: $(BENCH_DIR)/energy_bias
	$(BENCH_DIR)/energy_bias 100000000

-include $(BENCH_OBJ:.o=.d) $(BENCH_DIR)/callsite.d $(BENCH_DIR)/energy_bias.d $(BENCH_DIR)/world.d
