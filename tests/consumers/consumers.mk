# SPDX-License-Identifier: MIT
# tests/consumers/consumers.mk - the three ways a user picks collide2d up
# (included by the top-level Makefile):
#   make test-consumers   a tiny project (tests/consumers/consumer.c) built
#                         and run through CMake find_package against a
#                         DESTDIR install made by CMake, CMake
#                         add_subdirectory and FetchContent on the source
#                         tree, and pkg-config against a DESTDIR
#                         `make install PREFIX=/opt/c2d`, and CMake
#                         find_package against that install; then `make
#                         uninstall` must leave the DESTDIR empty.
# Under SANITIZE=1 it is skipped: the libraries it installs are the plain
# ones, which the normal run has checked.

CONSUMERS_DEPS := cmake pkg-config

.PHONY: test-consumers
ifeq ($(SANITIZE),1)
test-consumers:
	@echo "consumers: skipped under SANITIZE=1 (packaging, not code: the plain run covers it)"
else
test-consumers: lib
	@sh scripts/deps.sh $(CONSUMERS_DEPS)
	@sh tests/consumers/run.sh $(B)/consumers $(MAKE)
endif

TEST_TARGETS += test-consumers
