/* SPDX-License-Identifier: MIT */
/* cases_rough.h - rough-disk contacts for the tests and the benchmark:
 * the generators (unit scale, whole range), the case as the float call sees
 * it, and the library called on a case. */
#ifndef C2D_CASES_ROUGH_H
#define C2D_CASES_ROUGH_H
#include "ref_rough.h"
#include "rng.h"

/* A unit-scale contact: radii 0.1..1 touching (to rounding) along a random
 * line, speeds and spin x radius up to 10, inertia k m r^2 with k in
 * [0.1, 1] or INFINITY, 10% walls, restitution, friction (0.05, 0.2, 1,
 * 1e6, INFINITY) and beta over their range; approaching more often than not. */
void gen_rough(c2d_rng *r, ref_rough_case *c);
/* The normal part anywhere in the range (gen_extreme), spins, radii and
 * inertias too, for the format of precision prec and exponents emin..emax. */
void gen_rough_extreme(c2d_rng *r, ref_rough_case *c, int prec, int emin, int emax);
/* Every input rounded to float (what the float call sees). */
void rough_case_to_float(ref_rough_case *c);

void rough_disk_of(c2d_disk *d, const ref_disk *r);
void rough_diskf_of(c2d_diskf *d, const ref_disk *r);
c2d_surface rough_surface_of(const ref_rough_case *c);
/* c2d_collide_rough(_normal) (double) or its float twin on the case:
 * the status and {va.x, va.y, vb.x, vb.y, spin a, spin b} (inputs where
 * nothing was written). */
c2d_status rough_call(const ref_rough_case *c, double out[6]);
c2d_status rough_callf(const ref_rough_case *c, double out[6]);
#endif
