/* SPDX-License-Identifier: MIT */
/* check_fixed.c - the vector table's checks for Q16.16 (check_template.h;
 * no batch entry point, so no soa_template.h). */
#include "check_vectors.h"

#ifndef C2D_NO_FIXED
#include "type_fixed.h"
#include "check_template.h"

void c2d_check_vectors_x(c2d_tally *tally) { c2d_vector_run_table(tally); }
#endif
