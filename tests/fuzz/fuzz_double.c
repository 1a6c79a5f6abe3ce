/* SPDX-License-Identifier: MIT */
/* fuzz_double.c - the fuzz checks of double (fuzz_template.h), the entry
 * points and the double answer the float and Q16.16 checks compare with,
 * written out by name (fuzz.h). */
#include "fuzz.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "type_double.h"
#include "soa_template.h"
#include "referee.h"
#include "ref_rough.h"
#include "ref_sphere.h"
#include "cases_toi_accel.h"
#include "fuzz_template.h"
#include "fuzz_rough_template.h"
#include "fuzz_accel_template.h"
#include "fuzz_sphere_template.h"

void c2d_fuzz_collide(c2d_fuzz_reader *r, int with_normal)
{
    c2d_num_call c;
    c2d_num_fuzz_collide(r, with_normal, &c);
}

void c2d_fuzz_time_of_impact(c2d_fuzz_reader *r) { c2d_num_fuzz_time_of_impact(r); }

void c2d_fuzz_batch(c2d_fuzz_reader *r, int flags) { c2d_num_fuzz_batch(r, flags); }

c2d_status c2d_fuzz_collide_checked(c2d_body *a, c2d_body *b, const c2d_vec2 *n, double e)
{
    return c2d_num_collide_checked(a, b, n, e);
}

void c2d_fuzz_check_time_of_impact(c2d_status s, double t, double t0) { c2d_num_check_time_of_impact(s, t, t0); }

c2d_fuzz_response c2d_fuzz_response_of(const c2d_body *a0, const c2d_body *b0, const c2d_body *a, const c2d_body *b,
                                       long double nx, long double ny)
{
    return c2d_num_response(a0, b0, a, b, nx, ny);
}

void c2d_fuzz_collide_rough(c2d_fuzz_reader *r, int with_normal) { c2d_num_fuzz_collide_rough(r, with_normal); }

void c2d_fuzz_time_of_impact_accel(c2d_fuzz_reader *r) { c2d_num_fuzz_time_of_impact_accel(r); }

void c2d_fuzz_collide_balls(c2d_fuzz_reader *r) { c2d_num_fuzz_collide_balls(r); }

void c2d_fuzz_collide_cushion(c2d_fuzz_reader *r) { c2d_num_fuzz_collide_cushion(r); }
