# SPDX-License-Identifier: MIT
"""Every value the binding takes is checked before it reaches C:
a TypeError for the wrong kind of thing, a ValueError for a wrong value
(a wrong number of components, a number beyond the C type), never a silent
zero fill, truncation or infinity.  NaN and infinities pass: the C contract
answers C2D_INVALID for them (or reads an infinite mass, inertia, friction or
horizon as a value).  The rules are in collide2d._native; here each is
tried on every field of every struct, every argument of every function."""
import ctypes
import decimal
import fractions
import math

import numpy as np
import pytest

import collide2d as c
from collide2d import Status
from variants import DOUBLE, FLOAT, VARIANTS


STRUCT_NAMES = ("Vec2", "Body", "Disk", "Surface")
GOOD_FIELDS = {  # valid values of every field, in order
    "Vec2": (1.5, -2.0),
    "Body": ((0.0, 0.0), (1.0, 0.0), 2.0),
    "Disk": ((0.0, 0.0), (1.0, 0.0), 0.5, 2.0, 0.5, 0.25),
    "Surface": (0.75, 0.25, 0.5),  # exact in float: the twins compare bit for bit
    "Ball": ((0.0, 0.0), (1.0, 0.0), (0.5, -1.0, 2.0), 2.0, 0.5, 0.25),
}


def raw(*structs):
    return b"".join(bytes(s) for s in structs)


def params(cases):
    return [pytest.param(value, exc, id=what) for what, value, exc in cases]


# ------------------------------------------------------------ bad kinds

def bad_numbers(v):
    """(what, value, exception) for a real field or a real argument."""
    cases = [
        ("str", "1", TypeError), ("bytes", b"1", TypeError), ("None", None, TypeError),
        ("complex", 1j, TypeError), ("complex with zero imaginary part", complex(1, 0), TypeError),
        ("bool", True, TypeError), ("False", False, TypeError), ("numpy bool", np.bool_(True), TypeError),
        ("tuple", (1.0,), TypeError), ("list", [1.0], TypeError), ("dict", {1: 2}, TypeError),
        ("0-d array", np.array(1.0), TypeError), ("1-element array", np.array([1.0]), TypeError),
        ("Decimal", decimal.Decimal("1.5"), TypeError), ("a Vec2", c.Vec2(1, 2), TypeError),
        ("2**1024", 2 ** 1024, ValueError), ("-2**1024", -2 ** 1024, ValueError),
        ("2**20000", 2 ** 20000, ValueError), ("a huge Fraction", fractions.Fraction(2 ** 1100, 3), ValueError),
    ]
    if np.finfo(np.longdouble).max > np.finfo(np.float64).max:
        cases.append(("longdouble 1e4000", np.longdouble("1e4000"), ValueError))
    if v is FLOAT:
        cases += [("1e300 for float", 1e300, ValueError), ("-1e39 for float", -1e39, ValueError),
                  ("2**128 for float", 2 ** 128, ValueError), ("numpy 1e39 for float", np.float64(1e39), ValueError)]
    return cases


def good_numbers(v):
    """(what, value, stored) for a real field or argument."""
    big = 2.0 ** 1023 if v is DOUBLE else 2.0 ** 127
    return [
        ("int", 3, 3.0), ("float", 0.25, 0.25), ("negative", -1.5, -1.5), ("Fraction", fractions.Fraction(1, 4), 0.25),
        ("numpy float32", np.float32(0.5), 0.5), ("numpy float64", np.float64(-0.75), -0.75),
        ("numpy int64", np.int64(-2), -2.0), ("numpy uint8", np.uint8(7), 7.0),
        ("largest power of 2", int(big), big), ("inf", math.inf, math.inf), ("-inf", -math.inf, -math.inf),
        ("nan", math.nan, math.nan),
        ("rounds to the largest float" if v is FLOAT else "DBL_MAX", 3.4028235e38 if v is FLOAT else 1.7976931348623157e308,
         3.4028234663852886e38 if v is FLOAT else 1.7976931348623157e308),
    ]


def bad_sequences(v, n, name):
    """(what, value, exception) for a struct of n numbers (a Vec2, a Surface)."""
    ok = GOOD_FIELDS[name]
    cases = [
        ("one component short", ok[:-1], ValueError), ("one component too many", ok + (1.0,), ValueError),
        ("1 component", (1,), ValueError), ("empty", (), ValueError), ("a short list", list(ok[:-1]), ValueError),
        ("dict", {k: 1.0 for k in range(1, 2 * n, 2)}, TypeError), ("set", set(range(n)), TypeError),
        ("frozenset", frozenset(range(n)), TypeError),
        ("str", "ab" if n == 2 else "abc", TypeError), ("bytes", bytes(range(n)), TypeError),
        ("bytearray", bytearray(range(n)), TypeError), ("memoryview", memoryview(bytes(range(n))), TypeError),
        ("iterator", iter(ok), TypeError), ("generator", (x for x in ok), TypeError),
        ("None", None, TypeError), ("number", 1.0, TypeError), ("bool", True, TypeError),
        ("nested", ((1, 2),) + ok[1:], TypeError), ("text component", ("1",) + ok[1:], TypeError),
        ("None component", (None,) + ok[1:], TypeError), ("complex component", (1j,) + ok[1:], TypeError),
        ("bool component", (True,) + ok[1:], TypeError), ("huge component", (2 ** 1024,) + ok[1:], ValueError),
        ("array too long", np.array(ok + (1.0,)), ValueError), ("2-D array", np.array([ok]), ValueError),
        ("0-d array", np.array(1.0), ValueError), ("bool array", np.array([True] * n), TypeError),
        ("complex array", np.array(ok, dtype=complex), TypeError), ("str array", np.array(["1"] * n), TypeError),
        ("object array", np.array(ok, dtype=object), TypeError),
        ("a Body", c.Body(), TypeError), ("a Disk", c.Disk(), TypeError),
        ("the other struct", c.Surface() if name == "Vec2" else c.Vec2(), TypeError),
    ]
    if v is FLOAT:
        cases.append(("1e300 component for float", (1e300,) + ok[1:], ValueError))
    return cases


def good_sequences(v, name):
    """(what, value) that all mean GOOD_FIELDS[name]."""
    ok = GOOD_FIELDS[name]
    twin = getattr(v.other, name)(*ok)
    return [("tuple", ok), ("list", list(ok)), ("struct", getattr(v, name)(*ok)), ("the other precision", twin),
            ("float64 array", np.array(ok)), ("float32 array", np.array(ok, dtype=np.float32)),
            ("a row of a 2-D array", np.array([ok, ok])[1])]


def fields(v, name):
    cls = getattr(v, name)
    return [(f, t) for f, t in cls._fields_]


def field_cases():
    """(variant, struct name, field index, bad value, exception) over every field."""
    out = []
    for v in VARIANTS:
        for name in STRUCT_NAMES:
            for i, (field, ftype) in enumerate(fields(v, name)):
                nested = ftype is not v.real
                cases = bad_sequences(v, 2, "Vec2") if nested else bad_numbers(v)
                for what, value, exc in cases:
                    out.append(pytest.param(v, name, i, value, exc, id=f"{v!r}-{name}.{field}-{what}"))
    return out


FIELD_BAD = field_cases()


@pytest.mark.parametrize("v, name, i, value, exc", FIELD_BAD)
def test_a_bad_field_is_refused_in_the_constructor(v, name, i, value, exc):
    cls, ok = getattr(v, name), list(GOOD_FIELDS[name])
    ok[i] = value
    with pytest.raises(exc, match=rf"{cls.__name__}\.{cls._fields_[i][0]}"):
        cls(*ok)
    keywords = {f: a for (f, _), a in zip(cls._fields_, ok)}
    with pytest.raises(exc):
        cls(**keywords)


@pytest.mark.parametrize("v, name, i, value, exc", FIELD_BAD)
def test_a_bad_field_is_refused_on_assignment_and_nothing_changes(v, name, i, value, exc):
    s = getattr(v, name)(*GOOD_FIELDS[name])
    before = bytes(s)
    with pytest.raises(exc):
        setattr(s, s._fields_[i][0], value)
    assert bytes(s) == before


def test_every_field_has_bad_cases():
    fields_seen = {(repr(p.values[0]), p.values[1], p.values[2]) for p in FIELD_BAD}
    assert len(fields_seen) == 2 * (2 + 3 + 6 + 3)  # Vec2 2, Body 3, Disk 6, Surface 3 fields per variant


def good_field_cases():
    out = []
    for v in VARIANTS:
        for name in STRUCT_NAMES:
            for i, (field, ftype) in enumerate(fields(v, name)):
                if ftype is v.real:
                    for what, value, stored in good_numbers(v):
                        out.append(pytest.param(v, name, i, value, (stored,), id=f"{v!r}-{name}.{field}-{what}"))
                else:
                    for what, value in good_sequences(v, "Vec2"):
                        out.append(pytest.param(v, name, i, value, GOOD_FIELDS["Vec2"],
                                                id=f"{v!r}-{name}.{field}-{what}"))
    return out


def same(got, want):
    return all((math.isnan(g) and math.isnan(w)) or g == w for g, w in zip(got, want))


@pytest.mark.parametrize("v, name, i, value, stored", good_field_cases())
def test_a_good_field_is_stored(v, name, i, value, stored):
    cls, ok = getattr(v, name), list(GOOD_FIELDS[name])
    field = cls._fields_[i][0]
    ok[i] = value
    got = getattr(cls(*ok), field)
    assert same(tuple(got) if isinstance(got, ctypes.Structure) else (got,), stored)
    s = cls(*GOOD_FIELDS[name])
    setattr(s, field, value)
    got = getattr(s, field)
    assert same(tuple(got) if isinstance(got, ctypes.Structure) else (got,), stored)


# ------------------------------------------------------------ constructors

@pytest.mark.parametrize("v", VARIANTS, ids=repr)
@pytest.mark.parametrize("name", STRUCT_NAMES)
def test_all_fields_or_none(v, name):
    cls, ok = getattr(v, name), GOOD_FIELDS[name]
    names = [f for f, _ in cls._fields_]
    assert bytes(cls()) == bytes(ctypes.sizeof(cls))  # no arguments: all zero, as C's {0}
    assert cls(*ok) == cls(**dict(zip(names, ok))) == cls(*ok[:1], **dict(zip(names[1:], ok[1:])))
    for k in range(1, len(ok)):  # every prefix but the whole: a missing field, never a zero
        with pytest.raises(TypeError, match="missing field"):
            cls(*ok[:k])
        with pytest.raises(TypeError, match="missing field"):
            cls(**dict(zip(names[:k], ok[:k])))
    with pytest.raises(TypeError, match="takes"):
        cls(*ok, 1.0)
    with pytest.raises(TypeError, match="no field 'bogus'"):
        cls(*ok, bogus=1.0)
    with pytest.raises(TypeError, match="twice"):
        cls(*ok, **{names[0]: ok[0]})


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
@pytest.mark.parametrize("name", STRUCT_NAMES)
def test_an_attribute_that_is_no_field_is_refused(v, name):
    s = getattr(v, name)(*GOOD_FIELDS[name])
    before = bytes(s)
    with pytest.raises(AttributeError, match="no field"):
        s.masss = 1.0
    assert bytes(s) == before and not hasattr(s, "masss")


# ------------------------------------------------------------ short sequences, odd values

def test_a_short_position_is_a_value_error():
    with pytest.raises(ValueError, match="Body.pos must be a Vec2 of 2 components"):
        c.Body((0,), (1, 0), 1.0)


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_a_short_or_dict_normal_is_refused(v):
    a, b = v.Body((0, 0), (1, 0), 1), v.Body((1, 0), (0, 0), 1)
    before = raw(a, b)
    with pytest.raises(ValueError, match="argument 3 must be a Vec2f? of 2 components"):
        v.collide_normal(a, b, (1,), 1.0)
    with pytest.raises(TypeError, match="argument 3 must be Vec2f? or a sequence"):
        v.collide_normal(a, b, {1: 2, 3: 4}, 1.0)
    assert raw(a, b) == before


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_a_short_surface_is_a_value_error(v):
    d1 = v.Disk((0, 0), (1, 0), 0.0, 1.0, 0.5, 0.125)
    d2 = v.Disk((1, 0.5), (0, 0), 0.0, 1.0, 0.5, 0.125)
    before = raw(d1, d2)
    with pytest.raises(ValueError, match="argument 3 must be a Surfacef? of 3 components"):
        v.collide_rough(d1, d2, (1,))
    with pytest.raises(ValueError, match="argument 4 must be a Surfacef? of 3 components"):
        v.collide_rough_normal(d1, d2, (1, 0), (0.5, 0.2))
    assert raw(d1, d2) == before
    assert v.collide_rough(d1, d2, (1, 0.4, 0.5)) is Status.OK  # and the full one works


@pytest.mark.parametrize("value, exc", params([
    ("huge int", 2 ** 2000, ValueError), ("str", "x", TypeError), ("None", None, TypeError),
    ("complex", 1j, TypeError), ("nested", ((1, 2), 0), TypeError), ("bool", True, TypeError),
]))
def test_bad_values_raise_value_or_type_error(value, exc):
    for make in (lambda: c.Body((value, 0), (1, 0), 1.0), lambda: c.Body((0, 0), (1, 0), value),
                 lambda: c.Vec2(value, 0)):
        try:
            make()
        except exc:
            pass
        except (RuntimeError, OverflowError) as e:  # what ctypes raised before
            pytest.fail(f"{type(e).__name__}: {e}")
        else:
            pytest.fail(f"{value!r} accepted")


# ------------------------------------------------------------ functions

BODY, VEC2, REAL, DISK, SURFACE = "body", "vec2", "real", "disk", "surface"
BALL, BALL_SURFACE, CUSHION = "ball", "ball surface", "cushion"


def function_cases(v):
    """(name, [(kind, good value)], status with the good values)."""
    a, b = (0.0, 0.0), (1.0, 0.0)
    body = lambda p, vel: ("body", (p, vel, 1.0))  # noqa: E731
    disk = lambda p, vel: ("disk", (p, vel, 0.0, 1.0, 0.5, 0.125))  # noqa: E731
    ball = lambda p, vel: ("ball", (p, vel, (0.0, 2.0, 1.0), 1.0, 0.5, 0.125))  # noqa: E731
    return [
        ("collide", [body(a, (1, 0)), body(b, (0, 0)), (REAL, 1.0)], Status.OK),
        ("collide_normal", [body(a, (1, 0)), body(b, (0, 0)), (VEC2, (1.0, 0.0)), (REAL, 1.0)], Status.OK),
        ("time_of_impact", [body(a, (1, 0)), body((3, 0), (0, 0)), (REAL, 1.0)], Status.OK),
        ("time_of_impact_accel", [body(a, (1, 0)), (VEC2, (0.0, 0.0)), body((3, 0), (0, 0)), (VEC2, (0.0, 0.0)),
                                  (REAL, 1.0), (REAL, 10.0)], Status.OK),
        ("collide_rough", [disk(a, (1, 0)), disk(b, (0, 0)), (SURFACE, (1.0, 0.4, 0.5))], Status.OK),
        ("collide_rough_normal", [disk(a, (1, 0)), disk(b, (0, 0)), (VEC2, (1.0, 0.0)), (SURFACE, (1.0, 0.4, 0.5))],
         Status.OK),
        ("collide_balls", [ball(a, (1, 0)), ball(b, (0, 0)), (BALL_SURFACE, (1.0, 0.25, 0.125, 1.0))], Status.OK),
        ("collide_cushion", [ball(a, (1, 0)), (CUSHION, ((1.0, 0.0), 0.75, 0.75, 0.25))], Status.OK),
    ]


def build(v, kind, value):
    cls = {BODY: v.Body, DISK: v.Disk, BALL: v.Ball}.get(kind)
    return cls(*value) if cls else value


def bad_arguments(v, kind):
    if kind == REAL:
        return bad_numbers(v)
    if kind == VEC2:
        return bad_sequences(v, 2, "Vec2")
    if kind == SURFACE:
        return bad_sequences(v, 3, "Surface")
    if kind in (BALL_SURFACE, CUSHION):  # four fields each; a cushion's first is its normal
        head = (0.5,) if kind == BALL_SURFACE else ((1.0, 0.0),)
        return [("one component short", head + (0.5,) * 2, ValueError), ("None", None, TypeError),
                ("a dict", {}, TypeError), ("a Surface", v.Surface(), TypeError),
                ("a text component", head + ("1",) + (0.5,) * 2, TypeError),
                ("a huge component", head + (2 ** 1024,) + (0.5,) * 2, ValueError)]
    own, twin = {BODY: (v.Body, v.other.Body), DISK: (v.Disk, v.other.Disk), BALL: (v.Ball, v.other.Ball)}[kind]
    other_kind = v.Disk if kind == BODY else v.Body
    return [("None", None, TypeError), ("its fields as a tuple", GOOD_FIELDS[own.__name__.rstrip("f")], TypeError),
            ("the other precision", twin(), TypeError), ("the other struct", other_kind(), TypeError),
            ("a dict", {}, TypeError), ("a number", 1.0, TypeError), ("a ctypes pointer", ctypes.pointer(own()),
                                                                           TypeError)]


def argument_cases():
    out = []
    for v in VARIANTS:
        for name, args, _ in function_cases(v):
            for i, (kind, _) in enumerate(args):
                for what, value, exc in bad_arguments(v, kind):
                    out.append(pytest.param(v, name, i, value, exc, id=f"{v!r}-{name}{v.sfx}-arg{i + 1}-{what}"))
    return out


ARGUMENT_BAD = argument_cases()


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_every_function_with_good_arguments(v):
    names = []
    for name, args, status in function_cases(v):
        values = [build(v, k, a) for k, a in args]
        got = getattr(v, name)(*values)
        assert (got if isinstance(got, Status) else got[0]) is status, name
        names.append(name + v.sfx)
    public = {n for n in c.__all__ if callable(getattr(c, n)) and n.startswith(("collide", "time_of"))
              and not n.startswith("collide_batch") and n.endswith("f") == (v is FLOAT)}
    assert set(names) == public  # every scalar function of the binding is covered here


@pytest.mark.parametrize("v, name, i, value, exc", ARGUMENT_BAD)
def test_a_bad_argument_is_refused_and_nothing_is_written(v, name, i, value, exc):
    (_, args, _), = [f for f in function_cases(v) if f[0] == name]
    values = [build(v, k, a) for k, a in args]
    bodies = [x for x in values if isinstance(x, ctypes.Structure)]
    before = raw(*bodies)
    values[i] = value
    with pytest.raises(exc, match=rf"{name}{v.sfx}: argument {i + 1}"):
        getattr(v, name)(*values)
    assert raw(*bodies) == before


def test_every_argument_has_bad_cases():
    seen = {(repr(p.values[0]), p.values[1], p.values[2]) for p in ARGUMENT_BAD}
    assert len(seen) == 2 * (3 + 4 + 3 + 6 + 3 + 4 + 3 + 2)


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
@pytest.mark.parametrize("what", ["list", "float64 array", "float32 array", "the other precision",
                                  "a row of a 2-D array"])
def test_a_normal_and_a_surface_in_any_accepted_form_give_the_same_bits(v, what):
    normal = dict(good_sequences(v, "Vec2"))[what]
    surface = dict(good_sequences(v, "Surface"))[what]
    a1, b1 = v.Body((0, 0), (1, 0.25), 2), v.Body((1, 0.5), (-1, 0), 3)
    a2, b2 = v.Body((0, 0), (1, 0.25), 2), v.Body((1, 0.5), (-1, 0), 3)
    assert v.collide_normal(a1, b1, v.Vec2(*GOOD_FIELDS["Vec2"]), 0.5) is v.collide_normal(a2, b2, normal, 0.5)
    assert raw(a1, b1) == raw(a2, b2)
    d = [v.Disk((0, 0), (1, 0), 0.5, 1.0, 0.5, 0.125) for _ in range(2)]
    e = [v.Disk((1, 0.5), (0, 0), 0.0, 1.0, 0.5, 0.125) for _ in range(2)]
    assert v.collide_rough(d[0], e[0], v.Surface(*GOOD_FIELDS["Surface"])) is Status.OK
    assert v.collide_rough(d[1], e[1], surface) is Status.OK
    assert raw(d[0], e[0]) == raw(d[1], e[1])


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
@pytest.mark.parametrize("field", ["pos.x", "pos.y", "vel.x", "vel.y", "mass"])
@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf], ids=["nan", "inf", "-inf"])
def test_nan_and_inf_reach_the_library_which_says_invalid(v, field, bad):
    a, b = v.Body((0, 0), (1, 0), 1), v.Body((1, 0), (0, 0), 1)
    if "." in field:
        vec = getattr(a, field[:3])
        setattr(vec, field[4], bad)
    else:
        a.mass = bad
    want = Status.OK if (field, bad) == ("mass", math.inf) else Status.INVALID  # an infinite mass: a wall
    assert v.collide(a, b, 1.0) is want
    assert v.collide_normal(a, b, (bad, 0), 1.0) is Status.INVALID
    assert v.collide(v.Body((0, 0), (1, 0), 1), v.Body((1, 0), (0, 0), 1), bad) is Status.INVALID


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_infinities_that_are_values(v):
    a, b = v.Body((0, 0), (1, 0), 1), v.Body((3, 0), (0, 0), 1)
    assert v.time_of_impact_accel(a, (0, 0), b, (0, 0), 1.0, math.inf) == (Status.OK, 2.0)
    d = v.Disk((0, 0), (1, 0), 0.0, 1.0, 0.5, math.inf)
    e = v.Disk((1, 0.5), (0, 0), 0.0, math.inf, 0.5, math.inf)
    assert v.collide_rough(d, e, (1.0, math.inf, 0.5)) is Status.OK


# ------------------------------------------------------------ status_string

@pytest.mark.parametrize("value, want", [
    (Status.OK, "ok"), (Status.RANGE, "range"), (0, "ok"), (np.int64(1), "separating"), (np.intc(3), "invalid"),
    (-1, "unknown"), (5, "unknown"), (2 ** 31 - 1, "unknown"), (-2 ** 31, "unknown"),
], ids=repr)
def test_status_string_accepts_ints_within_c_int(value, want):
    assert c.status_string(value) == want


@pytest.mark.parametrize("value, exc", params([
    ("2**40", 2 ** 40, ValueError), ("2**31", 2 ** 31, ValueError), ("-2**31-1", -2 ** 31 - 1, ValueError),
    ("2**32", 2 ** 32, ValueError), ("2**70", 2 ** 70, ValueError), ("2**20000", 2 ** 20000, ValueError),
    ("numpy 2**40", np.int64(2 ** 40), ValueError),
    ("str", "0", TypeError), ("float", 0.0, TypeError), ("numpy float", np.float64(1), TypeError),
    ("None", None, TypeError), ("bool", True, TypeError), ("complex", 0j, TypeError), ("tuple", (0,), TypeError),
]))
def test_status_string_refuses_what_c_would_truncate(value, exc):
    with pytest.raises(exc, match="status_string"):
        c.status_string(value)


# ------------------------------------------------------------ batch restitution

BATCHES = [pytest.param((DOUBLE, np.float64, c.collide_batch), id="double"),
           pytest.param((FLOAT, np.float32, c.collide_batchf), id="float")]


def batch_restitution_cases():
    out = []
    for p in BATCHES:
        v = p.values[0][0]
        for what, value, exc in bad_numbers(v):
            out.append(pytest.param(p.values[0], value, exc, id=f"{p.id}-{what}"))
    return out


@pytest.mark.parametrize("b, value, exc", batch_restitution_cases())
def test_batch_restitution_is_checked_and_nothing_is_written(b, value, exc):
    _, dtype, batch = b
    pos_a, pos_b = np.zeros((2, 4), dtype), np.vstack([np.ones(4), np.zeros(4)]).astype(dtype)
    vel_a, vel_b = np.vstack([np.ones(4), np.zeros(4)]).astype(dtype), np.zeros((2, 4), dtype)
    status = np.full(4, -1, np.intc)
    before = vel_a.tobytes() + vel_b.tobytes() + status.tobytes()
    with pytest.raises(exc, match="restitution"):
        batch(pos_a, pos_b, vel_a, vel_b, np.ones(4, dtype), np.ones(4, dtype), value, status)
    assert vel_a.tobytes() + vel_b.tobytes() + status.tobytes() == before
    assert batch(pos_a, pos_b, vel_a, vel_b, np.ones(4, dtype), np.ones(4, dtype), np.float32(1), status) == 4


@pytest.mark.parametrize("b", BATCHES)
def test_batch_rows_of_a_wrong_count_are_a_value_error(b):
    _, dtype, batch = b
    z = np.zeros(4, dtype)
    with pytest.raises(ValueError, match="pos_a as rows must be a pair"):
        batch((z, z, z), np.zeros((2, 4), dtype), np.zeros((2, 4), dtype), np.zeros((2, 4), dtype), z + 1, z + 1, 1.0)
