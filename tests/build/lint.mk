# SPDX-License-Identifier: MIT
# tests/build/lint.mk - static analysis of lib/ and demo/, included by the
# top-level Makefile.  Configurations: .clang-tidy (repo root) and
# tests/build/cppcheck-suppressions.txt, each entry with its reason.
#   make lint-tidy       clang-tidy-14, warnings are errors
#   make lint-cppcheck   cppcheck 2.10, any finding is an error
# lib/ is checked as written, one translation unit at a time (each
# double.c / float.c instance includes the real/ templates).
# The demo part runs only when demo/*/*.cpp exist; it is C++17 against Debian's
# Box2D and SDL2 headers, taken as system headers (their own macros are
# not ours to lint).  Each prints "lint-NAME: N passed, N failed" (one per
# source file; tests/harness/tally.sh).

LINT_DEPS := clang-tidy-14 cppcheck
LINT_DEMO_DEPS := libbox2d-dev libsdl2-dev libpng-dev
LINT_DIR := $(B)/lint
LINT_LIB_FLAGS := -std=c99 -ffp-contract=off -Iinclude
# demo/web/hook.cpp is the browser's side only (emscripten.h, which a machine
# without the web build's packages lacks): emcc compiles it in `make web`.
LINT_DEMO_SRC = $(filter-out demo/web/hook.cpp,$(wildcard demo/*/*.cpp))
LINT_DEMO_FLAGS := -std=c++17 -ffp-contract=off -Iinclude -Idemo -isystem /usr/include/SDL2 -D_REENTRANT

.PHONY: lint-deps lint-tidy lint-cppcheck

lint-deps:
	@sh scripts/deps.sh $(LINT_DEPS) $(if $(LINT_DEMO_SRC),$(LINT_DEMO_DEPS))

lint-tidy: lint-deps
	@. tests/harness/tally.sh; c2d_tally_name=lint-tidy; \
	for f in $(LIB_SRC) $(LINT_DEMO_SRC); do \
	  case $$f in *.cpp) flags="$(LINT_DEMO_FLAGS)";; *) flags="$(LINT_LIB_FLAGS)";; esac; \
	  c2d_check $$f clang-tidy-14 --quiet $$f -- $$flags; \
	done; \
	c2d_summary

CPPCHECK := cppcheck --enable=warning,style,performance,portability --inline-suppr \
  --error-exitcode=1 -q --suppressions-list=tests/build/cppcheck-suppressions.txt

lint-cppcheck: lint-deps
	@mkdir -p $(LINT_DIR)
	@. tests/harness/tally.sh; c2d_tally_name=lint-cppcheck; \
	for f in $(LIB_SRC); do \
	  c2d_check $$f $(CPPCHECK) --std=c99 --language=c -Iinclude -Ilib -UC2D_HEADER $$f; \
	done; \
	for f in $(LINT_DEMO_SRC); do \
	  c2d_check $$f $(CPPCHECK) --std=c++17 --language=c++ -Iinclude -Idemo -I/usr/include/SDL2 -D_REENTRANT $$f; \
	done; \
	c2d_summary

LINT_TARGETS += lint-tidy lint-cppcheck
TEST_TARGETS += lint-tidy lint-cppcheck
