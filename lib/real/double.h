/* SPDX-License-Identifier: MIT */
/* real/double.h - binary64's parameters and the shared templates (real/,
 * derivations there) instantiated for them: what lib/double.c builds its
 * public functions on, and what a white-box test includes to reach the
 * internals.  Needs internal.h first. */
#ifndef C2D_REAL_DOUBLE_H
#define C2D_REAL_DOUBLE_H

#define C2D_R_TYPE double
#define C2D_R_BITS_TYPE uint64_t
#define C2D_R_BODY c2d_body
#define C2D_R_VEC c2d_vec2
#define C2D_R_PAIRS c2d_pairs
#define C2D_R_DISK c2d_disk
#define C2D_R_SURFACE c2d_surface
#define C2D_R_BALL c2d_ball
#define C2D_R_BALL_SURFACE c2d_ball_surface
#define C2D_R_CUSHION c2d_cushion
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
#define C2D_R_FUSED __builtin_fma /* TwoProduct by FMA where run-time dispatch finds it (real/arith/exact.h) */
#endif
#define C2D_R_EXP_K 900      /* fast window: |products| summed in [2^-900, 2^900] */
#define C2D_R_EXP_KAPPA2 41  /* tier-2 d trusted if it cancels by at most 2^41 */
#define C2D_R_WINDOW 600     /* exact-sum window, binades */
#define C2D_R_MARGIN 70      /* window sum must dominate the rest by 2^70 */

/* The front end's accept test and its window [2^-200, 2^200]: the public
 * header's (include/collide2d.h, C2D_ACCEPT_DEFINE_; real/collide/fast.h). */
#define C2D_R_ACCEPT c2d_accept
#define C2D_R_QUICK_HI C2D_ACCEPT_HI
#define C2D_R_QUICK_LO C2D_ACCEPT_LO

#define C2D_R_TOI_WINDOW 100   /* time of impact unscaled within [2^-100, 2^100] (real/toi.h) */

#define C2D_R_EXP_NEG_MAX 708    /* exp(-x) flushed to 0 beyond (real/sphere.h): below 2^(EMIN + 2) */
#define C2D_R_EXP_NEG_DEGREE 13 /* its Taylor degree: truncation below u/4 */

#include "instance.h"

#endif /* C2D_REAL_DOUBLE_H */
