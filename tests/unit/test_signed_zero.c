/* SPDX-License-Identifier: MIT */
/* An immovable body's velocity comes back exactly as given, bits included
 * (a velocity of -0.0 used to come back +0.0 on oblique impacts, its
 * change being a zero whose sign follows the impulse): every entry point,
 * double and float, over unit-scale and whole-range cases (so every tier:
 * front end, fast path, double-double, general path, axes), either body
 * immovable, each velocity component -0, +0 or a random value. */
#include "check.h"

#define CASES 40000
#define PAIRS 37 /* two full batch blocks and a tail */

/* A case with body `side` (0: a, 1: b) immovable; its velocity components
 * -0, +0 or as generated. */
static void gen_wall(c2d_rng *r, ref_case *c, int prec, int emin, int emax, int side)
{
    double *v;
    int i;
    if (c2d_rng_next(r) & 1) gen_plain(r, c); else gen_extreme(r, c, prec, emin, emax);
    c->e = c2d_rng_unit(r);
    if (side == 0) c->ma = INFINITY, v = c->va; else c->mb = INFINITY, v = c->vb;
    for (i = 0; i < 2; i++) {
        const unsigned k = (unsigned)(c2d_rng_next(r) % 3);
        if (k < 2) v[i] = k == 0 ? -0.0 : 0.0;
    }
}

/* The immovable body's velocity bits before and after one call. */
#define ASSERT_KEPT(before, after) assert_bits_equal(before, after)

static void test_double(void **state)
{
    c2d_rng r = {1901};
    int i, ok = 0;
    (void)state;
    for (i = 0; i < CASES; i++) {
        const int side = i & 1;
        ref_case c;
        c2d_body a, b, a0, b0;
        c2d_disk da, db;
        c2d_vec2 n;
        c2d_surface s;
        c2d_status st;
        gen_wall(&r, &c, 53, -1022, 1023, side);
        case_to_bodies(&c, &a0, &b0);
        n.x = c.n[0], n.y = c.n[1];
#define KEPT() do { if (side == 0) ASSERT_KEPT(a0.vel, a.vel); else ASSERT_KEPT(b0.vel, b.vel); } while (0)
        a = a0, b = b0;
        st = c2d_collide(&a, &b, c.e);
        ok += st == C2D_OK;
        KEPT();
        a = a0, b = b0;
        c2d_collide_normal(&a, &b, n, c.e);
        KEPT();
        s.restitution = c.e;
        s.friction = (i & 2) ? 0.0 : 0.5;
        s.tangential_restitution = (i & 4) ? -1.0 : 0.3;
        da.pos = a0.pos, da.vel = a0.vel, da.mass = a0.mass, da.radius = 0.5, da.spin = -0.0;
        db.pos = b0.pos, db.vel = b0.vel, db.mass = b0.mass, db.radius = side ? 0.0 : 0.5, db.spin = -0.0;
        da.inertia = side == 0 ? INFINITY : 0.1, db.inertia = side ? INFINITY : 0.1;
        {
            c2d_disk ea = da, eb = db;
            c2d_collide_rough(&ea, &eb, s);
            if (side == 0) ASSERT_KEPT(da.vel, ea.vel), ASSERT_KEPT(da.spin, ea.spin);
            else ASSERT_KEPT(db.vel, eb.vel), ASSERT_KEPT(db.spin, eb.spin);
            ea = da, eb = db;
            c2d_collide_rough_normal(&ea, &eb, n, s);
            if (side == 0) ASSERT_KEPT(da.vel, ea.vel), ASSERT_KEPT(da.spin, ea.spin);
            else ASSERT_KEPT(db.vel, eb.vel), ASSERT_KEPT(db.spin, eb.spin);
        }
#undef KEPT
    }
    assert_true(ok > CASES / 8); /* many impacts, not only refusals */
}

static void test_float(void **state)
{
    c2d_rng r = {1902};
    int i, ok = 0;
    (void)state;
    for (i = 0; i < CASES; i++) {
        const int side = i & 1;
        ref_case c;
        c2d_bodyf a, b, a0, b0;
        c2d_diskf da, db;
        c2d_vec2f n;
        c2d_surfacef s;
        c2d_status st;
        gen_wall(&r, &c, 24, -126, 127, side);
        case_to_float(&c);
        case_to_bodiesf(&c, &a0, &b0);
        n.x = (float)c.n[0], n.y = (float)c.n[1];
#define KEPT() do { if (side == 0) ASSERT_KEPT(a0.vel, a.vel); else ASSERT_KEPT(b0.vel, b.vel); } while (0)
        a = a0, b = b0;
        st = c2d_collidef(&a, &b, (float)c.e);
        ok += st == C2D_OK;
        KEPT();
        a = a0, b = b0;
        c2d_collide_normalf(&a, &b, n, (float)c.e);
        KEPT();
        s.restitution = (float)c.e;
        s.friction = (i & 2) ? 0.0f : 0.5f;
        s.tangential_restitution = (i & 4) ? -1.0f : 0.3f;
        da.pos = a0.pos, da.vel = a0.vel, da.mass = a0.mass, da.radius = 0.5f, da.spin = -0.0f;
        db.pos = b0.pos, db.vel = b0.vel, db.mass = b0.mass, db.radius = side ? 0.0f : 0.5f, db.spin = -0.0f;
        da.inertia = side == 0 ? INFINITY : 0.1f, db.inertia = side ? INFINITY : 0.1f;
        {
            c2d_diskf ea = da, eb = db;
            c2d_collide_roughf(&ea, &eb, s);
            if (side == 0) ASSERT_KEPT(da.vel, ea.vel), ASSERT_KEPT(da.spin, ea.spin);
            else ASSERT_KEPT(db.vel, eb.vel), ASSERT_KEPT(db.spin, eb.spin);
            ea = da, eb = db;
            c2d_collide_rough_normalf(&ea, &eb, n, s);
            if (side == 0) ASSERT_KEPT(da.vel, ea.vel), ASSERT_KEPT(da.spin, ea.spin);
            else ASSERT_KEPT(db.vel, eb.vel), ASSERT_KEPT(db.spin, eb.spin);
        }
#undef KEPT
    }
    assert_true(ok > CASES / 8);
}

/* The batch, kernel lanes and scalar lanes: every pair's immovable body as
 * given, and every pair as the scalar call gives it. */
static void test_batch(void **state)
{
    c2d_rng r = {1903};
    int round;
    (void)state;
    for (round = 0; round < CASES / PAIRS; round++) {
        double pax[PAIRS], pay[PAIRS], pbx[PAIRS], pby[PAIRS], vax[PAIRS], vay[PAIRS], vbx[PAIRS], vby[PAIRS];
        double ma[PAIRS], mb[PAIRS];
        float fpax[PAIRS], fpay[PAIRS], fpbx[PAIRS], fpby[PAIRS], fvax[PAIRS], fvay[PAIRS], fvbx[PAIRS], fvby[PAIRS];
        float fma_[PAIRS], fmb[PAIRS];
        c2d_body a[PAIRS], b[PAIRS];
        c2d_bodyf af[PAIRS], bf[PAIRS];
        c2d_pairs p = {pax, pay, pbx, pby, vax, vay, vbx, vby, ma, mb};
        c2d_pairsf pf = {fpax, fpay, fpbx, fpby, fvax, fvay, fvbx, fvby, fma_, fmb};
        int i;
        const double e = round % 2 ? 1.0 : 0.5; /* exact in float too */
        for (i = 0; i < PAIRS; i++) {
            ref_case c;
            gen_wall(&r, &c, 53, -1022, 1023, (int)(c2d_rng_next(&r) & 1));
            if (round % 3 == 0) c.ma = c.mb = 1; /* some lanes movable: the kernel's mixed blocks */
            case_to_bodies(&c, &a[i], &b[i]);
            pax[i] = a[i].pos.x, pay[i] = a[i].pos.y, vax[i] = a[i].vel.x, vay[i] = a[i].vel.y, ma[i] = a[i].mass;
            pbx[i] = b[i].pos.x, pby[i] = b[i].pos.y, vbx[i] = b[i].vel.x, vby[i] = b[i].vel.y, mb[i] = b[i].mass;
            case_to_float(&c);
            case_to_bodiesf(&c, &af[i], &bf[i]);
            fpax[i] = af[i].pos.x, fpay[i] = af[i].pos.y, fvax[i] = af[i].vel.x, fvay[i] = af[i].vel.y;
            fpbx[i] = bf[i].pos.x, fpby[i] = bf[i].pos.y, fvbx[i] = bf[i].vel.x, fvby[i] = bf[i].vel.y;
            fma_[i] = af[i].mass, fmb[i] = bf[i].mass;
        }
        c2d_collide_batch(&p, PAIRS, e, NULL);
        c2d_collide_batchf(&pf, PAIRS, (float)e, NULL);
        for (i = 0; i < PAIRS; i++) {
            c2d_body ca = a[i], cb = b[i];
            c2d_bodyf cfa = af[i], cfb = bf[i];
            double got[4];
            float gotf[4];
            got[0] = vax[i], got[1] = vay[i], got[2] = vbx[i], got[3] = vby[i];
            gotf[0] = fvax[i], gotf[1] = fvay[i], gotf[2] = fvbx[i], gotf[3] = fvby[i];
            if (a[i].mass > DBL_MAX) assert_memory_equal(&got[0], &a[i].vel, sizeof(a[i].vel));
            if (b[i].mass > DBL_MAX) assert_memory_equal(&got[2], &b[i].vel, sizeof(b[i].vel));
            if (af[i].mass > FLT_MAX) assert_memory_equal(&gotf[0], &af[i].vel, sizeof(af[i].vel));
            if (bf[i].mass > FLT_MAX) assert_memory_equal(&gotf[2], &bf[i].vel, sizeof(bf[i].vel));
            c2d_collide(&ca, &cb, e);
            c2d_collidef(&cfa, &cfb, (float)e);
            assert_memory_equal(&got[0], &ca.vel, sizeof(ca.vel));
            assert_memory_equal(&got[2], &cb.vel, sizeof(cb.vel));
            assert_memory_equal(&gotf[0], &cfa.vel, sizeof(cfa.vel));
            assert_memory_equal(&gotf[2], &cfb.vel, sizeof(cfb.vel));
        }
    }
}

/* The simplest case: a ball hits a wall at rest given as (-0, -0) at 45
 * degrees, in every entry point. */
static void test_wall_at_rest_negative_zero(void **state)
{
    c2d_body a = {{0, 0}, {1, 0}, 1}, b = {{1, 1}, {-0.0, -0.0}, INFINITY};
    c2d_bodyf af = {{0, 0}, {1, 0}, 1}, bf = {{1, 1}, {-0.0f, -0.0f}, INFINITY};
    c2d_vec2 n = {1, 1};
    c2d_vec2f nf = {1, 1};
    (void)state;
    assert_status(c2d_collide(&a, &b, 1), C2D_OK);
    assert_true(signbit(b.vel.x) && signbit(b.vel.y) && b.vel.x == 0 && b.vel.y == 0);
    assert_true(a.vel.x == 0 && a.vel.y == -1);
    a.vel.x = 1, a.vel.y = 0;
    assert_status(c2d_collide_normal(&a, &b, n, 1), C2D_OK);
    assert_true(signbit(b.vel.x) && signbit(b.vel.y));
    assert_status(c2d_collidef(&af, &bf, 1), C2D_OK);
    assert_true(signbit(bf.vel.x) && signbit(bf.vel.y) && bf.vel.x == 0 && bf.vel.y == 0);
    af.vel.x = 1, af.vel.y = 0;
    assert_status(c2d_collide_normalf(&af, &bf, nf, 1), C2D_OK);
    assert_true(signbit(bf.vel.x) && signbit(bf.vel.y));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_wall_at_rest_negative_zero),
        cmocka_unit_test(test_double),
        cmocka_unit_test(test_float),
        cmocka_unit_test(test_batch),
    };
    return c2d_run_tests("signed_zero", tests);
}
