/* c2d_collide_batch(f): bit-identical to the scalar call, statuses
 * included, for mixed inputs (valid, grazing, extreme, invalid) and any
 * count, including counts that are not a multiple of the kernel's block. */
#include "check.h"

#define N 1003 /* not a multiple of 8 */

typedef struct soa {
    double ax[N], ay[N], bx[N], by[N], avx[N], avy[N], bvx[N], bvy[N], ma[N], mb[N];
} soa;

static void fill(soa *s, ref_case *cs, uint64_t seed)
{
    c2d_rng r;
    int i;
    r.s = seed;
    for (i = 0; i < N; i++) {
        ref_case *c = &cs[i];
        uint64_t k = c2d_rng_next(&r) % 10;
        if (k < 6) {
            gen_plain(&r, c);
        } else {
            gen_extreme(&r, c, 53, -1022, 1023);
        }
        if (k == 9) c->va[0] = NAN;
        if (k == 8) c->ma = -1;
        s->ax[i] = c->pa[0], s->ay[i] = c->pa[1], s->bx[i] = c->pb[0], s->by[i] = c->pb[1];
        s->avx[i] = c->va[0], s->avy[i] = c->va[1], s->bvx[i] = c->vb[0], s->bvy[i] = c->vb[1];
        s->ma[i] = c->ma, s->mb[i] = c->mb;
    }
}

static c2d_pairs view(soa *s)
{
    c2d_pairs p;
    p.pos_ax = s->ax, p.pos_ay = s->ay, p.pos_bx = s->bx, p.pos_by = s->by;
    p.vel_ax = s->avx, p.vel_ay = s->avy, p.vel_bx = s->bvx, p.vel_by = s->bvy;
    p.mass_a = s->ma, p.mass_b = s->mb;
    return p;
}

static void check_restitution(double e, uint64_t seed)
{
    static soa s;
    static ref_case cs[N];
    static c2d_status st[N];
    c2d_pairs p;
    size_t done, expect_done = 0;
    int i;
    fill(&s, cs, seed);
    p = view(&s);
    done = c2d_collide_batch(&p, N, e, st);
    for (i = 0; i < N; i++) {
        c2d_body a, b;
        c2d_status want;
        case_to_bodies(&cs[i], &a, &b);
        want = c2d_collide(&a, &b, e);
        assert_status(st[i], want);
        if (want == C2D_OK) expect_done++;
        /* untouched on refusal is included: a and b keep their inputs */
        assert_memory_equal(&s.avx[i], &a.vel.x, sizeof(double));
        assert_memory_equal(&s.avy[i], &a.vel.y, sizeof(double));
        assert_memory_equal(&s.bvx[i], &b.vel.x, sizeof(double));
        assert_memory_equal(&s.bvy[i], &b.vel.y, sizeof(double));
    }
    assert_int_equal(done, expect_done);
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
    static soa s, s0;
    static ref_case cs[N];
    static c2d_status st[N];
    c2d_pairs p;
    int i;
    (void)state;
    fill(&s, cs, 404);
    s0 = s;
    p = view(&s);
    assert_int_equal(c2d_collide_batch(&p, N, 1.5, st), 0);
    for (i = 0; i < N; i++) assert_status(st[i], C2D_INVALID);
    assert_memory_equal(&s, &s0, sizeof s);
    assert_int_equal(c2d_collide_batch(NULL, N, 1.0, st), 0);
}

static void test_batch_without_status_array_and_tiny_counts(void **state)
{
    static soa s;
    static ref_case cs[N];
    c2d_pairs p;
    size_t n;
    (void)state;
    fill(&s, cs, 405);
    p = view(&s);
    for (n = 0; n < 20; n++) (void)c2d_collide_batch(&p, n, 1.0, NULL);
    assert_int_equal(c2d_collide_batch(&p, 0, 1.0, NULL), 0);
}

static void test_float_batch_is_bit_identical_to_scalar_calls(void **state)
{
    static float ax[N], ay[N], bx[N], by[N], avx[N], avy[N], bvx[N], bvy[N], ma[N], mb[N];
    static ref_case cs[N];
    static c2d_status st[N];
    c2d_pairsf p;
    c2d_rng r = {406};
    int i;
    (void)state;
    for (i = 0; i < N; i++) {
        ref_case *c = &cs[i];
        if (c2d_rng_next(&r) % 4) gen_plain(&r, c); else gen_extreme(&r, c, 24, -126, 127);
        ax[i] = (float)c->pa[0], ay[i] = (float)c->pa[1], bx[i] = (float)c->pb[0], by[i] = (float)c->pb[1];
        avx[i] = (float)c->va[0], avy[i] = (float)c->va[1], bvx[i] = (float)c->vb[0], bvy[i] = (float)c->vb[1];
        ma[i] = (float)c->ma, mb[i] = (float)c->mb;
    }
    p.pos_ax = ax, p.pos_ay = ay, p.pos_bx = bx, p.pos_by = by;
    p.vel_ax = avx, p.vel_ay = avy, p.vel_bx = bvx, p.vel_by = bvy, p.mass_a = ma, p.mass_b = mb;
    (void)c2d_collide_batchf(&p, N, 0.9f, st);
    for (i = 0; i < N; i++) {
        c2d_bodyf a, b;
        case_to_bodiesf(&cs[i], &a, &b);
        assert_status(st[i], c2d_collidef(&a, &b, 0.9f));
        assert_memory_equal(&avx[i], &a.vel.x, sizeof(float));
        assert_memory_equal(&bvy[i], &b.vel.y, sizeof(float));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_batch_is_bit_identical_to_scalar_calls),
        cmocka_unit_test(test_batch_with_invalid_restitution_refuses_every_pair),
        cmocka_unit_test(test_batch_without_status_array_and_tiny_counts),
        cmocka_unit_test(test_float_batch_is_bit_identical_to_scalar_calls),
    };
    return cmocka_run_group_tests_name("batch", tests, NULL, NULL);
}
