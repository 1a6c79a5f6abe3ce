/* SPDX-License-Identifier: MIT */
/* real/collide/collide.h - template: c2d_collide and c2d_collide_normal, the three
 * tiers chained.  Needs real/arith/bits.h, real/arith/exact.h, real/collide/fast.h and
 * real/collide/general.h first (and real/collide/axis.h after).
 *
 * THE TIERS
 *   1. The fast path (real/collide/fast.h): plain arithmetic, branch-free, when every
 *      intermediate is provably safe and d cancels by at most 4x.
 *   2. Tier 2: inputs valid and inside the window, but d cancels.  The
 *      normal is taken exactly (n = nh + nl, the TwoSum of the position
 *      difference) and d = (vb - va).n is recomputed as a double-double
 *      (c2d_dot2: exact differences, exact products), so its error is about
 *      one ulp of d plus u^2 of the terms.  Trusted when it kept
 *      C2D_R_EXP_KAPPA2 bits through the cancellation (k <= 2^KAPPA2 |d|);
 *      the rest of the formula is the fast path's (c2d_finish) on that d.
 *   3. The general path (real/collide/general.h): exact d, extended exponents.
 *   All three evaluate the same formula, so results are continuous across
 *   the tier boundaries.
 *
 * STATUS PRIORITY
 *   INVALID > DEGENERATE > SEPARATING > RANGE > OK.  The fast path cannot
 *   tell INVALID from DEGENERATE (both fail its window), so whatever it
 *   declines is validated in full, in priority order, before any tier runs.
 */
#ifndef C2D_REAL_COLLIDE_H
#define C2D_REAL_COLLIDE_H

static int c2d_mass_valid(c2d_real m) { return m > 0; } /* NaN fails; INFINITY passes */

/* INVALID or DEGENERATE for the bodies and restitution, else OK. */
static c2d_status c2d_validate(const c2d_real_body *a, const c2d_real_body *b, c2d_real e)
{
    if (a == NULL || b == NULL) return C2D_INVALID;
    if (!c2d_finite4(a->pos.x, a->pos.y, b->pos.x, b->pos.y)) return C2D_INVALID;
    if (!c2d_finite4(a->vel.x, a->vel.y, b->vel.x, b->vel.y)) return C2D_INVALID;
    if (!c2d_mass_valid(a->mass) || !c2d_mass_valid(b->mass)) return C2D_INVALID;
    if (!(e >= 0 && e <= 1)) return C2D_INVALID;
    if (a->mass > C2D_R_MAX && b->mass > C2D_R_MAX) return C2D_DEGENERATE;
    return C2D_OK;
}

/* The fast path's view of two bodies along a normal (filled field by field:
 * a struct copy becomes a memcpy call at -Os on small cores). */
static inline void c2d_pair_of(c2d_pair *p, const c2d_real_body *a, const c2d_real_body *b, c2d_real nx, c2d_real ny)
{
    p->n.x = nx;
    p->n.y = ny;
    p->va.x = a->vel.x;
    p->va.y = a->vel.y;
    p->vb.x = b->vel.x;
    p->vb.y = b->vel.y;
    p->ma = a->mass;
    p->mb = b->mass;
}

static void c2d_store(c2d_real_body *a, c2d_real_body *b, const c2d_real *out)
{
    a->vel.x = out[0];
    a->vel.y = out[1];
    b->vel.x = out[2];
    b->vel.y = out[3];
}

/* Tier 2 for valid inputs, the normal exact as nh + nl (nl = 0 for a given
 * normal).  GENERAL when the double-double d cannot be trusted or a step
 * leaves the window. */
static c2d_verdict c2d_accurate(const c2d_real_body *a, const c2d_real_body *b, const c2d_real_vec *nh,
                                const c2d_real_vec *nl, c2d_real e, c2d_real *out)
{
    const c2d_real k_lo = c2d_pow2(-C2D_R_EXP_K), k_hi = c2d_pow2(C2D_R_EXP_K);
    c2d_real rx = b->vel.x - a->vel.x, ry = b->vel.y - a->vel.y;
    c2d_real k = c2d_abs(rx * nh->x) + c2d_abs(ry * nh->y);
    c2d_real split = c2d_abs(rx) + c2d_abs(ry) + c2d_abs(nh->x) + c2d_abs(nh->y);
    c2d_real d;
    c2d_pair p;
    if (!(k >= k_lo && k <= k_hi && split <= c2d_pow2(C2D_R_EMAX / 2))) return C2D_VERDICT_GENERAL;
    d = c2d_dot2(nh, nl, &a->vel, &b->vel);
    if (!(c2d_abs(d) * c2d_pow2(C2D_R_EXP_KAPPA2) >= k)) return C2D_VERDICT_GENERAL;
    c2d_pair_of(&p, a, b, nh->x + nl->x, nh->y + nl->y);
    if (!c2d_finish(d, &p, 1 + e, out)) return C2D_VERDICT_GENERAL;
    if (d >= 0) return C2D_VERDICT_SEPARATING;
    return c2d_finite4(out[0], out[1], out[2], out[3]) ? C2D_VERDICT_OK : C2D_VERDICT_RANGE;
}

/* Tiers 2 and 3 with the exact normal, for valid non-degenerate inputs. */
static c2d_status c2d_resolve(c2d_real_body *a, c2d_real_body *b, const c2d_real_vec *nh, const c2d_real_vec *nl,
                              c2d_real e)
{
    c2d_real out[4];
    c2d_verdict v = c2d_accurate(a, b, nh, nl, e, out);
    if (v == C2D_VERDICT_GENERAL) return c2d_general_pair(a, b, nh, nl, e);
    if (v == C2D_VERDICT_OK) c2d_store(a, b, out);
    return c2d_verdict_status(v);
}

/* n = b.pos - a.pos exactly, as the floating pair nh + nl. */
static void c2d_exact_normal(const c2d_real_body *a, const c2d_real_body *b, c2d_real_vec *nh, c2d_real_vec *nl)
{
    nh->x = c2d_two_sum(b->pos.x, -a->pos.x, &nl->x);
    nh->y = c2d_two_sum(b->pos.y, -a->pos.y, &nl->y);
}

/* Everything c2d_collide's fast path declined as outside its window: full
 * validation in status priority, then the exact normal. */
C2D_COLD c2d_status c2d_collide_slow(c2d_real_body *a, c2d_real_body *b, c2d_real restitution)
{
    c2d_real_vec nh, nl;
    c2d_status s = c2d_validate(a, b, restitution);
    if (s != C2D_OK) return s;
    if (a->pos.x == b->pos.x && a->pos.y == b->pos.y) return C2D_DEGENERATE;
    if (c2d_abs(a->pos.x) + c2d_abs(a->pos.y) + c2d_abs(b->pos.x) + c2d_abs(b->pos.y) >= c2d_pow2(C2D_R_EMAX - 2)) {
        /* Near the top of the range the difference may overflow: go general
         * with the exact difference carried in extended form. */
        c2d_ext xh[2], xl[2];
        c2d_exact_diff(b->pos.x, a->pos.x, &xh[0], &xl[0]);
        c2d_exact_diff(b->pos.y, a->pos.y, &xh[1], &xl[1]);
        return c2d_general(a, b, xh, xl, restitution);
    }
    c2d_exact_normal(a, b, &nh, &nl);
    return c2d_resolve(a, b, &nh, &nl, restitution);
}

/* Valid inputs (the fast window held) whose d cancels: only d needs the
 * exact normal.  Out of line, so the fast path keeps its registers. */
C2D_COLD c2d_status c2d_collide_accurate(c2d_real_body *a, c2d_real_body *b, c2d_real restitution)
{
    c2d_real_vec nh, nl;
    c2d_exact_normal(a, b, &nh, &nl);
    return c2d_resolve(a, b, &nh, &nl, restitution);
}

/* Axis-aligned impacts, correctly rounded: real/collide/axis.h. */
C2D_COLD c2d_status c2d_axis_impact(c2d_real_body *a, c2d_real_body *b, const c2d_real_vec *given, int axis, int sign,
                                    c2d_real restitution);

#if !C2D_SMALL
/* Tier 2 for a pair the front end (c2d_quick) found valid and inside its
 * window, but whose d cancels: c2d_accurate's arithmetic without the checks
 * the window makes redundant.  With k, n.n and the masses in [W^-1, W] and
 * |d| >= 2^-KAPPA2 k, c = (1+e) d / (n.n (ma + mb)), la and lb are normal, so
 * c2d_finish cannot decline; the rest is c2d_accurate's own route.  `fused`:
 * TwoProduct by FMA (c2d_two_prod_as). */
C2D_HOT c2d_status c2d_cancelling_as(c2d_real_body *a, c2d_real_body *b, const c2d_real_vec *nh, const c2d_real_vec *nl,
                                     c2d_real restitution, int fused)
{
    const c2d_real rx = b->vel.x - a->vel.x, ry = b->vel.y - a->vel.y;
    const c2d_real k = c2d_abs(rx * nh->x) + c2d_abs(ry * nh->y);
    const c2d_real split = c2d_abs(rx) + c2d_abs(ry) + c2d_abs(nh->x) + c2d_abs(nh->y);
    c2d_real d, fa, fb, den, c, la, lb;
    if (!(split <= c2d_pow2(C2D_R_EMAX / 2))) return c2d_resolve(a, b, nh, nl, restitution);
    d = c2d_dot2_as(nh, nl, &a->vel, &b->vel, fused);
    if (!(c2d_abs(d) * c2d_pow2(C2D_R_EXP_KAPPA2) >= k)) return c2d_resolve(a, b, nh, nl, restitution);
    if (d >= 0) return C2D_SEPARATING;
    fa = a->mass > C2D_R_MAX ? (c2d_real)1.0 : (b->mass > C2D_R_MAX ? (c2d_real)0.0 : a->mass);
    fb = b->mass > C2D_R_MAX ? (c2d_real)1.0 : (a->mass > C2D_R_MAX ? (c2d_real)0.0 : b->mass);
    den = (nh->x * nh->x + nh->y * nh->y) * (fa + fb);
    c = (1 + restitution) * d / den;
    la = c * fb;
    lb = c * fa;
    if (!(a->mass > C2D_R_MAX)) { /* an immovable body keeps its velocity's bits (-0 too) */
        a->vel.x = a->vel.x + la * nh->x;
        a->vel.y = a->vel.y + la * nh->y;
    }
    if (!(b->mass > C2D_R_MAX)) {
        b->vel.x = b->vel.x - lb * nh->x;
        b->vel.y = b->vel.y - lb * nh->y;
    }
    return C2D_OK;
}

#endif /* !C2D_SMALL */

#if defined(C2D_R_FUSED) && !C2D_SMALL
/* The tier compiled for x86-64-v3 (which has FMA), with fused TwoProducts. */
__attribute__((target("arch=x86-64-v3"))) C2D_COLD c2d_status c2d_cancelling_fused(c2d_real_body *a, c2d_real_body *b,
                                                                                     const c2d_real_vec *nh,
                                                                                     const c2d_real_vec *nl,
                                                                                     c2d_real restitution)
{
    return c2d_cancelling_as(a, b, nh, nl, restitution, 1);
}
#endif

/* What c2d_collide's front end could not decide: the fast path, then the
 * tier its verdict names.  Out of line, so the front end stays small. */
C2D_COLD c2d_status c2d_collide_fallback(c2d_real_body *a, c2d_real_body *b, c2d_real restitution)
{
    c2d_real out[4];
    c2d_pair p;
    c2d_verdict v;
    c2d_pair_of(&p, a, b, b->pos.x - a->pos.x, b->pos.y - a->pos.y);
    v = c2d_fast(&p, 1 + restitution, out);
    if (v == C2D_VERDICT_ACCURATE) return c2d_collide_accurate(a, b, restitution);
    if (v == C2D_VERDICT_GENERAL) return c2d_collide_slow(a, b, restitution);
    if (v == C2D_VERDICT_OK) c2d_store(a, b, out);
    return c2d_verdict_status(v);
}

#if !C2D_SMALL
/* Tier 2 for the front end: with FMA when the CPU has it (chosen at run
 * time under C2D_DISPATCH), Dekker's split otherwise; the same bits.  The
 * normal is the given one (nl = 0), or with `given` NULL the exact position
 * difference, formed here so that the front end need not keep the
 * positions: where c2d_collide_slow would take another route (positions so
 * large that the difference may overflow), the fallback takes the pair. */
C2D_COLD c2d_status c2d_quick_cancelling(c2d_real_body *a, c2d_real_body *b, const c2d_real_vec *given,
                                         c2d_real restitution)
{
    c2d_real_vec nh, nl;
    if (given != NULL) {
        nh.x = given->x; /* field by field: a struct copy may become a memcpy call */
        nh.y = given->y;
        nl.x = 0;
        nl.y = 0;
    } else {
        if (!(c2d_abs(a->pos.x) + c2d_abs(a->pos.y) + c2d_abs(b->pos.x) + c2d_abs(b->pos.y) <
              c2d_pow2(C2D_R_EMAX - 2)))
            return c2d_collide_fallback(a, b, restitution);
        c2d_exact_normal(a, b, &nh, &nl);
    }
#ifdef C2D_R_FUSED
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
        return c2d_cancelling_fused(a, b, &nh, &nl, restitution);
#endif
    return c2d_cancelling_as(a, b, &nh, &nl, restitution, 0);
}
#endif /* !C2D_SMALL */

/* c2d_collide: the input-only front end (real/collide/fast.h), else the fallback.
 *
 * OPTIMISING FOR SIZE (C2D_SMALL)
 *   Only the axis test is kept: every other pair goes to the fallback, whose
 *   fast path gives the front end's answers with the same bits (fast.h: the
 *   accept test takes the fast path's operations in its order; a pair it
 *   calls undecided is one whose d cancels, the fast path's ACCURATE, and
 *   c2d_cancelling_as is c2d_resolve's route inside the window).  One copy
 *   of the formula instead of two. */
static inline c2d_status c2d_real_collide(c2d_real_body *a, c2d_real_body *b, c2d_real restitution)
{
#if C2D_SMALL
    c2d_real nx, ny;
    if (a == NULL || b == NULL || !(restitution >= 0 && restitution <= 1)) return C2D_INVALID;
    nx = b->pos.x - a->pos.x;
    ny = b->pos.y - a->pos.y;
    if (nx == 0 || ny == 0) { /* c2d_quick's C2D_VERDICT_AXIS */
        const int on_y = b->pos.x == a->pos.x;
        const c2d_real pa = on_y != 0 ? a->pos.y : a->pos.x, pb = on_y != 0 ? b->pos.y : b->pos.x;
        return c2d_axis_impact(a, b, NULL, on_y, pb > pa ? 1 : (pb < pa ? -1 : 0), restitution);
    }
    return c2d_collide_fallback(a, b, restitution);
#else
    c2d_real out[4];
    c2d_pair p;
    c2d_verdict v;
    if (a == NULL || b == NULL || !(restitution >= 0 && restitution <= 1)) return C2D_INVALID;
    c2d_pair_of(&p, a, b, b->pos.x - a->pos.x, b->pos.y - a->pos.y);
    v = c2d_quick(&p, 1 + restitution, out);
    if (v == C2D_VERDICT_OK) {
        c2d_store(a, b, out);
        return C2D_OK;
    }
    if (v == C2D_VERDICT_SEPARATING) return C2D_SEPARATING;
    if (v == C2D_VERDICT_AXIS) {
        const int on_y = b->pos.x == a->pos.x; /* the centres share x: the normal is along y */
        const c2d_real pa = on_y != 0 ? a->pos.y : a->pos.x, pb = on_y != 0 ? b->pos.y : b->pos.x;
        return c2d_axis_impact(a, b, NULL, on_y, pb > pa ? 1 : (pb < pa ? -1 : 0), restitution);
    }
    /* A valid pair whose d cancels: where the fast path would send it. */
    if (v == C2D_VERDICT_ACCURATE) return c2d_quick_cancelling(a, b, NULL, restitution);
    return c2d_collide_fallback(a, b, restitution);
#endif
}

/* What c2d_collide_normal's fast path declined, out of line. */
C2D_COLD c2d_status c2d_collide_normal_slow(c2d_real_body *a, c2d_real_body *b, const c2d_real_vec *n,
                                            c2d_real restitution, c2d_verdict verdict)
{
    c2d_real_vec zero;
    c2d_status s;
    zero.x = 0;
    zero.y = 0;
    if (verdict == C2D_VERDICT_ACCURATE) return c2d_resolve(a, b, n, &zero, restitution);
    s = c2d_validate(a, b, restitution);
    if (s == C2D_INVALID || !c2d_finite4(n->x, n->y, 0, 0)) return C2D_INVALID;
    if (s != C2D_OK || a == b || (n->x == 0 && n->y == 0)) return C2D_DEGENERATE;
    return c2d_resolve(a, b, n, &zero, restitution);
}

/* c2d_collide_normal's fast path and the tiers, for what its front end
 * could not decide. */
C2D_COLD c2d_status c2d_collide_normal_fallback(c2d_real_body *a, c2d_real_body *b, const c2d_real_vec *normal,
                                                c2d_real restitution)
{
    c2d_real out[4];
    c2d_pair p;
    c2d_verdict v;
    if (a == b) return c2d_collide_normal_slow(a, b, normal, restitution, C2D_VERDICT_GENERAL); /* itself */
    c2d_pair_of(&p, a, b, normal->x, normal->y);
    v = c2d_fast(&p, 1 + restitution, out);
    if (v == C2D_VERDICT_ACCURATE || v == C2D_VERDICT_GENERAL)
        return c2d_collide_normal_slow(a, b, normal, restitution, v);
    if (v == C2D_VERDICT_OK) c2d_store(a, b, out);
    return c2d_verdict_status(v);
}

/* c2d_collide_normal: positions are only validated.  The normal comes as
 * its two components, so the front end keeps it in registers whether or not
 * the compiler inlines it: given as a pointer to the public function's
 * by-value c2d_vec2, gcc 12 split the front end off (.part.0) and passed the
 * normal through memory, stored as two 8-byte halves and reloaded as one
 * 16-byte vector, which the store buffer cannot forward (some 10 cycles on
 * the critical path).  Only the out-of-line tiers take it by address, each
 * from a copy made on its own branch.  At -O3 (with or without
 * -march=native) gcc 12 did the same one level up, with the public
 * function's by-value argument itself, until c2d_collide_normal took its
 * fields through C2D_IN_REGISTER (lib/double.c, internal.h).
 * tests/build/normal_stall.sh checks the compiled hot path at every
 * optimisation level the documentation names. */
static inline c2d_status c2d_collide_normal_front(c2d_real_body *a, c2d_real_body *b, c2d_real nx, c2d_real ny,
                                                  c2d_real restitution)
{
#if C2D_SMALL /* as c2d_real_collide: the axis test, then the fallback's fast path */
    c2d_real_vec n;
    if (a == NULL || b == NULL || !(restitution >= 0 && restitution <= 1)) return C2D_INVALID;
    if (!c2d_finite4(a->pos.x, a->pos.y, b->pos.x, b->pos.y)) return C2D_INVALID;
    n.x = nx;
    n.y = ny;
    if (a != b && (nx == 0 || ny == 0)) {
        const int on_y = nx == 0;
        const c2d_real ni = on_y != 0 ? ny : nx;
        return c2d_axis_impact(a, b, &n, on_y, ni > 0 ? 1 : (ni < 0 ? -1 : 0), restitution);
    }
    return c2d_collide_normal_fallback(a, b, &n, restitution);
#else
    c2d_real out[4];
    c2d_real_vec n;
    c2d_pair p;
    c2d_verdict v;
    if (a == NULL || b == NULL || !(restitution >= 0 && restitution <= 1)) return C2D_INVALID;
    if (!c2d_finite4(a->pos.x, a->pos.y, b->pos.x, b->pos.y)) return C2D_INVALID;
    c2d_pair_of(&p, a, b, nx, ny);
    v = a == b ? C2D_VERDICT_GENERAL : c2d_quick(&p, 1 + restitution, out);
    if (v == C2D_VERDICT_OK) {
        c2d_store(a, b, out);
        return C2D_OK;
    }
    if (v == C2D_VERDICT_SEPARATING) return C2D_SEPARATING;
    n.x = nx;
    n.y = ny;
    if (v == C2D_VERDICT_AXIS) {
        const int on_y = nx == 0;
        const c2d_real ni = on_y != 0 ? ny : nx;
        return c2d_axis_impact(a, b, &n, on_y, ni > 0 ? 1 : (ni < 0 ? -1 : 0), restitution);
    }
    if (v == C2D_VERDICT_ACCURATE) return c2d_quick_cancelling(a, b, &n, restitution);
    return c2d_collide_normal_fallback(a, b, &n, restitution);
#endif
}

/* The same for a normal given by address (c2d_collide_rough_normal). */
static inline c2d_status c2d_real_collide_normal(c2d_real_body *a, c2d_real_body *b, const c2d_real_vec *normal,
                                                 c2d_real restitution)
{
    return c2d_collide_normal_front(a, b, normal->x, normal->y, restitution);
}

#endif /* C2D_REAL_COLLIDE_H */
