/* SPDX-License-Identifier: MIT */
// det_math.h - the elementary functions the simulation needs, built from
// + - * / and sqrt only, so that a shot gives the same bits on every machine
// and in every C library (glibc on x86-64 and aarch64, emscripten's musl in
// the browser).  Those libraries' sin, cos, atan2, hypot ... are accurate to
// about an ulp but differ from each other in the last bit on millions of
// inputs; IEEE 754 fixes the result of each basic operation and of sqrt, so a
// function written with nothing else is the same function everywhere
// (compiled with -ffp-contract=off, as the demo is: no fused multiply-adds).
//
// Which code uses them: everything between a shot and rest, and what decides a
// shot (demo/pool, demo/game).  Drawing and sound keep <cmath>.
//
// Accuracy (demo/tests/test_det_math.cpp measures it against glibc, which is
// itself within 1 ulp, on 10^6 inputs per function, and asserts these bounds):
//   det_hypot        within 1 ulp (sqrt of a sum of two rounded squares:
//                    relative error <= 1.5 u + u, u = 2^-53), no overflow or
//                    underflow in between (scaled by powers of two)
//   det_sin, det_cos within 1 ulp for |x| <= 2^20 pi/2 (Cody-Waite reduction by
//                    a three-piece pi/2, then fdlibm's minimax kernels on
//                    [-pi/4, pi/4]); beyond that the reduction loses bits
//                    (still the same bits everywhere); NaN for infinities
//   det_tan          det_sin / det_cos: within 3 ulp
//   det_atan         within 1 ulp (fdlibm's argument table and polynomial)
//   det_atan2        within 2 ulp, the quadrants and signed zeros as C's atan2
//   det_asin, det_acos  via det_atan2 and sqrt((1 - x)(1 + x)): within 3 ulp
//                    (acos near 1 and asin near +-1 lose relative accuracy, as
//                    the square root of a rounded 1 - x does); NaN outside [-1, 1]
// Cost: a few tens of flops each, no tables beyond 8 constants.
// Angles in radians; no errno, no exceptions.
#ifndef C2D_DEMO_DET_MATH_H
#define C2D_DEMO_DET_MATH_H

namespace demo {

constexpr double kPi = 3.14159265358979311600e+00;  // pi rounded to double (M_PI)

double det_hypot(double x, double y);
double det_sin(double x);
double det_cos(double x);
double det_tan(double x);
double det_atan(double x);
double det_atan2(double y, double x);
double det_asin(double x);
double det_acos(double x);

}  // namespace demo

#endif
