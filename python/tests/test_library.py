# SPDX-License-Identifier: MIT
"""Loading the library, version and statuses against the C header."""
import os
import re
import subprocess
import sys

import collide2d
from collide2d import Status
from conftest import PYTHON_DIR, REPO

HEADER = open(os.path.join(REPO, "include", "collide2d.h")).read()


def test_version_is_the_headers():
    parts = [int(re.search(rf"#define C2D_VERSION_{p} (\d+)", HEADER).group(1)) for p in ("MAJOR", "MINOR", "PATCH")]
    assert collide2d.version() == tuple(parts)
    assert collide2d.__version__ == "%d.%d.%d" % tuple(parts)


def test_status_enum_is_the_headers():
    in_header = {name: int(v) for name, v in re.findall(r"\bC2D_([A-Z]+) = (\d+)", HEADER)}
    assert in_header == {s.name: s.value for s in Status}


def test_status_strings():
    for s in Status:
        assert collide2d.status_string(s) == s.name.lower() == str(s)
    assert collide2d.status_string(99) == "unknown"


def _import_with(env_value):
    env = dict(os.environ, COLLIDE2D_LIB=env_value, PYTHONPATH=PYTHON_DIR)
    return subprocess.run([sys.executable, "-c", "import collide2d; print(collide2d.LIB_PATH)"],
                          env=env, capture_output=True, text=True, timeout=60)


def test_library_from_environment():
    r = _import_with(collide2d.LIB_PATH)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == collide2d.LIB_PATH


def test_missing_library_is_a_clear_import_error():
    r = _import_with("/nonexistent/libcollide2d.so")
    assert r.returncode == 1
    assert "ImportError: collide2d: COLLIDE2D_LIB='/nonexistent/libcollide2d.so' cannot be loaded" in r.stderr


def test_module_docstring_example():
    import doctest
    result = doctest.testmod(collide2d)
    assert result.attempted >= 3 and result.failed == 0
