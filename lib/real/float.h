/* SPDX-License-Identifier: MIT */
/* real/float.h - binary32's parameters and the shared templates (real/,
 * derivations there) instantiated for them: what lib/float.c builds its
 * public functions on, and what a white-box test includes to reach the
 * internals.  Needs internal.h first. */
#ifndef C2D_REAL_FLOAT_H
#define C2D_REAL_FLOAT_H

#define C2D_R_TYPE float
#define C2D_R_BITS_TYPE uint32_t
#define C2D_R_BODY c2d_bodyf
#define C2D_R_VEC c2d_vec2f
#define C2D_R_PAIRS c2d_pairsf
#define C2D_R_DISK c2d_diskf
#define C2D_R_SURFACE c2d_surfacef
#define C2D_R_BALL c2d_ballf
#define C2D_R_BALL_SURFACE c2d_ball_surfacef
#define C2D_R_CUSHION c2d_cushionf
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
#define C2D_R_FUSED __builtin_fmaf /* TwoProduct by FMA where run-time dispatch finds it (real/arith/exact.h) */
#endif
#define C2D_R_EXP_K 90       /* fast window: |products| summed in [2^-90, 2^90] */
#define C2D_R_EXP_KAPPA2 12  /* tier-2 d trusted if it cancels by at most 2^12 */
#define C2D_R_WINDOW 72      /* exact-sum window, binades */
#define C2D_R_MARGIN 36      /* window sum must dominate the rest by 2^36 */

/* The front end's accept test and its window [2^-20, 2^20]: the public
 * header's (include/collide2d.h, C2D_ACCEPT_DEFINE_; real/collide/fast.h). */
#define C2D_R_ACCEPT c2d_acceptf
#define C2D_R_QUICK_HI C2D_ACCEPT_HIF
#define C2D_R_QUICK_LO C2D_ACCEPT_LOF

#define C2D_R_TOI_WINDOW 12   /* time of impact unscaled within [2^-12, 2^12] (real/toi.h) */

#define C2D_R_EXP_NEG_MAX 86    /* exp(-x) flushed to 0 beyond (real/sphere.h): below 2^(EMIN + 2) */
#define C2D_R_EXP_NEG_DEGREE 7 /* its Taylor degree: truncation below u/4 */

#include "instance.h"

#endif /* C2D_REAL_FLOAT_H */
