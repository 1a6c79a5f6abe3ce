# SPDX-License-Identifier: MIT
"""Pool balls as spheres through the binding (collide_balls, collide_cushion
and their float twins), each checked against an independent calculation:
the rough-disk model (another C function) where the sphere model reduces to
it, collide where there is no friction, closed forms computed here in
Python, and the conservation laws with the documented error bounds."""
import math
import random

import numpy as np
import pytest

import collide2d as c
from collide2d import Status
from variants import DOUBLE, FLOAT, VARIANTS

M, R = 0.17, 0.028575  # a pool ball (kg, m)
CASES = 2000
BALLS_ULP, CUSHION_ULP, ROUGH_ULP = 24, 16, 18  # the header's bounds


def ulp(scale, v):
    return math.ldexp(1.0, math.frexp(scale)[1] - (53 if v is DOUBLE else 24))


def random_pair(rng, v, pool):
    """Two balls touching in a random direction, approaching; pool-like or
    of mixed masses, radii and inertias."""
    def one():
        m = M if pool else math.exp(rng.uniform(math.log(0.01), math.log(10)))
        r = R if pool else math.exp(rng.uniform(math.log(0.01), math.log(1)))
        k = 0.4 if pool else rng.uniform(0.1, 1)
        s = 3 if pool else 1
        return [(rng.uniform(-s, s), rng.uniform(-s, s)), [rng.uniform(-s, s) / r for _ in range(3)], m, r, k * m * r * r]
    a, b = one(), one()
    th = rng.uniform(0, 2 * math.pi)
    d = a[3] + b[3]
    pb = (d * math.cos(th), d * math.sin(th))
    gn = (b[0][0] - a[0][0]) * pb[0] + (b[0][1] - a[0][1]) * pb[1]
    if gn > 0:
        a[0], b[0] = (-a[0][0], -a[0][1]), (-b[0][0], -b[0][1])
    elif gn == 0:
        b[0] = (-pb[0] / d, -pb[1] / d)
    ball_a = v.Ball((0, 0), a[0], a[1], a[2], a[3], a[4])
    ball_b = v.Ball(pb, b[0], b[1], b[2], b[3], b[4])
    return ball_a, ball_b


def outputs(ball):
    return [ball.vel.x, ball.vel.y] + [w * ball.radius for w in ball.spin]


def pair_scale(before, after):
    return max(abs(x) for x in before + after)


def resolved(v, a, b, surface):
    a0, b0 = v.Ball(*a._values()), v.Ball(*b._values())
    st = v.collide_balls(a, b, surface)
    return st, a0, b0


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_spin_about_the_vertical_only_is_the_rough_disk(v):
    rng, n = random.Random(21), 0
    for i in range(CASES):
        a, b = random_pair(rng, v, pool=i % 2 == 0)
        a.spin = (0, 0, a.spin[2])
        b.spin = (0, 0, b.spin[2])
        e, mu = rng.uniform(0.5, 1), rng.uniform(0, 0.5)
        da = v.Disk(a.pos, a.vel, a.spin[2], a.mass, a.radius, a.inertia)
        db = v.Disk(b.pos, b.vel, b.spin[2], b.mass, b.radius, b.inertia)
        st, a0, b0 = resolved(v, a, b, (e, mu, 0, 0))
        assert st is Status.OK and v.collide_rough(da, db, (e, mu, 0)) is Status.OK
        got = outputs(a) + outputs(b)
        want = [da.vel.x, da.vel.y, 0, 0, da.spin * da.radius, db.vel.x, db.vel.y, 0, 0, db.spin * db.radius]
        tol = (BALLS_ULP + ROUGH_ULP) * ulp(pair_scale(outputs(a0) + outputs(b0), got), v)
        assert all(abs(g - w) <= tol for g, w in zip(got, want)), (got, want)
        n += 1
    assert n == CASES


def energy(ball):
    return 0.5 * ball.mass * (ball.vel.x ** 2 + ball.vel.y ** 2) + 0.5 * ball.inertia * sum(w * w for w in ball.spin)


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_energy_is_never_gained_and_momentum_is_kept(v):
    """Tolerances from the 24-ulp bound on each output (as the C tests)."""
    rng, n = random.Random(22), 0
    for i in range(CASES):
        a, b = random_pair(rng, v, pool=i % 2 == 0)
        surface = (rng.uniform(0.5, 1), 9.951e-3, 0.108, 1.088) if i % 3 else (1.0, rng.uniform(0, 1), 0, 0)
        st, a0, b0 = resolved(v, a, b, surface)
        assert st is Status.OK
        du = BALLS_ULP * ulp(pair_scale(outputs(a0) + outputs(b0), outputs(a) + outputs(b)), v)
        grow = sum(d.mass * sum(abs(x) for x in d.vel) + d.inertia / d.radius * sum(abs(w) for w in d.spin)
                   for d in (a, b)) * 2 * du
        e0, e1 = energy(a0) + energy(b0), energy(a) + energy(b)
        assert e1 <= e0 + grow + 8 * np.finfo(float).eps * e0
        for k in ("x", "y"):
            p0 = a0.mass * getattr(a0.vel, k) + b0.mass * getattr(b0.vel, k)
            p1 = a.mass * getattr(a.vel, k) + b.mass * getattr(b.vel, k)
            assert abs(p1 - p0) <= (a.mass + b.mass) * du + 8 * np.finfo(float).eps * (a.mass + b.mass) * 3
        n += 1
    assert n == CASES


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_without_friction_it_is_collide_bit_for_bit(v):
    rng = random.Random(23)
    for i in range(200):
        a, b = random_pair(rng, v, pool=i % 2 == 0)
        ba, bb = v.Body(a.pos, a.vel, a.mass), v.Body(b.pos, b.vel, b.mass)
        spin = a.spin[:]
        assert v.collide_balls(a, b, (0.9, 0, 0, 0)) is Status.OK and v.collide(ba, bb, 0.9) is Status.OK
        assert (tuple(a.vel), tuple(b.vel)) == (tuple(ba.vel), tuple(bb.vel))
        assert a.spin[:] == spin


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_a_rolling_ball_into_a_rail_loses_topspin_as_derived(v):
    """Head on at h = 0.635 D, rolling (wy = v / R): sin th = 0.27, the slip
    s2 = -(1 + sin th) v, Pn = (1 + e) m cos th v, sliding throughout
    (mu Pn < |s2| 2m/7), so vx' = v (1 - (1 + e) cos^2 th - mu (1 + e) cos th
    sin th) and R wy' = v - (5/2) mu Pn / m."""
    e, mu, vel, h = 0.8, 0.2, 1.5, 0.635 * 2 * R
    sn = (h - R) / R
    cs = math.sqrt(1 - sn * sn)
    pn = (1 + e) * M * cs * vel
    assert mu * pn < (1 + sn) * vel * 2 * M / 7
    ball = v.Ball((0, 0), (vel, 0), (0, vel / R, 0), M, R, 0.4 * M * R * R)
    assert v.collide_cushion(ball, ((1, 0), h, e, mu)) is Status.OK
    tol = 64 * ulp(vel, v)
    assert abs(ball.vel.x - vel * (1 - (1 + e) * cs * cs - mu * (1 + e) * cs * sn)) <= tol
    assert abs(ball.spin[1] * R - (vel - 2.5 * mu * pn / M)) <= tol
    assert ball.vel.y == 0 and ball.spin[0] == 0 and ball.spin[2] == 0


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_a_cushion_at_the_centre_height_is_the_rough_wall(v):
    rng = random.Random(24)
    for _ in range(500):
        th = rng.uniform(0, 2 * math.pi)
        normal = (math.cos(th), math.sin(th))
        vn, vt = rng.uniform(0.1, 3), rng.uniform(-3, 3)
        vel = (normal[0] * vn - normal[1] * vt, normal[1] * vn + normal[0] * vt)
        wz, e, mu = rng.uniform(-100, 100), rng.uniform(0.5, 1), rng.uniform(0, 0.4)
        ball = v.Ball((0, 0), vel, (0, 0, wz), M, R, 0.4 * M * R * R)
        disk = v.Disk((0, 0), vel, wz, M, R, 0.4 * M * R * R)
        wall = v.Disk((0, 0), (0, 0), 0, math.inf, 0, math.inf)
        before = outputs(ball)
        assert v.collide_cushion(ball, (normal, R, e, mu)) is Status.OK
        assert v.collide_rough_normal(disk, wall, normal, (e, mu, 0)) is Status.OK
        tol = (CUSHION_ULP + ROUGH_ULP) * ulp(pair_scale(before, outputs(ball)), v)
        want = [disk.vel.x, disk.vel.y, 0, 0, disk.spin * R]
        assert all(abs(g - w) <= tol for g, w in zip(outputs(ball), want))


def test_float_is_the_double_result_to_float_accuracy():
    rng = random.Random(25)
    for i in range(500):
        a, b = random_pair(rng, FLOAT, pool=True)
        ad, bd = c.Ball(*a._values()), c.Ball(*b._values())
        assert c.collide_ballsf(a, b, (0.95, 0.05, 0, 0)) is Status.OK
        assert c.collide_balls(ad, bd, (np.float32(0.95), np.float32(0.05), 0, 0)) is Status.OK
        got, want = outputs(a) + outputs(b), outputs(ad) + outputs(bd)
        tol = BALLS_ULP * ulp(pair_scale(got, want), FLOAT) + BALLS_ULP * ulp(pair_scale(got, want), DOUBLE)
        assert all(abs(g - w) <= tol for g, w in zip(got, want))


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_a_spin_is_three_checked_numbers(v):
    ball = v.Ball((0, 0), (1, 0), np.array([1.0, 2.0, 3.0]), M, R, 0.4 * M * R * R)
    assert ball.spin[:] == [1.0, 2.0, 3.0] and "spin=(1.0, 2.0, 3.0)" in repr(ball)
    assert v.Ball(*ball._values()) == ball
    for bad, exc in (((1, 2), ValueError), ((1, 2, 3, 4), ValueError), ("abc", TypeError), (1.0, TypeError),
                     ((1, "2", 3), TypeError), ((1, 2, 2 ** 1024), ValueError), (np.zeros((3, 1)), ValueError)):
        before = bytes(ball)
        with pytest.raises(exc, match=r"Ballf?\.spin"):
            ball.spin = bad
        assert bytes(ball) == before


@pytest.mark.parametrize("v", VARIANTS, ids=repr)
def test_bad_input_is_invalid_and_leaves_the_balls_untouched(v):
    a = v.Ball((0, 0), (1, 0), (0, math.nan, 0), M, R, 0.4 * M * R * R)
    b = v.Ball((2 * R, 0), (0, 0), (0, 0, 0), M, R, 0.4 * M * R * R)
    before = bytes(a) + bytes(b)
    assert v.collide_balls(a, b, (0.95, 0.05, 0, 0)) is Status.INVALID
    assert v.collide_cushion(a, ((1, 0), 0.036, 0.8, 0.2)) is Status.INVALID
    a.spin = (0, 0, 0)
    before = bytes(a)
    assert v.collide_cushion(a, ((1, 0), 3 * R, 0.8, 0.2)) is Status.INVALID  # above the ball
    assert bytes(a) == before
