/* check_float.c - the vector table's checks for float (check_template.h). */
#include "check_vectors.h"

#ifndef C2D_NO_FLOAT
#include "type_float.h"
#include "soa_template.h"
#include "check_template.h"

void c2d_check_vectors_f(c2d_tally *tally) { c2d_vector_run_table(tally); }
#endif
