# SPDX-License-Identifier: MIT
# collide2d - top-level build.  `make` builds the library; `make test` installs
# what it needs, builds and runs every test; `make demo` runs the billiards break.
#
# Conventions: CC is never assigned (use the environment's), CFLAGS ?= -O2 is
# yours, the flags the library needs are appended.  -ffp-contract=off keeps
# a*b+c from being fused differently per compiler/target, so results are
# reproducible bit for bit (docs/DETERMINISM.md).  -fno-math-errno lets the time
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
LIB_TEMPLATES := $(wildcard lib/*.h lib/real/*.h lib/real/*/*.h lib/world/*.h)
LIB_OBJ := $(patsubst lib/%.c,$(B)/obj/%.o,$(LIB_SRC))
LIB_PIC := $(patsubst lib/%.c,$(B)/obj/%.pic.o,$(LIB_SRC))
STATIC := $(B)/libcollide2d.a
SONAME := libcollide2d.so.$(VERSION_MAJOR)
SHARED := $(B)/libcollide2d.so.$(VERSION)
AMALGAMATION := $(B)/collide2d_all.c

# `make` alone builds the libraries and collide2d.pc (the first rule, and
# named, so that no rule of an included file or a .d file takes its place).
.DEFAULT_GOAL := all
all: lib
lib: $(STATIC) $(B)/libcollide2d.so $(B)/collide2d.pc
FORCE:
.PHONY: all lib amalgamate test test-unit check-deps-test check-vectors check-build vectors install uninstall clean demo play bench cross test-mcu lint fuzz

# Header dependencies: every compile of one source writes its .d beside the
# object (-MMD: the headers it included, not system ones; -MP: an empty rule
# per header, so a deleted header is no error), included at the end of this
# file and each fragment.  gcc and clang, given several sources and -o, write
# one .d with only the last source's headers, so a command that compiles and
# links several sources at once (fragments) takes MULTI_DEPS instead:
#   $(call MULTI_DEPS,COMPILER FLAGS,SOURCES)  writes $@.d for all of them
DEPFLAGS = -MMD -MP
MULTI_DEPS = $(1) -MM -MP -MT $@ $(2) >$@.d.tmp && mv $@.d.tmp $@.d

$(B)/obj/%.o: lib/%.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DEPFLAGS) -c $< -o $@

$(B)/obj/%.pic.o: lib/%.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DEPFLAGS) -fPIC -fvisibility=default -c $< -o $@

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
# rebuilds it, an unchanged one keeps its time stamp.  The directories are
# compared in the shell, not by make's word functions: they may hold spaces.
# C2D_SH_PATHS: shell functions for recipes, `rel DIR` (DIR as ${prefix}/...
# when under PREFIX), `esc TEXT` (TEXT as a sed replacement, | delimiter)
# and `pcq TEXT` (a space as "\ ", which pkg-config reads as part of the
# value and prints back so, so that `pkg-config --cflags` under a prefix
# with a space gives one word to a shell: -I/opt/my\ dir/include).
C2D_SH_PATHS = prefix='$(PREFIX)'; \
  rel() { case $$1 in "$$prefix"/*) printf '%s' "\$${prefix}/$${1\#"$$prefix"/}";; *) printf '%s' "$$1";; esac; }; \
  esc() { printf '%s' "$$1" | sed 's/[\\|&]/\\&/g'; }; \
  pcq() { printf '%s' "$$1" | sed 's/ /\\ /g'; }
$(B)/collide2d.pc: collide2d.pc.in FORCE
	@mkdir -p $(@D)
	@$(C2D_SH_PATHS); \
	sed -e "s|@C2D_PC_PREFIX@|$$(esc "$$(pcq "$$prefix")")|" -e "s|@C2D_PC_LIBDIR@|$$(esc "$$(pcq "$$(rel '$(LIBDIR)')")")|" \
	  -e "s|@C2D_PC_INCLUDEDIR@|$$(esc "$$(pcq "$$(rel '$(INCLUDEDIR)')")")|" -e 's|@C2D_PC_VERSION@|$(VERSION)|' \
	  -e 's|@C2D_PC_CFLAGS@||' collide2d.pc.in > $@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@ && echo "wrote $@ (prefix $(PREFIX))"; fi

# The CMake package, as `cmake --install` writes it (cmake/package.sh):
# collide2dConfig.cmake, collide2dConfigVersion.cmake and
# collide2dTargets.cmake (collide2d::collide2d, the shared library, and
# collide2d::collide2d_static), relative to LIBDIR/cmake/collide2d.
# Regenerated like collide2d.pc.  The pointer size, for the version file's
# 32/64-bit check, is the compiler's (empty, so no check, if it does not say).
CMAKE_PKG := $(B)/cmake
CMAKE_PKG_FILES := collide2dConfig.cmake collide2dConfigVersion.cmake collide2dTargets.cmake
CMAKEDIR = $(LIBDIR)/cmake/collide2d
cmake-package:
	@sh cmake/package.sh $(CMAKE_PKG) '$(PREFIX)' '$(LIBDIR)' '$(INCLUDEDIR)' $(VERSION) $(SONAME) \
	  "$$($(CC) $(CFLAGS) -dM -E - </dev/null 2>/dev/null | sed -n 's/^#define __SIZEOF_POINTER__ //p')"
.PHONY: cmake-package

# The whole library as one self-contained source, for firmware trees that
# take one .c file beside the header (scripts/amalgamate.sh).
amalgamate: $(AMALGAMATION)
$(AMALGAMATION): scripts/amalgamate.sh $(LIB_SRC) $(LIB_TEMPLATES)
	@mkdir -p $(@D)
	sh scripts/amalgamate.sh $@

# Directories install creates are listed in build/install-dirs.txt, so
# uninstall removes those (once empty) and no other (scripts/installdirs.sh).
# Every path is quoted: PREFIX, DESTDIR and the directories may hold spaces
# (not quotes).
PUBLIC_HDRS := include/collide2d.h include/collide2d_world.h
MAN_PAGES := $(wildcard man/*.3)
MAN3 = $(DESTDIR)$(MANDIR)/man3
INSTALL_DIRS = "$(DESTDIR)$(LIBDIR)/pkgconfig" "$(DESTDIR)$(CMAKEDIR)" "$(DESTDIR)$(INCLUDEDIR)" "$(MAN3)"
install: lib cmake-package
	sh scripts/installdirs.sh create build/install-dirs.txt $(INSTALL_DIRS)
	install -m 644 $(PUBLIC_HDRS) "$(DESTDIR)$(INCLUDEDIR)"
	install -m 644 $(STATIC) "$(DESTDIR)$(LIBDIR)/libcollide2d.a"
	install -m 755 $(SHARED) "$(DESTDIR)$(LIBDIR)/libcollide2d.so.$(VERSION)"
	ln -sf libcollide2d.so.$(VERSION) "$(DESTDIR)$(LIBDIR)/$(SONAME)"
	ln -sf libcollide2d.so.$(VERSION) "$(DESTDIR)$(LIBDIR)/libcollide2d.so"
	install -m 644 $(B)/collide2d.pc "$(DESTDIR)$(LIBDIR)/pkgconfig/collide2d.pc"
	install -m 644 $(addprefix $(CMAKE_PKG)/,$(CMAKE_PKG_FILES)) "$(DESTDIR)$(CMAKEDIR)"
	install -m 644 $(MAN_PAGES) "$(MAN3)"
	sh man/links.sh $(MAN_PAGES) | while read -r page name; do ln -sf "$$page" "$(MAN3)/$$name" || exit 1; done

uninstall:
	for f in $(notdir $(PUBLIC_HDRS)); do rm -f "$(DESTDIR)$(INCLUDEDIR)/$$f"; done
	rm -f "$(DESTDIR)$(LIBDIR)/libcollide2d.a" \
	  "$(DESTDIR)$(LIBDIR)/libcollide2d.so.$(VERSION)" "$(DESTDIR)$(LIBDIR)/$(SONAME)" \
	  "$(DESTDIR)$(LIBDIR)/libcollide2d.so" "$(DESTDIR)$(LIBDIR)/pkgconfig/collide2d.pc"
	for f in $(CMAKE_PKG_FILES); do rm -f "$(DESTDIR)$(CMAKEDIR)/$$f"; done
	for f in $(notdir $(MAN_PAGES)); do rm -f "$(MAN3)/$$f"; done
	sh man/links.sh $(MAN_PAGES) | while read -r page name; do rm -f "$(MAN3)/$$name"; done
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
VECTORS_SRC := tests/vectors/vectors.c $(wildcard tests/vectors/check_*.c)
TEST_SUPPORT := referee/referee.c referee/cases.c referee/ref_rough.c referee/cases_rough.c referee/ref_sphere.c referee/cases_sphere.c referee/ref_toi_accel.c referee/cases_toi_accel.c $(VECTORS_SRC) $(HARNESS_SRC)
TEST_INC := -Ireferee -Itests/harness -Itests/unit -Itests/vectors

check-deps-test:
	@sh scripts/deps.sh $(TEST_DEPS)

# Every source compiled once to its own object (and .d) under
# $(B)/tests/obj/, the support objects shared by every program.
TEST_OBJ_DIR := $(B)/tests/obj
TEST_SUPPORT_OBJ := $(TEST_SUPPORT:%.c=$(TEST_OBJ_DIR)/%.o)
TEST_MAIN_OBJ := $(TEST_SRCS:%.c=$(TEST_OBJ_DIR)/%.o)
$(TEST_OBJ_DIR)/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DEPFLAGS) -Wno-conversion $(TEST_INC) -c $< -o $@

# Each program: its own object (tests/unit/ or tests/vectors/), then the rest.
$(foreach s,$(TEST_SRCS),$(eval $(B)/tests/$(basename $(notdir $(s))): $(TEST_OBJ_DIR)/$(s:.c=.o)))
$(TEST_BINS): $(TEST_SUPPORT_OBJ) $(STATIC)
	$(CC) $(ALL_CFLAGS) -o $@ $(filter $(TEST_MAIN_OBJ),$^) $(TEST_SUPPORT_OBJ) $(STATIC) -lcmocka -lmpfr -lgmp -lm

GEN_VECTORS_SRC := tests/vectors/gen_vectors.c referee/referee.c referee/ref_rough.c referee/ref_toi_accel.c
GEN_VECTORS_OBJ := $(GEN_VECTORS_SRC:%.c=$(B)/gen/%.o)
$(B)/gen/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -std=c99 $(DEPFLAGS) -Iinclude -Ireferee -Itests/vectors -c $< -o $@
$(B)/gen_vectors: $(GEN_VECTORS_OBJ)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -o $@ $(GEN_VECTORS_OBJ) -lmpfr -lgmp -lm

# Regenerate the shared vector table from the exact referee.
vectors: check-deps-test $(B)/gen_vectors
	$(B)/gen_vectors tests/vectors/vectors.c

# The committed table must be exactly what the referee gives today.
check-vectors: check-deps-test $(B)/gen_vectors
	@$(B)/gen_vectors $(B)/vectors.c && cmp -s $(B)/vectors.c tests/vectors/vectors.c && \
	  echo "check-vectors: 1 passed, 0 failed" || \
	  { echo "check-vectors: tests/vectors/vectors.c differs from the referee (make vectors)" >&2; echo "check-vectors: 0 passed, 1 failed"; exit 1; }

check-build: $(AMALGAMATION)
	@sh tests/build/check_build.sh $(B)/check-build $(AMALGAMATION)

$(B)/tests/cxx_smoke: tests/unit/cxx_smoke.cpp $(STATIC)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) $(DEPFLAGS) -std=c++11 -pedantic -Wall -Wextra -Werror -Iinclude -o $@ $< $(STATIC) -lm

test-unit: check-deps-test
	@$(MAKE) --no-print-directory $(TEST_BINS) $(B)/tests/cxx_smoke
	@fail=0; for t in $(TEST_BINS) $(B)/tests/cxx_smoke; do echo "== $$t"; $$t || fail=1; done; \
	  if [ $$fail -ne 0 ]; then echo "unit tests FAILED"; exit 1; fi
	@$(MAKE) --no-print-directory check-vectors check-build

# Subsystems add their own targets and append to TEST_TARGETS.
TEST_TARGETS :=
LINT_TARGETS :=
-include demo/demo.mk
-include demo/web/web.mk
-include bench/bench.mk
-include tests/mcu/mcu.mk
-include tests/fuzz/fuzz.mk
-include tests/build/lint.mk
-include tests/build/build.mk
-include tests/consumers/consumers.mk
-include examples/examples.mk
-include python/python.mk
-include man/man.mk
-include tests/cross/cross.mk

# Static analysis: fragments append to LINT_TARGETS.
lint: $(LINT_TARGETS)

test: test-unit $(TEST_TARGETS)
	@echo "make test: all passed"

# The header dependencies of every object and program built above.
-include $(LIB_OBJ:.o=.d) $(LIB_PIC:.o=.d) $(TEST_SUPPORT_OBJ:.o=.d) $(TEST_MAIN_OBJ:.o=.d) \
  $(GEN_VECTORS_OBJ:.o=.d) $(B)/tests/cxx_smoke.d
