/* The shared vector table (tests/vectors/vectors.c, also run on emulated MCUs):
 * every entry's status, outputs within its tolerance, and bodies untouched
 * on refusal.  `make test` also regenerates the table from the exact
 * referee and requires it to be unchanged. */
#include "check.h"
#include "vectors.h"

#define CHECK_VECTOR(V, BODY, VEC, COLLIDE, COLLIDE_NORMAL, TOI, REAL)                                 \
    do {                                                                                               \
        BODY a, b, a0, b0;                                                                             \
        c2d_status s;                                                                                  \
        REAL got[4] = {0, 0, 0, 0};                                                                    \
        int k;                                                                                         \
        a.pos.x = V->pa[0], a.pos.y = V->pa[1], a.vel.x = V->va[0], a.vel.y = V->va[1], a.mass = V->ma; \
        b.pos.x = V->pb[0], b.pos.y = V->pb[1], b.vel.x = V->vb[0], b.vel.y = V->vb[1], b.mass = V->mb; \
        a0 = a, b0 = b;                                                                                \
        if (V->kind == VEC_TOI) {                                                                      \
            s = TOI(&a, &b, V->e, &got[0]);                                                            \
        } else {                                                                                       \
            VEC n;                                                                                     \
            n.x = V->n[0], n.y = V->n[1];                                                              \
            s = V->kind == VEC_COLLIDE ? COLLIDE(&a, &b, V->e) : COLLIDE_NORMAL(&a, &b, n, V->e);      \
            got[0] = a.vel.x, got[1] = a.vel.y, got[2] = b.vel.x, got[3] = b.vel.y;                    \
        }                                                                                              \
        if (s != (c2d_status)V->status) print_error("vector %s\n", V->name);                           \
        assert_status(s, (c2d_status)V->status);                                                       \
        if (s != C2D_OK || V->kind == VEC_TOI) {                                                       \
            assert_bits_equal(a, a0);                                                                  \
            assert_bits_equal(b, b0);                                                                  \
        }                                                                                              \
        if (s == C2D_OK)                                                                               \
            for (k = 0; k < 4; k++) {                                                                  \
                if (!(fabs((double)got[k] - (double)V->out[k]) <= (double)V->tol[k]))                 \
                    print_error("vector %s output %d\n", V->name, k);                                  \
                assert_close((double)got[k], (double)V->out[k], (double)V->tol[k]);                    \
            }                                                                                          \
    } while (0)

static void test_double_vectors_pass(void **state)
{
    int i;
    (void)state;
    assert_true(c2d_vector_count_d > 30);
    for (i = 0; i < c2d_vector_count_d; i++) {
        const c2d_vector_d *v = &c2d_vectors_d[i];
        CHECK_VECTOR(v, c2d_body, c2d_vec2, c2d_collide, c2d_collide_normal, c2d_time_of_impact, double);
    }
}

static void test_float_vectors_pass(void **state)
{
    int i;
    (void)state;
    assert_true(c2d_vector_count_f > 20);
    for (i = 0; i < c2d_vector_count_f; i++) {
        const c2d_vector_f *v = &c2d_vectors_f[i];
        CHECK_VECTOR(v, c2d_bodyf, c2d_vec2f, c2d_collidef, c2d_collide_normalf, c2d_time_of_impactf, float);
    }
}

static void test_fixed_vectors_pass(void **state)
{
    int i;
    (void)state;
    assert_true(c2d_vector_count_x > 20);
    for (i = 0; i < c2d_vector_count_x; i++) {
        const c2d_vector_x *v = &c2d_vectors_x[i];
        CHECK_VECTOR(v, c2d_bodyx, c2d_vec2x, c2d_collidex, c2d_collide_normalx, c2d_time_of_impactx, c2d_fixed);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_double_vectors_pass),
        cmocka_unit_test(test_float_vectors_pass),
        cmocka_unit_test(test_fixed_vectors_pass),
    };
    return cmocka_run_group_tests_name("vectors", tests, NULL, NULL);
}
