/* SPDX-License-Identifier: MIT */
/* axis_filter.h - the body of test_axis_filter.c (double) and
 * test_axis_filterf.c (float): the filter in front of the exact rounding
 * of axis-aligned impacts (lib/real/arith/round.h), tested white-box against the
 * exact referee.  The including file instantiates the library's templates
 * for its type (as lib/double.c / lib/float.c do) and defines FILTER_FLOAT
 * (0 or 1).
 *
 * What is asserted: every result the filter accepts is the correctly
 * rounded one (referee), in random cases over the whole range and in
 * constructed ones whose exact result lies on a midpoint between two
 * adjacent representable values or within 1e-30 (float: within u^2) of
 * one, or is exact, or is subnormal; an exact tie is always declined; and
 * both the accepting and the declining branch are taken (counted).  The
 * public calls on the same cases (filter, then the exact method where it
 * declined) are correctly rounded too. */

#define FILTER_PREC (C2D_R_MANT + 1)
#define FILTER_CASES 40000

typedef struct tally {
    long accepted, declined, ties, ties_declined;
} tally;

/* An exact power of two as a double (the referee's type). */
static double two_to(int k) { return ldexp(1.0, k); }

/* A random value of the format: (1 + mantissa) 2^k, k in [kmin, kmax],
 * random sign. */
static c2d_real rand_value(c2d_rng *r, int kmin, int kmax)
{
    return (c2d_real)gen_magnitude(r, kmin, kmax, FILTER_PREC);
}

/* The referee's case: a at the origin, b one unit along x on the side that
 * makes ua, ub approach, so the referee returns the velocities. */
static void make_case(ref_case *c, c2d_real u, c2d_real v, c2d_real ma, c2d_real mb, c2d_real e)
{
    memset(c, 0, sizeof *c);
    c->pb[0] = v < u ? 1 : -1;
    c->va[0] = u, c->vb[0] = v;
    c->va[1] = 0.25, c->vb[1] = -0.5; /* untouched: any value */
    c->ma = ma, c->mb = mb;
    c->e = e;
}

/* The filter on one case: each output it accepts must be the referee's
 * correctly rounded value; the public call must be correctly rounded in
 * every output.  Returns nothing; counts into *t.  `tie` says the case was
 * built with an output exactly on a midpoint (a, the first output). */
static void check_case(c2d_real u, c2d_real v, c2d_real ma, c2d_real mb, c2d_real e, int tie, tally *t)
{
    ref_case c;
    ref_answer ans;
    c2d_real y[2];
    int got[2] = {0, 0}, k;
    if (u == v) return;
    make_case(&c, u, v, ma, mb, e);
    ref_answer_init(&ans);
    ref_collide(&c, FILTER_FLOAT ? FLT_MAX : DBL_MAX, &ans);
    assert_status(ans.status, C2D_OK);
    if (mb > C2D_R_MAX) {
        got[0] = c2d_filter_wall(&y[0], u, v, e);
    } else {
        const c2d_real uv[2] = {u, v};
        c2d_real jh, jl;
        if (c2d_filter_impulse(&jh, &jl, uv, ma, mb, e) != 0) {
            got[0] = c2d_filter_apply(&y[0], u, mb, jh, jl);
            got[1] = c2d_filter_apply(&y[1], v, -ma, jh, jl);
        }
    }
    for (k = 0; k < (mb > C2D_R_MAX ? 1 : 2); k++) {
        if (got[k] != 0) {
            if (!ref_correctly_rounded((double)y[k], ans.v[2 * k], FILTER_FLOAT)) {
                print_error("filter accepted %a for output %d, not the nearest to %.25g (u %a v %a ma %a mb %a e %a)\n",
                            (double)y[k], k, mpq_get_d(ans.v[2 * k]), (double)u, (double)v, (double)ma, (double)mb,
                            (double)e);
                fail();
            }
            t->accepted++;
        } else {
            t->declined++;
        }
    }
    if (tie) {
        t->ties++;
        t->ties_declined += got[0] == 0;
    }
    { /* the public call: filter and exact method together */
        double out[4];
        c2d_status st;
#if FILTER_FLOAT
        c2d_bodyf a, b;
        case_to_bodiesf(&c, &a, &b);
        st = c2d_collidef(&a, &b, (float)e);
#else
        c2d_body a, b;
        case_to_bodies(&c, &a, &b);
        st = c2d_collide(&a, &b, e);
#endif
        out[0] = a.vel.x, out[1] = a.vel.y, out[2] = b.vel.x, out[3] = b.vel.y;
        if (!(st == C2D_RANGE && ans.range_required)) {
            assert_status(st, C2D_OK);
            for (k = 0; k < 4; k++) assert_true(ref_correctly_rounded(out[k], ans.v[k], FILTER_FLOAT));
        }
    }
    ref_answer_clear(&ans);
}

static c2d_real rand_restitution(c2d_rng *r)
{
    switch (c2d_rng_next(r) % 4) {
    case 0: return (c2d_real)0.8;
    case 1: return (c2d_real)two_to(-(int)(c2d_rng_next(r) % 60)); /* down to tiny */
    default: return (c2d_real)c2d_rng_unit(r);
    }
}

/* Random impacts: velocities and masses spread over `span` binades around
 * 1 (the whole range when span is the format's), walls one in four. */
static void random_family(c2d_rng *r, int span, tally *t)
{
    int i;
    for (i = 0; i < FILTER_CASES; i++) {
        const c2d_real u = rand_value(r, -span, span), v = c2d_rng_next(r) % 8 == 0 ? 0 : rand_value(r, -span, span);
        const c2d_real ma = c2d_abs(rand_value(r, -span, span));
        const c2d_real mb = c2d_rng_next(r) % 4 == 0 ? (c2d_real)INFINITY : c2d_abs(rand_value(r, -span, span));
        check_case(u, v, ma, mb, rand_restitution(r), 0, t);
    }
}

/* A wall at e = 1/2 whose exact result is on a midpoint or within a
 * relative 2^-100 (float: 2^-48 or closer) of one: y = 1.5 v - 0.5 u with
 * v an odd integer of FILTER_PREC bits below 2^PREC / 1.5, so 1.5 v is an
 * integer plus a half where the spacing is 1, and u zero or tiny; all
 * scaled by 2^s. */
static void midpoint_walls(c2d_rng *r, int smin, int smax, tally *t)
{
    int i;
    for (i = 0; i < FILTER_CASES; i++) {
        const int s = smin + (int)(c2d_rng_next(r) % (uint64_t)(smax - smin + 1));
        const double top = two_to(FILTER_PREC) / 1.5, lo = two_to(FILTER_PREC - 1);
        double vi = floor(c2d_rng_range(r, lo, top));
        const int tie = c2d_rng_next(r) % 4 == 0;
        double ui;
        if (fmod(vi, 2) == 0) vi += 1;
        if (vi >= top) vi -= 2;
        ui = tie ? 0 : ((c2d_rng_next(r) & 1) ? 1 : -1) * two_to(-(FILTER_PREC - 3) - (int)(c2d_rng_next(r) % 40));
        check_case((c2d_real)ldexp(ui, s), (c2d_real)ldexp(vi, s), 1, (c2d_real)INFINITY, (c2d_real)0.5, tie, t);
    }
}

/* Two equal masses at e = 1/2: ua' = 0.25 ua + 0.75 ub.  With ub = V an
 * integer in [2^PREC 2/3, 2^PREC) and ua = U0 + d, U0 = 4N + 2 - 3V
 * (N = floor(3V / 4), so U0 in [-1, 2]), 0.25 U0 + 0.75 V = N + 1/2 is a
 * midpoint, and d (zero: a tie; else tiny) moves ua' off it by d / 4. */
static void midpoint_pairs(c2d_rng *r, int smin, int smax, tally *t)
{
    int i;
    for (i = 0; i < FILTER_CASES; i++) {
        const int s = smin + (int)(c2d_rng_next(r) % (uint64_t)(smax - smin + 1));
        const int64_t vint = (int64_t)c2d_rng_range(r, two_to(FILTER_PREC) * 2 / 3 + 1, two_to(FILTER_PREC));
        const int64_t n = 3 * vint / 4; /* in integers: 3V has more bits than the format */
        const double vi = (double)vint, u0 = (double)(4 * n + 2 - 3 * vint);
        const int tie = c2d_rng_next(r) % 4 == 0;
        const c2d_real m = (c2d_real)two_to((int)(c2d_rng_next(r) % 41) - 20);
        double d = 0;
        if (!tie) {
            const int lowest = u0 == 0 ? 60 : 0; /* U0 + d must stay representable */
            d = ((c2d_rng_next(r) & 1) ? 1 : -1) * two_to(-(FILTER_PREC - 3) - (int)(c2d_rng_next(r) % (uint64_t)(lowest + 1)));
        }
        check_case((c2d_real)ldexp(u0 + d, s), (c2d_real)ldexp(vi, s), m, m, (c2d_real)0.5, tie, t);
    }
}

/* Results near and below the smallest normal: subnormal velocities. */
static void subnormal_family(c2d_rng *r, tally *t)
{
    const int emin = C2D_R_EMIN, p = FILTER_PREC;
    int i;
    for (i = 0; i < FILTER_CASES; i++) {
        const c2d_real u = rand_value(r, emin - p + 1, emin + p + 8), v = rand_value(r, emin - p + 1, emin + p + 8);
        const c2d_real ma = c2d_abs(rand_value(r, -4, 4));
        const c2d_real mb = c2d_rng_next(r) % 3 == 0 ? (c2d_real)INFINITY : c2d_abs(rand_value(r, -4, 4));
        check_case(u, v, ma, mb, rand_restitution(r), 0, t);
    }
}

static void report(const char *what, const tally *t)
{
    print_message("%s %s: filter accepted %ld, declined %ld outputs (%.4f%% declined); exact ties %ld, declined %ld\n",
                  FILTER_FLOAT ? "float " : "double", what, t->accepted, t->declined,
                  100.0 * (double)t->declined / (double)(t->accepted + t->declined), t->ties, t->ties_declined);
}

/* Unit-scale games: the filter decides nearly everything, and rightly. */
static void test_filter_accepts_only_correct_roundings_at_unit_scale(void **state)
{
    c2d_rng r = {FILTER_FLOAT ? 711 : 701};
    tally t = {0, 0, 0, 0};
    (void)state;
    random_family(&r, 8, &t);
    report("unit scale", &t);
    assert_true(t.accepted > 0);
    assert_true(t.declined * 100 < t.accepted); /* the filter is the common path */
}

/* The whole range: the window declines what it must, and what it accepts
 * is right. */
static void test_filter_accepts_only_correct_roundings_over_the_range(void **state)
{
    c2d_rng r = {FILTER_FLOAT ? 712 : 702};
    tally t = {0, 0, 0, 0};
    (void)state;
    random_family(&r, C2D_R_EMAX, &t);
    report("whole range", &t);
    assert_true(t.accepted > 0 && t.declined > 0);
}

/* On and within a hair of a midpoint: never a wrong rounding, every exact
 * tie declined (the exact method breaks it to even), both branches taken. */
static void test_filter_declines_near_midpoints(void **state)
{
    c2d_rng r = {FILTER_FLOAT ? 713 : 703};
    tally walls = {0, 0, 0, 0}, pairs = {0, 0, 0, 0};
    const int s = FILTER_FLOAT ? 30 : 400;
    (void)state;
    midpoint_walls(&r, -s, s, &walls);
    midpoint_pairs(&r, -s, s, &pairs);
    report("midpoint walls", &walls);
    report("midpoint pairs", &pairs);
    assert_true(walls.ties > 0 && walls.ties_declined == walls.ties);
    assert_true(pairs.ties > 0 && pairs.ties_declined == pairs.ties);
    assert_true(walls.declined > walls.ties && pairs.declined > pairs.ties); /* near ties too */
    assert_true(pairs.accepted > 0); /* ub', clear of a boundary */
}

/* Subnormal and near-subnormal results: declined or right. */
static void test_filter_is_right_or_declines_near_underflow(void **state)
{
    c2d_rng r = {FILTER_FLOAT ? 714 : 704};
    tally t = {0, 0, 0, 0};
    (void)state;
    subnormal_family(&r, &t);
    report("near underflow", &t);
    assert_true(t.declined > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_filter_accepts_only_correct_roundings_at_unit_scale),
        cmocka_unit_test(test_filter_accepts_only_correct_roundings_over_the_range),
        cmocka_unit_test(test_filter_declines_near_midpoints),
        cmocka_unit_test(test_filter_is_right_or_declines_near_underflow),
    };
    return c2d_run_tests(FILTER_FLOAT ? "axis_filterf" : "axis_filter", tests);
}
