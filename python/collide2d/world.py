# SPDX-License-Identifier: MIT
"""The event-driven world of hard disks (collide2d_world.h) as World.

World owns its memory (a ctypes buffer of c2d_world_bytes, 8-byte aligned,
which never moves); every call goes to the C world, so events, states and
statistics are the C library's bit for bit.  Arguments are checked as
everywhere in the binding (collide2d._native): the wrong kind of thing is a
TypeError, a wrong value a ValueError.  What the C world refuses
(C2D_INVALID: a disk outside the box or overlapping another, a time before
the world's, a full world, ...) raises WorldError, a ValueError whose
.status is the Status; the world is then unchanged bit for bit.

numpy is imported by the bulk calls only (positions, velocities, add_many).
"""
import collections
import collections.abc
import ctypes
import enum
import math
import numbers

from . import Status, _native

Stats = collections.namedtuple("Stats", "collisions wall_collisions events time virial")
Stats.__doc__ = """The world's counters (c2d_world_stats): disk-disk impacts,
wall impacts, events processed (crossings included), the world's time, and
the virial sum over disk-disk impacts of r_ij . dp_j (r_ij from i to j at
contact, nearest image; dp_j the impulse on j)."""

Event = collections.namedtuple("Event", "kind time a b impulse")
Event.__doc__ = """One impact, as on_event receives it (c2d_world_event):
kind (EventKind), time, a and b (IMPACT: the disks, a < b; WALL: the disk
and the wall 0..3 for x = 0, x = width, y = 0, y = height) and impulse, an
(x, y) tuple (IMPACT: on b, a gets its negative; WALL: on the disk)."""


class Boundary(enum.IntEnum):
    """The box's edges (c2d_boundary)."""
    WALLS = 0
    PERIODIC = 1


class EventKind(enum.IntEnum):
    """What an Event is (c2d_world_event_kind)."""
    IMPACT = 0
    WALL = 1
    TIMER = 2   # a disk's timer is due (the C world's; not set from Python yet)
    STATIC = 3  # a disk met a static segment or circle (likewise)
    SENSOR = 4  # a disk's centre entered a sensor (likewise)


class WorldError(ValueError):
    """The C world refused a call (its status, .status, is not OK)."""

    def __init__(self, message, status):
        super().__init__(message)
        self.status = status


_UINT_MAX = 2 ** (8 * ctypes.sizeof(ctypes.c_uint)) - 1
MAX_CAPACITY = 2 ** 31 - 1


def _integer(value, where, lo, hi):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{where} must be an int, not {type(value).__name__}")
    value = int(value)
    if not lo <= value <= hi:
        raise ValueError(f"{where} = {_native.show(value)} is outside [{lo}, {hi}]")
    return value


def _nonnegative(value, where):
    x = _native.real(value, ctypes.c_double, where)
    if not (x >= 0 and math.isfinite(x)):
        raise ValueError(f"{where} = {x!r} must be finite and >= 0")
    return x


def _boundary(value):
    if isinstance(value, Boundary):
        return value
    if isinstance(value, str):
        try:
            return Boundary[value.upper()]
        except KeyError:
            raise ValueError(f"World: boundary = {value!r} must be 'walls' or 'periodic'") from None
    raise TypeError(f"World: boundary must be 'walls', 'periodic' or a Boundary, not {type(value).__name__}")


def _functions():
    fns = _native.world_functions()
    if fns is None:
        raise NotImplementedError(f"c2d_world_* is not in {_native.LIB_PATH} (built without the world?)")
    return fns


def _column(np, value, n, where):
    """A mass or radius argument of add_many: a number for all, or n of them."""
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        return np.full(n, _native.real(value, ctypes.c_double, where))
    return _array(np, value, (n,), where)


def _array(np, value, shape, where):
    """value (a numpy array or a nested sequence) as float64 of `shape`
    (None in it: any length)."""
    if isinstance(value, (str, bytes)) or not isinstance(value, (np.ndarray, collections.abc.Sequence)):
        raise TypeError(f"{where} must be a numpy array or a sequence of numbers, not {type(value).__name__}")
    try:
        a = np.asarray(value)
    except ValueError as e:  # ragged
        raise ValueError(f"{where}: {e}") from None
    if a.dtype.kind not in "fiu":
        raise TypeError(f"{where} must hold real numbers, not dtype {a.dtype.name}")
    if a.ndim != len(shape) or any(want is not None and got != want for got, want in zip(a.shape, shape)):
        want = "(" + ", ".join("n" if k is None else str(k) for k in shape) + ("," if len(shape) == 1 else "") + ")"
        raise ValueError(f"{where} must have shape {want}, not {a.shape}")
    with np.errstate(over="ignore"):
        out = a.astype(np.float64)
    if a.dtype.kind == "f" and np.any(np.isinf(out) & np.isfinite(a)):
        raise ValueError(f"{where} has a finite value beyond the range of double")
    return out


class World:
    """An event-driven world of hard disks in the box [0, width) x [0, height).

    World(width, height, *, capacity, boundary='walls', restitution=1.0,
          wall_restitution=1.0, collapse_speed=0.0, collapse_count=0,
          collapse_time=0.0, collapse_length=0.0, on_event=None)

    capacity: the most disks (1 to 2^31 - 1); boundary: 'walls', 'periodic'
    or a Boundary; restitution (disk-disk) and wall_restitution in [0, 1];
    the collapse_* rules for restitution < 1 as in collide2d_world.h (0: the
    default).  on_event: None, or a callable given an Event after each
    impact during advance(); it may read the world (get, positions, ...)
    but not change it (RuntimeError).  An exception it raises stops nothing
    in C: the advance completes and then raises it.

    Disks are indexed from 0 in order of addition; a removed disk keeps its
    index (its rows of positions() and velocities() are NaN)."""

    def __init__(self, width, height, *, capacity, boundary="walls", restitution=1.0, wall_restitution=1.0,
                 collapse_speed=0.0, collapse_count=0, collapse_time=0.0, collapse_length=0.0, on_event=None):
        fns = _functions()
        d = _native.WorldDesc()
        d.capacity = _integer(capacity, "World: capacity", 1, MAX_CAPACITY)
        for name, value in (("width", width), ("height", height)):
            x = _native.real(value, ctypes.c_double, f"World: {name}")
            if not (x > 0 and math.isfinite(x)):
                raise ValueError(f"World: {name} = {x!r} must be finite and > 0")
            setattr(d, name, x)
        d.boundary = _boundary(boundary)
        for name, value in (("restitution", restitution), ("wall_restitution", wall_restitution)):
            x = _native.real(value, ctypes.c_double, f"World: {name}")
            if not 0 <= x <= 1:
                raise ValueError(f"World: {name} = {x!r} must be in [0, 1]")
            setattr(d, name, x)
        d.collapse_speed = _nonnegative(collapse_speed, "World: collapse_speed")
        d.collapse_count = _integer(collapse_count, "World: collapse_count", 0, _UINT_MAX)
        d.collapse_time = _nonnegative(collapse_time, "World: collapse_time")
        d.collapse_length = _nonnegative(collapse_length, "World: collapse_length")
        self._on_event, self._callback, self._error, self._in_event = None, None, None, False
        if on_event is not None:
            if not callable(on_event):
                raise TypeError(f"World: on_event must be callable or None, not {type(on_event).__name__}")
            self._on_event = on_event
            self._callback = _native.EVENT_CALLBACK(self._event)  # kept alive as long as the world
            d.on_event = self._callback
        nbytes = fns["bytes"](ctypes.byref(d))
        if nbytes == 0:  # every field was checked above: not expected
            raise ValueError("World: the C library refuses this description")
        self._fns, self._desc = fns, d
        self._memory = (ctypes.c_uint64 * ((nbytes + 7) // 8))()  # 8-byte aligned, never moved
        self._world = ctypes.c_void_p()
        self._check(fns["init"](ctypes.byref(self._world), self._memory, nbytes, ctypes.byref(d)),
                    "World: c2d_world_init refused the memory or the description")
        self._body = _native.DOUBLE["Body"]()  # reused by positions() and velocities()

    # ------------------------------------------------ plumbing

    def _check(self, status, message):
        if status != 0:
            raise WorldError(f"{message} (status {_native.LIB.c2d_status_string(status).decode()})",
                             Status(status))

    def _event(self, user, pointer):
        e = _native.WorldEvent.from_address(pointer)
        try:
            if self._error is None:
                self._in_event = True
                self._on_event(Event(EventKind(e.kind), e.time, e.a, e.b, (e.impulse.x, e.impulse.y)))
        except BaseException as exc:  # noqa: B902  (re-raised by advance)
            self._error = exc
        finally:
            self._in_event = False

    def _changing(self, what):
        if self._in_event:
            raise RuntimeError(f"World.{what}: the world cannot be changed from on_event")

    def _index(self, index, what):
        if isinstance(index, bool) or not isinstance(index, numbers.Integral):
            raise TypeError(f"World.{what}: index must be an int, not {type(index).__name__}")
        i = int(index)
        if not 0 <= i < self.count:
            raise ValueError(f"World.{what}: index {_native.show(index)} is not a disk of this world "
                             f"(0 to {self.count - 1})")
        return i

    # ------------------------------------------------ the description

    width = property(lambda self: self._desc.width, doc="The box's width.")
    height = property(lambda self: self._desc.height, doc="The box's height.")
    boundary = property(lambda self: Boundary(self._desc.boundary), doc="WALLS or PERIODIC.")
    restitution = property(lambda self: self._desc.restitution, doc="Disk-disk restitution.")
    wall_restitution = property(lambda self: self._desc.wall_restitution, doc="The walls' restitution.")
    capacity = property(lambda self: self._desc.capacity, doc="The most disks.")

    def __repr__(self):
        return (f"World(width={self.width!r}, height={self.height!r}, capacity={self.capacity}, "
                f"boundary={self.boundary.name.lower()!r}, count={self.count}, time={self.time!r})")

    # ------------------------------------------------ reading

    @property
    def count(self):
        """Disks added (removed ones included: indices stay)."""
        return self._fns["count"](self._world)

    def __len__(self):
        return self.count

    @property
    def stats(self):
        """A Stats: collisions, wall_collisions, events, time, virial."""
        s = _native.WorldStats()
        self._fns["get_stats"](self._world, ctypes.byref(s))
        return Stats(s.collisions, s.wall_collisions, s.events, s.time, s.virial)

    @property
    def time(self):
        """The world's time."""
        return self.stats.time

    def get(self, index):
        """Disk `index` at the world's time as a new Body (pos, vel, mass).
        A removed disk is a WorldError."""
        i = self._index(index, "get")
        body = _native.DOUBLE["Body"]()
        self._check(self._fns["get"](self._world, i, ctypes.byref(body)), f"World.get: disk {i} was removed")
        return body

    def _states(self):
        import numpy as np
        n = self.count
        out = np.full((n, 4), np.nan)
        get, w, body = self._fns["get"], self._world, self._body
        ref = ctypes.byref(body)
        for i in range(n):
            if get(w, i, ref) == 0:
                out[i] = (body.pos.x, body.pos.y, body.vel.x, body.vel.y)
        return out

    def positions(self):
        """Every disk's position at the world's time, shape (count, 2) float64
        (NaN rows for removed disks); the same numbers as get()."""
        return self._states()[:, :2].copy()

    def velocities(self):
        """Every disk's velocity, shape (count, 2) float64 (NaN rows for removed disks)."""
        return self._states()[:, 2:].copy()

    # ------------------------------------------------ changing

    def add(self, pos, vel, mass, radius):
        """Add a disk at the world's time: pos, vel a Vec2 or (x, y), mass and
        radius finite and > 0.  Returns its index.  WorldError when the world
        refuses it (outside the box, overlapping a disk, the world full, a
        periodic box under 3 diameters, a mass or radius <= 0 or not finite)."""
        self._changing("add")
        vec2 = _native.DOUBLE["Vec2"]
        body = _native.DOUBLE["Body"](_native.struct_value(vec2, pos, "World.add: pos"),
                                      _native.struct_value(vec2, vel, "World.add: vel"),
                                      _native.real(mass, ctypes.c_double, "World.add: mass"))
        r = _native.real(radius, ctypes.c_double, "World.add: radius")
        return self._add(body, r, "World.add")

    def _add(self, body, radius, where):
        index = ctypes.c_size_t()
        status = self._fns["add"](self._world, ctypes.byref(body), radius, ctypes.byref(index))
        if status != 0:
            self._check(status, f"{where}: the world refuses the disk at ({body.pos.x!r}, {body.pos.y!r}) "
                                f"of radius {radius!r}: {self._why(body, radius)}")
        return index.value

    def _why(self, body, r):
        """What c2d_world_add's contract most likely refused (for the message)."""
        x, y, w, h = body.pos.x, body.pos.y, self.width, self.height
        if self.count >= self.capacity:
            return f"the world is full ({self.capacity} disks)"
        if not all(map(math.isfinite, (x, y, body.vel.x, body.vel.y, body.mass, r))):
            return "NaN or Inf"
        if not (body.mass > 0 and r > 0):
            return "a mass or radius <= 0"
        if self.boundary is Boundary.PERIODIC:
            if not (0 <= x < w and 0 <= y < h):
                return "outside the box [0, width) x [0, height)"
            if 6 * r * (1 + 2 ** -24) > min(w, h):
                return "a diameter over a third of the periodic box (x (1 + 2^-24))"
        elif not (r <= x <= w - r and r <= y <= h - r):
            return "outside the box (radius <= x <= width - radius, the same in y)"
        return "overlapping a disk"

    def __reduce__(self):
        raise TypeError("a World cannot be copied or pickled (its memory points into itself): make a new one")

    __copy__ = __deepcopy__ = lambda self, *memo: self.__reduce__()

    def add_many(self, pos, vel, mass, radius):
        """Add n disks in order: pos, vel arrays of shape (n, 2), mass and
        radius a number for all or arrays of n.  Returns their indices (a
        numpy array, consecutive).  All or nothing: if the world refuses one
        (WorldError, naming it), none is added."""
        import numpy as np
        self._changing("add_many")
        pos = _array(np, pos, (None, 2), "World.add_many: pos")
        n = len(pos)
        vel = _array(np, vel, (n, 2), "World.add_many: vel")
        mass = _column(np, mass, n, "World.add_many: mass")
        radius = _column(np, radius, n, "World.add_many: radius")
        if self.count + n > self.capacity:
            raise WorldError(f"World.add_many: {n} disks do not fit ({self.count} of {self.capacity} used)",
                             Status.INVALID)
        saved = bytes(self._memory)
        first, body = self.count, _native.DOUBLE["Body"]()
        try:
            for k in range(n):
                body.pos.x, body.pos.y = float(pos[k, 0]), float(pos[k, 1])
                body.vel.x, body.vel.y = float(vel[k, 0]), float(vel[k, 1])
                body.mass = float(mass[k])
                self._add(body, float(radius[k]), f"World.add_many: disk {k}")
        except WorldError:
            ctypes.memmove(self._memory, saved, len(saved))  # the same address: bit for bit as before
            raise
        return np.arange(first, first + n)

    def advance(self, t):
        """Process every event up to time t (>= the world's time) and set the
        world's time to t."""
        self._changing("advance")
        t = _native.real(t, ctypes.c_double, "World.advance: t")
        self._error = None
        self._check(self._fns["advance"](self._world, t),
                    f"World.advance: t = {t!r} is not finite or before the world's time {self.time!r}")
        if self._error is not None:
            error, self._error = self._error, None
            raise error

    def set_velocity(self, index, vel):
        """Give disk `index` the velocity vel (Vec2 or (x, y)) at the world's time."""
        self._changing("set_velocity")
        i = self._index(index, "set_velocity")
        v = _native.struct_value(_native.DOUBLE["Vec2"], vel, "World.set_velocity: vel")
        self._check(self._fns["set_velocity"](self._world, i, v),
                    f"World.set_velocity: disk {i} was removed, or the velocity is not finite")

    def remove(self, index):
        """Take disk `index` out of the world (its index is not reused)."""
        self._changing("remove")
        i = self._index(index, "remove")
        self._check(self._fns["remove"](self._world, i), f"World.remove: disk {i} was already removed")
