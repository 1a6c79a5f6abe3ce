/* SPDX-License-Identifier: MIT */
// det_math.cpp - see det_math.h.  Only + - * /, sqrt, comparisons and exact
// conversions; the methods and the constants are those of Sun's fdlibm
// (which glibc's and musl's own come from), written out again here:
//   Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
//   Developed at SunPro, a Sun Microsystems, Inc. business.  Permission to
//   use, copy, modify, and distribute this software is freely granted,
//   provided that this notice is preserved.
// Each constant is the double nearest the decimal given (fdlibm's hex words
// beside it); a wrong digit would show as a large error in
// demo/tests/test_det_math.cpp, which compares each function with glibc's.
#include "pool/det_math.h"

#include <cmath>  // sqrt (correctly rounded by IEEE 754), std::signbit (a bit test)

namespace demo {

namespace {

double magnitude(double x) { return x < 0 ? -x : x; }

// Rounds t to the nearest integer (ties to even) without a library call: for
// |t| < 2^51, t + 1.5 * 2^52 lands where the unit is 1, so the addition rounds
// t to an integer and the subtraction is exact; larger t are integers already.
double nearest_integer(double t) {
    constexpr double shift = 6755399441055744.0;  // 1.5 * 2^52
    if (!(magnitude(t) < 2251799813685248.0)) return t;  // 2^51 (and NaN)
    return t >= 0 ? (t + shift) - shift : (t - shift) + shift;
}

// x = n pi/2 + (y0 + y1), |y0 + y1| <= ~pi/4, n mod 4 returned.  pi/2 in
// three pieces of 33 significant bits (pio2_1, pio2_2, pio2_3) and the tails
// of the last two (..t): n * pio2_k is exact for |n| < 2^20, so the first
// subtractions are exact and each step carries what the previous dropped
// (fdlibm's __ieee754_rem_pio2, its medium-size path, all three steps always).
int reduce_pio2(double x, double &y0, double &y1) {
    constexpr double invpio2 = 6.36619772367581382433e-01;  // 0x3FE45F30 6DC9C883
    constexpr double pio2_1 = 1.57079632673412561417e+00;   // 0x3FF921FB 54400000
    constexpr double pio2_2 = 6.07710050630396597660e-11;   // 0x3DD0B461 1A600000
    constexpr double pio2_3 = 2.02226624871116645580e-21;   // 0x3BA3198A 2E000000
    constexpr double pio2_3t = 8.47842766036889956997e-32;  // 0x397B839A 252049C1
    const double fn = nearest_integer(x * invpio2);
    // the first tail (pi/2 - pio2_1 = pio2_2 + pio2_2t + ...) is taken in
    // its own two pieces, so the steps start with pio2_2
    // (fdlibm's second step's tail, fn * pio2_2t - ((t - r) - w), feeds only
    // its y[0], which the third step recomputes: not formed here)
    double t = x - fn * pio2_1, w = fn * pio2_2, r = t - w;
    t = r;
    w = fn * pio2_3;
    r = t - w;
    w = fn * pio2_3t - ((t - r) - w);
    y0 = r - w;
    y1 = (r - y0) - w;
    // n mod 4: |fn| >= 2^62 is a multiple of 4 (its unit is >= 2^10)
    if (!(magnitude(fn) < 4611686018427387904.0)) return 0;
    return static_cast<int>(static_cast<long long>(fn) & 3);
}

// sin(x + y) on |x| <= pi/4, y a tail below x's last bit: x + x^3 (S1 + x^2 r)
// with the tail's first-order term y (1 - x^2/2) (fdlibm's __kernel_sin).
double kernel_sin(double x, double y) {
    constexpr double S1 = -1.66666666666666324348e-01;  // 0xBFC55555 55555549
    constexpr double S2 = 8.33333333332248946124e-03;   // 0x3F811111 1110F8A6
    constexpr double S3 = -1.98412698298579493134e-04;  // 0xBF2A01A0 19C161D5
    constexpr double S4 = 2.75573137070700676789e-06;   // 0x3EC71DE3 57B1FE7D
    constexpr double S5 = -2.50507602534068634195e-08;  // 0xBE5AE5E6 8A2B9CEB
    constexpr double S6 = 1.58969099521155010221e-10;   // 0x3DE5D93A 5ACFD57C
    const double z = x * x, v = z * x, r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    return x - ((z * (0.5 * y - v * r) - y) - v * S1);
}

// cos(x + y) on |x| <= pi/4: 1 - x^2/2 + x^4 (C1 + ...), the 1 - x^2/2
// split so that its rounding error is added back (fdlibm's __kernel_cos).
double kernel_cos(double x, double y) {
    constexpr double C1 = 4.16666666666666019037e-02;   // 0x3FA55555 5555554C
    constexpr double C2 = -1.38888888888741095749e-03;  // 0xBF56C16C 16C15177
    constexpr double C3 = 2.48015872894767294178e-05;   // 0x3EFA01A0 19CB1590
    constexpr double C4 = -2.75573143513906633035e-07;  // 0xBE927E4F 809C52AD
    constexpr double C5 = 2.08757232129817482790e-09;   // 0x3E21EE9E BDB4B1C4
    constexpr double C6 = -1.13596475577881948265e-11;  // 0xBDA8FAE9 BE8838D4
    const double z = x * x, r = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
    const double hz = 0.5 * z, w = 1.0 - hz;
    return w + (((1.0 - w) - hz) + (z * r - x * y));
}

constexpr double kPio4 = 7.85398163397448278999e-01;  // 0x3FE921FB 54442D18

}  // namespace

double det_hypot(double x, double y) {
    double a = magnitude(x), b = magnitude(y);
    if (a == INFINITY || b == INFINITY) return INFINITY;  // also with a NaN, as C's hypot
    if (a != a || b != b) return a + b;                   // NaN
    if (a < b) {
        const double t = a;
        a = b;
        b = t;
    }
    if (a == 0) return 0;
    // keep the squares clear of overflow and of the subnormals: scale by an
    // exact power of two (a smaller b underflowing adds less than a rounding)
    double scale = 1;
    if (a > 0x1p500) {
        a *= 0x1p-600;
        b *= 0x1p-600;
        scale = 0x1p600;
    } else if (a < 0x1p-500) {
        a *= 0x1p600;
        b *= 0x1p600;
        scale = 0x1p-600;
    }
    return std::sqrt(a * a + b * b) * scale;
}

double det_sin(double x) {
    if (magnitude(x) <= kPio4) return x == 0 ? x : kernel_sin(x, 0.0);  // keeps -0
    if (x - x != 0) return x - x;                                      // infinity or NaN: NaN
    double y0 = 0, y1 = 0;
    switch (reduce_pio2(x, y0, y1)) {
    case 0: return kernel_sin(y0, y1);
    case 1: return kernel_cos(y0, y1);
    case 2: return -kernel_sin(y0, y1);
    default: return -kernel_cos(y0, y1);
    }
}

double det_cos(double x) {
    if (magnitude(x) <= kPio4) return kernel_cos(x, 0.0);
    if (x - x != 0) return x - x;
    double y0 = 0, y1 = 0;
    switch (reduce_pio2(x, y0, y1)) {
    case 0: return kernel_cos(y0, y1);
    case 1: return -kernel_sin(y0, y1);
    case 2: return -kernel_cos(y0, y1);
    default: return kernel_sin(y0, y1);
    }
}

double det_tan(double x) { return det_sin(x) / det_cos(x); }

// atan: |x| reduced to [0, 7/16] by atan(x) = atan(c) + atan((x - c)/(1 + c x))
// for c = 1/2, 1, 3/2, infinity (atan(c) in two pieces), then an odd minimax
// polynomial in the even and the odd coefficients (fdlibm's s_atan.c).
double det_atan(double x) {
    static const double atanhi[] = {4.63647609000806093515e-01, 7.85398163397448278999e-01, 9.82793723247329054082e-01,
                                    1.57079632679489655800e+00};
    static const double atanlo[] = {2.26987774529616870924e-17, 3.06161699786838301793e-17, 1.39033110312309984516e-17,
                                    6.12323399573676603587e-17};
    static const double aT[] = {3.33333333333329318027e-01,  -1.99999999998764832476e-01, 1.42857142725034663711e-01,
                                -1.11111104054623557880e-01, 9.09088713343650656196e-02,  -7.69187620504482999495e-02,
                                6.66107313738753120669e-02,  -5.83357013379057348645e-02, 4.97687799461593236017e-02,
                                -3.65315727442169155270e-02, 1.62858201153657823623e-02};
    if (x != x) return x + x;
    const bool negative = x < 0;
    double a = magnitude(x);
    if (a >= 0x1p66) return negative ? -(atanhi[3] + atanlo[3]) : atanhi[3] + atanlo[3];
    int id = -1;
    if (a < 0.4375) {
        if (a < 0x1p-27) return x;  // atan(x) = x - x^3/3 rounds to x
    } else if (a < 1.1875) {
        if (a < 0.6875) {
            id = 0;
            a = (2.0 * a - 1.0) / (2.0 + a);
        } else {
            id = 1;
            a = (a - 1.0) / (a + 1.0);
        }
    } else if (a < 2.4375) {
        id = 2;
        a = (a - 1.5) / (1.0 + 1.5 * a);
    } else {
        id = 3;
        a = -1.0 / a;
    }
    const double z = a * a, w = z * z;
    const double s1 = z * (aT[0] + w * (aT[2] + w * (aT[4] + w * (aT[6] + w * (aT[8] + w * aT[10])))));
    const double s2 = w * (aT[1] + w * (aT[3] + w * (aT[5] + w * (aT[7] + w * aT[9]))));
    if (id < 0) return negative ? -(a - a * (s1 + s2)) : a - a * (s1 + s2);
    const double r = atanhi[id] - ((a * (s1 + s2) - atanlo[id]) - a);
    return negative ? -r : r;
}

// atan2: atan(|y/x|) put in its quadrant, pi - z as pi - (z - pi_lo) so that
// pi's rounding error is not added to z's; the special cases of C's atan2.
double det_atan2(double y, double x) {
    constexpr double pi_lo = 1.2246467991473531772e-16;  // pi - kPi, 0x3CA1A626 33145C07
    constexpr double pio2 = 1.57079632679489655800e+00;
    if (x != x || y != y) return x + y;
    const bool y_neg = std::signbit(y), x_neg = std::signbit(x);
    if (y == 0) return x_neg ? (y_neg ? -kPi : kPi) : y;  // +-0 for x >= +0, +-pi for x <= -0
    if (x == 0) return y_neg ? -pio2 : pio2;
    const double ax = magnitude(x), ay = magnitude(y);
    if (ax == INFINITY) {
        if (ay == INFINITY) {
            const double q = x_neg ? 3 * kPio4 : kPio4;
            return y_neg ? -q : q;
        }
        return x_neg ? (y_neg ? -kPi : kPi) : (y_neg ? -0.0 : 0.0);
    }
    if (ay == INFINITY) return y_neg ? -pio2 : pio2;
    const double z = det_atan(ay / ax);  // ay / ax may overflow to infinity (pi/2) or underflow (0)
    if (!x_neg) return y_neg ? -z : z;
    const double r = kPi - (z - pi_lo);
    return y_neg ? -r : r;
}

double det_asin(double x) { return det_atan2(x, std::sqrt((1.0 - x) * (1.0 + x))); }

double det_acos(double x) { return det_atan2(std::sqrt((1.0 - x) * (1.0 + x)), x); }

}  // namespace demo
