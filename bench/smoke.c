/* SPDX-License-Identifier: MIT */
/* `bench --smoke` (make test-bench): every contender runs on every input
 * kind, the referee agrees with hand-computed collisions, and the library
 * rows keep their documented accuracy.  No timing is asserted. */
#include "bench.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "approaches.h"
#include "box2d_contender.h"
#include "cases_toi_accel.h"
#include "old.h"

static c2d_tally tally;

static void check(int ok, const char *what)
{
    if (!c2d_tally_add(&tally, ok)) printf("FAIL: %s\n", what);
}

typedef struct hand_case {
    const char *name;
    ref_case c;
    c2d_status status;
    double v[4]; /* exact answer on OK */
} hand_case;

/* Worked by hand from va' = va + (1+e) wa (d/n.n) n, vb' = vb - (1+e) wb (d/n.n) n. */
static const hand_case hand[] = {
    {"seed 45-degree case", {{0, 0}, {1, 1}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 0, 1}, C2D_OK, {0.5, -0.5, 0.5, 0.5}},
    {"head-on swap", {{0, 0}, {1, 0}, {1, 0}, {-1, 0}, 2, 2, {0, 0}, 0, 1}, C2D_OK, {-1, 0, 1, 0}},
    {"wall bounce e=1", {{0, 0}, {0, 1}, {3, 4}, {0, 0}, 1, INFINITY, {0, 0}, 0, 1}, C2D_OK, {3, -4, 0, 0}},
    {"wall bounce e=0.5", {{0, 0}, {0, 1}, {3, 4}, {0, 0}, 1, INFINITY, {0, 0}, 0, 0.5}, C2D_OK, {3, -2, 0, 0}},
    {"1:3 masses head-on", {{0, 0}, {1, 0}, {2, 0}, {0, 0}, 1, 3, {0, 0}, 0, 1}, C2D_OK, {-1, 0, 1, 0}},
    {"separating", {{0, 0}, {1, 0}, {-1, 0}, {1, 0}, 1, 1, {0, 0}, 0, 1}, C2D_SEPARATING, {-1, 0, 1, 0}},
    {"coincident centres", {{2, 2}, {2, 2}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 0, 1}, C2D_DEGENERATE, {1, 0, 0, 0}},
    {"NaN velocity", {{0, 0}, {1, 0}, {NAN, 0}, {0, 0}, 1, 1, {0, 0}, 0, 1}, C2D_INVALID, {NAN, 0, 0, 0}},
};
#define NHAND ((int)(sizeof hand / sizeof hand[0]))

static void check_referee(void)
{
    char what[160];
    int i, j;
    for (i = 0; i < NHAND; i++) {
        ref_answer r;
        ref_answer_init(&r);
        ref_collide(&hand[i].c, DBL_MAX, &r);
        snprintf(what, sizeof what, "referee status, %s", hand[i].name);
        check(r.status == hand[i].status, what);
        if (r.status == C2D_OK)
            for (j = 0; j < 4; j++) {
                snprintf(what, sizeof what, "referee velocity %d, %s", j, hand[i].name);
                check(mpq_get_d(r.v[j]) == hand[i].v[j], what);
            }
        ref_answer_clear(&r);
    }
}

/* Does contender k claim this case?  Equal-mass formulas only get equal
 * masses at e = 1; Box2D and Q16.16 need finite masses (Box2D) and valid
 * finite inputs. */
static int applies(const contender *k, const hand_case *h)
{
    int valid = h->status == C2D_OK;
    if (k->kind == KIND_FIXED && h->status == C2D_INVALID) return 0; /* no NaN in Q16.16 */
    if (k->equal_only) return valid && h->c.ma == h->c.mb && h->c.e == 1;
    if (k->kind == KIND_BOX2D) return valid && isfinite(h->c.mb);
    if (k->fn == bench_seed_masses || k->fn == bench_trig) return valid && isfinite(h->c.mb);
    return 1;
}

static double tolerance(const contender *k)
{
    if (k->kind == KIND_BOX2D) return 1e-5;
    if (k->kind == KIND_FIXED) return 4 * 0x1p-16;
    if (k->kind == KIND_FLOAT || k->kind == KIND_BATCHF) return 16 * 0x1p-23 * 4;
    return 1e-14;
}

static void check_contenders_on_hand_cases(void)
{
    char what[200];
    int i, j, q, lib_status = 0, lib_vel = 0, ok_cases = 0;
    for (j = 0; j < bench_ncontenders; j++) {
        const contender *k = &bench_contenders[j];
        for (i = 0; i < NHAND; i++) {
            const hand_case *h = &hand[i];
            ref_case c = h->c;
            double got[4];
            c2d_status s;
            int close = 1;
            if (!applies(k, h)) continue;
            if (k->kind == KIND_NORMAL) {
                c.n[0] = c.pb[0] - c.pa[0];
                c.n[1] = c.pb[1] - c.pa[1];
            }
            s = contender_run(k, &c, got);
            snprintf(what, sizeof what, "%s: status on %s", k->id, h->name);
            if (k->fn == bench_seed_summary && strcmp(h->name, "seed 45-degree case") == 0) {
                /* As printed, the summary gives a' = (-0.5, -0.5): the erratum. */
                check(got[0] == -0.5 && got[1] == -0.5 && got[2] == 0.5 && got[3] == 0.5,
                      "seed_summary reproduces the printed erratum on the 45-degree case");
                continue;
            }
            check(s == h->status, what);
            lib_status += k->fn == c2d_collide;
            if (s != C2D_OK && h->status != C2D_OK) continue;
            for (q = 0; q < 4; q++) close &= fabs(got[q] - h->v[q]) <= tolerance(k);
            snprintf(what, sizeof what, "%s: velocities on %s", k->id, h->name);
            check(close, what);
            lib_vel += k->fn == c2d_collide;
        }
    }
    /* The loops skip pairs a contender does not claim (applies) and the
     * velocities of refused cases: c2d_collide's row claims every hand case
     * and has its velocities checked on each one whose status is OK. */
    for (i = 0; i < NHAND; i++) ok_cases += hand[i].status == C2D_OK;
    snprintf(what, sizeof what, "c2d_collide checked on all %d hand cases (%d), velocities on the %d OK ones (%d)", NHAND,
             lib_status, ok_cases, lib_vel);
    check(lib_status == NHAND && lib_vel == ok_cases, what);
}

/* Every contender runs on random inputs of each kind; the library rows keep
 * the header's promise (16 ulp, right statuses, batch == scalar). */
static void check_random_sets(void)
{
    case_set sets[SET_COUNT];
    char what[200];
    int j, x, lib_sets = 0;
    sets_make(sets, 300, 300, 7);
    for (j = 0; j < bench_ncontenders; j++) {
        const contender *k = &bench_contenders[j];
        int is_lib = k->fn == c2d_collide || (k->kind != KIND_DOUBLE && k->kind != KIND_BOX2D);
        for (x = 0; x < 2; x++) {
            const case_set *s = sets_for(sets, k, x);
            acc_stats st;
            if (s == NULL) continue;
            evaluate(k, s, &st);
            snprintf(what, sizeof what, "%s runs on %s inputs", k->id, s->name);
            check(st.n == s->n && st.evaluated > 0, what);
            if (!is_lib) continue;
            lib_sets += k->fn == c2d_collide;
            snprintf(what, sizeof what, "%s: statuses on %s inputs", k->id, s->name);
            check(st.wrong_status == 0, what);
            snprintf(what, sizeof what, "%s: batch bit-identical to scalar on %s inputs", k->id, s->name);
            check(st.batch_mismatch == 0, what);
            if (k->kind == KIND_FIXED) continue; /* bound is per component, in the unit test */
            snprintf(what, sizeof what, "%s: max error %.3g ulp <= 16 on %s inputs", k->id, st.max_ulp, s->name);
            check(st.max_ulp <= 16, what);
        }
    }
    /* The loop skips the sets a contender has no inputs for and the bounds
     * of rows not the library's: c2d_collide's row has both, plain and
     * extreme. */
    snprintf(what, sizeof what, "c2d_collide checked on the plain and the extreme inputs (%d of 2)", lib_sets);
    check(lib_sets == 2, what);
    sets_free(sets);
}

static void check_timing_harness_runs(void)
{
    ref_case cases[64];
    double ns[64];
    c2d_rng r;
    int i, all_ran = 1;
    timing_data *t;
    r.s = 99;
    for (i = 0; i < 64; i++) gen_impact(&r, &cases[i]);
    t = timing_make(cases, 64);
    timing_run(t, 3, ns);
    callgrind_run(t, 8, "smoke");
    for (i = 0; i <= bench_ncontenders; i++) all_ran &= ns[i] >= 0;
    check(all_ran, "timing harness produced a figure for every contender");
    timing_free(t);
}

/* The ratio harness runs every group (3 rounds, 64 pairs each) and gives
 * a figure for every pass; the old library, when linked, gives the new
 * one's bits off the axes; the textbook time of impact agrees with the
 * library on ordinary pairs, and the bare impulse formula (issue 22's
 * baseline) on unit, break and gas pairs. */
static void check_ratios(void)
{
    static ratios r;
    char what[160];
    int v, s, p, x, all = 1, compared = 0, bad;
    ratios_measure(&r, 3, 64, 0);
    for (v = 0; v < GV_COUNT; v++)
        for (s = 0; s < GS_COUNT; s++)
            for (p = 0; p < GP_COUNT; p++) all &= r.goal[v][s][p].ns > 0 && r.goal[v][s][p].ratio > 0;
    for (p = 0; p < 2; p++)
        for (x = 0; x < 2; x++) all &= r.toi[p][x].ns > 0 && r.batch[p][x].ns > 0;
    for (x = 0; x < AX_COUNT; x++) all &= r.axis[x].ns > 0;
    for (x = 0; x < RG_COUNT; x++) all &= r.rough[x].ns > 0;
    for (p = 0; p < 2; p++)
        for (x = 0; x < 3; x++) all &= r.i22_unit[p][x].ns > 0 && r.i22_batch[0][p][x].ns > 0 && r.i22_batch[1][p][x].ns > 0;
    for (s = 0; s < 2; s++)
        for (p = 0; p < 2; p++)
            for (x = 0; x < I22_MIX; x++) all &= r.i22_mix[s][p][x].ns > 0;
    if (r.have_old)
        for (v = 0; v < BA_FN; v++)
            for (s = 0; s < BS_SETS; s++)
                if (v < BA_BATCH || s < BS_AXIS_SWAP) all &= r.ba[v][s][0].ns > 0 && r.ba[v][s][1].ns > 0;
    check(all, "ratio harness produced a figure for every pass");
    check(r.toi_hits > 0.5 && r.toi_hits < 0.95, "ordinary time-of-impact pairs: most hit, some miss");
    bad = ratios_selfcheck(300, &compared);
    snprintf(what, sizeof what,
             "old library == new off the axes, textbook toi == library, bare impulse == library on unit, break and "
             "gas pairs: %d of %d differ", bad, compared);
    check(bad == 0 && compared >= 4 * 300, what); /* toi and the three mixes; the old library's pairs on top */
}

/* Rough disks: the library rows keep the header's bound (18 ulp) and exact
 * statuses on plain and extreme cases; the transcription runs and, on
 * plain contacts, agrees with the library to 1e-9 of the scale. */
static void check_rough(void)
{
    char what[200];
    int k, x, i, agree = 1;
    c2d_rng r;
    for (k = 0; k < RK_COUNT; k++)
        for (x = 0; x < 2; x++) {
            rough_stats st;
            rough_evaluate(k, x, 150, 11 + (unsigned)x, &st);
            snprintf(what, sizeof what, "rough contender %d runs on %s cases", k, x ? "extreme" : "plain");
            check(st.n == 150 && st.evaluated > 10, what);
            if (k == RK_WALTON) continue;
            snprintf(what, sizeof what, "rough contender %d: statuses, max %.3g ulp <= 18, no NaN/Inf (%s)", k, st.max_ulp,
                     x ? "extreme" : "plain");
            check(st.wrong_status == 0 && st.max_ulp <= 18 && st.nan + st.inf == 0, what);
        }
    r.s = 13;
    for (i = 0; i < 200; i++) {
        ref_rough_case c;
        c2d_disk a, b, a2, b2;
        c2d_surface s;
        c2d_status s1, s2;
        double scale;
        gen_rough(&r, &c);
        rough_disk_of(&a, &c.a), rough_disk_of(&b, &c.b);
        s = rough_surface_of(&c);
        a2 = a, b2 = b;
        s1 = c2d_collide_rough(&a, &b, s);
        s2 = bench_walton(&a2, &b2, s);
        scale = 1e-9 * (20 + fabs(c.a.spin * c.a.radius) + fabs(c.b.spin * c.b.radius));
        agree &= s1 == s2 && fabs(a.vel.x - a2.vel.x) <= scale && fabs(a.vel.y - a2.vel.y) <= scale &&
                 fabs(b.vel.x - b2.vel.x) <= scale && fabs(b.vel.y - b2.vel.y) <= scale &&
                 fabs((a.spin - a2.spin) * a.radius) <= scale && fabs((b.spin - b2.spin) * b.radius) <= scale;
    }
    check(agree, "Walton transcription agrees with c2d_collide_rough on plain contacts");
}

/* The time of impact: the library's statuses exact and errors within the
 * header's 4 units on ordinary and extreme pairs; the other rows run. */
static void check_toi(void)
{
    char what[200];
    int k, p, x;
    for (k = 0; k < TK_COUNT; k++)
        for (p = 0; p < 2; p++)
            for (x = 0; x < 2; x++) {
                toi_stats st;
                if (k == TK_OLD && !BENCH_HAVE_OLD()) continue;
                toi_evaluate(k, p, x, 200, 21 + (unsigned)(2 * p + x), &st);
                snprintf(what, sizeof what, "toi contender %d (%s, %s) runs, %d hits", k, p ? "float" : "double",
                         x ? "extreme" : "ordinary", st.hits);
                check(st.n == 200 && st.hits > 10, what);
                if (k != TK_LIB) continue;
                snprintf(what, sizeof what, "library toi (%s, %s): %d wrong statuses, max %.3g units <= 4", p ? "float" : "double",
                         x ? "extreme" : "ordinary", st.wrong_status, st.max_units);
                check(st.wrong_status == 0 && st.nan_inf == 0 && !(st.max_units > 4), what);
            }
}

/* The accelerated time of impact's table: every contender runs on every
 * family and is timed; the library keeps its contract (exact statuses
 * outside the band, within 1 unit). */
static void check_toi_accel(void)
{
    toia_stats st[TA_COUNT], touch[TA_COUNT];
    char what[200];
    int k;
    toia_measure(12, 3, st, touch);
    for (k = 0; k < TA_COUNT; k++) {
        snprintf(what, sizeof what, "accel toi contender %d runs on %ld + %ld cases and is timed (%.1f / %.1f / %.1f ns)",
                 k, st[k].n, touch[k].n, st[k].ns[TA_BILLIARDS], st[k].ns[TA_ALL], st[k].ns[TA_TOUCHING]);
        check(st[k].n == 12L * toia_n_families && touch[k].n == 12 && st[k].ns[TA_BILLIARDS] > 0 &&
                  st[k].ns[TA_ALL] > 0 && st[k].ns[TA_TOUCHING] > 0,
              what);
        if (k != TA_LIB && k != TA_LIBF) continue;
        snprintf(what, sizeof what, "library accel toi (%s): %ld + %ld wrong statuses, worst %.3g / %.3g units <= 1",
                 k == TA_LIBF ? "float" : "double", st[k].wrong, touch[k].wrong, st[k].worst, touch[k].worst);
        check(st[k].wrong + touch[k].wrong == 0 && st[k].nan_inf + touch[k].nan_inf == 0 && !(st[k].worst > 1) &&
                  !(touch[k].worst > 1),
              what);
    }
}

int bench_smoke(void)
{
    check_referee();
    check_contenders_on_hand_cases();
    check_random_sets();
    check_timing_harness_runs();
    check_ratios();
    check_rough();
    check_toi();
    check_toi_accel();
    c2d_put_tally("bench-smoke", &tally);
    return c2d_tally_status(&tally);
}
