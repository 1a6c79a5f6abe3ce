/* SPDX-License-Identifier: MIT */
/* Case generators for the sphere contacts (c2d_collide_balls,
 * c2d_collide_cushion) and the calls that run one case through the library,
 * shared by tests/unit/test_sphere.c and bench/sphere.c. */
#ifndef C2D_CASES_SPHERE_H
#define C2D_CASES_SPHERE_H

#include "collide2d.h"
#include "ref_sphere.h"
#include "rng.h"

/* Pool: two solid balls of 0.17 kg and 28.575 mm touching, speeds up to
 * 3 m/s, spins up to 200 rad/s about every axis, e in [0.9, 1]; half the
 * cases constant mu in [0, 0.2], half Alciatore's mu(v).  Approaching. */
void gen_pool_balls(c2d_rng *r, ref_balls_case *c);
/* Mixed: masses 0.01-10 (one case in 8 an immovable b), radii 0.01-1,
 * inertia 0.1-1 m R^2, unit speeds and spin x radius.  Approaching. */
void gen_mixed_balls(c2d_rng *r, ref_balls_case *c);
/* A pool ball into a rail in any direction, h in [R, 2R) (half of them the
 * table's 0.635 D), e in [0.5, 1], mu in [0, 0.4].  Approaching. */
void gen_cushion(c2d_rng *r, ref_cushion_case *c);

/* Over many decades: masses, radii, each velocity component and each spin
 * x radius at exponents uniform in [-span, span] (span 300 for double, 30
 * for float keeps the inertia and every product within the format), one b
 * in 8 immovable, one inertia in 8 INFINITY, mu from 0 to INFINITY (sliding
 * and sticking), constant or Alciatore's form, the approach at any angle.
 * The cushion: the same ball, h = R, the table's 0.635 D or anywhere in
 * [R, 2R), a normal of any length.  Approaching (to rounding: a near
 * tangent pair may be SEPARATING). */
void gen_wide_balls(c2d_rng *r, ref_balls_case *c, int span);
void gen_wide_cushion(c2d_rng *r, ref_cushion_case *c, int span);

/* Over the whole range (prec, emin, emax: 53, -1022, 1023 double; 24,
 * -126, 127 float): every position, velocity and spin component, mass,
 * radius and inertia at its own exponent, uniform from the smallest
 * subnormal to the largest binade (zeros, immovable balls and infinite
 * inertias one in 8 each), mu from 0 to INFINITY, constant or Alciatore's
 * form with any decay.  Mostly approaching; the referee decides every
 * status.  The cushion: a finite mass, R > 0, a normal of any length. */
void gen_whole_balls(c2d_rng *r, ref_balls_case *c, int prec, int emin, int emax);
void gen_whole_cushion(c2d_rng *r, ref_cushion_case *c, int prec, int emin, int emax);

void balls_case_to_float(ref_balls_case *c);
void cushion_case_to_float(ref_cushion_case *c);

void ball_of(c2d_ball *d, const ref_ball *s);
void ballf_of(c2d_ballf *d, const ref_ball *s);
c2d_ball_surface ball_surface_of(const ref_balls_case *c);
c2d_cushion cushion_of(const ref_cushion_case *c);

/* The library on one case: status and out = {a: vx vy wx wy wz, b: ...}. */
c2d_status balls_call(const ref_balls_case *c, double out[10]);
c2d_status balls_callf(const ref_balls_case *c, double out[10]);
c2d_status cushion_call(const ref_cushion_case *c, double out[5]);
c2d_status cushion_callf(const ref_cushion_case *c, double out[5]);

#endif
