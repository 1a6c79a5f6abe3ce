# SPDX-License-Identifier: MIT
# tests/build/make.mk - the Makefile's own contract (issues 18, 19), included
# by the top-level Makefile:
#   make test-make   in a fresh copy of the tree ($(B)/test-make/tree):
#                    a plain `make` builds the libraries and collide2d.pc,
#                    the header dependencies rebuild what they should
#                    (tests/build/default_goal.sh); install and uninstall
#                    with spaces in DESTDIR and PREFIX stay inside them and
#                    remove what they installed (tests/build/install.sh)
# The copy builds with the defaults whatever this make was given, so under
# SANITIZE=1 it is skipped (the plain run covers it).

MAKE_TEST_DEPS := pkg-config cmake

.PHONY: test-make
ifeq ($(SANITIZE),1)
test-make:
	@echo "test-make: skipped under SANITIZE=1 (the Makefile, not code: the plain run covers it)"
else
test-make:
	@sh scripts/deps.sh $(MAKE_TEST_DEPS)
	@sh tests/build/default_goal.sh $(B)/test-make
	@sh tests/build/install.sh $(B)/test-make/tree $(B)/test-make
endif

TEST_TARGETS += test-make
