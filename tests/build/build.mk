# SPDX-License-Identifier: MIT
# tests/build/build.mk - build-contract checks beyond check-build, included
# by the top-level Makefile; each prints "NAME: N passed, N failed".
#   make check-tsan       the library under ThreadSanitizer, gcc and clang
#                         (tests/build/tsan.sh; skips a compiler without it)
#   make check-fast-math  -ffast-math / -ffinite-math-only stop lib/'s build
#                         unless C2D_ALLOW_FAST_MATH (tests/build/fast_math.sh)

.PHONY: check-tsan check-fast-math

check-tsan:
	@sh tests/build/tsan.sh $(B)/check-tsan

check-fast-math:
	@sh tests/build/fast_math.sh $(B)/check-fast-math

TEST_TARGETS += check-tsan check-fast-math
