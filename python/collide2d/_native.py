# SPDX-License-Identifier: MIT
"""The shared library, its C types and its prototypes (ctypes).

The library is found, in order:
  1. the path in the environment variable COLLIDE2D_LIB;
  2. build/libcollide2d.so of the source tree this package sits in
     (python/collide2d/ -> ../../build/), what `make` builds;
  3. the system's (`make install`, ctypes.util.find_library).
"""
import collections.abc
import ctypes
import ctypes.util
import functools
import math
import numbers
import os
import sys

_HERE = os.path.dirname(os.path.abspath(__file__))
_IN_TREE = os.path.join(_HERE, os.pardir, os.pardir, "build", "libcollide2d.so")


def _load():
    tried = []
    env = os.environ.get("COLLIDE2D_LIB")
    if env:
        try:
            return ctypes.CDLL(env), env
        except OSError as e:
            raise ImportError(f"collide2d: COLLIDE2D_LIB={env!r} cannot be loaded: {e}") from e
    candidates = [os.path.normpath(_IN_TREE)]
    found = ctypes.util.find_library("collide2d")
    if found:
        candidates.append(found)
    for path in candidates:
        tried.append(path)
        try:
            return ctypes.CDLL(path), path
        except OSError:
            continue
    raise ImportError("collide2d: shared library not found (tried " + ", ".join(tried) +
                      "); run `make` in the source tree, or set COLLIDE2D_LIB to libcollide2d.so")


LIB, LIB_PATH = _load()


# ------------------------------------------------------------ validation
# Every value that crosses into C goes through real() or struct_value():
#   a number      any numbers.Real but bool (numpy's float and integer
#                 scalars, fractions.Fraction included), else TypeError;
#                 rounded to the C type; NaN and infinities pass (the library
#                 answers C2D_INVALID wherever its contract refuses them, and
#                 an infinite mass, inertia, friction or horizon is a value);
#                 a finite number beyond the C type's range (2**1024, 1e300
#                 for float) is a ValueError, never an infinity.
#   a struct      an instance of that struct, its twin of the other precision
#                 (the same field names; every field checked as a number), a
#                 tuple, list or other sequence of exactly one number per
#                 field (not str, bytes, bytearray, memoryview), or a 1-D
#                 numpy array of a real dtype (float, int, not bool or
#                 complex) with one element per field.  Another kind of thing
#                 (a dict, a set, an iterator, a string, a number, a struct of
#                 another kind) is a TypeError; a wrong number of components
#                 or a wrong array shape a ValueError.

_NOT_SEQUENCES = (str, bytes, bytearray, memoryview)


def _kind(value):
    return type(value).__name__


def show(value):
    """A short repr for error messages (a 2**20000 has no repr in 3.11)."""
    if isinstance(value, int) and value.bit_length() > 64:
        return f"an integer of {value.bit_length()} bits"
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def real(value, ctype, where):
    """value as a Python float representable as `ctype` (c_double, c_float)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{where} must be a real number, not {_kind(value)}")
    name = "double" if ctype is ctypes.c_double else "float"
    try:
        x = float(value)
    except OverflowError:
        raise ValueError(f"{where} = {show(value)} is beyond the range of {name}") from None
    if ctype is not ctypes.c_double:
        x = ctype(x).value  # rounded to float; beyond FLT_MAX it is inf
    if math.isinf(x) and not value == x:  # a finite value (a float, numpy.longdouble) gone infinite
        raise ValueError(f"{where} = {show(value)} is finite but beyond the range of {name}")
    return x


def _components(cls, value, where):
    """The values of the fields of struct `cls` given as `value`, as a list."""
    names = [f for f, _ in cls._fields_]
    if isinstance(value, _Struct):
        if [f for f, _ in value._fields_] != names:
            raise TypeError(f"{where} must be {cls.__name__} or a sequence ({', '.join(names)}), "
                            f"not {_kind(value)}")
        return list(value._values())
    np = sys.modules.get("numpy")
    if np is not None and isinstance(value, np.ndarray):
        if value.dtype.kind not in "fiu":
            raise TypeError(f"{where} must be a {cls.__name__} or an array of real numbers, "
                            f"not an array of dtype {value.dtype.name}")
        if value.shape != (len(names),):
            raise ValueError(f"{where} must be a {cls.__name__} of shape ({len(names)},) ({', '.join(names)}), "
                             f"not {value.shape}")
        return list(value)
    if isinstance(value, _NOT_SEQUENCES) or not isinstance(value, collections.abc.Sequence):
        raise TypeError(f"{where} must be {cls.__name__} or a sequence ({', '.join(names)}) of numbers, "
                        f"not {_kind(value)}")
    if len(value) != len(names):
        raise ValueError(f"{where} must be a {cls.__name__} of {len(names)} components ({', '.join(names)}), "
                         f"not {len(value)}")
    return list(value)


def _array_value(ctype, value, where):
    """value as the ctypes array `ctype` (a ball's spin: three reals), from
    any sequence or 1-D numpy array of exactly that many numbers."""
    n, real_type = ctype._length_, ctype._type_
    np = sys.modules.get("numpy")
    if np is not None and isinstance(value, np.ndarray):
        if value.dtype.kind not in "fiu":
            raise TypeError(f"{where} must be an array of real numbers, not one of dtype {value.dtype.name}")
        if value.shape != (n,):
            raise ValueError(f"{where} must have shape ({n},), not {value.shape}")
    elif isinstance(value, _NOT_SEQUENCES) or not isinstance(value, collections.abc.Sequence):
        raise TypeError(f"{where} must be a sequence of {n} numbers, not {_kind(value)}")
    if len(value) != n:
        raise ValueError(f"{where} must have {n} components, not {len(value)}")
    return ctype(*(real(x, real_type, f"{where}[{i}]") for i, x in enumerate(value)))


def struct_value(cls, value, where):
    """value as an instance of the _Struct `cls` (a new one unless it is one)."""
    if type(value) is cls:
        return value
    out = cls()
    for (name, _), component in zip(cls._fields_, _components(cls, value, where)):
        out._set(name, component, f"{where}.{name}")
    return out


class _Struct(ctypes.Structure):
    """A C struct with a readable repr, equality by value, and every field
    checked (real(), struct_value()): Body((0, 0), (1, 0), 1.0), a nested
    struct field given as any sequence of numbers (a tuple, a list, a numpy
    row).  Either no arguments (all fields zero, as C's {0}) or every field,
    positionally or by name; assigning a field checks it the same way, and an
    attribute that is not a field is an AttributeError (no silent typo)."""

    def __init__(self, *args, **kwargs):
        super().__init__()
        names = [f for f, _ in self._fields_]
        cls = type(self).__name__
        if len(args) > len(names):
            raise TypeError(f"{cls}() takes {len(names)} fields ({', '.join(names)}), {len(args)} given")
        given = dict(zip(names, args))
        for k, a in kwargs.items():
            if k not in names:
                raise TypeError(f"{cls}() has no field {k!r} (fields: {', '.join(names)})")
            if k in given:
                raise TypeError(f"{cls}() got field {k!r} twice")
            given[k] = a
        if given and len(given) != len(names):
            missing = [n for n in names if n not in given]
            raise TypeError(f"{cls}() missing field{'s' if len(missing) > 1 else ''} {', '.join(missing)} "
                            f"(give every field, or none for all zeros)")
        for name in names:
            if name in given:
                self._set(name, given[name], f"{cls}.{name}")

    def _set(self, name, value, where):
        ctype = dict(self._fields_)[name]
        if isinstance(ctype, type) and issubclass(ctype, _Struct):
            value = struct_value(ctype, value, where)
        elif isinstance(ctype, type) and issubclass(ctype, ctypes.Array):
            value = _array_value(ctype, value, where)
        else:
            value = real(value, ctype, where)
        super().__setattr__(name, value)

    def __setattr__(self, name, value):
        if name not in dict(self._fields_):
            raise AttributeError(f"{type(self).__name__} has no field {name!r} "
                                 f"(fields: {', '.join(f for f, _ in self._fields_)})")
        self._set(name, value, f"{type(self).__name__}.{name}")

    def _values(self):
        """Every field's value; an array field (a ball's spin) as a tuple."""
        values = (getattr(self, name) for name, _ in self._fields_)
        return tuple(tuple(x) if isinstance(x, ctypes.Array) else x for x in values)

    def __repr__(self):
        return f"{type(self).__name__}(" + ", ".join(
            f"{name}={value!r}" for (name, _), value in zip(self._fields_, self._values())) + ")"

    def __eq__(self, other):
        return type(self) is type(other) and self._values() == other._values()

    __hash__ = None


def _vec2(real):
    class Vec2(_Struct):
        _fields_ = [("x", real), ("y", real)]

        def __iter__(self):  # so that x, y = v and tuple(v) work
            return iter((self.x, self.y))

    return Vec2


def _types(real, suffix):
    """The C structs of one variant (double: suffix "", float: "f")."""
    vec2 = _vec2(real)
    ns = {"Vec2": vec2}
    ns["Body"] = type("Body", (_Struct,), {"_fields_": [("pos", vec2), ("vel", vec2), ("mass", real)]})
    ns["Disk"] = type("Disk", (_Struct,), {"_fields_": [
        ("pos", vec2), ("vel", vec2), ("spin", real), ("mass", real), ("radius", real), ("inertia", real)]})
    ns["Surface"] = type("Surface", (_Struct,), {"_fields_": [
        ("restitution", real), ("friction", real), ("tangential_restitution", real)]})
    ns["Ball"] = type("Ball", (_Struct,), {"_fields_": [
        ("pos", vec2), ("vel", vec2), ("spin", real * 3), ("mass", real), ("radius", real), ("inertia", real)]})
    ns["BallSurface"] = type("BallSurface", (_Struct,), {"_fields_": [
        ("restitution", real), ("friction", real), ("friction_boost", real), ("friction_decay", real)]})
    ns["Cushion"] = type("Cushion", (_Struct,), {"_fields_": [
        ("normal", vec2), ("height", real), ("restitution", real), ("friction", real)]})
    ptr = ctypes.POINTER(real)
    ns["Pairs"] = type("Pairs", (ctypes.Structure,), {"_fields_": [
        (name, ptr) for name in ("pos_ax", "pos_ay", "pos_bx", "pos_by",
                                 "vel_ax", "vel_ay", "vel_bx", "vel_by", "mass_a", "mass_b")]})
    for name, cls in ns.items():
        cls.__name__ = cls.__qualname__ = name + suffix
        cls.__module__ = "collide2d"
    return ns


DOUBLE = _types(ctypes.c_double, "")
FLOAT = _types(ctypes.c_float, "f")


class Out:
    """Marks an output parameter: the wrapper allocates it and returns it."""

    def __init__(self, ctype):
        self.ctype = ctype


def _prototypes(t, real, sfx):
    p = ctypes.POINTER
    return {
        "c2d_collide" + sfx: (p(t["Body"]), p(t["Body"]), real),
        "c2d_collide_normal" + sfx: (p(t["Body"]), p(t["Body"]), t["Vec2"], real),
        "c2d_time_of_impact" + sfx: (p(t["Body"]), p(t["Body"]), real, Out(real)),
        "c2d_time_of_impact_accel" + sfx: (p(t["Body"]), t["Vec2"], p(t["Body"]), t["Vec2"], real, real,
                                           Out(real)),
        "c2d_collide_rough" + sfx: (p(t["Disk"]), p(t["Disk"]), t["Surface"]),
        "c2d_collide_rough_normal" + sfx: (p(t["Disk"]), p(t["Disk"]), t["Vec2"], t["Surface"]),
        "c2d_collide_balls" + sfx: (p(t["Ball"]), p(t["Ball"]), t["BallSurface"]),
        "c2d_collide_cushion" + sfx: (p(t["Ball"]), t["Cushion"]),
        "c2d_collide_batch" + sfx: (p(t["Pairs"]), ctypes.c_size_t, real, p(ctypes.c_int)),
    }


# Every entry point: its argument types; each returns c2d_status (a C int)
# but the batch, which returns size_t.  An Out(...) argument is allocated by
# the wrapper and returned after the status.  A new entry point is one line
# in _prototypes and a documented def in __init__.py that calls _call with
# its C name.
PROTOTYPES = {}
PROTOTYPES.update(_prototypes(DOUBLE, ctypes.c_double, ""))
PROTOTYPES.update(_prototypes(FLOAT, ctypes.c_float, "f"))


@functools.lru_cache(maxsize=None)
def function(name):
    """The C function `name` with its prototype set, or None if the library
    was built without it (C2D_NO_DOUBLE, C2D_NO_FLOAT, an older version)."""
    fn = getattr(LIB, name, None)
    if fn is None:
        return None
    args = PROTOTYPES[name]
    fn.argtypes = [ctypes.POINTER(a.ctype) if isinstance(a, Out) else a for a in args]
    fn.restype = ctypes.c_size_t if name.startswith("c2d_collide_batch") else ctypes.c_int
    return fn


LIB.c2d_version.argtypes = []
LIB.c2d_version.restype = ctypes.c_long
LIB.c2d_status_string.argtypes = [ctypes.c_int]
LIB.c2d_status_string.restype = ctypes.c_char_p


# ------------------------------------------------------------ the world
# collide2d_world.h's structs, plain ctypes (their fields are not all
# doubles; collide2d.World checks every value before it fills them in).

EVENT_CALLBACK = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_void_p)  # (user, const c2d_world_event *)


class WorldEvent(ctypes.Structure):
    _fields_ = [("kind", ctypes.c_int), ("time", ctypes.c_double), ("a", ctypes.c_size_t),
                ("b", ctypes.c_size_t), ("impulse", DOUBLE["Vec2"])]


class WorldDesc(ctypes.Structure):
    _fields_ = [("capacity", ctypes.c_size_t), ("width", ctypes.c_double), ("height", ctypes.c_double),
                ("boundary", ctypes.c_int), ("restitution", ctypes.c_double),
                ("wall_restitution", ctypes.c_double), ("collapse_speed", ctypes.c_double),
                ("collapse_count", ctypes.c_uint), ("collapse_time", ctypes.c_double),
                ("collapse_length", ctypes.c_double), ("on_event", EVENT_CALLBACK),
                ("user", ctypes.c_void_p), ("statics", ctypes.c_size_t), ("model", ctypes.c_int),
                ("friction", ctypes.c_double), ("wall_friction", ctypes.c_double),
                ("tangential_restitution", ctypes.c_double), ("inertia_factor", ctypes.c_double),
                ("resolve_impact", ctypes.c_void_p), ("resolve_wall", ctypes.c_void_p),
                ("resolve_static", ctypes.c_void_p),
                ("broadphase", ctypes.c_void_p)]  # const c2d_world_broadphase *: NULL, the built-in cells


class WorldContact(ctypes.Structure):
    """What a resolver is given (no resolver is set from Python yet)."""
    _fields_ = [("kind", ctypes.c_int), ("time", ctypes.c_double), ("a", ctypes.c_size_t),
                ("b", ctypes.c_size_t), ("normal", DOUBLE["Vec2"]), ("restitution", ctypes.c_double),
                ("collapsed", ctypes.c_int)]


class WorldStats(ctypes.Structure):
    _fields_ = [("collisions", ctypes.c_ulonglong), ("wall_collisions", ctypes.c_ulonglong),
                ("events", ctypes.c_ulonglong), ("time", ctypes.c_double), ("virial", ctypes.c_double)]


for _cls in (WorldEvent, WorldDesc, WorldContact, WorldStats):
    _cls.__module__ = "collide2d"


@functools.lru_cache(maxsize=None)
def world_functions():
    """The c2d_world_* functions with their prototypes, or None if the
    library has no world (C2D_NO_DOUBLE, a version before it)."""
    if getattr(LIB, "c2d_world_init", None) is None:
        return None
    p, vp, size, st = ctypes.POINTER, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int
    body = DOUBLE["Body"]
    protos = {
        "bytes": (size, [p(WorldDesc)]),
        "init": (st, [p(vp), vp, size, p(WorldDesc)]),
        "add": (st, [vp, p(body), ctypes.c_double, p(size)]),
        "advance": (st, [vp, ctypes.c_double]),
        "get": (st, [vp, size, p(body)]),
        "get_stats": (None, [vp, p(WorldStats)]),
        "count": (size, [vp]),
        "set_velocity": (st, [vp, size, DOUBLE["Vec2"]]),
        "remove": (st, [vp, size]),
    }
    fns = {}
    for name, (restype, argtypes) in protos.items():
        fn = getattr(LIB, "c2d_world_" + name)
        fn.restype, fn.argtypes = restype, argtypes
        fns[name] = fn
    return fns
