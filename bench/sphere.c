/* SPDX-License-Identifier: MIT */
/* sphere.c - pool balls as spheres (c2d_collide_balls, lib/real/sphere.h):
 * the library against the same equations transcribed plainly in double
 * (sphere_plain below: libm's exp, one rounding per operation, no exact
 * products), on the unit test's pool pairs (referee/cases_sphere.c).
 *
 *   sphere accuracy N      worst and median error of both in ulp of the
 *                          pair's scale against the MPFR referee
 *   sphere lib|plain N     resolve N pairs (constant mu and Alciatore's
 *                          mu(v), half each) for instruction counts:
 *                          make bench-sphere runs both under callgrind with
 *                          --toggle-collect on the call and prints Ir/call.
 *   sphere libf N          the same pairs rounded to float, c2d_collide_ballsf
 *   sphere cushion|cushionf N   N rail impacts (gen_cushion), either format
 *
 * Measured (x86-64, gcc 12.2 -O2, 2026-12-03, N = 100,000; docs/API.md):
 * accuracy worst 4.87 ulp (library) and 6.31 (plain), median 0.40 both;
 * 688 instructions per call against 248: 2.77x (float 1,307; the cushion
 * 424, float 937).  Printed, not asserted. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cases_sphere.h"

/* The model of lib/real/sphere.h in plain double. */
__attribute__((noinline)) static c2d_status sphere_plain(c2d_ball *a, c2d_ball *b, c2d_ball_surface s)
{
    const double dx = b->pos.x - a->pos.x, dy = b->pos.y - a->pos.y, len = sqrt(dx * dx + dy * dy);
    const double nx = dx / len, ny = dy / len;
    const double dvx = b->vel.x - a->vel.x, dvy = b->vel.y - a->vel.y;
    const double gn = dvx * nx + dvy * ny;
    const double gt = (dvy * nx - dvx * ny) - (a->radius * a->spin[2] + b->radius * b->spin[2]);
    const double gz = -(a->radius * (a->spin[0] * ny - a->spin[1] * nx) + b->radius * (b->spin[0] * ny - b->spin[1] * nx));
    const double g = sqrt(gt * gt + gz * gz), ima = 1 / a->mass, imb = 1 / b->mass;
    const double qa = a->radius / a->inertia, qb = b->radius / b->inertia;
    const double imn = ima + imb, imt = imn + a->radius * qa + b->radius * qb;
    const double jn = -(1 + s.restitution) * gn / imn;
    double mu, lam, f, jt, jz;
    if (gn >= 0) return C2D_SEPARATING;
    mu = s.friction + s.friction_boost * exp(-s.friction_decay * g);
    lam = fmin(mu * jn, g / imt);
    f = g > 0 ? lam / g : 0;
    jt = -f * gt, jz = -f * gz;
    a->vel.x -= (jn * nx - jt * ny) * ima;
    a->vel.y -= (jn * ny + jt * nx) * ima;
    b->vel.x += (jn * nx - jt * ny) * imb;
    b->vel.y += (jn * ny + jt * nx) * imb;
    a->spin[0] -= qa * jz * ny, a->spin[1] += qa * jz * nx, a->spin[2] -= qa * jt;
    b->spin[0] -= qb * jz * ny, b->spin[1] += qb * jz * nx, b->spin[2] -= qb * jt;
    return C2D_OK;
}

typedef struct pair { c2d_ball a, b; c2d_ball_surface s; } pair;

static void make_pairs(pair *p, int n)
{
    c2d_rng r;
    int i;
    r.s = 81;
    for (i = 0; i < n; i++) {
        ref_balls_case c;
        gen_pool_balls(&r, &c);
        ball_of(&p[i].a, &c.a), ball_of(&p[i].b, &c.b);
        p[i].s = ball_surface_of(&c);
    }
}

/* The float variant on the same pairs (rounded to float, ref_to_float) and
 * the cushion (gen_cushion's rails) in both formats: printed, no plain
 * counterpart (issue 21's target is for c2d_collide_balls). */
typedef struct pairf { c2d_ballf a, b; c2d_ball_surfacef s; } pairf;
typedef struct rail { c2d_ball a; c2d_cushion c; } rail;
typedef struct railf { c2d_ballf a; c2d_cushionf c; } railf;

static unsigned resolve_float(int n)
{
    pairf *p = malloc((size_t)n * sizeof *p);
    unsigned ok = 0;
    c2d_rng r;
    int i;
    if (p == NULL) return 0;
    r.s = 81;
    for (i = 0; i < n; i++) {
        ref_balls_case c;
        gen_pool_balls(&r, &c);
        balls_case_to_float(&c);
        ballf_of(&p[i].a, &c.a), ballf_of(&p[i].b, &c.b);
        p[i].s.restitution = (float)c.e, p[i].s.friction = (float)c.mu;
        p[i].s.friction_boost = (float)c.boost, p[i].s.friction_decay = (float)c.decay;
    }
    for (i = 0; i < n; i++) {
        c2d_ballf a = p[i].a, b = p[i].b;
        ok += c2d_collide_ballsf(&a, &b, p[i].s) == C2D_OK;
    }
    free(p);
    return ok;
}

static unsigned resolve_cushion(int n, int single)
{
    rail *p = single ? NULL : malloc((size_t)n * sizeof *p);
    railf *q = single ? malloc((size_t)n * sizeof *q) : NULL;
    unsigned ok = 0;
    c2d_rng r;
    int i;
    if (p == NULL && q == NULL) return 0;
    r.s = 83;
    for (i = 0; i < n; i++) {
        ref_cushion_case c;
        gen_cushion(&r, &c);
        if (single) {
            cushion_case_to_float(&c);
            ballf_of(&q[i].a, &c.a);
            q[i].c.normal.x = (float)c.n[0], q[i].c.normal.y = (float)c.n[1], q[i].c.height = (float)c.h;
            q[i].c.restitution = (float)c.e, q[i].c.friction = (float)c.mu;
        } else {
            ball_of(&p[i].a, &c.a);
            p[i].c = cushion_of(&c);
        }
    }
    for (i = 0; i < n; i++) {
        if (single) {
            c2d_ballf a = q[i].a;
            ok += c2d_collide_cushionf(&a, q[i].c) == C2D_OK;
        } else {
            c2d_ball a = p[i].a;
            ok += c2d_collide_cushion(&a, p[i].c) == C2D_OK;
        }
    }
    free(p), free(q);
    return ok;
}

typedef c2d_status (*resolver)(c2d_ball *, c2d_ball *, c2d_ball_surface);

/* Each pair from a fresh copy so every call is an impact; callgrind counts
 * inside the resolver only (--toggle-collect=c2d_collide_balls or
 * sphere_plain, called through the pointer so it is not inlined). */
static unsigned resolve_all(const pair *p, int n, resolver fn)
{
    unsigned ok = 0;
    int i;
    for (i = 0; i < n; i++) {
        c2d_ball a = p[i].a, b = p[i].b;
        ok += fn(&a, &b, p[i].s) == C2D_OK;
    }
    return ok;
}

static int cmp(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

static void out_of(double *o, const c2d_ball *d)
{
    o[0] = d->vel.x, o[1] = d->vel.y, o[2] = d->spin[0], o[3] = d->spin[1], o[4] = d->spin[2];
}

static void accuracy(int n)
{
    double *e[2];
    int k, i;
    c2d_rng r;
    e[0] = malloc((size_t)n * sizeof(double)), e[1] = malloc((size_t)n * sizeof(double));
    r.s = 82;
    for (i = 0; i < n; i++) {
        ref_balls_case c;
        c2d_ball a, b;
        double got[10];
        ref_sphere_verdict v;
        gen_pool_balls(&r, &c);
        balls_call(&c, got);
        ref_balls(&c, got, 53, -1022, DBL_MAX, &v);
        e[0][i] = v.err_ulp;
        ball_of(&a, &c.a), ball_of(&b, &c.b);
        sphere_plain(&a, &b, ball_surface_of(&c));
        out_of(got, &a), out_of(got + 5, &b);
        ref_balls(&c, got, 53, -1022, DBL_MAX, &v);
        e[1][i] = v.err_ulp;
    }
    for (k = 0; k < 2; k++) {
        qsort(e[k], (size_t)n, sizeof(double), cmp);
        printf("%-6s pool pairs: worst %.2f ulp, median %.2f ulp of the pair's scale (%d pairs)\n",
               k ? "plain" : "lib", e[k][n - 1], e[k][n / 2], n);
        free(e[k]);
    }
}

int main(int argc, char **argv)
{
    int n;
    pair *p;
    unsigned ok;
    if (argc != 3 || (n = atoi(argv[2])) <= 0 ||
        (strcmp(argv[1], "lib") && strcmp(argv[1], "plain") && strcmp(argv[1], "accuracy") &&
         strcmp(argv[1], "libf") && strcmp(argv[1], "cushion") && strcmp(argv[1], "cushionf"))) {
        fprintf(stderr, "usage: sphere accuracy|lib|plain|libf|cushion|cushionf N (N > 0)\n");
        return 2;
    }
    if (!strcmp(argv[1], "accuracy")) {
        accuracy(n);
        return 0;
    }
    if (!strcmp(argv[1], "libf") || !strcmp(argv[1], "cushion") || !strcmp(argv[1], "cushionf")) {
        ok = !strcmp(argv[1], "libf") ? resolve_float(n) : resolve_cushion(n, !strcmp(argv[1], "cushionf"));
        printf("%s: %u of %d impacts\n", argv[1], ok, n);
        return ok > 0 ? 0 : 1;
    }
    p = malloc((size_t)n * sizeof *p);
    if (p == NULL) return 1;
    make_pairs(p, n);
    ok = resolve_all(p, n, !strcmp(argv[1], "lib") ? c2d_collide_balls : sphere_plain);
    printf("%s: %u of %d impacts\n", argv[1], ok, n);
    free(p);
    return ok == (unsigned)n ? 0 : 1;
}
