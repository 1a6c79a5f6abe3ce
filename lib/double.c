/* SPDX-License-Identifier: MIT */
/* double.c - the double-precision API: binary64's parameters, the shared
 * templates instantiated for it (real_*.h, derivations there), and the
 * public functions written out by name.  C2D_NO_DOUBLE leaves it empty. */
#include "internal.h"

#ifndef C2D_NO_DOUBLE

#define C2D_R_TYPE double
#define C2D_R_BITS_TYPE uint64_t
#define C2D_R_BODY c2d_body
#define C2D_R_VEC c2d_vec2
#define C2D_R_PAIRS c2d_pairs
#define C2D_R_DISK c2d_disk
#define C2D_R_SURFACE c2d_surface
#define C2D_R_MANT 52
#define C2D_R_EBIAS 1023
#define C2D_R_EMAX 1023
#define C2D_R_EMIN (-1022)
#define C2D_R_MAX DBL_MAX
#define C2D_R_SPLIT 134217729.0 /* 2^27 + 1: Veltkamp's split into 26-bit halves */
/* -ffreestanding implies -fno-builtin: ask for the FPU instruction by name. */
#ifdef __GNUC__
#define C2D_R_SQRT __builtin_sqrt
#define C2D_R_FABS __builtin_fabs
#else
#define C2D_R_SQRT sqrt /* declared in internal.h */
#endif
#if defined(__FP_FAST_FMA) && defined(__GNUC__)
#define C2D_R_FMA __builtin_fma /* TwoProduct in one instruction; same bits */
#elif defined(C2D_DISPATCH)
#define C2D_R_FUSED __builtin_fma /* TwoProduct by FMA where run-time dispatch finds it (real_exact.h) */
#endif
#define C2D_R_EXP_K 900      /* fast window: |products| summed in [2^-900, 2^900] */
#define C2D_R_EXP_KAPPA2 41  /* tier-2 d trusted if it cancels by at most 2^41 */
#define C2D_R_WINDOW 600     /* exact-sum window, binades */
#define C2D_R_MARGIN 70      /* window sum must dominate the rest by 2^70 */

#define C2D_R_QUICK 200        /* front end's window: [2^-200, 2^200] (real_fast.h) */

#define C2D_R_TOI_WINDOW 100   /* time of impact unscaled within [2^-100, 2^100] (real_toi.h) */

#include "real_bits.h"
#include "real_exact.h"
#include "real_sign.h"
#include "real_round.h"
#include "real_fast.h"
#include "real_general.h"
#include "real_collide.h"
#include "real_axis.h"
#include "real_batch.h"
#include "real_toi.h"
#include "real_dd.h"
#include "real_rough.h"
#include "real_toia_num.h"
#include "real_toia_problem.h"
#include "real_toia_eval.h"
#include "real_toia_newton.h"
#include "real_toia_turns.h"
#include "real_toia_scan.h"
#include "real_toia.h"

c2d_status c2d_collide(c2d_body *a, c2d_body *b, double restitution)
{
    return c2d_real_collide(a, b, restitution);
}

/* The normal as two scalars (real_collide.h, c2d_collide_normal_front):
 * by address, gcc passes the 16-byte c2d_vec2 through memory. */
c2d_status c2d_collide_normal(c2d_body *a, c2d_body *b, c2d_vec2 normal, double restitution)
{
    return c2d_collide_normal_front(a, b, normal.x, normal.y, restitution);
}

c2d_status c2d_time_of_impact(const c2d_body *a, const c2d_body *b, double radius_sum, double *t)
{
    return c2d_real_time_of_impact(a, b, radius_sum, t);
}

size_t c2d_collide_batch(const c2d_pairs *p, size_t count, double restitution, c2d_status *status)
{
    return c2d_real_collide_batch(p, count, restitution, status);
}

c2d_status c2d_collide_rough(c2d_disk *a, c2d_disk *b, c2d_surface s)
{
    return c2d_real_collide_rough(a, b, NULL, &s);
}

c2d_status c2d_collide_rough_normal(c2d_disk *a, c2d_disk *b, c2d_vec2 normal, c2d_surface s)
{
    return c2d_real_collide_rough(a, b, &normal, &s);
}

c2d_status c2d_time_of_impact_accel(const c2d_body *a, c2d_vec2 acc_a, const c2d_body *b, c2d_vec2 acc_b,
                                    double radius_sum, double horizon, double *t)
{
    return c2d_toia_solve(a, &acc_a, b, &acc_b, radius_sum, horizon, t);
}

#endif /* C2D_NO_DOUBLE */
