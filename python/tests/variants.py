# SPDX-License-Identifier: MIT
"""The two precisions of the binding as one object each, shared by the test
modules: v.Body, v.collide, ... are collide2d's Body/collide (double) or
Bodyf/collidef (float); v.real is the ctypes scalar, v.other the other
precision.  (pytest puts python/tests on sys.path: `from variants import`.)"""
import ctypes

import collide2d as c


class Variant:
    def __init__(self, sfx, real):
        self.sfx, self.real = sfx, real
        for name in ("Vec2", "Body", "Disk", "Surface", "Ball", "BallSurface", "Cushion", "collide",
                     "collide_normal", "time_of_impact", "time_of_impact_accel", "collide_rough",
                     "collide_rough_normal", "collide_balls", "collide_cushion"):
            setattr(self, name, getattr(c, name + sfx))
        self.other = None

    def __repr__(self):
        return "double" if self.sfx == "" else "float"


DOUBLE, FLOAT = Variant("", ctypes.c_double), Variant("f", ctypes.c_float)
DOUBLE.other, FLOAT.other = FLOAT, DOUBLE
VARIANTS = [DOUBLE, FLOAT]
