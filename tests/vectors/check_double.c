/* check_double.c - the vector table's checks for double (check_template.h). */
#include "check_vectors.h"

#ifndef C2D_NO_DOUBLE
#include "type_double.h"
#include "soa_template.h"
#include "check_template.h"

void c2d_check_vectors_d(c2d_tally *tally) { c2d_vector_run_table(tally); }
#endif
