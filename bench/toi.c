/* SPDX-License-Identifier: MIT */
/* The time of impact against the exact referee (referee/referee.c: status
 * in rationals, t in 256-bit MPFR): the library, the library before the
 * speed work (bench/old.h) and the textbook quadratic, on the ordinary and
 * extreme pairs the speed comparisons use (ratio.c gen_toi_case).  What the
 * 3x of the time-of-impact goal buys. */
#include "bench.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "approaches.h"
#include "old.h"

static c2d_status run(int which, int is_float, const ref_case *c, double rad, double *t)
{
    c2d_status st;
    if (is_float) {
        c2d_bodyf a, b;
        float tf = NAN;
        case_to_bodiesf(c, &a, &b);
        st = which == TK_LIB ? c2d_time_of_impactf(&a, &b, (float)rad, &tf)
             : which == TK_OLD ? old_c2d_time_of_impactf(&a, &b, (float)rad, &tf)
                               : bench_toi_textbookf(&a, &b, (float)rad, &tf);
        *t = tf;
    } else {
        c2d_body a, b;
        *t = NAN;
        case_to_bodies(c, &a, &b);
        st = which == TK_LIB ? c2d_time_of_impact(&a, &b, rad, t)
             : which == TK_OLD ? old_c2d_time_of_impact(&a, &b, rad, t)
                               : bench_toi_textbook(&a, &b, rad, t);
    }
    return st;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

void toi_evaluate(int which, int is_float, int extreme, int n, unsigned long long seed, toi_stats *o)
{
    const double limit = is_float ? FLT_MAX : DBL_MAX;
    double *err = malloc((size_t)n * sizeof *err);
    c2d_rng r;
    int i, m = 0;
    memset(o, 0, sizeof *o);
    o->n = n;
    r.s = seed;
    for (i = 0; i < n; i++) {
        ref_case c;
        double rad, t, tref = 0, unit = 0;
        c2d_status st, want;
        gen_toi_case(&r, &c, &rad, extreme, is_float);
        if (is_float) case_to_float(&c), rad = (float)rad;
        st = run(which, is_float, &c, rad, &t);
        want = ref_time_of_impact(&c, rad, &tref, &unit, is_float ? 24 : 53, is_float ? -126 : -1022);
        if (want == C2D_OK && !(tref <= limit)) want = C2D_RANGE;
        o->hits += want == C2D_OK;
        if (st == C2D_OK && !isfinite(t)) o->nan_inf++;
        if (st != want && !(st == C2D_RANGE && want == C2D_OK && tref >= 0.5 * limit)) o->wrong_status++;
        if (st == C2D_OK && want == C2D_OK) err[m++] = isfinite(t) ? fabs(t - tref) / unit : INFINITY;
    }
    o->evaluated = m;
    if (m > 0) {
        qsort(err, (size_t)m, sizeof *err, cmp_double);
        o->max_units = err[m - 1];
        o->med_units = err[m / 2];
    } else {
        o->max_units = o->med_units = NAN;
    }
    free(err);
}
