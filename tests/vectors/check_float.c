/* SPDX-License-Identifier: MIT */
/* check_float.c - the vector table's checks for float (check_template.h) and the
 * models' tables (check_models.h). */
#include "check_vectors.h"

#ifndef C2D_NO_FLOAT
#include "type_float.h"
#include "soa_template.h"
#include "check_template.h"
#include "check_models.h"

void c2d_check_vectors_f(c2d_tally *tally) { c2d_vector_run_table(tally); }
void c2d_check_rough_vectors_f(c2d_tally *tally) { c2d_rough_run_table(tally); }
void c2d_check_accel_vectors_f(c2d_tally *tally) { c2d_accel_run_table(tally); }
#endif
