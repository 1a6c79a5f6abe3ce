/* SPDX-License-Identifier: MIT */
/* Referee for c2d_collide_balls and c2d_collide_cushion: the model of
 * lib/real/sphere.h written again in MPFR from its equations, at a
 * precision set per case from the spread of its inputs' exponents (512 bits,
 * 154 digits, at unit scale; about 2,700 over the whole double range: every
 * difference of inputs exact, every quantity formed to 2^-400 of itself),
 * exp by mpfr_exp.  Any inputs: the status and each output's error in ulp. */
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

/* The referee's verdict on one case at prec bits (53 double, 24 float),
 * smallest normal 2^emin (-1022, -126), largest finite value limit
 * (DBL_MAX, FLT_MAX). */
typedef struct ref_sphere_verdict {
    c2d_status status;  /* INVALID, DEGENERATE, SEPARATING, RANGE or OK */
    int range_allowed;  /* C2D_RANGE is acceptable: an exact result or change reaches limit / 8 */
    int range_required; /* an exact result is beyond limit */
    double err_ulp;     /* on OK: got's worst error in ulp of the scale */
} ref_sphere_verdict;

/* Two balls: the status (validity by the header's contract; DEGENERATE,
 * SEPARATING and RANGE for the normal part as c2d_collide's contract says,
 * the approach's sign exact) and, on OK, the worst error of
 * got (a's five outputs, then b's) in ulp of the pair's scale: the largest
 * |vx|, |vy|, |R w| of both balls before and exactly after (no upper
 * limit; ulp at least the format's smallest subnormal).  A spin whose exact
 * value is subnormal while R w is not is forgiven its own rounding. */
void ref_balls(const ref_balls_case *c, const double got[2 * REF_BALL_OUT], int prec, int emin, double limit,
               ref_sphere_verdict *v);

/* The same for a ball and a cushion (the ball's scale). */
void ref_cushion(const ref_cushion_case *c, const double got[REF_BALL_OUT], int prec, int emin, double limit,
                 ref_sphere_verdict *v);

/* exp(-x)'s relative error of got in ulp at prec bits (of the exact value). */
double ref_exp_neg_err(double x, double got, int prec);

#endif
