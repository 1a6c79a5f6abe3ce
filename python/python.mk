# SPDX-License-Identifier: MIT
# python/python.mk - the Python binding (python/collide2d, ctypes over
# $(B)/libcollide2d.so), included by the top-level Makefile:
#   make test-python   installs Debian's numpy and pytest, runs the pytest
#                      suite (python/tests) against the library just built
#                      (with $(B)/python/layout, the C struct layouts, for
#                      test_layout.py), and the hard-disk equation-of-state
#                      example on two packing fractions with its plot
#                      ($(B)/python/); python/run_tests.sh ends it with
#                      `python: N passed, M failed` (tests/harness/tally.sh)
# Debian's python3 is used whatever `python3` is first on PATH, since that is
# where python3-numpy and python3-pytest install (override with PYTHON=).
# Under SANITIZE=1 it is skipped: an ASan-built library cannot be loaded
# into a Python that was not started with the ASan runtime.

PYTHON ?= /usr/bin/python3
PYTHON_DEPS := python3 python3-numpy python3-pytest gnuplot-nox
PYTHON_ENV := PYTHONDONTWRITEBYTECODE=1 COLLIDE2D_LIB=$(abspath $(B)/libcollide2d.so)

.PHONY: test-python
ifeq ($(SANITIZE),1)
test-python:
	@echo "python: skipped under SANITIZE=1 (an ASan library needs an ASan-started interpreter)"
else
test-python: lib $(B)/python/layout
	@sh scripts/deps.sh $(PYTHON_DEPS)
	@mkdir -p $(B)/python
	@$(PYTHON_ENV) COLLIDE2D_LAYOUT=$(abspath $(B)/python/layout) sh python/run_tests.sh $(PYTHON) $(B)
endif

# The C layout of the public structs (sizeof, offsetof, alignment), which
# python/tests/test_layout.py compares with the ctypes ones.
$(B)/python/layout: python/tests/layout.c $(LIB_HDR) include/collide2d_world.h
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ python/tests/layout.c

TEST_TARGETS += test-python
