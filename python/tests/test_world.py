# SPDX-License-Identifier: MIT
"""collide2d.World, the event-driven world (collide2d_world.h): physics
(velocity exchange, energy over many impacts), the bulk arrays against
get(), frame independence bit for bit, set_velocity, remove, stats, the
event callback, and the checks of every argument."""
import fractions
import math

import numpy as np
import pytest

import collide2d as c2d
from collide2d import Boundary, EventKind, Status, World, WorldError


def pair(**kw):
    """The header's example: a at (1, 1) moving +x, b at rest at (3, 1)."""
    w = World(10, 2, capacity=2, **kw)
    return w, w.add((1, 1), (1, 0), 1.0, 0.5), w.add((3, 1), (0, 0), 1.0, 0.5)


def gas(side=8, eta=0.3, seed=3, **kw):
    """side^2 unit disks (radius 0.5) on a lattice in a periodic box, random velocities."""
    n = side * side
    box = math.sqrt(n * math.pi / (4 * eta))
    g = box / side
    k = np.arange(n)
    pos = np.column_stack([(k % side + 0.5) * g, (k // side + 0.5) * g])
    vel = np.random.default_rng(seed).uniform(-1, 1, (n, 2))
    w = World(box, box, capacity=n, boundary="periodic", **kw)
    w.add_many(pos, vel, 1.0, 0.5)
    return w


def kinetic(w, mass=1.0):
    return 0.5 * mass * float(np.sum(w.velocities() ** 2))


def bits(a):
    return np.ascontiguousarray(a).tobytes()


# ------------------------------------------------ physics

def test_two_disks_exchange_velocities():
    w, ia, ib = pair()
    assert (ia, ib) == (0, 1) and w.count == len(w) == 2
    w.advance(2.0)  # they meet at t = 1
    a, b = w.get(ia), w.get(ib)
    assert tuple(a.vel) == (0.0, 0.0) and tuple(b.vel) == (1.0, 0.0)
    assert tuple(a.pos) == (2.0, 1.0) and tuple(b.pos) == (4.0, 1.0)
    assert a.mass == b.mass == 1.0
    s = w.stats
    assert (s.collisions, s.wall_collisions, s.time) == (1, 0, 2.0)
    assert s.virial == 1.0  # r_ab = (1, 0) at contact, impulse on b (1, 0)
    assert w.time == 2.0


def test_energy_is_conserved_at_e_1_in_a_periodic_gas():
    w = gas()
    e0 = kinetic(w)
    p0 = w.velocities().sum(axis=0)
    w.advance(2500.0)
    assert w.stats.collisions > 100000 and w.stats.wall_collisions == 0
    assert abs(kinetic(w) - e0) / e0 < 1e-12
    assert np.allclose(w.velocities().sum(axis=0), p0, rtol=0, atol=1e-12)
    x = w.positions()
    assert np.all((x >= 0) & (x <= w.width))


def test_walls_reflect_and_count():
    w = World(4, 4, capacity=1)
    w.add((2, 2), (1, 0.5), 1.0, 0.5)
    w.advance(1.5)  # x = 3.5 at t = 1.5: the wall x = 4
    assert tuple(w.get(0).vel) == (-1.0, 0.5) and w.stats.wall_collisions == 1


def test_inelastic_world_loses_energy():
    w = gas(restitution=0.5)
    e0 = kinetic(w)
    w.advance(5.0)
    assert kinetic(w) < 0.5 * e0


# ------------------------------------------------ the bulk arrays

def test_positions_and_velocities_agree_with_get():
    w = gas(side=6)
    w.advance(3.25)
    x, v = w.positions(), w.velocities()
    assert x.shape == v.shape == (36, 2) and x.dtype == v.dtype == np.float64
    for i in range(w.count):
        b = w.get(i)
        assert (b.pos.x, b.pos.y) == tuple(x[i]) and (b.vel.x, b.vel.y) == tuple(v[i])


def test_add_many_matches_add():
    one = gas(side=5)
    other = World(one.width, one.height, capacity=25, boundary=Boundary.PERIODIC)
    for p, v in zip(gas(side=5).positions(), gas(side=5).velocities()):
        other.add(p, v, 1.0, 0.5)
    for w in (one, other):
        w.advance(10.0)
    assert bits(one.positions()) == bits(other.positions())
    assert bits(one.velocities()) == bits(other.velocities())


def test_add_many_returns_indices_and_takes_columns():
    w = World(10, 10, capacity=4)
    w.add((1, 1), (0, 0), 1.0, 0.5)
    idx = w.add_many([[3, 3], [5, 5]], np.zeros((2, 2), np.float32), np.array([1, 2]), [0.5, 0.25])
    assert list(idx) == [1, 2]
    assert w.get(2).mass == 2.0


def test_add_many_is_all_or_nothing():
    w = World(10, 10, capacity=4)
    w.add((1, 1), (0, 0), 1.0, 0.5)
    before = bytes(w._memory)
    with pytest.raises(WorldError, match="disk 1"):  # the second overlaps the first
        w.add_many([[5, 5], [5.5, 5]], np.zeros((2, 2)), 1.0, 0.5)
    assert w.count == 1 and bytes(w._memory) == before
    with pytest.raises(WorldError, match="do not fit"):
        w.add_many(np.full((4, 2), 5.0), np.zeros((4, 2)), 1.0, 0.1)
    assert w.count == 1


# ------------------------------------------------ frame independence

def test_one_advance_or_many_gives_the_same_bits():
    a, b = gas(side=7), gas(side=7)
    a.advance(50.0)
    for t in (0.001, 0.3, 0.30000000000000004, 7.0, 7.0, 19.123, 33.3, 49.999999, 50.0):
        b.advance(t)
    assert bits(a.positions()) == bits(b.positions())
    assert bits(a.velocities()) == bits(b.velocities())
    assert a.stats == b.stats


def test_reading_changes_nothing():
    a, b = gas(side=6), gas(side=6)
    for t in (1.0, 2.0, 3.0):
        a.advance(t)
        a.positions(), a.get(5), a.stats
    b.advance(3.0)
    assert bits(a.positions()) == bits(b.positions()) and a.stats.virial == b.stats.virial


# ------------------------------------------------ set_velocity, remove

def test_set_velocity_changes_the_course():
    w, ia, ib = pair()
    w.advance(0.5)
    w.set_velocity(ia, (-1, 0))  # now receding from b: no impact
    w.advance(1.0)
    assert tuple(w.get(ia).pos) == (1.0, 1.0) and w.stats.collisions == 0
    w.set_velocity(ib, c2d.Vec2(-2, 0))
    w.advance(1.5)  # a, from (1, 1) at -1, meets the wall x = 0 at t = 1.5; b from (3, 1) at -2
    assert (w.stats.collisions, w.stats.wall_collisions) == (0, 1)
    w.advance(2.5)  # a at +1 from (0.5, 1), b from (2, 1) at -2: they meet at t = 1.5 + 0.5 / 3
    assert w.stats.collisions >= 1


def test_remove_takes_a_disk_out():
    w, ia, ib = pair()
    w.remove(ib)
    w.advance(5.0)
    assert w.stats.collisions == 0 and w.count == 2
    assert tuple(w.get(ia).pos) == (6.0, 1.0)
    assert np.all(np.isnan(w.positions()[ib])) and np.all(np.isnan(w.velocities()[ib]))
    for call in (lambda: w.get(ib), lambda: w.remove(ib), lambda: w.set_velocity(ib, (0, 0))):
        with pytest.raises(WorldError) as e:
            call()
        assert e.value.status is Status.INVALID
    with pytest.raises(WorldError, match="full"):  # nor its index, nor its capacity
        w.add((8, 1), (0, 0), 1.0, 0.5)


def test_stats_fields():
    w = gas(side=5)
    w.advance(4.0)
    s = w.stats
    assert s._fields == ("collisions", "wall_collisions", "events", "time", "virial")
    assert s.events >= s.collisions > 0 and s.time == 4.0 and s.virial > 0
    assert all(isinstance(getattr(s, f), int) for f in s._fields[:3])


# ------------------------------------------------ the event callback

def test_on_event_sees_every_impact():
    events = []
    w = World(10, 2, capacity=2, on_event=events.append)
    w.add((1, 1), (1, 0), 1.0, 0.5)
    w.add((3, 1), (0, 0), 1.0, 0.5)
    w.advance(20.0)
    kinds = [e.kind for e in events]
    assert kinds.count(EventKind.IMPACT) == w.stats.collisions
    assert kinds.count(EventKind.WALL) == w.stats.wall_collisions
    first = events[0]
    assert (first.kind, first.time, first.a, first.b, first.impulse) == (EventKind.IMPACT, 1.0, 0, 1, (1.0, 0.0))
    assert sorted(e.time for e in events) == [e.time for e in events]


def test_on_event_virial_is_the_stats_virial():
    w = None
    total = [0.0]

    def virial(e):
        if e.kind is EventKind.IMPACT:  # states at the event's time: the pair in contact
            a, b = w.get(e.a).pos, w.get(e.b).pos
            dx, dy = b.x - a.x, b.y - a.y
            dx -= w.width * round(dx / w.width)
            dy -= w.height * round(dy / w.height)
            total[0] += dx * e.impulse[0] + dy * e.impulse[1]

    w = gas(side=5, on_event=virial)
    w.advance(3.0)
    assert total[0] == pytest.approx(w.stats.virial, rel=1e-9)


def test_on_event_may_not_change_the_world_and_errors_reach_advance():
    w = None

    def meddle(e):
        w.advance(100.0)

    w, _, _ = pair(on_event=meddle)
    with pytest.raises(RuntimeError, match="cannot be changed from on_event"):
        w.advance(2.0)
    assert w.time == 2.0  # the advance itself completed
    w.advance(3.0)  # and the world goes on

    def fail(e):
        raise KeyError("boom")

    w, _, _ = pair(on_event=fail)
    with pytest.raises(KeyError):
        w.advance(2.0)


# ------------------------------------------------ validation

GOOD = dict(width=10, height=10, capacity=4)


@pytest.mark.parametrize("field, value", [
    ("width", "10"), ("width", None), ("width", True), ("width", 1j), ("height", [1]),
    ("capacity", 4.0), ("capacity", "4"), ("capacity", True), ("capacity", None),
    ("boundary", 0), ("boundary", None), ("boundary", 1.0),
    ("restitution", "1"), ("wall_restitution", None),
    ("collapse_speed", "0"), ("collapse_count", 1.5), ("collapse_count", True), ("collapse_time", None),
    ("collapse_length", [0]), ("on_event", 3),
])
def test_world_wrong_kinds_are_type_errors(field, value):
    with pytest.raises(TypeError, match=field):
        World(**{**GOOD, field: value})


@pytest.mark.parametrize("field, value", [
    ("width", 0), ("width", -1), ("width", math.inf), ("width", math.nan), ("height", 2 ** 1024),
    ("capacity", 0), ("capacity", -1), ("capacity", 2 ** 31), ("capacity", 2 ** 70),
    ("boundary", "circle"), ("boundary", ""),
    ("restitution", 1.5), ("restitution", -0.1), ("restitution", math.nan), ("wall_restitution", 2),
    ("collapse_speed", -1), ("collapse_speed", math.inf), ("collapse_count", -1), ("collapse_count", 2 ** 32),
    ("collapse_time", math.nan), ("collapse_length", -1e-300),
])
def test_world_wrong_values_are_value_errors(field, value):
    with pytest.raises(ValueError, match=field):
        World(**{**GOOD, field: value})


def test_world_takes_numpy_and_fraction_numbers_and_enum_or_string_boundaries():
    w = World(np.float32(6), fractions.Fraction(13, 2), capacity=np.int64(3), boundary="PERIODIC",
              restitution=np.float64(0.5), collapse_count=np.uint8(4))
    assert (w.width, w.height, w.capacity, w.boundary, w.restitution) == (6.0, 6.5, 3, Boundary.PERIODIC, 0.5)
    assert World(1, 1, capacity=1, boundary=Boundary.WALLS).boundary is Boundary.WALLS
    with pytest.raises(TypeError):
        World(1, 1)  # capacity is required


@pytest.mark.parametrize("args, error", [
    ((("1", 1), (0, 0), 1.0, 0.5), TypeError), ((None, (0, 0), 1.0, 0.5), TypeError),
    (((5, 5), (0, 0, 0), 1.0, 0.5), ValueError), (((5, 5), "ab", 1.0, 0.5), TypeError),
    (((5, 5), (0, 0), "1", 0.5), TypeError), (((5, 5), (0, 0), 1.0, None), TypeError),
    (((5, 5), (0, 0), True, 0.5), TypeError), (((5, 5), (0, 0), 1.0, 2 ** 1024), ValueError),
])
def test_add_argument_checks(args, error):
    w = World(**GOOD)
    with pytest.raises(error):
        w.add(*args)
    assert w.count == 0


@pytest.mark.parametrize("pos, vel, mass, radius, why", [
    ((0.1, 5), (0, 0), 1.0, 0.5, "outside"),       # walls: radius <= x
    ((5, 9.6), (0, 0), 1.0, 0.5, "outside"),
    ((5, 5), (0, 0), 0.0, 0.5, "<= 0"),
    ((5, 5), (0, 0), 1.0, -0.5, "<= 0"),
    ((5, 5), (0, 0), math.nan, 0.5, "NaN"),
    ((5, 5), (math.inf, 0), 1.0, 0.5, "Inf"),
    ((8.5, 8), (0, 0), 1.0, 0.5, "overlapping"),   # the disk at (8, 8)
])
def test_add_refused_by_the_world(pos, vel, mass, radius, why):
    w = World(**GOOD)
    w.add((8, 8), (0, 0), 1.0, 0.5)
    before = bytes(w._memory)
    with pytest.raises(WorldError, match=why) as e:
        w.add(pos, vel, mass, radius)
    assert isinstance(e.value, ValueError) and e.value.status is Status.INVALID
    assert bytes(w._memory) == before


def test_add_full_and_periodic_too_large():
    w = World(10, 10, capacity=1)
    w.add((5, 5), (0, 0), 1.0, 0.5)
    with pytest.raises(WorldError, match="full"):
        w.add((2, 2), (0, 0), 1.0, 0.5)
    p = World(3, 3, capacity=2, boundary="periodic")
    with pytest.raises(WorldError, match="third"):
        p.add((1.5, 1.5), (0, 0), 1.0, 0.5)  # 3 diameters x (1 + 2^-24) > 3
    with pytest.raises(WorldError, match="outside"):
        p.add((3.0, 1.5), (0, 0), 1.0, 0.5)  # periodic: 0 <= x < width
    assert p.add((0.0, 2.9), (0, 0), 1.0, 0.49) == 0  # across the edge: fine


def test_a_world_cannot_be_copied():
    import copy
    import pickle
    w, _, _ = pair()
    for f in (copy.copy, copy.deepcopy, pickle.dumps):
        with pytest.raises(TypeError, match="cannot be copied"):
            f(w)


def test_argument_messages_name_the_argument():
    w = World(**GOOD)
    with pytest.raises(TypeError, match="World.add: vel"):
        w.add((5, 5), "ab", 1.0, 0.5)
    with pytest.raises(TypeError, match="World.add: mass"):
        w.add((5, 5), (0, 0), None, 0.5)


@pytest.mark.parametrize("pos, vel, mass, radius, error", [
    ("ab", np.zeros((1, 2)), 1.0, 0.5, TypeError),
    (None, np.zeros((1, 2)), 1.0, 0.5, TypeError),
    (np.array([[True, False]]), np.zeros((1, 2)), 1.0, 0.5, TypeError),
    (np.array([["a", "b"]]), np.zeros((1, 2)), 1.0, 0.5, TypeError),
    (np.ones((1, 2), complex), np.zeros((1, 2)), 1.0, 0.5, TypeError),
    (np.ones((1, 3)), np.zeros((1, 2)), 1.0, 0.5, ValueError),
    (np.ones(2), np.zeros((1, 2)), 1.0, 0.5, ValueError),
    (np.ones((1, 2)), np.zeros((2, 2)), 1.0, 0.5, ValueError),
    (np.ones((1, 2)), np.zeros((1, 2)), np.ones(2), 0.5, ValueError),
    (np.ones((1, 2)), np.zeros((1, 2)), 1.0, "0.5", TypeError),
    (np.ones((1, 2)), np.zeros((1, 2)), True, 0.5, TypeError),
    (np.ones((1, 2)), np.zeros((1, 2)), 1.0, np.array([1e300], np.longdouble) * 1e300, ValueError),
    ([[1, 2], [3]], np.zeros((2, 2)), 1.0, 0.5, ValueError),
])
def test_add_many_argument_checks(pos, vel, mass, radius, error):
    w = World(**GOOD)
    with pytest.raises(error):
        w.add_many(pos, vel, mass, radius)
    assert w.count == 0


@pytest.mark.parametrize("t, error", [("1", TypeError), (None, TypeError), (True, TypeError),
                                      (2 ** 1024, ValueError), (math.nan, WorldError),
                                      (math.inf, WorldError), (0.5, WorldError)])
def test_advance_checks(t, error):
    w, _, _ = pair()
    w.advance(1.0)
    before = bytes(w._memory)
    with pytest.raises(error):
        w.advance(t)
    assert bytes(w._memory) == before and w.time == 1.0


@pytest.mark.parametrize("method", ["get", "remove", "set_velocity"])
@pytest.mark.parametrize("index, error", [("0", TypeError), (0.0, TypeError), (True, TypeError),
                                          (None, TypeError), (-1, ValueError), (2, ValueError),
                                          (2 ** 70, ValueError)])
def test_index_checks(method, index, error):
    w, _, _ = pair()
    args = (index, (0, 0)) if method == "set_velocity" else (index,)
    with pytest.raises(error):
        getattr(w, method)(*args)
    assert w.get(np.int64(1)).mass == 1.0  # numpy's integers are indices


@pytest.mark.parametrize("vel, error", [("ab", TypeError), ((1,), ValueError), (None, TypeError),
                                        ((math.nan, 0), WorldError), ((math.inf, 0), WorldError)])
def test_set_velocity_checks(vel, error):
    w, ia, _ = pair()
    before = bytes(w._memory)
    with pytest.raises(error):
        w.set_velocity(ia, vel)
    assert bytes(w._memory) == before
