/* SPDX-License-Identifier: MIT */
/* The time of impact under constant acceleration as a game programmer or
 * pooltool writes it, for the benchmark only (never shipped): form the
 * quartic |d(t)|^2 - R^2 = c4 t^4 + c3 t^3 + c2 t^2 + c1 t + c0 in double,
 * with d(t) = d0 + v t + a t^2 / 2 (relative position, velocity and
 * acceleration of b to a):
 *   c4 = |a|^2 / 4, c3 = v.a, c2 = |v|^2 + d0.a, c1 = 2 d0.v, c0 = |d0|^2 - R^2,
 * then
 *   bench_toia_ferrari: solve it in closed form (depressed quartic, the
 *     resolvent cubic 8m^3 + 8pm^2 + (2p^2 - 8r)m - q^2 = 0 by Cardano or the
 *     trigonometric form, two quadratics), with the usual epsilons for a
 *     vanishing leading coefficient and a biquadratic;
 *   bench_toia_sturm: isolate the real roots in [0, H] with a Sturm sequence
 *     (remainders in double, small ones dropped) and bisect each 100 times.
 * The contact is the first root in [0, H] where the quartic decreases, or
 * t = 0 when the disks overlap and approach.  Deliberately no care beyond
 * that: this is what the library's exact statuses are measured against. */
#include "approaches.h"

#include <math.h>

#define BENCH_PI 3.14159265358979323846

static void coeffs(const c2d_body *a, c2d_vec2 aa, const c2d_body *b, c2d_vec2 ab, double R, double *c)
{
    double px = b->pos.x - a->pos.x, py = b->pos.y - a->pos.y;
    double vx = b->vel.x - a->vel.x, vy = b->vel.y - a->vel.y;
    double ax = ab.x - aa.x, ay = ab.y - aa.y;
    c[0] = px * px + py * py - R * R;
    c[1] = 2 * (px * vx + py * vy);
    c[2] = vx * vx + vy * vy + px * ax + py * ay;
    c[3] = vx * ax + vy * ay;
    c[4] = 0.25 * (ax * ax + ay * ay);
}

static double peval(const double *c, int n, double t)
{
    double s = c[n];
    int i;
    for (i = n - 1; i >= 0; i--) s = s * t + c[i];
    return s;
}

static double dpeval(const double *c, int n, double t)
{
    double s = n * c[n];
    int i;
    for (i = n - 1; i >= 1; i--) s = s * t + i * c[i];
    return s;
}

/* the contact from the real roots of the quartic */
static c2d_status pick(const double *c, const double *roots, int n, double H, double *t)
{
    double best = INFINITY;
    int i;
    if (c[0] <= 0 && c[1] < 0) {
        *t = 0;
        return C2D_OK;
    }
    for (i = 0; i < n; i++) {
        double r = roots[i];
        if (r >= 0 && r <= H && dpeval(c, 4, r) < 0 && r < best) best = r;
    }
    if (best == INFINITY) return C2D_SEPARATING;
    *t = best;
    return C2D_OK;
}

/* ------------------------------------------------------------- Ferrari */

static int quadratic(double a, double b, double c, double *r)
{
    double disc, q;
    if (fabs(a) < 1e-12 * (fabs(b) + fabs(c))) {
        if (b == 0) return 0;
        r[0] = -c / b;
        return 1;
    }
    disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    q = -0.5 * (b + copysign(sqrt(disc), b));
    r[0] = q / a;
    r[1] = q != 0 ? c / q : r[0];
    return 2;
}

static int cubic(double a, double b, double c, double d, double *r)
{
    double A, B, C, Q, R, disc, th, s;
    if (fabs(a) < 1e-12 * (fabs(b) + fabs(c) + fabs(d))) return quadratic(b, c, d, r);
    A = b / a, B = c / a, C = d / a;
    Q = (A * A - 3 * B) / 9;
    R = (2 * A * A * A - 9 * A * B + 27 * C) / 54;
    disc = R * R - Q * Q * Q;
    if (disc < 0) {
        th = acos(R / sqrt(Q * Q * Q));
        s = -2 * sqrt(Q);
        r[0] = s * cos(th / 3) - A / 3;
        r[1] = s * cos((th + 2 * BENCH_PI) / 3) - A / 3;
        r[2] = s * cos((th - 2 * BENCH_PI) / 3) - A / 3;
        return 3;
    }
    s = -copysign(cbrt(fabs(R) + sqrt(disc)), R);
    r[0] = s + (s != 0 ? Q / s : 0) - A / 3;
    return 1;
}

static int quartic(const double *c, double *r)
{
    double a, b, cc, d, p, q, rr, m, y[3], s, a4;
    int n = 0, k, i;
    double scale = fabs(c[0]) + fabs(c[1]) + fabs(c[2]) + fabs(c[3]);
    if (fabs(c[4]) < 1e-12 * scale) return cubic(c[3], c[2], c[1], c[0], r);
    a = c[3] / c[4], b = c[2] / c[4], cc = c[1] / c[4], d = c[0] / c[4];
    a4 = a / 4;
    p = b - 3 * a * a / 8;
    q = cc - a * b / 2 + a * a * a / 8;
    rr = d - a * cc / 4 + a * a * b / 16 - 3 * a * a * a * a / 256;
    if (fabs(q) < 1e-12) { /* biquadratic */
        double z[2];
        k = quadratic(1, p, rr, z);
        for (i = 0; i < k; i++)
            if (z[i] >= 0) {
                r[n++] = sqrt(z[i]) - a4;
                r[n++] = -sqrt(z[i]) - a4;
            }
        return n;
    }
    /* resolvent cubic 8 m^3 + 8 p m^2 + (2 p^2 - 8 r) m - q^2 = 0: a root m > 0 */
    k = cubic(8, 8 * p, 2 * p * p - 8 * rr, -q * q, y);
    m = -INFINITY;
    for (i = 0; i < k; i++)
        if (y[i] > m) m = y[i];
    if (!(m > 0)) return 0;
    s = sqrt(2 * m);
    {
        double z[2];
        k = quadratic(1, s, p / 2 + m - q / (2 * s), z);
        for (i = 0; i < k; i++) r[n++] = z[i] - a4;
        k = quadratic(1, -s, p / 2 + m + q / (2 * s), z);
        for (i = 0; i < k; i++) r[n++] = z[i] - a4;
    }
    return n;
}

c2d_status bench_toia_ferrari(const c2d_body *a, c2d_vec2 aa, const c2d_body *b, c2d_vec2 ab, double R, double H, double *t)
{
    double c[5], r[4];
    int n;
    coeffs(a, aa, b, ab, R, c);
    n = quartic(c, r);
    return pick(c, r, n, H, t);
}

/* ------------------------------------------------------- Sturm + bisection */

typedef struct poly {
    int n;
    double c[5];
} poly;

static void prem(const poly *a, const poly *b, poly *r) /* r = -(a mod b) */
{
    double t[5];
    int i, k;
    for (i = 0; i <= a->n; i++) t[i] = a->c[i];
    for (k = a->n - b->n; k >= 0; k--) {
        double q = t[k + b->n] / b->c[b->n];
        for (i = 0; i <= b->n; i++) t[k + i] -= q * b->c[i];
    }
    r->n = b->n - 1;
    for (i = 0; i <= r->n; i++) r->c[i] = -t[i];
    while (r->n > 0 && fabs(r->c[r->n]) < 1e-14 * fabs(b->c[b->n])) r->n--;
    if (r->n == 0 && fabs(r->c[0]) < 1e-300) r->n = -1;
}

static int changes(const poly *s, int m, double x)
{
    int i, v = 0;
    double last = 0;
    for (i = 0; i < m; i++) {
        double y = isinf(x) ? (s[i].n < 0 ? 0 : copysign(1, s[i].c[s[i].n]) * (s[i].n % 2 == 0 || x > 0 ? 1 : -1))
                            : peval(s[i].c, s[i].n, x);
        if (y == 0) continue;
        if (last != 0 && (y > 0) != (last > 0)) v++;
        last = y;
    }
    return v;
}

c2d_status bench_toia_sturm(const c2d_body *a, c2d_vec2 aa, const c2d_body *b, c2d_vec2 ab, double R, double H, double *t)
{
    double c[5], roots[4], lo[8], hi[8], Hin = H;
    poly s[6];
    int m, i, n = 0, deg = 4, top = 0;
    coeffs(a, aa, b, ab, R, c);
    if (c[0] <= 0 && c[1] < 0) {
        *t = 0;
        return C2D_OK;
    }
    while (deg > 0 && fabs(c[deg]) < 1e-12 * (fabs(c[0]) + fabs(c[1]) + fabs(c[2]))) deg--;
    if (deg == 0) return C2D_SEPARATING;
    s[0].n = deg;
    for (i = 0; i <= deg; i++) s[0].c[i] = c[i];
    s[1].n = deg - 1;
    for (i = 1; i <= deg; i++) s[1].c[i - 1] = i * c[i];
    m = 2;
    while (m < 6 && s[m - 1].n > 0) {
        prem(&s[m - 2], &s[m - 1], &s[m]);
        if (s[m].n < 0) break;
        m++;
    }
    /* bracket [0, H] (H = inf: Cauchy bound) and bisect each root out */
    if (!(H < INFINITY)) {
        double bnd = 0;
        for (i = 0; i < deg; i++)
            if (fabs(c[i] / c[deg]) > bnd) bnd = fabs(c[i] / c[deg]);
        H = 1 + bnd;
    }
    lo[0] = 0;
    hi[0] = H;
    top = 1;
    while (top > 0 && n < 4) {
        double l = lo[--top], h = hi[top];
        int k = changes(s, m, l) - changes(s, m, h);
        if (k <= 0) continue;
        if (k == 1 || h - l < 1e-15 * h) {
            int it;
            double fl = peval(c, deg, l);
            for (it = 0; it < 100; it++) {
                double mid = 0.5 * (l + h), fm = peval(c, deg, mid);
                if ((fm > 0) == (fl > 0)) l = mid, fl = fm;
                else h = mid;
            }
            roots[n++] = 0.5 * (l + h);
            continue;
        }
        if (top < 7) {
            double mid = 0.5 * (l + h);
            lo[top] = mid, hi[top] = h, top++;
            lo[top] = l, hi[top] = mid, top++;
        }
    }
    return pick(c, roots, n, Hin, t);
}
