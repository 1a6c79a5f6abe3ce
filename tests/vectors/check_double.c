/* SPDX-License-Identifier: MIT */
/* check_double.c - the vector table's checks for double (check_template.h) and the
 * models' tables (check_models.h). */
#include "check_vectors.h"

#ifndef C2D_NO_DOUBLE
#include "type_double.h"
#include "soa_template.h"
#include "check_template.h"
#include "check_models.h"

void c2d_check_vectors_d(c2d_tally *tally) { c2d_vector_run_table(tally); }
void c2d_check_rough_vectors_d(c2d_tally *tally) { c2d_rough_run_table(tally); }
void c2d_check_accel_vectors_d(c2d_tally *tally) { c2d_accel_run_table(tally); }
#endif
