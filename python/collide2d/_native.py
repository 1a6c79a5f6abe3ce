# SPDX-License-Identifier: MIT
"""The shared library, its C types and its prototypes (ctypes).

The library is found, in order:
  1. the path in the environment variable COLLIDE2D_LIB;
  2. build/libcollide2d.so of the source tree this package sits in
     (python/collide2d/ -> ../../build/), what `make` builds;
  3. the system's (`make install`, ctypes.util.find_library).
"""
import ctypes
import ctypes.util
import functools
import os

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


class _Struct(ctypes.Structure):
    """A C struct with a readable repr and equality by value; a nested struct
    field may be given as any sequence of numbers (a tuple, a list, a numpy
    row): Body((0, 0), (1, 0), 1.0)."""

    def __init__(self, *args, **kwargs):
        types = dict(self._fields_)
        args = [_nested(t, a) for (_, t), a in zip(self._fields_, args)] + list(args[len(self._fields_):])
        kwargs = {k: _nested(types.get(k), a) for k, a in kwargs.items()}
        super().__init__(*args, **kwargs)

    def _values(self):
        return tuple(getattr(self, name) for name, _ in self._fields_)

    def __repr__(self):
        return f"{type(self).__name__}(" + ", ".join(
            f"{name}={getattr(self, name)!r}" for name, _ in self._fields_) + ")"

    def __eq__(self, other):
        return type(self) is type(other) and self._values() == other._values()

    __hash__ = None


def _nested(ctype, value):
    """A sequence given for a struct field, as the tuple ctypes takes."""
    if isinstance(ctype, type) and issubclass(ctype, ctypes.Structure) and not isinstance(value, ctype):
        try:
            return tuple(value)
        except TypeError:
            return value
    return value


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
        "c2d_collide_rough" + sfx: (p(t["Disk"]), p(t["Disk"]), t["Surface"]),
        "c2d_collide_rough_normal" + sfx: (p(t["Disk"]), p(t["Disk"]), t["Vec2"], t["Surface"]),
        "c2d_collide_batch" + sfx: (p(t["Pairs"]), ctypes.c_size_t, real, p(ctypes.c_int)),
    }


# Every entry point: its argument types; each returns c2d_status (a C int)
# but the batch, which returns size_t.  An Out(...) argument is allocated by
# the wrapper and returned after the status.  A new entry point is one line
# in _prototypes (c2d_time_of_impact_accel: its pointer, vector and real
# arguments and Out(real) for *t) and a documented def in __init__.py that
# calls _call with its C name.
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
