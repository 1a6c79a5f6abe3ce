# SPDX-License-Identifier: MIT
"""collide2d: exact, robust 2-D disk collisions (Python binding over ctypes).

Every call goes straight to the C library (libcollide2d.so, built by `make`;
see collide2d._native for where it is looked for), so results are the C
library's bit for bit.

Units: any consistent set (SI: m, m/s, kg, s, rad/s, kg m^2).  Masses > 0;
math.inf is immovable.  Restitution in [0, 1].  A normal points from a
towards b and may have any finite non-zero length.

Scalar calls take the C structs (Body, Disk, Vec2, Surface, and for pool
balls as spheres Ball, BallSurface, Cushion, for double; the same names
ending in f for float), write the new velocities (and spins) into
the bodies in place, and return a Status.  Any status but Status.OK leaves
both bodies untouched, bit for bit.

    >>> from collide2d import Body, collide
    >>> a, b = Body((0, 0), (1, 0), 1.0), Body((1, 1), (0, 0), 1.0)
    >>> collide(a, b, 1.0)
    <Status.OK: 0>
    >>> tuple(a.vel), tuple(b.vel)
    ((0.5, -0.5), (0.5, 0.5))

Every argument and struct field is checked before it reaches C (the rules:
collide2d._native).  A number is any real number but a bool (numpy's
scalars and fractions included); a vector or a surface is its struct, its
twin of the other precision, a sequence of exactly its numbers (a tuple, a
list), or a 1-D numpy array of a real dtype of that length.  The wrong kind
of thing (a string, None, a bool, a complex, a dict, a set, an iterator, a
struct of another kind) is a TypeError; a wrong number of components or a
number beyond the C type (2**1024, or 1e300 for float) a ValueError.  NaN
and infinities pass: the library answers Status.INVALID where its contract
refuses them, and an infinite mass, inertia, friction or horizon is a value.
A struct takes every field or none (all zeros).

The batch calls (collide_batch, collide_batchf) work in place on numpy
arrays: see collide2d.batch.

World is the event-driven world of hard disks (collide2d_world.h): disks in
a box with walls or periodic edges, every impact resolved exactly in time
order by the C library, no time step.  It owns its memory; add / add_many
put disks in, advance(t) runs to time t, get(i) gives a Body, positions()
and velocities() numpy arrays of shape (count, 2) at the world's time, and
stats the counters and the collision virial (for the pressure).  What the
world refuses (a disk outside the box or overlapping another, a time in the
past, a full world) raises WorldError, a ValueError; arguments are checked
as above.  See collide2d.world.

    >>> from collide2d import World
    >>> w = World(10, 2, capacity=2)                  # walls, restitution 1
    >>> w.add((1, 1), (1, 0), 1.0, 0.5), w.add((3, 1), (0, 0), 1.0, 0.5)
    (0, 1)
    >>> w.advance(2.0)                                # they meet at t = 1
    >>> w.velocities().tolist(), w.stats.collisions
    ([[0.0, 0.0], [1.0, 0.0]], 1)
"""
import enum
import numbers

from . import _native

__all__ = [
    "Status", "version", "status_string", "LIB_PATH",
    "Vec2", "Body", "Disk", "Surface", "Vec2f", "Bodyf", "Diskf", "Surfacef",
    "collide", "collide_normal", "time_of_impact", "time_of_impact_accel", "collide_rough",
    "collide_rough_normal", "Ball", "BallSurface", "Cushion", "Ballf", "BallSurfacef", "Cushionf",
    "collide_balls", "collide_cushion", "collide_ballsf", "collide_cushionf",
    "collidef", "collide_normalf", "time_of_impactf", "time_of_impact_accelf", "collide_roughf",
    "collide_rough_normalf",
    "collide_batch", "collide_batchf",
    "World", "WorldError", "Boundary", "EventKind", "Event", "Stats",
]

LIB_PATH = _native.LIB_PATH

Vec2, Body, Disk, Surface = (_native.DOUBLE[k] for k in ("Vec2", "Body", "Disk", "Surface"))
Vec2f, Bodyf, Diskf, Surfacef = (_native.FLOAT[k] for k in ("Vec2", "Body", "Disk", "Surface"))
Ball, BallSurface, Cushion = (_native.DOUBLE[k] for k in ("Ball", "BallSurface", "Cushion"))
Ballf, BallSurfacef, Cushionf = (_native.FLOAT[k] for k in ("Ball", "BallSurface", "Cushion"))


class Status(enum.IntEnum):
    """What a call did (c2d_status).  Priority when several apply:
    INVALID > DEGENERATE > SEPARATING > RANGE > OK."""

    OK = 0          #: velocities updated
    SEPARATING = 1  #: not approaching along the normal (relative normal velocity >= 0)
    DEGENERATE = 2  #: zero normal (coincident centres) or both bodies immovable
    INVALID = 3     #: NaN or Inf anywhere, mass <= 0, restitution outside [0, 1], ...
    RANGE = 4       #: a result would overflow the format

    def __str__(self):
        return status_string(self)


def version():
    """The library's version as (major, minor, patch), from c2d_version()."""
    v = _native.LIB.c2d_version()
    return (v // 10000, v // 100 % 100, v % 100)


__version__ = "%d.%d.%d" % version()


def status_string(status):
    """The C library's name for a status ("ok", "separating", ...); "unknown"
    for an int outside the enum.  status: a Status or an int (numpy's too,
    not bool) within C's int; TypeError for anything else, ValueError beyond
    int's range (where C would truncate it)."""
    if isinstance(status, bool) or not isinstance(status, numbers.Integral):
        raise TypeError(f"status_string: status must be a Status or an int, not {type(status).__name__}")
    value = int(status)
    bits = 8 * _native.ctypes.sizeof(_native.ctypes.c_int)
    if not -2 ** (bits - 1) <= value < 2 ** (bits - 1):
        raise ValueError(f"status_string: status = {_native.show(value)} is beyond the range of C's int")
    return _native.LIB.c2d_status_string(value).decode("ascii")


# ------------------------------------------------------------ calling C

def _convert(value, ctype, position, name):
    """One argument as the C function wants it: TypeError for the wrong kind
    of thing, ValueError for a wrong value (rules: collide2d._native)."""
    where = f"{name}: argument {position}"
    if isinstance(ctype, type) and issubclass(ctype, _native.ctypes._Pointer):
        target = ctype._type_
        if not isinstance(value, target):
            raise TypeError(f"{where} must be {target.__name__}, not {type(value).__name__}")
        return _native.ctypes.byref(value)
    if isinstance(ctype, type) and issubclass(ctype, _native.ctypes.Structure):
        return _native.struct_value(ctype, value, where)
    return _native.real(value, ctype, where)


def _call(cname, *args):
    """Call the C function `cname`: check and convert the arguments, allocate
    its outputs.  Returns the Status, or (Status, output...) when it has
    outputs (each None unless the status is OK)."""
    fn, pyname = _native.function(cname), cname[len("c2d_"):]
    if fn is None:
        raise NotImplementedError(f"{cname} is not in {LIB_PATH} (built without this variant?)")
    proto = _native.PROTOTYPES[cname]
    inputs = [a for a in proto if not isinstance(a, _native.Out)]
    if len(args) != len(inputs):
        raise TypeError(f"{pyname} takes {len(inputs)} arguments ({len(args)} given)")
    values, outputs, it = [], [], iter(args)
    for position, ctype in enumerate(proto, 1):
        if isinstance(ctype, _native.Out):
            out = ctype.ctype()
            outputs.append(out)
            values.append(_native.ctypes.byref(out))
        else:
            values.append(_convert(next(it), ctype, position, pyname))
    status = Status(fn(*values))
    if not outputs:
        return status
    return (status,) + tuple(o.value if status == Status.OK else None for o in outputs)


# ------------------------------------------------------------ double

def collide(a, b, restitution):
    """Resolve an impact of disks a and b (Body) along the line of centres
    b.pos - a.pos, taken exactly.  restitution e in [0, 1]: the relative
    normal velocity after is -e times the one before.  Writes a.vel, b.vel
    (in the velocity unit of the inputs) on Status.OK.  Accuracy: each output
    component within 16 ulp of its body's velocity scale; correctly rounded
    when the centres share an x or a y coordinate (axis-aligned)."""
    return _call("c2d_collide", a, b, restitution)


def collide_normal(a, b, normal, restitution):
    """As collide, with the contact normal given (Vec2 or (x, y): any finite
    non-zero vector from a towards b; positions are only validated).  For
    walls: b.mass = math.inf, normal = the wall's normal pointing away from a."""
    return _call("c2d_collide_normal", a, b, normal, restitution)


def time_of_impact(a, b, radius_sum):
    """Time of impact of two disks (Body) moving with constant velocities:
    the earliest t >= 0 at which |(b.pos - a.pos) + (b.vel - a.vel) t| =
    radius_sum while they approach (radius_sum >= 0, in the position unit).
    Returns (Status, t): t in the velocities' time unit on Status.OK (0 when
    already overlapping and approaching), None otherwise (SEPARATING: they
    recede, miss or graze).  Masses are ignored."""
    return _call("c2d_time_of_impact", a, b, radius_sum)


def time_of_impact_accel(a, acc_a, b, acc_b, radius_sum, horizon=float("inf")):
    """Time of impact of two disks (Body) moving with constant accelerations
    acc_a, acc_b (Vec2 or (x, y)): p(t) = pos + vel t + acc t^2 / 2.  The
    earliest t in [0, horizon] at which they touch while approaching
    (horizon: until either motion changes, math.inf allowed).  Returns
    (Status, t): t on Status.OK, None otherwise (SEPARATING: no contact in
    the horizon, a graze, no relative motion; RANGE: beyond the format).
    Accuracy: within 1 unit of ulp(t) + ulp(|d|) / approach speed; the status
    is certified (see the C header for the ~2^-96 tie band)."""
    return _call("c2d_time_of_impact_accel", a, acc_a, b, acc_b, radius_sum, horizon)


def collide_rough(a, b, surface):
    """Impact of two rough disks (Disk: pos, vel, spin in rad per time unit
    counter-clockwise, mass, radius, inertia = moment of inertia about the
    centre, e.g. m r^2 / 2) along the line of centres, with friction and spin
    (Walton's model).  surface: Surface or (restitution e in [0, 1],
    friction mu >= 0, tangential_restitution beta in [-1, 1]).  Writes both
    velocities and spins on Status.OK.  mu = 0 or beta = -1 give collide's
    velocities bit for bit."""
    return _call("c2d_collide_rough", a, b, surface)


def collide_rough_normal(a, b, normal, surface):
    """As collide_rough with the contact normal given (from a towards b).
    For cushions: b.mass = b.inertia = math.inf, b.radius = 0."""
    return _call("c2d_collide_rough_normal", a, b, normal, surface)


def collide_balls(a, b, surface):
    """Impact of two pool balls as spheres (Ball: pos, vel in the table's
    plane, spin = (wx, wy, wz) in rad per time unit about +x, +y, +z (z up),
    mass, radius, inertia about the centre, 2/5 m r^2 for a solid ball),
    touching at their equators.  surface: BallSurface or (restitution e in
    [0, 1], friction, friction_boost, friction_decay): friction
    mu(v) = friction + friction_boost exp(-friction_decay v) on the 3-D slip
    at the contact (Alciatore's fit: 9.951e-3, 0.108, 1.088; boost 0 =
    constant).  Writes both velocities and spins on Status.OK.  With
    wx = wy = 0 and constant mu it is collide_rough with beta = 0; friction 0
    gives collide's velocities bit for bit.  Accuracy: each output within 24
    ulp of the pair's scale (C header, c2d_collide_balls)."""
    return _call("c2d_collide_balls", a, b, surface)


def collide_cushion(ball, cushion):
    """A ball's impact on a still rail (Cushion: normal from the ball towards
    the rail, height of the contact above the cloth in [radius, 2 radius],
    0.635 of the diameter on a pool table, restitution, friction).  Han
    2005's impulse with Coulomb friction along the slip; writes the ball's
    velocity and spin on Status.OK.  Within 16 ulp of the ball's scale."""
    return _call("c2d_collide_cushion", ball, cushion)


# ------------------------------------------------------------ float

def collidef(a, b, restitution):
    """Float twin of collide (Bodyf; float arithmetic only, accuracy in float
    ulp)."""
    return _call("c2d_collidef", a, b, restitution)


def collide_normalf(a, b, normal, restitution):
    """Float twin of collide_normal (Bodyf, Vec2f)."""
    return _call("c2d_collide_normalf", a, b, normal, restitution)


def time_of_impactf(a, b, radius_sum):
    """Float twin of time_of_impact (Bodyf): returns (Status, t or None)."""
    return _call("c2d_time_of_impactf", a, b, radius_sum)


def time_of_impact_accelf(a, acc_a, b, acc_b, radius_sum, horizon=float("inf")):
    """Float twin of time_of_impact_accel (Bodyf, Vec2f; band ~2^-38)."""
    return _call("c2d_time_of_impact_accelf", a, acc_a, b, acc_b, radius_sum, horizon)


def collide_roughf(a, b, surface):
    """Float twin of collide_rough (Diskf, Surfacef)."""
    return _call("c2d_collide_roughf", a, b, surface)


def collide_rough_normalf(a, b, normal, surface):
    """Float twin of collide_rough_normal (Diskf, Vec2f, Surfacef)."""
    return _call("c2d_collide_rough_normalf", a, b, normal, surface)


def collide_ballsf(a, b, surface):
    """Float twin of collide_balls (Ballf, BallSurfacef)."""
    return _call("c2d_collide_ballsf", a, b, surface)


def collide_cushionf(ball, cushion):
    """Float twin of collide_cushion (Ballf, Cushionf)."""
    return _call("c2d_collide_cushionf", ball, cushion)


from .batch import collide_batch, collide_batchf  # noqa: E402  (needs Status)
from .world import Boundary, Event, EventKind, Stats, World, WorldError  # noqa: E402  (needs Status)
