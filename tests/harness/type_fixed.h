/* SPDX-License-Identifier: MIT */
/* type_fixed.h - the Q16.16 variant's names for the test template it shares
 * with the floating types (tests/vectors/check_template.h).  Included once,
 * first, by each Q16.16 translation unit of the tests (check_fixed.c).  No
 * batch entry point: the templates leave that part out without C2D_T_BATCH. */
#include "harness.h"

typedef c2d_fixed c2d_num;
typedef c2d_bodyx c2d_num_body;
typedef c2d_vec2x c2d_num_vec;

#define C2D_T_NAME "Q16.16"
#define C2D_T_PUT c2d_put_fixed
/* In int64: the difference of two Q16.16 values can exceed int32. */
#define C2D_T_WITHIN(got, want, tol) (C2D_ABS((int64_t)(got) - (int64_t)(want)) <= (int64_t)(tol))

#define C2D_T_COLLIDE c2d_collidex
#define C2D_T_COLLIDE_NORMAL c2d_collide_normalx
#define C2D_T_TIME_OF_IMPACT c2d_time_of_impactx

/* The shared vector table (tests/vectors/vectors.h). */
#define C2D_T_VECTOR c2d_vector_x
#define C2D_T_VECTORS c2d_vectors_x
#define C2D_T_VECTOR_COUNT c2d_vector_count_x
