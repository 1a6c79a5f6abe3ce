# SPDX-License-Identifier: MIT
# collide2d - top-level build.  `make` builds the library; `make test` installs
# what it needs, builds and runs every test; `make demo` runs the billiards break.
#
# Conventions: CC is never assigned (use the environment's), CFLAGS ?= -O2 is
# yours, the flags the library needs are appended.  -ffp-contract=off keeps
# a*b+c from being fused differently per compiler/target, so results are
# reproducible bit for bit (README "Caveats").  -fno-math-errno lets the time
# of impact's square roots be the instruction (no libm call; same results).

CFLAGS ?= -O2
CXXFLAGS ?= -O2
PREFIX ?= /usr/local
LIBDIR ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
MANDIR ?= $(PREFIX)/share/man
DESTDIR ?=

VERSION_MAJOR := $(shell sed -n 's/^\#define C2D_VERSION_MAJOR \([0-9]*\)/\1/p' include/collide2d.h)
VERSION_MINOR := $(shell sed -n 's/^\#define C2D_VERSION_MINOR \([0-9]*\)/\1/p' include/collide2d.h)
VERSION_PATCH := $(shell sed -n 's/^\#define C2D_VERSION_PATCH \([0-9]*\)/\1/p' include/collide2d.h)
VERSION := $(VERSION_MAJOR).$(VERSION_MINOR).$(VERSION_PATCH)

B := build
WARN := -Wall -Wextra -Wconversion -Wshadow -pedantic
REQ_CFLAGS := -std=c99 $(WARN) -ffp-contract=off -fno-math-errno -Iinclude
ALL_CFLAGS = $(CFLAGS) $(REQ_CFLAGS) $(SAN_FLAGS)

# make test SANITIZE=1: everything under ASan + UBSan, no recovery.
ifeq ($(SANITIZE),1)
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
B := build/san
endif

# One translation unit per variant (lib/collide2d.c, double.c, float.c,
# fixed.c) over shared template headers (lib/real/).
LIB_SRC := $(wildcard lib/*.c)
LIB_HDR := include/collide2d.h
LIB_TEMPLATES := $(wildcard lib/*.h lib/real/*.h lib/real/*/*.h)
LIB_DEPS := $(LIB_HDR) $(LIB_TEMPLATES)
LIB_OBJ := $(patsubst lib/%.c,$(B)/obj/%.o,$(LIB_SRC))
LIB_PIC := $(patsubst lib/%.c,$(B)/obj/%.pic.o,$(LIB_SRC))
STATIC := $(B)/libcollide2d.a
SONAME := libcollide2d.so.$(VERSION_MAJOR)
SHARED := $(B)/libcollide2d.so.$(VERSION)
AMALGAMATION := $(B)/collide2d_all.c

FORCE:
.PHONY: all lib amalgamate test test-unit check-deps-test check-vectors check-build vectors install uninstall clean demo play bench cross test-mcu lint fuzz
all: lib
lib: $(STATIC) $(B)/libcollide2d.so $(B)/collide2d.pc

$(B)/obj/%.o: lib/%.c $(LIB_DEPS)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

$(B)/obj/%.pic.o: lib/%.c $(LIB_DEPS)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -fPIC -fvisibility=default -c $< -o $@

$(STATIC): $(LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(SHARED): $(LIB_PIC)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -shared -Wl,-soname,$(SONAME) -o $@ $^ -lm

$(B)/libcollide2d.so: $(SHARED)
	ln -sf libcollide2d.so.$(VERSION) $(B)/$(SONAME)
	ln -sf libcollide2d.so.$(VERSION) $@

# collide2d.pc (from collide2d.pc.in, as CMake writes it) names libdir and
# includedir relative to ${prefix} when they lie under it, so pkg-config
# --define-prefix works on a moved tree.  Regenerated on every make and
# replaced only when it differs: a change of PREFIX, LIBDIR or INCLUDEDIR
# rebuilds it, an unchanged one keeps its time stamp.
pc_dir = $(if $(filter $(PREFIX)/%,$(1)),$${prefix}/$(patsubst $(PREFIX)/%,%,$(1)),$(1))
$(B)/collide2d.pc: collide2d.pc.in FORCE
	@mkdir -p $(@D)
	@sed -e 's|@C2D_PC_PREFIX@|$(PREFIX)|' -e 's|@C2D_PC_LIBDIR@|$(call pc_dir,$(LIBDIR))|' \
	  -e 's|@C2D_PC_INCLUDEDIR@|$(call pc_dir,$(INCLUDEDIR))|' -e 's|@C2D_PC_VERSION@|$(VERSION)|' \
	  -e 's|@C2D_PC_CFLAGS@||' collide2d.pc.in > $@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@ && echo "wrote $@ (prefix $(PREFIX))"; fi

# The whole library as one self-contained source, for firmware trees that
# take one .c file beside the header (scripts/amalgamate.sh).
amalgamate: $(AMALGAMATION)
$(AMALGAMATION): scripts/amalgamate.sh $(LIB_SRC) $(LIB_TEMPLATES)
	@mkdir -p $(@D)
	sh scripts/amalgamate.sh $@

# Directories install creates are listed in build/install-dirs.txt, so
# uninstall removes those (once empty) and no other (scripts/installdirs.sh).
MAN_PAGES := $(wildcard man/*.3)
MAN3 = $(DESTDIR)$(MANDIR)/man3
INSTALL_DIRS = $(DESTDIR)$(LIBDIR)/pkgconfig $(DESTDIR)$(INCLUDEDIR) $(MAN3)
install: lib
	sh scripts/installdirs.sh create build/install-dirs.txt $(INSTALL_DIRS)
	install -m 644 $(LIB_HDR) $(DESTDIR)$(INCLUDEDIR)/collide2d.h
	install -m 644 include/collide2d_world.h $(DESTDIR)$(INCLUDEDIR)/collide2d_world.h
	install -m 644 $(STATIC) $(DESTDIR)$(LIBDIR)/libcollide2d.a
	install -m 755 $(SHARED) $(DESTDIR)$(LIBDIR)/libcollide2d.so.$(VERSION)
	ln -sf libcollide2d.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf libcollide2d.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libcollide2d.so
	install -m 644 $(B)/collide2d.pc $(DESTDIR)$(LIBDIR)/pkgconfig/collide2d.pc
	install -m 644 $(MAN_PAGES) $(MAN3)
	sh man/links.sh $(MAN_PAGES) | while read -r page name; do ln -sf $$page $(MAN3)/$$name || exit 1; done

uninstall:
	rm -f $(DESTDIR)$(INCLUDEDIR)/collide2d_world.h
	rm -f $(DESTDIR)$(INCLUDEDIR)/collide2d.h $(DESTDIR)$(LIBDIR)/libcollide2d.a \
	  $(DESTDIR)$(LIBDIR)/libcollide2d.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME) \
	  $(DESTDIR)$(LIBDIR)/libcollide2d.so $(DESTDIR)$(LIBDIR)/pkgconfig/collide2d.pc \
	  $(addprefix $(MAN3)/,$(notdir $(MAN_PAGES)))
	sh man/links.sh $(MAN_PAGES) | while read -r page name; do rm -f $(MAN3)/$$name; done
	sh scripts/installdirs.sh remove build/install-dirs.txt $(INSTALL_DIRS)

clean:
	rm -rf build

# ---------------------------------------------------------------- unit tests
# One cmocka program per unit (tests/unit/test_*.c, tests/vectors/test_*.c).
# The exact referee and the case generators (referee/, GMP rationals + MPFR),
# the shared test helper (tests/harness/) and the shared vector table with
# its checks (tests/vectors/, also run on emulated MCUs) are linked into each.
TEST_DEPS := libcmocka-dev libgmp-dev libmpfr-dev pkg-config
TEST_SRCS := $(wildcard tests/unit/test_*.c tests/vectors/test_*.c)
TEST_BINS := $(patsubst %.c,$(B)/tests/%,$(notdir $(TEST_SRCS)))
HARNESS_SRC := $(wildcard tests/harness/*.c)
HARNESS_HDR := $(wildcard tests/harness/*.h)
VECTORS_SRC := tests/vectors/vectors.c $(wildcard tests/vectors/check_*.c)
TEST_SUPPORT := referee/referee.c referee/cases.c referee/ref_rough.c referee/cases_rough.c referee/ref_toi_accel.c referee/cases_toi_accel.c $(VECTORS_SRC) $(HARNESS_SRC)
TEST_SUPPORT_HDR := $(wildcard referee/*.h tests/unit/*.h tests/vectors/*.h) $(HARNESS_HDR)
TEST_INC := -Ireferee -Itests/harness -Itests/unit -Itests/vectors

check-deps-test:
	@sh scripts/deps.sh $(TEST_DEPS)

$(B)/tests/%: tests/unit/%.c $(TEST_SUPPORT) $(TEST_SUPPORT_HDR) $(STATIC)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Wno-conversion $(TEST_INC) -o $@ $< $(TEST_SUPPORT) $(STATIC) -lcmocka -lmpfr -lgmp -lm

$(B)/tests/%: tests/vectors/%.c $(TEST_SUPPORT) $(TEST_SUPPORT_HDR) $(STATIC)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Wno-conversion $(TEST_INC) -o $@ $< $(TEST_SUPPORT) $(STATIC) -lcmocka -lmpfr -lgmp -lm

GEN_VECTORS_REF := referee/referee.c referee/ref_rough.c referee/ref_toi_accel.c
$(B)/gen_vectors: tests/vectors/gen_vectors.c $(GEN_VECTORS_REF) $(wildcard referee/*.h) tests/vectors/vectors.h $(LIB_HDR)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -std=c99 -Iinclude -Ireferee -Itests/vectors -o $@ tests/vectors/gen_vectors.c $(GEN_VECTORS_REF) -lmpfr -lgmp -lm

# Regenerate the shared vector table from the exact referee.
vectors: check-deps-test $(B)/gen_vectors
	$(B)/gen_vectors tests/vectors/vectors.c

# The committed table must be exactly what the referee gives today.
check-vectors: check-deps-test $(B)/gen_vectors
	@$(B)/gen_vectors $(B)/vectors.c && cmp -s $(B)/vectors.c tests/vectors/vectors.c && \
	  echo "check-vectors: 1 passed, 0 failed" || \
	  { echo "check-vectors: tests/vectors/vectors.c differs from the referee (make vectors)"; exit 1; }

check-build: $(AMALGAMATION)
	@sh tests/build/check_build.sh $(B)/check-build $(AMALGAMATION)

$(B)/tests/cxx_smoke: tests/unit/cxx_smoke.cpp $(STATIC)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -std=c++11 -pedantic -Wall -Wextra -Werror -Iinclude -o $@ $< $(STATIC) -lm

test-unit: check-deps-test
	@$(MAKE) --no-print-directory $(TEST_BINS) $(B)/tests/cxx_smoke
	@fail=0; for t in $(TEST_BINS) $(B)/tests/cxx_smoke; do echo "== $$t"; $$t || fail=1; done; \
	  if [ $$fail -ne 0 ]; then echo "unit tests FAILED"; exit 1; fi
	@$(MAKE) --no-print-directory check-vectors check-build

# Subsystems add their own targets and append to TEST_TARGETS.
TEST_TARGETS :=
LINT_TARGETS :=
-include demo/demo.mk
-include bench/bench.mk
-include tests/mcu/mcu.mk
-include tests/fuzz/fuzz.mk
-include tests/build/lint.mk
-include tests/consumers/consumers.mk
-include examples/examples.mk
-include python/python.mk
-include man/man.mk
-include tests/cross/cross.mk

# Static analysis: fragments append to LINT_TARGETS.
lint: $(LINT_TARGETS)

test: test-unit $(TEST_TARGETS)
	@echo "make test: all passed"
