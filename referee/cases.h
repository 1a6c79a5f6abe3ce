/* SPDX-License-Identifier: MIT */
/* Generators of collision cases, shared by the tests, the benchmark and
 * the vector generator: plain (unit-scale scenes) and extreme (the whole
 * range), driven by the seeded generator of rng.h, and the conversion of a
 * case into library bodies. */
#ifndef C2D_CASES_H
#define C2D_CASES_H

#include <stdint.h>
#include "referee.h"
#include "rng.h"

/* Unit-scale scene: positions within 10, centres ~1 apart, speeds <= 10,
 * masses 0.1..10, restitution in [0, 1] (0 and 1 included often). */
void gen_plain(c2d_rng *r, ref_case *c);

/* Anywhere in the format: each magnitude 2^k with k uniform over the whole
 * exponent range (subnormals included), zeros, mass ratios up to the full
 * range and INFINITY masses.  `prec`/`emin`/`emax` select double (53, -1022,
 * 1023) or float (24, -126, 127); values are exactly representable there. */
void gen_extreme(c2d_rng *r, ref_case *c, int prec, int emin, int emax);

/* A random value 2^k * (1 + mantissa) with k uniform in [kmin, kmax] and a
 * random sign, rounded to `prec` bits. */
double gen_magnitude(c2d_rng *r, int kmin, int kmax, int prec);
/* A time-of-impact pair with every component at its own exponent anywhere
 * in the format's range (subnormals included): magnitudes that differ by
 * more than the exponent range.  Approaching more often than not; unit
 * masses, e = 0, no normal. */
void gen_toi_ratios(c2d_rng *r, ref_case *c, double *radius, int prec, int emin, int emax);

/* Copy a case into library bodies. */
void case_to_bodies(const ref_case *c, c2d_body *a, c2d_body *b);
void case_to_bodiesf(const ref_case *c, c2d_bodyf *a, c2d_bodyf *b);

/* Round every input of a case to float, as a float caller has them (the
 * referee then sees exactly what the float function gets). */
/* x rounded to float and back, through a volatile: gcc 12.2's -O2 SLP
 * vectoriser drops a (double)(float) round trip in straight-line code (a
 * case generator's conversions came out unrounded in a plain build and
 * rounded in a sanitised one, so the streams differed). */
double ref_to_float(double x);
void case_to_float(ref_case *c);

#endif
