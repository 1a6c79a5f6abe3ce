# SPDX-License-Identifier: MIT
"""pytest set-up: the package from this source tree (python/), whatever the
current directory; the library it finds is ../build/libcollide2d.so unless
COLLIDE2D_LIB says otherwise."""
import os
import sys

PYTHON_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPO = os.path.dirname(PYTHON_DIR)
sys.path.insert(0, PYTHON_DIR)
