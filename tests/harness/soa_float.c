/* SPDX-License-Identifier: MIT */
/* soa_float.c - the structure-of-arrays helper for float
 * (soa_template.h), its functions written out by name (harness.h). */
#include "harness.h"

#ifndef C2D_NO_FLOAT
#include "type_float.h"
#include "soa_template.h"

c2d_soaf c2d_soa_inf(float *block, size_t capacity, c2d_status *status)
{
    return c2d_num_soa_in(block, capacity, status);
}

c2d_pairsf c2d_soa_pairsf(const c2d_soaf *s) { return c2d_num_soa_pairs(s); }

void c2d_soa_putf(const c2d_soaf *s, size_t i, const c2d_bodyf *a, const c2d_bodyf *b) { c2d_num_soa_put(s, i, a, b); }

void c2d_soa_getf(const c2d_soaf *s, size_t i, c2d_bodyf *a, c2d_bodyf *b) { c2d_num_soa_get(s, i, a, b); }

void c2d_batch_check_lanef(c2d_batch_check *c, const c2d_soaf *s, size_t i, c2d_status want, const c2d_bodyf *a,
                           const c2d_bodyf *b)
{
    c2d_num_check_lane(c, s, i, want, a, b);
}

size_t c2d_batch_check_copiesf(c2d_batch_check *c, const c2d_soaf *s, size_t lanes, const c2d_bodyf *a,
                               const c2d_bodyf *b, float e)
{
    return c2d_num_check_copies(c, s, lanes, a, b, e);
}
#endif
