/* SPDX-License-Identifier: MIT */
/* Rough disks (c2d_collide_rough, Walton's model) against the MPFR referee
 * (referee/ref_rough.c): the library in double and float and the model
 * transcribed plainly (bench_walton).  The generators are the unit test's
 * (referee/cases_rough.c), so the benchmark measures the same families. */
#include "bench.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "approaches.h"

/* The contender on one case: status and {va, vb, spin a, spin b} (inputs
 * where nothing was written).  The transcription has no given normal: its
 * cases always use b.pos - a.pos. */
static c2d_status run(int which, const ref_rough_case *c, double out[6])
{
    c2d_disk a, b;
    c2d_status st;
    if (which == RK_LIBF) return rough_callf(c, out);
    if (which != RK_WALTON) return rough_call(c, out);
    rough_disk_of(&a, &c->a), rough_disk_of(&b, &c->b);
    st = bench_walton(&a, &b, rough_surface_of(c));
    out[0] = a.vel.x, out[1] = a.vel.y, out[2] = b.vel.x, out[3] = b.vel.y, out[4] = a.spin, out[5] = b.spin;
    return st;
}

static int status_right(const ref_rough_answer *r, c2d_status s)
{
    if (r->status != C2D_OK) return s == r->status;
    if (r->range_required) return s == C2D_RANGE;
    if (s == C2D_RANGE) return r->range_allowed;
    return s == C2D_OK;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

void rough_evaluate(int which, int extreme, int n, unsigned long long seed, rough_stats *o)
{
    const int is_float = which == RK_LIBF, prec = is_float ? 24 : 53, emin = is_float ? -126 : -1022;
    double *ulps = malloc((size_t)n * sizeof *ulps);
    ref_rough_answer ans;
    c2d_rng r;
    int i, m = 0;
    memset(o, 0, sizeof *o);
    o->n = n;
    r.s = seed;
    ref_rough_init(&ans);
    for (i = 0; i < n; i++) {
        ref_rough_case c;
        double got[6];
        c2d_status st;
        int k, nan = 0, inf = 0;
        if (!extreme) gen_rough(&r, &c);
        else if (is_float) gen_rough_extreme(&r, &c, 24, -126, 127);
        else gen_rough_extreme(&r, &c, 53, -1022, 1023);
        if (which == RK_WALTON) c.has_normal = 0; /* its normal is b.pos - a.pos */
        if (is_float) rough_case_to_float(&c);
        st = run(which, &c, got);
        ref_rough(&c, is_float ? FLT_MAX : DBL_MAX, &ans);
        o->wrong_status += !status_right(&ans, st);
        for (k = 0; k < 6; k++) nan |= isnan(got[k]), inf |= isinf(got[k]) != 0;
        o->nan += nan, o->inf += inf;
        if (ans.status != C2D_OK || ans.range_allowed) continue;
        ulps[m] = ref_rough_err(&c, &ans, got, prec, emin);
        if (!(ulps[m] <= o->max_ulp)) o->max_ulp = ulps[m];
        m++;
        /* Energy can only be judged between bodies of finite mass and inertia:
         * an immovable moving wall or a spinning flywheel of infinite inertia
         * may give energy to the other body. */
        if (!extreme && st == C2D_OK && !nan && !inf && isfinite(c.a.mass) && isfinite(c.b.mass) &&
            isfinite(c.a.inertia) && isfinite(c.b.inertia)) {
            double before[4], after[4];
            ref_rough_invariants(&c, NULL, before);
            ref_rough_invariants(&c, got, after);
            if (before[0] > 0 && (after[0] - before[0]) / before[0] > o->max_energy_gain)
                o->max_energy_gain = (after[0] - before[0]) / before[0];
        }
    }
    ref_rough_clear(&ans);
    o->evaluated = m;
    if (m > 0) {
        qsort(ulps, (size_t)m, sizeof *ulps, cmp_double);
        o->med_ulp = m % 2 ? ulps[m / 2] : 0.5 * (ulps[m / 2 - 1] + ulps[m / 2]);
    } else {
        o->med_ulp = NAN;
    }
    free(ulps);
}
