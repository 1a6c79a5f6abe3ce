# SPDX-License-Identifier: MIT
# tests/build/build.mk - the build's own contract beyond check-build, included
# by the top-level Makefile; each prints "NAME: N passed, N failed".
#   make test-make        in a fresh copy of the tree ($(B)/test-make/tree):
#                         a plain `make` builds the libraries and collide2d.pc,
#                         the header dependencies rebuild what they should
#                         (tests/build/default_goal.sh); install and uninstall
#                         with spaces in DESTDIR and PREFIX stay inside them
#                         and remove what they installed (tests/build/install.sh)
#   make check-tsan       the library under ThreadSanitizer, gcc and clang
#                         (tests/build/tsan.sh; skips a compiler without it)
#   make check-fast-math  -ffast-math / -ffinite-math-only stop lib/'s build
#                         unless C2D_ALLOW_FAST_MATH (tests/build/fast_math.sh)
#   make check-normal-stall  no store-forwarding stall on the hot path of
#                         c2d_collide_normal (and c2d_collide, float too)
#                         at -O0, -O2, -O3, -O3 -march=native and -Os, gcc
#                         and clang, read from the machine code
#                         (tests/build/normal_stall.sh, issue 22)
#   make check-docs       README.md at most 12,000 bytes; every relative link
#                         and anchor of README.md, docs/*.md and
#                         lib/real/toia/README.md resolves (tests/build/docs.sh)
# The copy of test-make builds with the defaults whatever this make was
# given, so under SANITIZE=1 it is skipped (the plain run covers it).

MAKE_TEST_DEPS := pkg-config cmake

.PHONY: test-make check-tsan check-fast-math check-normal-stall check-docs
ifeq ($(SANITIZE),1)
test-make:
	@echo "test-make: skipped under SANITIZE=1 (the Makefile, not code: the plain run covers it)"
else
test-make:
	@sh scripts/deps.sh $(MAKE_TEST_DEPS)
	@sh tests/build/default_goal.sh $(B)/test-make
	@sh tests/build/install.sh $(B)/test-make/tree $(B)/test-make
endif

check-tsan:
	@sh tests/build/tsan.sh $(B)/check-tsan

check-fast-math:
	@sh tests/build/fast_math.sh $(B)/check-fast-math

check-normal-stall:
	@sh tests/build/normal_stall.sh $(B)/check-normal-stall

check-docs:
	@sh scripts/deps.sh python3
	@sh tests/build/docs.sh

TEST_TARGETS += test-make check-tsan check-fast-math check-normal-stall check-docs
