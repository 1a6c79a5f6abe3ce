# SPDX-License-Identifier: MIT
"""The ctypes structs against the C ones: size, alignment, and
every field's name, order, offset and size, as the C compiler lays them out
(python/tests/layout.c prints sizeof/offsetof of collide2d.h's and
collide2d_world.h's).  make test-python builds
that program as $(B)/python/layout and names it in COLLIDE2D_LAYOUT; run by
hand, the test builds it with $CC (default cc) itself."""
import ctypes
import os
import re
import shlex
import subprocess

import pytest

import collide2d
from collide2d import _native
from conftest import PYTHON_DIR, REPO

HEADER = "".join(open(os.path.join(REPO, "include", h)).read() for h in ("collide2d.h", "collide2d_world.h"))

MIRRORED = {  # C struct -> its ctypes class
    "c2d_vec2": collide2d.Vec2, "c2d_body": collide2d.Body, "c2d_disk": collide2d.Disk,
    "c2d_surface": collide2d.Surface, "c2d_pairs": _native.DOUBLE["Pairs"],
    "c2d_vec2f": collide2d.Vec2f, "c2d_bodyf": collide2d.Bodyf, "c2d_diskf": collide2d.Diskf,
    "c2d_surfacef": collide2d.Surfacef, "c2d_pairsf": _native.FLOAT["Pairs"],
    "c2d_world_event": _native.WorldEvent, "c2d_world_desc": _native.WorldDesc,
    "c2d_world_stats": _native.WorldStats, "c2d_world_contact": _native.WorldContact,
    "c2d_ball": collide2d.Ball, "c2d_ball_surface": collide2d.BallSurface, "c2d_cushion": collide2d.Cushion,
    "c2d_ballf": collide2d.Ballf, "c2d_ball_surfacef": collide2d.BallSurfacef, "c2d_cushionf": collide2d.Cushionf,
}
# The Q16.16 API has no binding (no c2d_*x function is wrapped): its structs
# are laid out by the program but have no ctypes twin to compare.
NOT_MIRRORED = {"c2d_vec2x", "c2d_bodyx"}
# Nor has a caller's broadphase (collide2d.World uses the built-in one; its
# WorldDesc.broadphase stays NULL).
NOT_MIRRORED |= {"c2d_world_box", "c2d_world_broadphase"}
TYPES = {  # C type -> the ctypes type the binding passes it as
    "c2d_status": ctypes.c_int,  # the scalar calls' restype, the batch's status array (numpy.intc)
    "int": ctypes.c_int, "size_t": ctypes.c_size_t, "long": ctypes.c_long,  # c2d_version's restype
    "c2d_boundary": ctypes.c_int, "c2d_world_event_kind": ctypes.c_int,  # enums: WorldDesc, WorldEvent
    "c2d_world_model": ctypes.c_int,
}
NOT_MIRRORED_TYPES = {"c2d_fixed"}


@pytest.fixture(scope="module")
def layout(tmp_path_factory):
    program = os.environ.get("COLLIDE2D_LAYOUT")
    if not program:
        program = str(tmp_path_factory.mktemp("layout") / "layout")
        cc = shlex.split(os.environ.get("CC", "cc"))
        build = subprocess.run(cc + ["-std=c99", "-I" + os.path.join(REPO, "include"), "-o", program,
                                     os.path.join(PYTHON_DIR, "tests", "layout.c")],
                               capture_output=True, text=True, timeout=120)
        assert build.returncode == 0, build.stderr
    run = subprocess.run([program], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    structs, fields, types = {}, {}, {}
    for line in run.stdout.splitlines():
        kind, name, *rest = line.split()
        if kind == "struct":
            structs[name] = tuple(map(int, rest))
        elif kind == "field":
            fields.setdefault(name, []).append((rest[0], int(rest[1]), int(rest[2])))
        elif kind == "type":
            types[name] = tuple(map(int, rest))
        else:
            pytest.fail(f"layout: unknown line {line!r}")
    return structs, fields, types


def test_the_program_covers_every_struct_of_the_header(layout):
    structs, fields, _ = layout
    in_header = set(re.findall(r"typedef struct (\w+) \{", HEADER))
    assert len(in_header) == 24
    assert set(structs) == in_header == set(MIRRORED) | NOT_MIRRORED
    for name in in_header:  # every member, as the header declares them
        body = re.search(r"typedef struct %s \{(.*?)\} %s;" % (name, name), HEADER, re.S).group(1)
        body = re.sub(r"/\*.*?\*/", "", body, flags=re.S)
        body = re.sub(r"\(\s*\*\s*(\w+)\s*\)\s*\([^)]*\)", r"\1", body)  # a function pointer: its name
        members = re.findall(r"(\w+)\s*(?:\[\w*\])?\s*[,;]", body)  # an array: its name
        assert [m for m, _, _ in fields[name]] == members, name


@pytest.mark.parametrize("cname", sorted(MIRRORED))
def test_struct_layout_is_the_c_one(layout, cname):
    structs, fields, _ = layout
    cls = MIRRORED[cname]
    size, align = structs[cname]
    assert (ctypes.sizeof(cls), ctypes.alignment(cls)) == (size, align)
    py = [(name, getattr(cls, name).offset, getattr(cls, name).size) for name, _ in cls._fields_]
    assert py == fields[cname]


@pytest.mark.parametrize("cname", sorted(TYPES))
def test_scalar_types_are_the_c_ones(layout, cname):
    _, _, types = layout
    assert (ctypes.sizeof(TYPES[cname]), ctypes.alignment(TYPES[cname])) == types[cname]


def test_every_type_is_checked_or_listed(layout):
    _, _, types = layout
    assert set(types) == set(TYPES) | NOT_MIRRORED_TYPES


def test_nested_fields_are_the_mirrored_structs():
    for cname, cls in MIRRORED.items():
        real = ctypes.c_float if cname.endswith("f") else ctypes.c_double
        for name, ctype in cls._fields_:
            if isinstance(ctype, type) and issubclass(ctype, ctypes.Structure):
                assert ctype is MIRRORED["c2d_vec2" + ("f" if cname.endswith("f") else "")], (cname, name)
            if isinstance(ctype, type) and issubclass(ctype, ctypes.Array):  # a ball's spin[3]
                assert (ctype._type_, ctype._length_) == (real, 3), (cname, name)
