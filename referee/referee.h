/* SPDX-License-Identifier: MIT */
/* Exact referee for collide2d: GMP rationals for the collision (the impulse
 * form is rational in the inputs), MPFR at 256 bits for the time of impact.
 * Used by the tests and the benchmark to measure errors in ulp. */
#ifndef C2D_REFEREE_H
#define C2D_REFEREE_H

#include <gmp.h>
#include "collide2d.h"

/* One collision's inputs in double (float inputs convert exactly). */
typedef struct ref_case {
    double pa[2], pb[2], va[2], vb[2];
    double ma, mb;
    double n[2];   /* used when has_normal; else n = pb - pa exactly */
    int has_normal;
    double e;
} ref_case;

/* Exact answer: status (INVALID/DEGENERATE/SEPARATING/OK) and, on OK, the
 * exact new velocities {va'x, va'y, vb'x, vb'y}.  `range_limit` is the largest
 * finite value of the precision under test; range_allowed is set when an
 * exact result or velocity change reaches range_limit / 8 (C2D_RANGE is then
 * acceptable) and range_required when a result exceeds range_limit. */
typedef struct ref_answer {
    c2d_status status;
    int range_allowed, range_required;
    mpq_t v[4];
} ref_answer;

void ref_answer_init(ref_answer *r);
void ref_answer_clear(ref_answer *r);
void ref_collide(const ref_case *c, double range_limit, ref_answer *out);

/* ulp of a velocity scale s >= 0 in a format with `prec` significand bits
 * and smallest normal exponent `emin` (53/-1022 double, 24/-126 float). */
double ref_ulp(double s, int prec, int emin);

/* |got - exact| / ulp, as a double (may be huge or Inf). */
double ref_err_ulp(double got, const mpq_t exact, double ulp);

/* Worst error over the four outputs, each in ulp of its own body's velocity
 * scale (largest |component| before and exactly after). */
double ref_collide_err(const ref_case *c, const ref_answer *r, const double got[4], int prec, int emin);

/* Time of impact: status and t (rounded to double from 256-bit MPFR).  Also
 * returns the tolerance unit: ulp(t) + ulp(|d|) / (approach speed at contact,
 * sqrt(b^2 - ac) / R): the time one rounding of the distance is worth. */
c2d_status ref_time_of_impact(const ref_case *c, double radius_sum, double *t, double *unit, int prec, int emin);

/* Is got the representable value nearest to exact (ties to the even
 * significand), in double (is_float 0) or float (1), subnormals included?
 * Past the largest finite value the neighbour is 2^1024 (2^128), the value
 * IEEE rounding treats as the next one. */
int ref_correctly_rounded(double got, const mpq_t exact, int is_float);

/* Exact (mpq) momentum and energy error of a collision result relative to
 * the total momentum / energy magnitude; immovable bodies are excluded. */
void ref_conservation(const ref_case *c, const double got[4], double *momentum_rel, double *energy_rel);

#endif
