# SPDX-License-Identifier: MIT
# man/man.mk - the section 3 manual pages (mdoc, written by hand from the
# header's comments), included by the top-level Makefile.  `make install`
# puts them in $(MANDIR)/man3 with a link for every other name a page
# documents (man/links.sh); `make uninstall` removes both.
#   make test-man   mandoc -T lint on every page, every .Xr resolved, and
#                   every function of include/collide2d.h documented
#                   (man/lint.sh)

MAN_DEPS := mandoc
# Header functions that are not the API: the inline front ends' helper.
MAN_INTERNAL := c2d_inline_front c2d_inline_frontf

.PHONY: test-man
test-man:
	@sh scripts/deps.sh $(MAN_DEPS)
	@C2D_MAN_INTERNAL='$(MAN_INTERNAL)' sh man/lint.sh $(LIB_HDR) $(MAN_PAGES)

TEST_TARGETS += test-man
