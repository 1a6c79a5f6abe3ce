# SPDX-License-Identifier: MIT
"""pytest set-up: the package from this source tree (python/), whatever the
current directory; the library it finds is ../build/libcollide2d.so unless
COLLIDE2D_LIB says otherwise."""
import os
import sys

PYTHON_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPO = os.path.dirname(PYTHON_DIR)
sys.path.insert(0, PYTHON_DIR)


_EXIT = {}


def pytest_sessionfinish(session, exitstatus):
    _EXIT["status"] = int(exitstatus)


def pytest_unconfigure(config):
    """End the run with the project's tally line, `python: N passed, M
    failed` (tests/harness/tally.sh), after pytest's own summary line (so at
    unconfigure, the last hook).  Failures count errors too (collection,
    set-up, tear-down), and a run that is not a success for another reason
    (exit status 5: no tests ran; interrupted; a usage error) is one more
    failure.  Under make test-python (COLLIDE2D_TALLY names a file) the
    counts go to that file instead, and python/run_tests.sh adds the
    example's run and prints the one line."""
    reporter = config.pluginmanager.get_plugin("terminalreporter")
    if reporter is None or "status" not in _EXIT:
        return
    stats, status = reporter.stats, _EXIT["status"]
    passed = len(stats.get("passed", ()))
    failed = len(stats.get("failed", ())) + len(stats.get("error", ()))
    if status != 0 and failed == 0:
        failed = 1
    tally = os.environ.get("COLLIDE2D_TALLY")
    if tally:
        with open(tally, "w") as f:
            f.write(f"{passed} {failed} {status}\n")
    else:
        reporter.write_line(f"python: {passed} passed, {failed} failed")
