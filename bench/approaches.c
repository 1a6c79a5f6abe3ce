/* SPDX-License-Identifier: MIT */
#include "approaches.h"

#include <math.h>

c2d_status bench_seed_equal(c2d_body *a, c2d_body *b, double restitution)
{
    const double nx = b->pos.x - a->pos.x, ny = b->pos.y - a->pos.y;
    const double len = sqrt(nx * nx + ny * ny);
    const double unx = nx / len, uny = ny / len;
    const double utx = -ny / len, uty = nx / len;
    const double v1n = unx * a->vel.x + uny * a->vel.y;
    const double v1t = utx * a->vel.x + uty * a->vel.y;
    const double v2n = unx * b->vel.x + uny * b->vel.y;
    const double v2t = utx * b->vel.x + uty * b->vel.y;
    (void)restitution;
    a->vel.x = v2n * unx + v1t * utx;
    a->vel.y = v2n * uny + v1t * uty;
    b->vel.x = v1n * unx + v2t * utx;
    b->vel.y = v1n * uny + v2t * uty;
    return C2D_OK;
}

c2d_status bench_seed_masses(c2d_body *a, c2d_body *b, double restitution)
{
    const double nx = b->pos.x - a->pos.x, ny = b->pos.y - a->pos.y;
    const double len = sqrt(nx * nx + ny * ny);
    const double unx = nx / len, uny = ny / len;
    const double utx = -ny / len, uty = nx / len;
    const double m1 = a->mass, m2 = b->mass, e = restitution;
    const double v1n = unx * a->vel.x + uny * a->vel.y;
    const double v1t = utx * a->vel.x + uty * a->vel.y;
    const double v2n = unx * b->vel.x + uny * b->vel.y;
    const double v2t = utx * b->vel.x + uty * b->vel.y;
    const double v1nf = (v1n * (m1 - e * m2) + (1 + e) * m2 * v2n) / (m1 + m2);
    const double v2nf = (v2n * (m2 - e * m1) + (1 + e) * m1 * v1n) / (m1 + m2);
    a->vel.x = v1nf * unx + v1t * utx;
    a->vel.y = v1nf * uny + v1t * uty;
    b->vel.x = v2nf * unx + v2t * utx;
    b->vel.y = v2nf * uny + v2t * uty;
    return C2D_OK;
}

c2d_status bench_seed_summary(c2d_body *a, c2d_body *b, double restitution)
{
    const double dx = b->pos.x - a->pos.x, dy = b->pos.y - a->pos.y;
    const double den = dx * dx + dy * dy;
    const double v1x = a->vel.x, v1y = a->vel.y, v2x = b->vel.x, v2y = b->vel.y;
    (void)restitution;
    a->vel.x = ((v2x * (dx * dx) + v2y * (dx * dy)) + (-v1x * (dx * dy) + v1y * (dx * dx))) / den;
    a->vel.y = ((v2x * (dx * dy) + v2y * (dy * dy)) + (-v1x * (dy * dy) + v1y * (dx * dy))) / den;
    b->vel.x = ((v1x * (dx * dx) + v1y * (dx * dy)) + (-v2x * (dx * dy) + v2y * (dx * dx))) / den;
    b->vel.y = ((v1x * (dx * dy) + v1y * (dy * dy)) + (-v2x * (dy * dy) + v2y * (dx * dy))) / den;
    return C2D_OK;
}

c2d_status bench_trig(c2d_body *a, c2d_body *b, double restitution)
{
    const double phi = atan2(b->pos.y - a->pos.y, b->pos.x - a->pos.x);
    const double c = cos(phi), s = sin(phi);
    const double m1 = a->mass, m2 = b->mass, e = restitution;
    const double v1n = a->vel.x * c + a->vel.y * s, v1t = -a->vel.x * s + a->vel.y * c;
    const double v2n = b->vel.x * c + b->vel.y * s, v2t = -b->vel.x * s + b->vel.y * c;
    double v1nf, v2nf;
    if (v2n - v1n >= 0) return C2D_SEPARATING;
    v1nf = (v1n * (m1 - e * m2) + (1 + e) * m2 * v2n) / (m1 + m2);
    v2nf = (v2n * (m2 - e * m1) + (1 + e) * m1 * v1n) / (m1 + m2);
    a->vel.x = v1nf * c - v1t * s;
    a->vel.y = v1nf * s + v1t * c;
    b->vel.x = v2nf * c - v2t * s;
    b->vel.y = v2nf * s + v2t * c;
    return C2D_OK;
}

c2d_status bench_bare(c2d_body *a, c2d_body *b, double restitution)
{
    c2d_status s;
    BENCH_BARE(double, sqrt, a, b, restitution, s);
    return s;
}

c2d_status bench_baref(c2d_bodyf *a, c2d_bodyf *b, float restitution)
{
    c2d_status s;
    BENCH_BARE(float, sqrtf, a, b, restitution, s);
    return s;
}

c2d_status bench_noop(c2d_body *a, c2d_body *b, double restitution)
{
    (void)a;
    (void)b;
    (void)restitution;
    return C2D_OK;
}

/* ------------------------------------------ the speed goals' baselines */

c2d_status bench_seed_equalf(c2d_bodyf *a, c2d_bodyf *b, float restitution)
{
    const float nx = b->pos.x - a->pos.x, ny = b->pos.y - a->pos.y;
    const float len = sqrtf(nx * nx + ny * ny);
    const float unx = nx / len, uny = ny / len;
    const float utx = -ny / len, uty = nx / len;
    const float v1n = unx * a->vel.x + uny * a->vel.y;
    const float v1t = utx * a->vel.x + uty * a->vel.y;
    const float v2n = unx * b->vel.x + uny * b->vel.y;
    const float v2t = utx * b->vel.x + uty * b->vel.y;
    (void)restitution;
    a->vel.x = v2n * unx + v1t * utx;
    a->vel.y = v2n * uny + v1t * uty;
    b->vel.x = v1n * unx + v2t * utx;
    b->vel.y = v1n * uny + v2t * uty;
    return C2D_OK;
}

c2d_status bench_seed_equal_normal(c2d_body *a, c2d_body *b, double nx, double ny, double restitution)
{
    const double len = sqrt(nx * nx + ny * ny);
    const double unx = nx / len, uny = ny / len;
    const double utx = -ny / len, uty = nx / len;
    const double v1n = unx * a->vel.x + uny * a->vel.y;
    const double v1t = utx * a->vel.x + uty * a->vel.y;
    const double v2n = unx * b->vel.x + uny * b->vel.y;
    const double v2t = utx * b->vel.x + uty * b->vel.y;
    (void)restitution;
    a->vel.x = v2n * unx + v1t * utx;
    a->vel.y = v2n * uny + v1t * uty;
    b->vel.x = v1n * unx + v2t * utx;
    b->vel.y = v1n * uny + v2t * uty;
    return C2D_OK;
}

c2d_status bench_seed_equal_normalf(c2d_bodyf *a, c2d_bodyf *b, float nx, float ny, float restitution)
{
    const float len = sqrtf(nx * nx + ny * ny);
    const float unx = nx / len, uny = ny / len;
    const float utx = -ny / len, uty = nx / len;
    const float v1n = unx * a->vel.x + uny * a->vel.y;
    const float v1t = utx * a->vel.x + uty * a->vel.y;
    const float v2n = unx * b->vel.x + uny * b->vel.y;
    const float v2t = utx * b->vel.x + uty * b->vel.y;
    (void)restitution;
    a->vel.x = v2n * unx + v1t * utx;
    a->vel.y = v2n * uny + v1t * uty;
    b->vel.x = v1n * unx + v2t * utx;
    b->vel.y = v1n * uny + v2t * uty;
    return C2D_OK;
}

c2d_status bench_seed_equal_normal_v(c2d_body *a, c2d_body *b, c2d_vec2 normal, double restitution)
{
    const double nx = normal.x, ny = normal.y;
    const double len = sqrt(nx * nx + ny * ny);
    const double unx = nx / len, uny = ny / len;
    const double utx = -ny / len, uty = nx / len;
    const double v1n = unx * a->vel.x + uny * a->vel.y;
    const double v1t = utx * a->vel.x + uty * a->vel.y;
    const double v2n = unx * b->vel.x + uny * b->vel.y;
    const double v2t = utx * b->vel.x + uty * b->vel.y;
    (void)restitution;
    a->vel.x = v2n * unx + v1t * utx;
    a->vel.y = v2n * uny + v1t * uty;
    b->vel.x = v1n * unx + v2t * utx;
    b->vel.y = v1n * uny + v2t * uty;
    return C2D_OK;
}

c2d_status bench_toi_textbook(const c2d_body *a, const c2d_body *b, double radius_sum, double *t)
{
    const double dx = b->pos.x - a->pos.x, dy = b->pos.y - a->pos.y;
    const double vx = b->vel.x - a->vel.x, vy = b->vel.y - a->vel.y;
    const double qa = vx * vx + vy * vy, qb = dx * vx + dy * vy;
    const double qc = dx * dx + dy * dy - radius_sum * radius_sum;
    double disc;
    if (qb >= 0) return C2D_SEPARATING; /* not approaching (also no relative motion) */
    if (qc <= 0) {                      /* touching or overlapping, approaching */
        *t = 0;
        return C2D_OK;
    }
    disc = qb * qb - qa * qc;
    if (disc <= 0) return C2D_SEPARATING; /* passes by (or grazes) */
    *t = (-qb - sqrt(disc)) / qa;
    return C2D_OK;
}

c2d_status bench_toi_textbookf(const c2d_bodyf *a, const c2d_bodyf *b, float radius_sum, float *t)
{
    const float dx = b->pos.x - a->pos.x, dy = b->pos.y - a->pos.y;
    const float vx = b->vel.x - a->vel.x, vy = b->vel.y - a->vel.y;
    const float qa = vx * vx + vy * vy, qb = dx * vx + dy * vy;
    const float qc = dx * dx + dy * dy - radius_sum * radius_sum;
    float disc;
    if (qb >= 0) return C2D_SEPARATING;
    if (qc <= 0) {
        *t = 0;
        return C2D_OK;
    }
    disc = qb * qb - qa * qc;
    if (disc <= 0) return C2D_SEPARATING;
    *t = (-qb - sqrtf(disc)) / qa;
    return C2D_OK;
}

c2d_status bench_walton(c2d_disk *a, c2d_disk *b, c2d_surface s)
{
    const double nx = b->pos.x - a->pos.x, ny = b->pos.y - a->pos.y;
    const double len = sqrt(nx * nx + ny * ny);
    const double unx = nx / len, uny = ny / len, tx = -uny, ty = unx;
    const double gx = b->vel.x - a->vel.x, gy = b->vel.y - a->vel.y;
    const double gn = gx * unx + gy * uny;
    const double gt = gx * tx + gy * ty - (a->spin * a->radius + b->spin * b->radius);
    const double ima = 1 / a->mass, imb = 1 / b->mass; /* 0 for an immovable body */
    const double ka = a->radius * a->radius / a->inertia, kb = b->radius * b->radius / b->inertia;
    const double jn = -(1 + s.restitution) * gn / (ima + imb);
    double jt = -(1 + s.tangential_restitution) * gt / (ima + imb + ka + kb);
    double jx, jy;
    if (gn >= 0) return C2D_SEPARATING;
    if (fabs(jt) > s.friction * jn) jt = gt > 0 ? -s.friction * jn : s.friction * jn; /* sliding */
    jx = jn * unx + jt * tx;
    jy = jn * uny + jt * ty;
    a->vel.x -= jx * ima;
    a->vel.y -= jy * ima;
    b->vel.x += jx * imb;
    b->vel.y += jy * imb;
    a->spin -= a->radius * jt / a->inertia;
    b->spin -= b->radius * jt / b->inertia;
    return C2D_OK;
}
