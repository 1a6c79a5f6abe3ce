# SPDX-License-Identifier: MIT
# python/python.mk - the Python binding (python/collide2d, ctypes over
# $(B)/libcollide2d.so), included by the top-level Makefile:
#   make test-python   installs Debian's numpy and pytest, runs the pytest
#                      suite (python/tests) against the library just built,
#                      and the hard-disk equation-of-state example on two
#                      packing fractions with its plot ($(B)/python/)
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
test-python: lib
	@sh scripts/deps.sh $(PYTHON_DEPS)
	@mkdir -p $(B)/python
	@$(PYTHON_ENV) $(PYTHON) -m pytest -q -p no:cacheprovider python/tests
	@$(PYTHON_ENV) $(PYTHON) python/examples/hard_disk_eos.py --eta 0.2,0.4 --impacts 60 \
	  --plot $(B)/python/hard_disk_eos.png
endif

TEST_TARGETS += test-python
