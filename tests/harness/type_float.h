/* SPDX-License-Identifier: MIT */
/* type_float.h - the float variant's names for the test templates
 * (soa_template.h, tests/vectors/check_template.h, tests/fuzz/fuzz_template.h),
 * as lib/float.c names its type for lib/real/.  Included once, first, by
 * each float translation unit of the tests (soa_float.c, check_float.c,
 * fuzz_float.c); macros that name what a program does not link are never
 * expanded there. */
#include "harness.h"

typedef float c2d_num;
typedef c2d_bodyf c2d_num_body;
typedef c2d_vec2f c2d_num_vec;
typedef c2d_pairsf c2d_num_pairs;
typedef c2d_soaf c2d_num_soa;

#define C2D_T_NAME "float"
#define C2D_T_PREC 24      /* significand bits and smallest normal exponent: the ulp */
#define C2D_T_EMIN (-126)
#define C2D_T_IS_FLOAT 1
#define C2D_T_LIMIT FLT_MAX /* largest finite value (float.h) */
#define C2D_T_FABS fabsf
#define C2D_T_PUT c2d_put_float
/* Equal first: also accepts two equal infinities. */
#define C2D_T_WITHIN(got, want, tol) ((got) == (want) || C2D_ABS((got) - (want)) <= (tol))

#define C2D_T_COLLIDE c2d_collidef
#define C2D_T_COLLIDE_NORMAL c2d_collide_normalf
#define C2D_T_TIME_OF_IMPACT c2d_time_of_impactf
#define C2D_T_BATCH c2d_collide_batchf

/* The shared vector table (tests/vectors/vectors.h). */
#define C2D_T_VECTOR c2d_vector_f
#define C2D_T_VECTORS c2d_vectors_f
#define C2D_T_VECTOR_COUNT c2d_vector_count_f

/* The models (tests/vectors/check_models.h and its tables). */
#define C2D_T_DISK c2d_diskf
#define C2D_T_SURFACE c2d_surfacef
#define C2D_T_COLLIDE_ROUGH c2d_collide_roughf
#define C2D_T_COLLIDE_ROUGH_NORMAL c2d_collide_rough_normalf
#define C2D_T_TIME_OF_IMPACT_ACCEL c2d_time_of_impact_accelf
#define C2D_T_BALL c2d_ballf
#define C2D_T_BALL_SURFACE c2d_ball_surfacef
#define C2D_T_CUSHION c2d_cushionf
#define C2D_T_COLLIDE_BALLS c2d_collide_ballsf
#define C2D_T_COLLIDE_CUSHION c2d_collide_cushionf
#define C2D_T_ROUGH_VECTOR c2d_rough_vector_f
#define C2D_T_ROUGH_VECTORS c2d_rough_vectors_f
#define C2D_T_ROUGH_VECTOR_COUNT c2d_rough_vector_count_f
#define C2D_T_ACCEL_VECTOR c2d_accel_vector_f
#define C2D_T_ACCEL_VECTORS c2d_accel_vectors_f
#define C2D_T_ACCEL_VECTOR_COUNT c2d_accel_vector_count_f

/* The fuzz harness's decoders (tests/fuzz/fuzz.h). */
#define C2D_T_READ c2d_fuzz_read_float
#define C2D_T_READ_MASS c2d_fuzz_read_massf
#define C2D_T_READ_RESTITUTION c2d_fuzz_read_restitutionf
#define C2D_T_READ_FRICTION c2d_fuzz_read_frictionf
#define C2D_T_READ_BETA c2d_fuzz_read_betaf
#define C2D_T_READ_HORIZON c2d_fuzz_read_horizonf
