/* SPDX-License-Identifier: MIT */
/* c2d_collide_batch(f): bit-identical to the scalar call, statuses
 * included, for mixed inputs (valid, grazing, extreme, invalid), walls and
 * cancelling pairs (the second vector pass), and any count, including
 * counts that are not a multiple of the kernel's block. */
#include "check.h"

#define N 1003 /* not a multiple of 8 */

/* The batch's arrays (tests/harness: c2d_soa over one block). */
static double block[C2D_SOA_FIELDS * N];
static c2d_status status[N];

/* N mixed cases into the batch's arrays; cs keeps them for the scalar calls. */
static c2d_soa fill(ref_case *cs, uint64_t seed)
{
    c2d_soa s = c2d_soa_in(block, N, status);
    c2d_rng r;
    int i;
    r.s = seed;
    for (i = 0; i < N; i++) {
        ref_case *c = &cs[i];
        c2d_body a, b;
        uint64_t k = c2d_rng_next(&r) % 10;
        if (k < 6) {
            gen_plain(&r, c);
        } else {
            gen_extreme(&r, c, 53, -1022, 1023);
        }
        if (k == 9) c->va[0] = NAN;
        if (k == 8) c->ma = -1;
        case_to_bodies(c, &a, &b);
        c2d_soa_put(&s, (size_t)i, &a, &b);
    }
    return s;
}

/* Every lane had the scalar call's status and bits, and the count was right. */
static void assert_lanes_agree(const c2d_batch_check *check, size_t done)
{
    if (check->differing != 0) print_error("batch lane %zu differs from the scalar call\n", check->first);
    assert_int_equal(check->differing, 0);
    assert_int_equal(done, check->resolved);
}

static void check_restitution(double e, uint64_t seed)
{
    static ref_case cs[N];
    const c2d_soa s = fill(cs, seed);
    const c2d_pairs p = c2d_soa_pairs(&s);
    c2d_batch_check check = {0, 0, 0};
    size_t done, i;
    done = c2d_collide_batch(&p, N, e, s.status);
    for (i = 0; i < N; i++) {
        c2d_body a, b;
        c2d_status want;
        case_to_bodies(&cs[i], &a, &b);
        want = c2d_collide(&a, &b, e);
        /* untouched on refusal is included: a and b keep their inputs */
        c2d_batch_check_lane(&check, &s, i, want, &a, &b);
    }
    assert_lanes_agree(&check, done);
}

static void test_batch_is_bit_identical_to_scalar_calls(void **state)
{
    (void)state;
    check_restitution(1.0, 401);
    check_restitution(0.95, 402);
    check_restitution(0.0, 403);
}

static void test_batch_with_invalid_restitution_refuses_every_pair(void **state)
{
    static ref_case cs[N];
    static double before[C2D_SOA_FIELDS * N];
    const c2d_soa s = fill(cs, 404);
    const c2d_pairs p = c2d_soa_pairs(&s);
    int i;
    (void)state;
    memcpy(before, block, sizeof block);
    assert_int_equal(c2d_collide_batch(&p, N, 1.5, s.status), 0);
    for (i = 0; i < N; i++) assert_status(s.status[i], C2D_INVALID);
    assert_memory_equal(block, before, sizeof block);
    assert_int_equal(c2d_collide_batch(NULL, N, 1.0, s.status), 0);
}

static void test_batch_without_status_array_and_tiny_counts(void **state)
{
    static ref_case cs[N];
    const c2d_soa s = fill(cs, 405);
    const c2d_pairs p = c2d_soa_pairs(&s);
    size_t n;
    (void)state;
    for (n = 0; n < 20; n++) (void)c2d_collide_batch(&p, n, 1.0, NULL);
    assert_int_equal(c2d_collide_batch(&p, 0, 1.0, NULL), 0);
}

static void test_float_batch_is_bit_identical_to_scalar_calls(void **state)
{
    static float blockf[C2D_SOA_FIELDS * N];
    static ref_case cs[N];
    const c2d_soaf s = c2d_soa_inf(blockf, N, status);
    const c2d_pairsf p = c2d_soa_pairsf(&s);
    c2d_batch_check check = {0, 0, 0};
    c2d_rng r = {406};
    size_t done, i;
    (void)state;
    for (i = 0; i < N; i++) {
        ref_case *c = &cs[i];
        c2d_bodyf a, b;
        if (c2d_rng_next(&r) % 4) gen_plain(&r, c); else gen_extreme(&r, c, 24, -126, 127);
        case_to_bodiesf(c, &a, &b);
        c2d_soa_putf(&s, i, &a, &b);
    }
    done = c2d_collide_batchf(&p, N, 0.9f, s.status);
    for (i = 0; i < N; i++) {
        c2d_bodyf a, b;
        c2d_status want;
        case_to_bodiesf(&cs[i], &a, &b);
        want = c2d_collidef(&a, &b, 0.9f);
        c2d_batch_check_lanef(&check, &s, i, want, &a, &b);
    }
    assert_lanes_agree(&check, done);
}

/* Walls (one mass INFINITY) run in the batch's kernel: plain scenes with
 * a or b immovable, and every fifth lane's other mass at an edge of the
 * kernel's window or outside it (2^-W and just below, huge but finite, the
 * largest finite, NaN, INFINITY: two walls, negative).  Each lane must be
 * the scalar call bit for bit, and most must be resolved. */
static double wall_partner(c2d_rng *r, double m, double lo, double big, double max)
{
    const double edges[8] = {lo, lo * (1 - 0x1p-20), big, max, NAN, INFINITY, -1, 0};
    return c2d_rng_next(r) % 5 == 0 ? edges[c2d_rng_next(r) % 8] : m;
}

static void wall_cases(ref_case *cs, uint64_t seed, double lo, double big, double max)
{
    c2d_rng r;
    int i;
    r.s = seed;
    for (i = 0; i < N; i++) {
        ref_case *c = &cs[i];
        gen_plain(&r, c);
        if (c2d_rng_next(&r) % 2) {
            c->mb = INFINITY;
            c->ma = wall_partner(&r, c->ma, lo, big, max);
        } else {
            c->ma = INFINITY;
            c->mb = wall_partner(&r, c->mb, lo, big, max);
        }
    }
}

static void test_walls_in_the_batch_are_the_scalar_call(void **state)
{
    static ref_case cs[N];
    static float blockf[C2D_SOA_FIELDS * N];
    const c2d_soa s = c2d_soa_in(block, N, status);
    const c2d_pairs p = c2d_soa_pairs(&s);
    const c2d_soaf sf = c2d_soa_inf(blockf, N, status);
    const c2d_pairsf pf = c2d_soa_pairsf(&sf);
    c2d_batch_check check = {0, 0, 0}, checkf = {0, 0, 0};
    size_t done, donef, i;
    (void)state;
    wall_cases(cs, 407, 0x1p-200, 1e250, DBL_MAX);
    for (i = 0; i < N; i++) {
        c2d_body a, b;
        case_to_bodies(&cs[i], &a, &b);
        c2d_soa_put(&s, i, &a, &b);
    }
    done = c2d_collide_batch(&p, N, 0.8, s.status);
    for (i = 0; i < N; i++) {
        c2d_body a, b;
        c2d_status want;
        case_to_bodies(&cs[i], &a, &b);
        want = c2d_collide(&a, &b, 0.8);
        c2d_batch_check_lane(&check, &s, i, want, &a, &b);
    }
    assert_lanes_agree(&check, done);
    assert_true(done > N / 4); /* the family does hold resolved walls */
    wall_cases(cs, 408, 0x1p-20, 1e30, FLT_MAX);
    for (i = 0; i < N; i++) {
        c2d_bodyf a, b;
        case_to_bodiesf(&cs[i], &a, &b);
        c2d_soa_putf(&sf, i, &a, &b);
    }
    donef = c2d_collide_batchf(&pf, N, 0.8f, sf.status);
    for (i = 0; i < N; i++) {
        c2d_bodyf a, b;
        c2d_status want;
        case_to_bodiesf(&cs[i], &a, &b);
        want = c2d_collidef(&a, &b, 0.8f);
        c2d_batch_check_lanef(&checkf, &sf, i, want, &a, &b);
    }
    assert_lanes_agree(&checkf, donef);
    assert_true(donef > N / 4); /* in float too */
}

/* ------------------------------------------------------------ cancelling lanes
 * Pairs whose d cancels (kappa = (|px| + |py|) / |px + py| > 4 in the
 * precision's own arithmetic), which the batch settles in its second vector
 * pass: a plain scene whose relative velocity is turned nearly
 * perpendicular to n, by a relative tilt, in five families (i % 5): 0 the
 * tilt up to 1/5 of either sign (OK and SEPARATING); 1 the same with both
 * positions offset by 2^1..2^40 (the exact normal's low part nl nonzero);
 * 2 a grazing tilt 2^-(prec-18)..2^-(prec+17), across the double-double's
 * trust bound (beyond it the lane takes the scalar call's general tier);
 * 3 a wall (mass INFINITY) whose velocity is (-0, +0); 4 n_x tiny and the
 * relative velocity's x huge, with n_x's exponent spread across the tier's
 * split bound (beyond it the scalar call's general tier again). */
enum { CANCEL_FAMILIES = 5 };

static void cancelling_case(c2d_rng *r, ref_case *c, int family, int prec, int emax)
{
    const double tilt_max = 0.2, speed = c2d_rng_range(r, 0.5, 10);
    double nx, ny, tilt = c2d_rng_range(r, -tilt_max, tilt_max), rvx, rvy;
    gen_plain(r, c);
    c->has_normal = 0;
    if (family == 2) tilt = (c2d_rng_next(r) & 1 ? 1 : -1) * ldexp(1, -(prec - 18) - (int)(c2d_rng_next(r) % 36));
    if (family == 4) {
        /* n = (2^-s (1 + u), 1): s around half the exponent range, so that
         * |rvx| = 2^4 / |nx| straddles the split bound 2^(emax/2). */
        const int s = emax / 2 - 60 + (int)(c2d_rng_next(r) % 120) + 4;
        c->pa[0] = 0;
        c->pb[0] = ldexp(1 + c2d_rng_unit(r), -s);
        c->pb[1] = c->pa[1] + 1;
    }
    if (family == 1) {
        const double off = ldexp(1, 1 + (int)(c2d_rng_next(r) % 40));
        c->pa[0] += off, c->pa[1] += off, c->pb[0] += off, c->pb[1] += off;
    }
    nx = c->pb[0] - c->pa[0], ny = c->pb[1] - c->pa[1];
    if (family == 4) {
        rvx = 16 / nx;
        rvy = -16 * (1 + tilt) / ny;
    } else {
        rvx = speed * (-ny + tilt * nx);
        rvy = speed * (nx + tilt * ny);
    }
    if (family == 3) {
        if (c2d_rng_next(r) & 1) {
            c->mb = INFINITY, c->vb[0] = -0.0, c->vb[1] = 0.0;
            c->va[0] = -rvx, c->va[1] = -rvy;
        } else {
            c->ma = INFINITY, c->va[0] = -0.0, c->va[1] = 0.0;
            c->vb[0] = rvx, c->vb[1] = rvy;
        }
    } else {
        c->vb[0] = c->va[0] + rvx, c->vb[1] = c->va[1] + rvy;
    }
}

/* Kappa > 4 in double, for the bodies as the call gets them. */
static int cancels_double(const c2d_body *a, const c2d_body *b)
{
    const double px = (b->vel.x - a->vel.x) * (b->pos.x - a->pos.x);
    const double py = (b->vel.y - a->vel.y) * (b->pos.y - a->pos.y);
    return fabs(px) + fabs(py) > 4 * fabs(px + py);
}

static int cancels_float(const c2d_bodyf *a, const c2d_bodyf *b)
{
    const float px = (b->vel.x - a->vel.x) * (b->pos.x - a->pos.x);
    const float py = (b->vel.y - a->vel.y) * (b->pos.y - a->pos.y);
    return fabsf(px) + fabsf(py) > 4 * fabsf(px + py);
}

/* What a cancelling run met: lanes that cancel, and of those OK and
 * SEPARATING, per family. */
typedef struct cancel_tally {
    int cancelling[CANCEL_FAMILIES], ok, separating;
} cancel_tally;

static void tally_lane(cancel_tally *t, int family, int cancelling, c2d_status want)
{
    if (!cancelling) return;
    t->cancelling[family]++;
    t->ok += want == C2D_OK;
    t->separating += want == C2D_SEPARATING;
}

static void assert_cancelling_met(const cancel_tally *t, const char *what)
{
    int f, all = 0;
    for (f = 0; f < CANCEL_FAMILIES; f++) {
        all += t->cancelling[f];
        assert_true(t->cancelling[f] > N / CANCEL_FAMILIES / 4); /* every family reaches the pass */
    }
    print_message("%s: %d of %d lanes cancel (families %d %d %d %d %d), %d OK, %d separating\n", what, all, N,
                  t->cancelling[0], t->cancelling[1], t->cancelling[2], t->cancelling[3], t->cancelling[4], t->ok,
                  t->separating);
    assert_true(all > N / 2);
    assert_true(t->ok > N / 8 && t->separating > N / 8);
}

static void check_cancelling(double e, uint64_t seed)
{
    static ref_case cs[N];
    const c2d_soa s = c2d_soa_in(block, N, status);
    const c2d_pairs p = c2d_soa_pairs(&s);
    c2d_batch_check check = {0, 0, 0};
    cancel_tally t = {{0}, 0, 0};
    c2d_rng r;
    size_t done, i;
    r.s = seed;
    for (i = 0; i < N; i++) {
        c2d_body a, b;
        cancelling_case(&r, &cs[i], (int)(i % CANCEL_FAMILIES), 53, 1023);
        case_to_bodies(&cs[i], &a, &b);
        c2d_soa_put(&s, i, &a, &b);
    }
    done = c2d_collide_batch(&p, N, e, s.status);
    for (i = 0; i < N; i++) {
        c2d_body a, b;
        c2d_status want;
        int cancels;
        case_to_bodies(&cs[i], &a, &b);
        cancels = cancels_double(&a, &b);
        want = c2d_collide(&a, &b, e);
        tally_lane(&t, (int)(i % CANCEL_FAMILIES), cancels, want);
        c2d_batch_check_lane(&check, &s, i, want, &a, &b);
    }
    assert_lanes_agree(&check, done);
    assert_cancelling_met(&t, "double");
}

static void check_cancelling_float(float e, uint64_t seed)
{
    static float blockf[C2D_SOA_FIELDS * N];
    static ref_case cs[N];
    const c2d_soaf s = c2d_soa_inf(blockf, N, status);
    const c2d_pairsf p = c2d_soa_pairsf(&s);
    c2d_batch_check check = {0, 0, 0};
    cancel_tally t = {{0}, 0, 0};
    c2d_rng r;
    size_t done, i;
    r.s = seed;
    for (i = 0; i < N; i++) {
        c2d_bodyf a, b;
        cancelling_case(&r, &cs[i], (int)(i % CANCEL_FAMILIES), 24, 127);
        case_to_float(&cs[i]);
        case_to_bodiesf(&cs[i], &a, &b);
        c2d_soa_putf(&s, i, &a, &b);
    }
    done = c2d_collide_batchf(&p, N, e, s.status);
    for (i = 0; i < N; i++) {
        c2d_bodyf a, b;
        c2d_status want;
        int cancels;
        case_to_bodiesf(&cs[i], &a, &b);
        cancels = cancels_float(&a, &b);
        want = c2d_collidef(&a, &b, e);
        tally_lane(&t, (int)(i % CANCEL_FAMILIES), cancels, want);
        c2d_batch_check_lanef(&check, &s, i, want, &a, &b);
    }
    assert_lanes_agree(&check, done);
    assert_cancelling_met(&t, "float");
}

static void test_cancelling_lanes_are_the_scalar_call(void **state)
{
    (void)state;
    check_cancelling(1.0, 409);
    check_cancelling(0.5, 410);
    check_cancelling(0.0, 411);
    check_cancelling_float(1.0f, 412);
    check_cancelling_float(0.25f, 413);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_batch_is_bit_identical_to_scalar_calls),
        cmocka_unit_test(test_batch_with_invalid_restitution_refuses_every_pair),
        cmocka_unit_test(test_batch_without_status_array_and_tiny_counts),
        cmocka_unit_test(test_float_batch_is_bit_identical_to_scalar_calls),
        cmocka_unit_test(test_walls_in_the_batch_are_the_scalar_call),
        cmocka_unit_test(test_cancelling_lanes_are_the_scalar_call),
    };
    return c2d_run_tests("batch", tests);
}
