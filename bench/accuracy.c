/* SPDX-License-Identifier: MIT */
#include "bench.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define Q16_MAX (2147483647.0 / 65536.0)

void gen_impact(c2d_rng *r, ref_case *c)
{
    /* Relative velocity in a random direction; the contact normal makes an
     * angle asin(beta) with the approach direction, beta (the impact
     * parameter over the radius sum) uniform in (-1, 1) as for disks
     * thrown at each other at random. */
    double beta = c2d_rng_range(r, -1, 1), dist = c2d_rng_range(r, 0.5, 2.0);
    double th = asin(beta), ux, uy, rx, ry, len;
    int i;
    gen_plain(r, c);
    rx = c->vb[0] - c->va[0];
    ry = c->vb[1] - c->va[1];
    len = hypot(rx, ry);
    ux = -rx / len;
    uy = -ry / len;
    for (i = 0; i < 2; i++) c->pb[i] = c->pa[i];
    c->pb[0] += dist * (ux * cos(th) - uy * sin(th));
    c->pb[1] += dist * (ux * sin(th) + uy * cos(th));
    c->has_normal = 0;
    c->e = 1.0;
}

static double round_fixed(double v) { return rint(v * 65536.0) / 65536.0; }

static void to_float_case(ref_case *c)
{
    int i;
    for (i = 0; i < 2; i++) {
        c->pa[i] = (float)c->pa[i], c->pb[i] = (float)c->pb[i];
        c->va[i] = (float)c->va[i], c->vb[i] = (float)c->vb[i];
    }
    c->ma = (float)c->ma, c->mb = (float)c->mb, c->e = (float)c->e;
}

static void to_fixed_case(ref_case *c)
{
    int i;
    for (i = 0; i < 2; i++) {
        c->pa[i] = round_fixed(c->pa[i]), c->pb[i] = round_fixed(c->pb[i]);
        c->va[i] = round_fixed(c->va[i]), c->vb[i] = round_fixed(c->vb[i]);
    }
    c->ma = fmax(round_fixed(c->ma), 0x1p-16);
    c->mb = fmax(round_fixed(c->mb), 0x1p-16);
    c->e = round_fixed(c->e);
}

static void to_equal_case(ref_case *c)
{
    if (isinf(c->ma)) c->ma = c->mb;
    c->mb = c->ma;
    c->e = 1.0;
}

static void to_normal_case(ref_case *c)
{
    c->has_normal = 1;
    c->n[0] = c->pb[0] - c->pa[0];
    c->n[1] = c->pb[1] - c->pa[1];
}

static void answer_all(case_set *s, double range_limit)
{
    int i, j;
    s->r = malloc((size_t)s->n * sizeof *s->r);
    for (i = 0; i < s->n; i++) {
        const ref_case *c = &s->c[i];
        ref_answer_init(&s->r[i]);
        ref_collide(c, range_limit, &s->r[i]);
        if (s->r[i].status == C2D_SEPARATING)
            for (j = 0; j < 2; j++) {
                mpq_set_d(s->r[i].v[j], c->va[j]);
                mpq_set_d(s->r[i].v[2 + j], c->vb[j]);
            }
    }
}

static void derive(case_set *dst, const case_set *src, const char *name, void (*map)(ref_case *))
{
    int i;
    dst->name = name;
    dst->n = src->n;
    dst->prec = src->prec;
    dst->emin = src->emin;
    dst->c = malloc((size_t)src->n * sizeof *dst->c);
    memcpy(dst->c, src->c, (size_t)src->n * sizeof *dst->c);
    for (i = 0; i < dst->n; i++) map(&dst->c[i]);
}

static void generate(case_set *s, const char *name, int n, unsigned long long seed, int extreme, int prec)
{
    c2d_rng r;
    int i;
    r.s = seed;
    s->name = name;
    s->n = n;
    s->prec = prec;
    s->emin = prec == 24 ? -126 : -1022;
    s->c = malloc((size_t)n * sizeof *s->c);
    for (i = 0; i < n; i++) {
        if (!extreme) gen_plain(&r, &s->c[i]);
        else if (prec == 24) gen_extreme(&r, &s->c[i], 24, -126, 127);
        else gen_extreme(&r, &s->c[i], 53, -1022, 1023);
        s->c[i].has_normal = 0;
    }
}

void sets_make(case_set *s, int n_plain, int n_extreme, unsigned long long seed)
{
    generate(&s[SET_PLAIN], "plain", n_plain, seed, 0, 53);
    derive(&s[SET_PLAIN_NORMAL], &s[SET_PLAIN], "plain, normal given", to_normal_case);
    derive(&s[SET_PLAIN_FLOAT], &s[SET_PLAIN], "plain, rounded to float", to_float_case);
    s[SET_PLAIN_FLOAT].prec = 24, s[SET_PLAIN_FLOAT].emin = -126;
    derive(&s[SET_PLAIN_FIXED], &s[SET_PLAIN], "plain, rounded to Q16.16", to_fixed_case);
    s[SET_PLAIN_FIXED].prec = 0;
    derive(&s[SET_PLAIN_EQUAL], &s[SET_PLAIN], "plain, equal masses, e = 1", to_equal_case);
    generate(&s[SET_EXTREME], "extreme", n_extreme, seed + 1, 1, 53);
    derive(&s[SET_EXTREME_NORMAL], &s[SET_EXTREME], "extreme, normal given", to_normal_case);
    generate(&s[SET_EXTREME_FLOAT], "extreme float", n_extreme, seed + 2, 1, 24);
    derive(&s[SET_EXTREME_EQUAL], &s[SET_EXTREME], "extreme, equal masses, e = 1", to_equal_case);
    answer_all(&s[SET_PLAIN], DBL_MAX);
    answer_all(&s[SET_PLAIN_NORMAL], DBL_MAX);
    answer_all(&s[SET_PLAIN_FLOAT], FLT_MAX);
    answer_all(&s[SET_PLAIN_FIXED], Q16_MAX);
    answer_all(&s[SET_PLAIN_EQUAL], DBL_MAX);
    answer_all(&s[SET_EXTREME], DBL_MAX);
    answer_all(&s[SET_EXTREME_NORMAL], DBL_MAX);
    answer_all(&s[SET_EXTREME_FLOAT], FLT_MAX);
    answer_all(&s[SET_EXTREME_EQUAL], DBL_MAX);
}

void sets_free(case_set *s)
{
    int i, j;
    for (i = 0; i < SET_COUNT; i++) {
        for (j = 0; j < s[i].n; j++) ref_answer_clear(&s[i].r[j]);
        free(s[i].r);
        free(s[i].c);
    }
}

const case_set *sets_for(const case_set *s, const contender *k, int extreme)
{
    if (extreme && !k->extreme) return NULL;
    if (k->equal_only) return &s[extreme ? SET_EXTREME_EQUAL : SET_PLAIN_EQUAL];
    switch (k->kind) {
    case KIND_NORMAL: return &s[extreme ? SET_EXTREME_NORMAL : SET_PLAIN_NORMAL];
    case KIND_FLOAT:
    case KIND_BATCHF: return &s[extreme ? SET_EXTREME_FLOAT : SET_PLAIN_FLOAT];
    case KIND_FIXED: return &s[SET_PLAIN_FIXED];
    default: return &s[extreme ? SET_EXTREME : SET_PLAIN];
    }
}

/* Q16.16 may report SEPARATING when the approach speed rounds below one
 * step (its documented contract). */
static int below_fixed_step(const ref_case *c)
{
    double nx = c->pb[0] - c->pa[0], ny = c->pb[1] - c->pa[1];
    double d = (c->vb[0] - c->va[0]) * nx + (c->vb[1] - c->va[1]) * ny;
    return fabs(d) / hypot(nx, ny) < 0x1p-15;
}

static int status_right(const contender *k, const ref_case *c, const ref_answer *r, c2d_status s)
{
    if (r->status != C2D_OK) return s == r->status;
    if (r->range_required) return s == C2D_RANGE;
    if (s == C2D_RANGE) return r->range_allowed;
    if (s == C2D_SEPARATING && k->kind == KIND_FIXED) return below_fixed_step(c);
    return s == C2D_OK;
}

static double fixed_err_steps(const ref_answer *r, const double got[4])
{
    double worst = 0;
    int i;
    for (i = 0; i < 4; i++) {
        double e = ref_err_ulp(got[i], r->v[i], 0x1p-16);
        if (!(e <= worst)) worst = e;
    }
    return worst;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    if (n == 0) return NAN;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static void tally_finite(const double got[4], acc_stats *o)
{
    int i, nan = 0, inf = 0;
    for (i = 0; i < 4; i++) {
        nan |= isnan(got[i]);
        inf |= isinf(got[i]) != 0;
    }
    o->nan += nan;
    o->inf += inf;
}

static void tally_conservation(const ref_case *c, const double got[4], acc_stats *o)
{
    double mom, en;
    int i;
    for (i = 0; i < 4; i++)
        if (!isfinite(got[i])) {
            o->max_momentum = o->max_energy = INFINITY;
            return;
        }
    ref_conservation(c, got, &mom, &en);
    if (!(mom <= o->max_momentum)) o->max_momentum = mom;
    if (c->e == 1.0 && !(fabs(en) <= o->max_energy)) o->max_energy = fabs(en);
}

void evaluate(const contender *k, const case_set *s, acc_stats *o)
{
    double *ulps = malloc((size_t)s->n * sizeof *ulps), *rels = malloc((size_t)s->n * sizeof *rels);
    int i, m = 0;
    memset(o, 0, sizeof *o);
    o->n = s->n;
    for (i = 0; i < s->n; i++) {
        const ref_case *c = &s->c[i];
        const ref_answer *r = &s->r[i];
        double got[4];
        c2d_status st = contender_run(k, c, got);
        o->wrong_status += !status_right(k, c, r, st);
        o->batch_mismatch += !contender_batch_agrees(k, c);
        tally_finite(got, o);
        /* Errors over real impacts only; a contender that writes where it
         * should not is already counted as a wrong status. */
        if (r->status != C2D_OK || r->range_allowed) continue;
        ulps[m] = s->prec ? ref_collide_err(c, r, got, s->prec, s->emin) : fixed_err_steps(r, got);
        rels[m] = ref_collide_err(c, r, got, 53, -1022) * 0x1p-52;
        if (!(ulps[m] <= o->max_ulp)) o->max_ulp = ulps[m];
        if (!(rels[m] <= o->max_rel)) o->max_rel = rels[m];
        m++;
        tally_conservation(c, got, o);
    }
    o->evaluated = m;
    o->med_ulp = median(ulps, m);
    o->med_rel = median(rels, m);
    free(ulps);
    free(rels);
}
