/* SPDX-License-Identifier: MIT */
#include "referee.h"

#include <math.h>
#include <mpfr.h>
#include <stdint.h>
#include <string.h>

void ref_answer_init(ref_answer *r)
{
    int i;
    for (i = 0; i < 4; i++) mpq_init(r->v[i]);
    r->status = C2D_INVALID;
    r->range_allowed = r->range_required = 0;
}

void ref_answer_clear(ref_answer *r)
{
    int i;
    for (i = 0; i < 4; i++) mpq_clear(r->v[i]);
}

static int finite_all(const double *x, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

static int mpq_cmp_abs_d(const mpq_t q, double limit)
{
    mpq_t a, l;
    int c;
    mpq_inits(a, l, NULL);
    mpq_abs(a, q);
    mpq_set_d(l, limit);
    c = mpq_cmp(a, l);
    mpq_clears(a, l, NULL);
    return c;
}

void ref_collide(const ref_case *c, double range_limit, ref_answer *out)
{
    mpq_t n[2], d, nn, t, w[2], lam, dv, e1;
    double vals[8] = {c->pa[0], c->pa[1], c->pb[0], c->pb[1], c->va[0], c->va[1], c->vb[0], c->vb[1]};
    int i, j;
    out->range_allowed = out->range_required = 0;
    if (!finite_all(vals, 8) || !(c->ma > 0) || !(c->mb > 0) || !(c->e >= 0 && c->e <= 1) ||
        (c->has_normal && !finite_all(c->n, 2))) {
        out->status = C2D_INVALID;
        return;
    }
    if (isinf(c->ma) && isinf(c->mb)) {
        out->status = C2D_DEGENERATE;
        return;
    }
    mpq_inits(n[0], n[1], d, nn, t, w[0], w[1], lam, dv, e1, NULL);
    for (i = 0; i < 2; i++) {
        if (c->has_normal) {
            mpq_set_d(n[i], c->n[i]);
        } else {
            mpq_set_d(n[i], c->pb[i]);
            mpq_set_d(t, c->pa[i]);
            mpq_sub(n[i], n[i], t);
        }
    }
    if (mpq_sgn(n[0]) == 0 && mpq_sgn(n[1]) == 0) {
        out->status = C2D_DEGENERATE;
        goto done;
    }
    mpq_set_ui(d, 0, 1);
    for (i = 0; i < 2; i++) {
        mpq_set_d(t, c->vb[i]);
        mpq_set_d(dv, c->va[i]);
        mpq_sub(t, t, dv);
        mpq_mul(t, t, n[i]);
        mpq_add(d, d, t);
        mpq_mul(t, n[i], n[i]);
        mpq_add(nn, nn, t);
    }
    if (mpq_sgn(d) >= 0) {
        out->status = C2D_SEPARATING;
        goto done;
    }
    if (isinf(c->ma)) {
        mpq_set_ui(w[0], 0, 1);
        mpq_set_ui(w[1], 1, 1);
    } else if (isinf(c->mb)) {
        mpq_set_ui(w[0], 1, 1);
        mpq_set_ui(w[1], 0, 1);
    } else {
        mpq_set_d(t, c->ma);
        mpq_set_d(dv, c->mb);
        mpq_add(lam, t, dv);
        mpq_div(w[0], dv, lam);
        mpq_div(w[1], t, lam);
    }
    mpq_set_d(e1, c->e);
    mpq_set_ui(t, 1, 1);
    mpq_add(e1, e1, t);
    for (j = 0; j < 2; j++) {
        const double *v = j == 0 ? c->va : c->vb;
        mpq_mul(lam, e1, w[j]);
        mpq_mul(lam, lam, d);
        mpq_div(lam, lam, nn);
        if (j == 1) mpq_neg(lam, lam);
        for (i = 0; i < 2; i++) {
            mpq_mul(dv, lam, n[i]);
            mpq_set_d(out->v[2 * j + i], v[i]);
            mpq_add(out->v[2 * j + i], out->v[2 * j + i], dv);
            if (mpq_cmp_abs_d(dv, range_limit / 8) >= 0 || mpq_cmp_abs_d(out->v[2 * j + i], range_limit / 8) >= 0)
                out->range_allowed = 1;
            if (mpq_cmp_abs_d(out->v[2 * j + i], range_limit) > 0) out->range_required = 1;
        }
    }
    out->status = C2D_OK;
done:
    mpq_clears(n[0], n[1], d, nn, t, w[0], w[1], lam, dv, e1, NULL);
}

double ref_ulp(double s, int prec, int emin)
{
    int ex;
    if (!(s > 0) || s < ldexp(1.0, emin)) return ldexp(1.0, emin - prec + 1);
    (void)frexp(s, &ex); /* s = f * 2^ex, f in [0.5, 1) */
    return ldexp(1.0, ex - 1 - (prec - 1));
}

double ref_err_ulp(double got, const mpq_t exact, double ulp)
{
    mpq_t g, u;
    double r;
    if (!isfinite(got)) return INFINITY;
    mpq_inits(g, u, NULL);
    mpq_set_d(g, got);
    mpq_sub(g, g, exact);
    mpq_abs(g, g);
    mpq_set_d(u, ulp);
    mpq_div(g, g, u);
    r = mpq_get_d(g);
    mpq_clears(g, u, NULL);
    return r;
}

static double body_scale(const double *v_before, const mpq_t *exact_after)
{
    double s = fmax(fabs(v_before[0]), fabs(v_before[1]));
    int i;
    for (i = 0; i < 2; i++) {
        double a = fabs(mpq_get_d(exact_after[i]));
        if (a > s) s = a;
    }
    return s;
}

double ref_collide_err(const ref_case *c, const ref_answer *r, const double got[4], int prec, int emin)
{
    double worst = 0;
    int j, i;
    for (j = 0; j < 2; j++) {
        const double *v = j == 0 ? c->va : c->vb;
        double ulp = ref_ulp(body_scale(v, &r->v[2 * j]), prec, emin);
        for (i = 0; i < 2; i++) {
            double e = ref_err_ulp(got[2 * j + i], r->v[2 * j + i], ulp);
            if (!(e <= worst)) worst = e;
        }
    }
    return worst;
}

c2d_status ref_time_of_impact(const ref_case *c, double radius_sum, double *t, double *unit, int prec, int emin)
{
    mpq_t d[2], v[2], a, b, cc, tmp, disc;
    mpfr_t fa, fb, fc, fd, ft;
    double vals[8] = {c->pa[0], c->pa[1], c->pb[0], c->pb[1], c->va[0], c->va[1], c->vb[0], c->vb[1]};
    c2d_status st;
    int i;
    if (!finite_all(vals, 8) || !(radius_sum >= 0) || isinf(radius_sum)) return C2D_INVALID;
    mpq_inits(d[0], d[1], v[0], v[1], a, b, cc, tmp, disc, NULL);
    mpfr_inits2(256, fa, fb, fc, fd, ft, (mpfr_ptr)0);
    for (i = 0; i < 2; i++) {
        mpq_set_d(d[i], c->pb[i]);
        mpq_set_d(tmp, c->pa[i]);
        mpq_sub(d[i], d[i], tmp);
        mpq_set_d(v[i], c->vb[i]);
        mpq_set_d(tmp, c->va[i]);
        mpq_sub(v[i], v[i], tmp);
        mpq_mul(tmp, v[i], v[i]);
        mpq_add(a, a, tmp);
        mpq_mul(tmp, d[i], v[i]);
        mpq_add(b, b, tmp);
        mpq_mul(tmp, d[i], d[i]);
        mpq_add(cc, cc, tmp);
    }
    mpq_set_d(tmp, radius_sum);
    mpq_mul(tmp, tmp, tmp);
    mpq_sub(cc, cc, tmp); /* c = d.d - R^2 */
    /* unit = ulp(t) + ulp(|d|) / closing speed, closing speed = -b / |d| */
    mpq_add(tmp, cc, tmp);
    mpfr_set_q(fd, tmp, MPFR_RNDN);
    mpfr_sqrt(fd, fd, MPFR_RNDN); /* |d| */
    if (mpq_sgn(a) == 0) {
        st = C2D_SEPARATING;
    } else if (mpq_sgn(cc) <= 0) {
        st = mpq_sgn(b) < 0 ? C2D_OK : C2D_SEPARATING;
        if (st == C2D_OK) {
            *t = 0;
            *unit = ref_ulp(0, prec, emin);
        }
    } else if (mpq_sgn(b) >= 0) {
        st = C2D_SEPARATING;
    } else {
        mpq_mul(disc, b, b);
        mpq_mul(tmp, a, cc);
        mpq_sub(disc, disc, tmp);
        if (mpq_sgn(disc) <= 0) { /* misses, or grazes with no approach speed */
            st = C2D_SEPARATING;
        } else {
            mpfr_set_q(fa, disc, MPFR_RNDN);
            mpfr_sqrt(fa, fa, MPFR_RNDN);
            mpfr_set_q(fb, b, MPFR_RNDN);
            mpfr_sub(fa, fa, fb, MPFR_RNDN); /* sqrt(disc) - b, both positive */
            mpfr_set_q(fc, cc, MPFR_RNDN);
            mpfr_div(ft, fc, fa, MPFR_RNDN);
            *t = mpfr_get_d(ft, MPFR_RNDN);
            st = C2D_OK;
            /* Approach speed at contact: (d + v t).v / R = -sqrt(b^2 - ac) / R.
             * One rounding of |d| moves the contact time by ulp(|d|) / that. */
            mpfr_set_q(fb, disc, MPFR_RNDN);
            mpfr_sqrt(fb, fb, MPFR_RNDN);
            mpfr_div_d(fb, fb, radius_sum, MPFR_RNDN);
            {
                double dist = mpfr_get_d(fd, MPFR_RNDN);
                double close = mpfr_get_d(fb, MPFR_RNDN);
                *unit = ref_ulp(fabs(*t), prec, emin) + ref_ulp(dist, prec, emin) / close;
            }
        }
    }
    mpq_clears(d[0], d[1], v[0], v[1], a, b, cc, tmp, disc, NULL);
    mpfr_clears(fa, fb, fc, fd, ft, (mpfr_ptr)0);
    return st;
}

void ref_conservation(const ref_case *c, const double got[4], double *momentum_rel, double *energy_rel)
{
    mpq_t pb, pa, eb, ea, m, v, t, scale;
    int i, j;
    double mass[2] = {c->ma, c->mb};
    const double *vin[2] = {c->va, c->vb};
    mpq_inits(pb, pa, eb, ea, m, v, t, scale, NULL);
    *momentum_rel = *energy_rel = 0;
    for (i = 0; i < 2; i++) { /* per momentum component */
        mpq_set_ui(pb, 0, 1);
        mpq_set_ui(pa, 0, 1);
        mpq_set_ui(scale, 0, 1);
        for (j = 0; j < 2; j++) {
            if (isinf(mass[j])) continue;
            mpq_set_d(m, mass[j]);
            mpq_set_d(v, vin[j][i]);
            mpq_mul(t, m, v);
            mpq_add(pb, pb, t);
            mpq_abs(t, t);
            mpq_add(scale, scale, t);
            mpq_set_d(v, got[2 * j + i]);
            mpq_mul(t, m, v);
            mpq_add(pa, pa, t);
        }
        if (isinf(c->ma) || isinf(c->mb)) continue; /* a wall absorbs momentum */
        mpq_sub(t, pa, pb);
        mpq_abs(t, t);
        if (mpq_sgn(scale) > 0) {
            mpq_div(t, t, scale);
            if (mpq_get_d(t) > *momentum_rel) *momentum_rel = mpq_get_d(t);
        }
    }
    mpq_set_ui(eb, 0, 1);
    mpq_set_ui(ea, 0, 1);
    for (j = 0; j < 2; j++) {
        if (isinf(mass[j])) continue;
        mpq_set_d(m, mass[j]);
        for (i = 0; i < 2; i++) {
            mpq_set_d(v, vin[j][i]);
            mpq_mul(t, v, v);
            mpq_mul(t, t, m);
            mpq_add(eb, eb, t);
            mpq_set_d(v, got[2 * j + i]);
            mpq_mul(t, v, v);
            mpq_mul(t, t, m);
            mpq_add(ea, ea, t);
        }
    }
    if (mpq_sgn(eb) > 0) {
        mpq_sub(t, ea, eb); /* signed: > 0 means energy gained */
        mpq_div(t, t, eb);
        *energy_rel = mpq_get_d(t);
    }
    mpq_clears(pb, pa, eb, ea, m, v, t, scale, NULL);
}

/* out = |n - exact| for got's neighbour n towards dir in the format; past
 * the largest finite value n is the power of two just beyond it (2^1024,
 * 2^128), where IEEE rounding puts the next value. */
static void ref_neighbour_distance(mpq_t out, double got, double dir, const mpq_t exact, int is_float)
{
    double n = is_float ? (double)nextafterf((float)got, (float)dir) : nextafter(got, dir);
    if (isinf(n)) {
        mpz_t p;
        mpz_init(p);
        mpz_ui_pow_ui(p, 2, is_float ? 128 : 1024);
        mpq_set_z(out, p);
        if (dir < 0) mpq_neg(out, out);
        mpz_clear(p);
    } else {
        mpq_set_d(out, n);
    }
    mpq_sub(out, out, exact);
    mpq_abs(out, out);
}

int ref_correctly_rounded(double got, const mpq_t exact, int is_float)
{
    mpq_t dg, du, dd;
    int ok, tie, even;
    uint64_t u;
    if (!isfinite(got)) return 0;
    mpq_inits(dg, du, dd, NULL);
    mpq_set_d(dg, got);
    mpq_sub(dg, dg, exact);
    mpq_abs(dg, dg);
    ref_neighbour_distance(du, got, INFINITY, exact, is_float);
    ref_neighbour_distance(dd, got, -INFINITY, exact, is_float);
    tie = mpq_cmp(dg, du) == 0 || mpq_cmp(dg, dd) == 0;
    if (is_float) {
        float f = (float)got;
        uint32_t w;
        memcpy(&w, &f, sizeof w);
        u = w;
    } else {
        memcpy(&u, &got, sizeof u);
    }
    even = (u & 1u) == 0;
    ok = mpq_cmp(dg, du) <= 0 && mpq_cmp(dg, dd) <= 0 && (!tie || even);
    mpq_clears(dg, du, dd, NULL);
    return ok;
}
