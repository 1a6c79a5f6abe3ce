/* SPDX-License-Identifier: MIT */
/* Axis-aligned impacts (a normal with one zero component) are correctly
 * rounded, double and float, scalar and batch, over the whole range; and
 * Newton's cradle comes out exactly, with the least number of impacts. */
#include "check.h"

#define CASES 20000

/* A case whose normal lies on an axis: for c2d_collide the centres share a
 * coordinate, for c2d_collide_normal the given normal has a zero component. */
static void gen_axis(c2d_rng *r, ref_case *c, int extreme, int prec, int emin, int emax)
{
    const int axis = (int)(c2d_rng_next(r) & 1);
    if (extreme)
        gen_extreme(r, c, prec, emin, emax);
    else
        gen_plain(r, c);
    if (c2d_rng_next(r) % 4 == 0) c->mb = c->ma; /* equal masses often */
    if (c2d_rng_next(r) % 8 == 0) c->mb = INFINITY;
    if (isinf(c->ma) && isinf(c->mb)) c->ma = 1;
    c->pb[1 - axis] = c->pa[1 - axis];
    c->n[1 - axis] = 0;
    if (c->n[axis] == 0) c->n[axis] = 1;
    if (c2d_rng_next(r) % 2 == 0) { /* approach along the axis */
        const double s = c->has_normal ? c->n[axis] : c->pb[axis] - c->pa[axis];
        if ((c->vb[axis] - c->va[axis]) * s > 0) {
            const double t = c->va[axis];
            c->va[axis] = c->vb[axis];
            c->vb[axis] = t;
        }
    }
}

static c2d_status run(const ref_case *c, double out[4], int is_float)
{
    c2d_status st;
    if (is_float) {
        c2d_bodyf a, b;
        case_to_bodiesf(c, &a, &b);
        if (c->has_normal) {
            c2d_vec2f n = {(float)c->n[0], (float)c->n[1]};
            st = c2d_collide_normalf(&a, &b, n, (float)c->e);
        } else {
            st = c2d_collidef(&a, &b, (float)c->e);
        }
        out[0] = a.vel.x, out[1] = a.vel.y, out[2] = b.vel.x, out[3] = b.vel.y;
    } else {
        c2d_body a, b;
        case_to_bodies(c, &a, &b);
        if (c->has_normal) {
            c2d_vec2 n = {c->n[0], c->n[1]};
            st = c2d_collide_normal(&a, &b, n, c->e);
        } else {
            st = c2d_collide(&a, &b, c->e);
        }
        out[0] = a.vel.x, out[1] = a.vel.y, out[2] = b.vel.x, out[3] = b.vel.y;
    }
    return st;
}

/* want_checked: how many of the CASES are resolved by both and so checked,
 * the exact count of the seeded stream (in the calls below; roughly 85%:
 * half the pairs are turned to approach along the axis, and moving b onto
 * the axis leaves gen_plain's approach in most of the rest).  A different
 * count means the generator or the statuses changed. */
static void check_family(int is_float, int extreme, uint64_t seed, int want_checked)
{
    const int prec = is_float ? 24 : 53, emin = is_float ? -126 : -1022, emax = is_float ? 127 : 1023;
    const double limit = is_float ? FLT_MAX : DBL_MAX;
    c2d_rng r;
    ref_answer ans;
    int i, k, ok = 0;
    r.s = seed;
    ref_answer_init(&ans);
    for (i = 0; i < CASES; i++) {
        ref_case c;
        double got[4], in[4];
        c2d_status st;
        gen_axis(&r, &c, extreme, prec, emin, emax);
        if (is_float) case_to_float(&c);
        in[0] = c.va[0], in[1] = c.va[1], in[2] = c.vb[0], in[3] = c.vb[1];
        st = run(&c, got, is_float);
        ref_collide(&c, limit, &ans);
        if (ans.status == C2D_OK && ans.range_required) ans.status = C2D_RANGE;
        if (st == C2D_RANGE && ans.status == C2D_OK) {
            /* only where the correctly rounded result overflows */
            for (k = 0; k < 4; k++) assert_true(fabs(mpq_get_d(ans.v[k])) >= limit);
            continue;
        }
        assert_status(st, ans.status);
        if (st != C2D_OK) continue;
        for (k = 0; k < 4; k++) {
            if (!ref_correctly_rounded(got[k], ans.v[k], is_float)) {
                print_error("output %d = %a (input %a) is not the nearest to %.20g\n", k, got[k], in[k],
                            mpq_get_d(ans.v[k]));
                fail();
            }
        }
        ok++;
    }
    ref_answer_clear(&ans);
    assert_cases_checked(ok, want_checked);
    print_message("%s %s: %d axis-aligned impacts, every output correctly rounded\n", is_float ? "float " : "double",
                  extreme ? "whole range" : "unit scale", ok);
}

static void test_double_axis_impacts_are_correctly_rounded(void **state)
{
    (void)state;
    check_family(0, 0, 501, 17192);
}

static void test_double_axis_impacts_are_correctly_rounded_over_the_range(void **state)
{
    (void)state;
    check_family(0, 1, 502, 16587);
}

static void test_float_axis_impacts_are_correctly_rounded(void **state)
{
    (void)state;
    check_family(1, 0, 503, 17280);
}

static void test_float_axis_impacts_are_correctly_rounded_over_the_range(void **state)
{
    (void)state;
    check_family(1, 1, 504, 16735);
}

/* Equal masses at e = 1 swap exactly; a wall at e = 1 negates exactly; the
 * other component is untouched, bit for bit. */
static void test_swaps_and_wall_bounces_are_exact(void **state)
{
    c2d_rng r = {505};
    int i, checked = 0;
    (void)state;
    for (i = 0; i < CASES; i++) {
        const double m = c2d_rng_range(&r, 0.1, 10), u = c2d_rng_range(&r, -10, 10), v = u - c2d_rng_range(&r, 0, 10);
        const double y = c2d_rng_range(&r, -1e6, 1e6), t1 = c2d_rng_range(&r, -5, 5), t2 = c2d_rng_range(&r, -5, 5);
        c2d_body a = {{y, 3}, {u, t1}, m}, b = {{y + 1e-3 + c2d_rng_unit(&r), 3}, {v, t2}, m};
        c2d_body ball = {{0, 0}, {t1, u}, m}, wall = {{0, 1}, {0, 0}, INFINITY};
        c2d_vec2 up = {0, 1};
        if (u == v) continue;
        checked++;
        assert_status(c2d_collide(&a, &b, 1), C2D_OK);
        assert_true(a.vel.x == v && b.vel.x == u && a.vel.y == t1 && b.vel.y == t2);
        if (u > 0) {
            assert_status(c2d_collide_normal(&ball, &wall, up, 1), C2D_OK);
            assert_true(ball.vel.y == -u && ball.vel.x == t1 && wall.vel.y == 0);
        }
    }
    /* u == v only when the generator's unit draw is exactly 0 (one in 2^53):
     * every case is checked. */
    assert_cases_checked(checked, CASES);
}

/* The batch gives the scalar call's bits on axis-aligned lanes too. */
static void test_batch_matches_scalar_on_axis_aligned_lanes(void **state)
{
    enum { LANES = 1000 };
    static double block[C2D_SOA_FIELDS * LANES];
    static c2d_status status[LANES];
    static c2d_body sa[LANES], sb[LANES];
    static c2d_status want[LANES];
    const c2d_soa s = c2d_soa_in(block, LANES, status);
    const c2d_pairs p = c2d_soa_pairs(&s);
    c2d_batch_check check = {0, 0, 0};
    c2d_rng r = {506};
    size_t i, done;
    (void)state;
    for (i = 0; i < LANES; i++) {
        ref_case c;
        gen_axis(&r, &c, i % 3 == 0, 53, -1022, 1023);
        case_to_bodies(&c, &sa[i], &sb[i]);
        c2d_soa_put(&s, i, &sa[i], &sb[i]);
        want[i] = c2d_collide(&sa[i], &sb[i], 0.9);
    }
    done = c2d_collide_batch(&p, LANES, 0.9, status);
    for (i = 0; i < LANES; i++) c2d_batch_check_lane(&check, &s, i, want[i], &sa[i], &sb[i]);
    assert_true(c2d_batch_check_passed(&check, done));
}

/* ------------------------------------------------------- Newton's cradle */

enum { CRADLE_MAX = 23 };

typedef struct cradle {
    c2d_body disk[CRADLE_MAX];
    int count;
    long impacts;
} cradle;

/* n disks of radius 1/2 touching in a row along `axis` (0 x, 1 y), starting
 * at `origin`; the first k move at v towards the rest, in `dir` (+1, -1). */
static void cradle_make(cradle *c, int n, int k, int axis, int dir, double origin, double v)
{
    int i;
    c->count = n + k;
    c->impacts = 0;
    for (i = 0; i < c->count; i++) {
        c2d_body *d = &c->disk[i];
        const double along = origin + dir * (double)i;
        d->pos.x = axis == 0 ? along : origin;
        d->pos.y = axis == 0 ? origin : along;
        d->vel.x = d->vel.y = 0;
        d->mass = 1;
        if (i < k) {
            if (axis == 0) d->vel.x = dir * v; else d->vel.y = dir * v;
        }
    }
}

/* Time-ordered events on the public API: the earliest contact among
 * neighbours (c2d_time_of_impact), every disk moved to it, the impact
 * resolved (c2d_collide), until no pair will meet. */
static void cradle_run(cradle *c)
{
    for (;;) {
        double tmin = INFINITY;
        int i, first = -1;
        for (i = 0; i + 1 < c->count; i++) {
            double t;
            if (c2d_time_of_impact(&c->disk[i], &c->disk[i + 1], 1.0, &t) == C2D_OK && t < tmin) tmin = t, first = i;
        }
        if (first < 0) return;
        for (i = 0; i < c->count; i++) {
            c->disk[i].pos.x += c->disk[i].vel.x * tmin;
            c->disk[i].pos.y += c->disk[i].vel.y * tmin;
        }
        assert_status(c2d_collide(&c->disk[first], &c->disk[first + 1], 1.0), C2D_OK);
        c->impacts++;
        assert_true(c->impacts <= 10000);
    }
}

/* N touching disks, K cue disks at v: the last K leave at exactly v, the
 * rest stand exactly still, after exactly K N impacts (each of the K
 * pulses crosses the N gaps once: cue to first, then disk to disk), with
 * no spurious micro-impacts from residual velocities. */
static void test_newtons_cradle_is_exact_with_the_least_impacts(void **state)
{
    static const double origins[] = {0, 12.5, 1e6 + 0.25, -3e9};
    int n, k, axis, dir, o, configs = 0;
    (void)state;
    for (n = 1; n <= 20; n++)
        for (k = 1; k <= 3; k++)
            for (axis = 0; axis < 2; axis++)
                for (dir = -1; dir <= 1; dir += 2)
                    for (o = 0; o < 4; o++) {
                        static cradle c;
                        int i;
                        cradle_make(&c, n, k, axis, dir, origins[o], 0.75);
                        cradle_run(&c);
                        assert_int_equal(c.impacts, (long)k * n);
                        for (i = 0; i < c.count; i++) {
                            const double want = i >= n ? dir * 0.75 : 0.0;
                            const double along = axis == 0 ? c.disk[i].vel.x : c.disk[i].vel.y;
                            const double across = axis == 0 ? c.disk[i].vel.y : c.disk[i].vel.x;
                            assert_true(along == want && across == 0);
                        }
                        configs++;
                    }
    print_message("cradle: %d configurations (N 1-20, K 1-3, both axes and directions, 4 origins) "
                  "bit-exact with K N impacts\n", configs);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_swaps_and_wall_bounces_are_exact),
        cmocka_unit_test(test_double_axis_impacts_are_correctly_rounded),
        cmocka_unit_test(test_double_axis_impacts_are_correctly_rounded_over_the_range),
        cmocka_unit_test(test_float_axis_impacts_are_correctly_rounded),
        cmocka_unit_test(test_float_axis_impacts_are_correctly_rounded_over_the_range),
        cmocka_unit_test(test_batch_matches_scalar_on_axis_aligned_lanes),
        cmocka_unit_test(test_newtons_cradle_is_exact_with_the_least_impacts),
    };
    return c2d_run_tests("axis", tests);
}
