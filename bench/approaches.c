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

c2d_status bench_noop(c2d_body *a, c2d_body *b, double restitution)
{
    (void)a;
    (void)b;
    (void)restitution;
    return C2D_OK;
}
