# SPDX-License-Identifier: MIT
"""Batch collisions on numpy arrays, in place (c2d_collide_batch(f)).

Pair i is disk a = (pos_a[:, i], vel_a[:, i], mass_a[i]) against disk b, the
same fields of b.  Positions and velocities are arrays of shape (2, n): row 0
the x components, row 1 the y components, each row contiguous (structure of
arrays, as the C library takes them); or a pair (x, y) of 1-D arrays.
Masses are 1-D arrays of length n.  The velocities are written in place, so
their arrays must be writeable and must not share memory with any other
argument.  Every pair is resolved exactly as collide / collidef would (the
same bits and statuses).

dtype: float64 for collide_batch, float32 for collide_batchf, exactly (no
conversion, since the results are written back into your arrays); status, if
given, an array of n numpy.intc.  A wrong type is a TypeError, a wrong shape,
layout or an overlap a ValueError; nothing is written then.

numpy is imported on the first batch call, so the scalar API works without it.
"""
import ctypes

from . import _native

FIELDS = ("pos_a", "pos_b", "vel_a", "vel_b")


def _rows(np, fn, name, value, dtype, writeable):
    """The x and y rows of a position or velocity argument, checked."""
    if isinstance(value, np.ndarray):
        if value.ndim != 2 or value.shape[0] != 2:
            raise ValueError(f"{fn}: {name} must have shape (2, n) (rows x, y), not {value.shape}")
        rows = (value[0], value[1])
    elif isinstance(value, (tuple, list)):
        if len(value) != 2:
            raise ValueError(f"{fn}: {name} as rows must be a pair (x, y), not {len(value)} rows")
        rows = tuple(value)
    else:
        raise TypeError(f"{fn}: {name} must be a numpy array of shape (2, n) or a pair (x, y) of "
                        f"1-D numpy arrays, not {type(value).__name__}")
    return tuple(_array(np, fn, f"{name}[{k}]", r, dtype, writeable) for k, r in enumerate(rows))


def _array(np, fn, name, value, dtype, writeable):
    """A 1-D contiguous array of exactly `dtype`, checked."""
    if not isinstance(value, np.ndarray):
        raise TypeError(f"{fn}: {name} must be a numpy array, not {type(value).__name__}")
    if value.dtype != dtype:
        raise TypeError(f"{fn}: {name} must have dtype {np.dtype(dtype).name}, not {value.dtype.name} "
                        f"(it is written in place, so it is not converted)")
    if value.ndim != 1:
        raise ValueError(f"{fn}: {name} must be 1-D, not of shape {value.shape}")
    if not value.flags.c_contiguous:
        raise ValueError(f"{fn}: {name} must be contiguous (use numpy.ascontiguousarray)")
    if writeable and not value.flags.writeable:
        raise ValueError(f"{fn}: {name} is written in place but is read-only")
    return value


def _batch(cname, dtype, ctype, pos_a, pos_b, vel_a, vel_b, mass_a, mass_b, restitution, status):
    import numpy as np

    fn = cname[len("c2d_"):]
    arrays = {}
    for name, value in zip(FIELDS, (pos_a, pos_b, vel_a, vel_b)):
        arrays[name + "x"], arrays[name + "y"] = _rows(np, fn, name, value, dtype, name.startswith("vel"))
    arrays["mass_a"] = _array(np, fn, "mass_a", mass_a, dtype, False)
    arrays["mass_b"] = _array(np, fn, "mass_b", mass_b, dtype, False)
    n = len(arrays["mass_a"])
    for name, a in arrays.items():
        if len(a) != n:
            shown = name[:-1] + ("[0]" if name[-1] == "x" else "[1]") if name.startswith(FIELDS) else name
            raise ValueError(f"{fn}: {shown} has {len(a)} pairs, mass_a {n}: every array needs the same length")
    if status is not None:
        status = _array(np, fn, "status", status, np.intc, True)
        if len(status) != n:
            raise ValueError(f"{fn}: status has {len(status)} entries for {n} pairs")
    restitution = _native.real(restitution, ctype, f"{fn}: restitution")
    written = [arrays[k] for k in arrays if k.startswith("vel")] + ([status] if status is not None else [])
    everything = list(arrays.values()) + ([status] if status is not None else [])
    for w in written:
        for other in everything:
            if other is not w and np.shares_memory(w, other):
                raise ValueError(f"{fn}: the velocity and status arrays must not share memory "
                                 "with each other or with any other argument")
    c_fn = _native.function(cname)
    if c_fn is None:
        raise NotImplementedError(f"{cname} is not in {_native.LIB_PATH} (built without this variant?)")
    pairs = _native.DOUBLE["Pairs"]() if dtype == np.float64 else _native.FLOAT["Pairs"]()
    for field, a in arrays.items():  # the C struct's field names
        setattr(pairs, field, a.ctypes.data_as(ctypes.POINTER(ctype)))
    st = status.ctypes.data_as(ctypes.POINTER(ctypes.c_int)) if status is not None else None
    return int(c_fn(ctypes.byref(pairs), n, restitution, st))


def collide_batch(pos_a, pos_b, vel_a, vel_b, mass_a, mass_b, restitution, status=None):
    """Resolve n independent pairs in place (float64 arrays), each exactly as
    collide() would.  pos_*, vel_*: shape (2, n) or (x, y); mass_*: (n,),
    math.inf = immovable; restitution in [0, 1] for every pair; status: None
    or an int array (numpy.intc) of n to receive each pair's Status.  Returns
    the number of pairs resolved (Status.OK); the others are left untouched."""
    import numpy as np
    return _batch("c2d_collide_batch", np.float64, ctypes.c_double,
                  pos_a, pos_b, vel_a, vel_b, mass_a, mass_b, restitution, status)


def collide_batchf(pos_a, pos_b, vel_a, vel_b, mass_a, mass_b, restitution, status=None):
    """Float twin of collide_batch: float32 arrays, each pair as collidef()."""
    import numpy as np
    return _batch("c2d_collide_batchf", np.float32, ctypes.c_float,
                  pos_a, pos_b, vel_a, vel_b, mass_a, mass_b, restitution, status)
