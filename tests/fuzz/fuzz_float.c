/* SPDX-License-Identifier: MIT */
/* fuzz_float.c - the fuzz checks of float (fuzz_template.h), plus the
 * comparison with double on the same inputs, written out by name
 * (fuzz.h). */
#include "fuzz.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "type_float.h"
#include "soa_template.h"
#include "referee.h"
#include "ref_rough.h"
#include "ref_sphere.h"
#include "cases_toi_accel.h"
#include "fuzz_template.h"
#include "fuzz_rough_template.h"
#include "fuzz_accel_template.h"
#include "fuzz_sphere_template.h"

static int float_result_near_limit(const c2d_body *a0, const c2d_body *b0, const c2d_body *a, const c2d_body *b)
{
    const double lim = FLT_MAX / 8 * (1 - 1e-6); /* the double result is itself 16 ulp off */
    const double *v0[2] = {&a0->vel.x, &b0->vel.x}, *v1[2] = {&a->vel.x, &b->vel.x};
    int j, i;
    for (j = 0; j < 2; j++)
        for (i = 0; i < 2; i++)
            if (fabs(v1[j][i]) >= lim || fabs(v1[j][i] - v0[j][i]) >= lim) return 1;
    return 0;
}

/* The float answer against the double answer for the same (widened)
 * inputs: both within their documented bound of the exact result. */
static void compare_float_double(c2d_status sf, c2d_status sd, const c2d_bodyf *af, const c2d_bodyf *bf,
                                 const c2d_bodyf *af0, const c2d_bodyf *bf0, const c2d_body *ad,
                                 const c2d_body *bd, const c2d_body *ad0, const c2d_body *bd0)
{
    const double vf[4] = {af->vel.x, af->vel.y, bf->vel.x, bf->vel.y};
    const double vd[4] = {ad->vel.x, ad->vel.y, bd->vel.x, bd->vel.y};
    c2d_fuzz_response xf, xd;
    int i;
    if (sf == C2D_RANGE && sd == C2D_OK) {
        if (!float_result_near_limit(ad0, bd0, ad, bd))
            c2d_fuzz_fail("float RANGE where the result is far below FLT_MAX/8");
        return;
    }
    if (sf != sd) c2d_fuzz_fail("float status %s, double status %s", c2d_status_string(sf), c2d_status_string(sd));
    if (sf != C2D_OK) return;
    xf = c2d_num_response(af0, bf0, af, bf, 1, 0); /* only the deltas are used */
    xd = c2d_fuzz_response_of(ad0, bd0, ad, bd, 1, 0);
    for (i = 0; i < 4; i++) {
        long double bound = xf.delta[i / 2] + xd.delta[i / 2];
        if (!(fabsl((long double)vf[i] - vd[i]) <= bound))
            c2d_fuzz_fail("float/double disagree in output %d: %a vs %a (bound %La)", i, vf[i], vd[i], bound);
    }
}

void c2d_fuzz_collidef(c2d_fuzz_reader *r, int with_normal)
{
    c2d_num_call c;
    c2d_body ad, bd, ad0, bd0;
    c2d_vec2 nd;
    c2d_status sd;
    c2d_num_fuzz_collide(r, with_normal, &c);
    c2d_num_widen(&c.a0, &ad);
    c2d_num_widen(&c.b0, &bd);
    nd.x = c.n.x, nd.y = c.n.y;
    ad0 = ad, bd0 = bd;
    sd = c2d_fuzz_collide_checked(&ad, &bd, with_normal ? &nd : NULL, c.e);
    compare_float_double(c.s, sd, &c.a, &c.b, &c.a0, &c.b0, &ad, &bd, &ad0, &bd0);
}

void c2d_fuzz_time_of_impactf(c2d_fuzz_reader *r) { c2d_num_fuzz_time_of_impact(r); }

void c2d_fuzz_batchf(c2d_fuzz_reader *r, int flags) { c2d_num_fuzz_batch(r, flags); }

void c2d_fuzz_collide_roughf(c2d_fuzz_reader *r, int with_normal) { c2d_num_fuzz_collide_rough(r, with_normal); }

void c2d_fuzz_time_of_impact_accelf(c2d_fuzz_reader *r) { c2d_num_fuzz_time_of_impact_accel(r); }

void c2d_fuzz_collide_ballsf(c2d_fuzz_reader *r) { c2d_num_fuzz_collide_balls(r); }

void c2d_fuzz_collide_cushionf(c2d_fuzz_reader *r) { c2d_num_fuzz_collide_cushion(r); }
