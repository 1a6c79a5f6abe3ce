# SPDX-License-Identifier: MIT
# tally.sh - the pass/fail tally of the shell checks, the shell twin of
# c2d_tally (harness.h).  Sourced (POSIX sh):
#   c2d_tally_name=NAME      prefix of every line ("check-build", ...)
#   c2d_passed / c2d_failed [WHAT]   count one result; a failure says
#                            "NAME: FAILED WHAT" on stderr
#   c2d_check WHAT COMMAND... run COMMAND, count its exit status, return it
#   c2d_summary              "NAME: N passed, N failed"; status 1 on any failure
c2d_tally_name=${c2d_tally_name:-tally}
c2d_pass=0
c2d_fail=0

c2d_passed() { c2d_pass=$((c2d_pass + 1)); }

c2d_failed() {
    c2d_fail=$((c2d_fail + 1))
    [ $# -eq 0 ] || echo "$c2d_tally_name: FAILED $*" >&2
}

c2d_check() {
    c2d_what=$1
    shift
    if "$@"; then
        c2d_passed
        return 0
    fi
    c2d_failed "$c2d_what"
    return 1
}

c2d_summary() {
    echo "$c2d_tally_name: $c2d_pass passed, $c2d_fail failed"
    [ "$c2d_fail" -eq 0 ]
}
