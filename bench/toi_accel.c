/* SPDX-License-Identifier: MIT */
/* The time of impact under constant acceleration: what the library's exact
 * statuses cost against the textbook quartic solvers (bench/quartic.c).
 *
 * Accuracy: every family of the unit test (referee/cases_toi_accel.c:
 * billiard balls on cloth, random accelerations, zero acceleration, one at
 * rest, scaled and extreme magnitudes, grazes, inner touches, touches at
 * t = 0, the horizon at a root, leave and re-enter, sub-ulp contacts, turns
 * while overlapping, huge and zero horizons), each case decided by the
 * exact referee (referee/ref_toi_accel.c).  A status that differs from the
 * referee's counts as wrong outside the contract's tie band and as a band
 * disagreement inside it; errors are in the header's units (ulp(t) plus
 * the time one rounding of the distance is worth at the approach speed).
 * The float library runs on the same families generated for float and
 * decided by the referee in float's units.
 *
 * Speed: each contender's pass over the same in-memory cases, the passes
 * interleaved round after round, the median ns per call over the rounds;
 * once on the billiards family (what a pool table asks) and once on all
 * families mixed (what an adversary asks). */
#define _POSIX_C_SOURCE 199309L
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "approaches.h"
#include "callgrind.h"
#include "cases_toi_accel.h"

/* One case as every contender takes it (the float library reads the float
 * set, whose inputs are floats). */
typedef struct toia_call {
    c2d_body a, b;
    c2d_vec2 aa, ab;
    double r, h;
} toia_call;

typedef c2d_status (*toia_solver)(const toia_call *c, double *t);

static c2d_status solve_lib(const toia_call *c, double *t)
{
    return c2d_time_of_impact_accel(&c->a, c->aa, &c->b, c->ab, c->r, c->h, t);
}

static c2d_status solve_libf(const toia_call *c, double *t)
{
    c2d_bodyf a = {{(float)c->a.pos.x, (float)c->a.pos.y}, {(float)c->a.vel.x, (float)c->a.vel.y}, 1};
    c2d_bodyf b = {{(float)c->b.pos.x, (float)c->b.pos.y}, {(float)c->b.vel.x, (float)c->b.vel.y}, 1};
    c2d_vec2f aa = {(float)c->aa.x, (float)c->aa.y}, ab = {(float)c->ab.x, (float)c->ab.y};
    float tf = -1;
    c2d_status s = c2d_time_of_impact_accelf(&a, aa, &b, ab, (float)c->r, (float)c->h, &tf);
    *t = tf;
    return s;
}

static c2d_status solve_ferrari(const toia_call *c, double *t)
{
    return bench_toia_ferrari(&c->a, c->aa, &c->b, c->ab, c->r, c->h, t);
}

static c2d_status solve_sturm(const toia_call *c, double *t)
{
    return bench_toia_sturm(&c->a, c->aa, &c->b, c->ab, c->r, c->h, t);
}

static const toia_solver kSolver[TA_COUNT] = {solve_lib, solve_libf, solve_ferrari, solve_sturm};

/* The plain time of impact on the same positions and velocities (the
 * accelerations ignored), and the loop alone, for the instruction counts. */
static c2d_status solve_plain(const toia_call *c, double *t) { return c2d_time_of_impact(&c->a, &c->b, c->r, t); }

static c2d_status solve_plainf(const toia_call *c, double *t)
{
    c2d_bodyf a = {{(float)c->a.pos.x, (float)c->a.pos.y}, {(float)c->a.vel.x, (float)c->a.vel.y}, 1};
    c2d_bodyf b = {{(float)c->b.pos.x, (float)c->b.pos.y}, {(float)c->b.vel.x, (float)c->b.vel.y}, 1};
    float tf = -1;
    c2d_status s = c2d_time_of_impactf(&a, &b, (float)c->r, &tf);
    *t = tf;
    return s;
}

static c2d_status solve_noop(const toia_call *c, double *t)
{
    *t = c->r;
    return C2D_OK;
}

static toia_call to_call(const ref_toia_in *in)
{
    toia_call c;
    c.a.pos.x = in->pa[0], c.a.pos.y = in->pa[1], c.a.vel.x = in->va[0], c.a.vel.y = in->va[1], c.a.mass = 1;
    c.b.pos.x = in->pb[0], c.b.pos.y = in->pb[1], c.b.vel.x = in->vb[0], c.b.vel.y = in->vb[1], c.b.mass = 1;
    c.aa.x = in->aa[0], c.aa.y = in->aa[1], c.ab.x = in->ab[0], c.ab.y = in->ab[1];
    c.r = in->r, c.h = in->h;
    return c;
}

static void tally(toia_stats *s, c2d_status got, double t, const ref_toia_out *o, int band)
{
    s->n++;
    s->band += band;
    if (got == C2D_OK && !isfinite(t)) s->nan_inf++;
    if (got != o->status) {
        if (band) s->band_wrong++;
        else s->wrong++;
        return;
    }
    if (got == C2D_OK && !band) {
        const double e = ref_toia_err(o, t);
        s->evaluated++;
        if (!(e <= TOIA_BEYOND_UNITS)) s->beyond++;
        if (!(e <= s->worst)) s->worst = e;
    }
}

/* Generate family f's cases for a format, decide each with the referee and
 * tally the contenders that run in that format; the calls are kept for the
 * timing. */
static void evaluate_family(const family *fam, unsigned long long seed, int is_float, int n, toia_call *keep,
                            toia_stats out[TA_COUNT], ref_toia_out *o)
{
    c2d_rng r;
    int i, k;
    r.s = seed + (unsigned)is_float;
    for (i = 0; i < n; i++) {
        ref_toia_in in;
        int band;
        fam->gen(&r, is_float ? 24 : 53, &in);
        if (is_float) toia_case_to_float(&in);
        ref_toia(&in, is_float ? 24 : 53, is_float ? -126 : -1022, o);
        band = toia_in_band(o, is_float, &in);
        keep[i] = to_call(&in);
        for (k = 0; k < TA_COUNT; k++) {
            double t = -1;
            c2d_status s;
            if ((k == TA_LIBF) != is_float) continue;
            s = kSolver[k](&keep[i], &t);
            tally(&out[k], s, t, o, band);
        }
    }
}

static double pass_ns(toia_solver solve, const toia_call *c, long n)
{
    double sink = 0, t0 = bench_now_ns();
    long i;
    for (i = 0; i < n; i++) {
        double t = 0;
        const c2d_status s = solve(&c[i], &t);
        sink += t + (double)s;
    }
    bench_sink = sink;
    return (bench_now_ns() - t0) / (double)n;
}

static int cmp_double(const void *x, const void *y)
{
    const double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* Median ns per call of each contender over `rounds` interleaved passes;
 * calls[0] is the double set, calls[1] the float one. */
static void time_set(toia_call *const calls[2], long n, int rounds, int set, toia_stats out[TA_COUNT])
{
    double *ns = malloc((size_t)rounds * TA_COUNT * sizeof *ns);
    int q, k;
    for (q = 0; q < rounds; q++)
        for (k = 0; k < TA_COUNT; k++) ns[k * rounds + q] = pass_ns(kSolver[k], calls[k == TA_LIBF], n);
    for (k = 0; k < TA_COUNT; k++) {
        qsort(ns + k * rounds, (size_t)rounds, sizeof *ns, cmp_double);
        out[k].ns[set] = ns[k * rounds + rounds / 2];
    }
    free(ns);
}

static int billiards_family(void)
{
    int f;
    for (f = 0; f < toia_n_families; f++)
        if (strcmp(toia_families[f].name, "billiards") == 0) return f;
    return 0;
}

static const family kTouching = {"touching", toia_gen_touching};

void toia_measure(int n_per_family, int rounds, toia_stats out[TA_COUNT], toia_stats touch[TA_COUNT])
{
    const long total = (long)n_per_family * toia_n_families;
    const int billiards = billiards_family();
    toia_call *calls[2], *touching[2];
    ref_toia_out o;
    int f, p;
    memset(out, 0, TA_COUNT * sizeof *out);
    memset(touch, 0, TA_COUNT * sizeof *touch);
    for (p = 0; p < 2; p++) {
        calls[p] = malloc((size_t)total * sizeof *calls[p]);
        touching[p] = malloc((size_t)n_per_family * sizeof *touching[p]);
    }
    ref_toia_init(&o);
    for (f = 0; f < toia_n_families; f++)
        for (p = 0; p < 2; p++)
            evaluate_family(&toia_families[f], 424242u + (unsigned)f * 7919u, p, n_per_family,
                            calls[p] + (long)f * n_per_family, out, &o);
    for (p = 0; p < 2; p++) evaluate_family(&kTouching, 525252u, p, n_per_family, touching[p], touch, &o);
    ref_toia_clear(&o);
    {
        toia_call *bil[2];
        bil[0] = calls[0] + (long)billiards * n_per_family, bil[1] = calls[1] + (long)billiards * n_per_family;
        time_set(bil, n_per_family, rounds, TA_BILLIARDS, out);
    }
    time_set(calls, total, rounds, TA_ALL, out);
    time_set(touching, n_per_family, rounds, TA_TOUCHING, out);
    for (p = 0; p < 2; p++) free(calls[p]), free(touching[p]);
}

/* One dumped pass: the counts between the client requests are the pass's. */
static void callgrind_pass(const char *set, const char *who, toia_solver solve, const toia_call *c, long n)
{
    char name[64];
    snprintf(name, sizeof name, "toia/%s/%s", set, who);
    CALLGRIND_ZERO_STATS;
    (void)pass_ns(solve, c, n);
    CALLGRIND_DUMP_STATS_AT(name);
}

static void make_calls(const family *fam, unsigned long long seed, int is_float, int n, toia_call *c)
{
    c2d_rng r;
    int i;
    r.s = seed + (unsigned)is_float;
    for (i = 0; i < n; i++) {
        ref_toia_in in;
        fam->gen(&r, is_float ? 24 : 53, &in);
        if (is_float) toia_case_to_float(&in);
        c[i] = to_call(&in);
    }
}

void toia_callgrind(int n)
{
    const family *sets[2] = {&toia_families[billiards_family()], &kTouching};
    static const char *const set_name[2] = {"billiards", "touching"};
    toia_call *c[2];
    int s, p;
    for (p = 0; p < 2; p++) c[p] = malloc((size_t)n * sizeof *c[p]);
    for (s = 0; s < 2; s++) {
        for (p = 0; p < 2; p++) make_calls(sets[s], 626262u + 2u * (unsigned)s, p, n, c[p]);
        callgrind_pass(set_name[s], "noop", solve_noop, c[0], n);
        callgrind_pass(set_name[s], "lib", solve_lib, c[0], n);
        callgrind_pass(set_name[s], "libf", solve_libf, c[1], n);
        callgrind_pass(set_name[s], "ferrari", solve_ferrari, c[0], n);
        if (s == 1) {
            callgrind_pass(set_name[s], "plain", solve_plain, c[0], n);
            callgrind_pass(set_name[s], "plainf", solve_plainf, c[1], n);
        }
    }
    for (p = 0; p < 2; p++) free(c[p]);
}
