/* SPDX-License-Identifier: MIT */
/* float.c - the single-precision API: binary32's parameters, the shared
 * templates instantiated for it (real_*.h, derivations there), and the
 * public functions written out by name.  Float arithmetic only: nothing here
 * uses or links double, so single-precision FPUs (Cortex-M4F) run it in
 * hardware.  C2D_NO_FLOAT leaves it empty. */
#include "internal.h"

#ifndef C2D_NO_FLOAT

#define C2D_R_TYPE float
#define C2D_R_BITS_TYPE uint32_t
#define C2D_R_BODY c2d_bodyf
#define C2D_R_VEC c2d_vec2f
#define C2D_R_PAIRS c2d_pairsf
#define C2D_R_DISK c2d_diskf
#define C2D_R_SURFACE c2d_surfacef
#define C2D_R_MANT 23
#define C2D_R_EBIAS 127
#define C2D_R_EMAX 127
#define C2D_R_EMIN (-126)
#define C2D_R_MAX FLT_MAX
#define C2D_R_SPLIT 4097.0f /* 2^12 + 1: Veltkamp's split into 12-bit halves */
#ifdef __GNUC__
#define C2D_R_SQRT __builtin_sqrtf
#define C2D_R_FABS __builtin_fabsf
#else
#define C2D_R_SQRT sqrtf /* declared in internal.h */
#endif
#if defined(__FP_FAST_FMAF) && defined(__GNUC__)
#define C2D_R_FMA __builtin_fmaf /* TwoProduct in one instruction; same bits */
#elif defined(C2D_DISPATCH)
#define C2D_R_FUSED __builtin_fmaf /* TwoProduct by FMA where run-time dispatch finds it (real_exact.h) */
#endif
#define C2D_R_EXP_K 90       /* fast window: |products| summed in [2^-90, 2^90] */
#define C2D_R_EXP_KAPPA2 12  /* tier-2 d trusted if it cancels by at most 2^12 */
#define C2D_R_WINDOW 72      /* exact-sum window, binades */
#define C2D_R_MARGIN 36      /* window sum must dominate the rest by 2^36 */

#define C2D_R_QUICK 20        /* front end's window: [2^-20, 2^20] (real_fast.h) */

#define C2D_R_TOI_WINDOW 12   /* time of impact unscaled within [2^-12, 2^12] (real_toi.h) */

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

c2d_status c2d_collidef(c2d_bodyf *a, c2d_bodyf *b, float restitution)
{
    return c2d_real_collide(a, b, restitution);
}

/* The normal by address, unlike double.c: gcc inlines the whole front end
 * here, and the 8-byte c2d_vec2f forwards from the store to its loads;
 * given as two floats, gcc unpacks them through an integer register. */
c2d_status c2d_collide_normalf(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f normal, float restitution)
{
    return c2d_real_collide_normal(a, b, &normal, restitution);
}

c2d_status c2d_time_of_impactf(const c2d_bodyf *a, const c2d_bodyf *b, float radius_sum, float *t)
{
    return c2d_real_time_of_impact(a, b, radius_sum, t);
}

size_t c2d_collide_batchf(const c2d_pairsf *p, size_t count, float restitution, c2d_status *status)
{
    return c2d_real_collide_batch(p, count, restitution, status);
}

c2d_status c2d_collide_roughf(c2d_diskf *a, c2d_diskf *b, c2d_surfacef s)
{
    return c2d_real_collide_rough(a, b, NULL, &s);
}

c2d_status c2d_collide_rough_normalf(c2d_diskf *a, c2d_diskf *b, c2d_vec2f normal, c2d_surfacef s)
{
    return c2d_real_collide_rough(a, b, &normal, &s);
}

c2d_status c2d_time_of_impact_accelf(const c2d_bodyf *a, c2d_vec2f acc_a, const c2d_bodyf *b, c2d_vec2f acc_b,
                                    float radius_sum, float horizon, float *t)
{
    return c2d_toia_solve(a, &acc_a, b, &acc_b, radius_sum, horizon, t);
}

#endif /* C2D_NO_FLOAT */
