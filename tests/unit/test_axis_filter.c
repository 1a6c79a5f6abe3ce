/* SPDX-License-Identifier: MIT */
/* The filter in front of the exact rounding of axis-aligned impacts, double
 * (body in axis_filter.h): the library's templates instantiated here as
 * lib/double.c does, so the filter's decisions can be counted. */
#include "check.h"
#include "../../lib/internal.h"

#pragma GCC diagnostic ignored "-Wunused-function" /* the templates hold more than the filter */

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
#define C2D_R_SPLIT 134217729.0
#define C2D_R_SQRT __builtin_sqrt
#define C2D_R_FABS __builtin_fabs
#if defined(__FP_FAST_FMA) && defined(__GNUC__)
#define C2D_R_FMA __builtin_fma
#endif
#define C2D_R_WINDOW 600
#define C2D_R_MARGIN 70

#include "../../lib/real_bits.h"
#include "../../lib/real_exact.h"
#include "../../lib/real_sign.h"
#include "../../lib/real_round.h"

#define FILTER_FLOAT 0
#include "axis_filter.h"
