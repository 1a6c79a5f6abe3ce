/* SPDX-License-Identifier: MIT */
/* real/toia/problem.h - template, accelerated time of impact: the problem
 * (exact differences d0, v, a on common scales, the radius) and the exact
 * signs at t = 0, degree-2 polynomials in the inputs.  See
 * real/toia/README.md. */
#ifndef C2D_REAL_TOIA_PROBLEM_H
#define C2D_REAL_TOIA_PROBLEM_H
/* ===================================================================== */
/* The problem                                                           */
/* ===================================================================== */

/* Form vector k's exact parts (c2d_toia_part) in c->parts. */
C2D_COLD void c2d_toia_parts_fill(const c2d_toia_ctx *c, int k)
{
    c2d_toia_parts *p = c->parts;
    int ax;
    for (ax = 0; ax < 2; ax++) {
        if (k == 0) {
            c2d_exact_diff(ax == 0 ? c->body_b->pos.x : c->body_b->pos.y, ax == 0 ? c->body_a->pos.x : c->body_a->pos.y,
                           &p->x[k][ax][0], &p->x[k][ax][1]);
        } else if (k == 1) {
            c2d_exact_diff(ax == 0 ? c->body_b->vel.x : c->body_b->vel.y, ax == 0 ? c->body_a->vel.x : c->body_a->vel.y,
                           &p->x[k][ax][0], &p->x[k][ax][1]);
        } else {
            c2d_exact_diff(ax == 0 ? c->acc_b->x : c->acc_b->y, ax == 0 ? c->acc_a->x : c->acc_a->y, &p->x[k][ax][0],
                           &p->x[k][ax][1]);
        }
    }
    p->ready |= 1U << (unsigned)k;
}

/* The exact part (hi: j = 0, lo: j = 1) of input difference k (0
 * position, 1 velocity, 2 acceleration) along axis i, as an extended number.
 * The exact sums ask for the same parts over and over (a touching pair's
 * exact retries: thousands of instructions recomputing them), so vector
 * k's four are formed on its first use and kept: the same numbers. */
static inline void c2d_toia_part(const c2d_toia_ctx *c, int k, int i, int j, c2d_ext *x)
{
    if ((c->parts->ready & (1U << (unsigned)k)) == 0U) c2d_toia_parts_fill(c, k);
    c2d_ext_copy(x, &c->parts->x[k][i][j]);
}

/* One vector's exact difference x1 - x0 (per axis hi + lo, halved first
 * when it could overflow) as hi/lo vectors on a common scale 2^exp[k]. */
static void c2d_toia_load_vec(c2d_toia_ctx *c, int k, c2d_real x1, c2d_real x0, c2d_real y1, c2d_real y0)
{
    const c2d_real big = c2d_pow2(C2D_R_EMAX - 1);
    c2d_real h[2], l[2];
    int sh = 0, i, top = 0, nz = 0;
    if (c2d_abs(x1) >= big || c2d_abs(x0) >= big || c2d_abs(y1) >= big || c2d_abs(y0) >= big) {
        x1 *= (c2d_real)0.5;
        x0 *= (c2d_real)0.5;
        y1 *= (c2d_real)0.5;
        y0 *= (c2d_real)0.5;
        sh = 1; /* (exact for the large operands; a subnormal small one's last bit is far below) */
    }
    h[0] = c2d_two_sum(x1, -x0, &l[0]);
    h[1] = c2d_two_sum(y1, -y0, &l[1]);
    for (i = 0; i < 2; i++) {
        if (h[i] != 0) {
            int e = c2d_ilogb(h[i]);
            if (nz == 0 || e > top) top = e;
            nz = 1;
        }
    }
    c->exp[k] = top + sh;
    c->nonzero[k] = nz;
    if (top >= -C2D_R_EMAX && top <= -C2D_R_EMIN) { /* 2^-top is a normal number: one exact multiply */
        c2d_real s = c2d_pow2(-top);
        for (i = 0; i < 2; i++) {
            c->hi[k][i] = h[i] * s;
            c->lo[k][i] = l[i] * s;
        }
    } else {
        for (i = 0; i < 2; i++) {
            c->hi[k][i] = c2d_scale2(h[i], -top);
            c->lo[k][i] = c2d_scale2(l[i], -top);
        }
    }
}

static void c2d_toia_load(c2d_toia_ctx *c, const c2d_real_body *a, const c2d_real_vec *aa, const c2d_real_body *b,
                          const c2d_real_vec *ab, c2d_real radius_sum, c2d_toia_parts *parts)
{
    c->parts = parts;
    parts->ready = 0U;
    c->body_a = a;
    c->body_b = b;
    c->acc_a = aa;
    c->acc_b = ab;
    c2d_toia_load_vec(c, 0, b->pos.x, a->pos.x, b->pos.y, a->pos.y);
    c2d_toia_load_vec(c, 1, b->vel.x, a->vel.x, b->vel.y, a->vel.y);
    c2d_toia_load_vec(c, 2, ab->x, aa->x, ab->y, aa->y);
    c2d_ext_set(&c->radius, radius_sum, 0);
}

/* ===================================================================== */
/* Exact signs at t = 0 (degree-2 polynomials in the inputs)             */
/* ===================================================================== */

/* Append the atoms of sgn * (x.y) for two input differences x = vector kx,
 * y = vector ky (exact: hi + lo per axis). */
static int c2d_toia_push_dot(const c2d_toia_ctx *c, c2d_real *m, int *e, int n, int kx, int ky, int sgn)
{
    int i, j, k;
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++)
            for (k = 0; k < 2; k++) {
                c2d_ext x, y;
                c2d_toia_part(c, kx, i, j, &x);
                c2d_toia_part(c, ky, i, k, &y);
                n = c2d_toia_push_product(m, e, n, &x, &y, 0, sgn);
            }
    return n;
}

/* Exact sign of f(0) = |d0|^2 - R^2 (which 0), g(0) = d0.v (1),
 * h(0) = |v|^2 + d0.a (2) or hp(0) / 3 = v.a (3). */
C2D_COLD int c2d_toia_exact_sign_at0(c2d_toia_ctx *c, int which)
{
    c2d_real m[C2D_TOIA_ATOMS], hi, lo;
    int e[C2D_TOIA_ATOMS], n = 0, k;
    if (which == C2D_TOIA_QF) {
        n = c2d_toia_push_dot(c, m, e, n, 0, 0, 1);
        n = c2d_toia_push_product(m, e, n, &c->radius, &c->radius, 0, -1);
    } else if (which == C2D_TOIA_QG) {
        n = c2d_toia_push_dot(c, m, e, n, 0, 1, 1);
    } else if (which == C2D_TOIA_QH) {
        n = c2d_toia_push_dot(c, m, e, n, 1, 1, 1);
        n = c2d_toia_push_dot(c, m, e, n, 0, 2, 1);
    } else {
        n = c2d_toia_push_dot(c, m, e, n, 1, 2, 1);
    }
    (void)c2d_toia_exact_sum(m, e, n, &hi, &lo, &k);
    return c2d_toia_sign_of(hi);
}
/* ===================================================================== */

#endif /* C2D_REAL_TOIA_PROBLEM_H */
