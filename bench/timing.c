/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 199309L
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "callgrind.h"

#include "approaches.h"

/* Results go here so no timed loop can be optimised away. */
volatile double bench_sink;

struct timing_data {
    int n;
    c2d_body *a0, *b0, *a, *b;     /* pristine and working copies */
    c2d_bodyf *af0, *bf0, *af, *bf;
    c2d_bodyx *ax0, *bx0, *ax, *bx;
    c2d_vec2 *normal;
    c2d_soa soa;                   /* the batch's arrays, one allocation each */
    c2d_soaf soaf;
    c2d_pairs pairs;               /* their views, made once, outside the timed passes */
    c2d_pairsf pairsf;
    double *soa_v0[4];             /* pristine velocities */
    float *soaf_v0[4];
    c2d_status *st;
};

double bench_now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static c2d_fixed q16(double v) { return (c2d_fixed)lrint(v * 65536.0); }

static void fill_soa(timing_data *t, int i)
{
    const size_t u = (size_t)i;
    int k;
    c2d_soa_put(&t->soa, u, &t->a0[i], &t->b0[i]);
    c2d_soa_putf(&t->soaf, u, &t->af0[i], &t->bf0[i]);
    for (k = 0; k < 4; k++) {
        t->soa_v0[k][i] = t->soa.field[C2D_SOA_VEL_AX + k][i];
        t->soaf_v0[k][i] = t->soaf.field[C2D_SOA_VEL_AX + k][i];
    }
}

timing_data *timing_make(const ref_case *cases, int n)
{
    timing_data *t = calloc(1, sizeof *t);
    size_t un = (size_t)n;
    int i, k;
    t->n = n;
    t->a0 = malloc(un * sizeof *t->a0), t->b0 = malloc(un * sizeof *t->b0);
    t->a = malloc(un * sizeof *t->a), t->b = malloc(un * sizeof *t->b);
    t->af0 = malloc(un * sizeof *t->af0), t->bf0 = malloc(un * sizeof *t->bf0);
    t->af = malloc(un * sizeof *t->af), t->bf = malloc(un * sizeof *t->bf);
    t->ax0 = malloc(un * sizeof *t->ax0), t->bx0 = malloc(un * sizeof *t->bx0);
    t->ax = malloc(un * sizeof *t->ax), t->bx = malloc(un * sizeof *t->bx);
    t->normal = malloc(un * sizeof *t->normal);
    t->st = malloc(un * sizeof *t->st);
    for (k = 0; k < C2D_SOA_FIELDS; k++) {
        t->soa.field[k] = malloc(un * sizeof(double));
        t->soaf.field[k] = malloc(un * sizeof(float));
    }
    t->soa.status = t->soaf.status = t->st;
    t->pairs = c2d_soa_pairs(&t->soa);
    t->pairsf = c2d_soa_pairsf(&t->soaf);
    for (k = 0; k < 4; k++) {
        t->soa_v0[k] = malloc(un * sizeof(double));
        t->soaf_v0[k] = malloc(un * sizeof(float));
    }
    for (i = 0; i < n; i++) {
        ref_case c = cases[i];
        c.e = 1.0; /* one restitution for every contender, batch included */
        case_to_bodies(&c, &t->a0[i], &t->b0[i]);
        case_to_bodiesf(&c, &t->af0[i], &t->bf0[i]);
        t->ax0[i].pos.x = q16(c.pa[0]), t->ax0[i].pos.y = q16(c.pa[1]);
        t->ax0[i].vel.x = q16(c.va[0]), t->ax0[i].vel.y = q16(c.va[1]), t->ax0[i].mass = q16(c.ma);
        t->bx0[i].pos.x = q16(c.pb[0]), t->bx0[i].pos.y = q16(c.pb[1]);
        t->bx0[i].vel.x = q16(c.vb[0]), t->bx0[i].vel.y = q16(c.vb[1]), t->bx0[i].mass = q16(c.mb);
        t->normal[i].x = c.pb[0] - c.pa[0];
        t->normal[i].y = c.pb[1] - c.pa[1];
        fill_soa(t, i);
    }
    return t;
}

void timing_free(timing_data *t)
{
    int k;
    free(t->a0), free(t->b0), free(t->a), free(t->b);
    free(t->af0), free(t->bf0), free(t->af), free(t->bf);
    free(t->ax0), free(t->bx0), free(t->ax), free(t->bx);
    free(t->normal), free(t->st);
    for (k = 0; k < C2D_SOA_FIELDS; k++) free(t->soa.field[k]), free(t->soaf.field[k]);
    for (k = 0; k < 4; k++) free(t->soa_v0[k]), free(t->soaf_v0[k]);
    free(t);
}

/* Put the inputs back (untimed): every timed pass sees the same collisions,
 * not the already separating pairs the previous pass left behind. */
static void restore(timing_data *t, const contender *k)
{
    size_t n = (size_t)t->n;
    int j;
    switch (k == NULL ? KIND_DOUBLE : k->kind) {
    case KIND_FLOAT:
        memcpy(t->af, t->af0, n * sizeof *t->af), memcpy(t->bf, t->bf0, n * sizeof *t->bf);
        break;
    case KIND_FIXED:
        memcpy(t->ax, t->ax0, n * sizeof *t->ax), memcpy(t->bx, t->bx0, n * sizeof *t->bx);
        break;
    case KIND_BATCH:
        for (j = 0; j < 4; j++) memcpy(t->soa.field[C2D_SOA_VEL_AX + j], t->soa_v0[j], n * sizeof(double));
        break;
    case KIND_BATCHF:
        for (j = 0; j < 4; j++) memcpy(t->soaf.field[C2D_SOA_VEL_AX + j], t->soaf_v0[j], n * sizeof(float));
        break;
    default:
        memcpy(t->a, t->a0, n * sizeof *t->a), memcpy(t->b, t->b0, n * sizeof *t->b);
        break;
    }
}

/* One pass of contender k (NULL: the empty call) over the working copy. */
static void run_pass(timing_data *t, const contender *k, int n)
{
    unsigned acc = 0;
    int i;
    if (k == NULL) {
        bench_fn fn = bench_noop;
        for (i = 0; i < n; i++) acc += (unsigned)fn(&t->a[i], &t->b[i], 1.0);
    } else if (k->kind == KIND_DOUBLE || k->kind == KIND_BOX2D) {
        bench_fn fn = k->fn;
        for (i = 0; i < n; i++) acc += (unsigned)fn(&t->a[i], &t->b[i], 1.0);
    } else if (k->kind == KIND_NORMAL) {
        for (i = 0; i < n; i++) acc += (unsigned)c2d_collide_normal(&t->a[i], &t->b[i], t->normal[i], 1.0);
    } else if (k->kind == KIND_FLOAT) {
        for (i = 0; i < n; i++) acc += (unsigned)c2d_collidef(&t->af[i], &t->bf[i], 1.0f);
    } else if (k->kind == KIND_FIXED) {
        for (i = 0; i < n; i++) acc += (unsigned)c2d_collidex(&t->ax[i], &t->bx[i], C2D_FIXED_ONE);
    } else if (k->kind == KIND_BATCH) {
        acc += (unsigned)c2d_collide_batch(&t->pairs, (size_t)n, 1.0, t->st);
    } else {
        acc += (unsigned)c2d_collide_batchf(&t->pairsf, (size_t)n, 1.0f, t->st);
    }
    bench_sink += acc;
}

static double time_pass(timing_data *t, const contender *k)
{
    double t0, t1;
    restore(t, k);
    t0 = bench_now_ns();
    run_pass(t, k, t->n);
    t1 = bench_now_ns();
    return (t1 - t0) / t->n;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The canary of a round (as ratio.c's): the seed transcription's pass,
 * whose time tells a quiet machine from a busy one. */
static double canary_pass(timing_data *t)
{
    static const contender seed = {"canary", "canary", KIND_DOUBLE, bench_seed_equal, 1, 0};
    return time_pass(t, &seed);
}

int timing_quiet_rounds, timing_rounds_run;
double bench_canary_best = INFINITY;

void timing_run(timing_data *t, int rounds, double *ns)
{
    const int kn = bench_ncontenders + 1, most = 5 * rounds; /* the last slot: the empty call */
    double *all = malloc((size_t)(kn * most) * sizeof *all), *canary = malloc((size_t)most * sizeof *canary);
    double *v = malloc((size_t)most * sizeof *v);
    int r, j, quiet = 0, done;
    /* `rounds` rounds, and more (up to five times as many) until enough of
     * them are quiet against the best canary seen in this run of the bench */
    for (r = 0; r < most && (r < rounds || quiet < RATIO_MIN_QUIET); r++) {
        canary[r] = canary_pass(t);
        if (canary[r] < bench_canary_best) bench_canary_best = canary[r];
        quiet += canary[r] <= 1.10 * bench_canary_best;
        for (j = 0; j < kn; j++) {
            int idx = (j + r) % kn; /* rotate the order: no contender always runs first */
            all[idx * most + r] = time_pass(t, idx < bench_ncontenders ? &bench_contenders[idx] : NULL);
        }
    }
    done = r;
    for (quiet = 0, r = 0; r < done; r++) quiet += canary[r] <= 1.10 * bench_canary_best;
    timing_quiet_rounds = quiet;
    timing_rounds_run = done;
    /* The median over the quiet rounds when there are enough (ratio.c). */
    for (j = 0; j < kn; j++) {
        int m = 0;
        for (r = 0; r < done; r++)
            if (quiet < RATIO_MIN_QUIET || canary[r] <= 1.10 * bench_canary_best) v[m++] = all[j * most + r];
        qsort(v, (size_t)m, sizeof *v, cmp_double);
        ns[j] = v[m / 2];
    }
    free(all), free(canary), free(v);
}

void callgrind_run(timing_data *t, int n, const char *label)
{
    char name[128];
    int j;
    if (n > t->n) n = t->n;
    for (j = 0; j <= bench_ncontenders; j++) {
        const contender *k = j < bench_ncontenders ? &bench_contenders[j] : NULL;
        restore(t, k);
        CALLGRIND_ZERO_STATS;
        run_pass(t, k, n);
        snprintf(name, sizeof name, "%s/%s", label, k ? k->id : "noop");
        CALLGRIND_DUMP_STATS_AT(name);
    }
}

double timing_slow_share(const ref_case *c, int n)
{
    int i, slow = 0;
    for (i = 0; i < n; i++) {
        double nx = c[i].pb[0] - c[i].pa[0], ny = c[i].pb[1] - c[i].pa[1];
        double px = (c[i].vb[0] - c[i].va[0]) * nx, py = (c[i].vb[1] - c[i].va[1]) * ny;
        slow += !(fabs(px) + fabs(py) <= 2 * fabs(px + py));
    }
    return (double)slow / n;
}

/* ------------------------------------------------------ bandwidth roof */

/* Reads the ten input arrays and writes the four velocity arrays and the
 * statuses, exactly the bytes the batch kernel moves, with no arithmetic
 * to speak of. */
static void roof_kernel(const c2d_pairs *p, size_t n, c2d_status *st)
{
    const double *restrict pax = p->pos_ax, *restrict pay = p->pos_ay;
    const double *restrict pbx = p->pos_bx, *restrict pby = p->pos_by;
    const double *restrict ma = p->mass_a, *restrict mb = p->mass_b;
    double *restrict vax = p->vel_ax, *restrict vay = p->vel_ay;
    double *restrict vbx = p->vel_bx, *restrict vby = p->vel_by;
    size_t i;
    for (i = 0; i < n; i++) {
        vax[i] += pbx[i] - pax[i];
        vay[i] += pby[i] - pay[i];
        vbx[i] += ma[i];
        vby[i] += mb[i];
        st[i] = C2D_OK;
    }
}

static void roof_kernelf(const c2d_pairsf *p, size_t n, c2d_status *st)
{
    const float *restrict pax = p->pos_ax, *restrict pay = p->pos_ay;
    const float *restrict pbx = p->pos_bx, *restrict pby = p->pos_by;
    const float *restrict ma = p->mass_a, *restrict mb = p->mass_b;
    float *restrict vax = p->vel_ax, *restrict vay = p->vel_ay;
    float *restrict vbx = p->vel_bx, *restrict vby = p->vel_by;
    size_t i;
    for (i = 0; i < n; i++) {
        vax[i] += pbx[i] - pax[i];
        vay[i] += pby[i] - pay[i];
        vbx[i] += ma[i];
        vby[i] += mb[i];
        st[i] = C2D_OK;
    }
}

void roof_run(int is_float, size_t count, int reps, roof_result *out)
{
    const size_t elt = is_float ? sizeof(float) : sizeof(double);
    void *arr[C2D_SOA_FIELDS], *v0[4];
    c2d_status *st = malloc(count * sizeof *st);
    c2d_soa s;   /* the arrays seen as double or as float: one of the two is used */
    c2d_soaf sf;
    c2d_pairs p;
    c2d_pairsf pf;
    double tb[64], tr[64];
    c2d_rng r;
    size_t i;
    int k, rep;
    r.s = 12345;
    for (k = 0; k < C2D_SOA_FIELDS; k++) {
        arr[k] = malloc(count * elt);
        s.field[k] = arr[k];
        sf.field[k] = arr[k];
    }
    for (k = 0; k < 4; k++) v0[k] = malloc(count * elt);
    s.status = sf.status = st;
    p = c2d_soa_pairs(&s);
    pf = c2d_soa_pairsf(&sf);
    for (i = 0; i < count; i++) {
        ref_case c;
        c2d_body a, b;
        c2d_bodyf af, bf;
        gen_plain(&r, &c);
        case_to_bodies(&c, &a, &b);
        case_to_bodiesf(&c, &af, &bf);
        if (is_float) c2d_soa_putf(&sf, i, &af, &bf);
        else c2d_soa_put(&s, i, &a, &b);
    }
    for (k = 0; k < 4; k++) memcpy(v0[k], arr[C2D_SOA_VEL_AX + k], count * elt);
    if (reps > 64) reps = 64;
    for (rep = 0; rep < reps; rep++) {
        int which;
        for (which = 0; which < 2; which++) {
            double t0, t1;
            for (k = 0; k < 4; k++) memcpy(arr[C2D_SOA_VEL_AX + k], v0[k], count * elt);
            t0 = bench_now_ns();
            if (is_float) {
                if (which == 0) bench_sink += (double)c2d_collide_batchf(&pf, count, 1.0f, st);
                else roof_kernelf(&pf, count, st);
            } else {
                if (which == 0) bench_sink += (double)c2d_collide_batch(&p, count, 1.0, st);
                else roof_kernel(&p, count, st);
            }
            t1 = bench_now_ns();
            (which == 0 ? tb : tr)[rep] = t1 - t0;
        }
    }
    qsort(tb, (size_t)reps, sizeof *tb, cmp_double);
    qsort(tr, (size_t)reps, sizeof *tr, cmp_double);
    out->batch_pps = (double)count / (tb[reps / 2] * 1e-9);
    out->roof_pps = (double)count / (tr[reps / 2] * 1e-9);
    out->bytes_per_pair = (double)(C2D_SOA_FIELDS * elt + 4 * elt + sizeof(c2d_status));
    for (k = 0; k < C2D_SOA_FIELDS; k++) free(arr[k]);
    for (k = 0; k < 4; k++) free(v0[k]);
    free(st);
}
