#!/bin/sh
# SPDX-License-Identifier: MIT
# python/run_tests.sh - the Python suite for make test-python, ending with
# the project's tally line (tests/harness/tally.sh): `python: N passed,
# M failed`, N and M counting pytest's tests and the example's run.
#   sh python/run_tests.sh PYTHON BUILD_DIR [PYTEST_ARGUMENT...]
# Environment: COLLIDE2D_LIB, COLLIDE2D_LAYOUT (as python.mk sets them).
# pytest's own output is kept; its counts come from python/tests/conftest.py
# (COLLIDE2D_TALLY).  A pytest exit status but 0 is a failure even with no
# failed test (5: no tests ran), and so is a run that reports no counts.
python=$1
build=$2
shift 2
c2d_tally_name=python
. tests/harness/tally.sh

counts=$build/python/pytest.counts
rm -f "$counts"
COLLIDE2D_TALLY=$counts "$python" -m pytest -q -p no:cacheprovider python/tests "$@"
rc=$?
if read -r passed failed status < "$counts" 2>/dev/null; then
    c2d_pass=$((c2d_pass + passed))
    c2d_fail=$((c2d_fail + failed))
    [ "$failed" -gt 0 ] && echo "python: FAILED $failed of pytest's tests (exit status $status)" >&2
    [ "$rc" -eq 0 ] || [ "$failed" -gt 0 ] || c2d_failed "pytest exit status $rc"
else
    c2d_failed "pytest (exit status $rc) reported no counts"
fi
[ "$rc" -ne 0 ] || [ "${passed:-0}" -gt 0 ] || c2d_failed "pytest ran no tests"

c2d_check "the hard-disk example" "$python" python/examples/hard_disk_eos.py --eta 0.2,0.4 --impacts 60 \
    --plot "$build/python/hard_disk_eos.png"
c2d_summary
