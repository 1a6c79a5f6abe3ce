# SPDX-License-Identifier: MIT
"""The batch entry points on numpy arrays: bit-identical to the scalar
calls, in place, and every bad argument a TypeError or ValueError."""
import math

import numpy as np
import pytest

import collide2d as c
from collide2d import Status

VARIANTS = [
    pytest.param((np.float64, c.collide_batch, c.Body, c.collide), id="double"),
    pytest.param((np.float32, c.collide_batchf, c.Bodyf, c.collidef), id="float"),
]


def scene(dtype, n, seed=1):
    rng = np.random.default_rng(seed)
    pos_a = rng.uniform(-1, 1, (2, n)).astype(dtype)
    pos_b = (pos_a + rng.uniform(-1, 1, (2, n))).astype(dtype)
    vel_a = rng.uniform(-3, 3, (2, n)).astype(dtype)
    vel_b = rng.uniform(-3, 3, (2, n)).astype(dtype)
    mass_a = rng.uniform(0.1, 5, n).astype(dtype)
    mass_b = rng.uniform(0.1, 5, n).astype(dtype)
    mass_b[::7] = np.inf
    vel_a[0, ::11] = np.nan  # some refusals among them
    mass_a[5::13] = -1
    pos_b[:, 3::17] = pos_a[:, 3::17]
    return pos_a, pos_b, vel_a, vel_b, mass_a, mass_b


@pytest.mark.parametrize("v", VARIANTS)
def test_batch_is_the_scalar_call_bit_for_bit(v):
    dtype, batch, Body, collide = v
    n = 1000
    pos_a, pos_b, vel_a, vel_b, mass_a, mass_b = scene(dtype, n)
    want_a, want_b, want_s = vel_a.copy(), vel_b.copy(), []
    for i in range(n):
        a = Body(pos_a[:, i], vel_a[:, i], mass_a[i])  # numpy rows as the (x, y) of a Vec2
        b = Body(pos_b[:, i], vel_b[:, i], mass_b[i])
        want_s.append(collide(a, b, 0.9))
        want_a[:, i], want_b[:, i] = tuple(a.vel), tuple(b.vel)
    status = np.full(n, -1, dtype=np.intc)
    count = batch(pos_a, pos_b, vel_a, vel_b, mass_a, mass_b, 0.9, status)
    assert [Status(s) for s in status] == want_s
    assert count == want_s.count(Status.OK)
    assert 0 < count < n
    assert vel_a.tobytes() == want_a.tobytes() and vel_b.tobytes() == want_b.tobytes()


@pytest.mark.parametrize("v", VARIANTS)
def test_row_pairs_and_no_status(v):
    dtype, batch, _, _ = v
    arrays = scene(dtype, 64)
    copy = [x.copy() for x in arrays]
    n1 = batch(*arrays, 1.0)
    pos_a, pos_b, vel_a, vel_b, mass_a, mass_b = copy
    n2 = batch((pos_a[0], pos_a[1]), [pos_b[0], pos_b[1]], (vel_a[0], vel_a[1]), (vel_b[0], vel_b[1]),
               mass_a, mass_b, 1.0)
    assert n1 == n2
    assert arrays[2].tobytes() == vel_a.tobytes() and arrays[3].tobytes() == vel_b.tobytes()


@pytest.mark.parametrize("v", VARIANTS)
def test_empty_batch(v):
    dtype, batch, _, _ = v
    e2, e1 = np.empty((2, 0), dtype), np.empty(0, dtype)
    assert batch(e2, e2.copy(), e2.copy(), e2.copy(), e1, e1.copy(), 1.0, np.empty(0, np.intc)) == 0


def bad_calls(dtype):
    """(what, change, exception, message) for every kind of bad argument."""
    other = np.float32 if dtype == np.float64 else np.float64
    return [
        ("wrong dtype", lambda a: a.__setitem__(2, a[2].astype(other)), TypeError, "vel_a.* dtype"),
        ("integer masses", lambda a: a.__setitem__(4, np.ones(8, int)), TypeError, "mass_a must have dtype"),
        ("a list", lambda a: a.__setitem__(0, a[0].tolist()), TypeError, "pos_a.* must be a numpy array"),
        ("a list of rows", lambda a: a.__setitem__(0, [[1.0] * 8, [2.0] * 8]), TypeError, "must be a numpy array"),
        ("(n, 2) shape", lambda a: a.__setitem__(1, np.ascontiguousarray(a[1].T)), ValueError, "shape \\(2, n\\)"),
        ("3 rows", lambda a: a.__setitem__(3, np.zeros((3, 8), dtype)), ValueError, "shape \\(2, n\\)"),
        ("short mass", lambda a: a.__setitem__(5, a[5][:7]), ValueError, "same length"),
        ("short row", lambda a: a.__setitem__(2, (a[2][0], a[2][1][:7])), ValueError, "vel_a\\[1\\] has 7"),
        ("2-D mass", lambda a: a.__setitem__(4, a[4].reshape(2, 4)), ValueError, "1-D"),
        ("strided rows", lambda a: a.__setitem__(0, np.zeros((2, 16), dtype)[:, ::2]), ValueError, "contiguous"),
        ("read-only velocity", lambda a: a[3].setflags(write=False), ValueError, "read-only"),
        ("shared velocities", lambda a: a.__setitem__(3, a[2]), ValueError, "must not share memory"),
        ("velocity as position", lambda a: a.__setitem__(0, a[2]), ValueError, "must not share memory"),
        ("restitution text", lambda a: a.__setitem__(6, "1"), TypeError, "restitution"),
        ("status dtype", lambda a: a.__setitem__(7, np.zeros(8, np.int64)), TypeError, "status"),
        ("status length", lambda a: a.__setitem__(7, np.zeros(9, np.intc)), ValueError, "status has 9"),
        ("status in the masses", lambda a: a.__setitem__(7, a[4].view(np.intc)[:8]), None, None),
    ]


@pytest.mark.parametrize("v", VARIANTS)
def test_bad_arguments_raise_and_write_nothing(v):
    dtype, batch, _, _ = v
    cases, checked = bad_calls(dtype), 0
    for what, change, exc, message in cases:
        args = list(scene(dtype, 8)) + [1.0, np.zeros(8, np.intc)]
        change(args)
        checked += 1
        if exc is None:  # a dtype error or an overlap, whichever applies
            with pytest.raises((TypeError, ValueError)):
                batch(*args)
            continue
        before = [x.copy() if isinstance(x, np.ndarray) else x for x in args]
        with pytest.raises(exc, match=message):
            batch(*args)
        for x, y in zip(args, before):
            if isinstance(x, np.ndarray):
                assert x.tobytes() == y.tobytes(), what
    assert checked == len(cases) == 17


def test_wall_batch_matches_closed_form():
    n = 100
    rng = np.random.default_rng(3)
    pos_a = np.zeros((2, n))
    pos_b = np.vstack([np.ones(n), np.zeros(n)])  # the wall along +x
    vel_a = np.vstack([rng.uniform(0.1, 2, n), rng.uniform(-1, 1, n)])
    want = vel_a.copy()
    want[0] *= -0.5
    vel_b = np.zeros((2, n))
    assert c.collide_batch(pos_a, pos_b, vel_a, vel_b, np.ones(n), np.full(n, math.inf), 0.5) == n
    np.testing.assert_allclose(vel_a, want, rtol=1e-15, atol=0)
    assert not vel_b.any()
