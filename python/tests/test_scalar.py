# SPDX-License-Identifier: MIT
"""The scalar entry points, double and float, through the binding."""
import math
import random

import pytest

import collide2d as c
from collide2d import Status
from variants import VARIANTS

variant = pytest.mark.parametrize("v", VARIANTS, ids=repr)


def raw(*structs):
    return b"".join(bytes(s) for s in structs)


@variant
def test_readme_two_body(v):
    a, b = v.Body((0, 0), (1, 0), 1), v.Body((1, 1), (0, 0), 1)
    assert v.collide(a, b, 1.0) is Status.OK
    assert tuple(a.vel) == (0.5, -0.5) and tuple(b.vel) == (0.5, 0.5)
    wall = v.Body((2, 1), (0, 0), math.inf)
    assert v.collide_normal(b, wall, (1, 0), 0.8) is Status.OK
    assert b.vel.x == pytest.approx(-0.4, rel=2 ** -21) and b.vel.y == 0.5  # double: -0.4 exactly
    assert tuple(wall.vel) == (0, 0)


@variant
def test_normal_as_struct_or_sequence(v):
    a1, b1 = v.Body((0, 0), (1, 0.25), 2), v.Body((1, 0.5), (-1, 0), 3)
    a2, b2 = v.Body((0, 0), (1, 0.25), 2), v.Body((1, 0.5), (-1, 0), 3)
    assert v.collide_normal(a1, b1, v.Vec2(3, 1), 0.5) is v.collide_normal(a2, b2, [3, 1], 0.5) is Status.OK
    assert raw(a1, b1) == raw(a2, b2)


@variant
def test_time_of_impact(v):
    a, b = v.Body((0, 0), (1, 0), 1), v.Body((3, 0), (-1, 0), 1)
    assert v.time_of_impact(a, b, 1.0) == (Status.OK, 1.0)
    assert v.time_of_impact(a, b, 3.5) == (Status.OK, 0.0)  # already overlapping, approaching
    b.vel = (2, 0)
    assert v.time_of_impact(a, b, 1.0) == (Status.SEPARATING, None)
    assert v.time_of_impact(a, b, -1.0) == (Status.INVALID, None)


@variant
def test_a_decelerating_ball_hits_only_if_it_reaches(v):
    # a rolls from 0 at speed 2 and slows at 1: it travels 2 t - t^2 / 2, at most 2 (at t = 2)
    a, b = v.Body((0, 0), (2, 0), 1), v.Body((3, 0), (0, 0), 1)
    slowing, still = (-1, 0), (0, 0)
    assert v.time_of_impact_accel(a, slowing, b, still, 1.5) == (Status.OK, 1.0)
    assert v.time_of_impact_accel(a, slowing, b, still, 1.5, 0.5) == (Status.SEPARATING, None)
    assert v.time_of_impact_accel(a, slowing, b, still, 1.0) == (Status.SEPARATING, None)  # stops touching: a graze
    assert v.time_of_impact_accel(a, slowing, b, still, 0.5) == (Status.SEPARATING, None)  # stops short
    assert v.time_of_impact_accel(a, still, b, still, 1.0) == v.time_of_impact(a, b, 1.0)
    assert v.time_of_impact_accel(a, (math.nan, 0), b, still, 1.0) == (Status.INVALID, None)


@variant
@pytest.mark.parametrize("bad, status", [
    ({"a_vel": (math.nan, 0)}, Status.INVALID),
    ({"a_vel": (math.inf, 0)}, Status.INVALID),
    ({"a_mass": 0.0}, Status.INVALID),
    ({"a_mass": -1.0}, Status.INVALID),
    ({"e": 1.5}, Status.INVALID),
    ({"e": math.nan}, Status.INVALID),
    ({"b_pos": (0, 0)}, Status.DEGENERATE),
    ({"a_mass": math.inf, "b_mass": math.inf}, Status.DEGENERATE),
    ({"a_vel": (-1, 0)}, Status.SEPARATING),
], ids=lambda x: repr(x) if isinstance(x, dict) else None)
def test_refusals_leave_bodies_untouched(v, bad, status):
    a = v.Body((0, 0), bad.get("a_vel", (1, 0)), bad.get("a_mass", 1.0))
    b = v.Body(bad.get("b_pos", (1, 0)), (0, 0), bad.get("b_mass", 1.0))
    before = raw(a, b)
    assert v.collide(a, b, bad.get("e", 1.0)) is status
    assert raw(a, b) == before


@variant
def test_type_errors(v):
    a, b = v.Body((0, 0), (1, 0), 1), v.Body((1, 0), (0, 0), 1)
    other = c.Bodyf if v.sfx == "" else c.Body
    with pytest.raises(TypeError, match="argument 1 must be Body"):
        v.collide(other(), b, 1.0)
    with pytest.raises(TypeError, match="argument 2"):
        v.collide(a, None, 1.0)
    with pytest.raises(TypeError, match="argument 3 must be a real number"):
        v.collide(a, b, "1")
    with pytest.raises(TypeError):
        v.collide(a, b)
    with pytest.raises(ValueError, match="argument 3 must be a Vec2f? of 2 components"):
        v.collide_normal(a, b, (1, 2, 3), 1.0)
    with pytest.raises(TypeError, match="argument 3 must be Surface"):
        v.collide_rough(v.Disk(), v.Disk(), "rough")
    assert tuple(a.vel) == (1, 0)


@variant
def test_elastic_impacts_conserve_momentum_and_energy(v):
    rng = random.Random(13)
    tol = 1e-13 if v.sfx == "" else 1e-5
    hits = 0
    for _ in range(200):
        a = v.Body((0, 0), (rng.uniform(-5, 5), rng.uniform(-5, 5)), rng.uniform(0.1, 10))
        b = v.Body((rng.uniform(-2, 2), rng.uniform(-2, 2)), (rng.uniform(-5, 5), rng.uniform(-5, 5)),
                   rng.uniform(0.1, 10))
        p0 = (a.mass * a.vel.x + b.mass * b.vel.x, a.mass * a.vel.y + b.mass * b.vel.y)
        e0 = a.mass * (a.vel.x ** 2 + a.vel.y ** 2) + b.mass * (b.vel.x ** 2 + b.vel.y ** 2)
        if v.collide(a, b, 1.0) is not Status.OK:
            continue
        hits += 1
        scale = math.sqrt(e0 * (a.mass + b.mass))
        assert abs(a.mass * a.vel.x + b.mass * b.vel.x - p0[0]) <= tol * scale
        assert abs(a.mass * a.vel.y + b.mass * b.vel.y - p0[1]) <= tol * scale
        assert abs(a.mass * (a.vel.x ** 2 + a.vel.y ** 2) + b.mass * (b.vel.x ** 2 + b.vel.y ** 2) - e0) <= tol * e0
    assert hits > 50, hits  # about half of the random pairs approach


def rough_pair(v, rng):
    ra, rb = rng.uniform(0.2, 1), rng.uniform(0.2, 1)
    angle = rng.uniform(0, 2 * math.pi)
    ma, mb = rng.uniform(0.5, 5), rng.uniform(0.5, 5)
    a = v.Disk((0, 0), (rng.uniform(-3, 3), rng.uniform(-3, 3)), rng.uniform(-5, 5), ma, ra, ma * ra * ra / 2)
    b = v.Disk(((ra + rb) * math.cos(angle), (ra + rb) * math.sin(angle)), (rng.uniform(-3, 3), rng.uniform(-3, 3)),
               rng.uniform(-5, 5), mb, rb, mb * rb * rb / 2)
    return a, b


@variant
def test_rough_without_friction_is_collide_bit_for_bit(v):
    rng = random.Random(7)
    for surface in [(0.9, 0.0, 0.5), (0.9, 0.7, -1.0)]:
        for _ in range(50):
            a, b = rough_pair(v, rng)
            pa, pb = v.Body(a.pos, a.vel, a.mass), v.Body(b.pos, b.vel, b.mass)
            spins = (a.spin, b.spin)
            s = v.collide_rough(a, b, surface)
            assert s is v.collide(pa, pb, surface[0])
            assert raw(a.vel, b.vel) == raw(pa.vel, pb.vel)
            assert (a.spin, b.spin) == spins


@variant
def test_rough_conserves_momenta_and_never_gains_energy(v):
    rng = random.Random(11)
    tol = 1e-12 if v.sfx == "" else 1e-4
    hits = 0
    for _ in range(200):
        a, b = rough_pair(v, rng)
        def momenta():
            px = a.mass * a.vel.x + b.mass * b.vel.x
            py = a.mass * a.vel.y + b.mass * b.vel.y
            # angular momentum about the origin: r x p + I w
            lz = sum(d.pos.x * d.mass * d.vel.y - d.pos.y * d.mass * d.vel.x + d.inertia * d.spin for d in (a, b))
            e = sum(d.mass * (d.vel.x ** 2 + d.vel.y ** 2) + d.inertia * d.spin ** 2 for d in (a, b)) / 2
            return px, py, lz, e
        before = momenta()
        if v.collide_rough(a, b, v.Surface(0.8, 0.4, 0.6)) is not Status.OK:
            continue
        hits += 1
        after = momenta()
        scale = 1 + max(abs(x) for x in before)
        for k in range(3):
            assert abs(after[k] - before[k]) <= tol * scale
        assert after[3] <= before[3] * (1 + tol)
    assert hits > 50


@variant
def test_rough_cushion_spins_the_ball(v):
    m, r = 0.17, 0.028575
    ball = v.Disk((0, 0), (1.0, 0.5), 0.0, m, r, 0.4 * m * r * r)
    cushion = v.Disk((r, 0), (0, 0), 0.0, math.inf, 0.0, math.inf)
    assert v.collide_rough_normal(ball, cushion, (1, 0), (0.8, 0.2, 0.5)) is Status.OK
    assert ball.vel.x == pytest.approx(-0.8, rel=1e-6)
    assert ball.spin != 0 and ball.vel.y < 0.5
    assert tuple(cushion.vel) == (0, 0) and cushion.spin == 0
