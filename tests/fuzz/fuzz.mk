# SPDX-License-Identifier: MIT
# tests/fuzz/fuzz.mk - dynamic hardening runs, included by the top-level
# Makefile: the libFuzzer harness for every public entry point, the
# cross-compiler determinism hash, and the demo under valgrind.
# (Static analysis: tests/build/lint.mk.)
#   make fuzz          fuzz for FUZZ_SECONDS (new inputs: $(B)/fuzz/corpus,
#                      crashes: $(B)/fuzz/crash-*); add a crash to
#                      tests/fuzz/corpus/regress-NAME once the bug is fixed
#   make test-fuzz     the committed corpus under the harness built by $(CC)
#                      (sanitised with SANITIZE=1) and by clang-14 with
#                      libFuzzer + ASan + UBSan, then a bounded smoke run with a
#                      fixed seed (FUZZ_RUNS executions); part of `make test`
#   make fuzz-seeds    rewrite the hand-made seeds (tests/fuzz/make_seeds.c)
# The libFuzzer build is always sanitised: libFuzzer, ASan and UBSan need
# clang, hence clang-14 here whatever CC is.  Both builds link the exact
# referee (referee/, GMP + MPFR) the harness checks statuses and accuracy
# against; under libFuzzer it is sanitised but not coverage-instrumented, so
# the corpus grows on the library's paths and the harness's, not the referee's.

FUZZ_SECONDS ?= 60
# The referee checks cost about a millisecond per execution on average (the
# time of impact under acceleration most): ~800 executions/s on an idle core,
# ~280 on a loaded one, so the smoke run takes ~25 s (60 s at most).
FUZZ_RUNS ?= 20000
FUZZ_DEPS := clang-14 libclang-rt-14-dev libgmp-dev libmpfr-dev
FUZZ_CLANG := clang-14
FUZZ_DIR := $(B)/fuzz
FUZZ_BIN := $(FUZZ_DIR)/fuzz_collide2d
FUZZ_REPLAY := $(FUZZ_DIR)/replay
# The harness: the entry point and report, the decoder, the bounds, one
# translation unit per variant (fuzz_template.h for double and float), and
# the shared test helper (tests/harness/) for the batch arrays and checks.
FUZZ_SRC := $(addprefix tests/fuzz/,fuzz_collide2d.c decode.c bounds.c fuzz_double.c fuzz_float.c fuzz_fixed.c) \
  tests/harness/harness.c
FUZZ_REF_SRC := referee/referee.c referee/ref_rough.c referee/ref_sphere.c referee/ref_toi_accel.c referee/cases_toi_accel.c
FUZZ_CORPUS := tests/fuzz/corpus
FUZZ_INC := -Iinclude -Itests/harness -Itests/fuzz -Ireferee
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_CFLAGS := -g -O2 -std=c99 $(WARN) -ffp-contract=off $(FUZZ_INC) -fsanitize=fuzzer $(FUZZ_SAN)
FUZZ_REF_OBJ := $(patsubst referee/%.c,$(FUZZ_DIR)/ref/%.o,$(FUZZ_REF_SRC))
FUZZ_REPLAY_REF_OBJ := $(patsubst referee/%.c,$(FUZZ_DIR)/replay-ref/%.o,$(FUZZ_REF_SRC))
FUZZ_LIBS := -lmpfr -lgmp -lm

.PHONY: fuzz-deps fuzz test-fuzz fuzz-seeds

fuzz-deps:
	@sh scripts/deps.sh $(FUZZ_DEPS)

# Header dependencies: .d files (DEPFLAGS; MULTI_DEPS for the programs
# compiled from several sources in one command), included at the end.
# c2d_put (the helper's output, for the replay's closing line) goes to stdout.
$(FUZZ_DIR)/ref/%.o: referee/%.c | fuzz-deps
	@mkdir -p $(@D)
	$(FUZZ_CLANG) -g -O2 -std=c99 $(WARN) -Wno-conversion -ffp-contract=off $(FUZZ_INC) $(FUZZ_SAN) $(DEPFLAGS) -c -o $@ $<

$(FUZZ_BIN): $(FUZZ_SRC) $(FUZZ_REF_OBJ) $(LIB_SRC) | fuzz-deps
	@mkdir -p $(@D)
	$(call MULTI_DEPS,$(FUZZ_CLANG) $(FUZZ_CFLAGS),$(FUZZ_SRC) tests/harness/put_stdio.c $(LIB_SRC))
	$(FUZZ_CLANG) $(FUZZ_CFLAGS) -o $@ $(FUZZ_SRC) tests/harness/put_stdio.c $(LIB_SRC) $(FUZZ_REF_OBJ) $(FUZZ_LIBS)

# The referee as the unit tests build it (-Wno-conversion: GMP's types).
$(FUZZ_DIR)/replay-ref/%.o: referee/%.c | fuzz-deps
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Wno-conversion $(FUZZ_INC) $(DEPFLAGS) -c -o $@ $<

$(FUZZ_REPLAY): tests/fuzz/replay.c $(FUZZ_SRC) $(FUZZ_REPLAY_REF_OBJ) $(LIB_SRC)
	@mkdir -p $(@D)
	$(call MULTI_DEPS,$(CC) $(ALL_CFLAGS) $(FUZZ_INC),tests/fuzz/replay.c $(FUZZ_SRC) tests/harness/put_stdio.c $(LIB_SRC))
	$(CC) $(ALL_CFLAGS) $(FUZZ_INC) -o $@ tests/fuzz/replay.c $(FUZZ_SRC) tests/harness/put_stdio.c $(LIB_SRC) \
	  $(FUZZ_REPLAY_REF_OBJ) $(FUZZ_LIBS)

$(FUZZ_DIR)/make_seeds: tests/fuzz/make_seeds.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -std=c99 $(WARN) $(FUZZ_INC) $(DEPFLAGS) -o $@ $<

fuzz-seeds: $(FUZZ_DIR)/make_seeds
	$(FUZZ_DIR)/make_seeds $(FUZZ_CORPUS)

fuzz: $(FUZZ_BIN)
	@mkdir -p $(FUZZ_DIR)/corpus
	$(FUZZ_BIN) -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	  -artifact_prefix=$(FUZZ_DIR)/ $(FUZZ_DIR)/corpus $(FUZZ_CORPUS)

# Counts: one per corpus file under $(CC), the whole corpus under libFuzzer,
# and the smoke run.  The smoke run starts from a scratch copy of the corpus
# so nothing is written into the committed one.
test-fuzz: $(FUZZ_BIN) $(FUZZ_REPLAY)
	@sh tests/fuzz/test_fuzz.sh $(FUZZ_BIN) $(FUZZ_REPLAY) $(FUZZ_CORPUS) $(FUZZ_DIR) $(FUZZ_RUNS)

TEST_TARGETS += test-fuzz

# ------------------------------------------------------------ determinism
# Output bits hashed over 100k generated cases must match across gcc/clang
# -O0/-O2/-O3 (-ffp-contract=off); also reports what FMA contraction changes.
# See docs/DETERMINISM.md.
.PHONY: test-determinism test-valgrind
test-determinism: $(AMALGAMATION)
	@sh scripts/deps.sh gcc clang
	@sh tests/build/determinism.sh $(B)/determinism 100000 $(AMALGAMATION)

TEST_TARGETS += test-determinism

# --------------------------------------------------------------- valgrind
# Short headless demo runs under memcheck: 0 errors, nothing definitely lost.
# Valgrind cannot run ASan binaries, so SANITIZE=1 skips it (ASan covers).
VALGRIND_DEPS := valgrind
ifeq ($(SANITIZE),1)
test-valgrind:
	@echo "valgrind: skipped under SANITIZE=1 (AddressSanitizer runs instead)"
else
test-valgrind: $(B)/billiards
	@sh scripts/deps.sh $(VALGRIND_DEPS)
	@sh tests/build/valgrind.sh $(B)/billiards $(B)/valgrind
endif

TEST_TARGETS += test-valgrind

-include $(FUZZ_REF_OBJ:.o=.d) $(FUZZ_REPLAY_REF_OBJ:.o=.d) $(FUZZ_BIN).d $(FUZZ_REPLAY).d $(FUZZ_DIR)/make_seeds.d
