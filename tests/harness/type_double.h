/* SPDX-License-Identifier: MIT */
/* type_double.h - the double variant's names for the test templates
 * (soa_template.h, tests/vectors/check_template.h, tests/fuzz/fuzz_template.h),
 * as lib/double.c names its type for lib/real/.  Included once, first, by
 * each double translation unit of the tests (soa_double.c, check_double.c,
 * fuzz_double.c); macros that name what a program does not link are never
 * expanded there. */
#include "harness.h"

typedef double c2d_num;
typedef c2d_body c2d_num_body;
typedef c2d_vec2 c2d_num_vec;
typedef c2d_pairs c2d_num_pairs;
typedef c2d_soa c2d_num_soa;

#define C2D_T_NAME "double"
#define C2D_T_PREC 53      /* significand bits and smallest normal exponent: the ulp */
#define C2D_T_EMIN (-1022)
#define C2D_T_IS_FLOAT 0
#define C2D_T_LIMIT DBL_MAX /* largest finite value (float.h) */
#define C2D_T_FABS fabs
#define C2D_T_PUT c2d_put_double
/* Equal first: also accepts two equal infinities. */
#define C2D_T_WITHIN(got, want, tol) ((got) == (want) || C2D_ABS((got) - (want)) <= (tol))

#define C2D_T_COLLIDE c2d_collide
#define C2D_T_COLLIDE_NORMAL c2d_collide_normal
#define C2D_T_TIME_OF_IMPACT c2d_time_of_impact
#define C2D_T_BATCH c2d_collide_batch

/* The shared vector table (tests/vectors/vectors.h). */
#define C2D_T_VECTOR c2d_vector_d
#define C2D_T_VECTORS c2d_vectors_d
#define C2D_T_VECTOR_COUNT c2d_vector_count_d

/* The models (tests/vectors/check_models.h and its tables). */
#define C2D_T_DISK c2d_disk
#define C2D_T_SURFACE c2d_surface
#define C2D_T_COLLIDE_ROUGH c2d_collide_rough
#define C2D_T_COLLIDE_ROUGH_NORMAL c2d_collide_rough_normal
#define C2D_T_TIME_OF_IMPACT_ACCEL c2d_time_of_impact_accel
#define C2D_T_BALL c2d_ball
#define C2D_T_BALL_SURFACE c2d_ball_surface
#define C2D_T_CUSHION c2d_cushion
#define C2D_T_COLLIDE_BALLS c2d_collide_balls
#define C2D_T_COLLIDE_CUSHION c2d_collide_cushion
#define C2D_T_ROUGH_VECTOR c2d_rough_vector_d
#define C2D_T_ROUGH_VECTORS c2d_rough_vectors_d
#define C2D_T_ROUGH_VECTOR_COUNT c2d_rough_vector_count_d
#define C2D_T_ACCEL_VECTOR c2d_accel_vector_d
#define C2D_T_ACCEL_VECTORS c2d_accel_vectors_d
#define C2D_T_ACCEL_VECTOR_COUNT c2d_accel_vector_count_d

/* The fuzz harness's decoders (tests/fuzz/fuzz.h). */
#define C2D_T_READ c2d_fuzz_read_double
#define C2D_T_READ_MASS c2d_fuzz_read_mass
#define C2D_T_READ_RESTITUTION c2d_fuzz_read_restitution
#define C2D_T_READ_FRICTION c2d_fuzz_read_friction
#define C2D_T_READ_BETA c2d_fuzz_read_beta
#define C2D_T_READ_HORIZON c2d_fuzz_read_horizon
