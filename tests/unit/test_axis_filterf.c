/* SPDX-License-Identifier: MIT */
/* The filter in front of the exact rounding of axis-aligned impacts, float
 * (body in axis_filter.h): the library's templates instantiated here as
 * lib/float.c does, so the filter's decisions can be counted. */
#include "check.h"
#include "../../lib/internal.h"

#pragma GCC diagnostic ignored "-Wunused-function" /* the templates hold more than the filter */

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
#define C2D_R_SPLIT 4097.0f
#define C2D_R_SQRT __builtin_sqrtf
#define C2D_R_FABS __builtin_fabsf
#if defined(__FP_FAST_FMAF) && defined(__GNUC__)
#define C2D_R_FMA __builtin_fmaf
#endif
#define C2D_R_WINDOW 72
#define C2D_R_MARGIN 36

#include "../../lib/real_bits.h"
#include "../../lib/real_exact.h"
#include "../../lib/real_sign.h"
#include "../../lib/real_round.h"

#define FILTER_FLOAT 1
#include "axis_filter.h"
