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
    int i, j, q;
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
            if (s != C2D_OK && h->status != C2D_OK) continue;
            for (q = 0; q < 4; q++) close &= fabs(got[q] - h->v[q]) <= tolerance(k);
            snprintf(what, sizeof what, "%s: velocities on %s", k->id, h->name);
            check(close, what);
        }
    }
}

/* Every contender runs on random inputs of each kind; the library rows keep
 * the header's promise (16 ulp, right statuses, batch == scalar). */
static void check_random_sets(void)
{
    case_set sets[SET_COUNT];
    char what[200];
    int j, x;
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
            snprintf(what, sizeof what, "%s: statuses on %s inputs", k->id, s->name);
            check(st.wrong_status == 0, what);
            snprintf(what, sizeof what, "%s: batch bit-identical to scalar on %s inputs", k->id, s->name);
            check(st.batch_mismatch == 0, what);
            if (k->kind == KIND_FIXED) continue; /* bound is per component, in the unit test */
            snprintf(what, sizeof what, "%s: max error %.3g ulp <= 16 on %s inputs", k->id, st.max_ulp, s->name);
            check(st.max_ulp <= 16, what);
        }
    }
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

int bench_smoke(void)
{
    check_referee();
    check_contenders_on_hand_cases();
    check_random_sets();
    check_timing_harness_runs();
    c2d_put_tally(NULL, &tally);
    return c2d_tally_status(&tally);
}
