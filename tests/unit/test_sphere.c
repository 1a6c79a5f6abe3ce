/* SPDX-License-Identifier: MIT */
/* c2d_collide_balls(f) and c2d_collide_cushion(f): pool balls as spheres.
 * Accuracy and statuses against the MPFR referee (referee/ref_sphere.c) in
 * ulp of the pair's scale, at unit scale and over the whole range, the
 * identities with the rough-disk model, throw against
 * Alciatore's closed form, energy and momenta over random cases, statuses
 * and untouched bodies, and exp(-x) against MPFR. */
#include "check.h"
#include "cases_sphere.h"

#define CASES 20000
#define BOUND_ULP 24.0 /* c2d_collide's 16 ulp plus the friction part's 8 (the header's bound) */
/* The cushion's: at most ten roundings, each of a term within twice the
 * ball's scale, on the way to an output, plus the unit normal's (the header's bound) */
#define CUSHION_BOUND_ULP 16.0
/* The seeded stream's OK calls (test_any_bits_...): 38,421 before the exact
 * normal speed and the slip length were scaled (speeds beyond 2^996 made
 * them NaN or Inf: a SEPARATING or RANGE for an impact), 78,776 before the
 * double-length slow path (an impulse, R^2/I or a slip beyond the format
 * was a RANGE). */
#define SPHERE_ANY_BITS_OK 99089
/* The whole-range streams' impacts resolved OK by both (whole_balls_run,
 * whole_cushion_run, seeds 27, 28, 37, 38). */
#define WHOLE_BALLS_DOUBLE_OK 4611
#define WHOLE_BALLS_FLOAT_OK 4879
#define WHOLE_CUSHION_DOUBLE_OK 5433
#define WHOLE_CUSHION_FLOAT_OK 5613
#define SPHERE_ENERGY_CHECKED 18748 /* the seeded stream's finite pairs (test_energy_never_grows...) */

static void print_ball(const char *name, const ref_ball *d)
{
    print_error("%s: pos (%a,%a) vel (%a,%a) w (%a,%a,%a) m %a r %a I %a\n", name, d->pos[0], d->pos[1], d->vel[0],
                d->vel[1], d->w[0], d->w[1], d->w[2], d->m, d->r, d->inertia);
}

typedef void (*balls_gen)(c2d_rng *, ref_balls_case *);

/* Every generated pair approaches, so every case reaches the check. */
static double balls_worst(balls_gen gen, int is_float, uint64_t seed)
{
    double worst = 0;
    int i, ok = 0;
    c2d_rng r;
    r.s = seed;
    for (i = 0; i < CASES; i++) {
        ref_balls_case c;
        double got[10], err;
        c2d_status st, want;
        ref_sphere_verdict v;
        gen(&r, &c);
        if (is_float) balls_case_to_float(&c);
        st = is_float ? balls_callf(&c, got) : balls_call(&c, got);
        ref_balls(&c, got, is_float ? 24 : 53, is_float ? -126 : -1022, is_float ? FLT_MAX : DBL_MAX, &v);
        want = v.status, err = v.err_ulp;
        if (st != want || !(err <= BOUND_ULP)) {
            print_ball("a", &c.a), print_ball("b", &c.b);
            print_error("e %a mu %a boost %a decay %a: error %.2f ulp\n", c.e, c.mu, c.boost, c.decay, err);
        }
        assert_status(st, want);
        assert_true(err <= BOUND_ULP);
        worst = fmax(worst, err);
        ok += st == C2D_OK;
    }
    assert_cases_checked(ok, CASES);
    return worst;
}

static void test_pool_pairs_match_the_referee_in_double_and_float(void **state)
{
    (void)state;
    print_message("pool pairs: worst %.2f ulp (double), %.2f ulp (float)\n", balls_worst(gen_pool_balls, 0, 21),
                  balls_worst(gen_pool_balls, 1, 22));
}

static void test_mixed_pairs_match_the_referee_in_double_and_float(void **state)
{
    (void)state;
    print_message("mixed pairs: worst %.2f ulp (double), %.2f ulp (float)\n", balls_worst(gen_mixed_balls, 0, 23),
                  balls_worst(gen_mixed_balls, 1, 24));
}

typedef void (*cushion_gen)(c2d_rng *, ref_cushion_case *);

static double cushion_worst(cushion_gen gen, int is_float, uint64_t seed)
{
    double worst = 0;
    int i, ok = 0;
    c2d_rng r;
    r.s = seed;
    for (i = 0; i < CASES; i++) {
        ref_cushion_case c;
        double got[5], err;
        c2d_status st, want;
        ref_sphere_verdict v;
        gen(&r, &c);
        if (is_float) cushion_case_to_float(&c);
        st = is_float ? cushion_callf(&c, got) : cushion_call(&c, got);
        ref_cushion(&c, got, is_float ? 24 : 53, is_float ? -126 : -1022, is_float ? FLT_MAX : DBL_MAX, &v);
        want = v.status, err = v.err_ulp;
        if (st != want || !(err <= CUSHION_BOUND_ULP)) {
            print_ball("ball", &c.a);
            print_error("n (%a,%a) h %a e %a mu %a: error %.2f ulp\n", c.n[0], c.n[1], c.h, c.e, c.mu, err);
        }
        assert_status(st, want);
        assert_true(err <= CUSHION_BOUND_ULP);
        worst = fmax(worst, err);
        ok += st == C2D_OK;
    }
    /* Both generators turn every ball towards the rail; h = 2R never comes
     * out of c2d_rng_range's half-open interval. */
    assert_cases_checked(ok, CASES);
    return worst;
}

static void test_cushion_impacts_match_the_referee_in_double_and_float(void **state)
{
    (void)state;
    print_message("cushion: worst %.2f ulp (double), %.2f ulp (float)\n", cushion_worst(gen_cushion, 0, 31),
                  cushion_worst(gen_cushion, 1, 32));
}

/* Over many decades (gen_wide_balls): 300 binades either side of 1 in
 * double, 30 in float, where the inertia and every product of the model
 * stay within the format.  The same bounds as at unit scale: the analysis
 * (lib/real/sphere.h, ACCURACY) is in ulp of the scale and holds at any. */
static void wide_double(c2d_rng *r, ref_balls_case *c) { gen_wide_balls(r, c, 300); }
static void wide_float(c2d_rng *r, ref_balls_case *c) { gen_wide_balls(r, c, 30); }
static void wide_cushion_double(c2d_rng *r, ref_cushion_case *c) { gen_wide_cushion(r, c, 300); }
static void wide_cushion_float(c2d_rng *r, ref_cushion_case *c) { gen_wide_cushion(r, c, 30); }

static void test_pairs_over_many_decades_match_the_referee_in_double_and_float(void **state)
{
    (void)state;
    print_message("pairs over many decades: worst %.2f ulp (double), %.2f ulp (float)\n",
                  balls_worst(wide_double, 0, 25), balls_worst(wide_float, 1, 26));
}

static void test_cushion_impacts_over_many_decades_match_the_referee_in_double_and_float(void **state)
{
    (void)state;
    print_message("cushion over many decades: worst %.2f ulp (double), %.2f ulp (float)\n",
                  cushion_worst(wide_cushion_double, 0, 33),
                  cushion_worst(wide_cushion_float, 1, 34));
}

/* Over the whole range (gen_whole_balls, gen_whole_cushion): every field
 * at its own exponent from the smallest subnormal to the largest binade.
 * The status exactly as the referee's, except that C2D_RANGE may stand for
 * an impact whose exact result or change reaches a limit / 8 (the
 * contract's margin, c2d_collide's); on OK every output within the bound.
 * The counts are what the seeded streams give (the rest are INVALID,
 * DEGENERATE, SEPARATING or RANGE as the referee says): a different count
 * means the generator or the statuses changed. */
#define WHOLE_CASES 6000

/* The tally of a whole-range run: impacts checked, RANGE answers allowed
 * near the limit, the worst error. */
typedef struct whole_tally {
    int ok, range;
    double worst;
} whole_tally;

/* The library's answer st agrees with the referee's verdict: RANGE where an
 * exact output reaches the margin, else the referee's status and on OK an
 * error within bound. */
static int whole_agrees(c2d_status st, const ref_sphere_verdict *v, double bound)
{
    if (st == C2D_RANGE && v->status == C2D_OK && v->range_allowed) return 1;
    return st == v->status && (st != C2D_OK || v->err_ulp <= bound);
}

/* Count one case (the caller has printed it if whole_agrees said no). */
static void whole_count(whole_tally *t, c2d_status st, const ref_sphere_verdict *v, double bound)
{
    if (st == C2D_RANGE && v->status == C2D_OK && v->range_allowed) {
        t->range++;
        return;
    }
    assert_status(st, v->status);
    if (st != C2D_OK) return;
    assert_true(v->err_ulp <= bound);
    t->worst = fmax(t->worst, v->err_ulp);
    t->ok++;
}

static void whole_report(const whole_tally *t, const char *what, int is_float, int want_checked)
{
    print_message("%s %s, whole range: %d impacts (%d RANGE near the limit), worst %.2f ulp\n", what,
                  is_float ? "float " : "double", t->ok, t->range, t->worst);
    assert_cases_checked(t->ok, want_checked);
}

static void whole_balls_run(int is_float, uint64_t seed, int want_checked)
{
    const int prec = is_float ? 24 : 53, emin = is_float ? -126 : -1022, emax = is_float ? 127 : 1023;
    whole_tally t = {0, 0, 0};
    int i;
    c2d_rng r;
    r.s = seed;
    for (i = 0; i < WHOLE_CASES; i++) {
        ref_balls_case c;
        double got[10];
        c2d_status st;
        ref_sphere_verdict v;
        gen_whole_balls(&r, &c, prec, emin, emax);
        if (is_float) balls_case_to_float(&c);
        st = is_float ? balls_callf(&c, got) : balls_call(&c, got);
        ref_balls(&c, got, prec, emin, is_float ? FLT_MAX : DBL_MAX, &v);
        if (!whole_agrees(st, &v, BOUND_ULP)) {
            print_ball("a", &c.a), print_ball("b", &c.b);
            print_error("e %a mu %a boost %a decay %a: status %d, referee %d, error %.2f ulp\n", c.e, c.mu, c.boost,
                        c.decay, st, v.status, v.err_ulp);
        }
        whole_count(&t, st, &v, BOUND_ULP);
    }
    whole_report(&t, "balls", is_float, want_checked);
}

static void whole_cushion_run(int is_float, uint64_t seed, int want_checked)
{
    const int prec = is_float ? 24 : 53, emin = is_float ? -126 : -1022, emax = is_float ? 127 : 1023;
    whole_tally t = {0, 0, 0};
    int i;
    c2d_rng r;
    r.s = seed;
    for (i = 0; i < WHOLE_CASES; i++) {
        ref_cushion_case c;
        double got[5];
        c2d_status st;
        ref_sphere_verdict v;
        gen_whole_cushion(&r, &c, prec, emin, emax);
        if (is_float) cushion_case_to_float(&c);
        st = is_float ? cushion_callf(&c, got) : cushion_call(&c, got);
        ref_cushion(&c, got, prec, emin, is_float ? FLT_MAX : DBL_MAX, &v);
        if (!whole_agrees(st, &v, CUSHION_BOUND_ULP)) {
            print_ball("ball", &c.a);
            print_error("n (%a,%a) h %a e %a mu %a: status %d, referee %d, error %.2f ulp\n", c.n[0], c.n[1], c.h, c.e,
                        c.mu, st, v.status, v.err_ulp);
        }
        whole_count(&t, st, &v, CUSHION_BOUND_ULP);
    }
    whole_report(&t, "cushion", is_float, want_checked);
}

static void test_balls_match_the_referee_over_the_whole_range_in_double_and_float(void **state)
{
    (void)state;
    whole_balls_run(0, 27, WHOLE_BALLS_DOUBLE_OK);
    whole_balls_run(1, 28, WHOLE_BALLS_FLOAT_OK);
}

static void test_cushion_impacts_match_the_referee_over_the_whole_range_in_double_and_float(void **state)
{
    (void)state;
    whole_cushion_run(0, 37, WHOLE_CUSHION_DOUBLE_OK);
    whole_cushion_run(1, 38, WHOLE_CUSHION_FLOAT_OK);
}

/* Rails just below h = 2R, where cos(th) -> 0: the sliding friction mu Pn
 * is proportional to cos(th), so cos(th) must keep a few u however small
 * (c2d_cushion_tilt); h = 2R (1 - 2^-k) for k up to the format's
 * precision, against the referee at the cushion's bound. */
static void test_a_rail_near_the_top_of_the_ball_stays_within_the_bound(void **state)
{
    int k, is_float, n = 0;
    c2d_rng r;
    (void)state;
    r.s = 35;
    for (is_float = 0; is_float < 2; is_float++)
        for (k = 2; k < (is_float ? 24 : 53); k++) {
            ref_cushion_case c;
            double got[5];
            ref_sphere_verdict v;
            gen_cushion(&r, &c);
            if (is_float) cushion_case_to_float(&c);
            c.h = 2 * c.a.r - ldexp(2 * c.a.r, -k), c.mu = 1;
            if (is_float) c.h = (float)c.h;
            assert_status(is_float ? cushion_callf(&c, got) : cushion_call(&c, got), C2D_OK);
            ref_cushion(&c, got, is_float ? 24 : 53, is_float ? -126 : -1022, is_float ? FLT_MAX : DBL_MAX, &v);
            assert_status(v.status, C2D_OK);
            if (!(v.err_ulp <= CUSHION_BOUND_ULP)) print_error("h = 2R (1 - 2^-%d): error %.2f ulp\n", k, v.err_ulp);
            assert_true(v.err_ulp <= CUSHION_BOUND_ULP);
            n++;
        }
    assert_cases_checked(n, 51 + 22);
}

static double pair_scale(const c2d_ball *a0, const c2d_ball *b0, const double *got)
{
    const c2d_ball *d[2] = {a0, b0};
    double s = 0;
    int k, i;
    for (k = 0; k < 2; k++) {
        s = fmax(s, fmax(fabs(d[k]->vel.x), fabs(d[k]->vel.y)));
        for (i = 0; i < 3; i++) s = fmax(s, fabs(d[k]->spin[i]) * d[k]->radius);
        for (i = 0; i < 5; i++) s = fmax(s, fabs(got[5 * k + i]) * (i < 2 ? 1 : d[k]->radius));
    }
    return s;
}

/* wx = wy = 0 on both balls with constant mu: c2d_collide_rough at beta 0.
 * Two results within the bound of the referee each differ by at most twice
 * it (the rough model's 18 ulp plus this one's 24). */
static void test_spin_about_the_vertical_only_is_the_rough_disk_model(void **state)
{
    int i, k;
    c2d_rng r;
    (void)state;
    r.s = 41;
    for (i = 0; i < CASES; i++) {
        ref_balls_case c;
        c2d_ball a, b;
        c2d_disk da, db;
        c2d_surface s;
        double got[10], want[10], ulp;
        if (i % 2) gen_pool_balls(&r, &c); else gen_mixed_balls(&r, &c);
        c.a.w[0] = c.a.w[1] = c.b.w[0] = c.b.w[1] = 0;
        c.boost = 0;
        ball_of(&a, &c.a), ball_of(&b, &c.b);
        assert_status(balls_call(&c, got), C2D_OK);
        da.pos = a.pos, da.vel = a.vel, da.spin = a.spin[2], da.mass = a.mass, da.radius = a.radius;
        da.inertia = a.inertia;
        db.pos = b.pos, db.vel = b.vel, db.spin = b.spin[2], db.mass = b.mass, db.radius = b.radius;
        db.inertia = b.inertia;
        s.restitution = c.e, s.friction = c.mu, s.tangential_restitution = 0;
        assert_status(c2d_collide_rough(&da, &db, s), C2D_OK);
        want[0] = da.vel.x, want[1] = da.vel.y, want[2] = 0, want[3] = 0, want[4] = da.spin;
        want[5] = db.vel.x, want[6] = db.vel.y, want[7] = 0, want[8] = 0, want[9] = db.spin;
        ulp = ldexp(1.0, ilogb(pair_scale(&a, &b, got)) - 52);
        for (k = 0; k < 10; k++) {
            double rr = k % 5 < 2 ? 1 : (k < 5 ? a.radius : b.radius);
            assert_true(fabs(got[k] - want[k]) * rr <= (18 + BOUND_ULP) * ulp);
        }
    }
}

/* h = R and wx = wy = 0: c2d_collide_rough_normal against a wall. */
static void test_a_cushion_at_the_centre_height_is_the_rough_wall(void **state)
{
    int i;
    c2d_rng r;
    (void)state;
    r.s = 43;
    for (i = 0; i < CASES; i++) {
        ref_cushion_case c;
        c2d_disk da, wall;
        c2d_surface s;
        c2d_vec2 n;
        double got[5], ulp, sc;
        gen_cushion(&r, &c);
        c.h = c.a.r;
        c.a.w[0] = c.a.w[1] = 0;
        assert_status(cushion_call(&c, got), C2D_OK);
        da.pos.x = c.a.pos[0], da.pos.y = c.a.pos[1], da.vel.x = c.a.vel[0], da.vel.y = c.a.vel[1];
        da.spin = c.a.w[2], da.mass = c.a.m, da.radius = c.a.r, da.inertia = c.a.inertia;
        wall = da;
        wall.vel.x = wall.vel.y = 0, wall.spin = 0, wall.mass = wall.inertia = INFINITY, wall.radius = 0;
        s.restitution = c.e, s.friction = c.mu, s.tangential_restitution = 0;
        n.x = c.n[0], n.y = c.n[1];
        assert_status(c2d_collide_rough_normal(&da, &wall, n, s), C2D_OK);
        sc = fmax(fmax(fmax(fabs(got[0]), fabs(got[1])), fmax(fabs(c.a.vel[0]), fabs(c.a.vel[1]))),
                  c.a.r * fmax(fabs(got[4]), fabs(c.a.w[2])));
        ulp = ldexp(1.0, ilogb(sc) - 52);
        assert_true(fabs(got[0] - da.vel.x) <= (18 + CUSHION_BOUND_ULP) * ulp);
        assert_true(fabs(got[1] - da.vel.y) <= (18 + CUSHION_BOUND_ULP) * ulp);
        assert_true(fabs(got[4] - da.spin) * c.a.r <= (18 + CUSHION_BOUND_ULP) * ulp);
        assert_true(got[2] == 0 && got[3] == 0);
    }
}

/* Alciatore, technical proof A.14: equal solid balls, e = 1, a cut at phi
 * with the cue ball sliding without spin (stun) or rolling: the object
 * ball leaves at the throw angle
 *   stun     atan(min(mu, tan(phi) / 7))
 *   rolling  atan(min(mu, 1 / (7 cos(phi))) sin(phi)).
 * Outputs within 24 ulp of v = 1: the angle within 48 ulp / (v_n) with
 * v_n = cos(phi) the object ball's normal speed. */
static void test_throw_follows_alciatores_closed_form(void **state)
{
    const double m = 0.17, R = 0.028575, mus[3] = {0.02, 0.05, 0.1};
    int deg, k, rolling, n = 0;
    (void)state;
    for (rolling = 0; rolling < 2; rolling++)
        for (k = 0; k < 3; k++)
            for (deg = 5; deg <= 80; deg += 5) {
                double phi = deg * 3.14159265358979323846 / 180, want, got;
                c2d_ball a = {{0, 0}, {1, 0}, {0, 0, 0}, m, R, 0.4 * m * R * R}, b = a;
                c2d_ball_surface s = {1, 0, 0, 0};
                s.friction = mus[k];
                b.vel.x = 0;
                b.pos.x = 2 * R * cos(phi), b.pos.y = 2 * R * sin(phi);
                if (rolling) a.spin[1] = 1 / R;
                assert_status(c2d_collide_balls(&a, &b, s), C2D_OK);
                got = atan2(b.vel.x * sin(phi) - b.vel.y * cos(phi), b.vel.x * cos(phi) + b.vel.y * sin(phi));
                want = rolling ? atan(fmin(mus[k], 1 / (7 * cos(phi))) * sin(phi)) : atan(fmin(mus[k], tan(phi) / 7));
                assert_close(got, want, 48 * DBL_EPSILON / cos(phi));
                n++;
            }
    assert_cases_checked(n, 2 * 3 * 16);
}

/* L about the contact point along n and z, for a ball whose lever from the
 * centre to the contact is sign R n (ball-ball: the z part of -r x m v). */
static void contact_momenta(const c2d_ball *d, const double *o, double nx, double ny, double sign, double out[2])
{
    out[0] = d->inertia * (o[2] * nx + o[3] * ny);
    out[1] = d->inertia * o[4] - sign * d->radius * d->mass * (nx * o[1] - ny * o[0]);
}

static double ball_energy(const c2d_ball *d, const double *o)
{
    return 0.5 * d->mass * (o[0] * o[0] + o[1] * o[1]) + 0.5 * d->inertia * (o[2] * o[2] + o[3] * o[3] + o[4] * o[4]);
}

/* Tolerances from the outputs' bound: a quantity sum c_i x_i with each x_i
 * within BOUND_ULP ulp of the scale moves by at most BOUND_ULP ulp x sum
 * |c_i| (energy: c_i = m |v| + I |w| / R per component, twice for safety
 * of the square's second-order term). */
static void test_energy_never_grows_and_momenta_are_kept(void **state)
{
    int i, k, checked = 0;
    c2d_rng r;
    (void)state;
    r.s = 51;
    for (i = 0; i < CASES; i++) {
        ref_balls_case c;
        c2d_ball a, b;
        double before[10], after[10], ulp, nx, ny, len, la0[2], la1[2], lb0[2], lb1[2], e0, e1, te = 0, tp, tl;
        if (i % 2) gen_pool_balls(&r, &c); else gen_mixed_balls(&r, &c);
        if (isinf(c.b.m)) continue;
        ball_of(&a, &c.a), ball_of(&b, &c.b);
        assert_status(balls_call(&c, after), C2D_OK);
        for (k = 0; k < 2; k++) before[k] = c.a.vel[k], before[5 + k] = c.b.vel[k];
        for (k = 0; k < 3; k++) before[2 + k] = c.a.w[k], before[7 + k] = c.b.w[k];
        ulp = ldexp(1.0, ilogb(pair_scale(&a, &b, after)) - 52) * BOUND_ULP;
        e0 = ball_energy(&a, before) + ball_energy(&b, before + 5);
        e1 = ball_energy(&a, after) + ball_energy(&b, after + 5);
        for (k = 0; k < 5; k++) {
            te += k < 2 ? a.mass * fabs(after[k]) + b.mass * fabs(after[5 + k])
                        : a.inertia * fabs(after[k]) / a.radius + b.inertia * fabs(after[5 + k]) / b.radius;
        }
        assert_true(e1 <= e0 + 2 * te * ulp + 4 * DBL_EPSILON * e0);
        tp = (a.mass + b.mass) * ulp;
        for (k = 0; k < 2; k++)
            assert_true(fabs(a.mass * (after[k] - before[k]) + b.mass * (after[5 + k] - before[5 + k])) <=
                        tp + 4 * DBL_EPSILON * (a.mass * fabs(before[k]) + b.mass * fabs(before[5 + k])));
        nx = b.pos.x - a.pos.x, ny = b.pos.y - a.pos.y, len = hypot(nx, ny), nx /= len, ny /= len;
        contact_momenta(&a, before, nx, ny, 1, la0), contact_momenta(&a, after, nx, ny, 1, la1);
        contact_momenta(&b, before + 5, nx, ny, -1, lb0), contact_momenta(&b, after + 5, nx, ny, -1, lb1);
        for (k = 0; k < 2; k++) {
            tl = (a.inertia / a.radius + a.radius * a.mass + b.inertia / b.radius + b.radius * b.mass) * 2 * ulp;
            assert_true(fabs(la1[k] - la0[k]) <= tl + 8 * DBL_EPSILON * (fabs(la0[k]) + fabs(la1[k])));
            assert_true(fabs(lb1[k] - lb0[k]) <= tl + 8 * DBL_EPSILON * (fabs(lb0[k]) + fabs(lb1[k])));
        }
        checked++;
    }
    /* gen_mixed_balls makes b immovable in one case in 8 (skipped): the
     * count the seeded stream gives. */
    assert_cases_checked(checked, SPHERE_ENERGY_CHECKED);
}

/* The cushion: energy never grows; L about the contact point along n^ and
 * z^: L.n = I w.n + R m sin(th) vt, L.z = I wz - R m cos(th) vt. */
static void test_a_cushion_never_adds_energy_and_keeps_its_contact_momenta(void **state)
{
    int i, k;
    c2d_rng r;
    (void)state;
    r.s = 53;
    for (i = 0; i < CASES; i++) {
        ref_cushion_case c;
        c2d_ball a;
        double before[5], after[5], ulp, nx, ny, len, sn, cs, l0[2], l1[2], e0, e1, te = 0, tl, vt0, vt1;
        gen_cushion(&r, &c);
        ball_of(&a, &c.a);
        assert_status(cushion_call(&c, after), C2D_OK);
        for (k = 0; k < 2; k++) before[k] = c.a.vel[k];
        for (k = 0; k < 3; k++) before[2 + k] = c.a.w[k];
        ulp = 0;
        for (k = 0; k < 5; k++) ulp = fmax(ulp, fmax(fabs(before[k]), fabs(after[k])) * (k < 2 ? 1 : a.radius));
        ulp = ldexp(1.0, ilogb(ulp) - 52) * CUSHION_BOUND_ULP;
        e0 = ball_energy(&a, before), e1 = ball_energy(&a, after);
        for (k = 0; k < 5; k++) te += k < 2 ? a.mass * fabs(after[k]) : a.inertia * fabs(after[k]) / a.radius;
        assert_true(e1 <= e0 + 2 * te * ulp + 4 * DBL_EPSILON * e0);
        len = hypot(c.n[0], c.n[1]), nx = c.n[0] / len, ny = c.n[1] / len;
        sn = (c.h - a.radius) / a.radius, cs = sqrt(1 - sn * sn);
        vt0 = ny * -before[0] + nx * before[1], vt1 = ny * -after[0] + nx * after[1];
        l0[0] = a.inertia * (before[2] * nx + before[3] * ny) + a.radius * a.mass * sn * vt0;
        l1[0] = a.inertia * (after[2] * nx + after[3] * ny) + a.radius * a.mass * sn * vt1;
        l0[1] = a.inertia * before[4] - a.radius * a.mass * cs * vt0;
        l1[1] = a.inertia * after[4] - a.radius * a.mass * cs * vt1;
        tl = (a.inertia / a.radius + a.radius * a.mass) * 2 * ulp;
        for (k = 0; k < 2; k++) assert_true(fabs(l1[k] - l0[k]) <= tl + 8 * DBL_EPSILON * (fabs(l0[k]) + fabs(l1[k])));
    }
}

static void test_frictionless_balls_are_c2d_collide_bit_for_bit(void **state)
{
    int i;
    c2d_rng r;
    (void)state;
    r.s = 61;
    for (i = 0; i < CASES; i++) {
        ref_balls_case c;
        c2d_ball a, b, a0;
        c2d_body ba, bb;
        c2d_ball_surface s;
        gen_mixed_balls(&r, &c);
        c.mu = 0, c.boost = 0;
        ball_of(&a, &c.a), ball_of(&b, &c.b);
        a0 = a;
        ba.pos = a.pos, ba.vel = a.vel, ba.mass = a.mass, bb.pos = b.pos, bb.vel = b.vel, bb.mass = b.mass;
        s = ball_surface_of(&c);
        assert_status(c2d_collide_balls(&a, &b, s), C2D_OK);
        assert_status(c2d_collide(&ba, &bb, c.e), C2D_OK);
        assert_bits_equal(a.vel, ba.vel);
        assert_bits_equal(b.vel, bb.vel);
        assert_memory_equal(a.spin, a0.spin, sizeof a.spin);
    }
}

/* Each bad field alone is C2D_INVALID; INVALID before DEGENERATE before
 * SEPARATING; nothing written unless OK (bit for bit). */
static void test_bad_fields_are_invalid_in_priority_and_untouched(void **state)
{
    const double bad[4] = {NAN, INFINITY, -INFINITY, -1};
    c2d_ball a0 = {{0, 0}, {1, 0}, {1, 2, 3}, 0.17, 0.028575, 5.5e-5}, b0 = a0;
    c2d_ball_surface s0 = {0.95, 0.05, 0.108, 1.088};
    c2d_cushion k0 = {{1, 0}, 0.036, 0.8, 0.2};
    int f, j, n = 0;
    (void)state;
    b0.pos.x = 0.05715, b0.vel.x = 0;
    for (f = 0; f < 21; f++)
        for (j = 0; j < 4; j++) {
            c2d_ball a = a0, b = b0, a1, b1;
            c2d_ball_surface s = s0;
            double *field[21] = {&a.pos.x, &a.pos.y, &a.vel.x, &a.vel.y, &a.spin[0], &a.spin[1], &a.spin[2],
                                 &a.mass, &a.radius, &a.inertia, &b.pos.x, &b.vel.y, &b.spin[2], &b.mass,
                                 &b.radius, &b.inertia, &s.restitution, &s.friction, &s.friction_boost,
                                 &s.friction_decay, &b.spin[0]};
            /* INFINITY is a valid mass, inertia and friction */
            if (bad[j] == INFINITY && (field[f] == &a.mass || field[f] == &a.inertia || field[f] == &b.mass ||
                                       field[f] == &b.inertia || field[f] == &s.friction))
                continue;
            *field[f] = bad[j];
            /* -1 is fine for positions, velocities and spins */
            if (bad[j] == -1 && f < 7) continue;
            if (bad[j] == -1 && (f == 10 || f == 11 || f == 12 || f == 20)) continue;
            a1 = a, b1 = b;
            assert_status(c2d_collide_balls(&a, &b, s), C2D_INVALID);
            assert_memory_equal(&a, &a1, sizeof a);
            assert_memory_equal(&b, &b1, sizeof b);
            n++;
        }
    /* 21 fields x 4 values, less INFINITY for 5 fields and -1 for 11 */
    assert_cases_checked(n, 21 * 4 - 5 - 11);
    {
        c2d_ball a = a0, b = b0, a1;
        c2d_ball_surface s = s0;
        assert_status(c2d_collide_balls(NULL, &b, s), C2D_INVALID);
        assert_status(c2d_collide_balls(&a, &a, s), C2D_DEGENERATE);
        b.pos = a.pos;
        assert_status(c2d_collide_balls(&a, &b, s), C2D_DEGENERATE);
        b.spin[1] = NAN;
        assert_status(c2d_collide_balls(&a, &b, s), C2D_INVALID);
        b = b0, b.vel.x = 2;
        a1 = a;
        assert_status(c2d_collide_balls(&a, &b, s), C2D_SEPARATING);
        assert_memory_equal(&a, &a1, sizeof a);
        b.mass = b.inertia = a.mass = INFINITY, b.vel.x = 0;
        assert_status(c2d_collide_balls(&a, &b, s), C2D_DEGENERATE);
    }
    {
        c2d_ball a = a0, a1;
        c2d_cushion k = k0;
        a1 = a;
        assert_status(c2d_collide_cushion(NULL, k), C2D_INVALID);
        k.height = 0.028;
        assert_status(c2d_collide_cushion(&a, k), C2D_INVALID);
        k.height = 0.058;
        assert_status(c2d_collide_cushion(&a, k), C2D_INVALID);
        k = k0, k.normal.y = NAN;
        assert_status(c2d_collide_cushion(&a, k), C2D_INVALID);
        k = k0, k.restitution = 1.5;
        assert_status(c2d_collide_cushion(&a, k), C2D_INVALID);
        k = k0, k.friction = -0.1;
        assert_status(c2d_collide_cushion(&a, k), C2D_INVALID);
        k = k0, a.mass = INFINITY;
        assert_status(c2d_collide_cushion(&a, k), C2D_INVALID);
        a = a0, a.radius = 0;
        assert_status(c2d_collide_cushion(&a, k), C2D_INVALID);
        a = a0, k.normal.x = 0;
        assert_status(c2d_collide_cushion(&a, k), C2D_DEGENERATE);
        a.spin[0] = NAN;
        assert_status(c2d_collide_cushion(&a, k), C2D_INVALID);
        a = a0, k = k0, k.normal.x = -1;
        assert_status(c2d_collide_cushion(&a, k), C2D_SEPARATING);
        k = k0, k.height = 2 * a.radius;
        assert_status(c2d_collide_cushion(&a, k), C2D_SEPARATING);
        assert_memory_equal(&a, &a1, sizeof a);
        k = k0;
        assert_status(c2d_collide_cushion(&a, k), C2D_OK);
        assert_true(a.vel.x < 0);
    }
}

/* A rolling ball head-on into a rail at h = 0.635 D, by hand from the
 * derivation (lib/real/sphere.h): sin th = 0.27, vn = v, w.t = v / R, so
 * s1 = 0, s2 = -(1 + sin th) v; Pn = (1 + e) m cos th v; lambda =
 * min(mu Pn, |s2| 2m/7) = mu Pn here (0.3466 m v < 0.3629 m v), along +e2:
 *   vx' = v (1 - (1 + e) cos^2 th - mu (1 + e) cos th sin th)
 *   wy' = v / R - (5 / (2 m R)) mu Pn.
 * At h = R the same ball keeps less of its rebound to friction: sin th = 0. */
static void test_a_rolling_ball_into_a_rail_loses_topspin_as_derived(void **state)
{
    const double m = 0.17, R = 0.028575, e = 0.8, mu = 0.2, v = 1.5;
    double sn = (0.635 * 2 * R - R) / R, cs = sqrt(1 - sn * sn), pn = (1 + e) * m * cs * v;
    c2d_ball a = {{0, 0}, {1.5, 0}, {0, 1.5 / 0.028575, 0}, m, R, 0.4 * m * R * R}, a2;
    c2d_cushion k = {{1, 0}, 0.635 * 2 * 0.028575, 0.8, 0.2};
    (void)state;
    a2 = a;
    assert_true(mu * pn < (1 + sn) * v * 2 * m / 7); /* sliding throughout, as the comment says */
    assert_status(c2d_collide_cushion(&a, k), C2D_OK);
    assert_close(a.vel.x, v * (1 - (1 + e) * cs * cs - mu * (1 + e) * cs * sn), 64 * DBL_EPSILON);
    assert_close(a.spin[1] * R, v - 2.5 * mu * pn / m, 64 * DBL_EPSILON);
    assert_true(a.vel.y == 0 && a.spin[0] == 0 && a.spin[2] == 0);
    k.height = R;
    assert_status(c2d_collide_cushion(&a2, k), C2D_OK);
    assert_close(a2.vel.x, -e * v, 16 * DBL_EPSILON);
}

/* A double from random bits: any exponent, NaN and Inf included, or (half
 * the time) a plausible value, so some calls get through to C2D_OK. */
static double any_double(c2d_rng *r)
{
    uint64_t u = c2d_rng_next(r);
    double x;
    if (u & 1) return c2d_rng_range(r, -2, 2);
    memcpy(&x, &u, sizeof x);
    return x;
}

static void any_ball(c2d_rng *r, c2d_ball *d)
{
    d->pos.x = any_double(r), d->pos.y = any_double(r), d->vel.x = any_double(r), d->vel.y = any_double(r);
    d->spin[0] = any_double(r), d->spin[1] = any_double(r), d->spin[2] = any_double(r);
    d->mass = fabs(any_double(r)), d->radius = fabs(any_double(r)), d->inertia = fabs(any_double(r));
}

/* Whatever the bits: never a NaN or Inf written, and nothing written
 * unless C2D_OK.  The count of OK calls is what the seeded stream gives. */
static void test_any_bits_never_write_nan_and_leave_refused_balls_untouched(void **state)
{
    int i, k, ok = 0;
    c2d_rng r;
    (void)state;
    r.s = 91;
    for (i = 0; i < 200000; i++) {
        c2d_ball a, b, a0, b0;
        c2d_ball_surface s;
        c2d_cushion c;
        c2d_status st;
        any_ball(&r, &a), any_ball(&r, &b);
        s.restitution = c2d_rng_unit(&r), s.friction = fabs(any_double(&r)), s.friction_boost = fabs(any_double(&r));
        s.friction_decay = fabs(any_double(&r));
        c.normal.x = any_double(&r), c.normal.y = any_double(&r), c.restitution = c2d_rng_unit(&r);
        c.friction = fabs(any_double(&r)), c.height = a.radius * (1 + c2d_rng_unit(&r));
        a0 = a, b0 = b;
        st = i % 2 ? c2d_collide_balls(&a, &b, s) : c2d_collide_cushion(&a, c);
        if (st != C2D_OK) {
            assert_memory_equal(&a, &a0, sizeof a);
            assert_memory_equal(&b, &b0, sizeof b);
            continue;
        }
        for (k = 0; k < 3; k++) assert_true(isfinite(a.spin[k]) && (i % 2 == 0 || isfinite(b.spin[k])));
        assert_true(isfinite(a.vel.x) && isfinite(a.vel.y));
        assert_true(i % 2 == 0 || (isfinite(b.vel.x) && isfinite(b.vel.y))); /* b is the cushion's bystander */
        ok++;
    }
    assert_cases_checked(ok, SPHERE_ANY_BITS_OK);
}

/* Speeds near the top of the range: the exact normal speed's products and
 * the slip's length must not overflow on the way (they did: Veltkamp's
 * split beyond 2^996 made the normal speed NaN, a SEPARATING without FMA,
 * and the slip's square overflowed, a RANGE with it).  A ball at 2^1006
 * along x into a rail whose normal leans 2^-788 towards x: its normal
 * speed is 2^1006 2^-788 + 2^96 (about 2^218, as vx nx + vy ny).  Without
 * friction and at e = 0 it keeps vx and ends with v.n^ = 0:
 * vy' = -vx nx / ny; with friction, every output stays finite. */
static void test_a_ball_near_the_top_of_the_range_meets_a_rail_in_every_build(void **state)
{
    const c2d_ball start = {{0x1.6f003c4b4734ep+856, 0x1.dece98e40163bp+68},
                            {0x1.51d3f79dec067p+1006, 0x1.2f24d016e6d44p+96},
                            {0x1.2c650346af089p-307, -0x1.dde243da959d3p+657, 0x1.6919f995c84c4p+680},
                            0x1.da592478f4d26p-689,
                            0x1.fab4c2feda98bp-575,
                            0x1.f850082934f8ep+437};
    c2d_cushion c = {{0x1.53763a36dc6a8p-722, 0x1.5a40e980f9912p+66}, 0x1.fab4c2feda98bp-575, 0, 0};
    c2d_ball a = start;
    const double want_vy = -(start.vel.x * c.normal.x) / c.normal.y;
    (void)state;
    assert_status(c2d_collide_cushion(&a, c), C2D_OK);
    assert_true(a.vel.x == start.vel.x);
    assert_close(a.vel.y, want_vy, 1e-12 * fabs(want_vy));
    assert_true(memcmp(a.spin, start.spin, sizeof a.spin) == 0);
    a = start;
    c.friction = 0x1.775c8d4be5ca3p-1;
    assert_status(c2d_collide_cushion(&a, c), C2D_OK);
    assert_true(isfinite(a.vel.x) && isfinite(a.vel.y) && isfinite(a.spin[0]) && isfinite(a.spin[1]) &&
                isfinite(a.spin[2]));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pool_pairs_match_the_referee_in_double_and_float),
        cmocka_unit_test(test_mixed_pairs_match_the_referee_in_double_and_float),
        cmocka_unit_test(test_cushion_impacts_match_the_referee_in_double_and_float),
        cmocka_unit_test(test_balls_match_the_referee_over_the_whole_range_in_double_and_float),
        cmocka_unit_test(test_cushion_impacts_match_the_referee_over_the_whole_range_in_double_and_float),
        cmocka_unit_test(test_a_rail_near_the_top_of_the_ball_stays_within_the_bound),
        cmocka_unit_test(test_pairs_over_many_decades_match_the_referee_in_double_and_float),
        cmocka_unit_test(test_cushion_impacts_over_many_decades_match_the_referee_in_double_and_float),
        cmocka_unit_test(test_spin_about_the_vertical_only_is_the_rough_disk_model),
        cmocka_unit_test(test_a_cushion_at_the_centre_height_is_the_rough_wall),
        cmocka_unit_test(test_throw_follows_alciatores_closed_form),
        cmocka_unit_test(test_energy_never_grows_and_momenta_are_kept),
        cmocka_unit_test(test_a_cushion_never_adds_energy_and_keeps_its_contact_momenta),
        cmocka_unit_test(test_frictionless_balls_are_c2d_collide_bit_for_bit),
        cmocka_unit_test(test_bad_fields_are_invalid_in_priority_and_untouched),
        cmocka_unit_test(test_a_rolling_ball_into_a_rail_loses_topspin_as_derived),
        cmocka_unit_test(test_any_bits_never_write_nan_and_leave_refused_balls_untouched),
        cmocka_unit_test(test_a_ball_near_the_top_of_the_range_meets_a_rail_in_every_build),
    };
    return c2d_run_tests("sphere", tests);
}
