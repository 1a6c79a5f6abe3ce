/* SPDX-License-Identifier: MIT */
/* Referee for c2d_collide_balls and c2d_collide_cushion: the model of
 * lib/real/sphere.h written again in MPFR at REF_SPHERE_BITS bits (> 120
 * decimal digits) from its equations, every input taken exactly, exp by
 * mpfr_exp.  For valid inputs at ordinary scales (the unit tests' cases):
 * the status (OK or SEPARATING) and each output's error in ulp. */
#ifndef C2D_REF_SPHERE_H
#define C2D_REF_SPHERE_H

#include "collide2d.h"

typedef struct ref_ball { double pos[2], vel[2], w[3], m, r, inertia; } ref_ball;

typedef struct ref_balls_case {
    ref_ball a, b;
    double e, mu, boost, decay;
} ref_balls_case;

typedef struct ref_cushion_case {
    ref_ball a;
    double n[2], h, e, mu;
} ref_cushion_case;

/* Outputs of one ball: {vx, vy, wx, wy, wz}. */
enum { REF_BALL_OUT = 5 };

/* The referee's status for the pair and, on OK, the worst error of got
 * (a's five outputs, then b's) in ulp of the pair's scale at prec bits:
 * the largest |vx|, |vy|, |R w| of both balls before and after. */
c2d_status ref_balls(const ref_balls_case *c, const double got[2 * REF_BALL_OUT], int prec, double *err_ulp);

/* The same for a ball and a cushion (the ball's scale). */
c2d_status ref_cushion(const ref_cushion_case *c, const double got[REF_BALL_OUT], int prec, double *err_ulp);

/* exp(-x)'s relative error of got in ulp at prec bits (of the exact value). */
double ref_exp_neg_err(double x, double got, int prec);

#endif
