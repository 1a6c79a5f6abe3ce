/* SPDX-License-Identifier: MIT */
/* check_vectors.h - the checks of the shared vector table (vectors.h), one
 * per variant compiled in (check_template.h, instantiated by check_double.c,
 * check_float.c, check_fixed.c), and for double and float the models'
 * tables (c2d_check_rough_vectors_*, c2d_check_accel_vectors_*:
 * check_models.h).  Each runs every entry of its variant's
 * table, counts it in *tally and prints each failure ("FAIL double NAME:
 * what") through c2d_put.  Used by test_vectors.c on the host and by
 * tests/mcu/main.c on microcontrollers.  Freestanding. */
#ifndef C2D_CHECK_VECTORS_H
#define C2D_CHECK_VECTORS_H

#include "harness.h"
#include "vectors.h"

#ifndef C2D_NO_DOUBLE
void c2d_check_vectors_d(c2d_tally *tally);
void c2d_check_rough_vectors_d(c2d_tally *tally);
void c2d_check_accel_vectors_d(c2d_tally *tally);
#endif
#ifndef C2D_NO_FLOAT
void c2d_check_vectors_f(c2d_tally *tally);
void c2d_check_rough_vectors_f(c2d_tally *tally);
void c2d_check_accel_vectors_f(c2d_tally *tally);
#endif
#ifndef C2D_NO_FIXED
void c2d_check_vectors_x(c2d_tally *tally);
#endif

#endif
