/* SPDX-License-Identifier: MIT */
/* soa_double.c - the structure-of-arrays helper for double
 * (soa_template.h), its functions written out by name (harness.h). */
#include "harness.h"

#ifndef C2D_NO_DOUBLE
#include "type_double.h"
#include "soa_template.h"

c2d_soa c2d_soa_in(double *block, size_t capacity, c2d_status *status)
{
    return c2d_num_soa_in(block, capacity, status);
}

c2d_pairs c2d_soa_pairs(const c2d_soa *s) { return c2d_num_soa_pairs(s); }

void c2d_soa_put(const c2d_soa *s, size_t i, const c2d_body *a, const c2d_body *b) { c2d_num_soa_put(s, i, a, b); }

void c2d_soa_get(const c2d_soa *s, size_t i, c2d_body *a, c2d_body *b) { c2d_num_soa_get(s, i, a, b); }

void c2d_batch_check_lane(c2d_batch_check *c, const c2d_soa *s, size_t i, c2d_status want, const c2d_body *a,
                          const c2d_body *b)
{
    c2d_num_check_lane(c, s, i, want, a, b);
}

size_t c2d_batch_check_copies(c2d_batch_check *c, const c2d_soa *s, size_t lanes, const c2d_body *a,
                              const c2d_body *b, double e)
{
    return c2d_num_check_copies(c, s, lanes, a, b, e);
}
#endif
