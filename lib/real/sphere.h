/* SPDX-License-Identifier: MIT */
/* real/sphere.h - template: c2d_collide_balls and c2d_collide_cushion, pool
 * balls as spheres on a table: three-component spin, friction on the full
 * 3-D slip, a cushion that touches the ball above its centre.
 * Needs real/collide/collide.h, real/arith/bits.h and real/arith/exact.h first.
 *
 * FRAME AND BALL
 *   x, y the table's plane, z up.  A ball: centre (x, y, R) (on the cloth),
 *   velocity (vx, vy, 0), angular velocity w = (wx, wy, wz), mass m, radius
 *   R, moment of inertia I (2/5 m R^2 solid).  A point at r from the centre
 *   moves at v + w x r.
 *
 * THE IMPACT: A FREE IMPULSE, THEN THE TABLE (both contacts)
 *   An impulse P at the contact point C = centre + r changes
 *       v += P / m,   w += (r x P) / I.
 *   It is computed as for free balls (Han 2005, "Dynamics in carom and three
 *   cushion billiards", J. Mech. Sci. Tech. 19(4); Alciatore, TP A.14, for
 *   ball-ball throw), then the cloth takes the vertical velocity away: a
 *   vertical reaction through the centre (a ball pressed into the cloth does
 *   not leave it; the reaction's moment about the centre is zero, so the
 *   spin keeps what P gave it).  For a free sphere the inverse mass of a
 *   contact point along any direction d perpendicular to r^ is
 *       d.(dv) / |P| = 1/m + R^2 / I      (r x (r x d) = -R^2 d),
 *   the same in every tangential direction: the tangential slip S keeps its
 *   direction while Coulomb friction acts (-mu |dPn| S^), so the impulse of
 *   friction has the closed form
 *       F = -lambda S^,  lambda = min(mu Pn, |S| / A),  A = the tangential
 *                                                      inverse mass,
 *   sliding throughout (mu Pn) or the slip stopping on the way (|S| / A):
 *   exactly Coulomb's law integrated over the impact, continuous in every
 *   input.  Normal: Newton's restitution on the normal approach speed.
 *
 * BALL-BALL (c2d_collide_balls)
 *   n^ = (b - a) / |b - a| horizontal, t^ = (-n^y, n^x, 0) = z^ x n^.  The
 *   contact is at the equator: ra = Ra n^, rb = -Rb n^.  b's contact point
 *   slides past a's at
 *       g = vb - va - (Ra wa + Rb wb) x n^,
 *       gn = (vb - va).n^,
 *       gt = (vb - va).t^ - (Ra wza + Rb wzb)          ((w x n^).t^ = wz),
 *       gz = -(Ra (wxa n^y - wya n^x) + Rb (wxb n^y - wyb n^x)).
 *   The normal impulse Jn n^ on b (-Jn n^ on a) is c2d_collide's, computed
 *   by it: Jn = (1 + e)(-gn) mn, 1/mn = 1/ma + 1/mb.  The friction
 *   J = Jt t^ + Jz z^ on b, -J on a, with
 *       1/mt = A = 1/ma + 1/mb + Ra^2/Ia + Rb^2/Ib,
 *       lambda = min(mu Jn, mt |g_tz|),  (Jt, Jz) = -lambda (gt, gz) / |g_tz|,
 *   where mu = a + b exp(-c |g_tz|) (Alciatore's fit for ball-ball throw,
 *   TP A.14: a 9.951e-3, b 0.108, c 1.088; b = 0: constant).  Torques
 *   (n^ x t^ = z^, n^ x z^ = -t^):
 *       wa += Ra (Jz t^ - Jt z^) / Ia,   wb += Rb (Jz t^ - Jt z^) / Ib,
 *       va -= Jt t^ / ma,  vb += Jt t^ / mb      (Jz taken by the cloth).
 *   With wx = wy = 0, gz = 0 and this is c2d_collide_rough with beta = 0:
 *   Jt = -min(mu Jn, mt |gt|) sign(gt).
 *
 * BALL-CUSHION (c2d_collide_cushion)
 *   n^ horizontal from the ball to the rail, t^ = z^ x n^.  The rail's nose
 *   is at height h above the cloth, R <= h <= 2R: the contact is at
 *   r = R nu, nu = cos(th) n^ + sin(th) z^, sin(th) = (h - R) / R (Han 2005,
 *   eq. 14's theta; pooltool's han_2005 resolver).  Take e2 = nu x t^ =
 *   -sin(th) n^ + cos(th) z^; (nu, t^, e2) is orthonormal.
 *       approach  u = v.nu = cos(th) vn   ((w x r).nu = 0): impact if u > 0
 *       normal    P = -Pn nu,  Pn = (1 + e) m u   (inverse mass 1/m)
 *       slip      s1 = (v + w x r).t^  = v.t^ + R w.e2
 *                 s2 = (v + w x r).e2  = -sin(th) vn - R w.t^
 *                 ((w x nu).t^ = w.(nu x t^) = w.e2, (w x nu).e2 = -w.t^)
 *       friction  F = -lambda (s1 t^ + s2 e2) / |s|,
 *                 lambda = min(mu Pn, |s| / A),  A = 1/m + R^2/I
 *       update    v += horizontal part of (-Pn nu + F) / m:
 *                      vn -= (Pn cos(th) + F2 sin(th)) / m,  vt += F1 / m
 *                 w += R nu x F / I = R (F1 e2 - F2 t^) / I.
 *   Han's own closed form (as pooltool codes it) takes the friction's
 *   direction from the ball's velocity, not the slip, and tests sticking
 *   without mu; here the friction opposes the slip, as Coulomb's law says.
 *   Han neglects the cloth's friction during the impact (Mathavan et al.
 *   2010 integrate it numerically); so does this model.  At h = R
 *   (th = 0) and wx = wy = 0 it is c2d_collide_rough_normal against a wall
 *   (b immovable, radius 0) with beta = 0.
 *
 * CONSERVATION (exact arithmetic)
 *   Energy: the normal impulse loses (1 - e^2) of the normal kinetic energy;
 *   friction changes energy by -lambda |S| + lambda^2 A / 2 <= -lambda |S| / 2
 *   (lambda <= |S| / A); the cloth then removes m vz^2 / 2.  Never gained;
 *   kept at e = 1 with no friction.  Linear momentum: J and -J in the plane.
 *   Angular momentum of each ball about the contact point C: P acts at C,
 *   the cloth's vertical reaction at the centre, at -r from C, with moment
 *   -r x (-m vz z^) along r x z^ (along t^ for both contacts): the
 *   components of L_C = I w + (-r) x m v along n^ and z^ are kept.
 *
 * ACCURACY (the fast path: plain arithmetic, one exact step)
 *   The normal part is c2d_collide's, with its bound.  The friction part
 *   is evaluated once in plain arithmetic: the slip is a sum of products of
 *   the pair's speeds, so its absolute error is a few ulp of the pair's
 *   scale; lambda <= mt |g| and the change of each output is at most
 *   (mt / m) or (R^2 mt / I) <= 1 times the slip's error: a few ulp of the
 *   pair's scale (the largest |vx|, |vy|, |R w| of both balls before and
 *   after) on top of c2d_collide's bound.  One quantity is not bounded so:
 *   sliding, the spins change by mu Jn R^2 / I, and mn R^2 / I may be large,
 *   so Jn's relative error must be a few u even for a glancing impact,
 *   whose normal speed cancels: c2d_normal_speed takes exact products then
 *   (the only step beyond plain arithmetic).  Measured against the 512-bit
 *   referee (tests/unit/test_sphere.c): 8.3 ulp at worst for two balls, all
 *   parts included, 9.3 for a cushion; pool pairs 4.4 (double), 5.0 (float);
 *   over 2^+-300 (float 2^+-30) in every magnitude 5.5 and 9.7 (float 6.0,
 *   7.9); over the whole range, every field at its own exponent, 3.5 and
 *   5.3 (float 4.2, 4.1).
 *
 * THE WHOLE RANGE (the slow path)
 *   Each plain step is a product or quotient whose error stays relative
 *   only while it is normal: with masses, inertias and radii anywhere in the
 *   range, an impulse (mass x speed), R^2/I or R w may overflow, or a
 *   product underflow to a subnormal or to zero (a light ball's impulse,
 *   then divided by its tiny mass; a subnormal spin's product, which R
 *   makes count).  So the plain path is taken only where the window test
 *   (every input - masses, radii, inertias, velocities, spins, the normal
 *   and mu - zero or within 2^+-EMAX/16, C2D_SPHERE_WINDOW below) or the
 *   step-by-step check (c2d_sphere_fine: every impulse, inverse mass, R/I,
 *   R^2/I, slip and spin change finite and normal, or exactly zero from a
 *   zero factor) says no step left the normal range; the window implies
 *   every check, so which of the two decides changes no bit (the window
 *   only skips the checks, the inverses' guards and the outputs' finite
 *   test, all of which it makes pass).  The window test
 *   itself is branch-free on the bits (c2d_span_add: the least u - 1 and
 *   the largest u of u = bits << 1, zeros passing) for the fields that may
 *   be zero, and the least and largest value of the masses, inertias and
 *   radii, which it needs positive; run before validation, so that inside
 *   it only the positions are left to check.  Elsewhere the same equations run
 *   in double length with an extended exponent (real/arith/dd.h) and each
 *   output is rounded once on top of its start: C2D_RANGE only when an
 *   output itself overflows.  Everywhere else, bit for bit the plain path.
 *   The glancing normal speed's exact products run unscaled inside the
 *   window (and with dl, the position difference's rounding error, zero or
 *   at least 2^-W): every term is then a product of two inputs or of their
 *   rounding errors, nonzero ones within 2^+-(2 W + 4 MANT), so no step
 *   over- or underflows and the scaling below changes no bit; with FMA
 *   where run-time dispatch finds it (the same bits: the TwoProduct's error
 *   is exact either way).  Outside, they are scaled by powers of two, and
 *   fall back to exact
 *   sums with extended exponents (c2d_normal_speed_dd) where the scaling
 *   would lose a component far below the largest, and a speed too small
 *   for the format stays an approach (the smallest subnormal, then the
 *   slow path).
 *   exp(-x): c2d_exp_neg below.
 */
#ifndef C2D_REAL_SPHERE_H
#define C2D_REAL_SPHERE_H

typedef C2D_R_BALL c2d_real_ball;
typedef C2D_R_BALL_SURFACE c2d_real_ball_surface;
typedef C2D_R_CUSHION c2d_real_cushion;

/* exp(-x) for x >= 0 (0 beyond C2D_R_EXP_NEG_MAX, where it is below
 * 2^(C2D_R_EMIN + 2)).  x = k ln2 + r, k the nearest integer, |r| <= ln2/2
 * (+ rounding); ln2 = hi + lo with hi's 16 bits, so k hi is exact for the
 * k <= 2^10 used and r carries an error below 2^-60 |k|, relative to the
 * result.  exp(-r) by the Taylor series to degree C2D_R_EXP_NEG_DEGREE,
 * nested as 1 + y (1 + y/2 (1 + y/3 (...))), y = -r: every factor |y/i| <
 * 0.35, so each nesting step's rounding is damped by the steps outside it
 * (a few u in all; the constants 1/i are rounded, one more u each, damped
 * alike), and the truncation (ln2/2)^(N+1)/(N+1)! is below u/4
 * (double N = 13: 4e-18; float N = 7: 5e-9).  Then 2^-k exactly (the result
 * stays normal).  Measured against MPFR in tests/unit/test_exp_neg.c, test_exp_negf.c. */
static c2d_real c2d_exp_neg(c2d_real x)
{
    const c2d_real ln2_hi = (c2d_real)0.693145751953125, ln2_lo = (c2d_real)1.42860682030941723212e-6;
    const c2d_real inv_ln2 = (c2d_real)1.44269504088896340736;
    c2d_real r, y, p;
    int k;
    if (x > (c2d_real)C2D_R_EXP_NEG_MAX) return 0;
    k = (int)(x * inv_ln2 + (c2d_real)0.5);
    r = (x - (c2d_real)k * ln2_hi) - (c2d_real)k * ln2_lo;
    y = -r;
    p = 1;
#if C2D_R_EXP_NEG_DEGREE == 13
    p = 1 + y * p * (c2d_real)(1.0 / 13);
    p = 1 + y * p * (c2d_real)(1.0 / 12);
    p = 1 + y * p * (c2d_real)(1.0 / 11);
    p = 1 + y * p * (c2d_real)(1.0 / 10);
    p = 1 + y * p * (c2d_real)(1.0 / 9);
    p = 1 + y * p * (c2d_real)(1.0 / 8);
#elif C2D_R_EXP_NEG_DEGREE != 7
#error "c2d_exp_neg: degree 7 or 13"
#endif
    p = 1 + y * p * (c2d_real)(1.0 / 7);
    p = 1 + y * p * (c2d_real)(1.0 / 6);
    p = 1 + y * p * (c2d_real)(1.0 / 5);
    p = 1 + y * p * (c2d_real)(1.0 / 4);
    p = 1 + y * p * (c2d_real)(1.0 / 3);
    p = 1 + y * p * (c2d_real)0.5;
    p = 1 + y * p;
    return p * c2d_pow2(-k);
}

/* 1/x, or 0 for an infinite x (an immovable ball, a spin that never changes). */
static c2d_real c2d_sphere_inverse(c2d_real x) { return x > C2D_R_MAX ? 0 : 1 / x; }

static int c2d_ball_valid(const c2d_real_ball *d)
{
    return c2d_finite4(d->pos.x, d->pos.y, d->vel.x, d->vel.y) && c2d_finite4(d->spin[0], d->spin[1], d->spin[2], 0) &&
           c2d_finite4(d->radius, 0, 0, 0) && d->mass > 0 && d->radius >= 0 && d->inertia > 0;
}

/* mu = friction + friction_boost exp(-friction_decay v), each >= 0, the last
 * two finite; friction may be INFINITY (never slides). */
static int c2d_ball_surface_valid(const c2d_real_ball_surface *s)
{
    return s->restitution >= 0 && s->restitution <= 1 && s->friction >= 0 && s->friction_boost >= 0 &&
           s->friction_boost <= C2D_R_MAX && s->friction_decay >= 0 && s->friction_decay <= C2D_R_MAX;
}

static c2d_real c2d_ball_friction(const c2d_real_ball_surface *s, c2d_real slip)
{
    if (s->friction_boost == 0) return s->friction;
    return s->friction + s->friction_boost * c2d_exp_neg(s->friction_decay * slip);
}

/* The friction's size: sliding all through (mu Pn) or stopping the slip on
 * the way (|S| / A), each >= 0. */
static c2d_real c2d_friction_size(c2d_real mu, c2d_real normal_impulse, c2d_real stop)
{
    c2d_real cone;
    if (mu > C2D_R_MAX) return stop;
    cone = mu * normal_impulse;
    return cone < stop ? cone : stop;
}

/* The unit horizontal normal along (x, y), neither infinite nor both zero;
 * returns |(x, y)| (to a few u; infinite only beyond C2D_R_MAX). */
static c2d_real c2d_unit_normal(c2d_real *nx, c2d_real *ny, c2d_real x, c2d_real y)
{
    c2d_real m = c2d_abs(x) > c2d_abs(y) ? c2d_abs(x) : c2d_abs(y), l;
    x /= m;
    y /= m;
    l = C2D_R_SQRT(x * x + y * y);
    *nx = x / l;
    *ny = y / l;
    return l * m;
}

/* The fast test that makes the checks below unnecessary: every nonzero
 * input magnitude (masses, radii, inertias, velocity and spin components,
 * the normal, mu; the cushion's cos(th)) within 2^+-W, W = EMAX / 16
 * (double 63, float 7).  Each
 * quantity the plain path forms is then a product or quotient of at most
 * ten of them, or a cancelling sum of such (at least a product of two
 * input ulps when nonzero): within 2^+-(10 W + 2 MANT + 8), inside the
 * normal range, so no step over- or underflows, and every output (a
 * start, itself such a quantity or c2d_collide's finite result of them,
 * plus changes of that size) is finite.  Infinite masses and inertias fail
 * it (the checks then decide). */
#define C2D_SPHERE_WINDOW (C2D_R_EMAX / 16)

/* The test by the bits, branch-free: u = bits << 1 (the sign shifted out)
 * orders the magnitudes as integers, +0 at u = 0 and infinity above every
 * finite one; u - 1 takes zero to the largest integer, so the least u - 1
 * is the smallest nonzero magnitude's and zeros pass, as above.  One
 * compare-and-select per bound and input, no loop: the same verdict as
 * comparing the magnitudes.  It runs before validation: a NaN, whose u is
 * above infinity's, fails it, and validation then runs in full. */
typedef struct c2d_sphere_span { c2d_real_bits lo, hi; } c2d_sphere_span;

static void c2d_span_start(c2d_sphere_span *s)
{
    s->lo = (c2d_real_bits)~(c2d_real_bits)0;
    s->hi = 0;
}

static void c2d_span_add(c2d_sphere_span *s, c2d_real x)
{
    const c2d_real_bits u = (c2d_real_bits)(c2d_bits(x) << 1), v = (c2d_real_bits)(u - 1u);
    s->lo = v < s->lo ? v : s->lo;
    s->hi = u > s->hi ? u : s->hi;
}

static int c2d_span_ordinary(const c2d_sphere_span *s)
{
    return s->lo >= (c2d_real_bits)((c2d_real_bits)(c2d_bits(c2d_pow2(-C2D_SPHERE_WINDOW)) << 1) - 1u) &&
           s->hi <= (c2d_real_bits)(c2d_bits(c2d_pow2(C2D_SPHERE_WINDOW)) << 1);
}

/* mu in the window (or 0, or INFINITY, which is never multiplied). */
static int c2d_sphere_mu_ordinary(c2d_real mu)
{
    return (mu >= c2d_pow2(-C2D_SPHERE_WINDOW) && mu <= c2d_pow2(C2D_SPHERE_WINDOW)) || mu == 0 || mu > C2D_R_MAX;
}

/* A ball's fields that may be zero: velocity, spin. */
C2D_HOT void c2d_ball_span(c2d_sphere_span *s, const c2d_real_ball *d)
{
    c2d_span_add(s, d->vel.x);
    c2d_span_add(s, d->vel.y);
    c2d_span_add(s, d->spin[0]);
    c2d_span_add(s, d->spin[1]);
    c2d_span_add(s, d->spin[2]);
}

/* The masses, inertias and radii in the window by their least and largest
 * value, all positive (so inside it they are valid too; a radius of zero,
 * valid, fails it and the checks decide); a NaN, which the selections may
 * drop, makes the sum fail. */
C2D_HOT int c2d_balls_sizes_ordinary(const c2d_real_ball *a, const c2d_real_ball *b)
{
    c2d_real lo = a->mass < a->inertia ? a->mass : a->inertia, hi = a->mass > a->inertia ? a->mass : a->inertia;
    lo = a->radius < lo ? a->radius : lo;
    lo = b->mass < lo ? b->mass : lo;
    lo = b->inertia < lo ? b->inertia : lo;
    lo = b->radius < lo ? b->radius : lo;
    hi = a->radius > hi ? a->radius : hi;
    hi = b->mass > hi ? b->mass : hi;
    hi = b->inertia > hi ? b->inertia : hi;
    hi = b->radius > hi ? b->radius : hi;
    return lo >= c2d_pow2(-C2D_SPHERE_WINDOW) && hi <= c2d_pow2(C2D_SPHERE_WINDOW) &&
           ((a->mass + a->inertia) + a->radius) + ((b->mass + b->inertia) + b->radius) <=
               c2d_pow2(C2D_SPHERE_WINDOW + 3);
}

/* Both balls in the window (their span and masses, from
 * c2d_real_collide_balls) and the position difference dh. */
static int c2d_balls_ordinary(const c2d_sphere_span *balls, const c2d_real_vec *dh)
{
    c2d_sphere_span s;
    s.lo = balls->lo;
    s.hi = balls->hi;
    c2d_span_add(&s, dh->x);
    c2d_span_add(&s, dh->y);
    return c2d_span_ordinary(&s);
}

/* dl, the position difference's rounding error, zero or at least 2^-W
 * (at most ulp(dh) / 2, so below 2^W with dh): what c2d_normal_speed's
 * unscaled exact products need on top of the window. */
static int c2d_sphere_low_ordinary(const c2d_real_vec *dl)
{
    const c2d_real_bits lo = (c2d_real_bits)((c2d_real_bits)(c2d_bits(c2d_pow2(-C2D_SPHERE_WINDOW)) << 1) - 1u);
    return (c2d_real_bits)((c2d_real_bits)(c2d_bits(dl->x) << 1) - 1u) >= lo &&
           (c2d_real_bits)((c2d_real_bits)(c2d_bits(dl->y) << 1) - 1u) >= lo;
}

#ifdef C2D_R_FUSED
/* c2d_dot2 compiled for x86-64-v3, its TwoProducts fused (the same bits:
 * the error term is exact either way), for c2d_normal_speed's unscaled
 * exact products where run-time dispatch finds FMA. */
__attribute__((target("arch=x86-64-v3"))) C2D_COLD c2d_real c2d_sphere_dot2_fused(const c2d_real_vec *nh,
                                                                                   const c2d_real_vec *nl,
                                                                                   const c2d_real_vec *va,
                                                                                   const c2d_real_vec *vb)
{
    return c2d_dot2_as(nh, nl, va, vb, 1);
}
#endif

/* (vb - va).n^ to a few u of itself.  A glancing impact's normal speed is a
 * cancelling sum, and the normal impulse it gives reaches the spins through
 * mu Jn R^2 / I, which the pair's scale does not bound: plainly (error
 * ~3u (|dvx| + |dvy|)) only when that is within 6u of the result, else
 * from d = dh + dl exactly with exact products (c2d_dot2,
 * real/arith/exact.h), to ~1 ulp. */
/* The exponent of the largest |component| (0 when all are zero). */
static int c2d_sphere_scale_of(c2d_real a, c2d_real b, c2d_real c, c2d_real d)
{
    c2d_real m = c2d_abs(a) > c2d_abs(b) ? c2d_abs(a) : c2d_abs(b);
    m = c2d_abs(c) > m ? c2d_abs(c) : m;
    m = c2d_abs(d) > m ? c2d_abs(d) : m;
    return m == 0 ? 0 : c2d_ilogb(m);
}

static void c2d_sphere_scale_vec(c2d_real_vec *out, const c2d_real_vec *v, int k)
{
    out->x = c2d_scale2(v->x, k);
    out->y = c2d_scale2(v->y, k);
}

/* x 2^k, or the smallest subnormal of x's sign where that underflows to
 * zero: an impact stays one (the callers' checks take the slow path). */
static c2d_real c2d_sphere_keep_sign(c2d_real x, int k)
{
    c2d_real v = c2d_scale2(x, k), tiny = c2d_scale2(1, C2D_R_EMIN - C2D_R_MANT);
    if (v == 0 && x != 0) v = x > 0 ? tiny : -tiny;
    return v;
}

/* The scaling by a power of two lost no bits: it can only where a nonzero
 * component lands below the normal range. */
static int c2d_sphere_scaled_exact(const c2d_real_vec *scaled, const c2d_real_vec *v)
{
    return (c2d_abs(scaled->x) >= c2d_pow2(C2D_R_EMIN) || v->x == 0) &&
           (c2d_abs(scaled->y) >= c2d_pow2(C2D_R_EMIN) || v->y == 0);
}

/* (vb - va).n / |n|, n = dh + dl, from exact sums with extended exponents
 * (real/arith/sign.h), rounded once; a nonzero value too small for the
 * format comes back as the smallest subnormal of its sign (the callers'
 * checks then take their slow paths).  For components so far apart that
 * scaling them to the largest would lose the smaller. */
C2D_COLD c2d_real c2d_normal_speed_dd(const c2d_real_vec *dh, const c2d_real_vec *dl, const c2d_real_vec *va,
                                      const c2d_real_vec *vb)
{
    c2d_ext n[2][2], r[2][2];
    c2d_acc acc;
    c2d_dd len, x;
    c2d_ext_set(&n[0][0], dh->x, 0);
    c2d_ext_set(&n[0][1], dl->x, 0);
    c2d_ext_set(&n[1][0], dh->y, 0);
    c2d_ext_set(&n[1][1], dl->y, 0);
    c2d_exact_diff(vb->x, va->x, &r[0][0], &r[0][1]);
    c2d_exact_diff(vb->y, va->y, &r[1][0], &r[1][1]);
    c2d_acc_clear(&acc);
    c2d_acc_pair_product(&acc, n[0], n[0], 1);
    c2d_acc_pair_product(&acc, n[1], n[1], 1);
    c2d_dd_of_acc(&x, &acc);
    c2d_dd_sqrt(&len, &x);
    c2d_acc_clear(&acc);
    c2d_acc_pair_product(&acc, r[0], n[0], 1);
    c2d_acc_pair_product(&acc, r[1], n[1], 1);
    c2d_dd_of_acc(&x, &acc);
    c2d_dd_div(&x, &x, &len);
    return c2d_sphere_keep_sign(x.h + x.l, x.e);
}

/* The exact products assume no overflow (Veltkamp's split overflows
 * beyond 2^996, a product beyond the range), and the inputs here come from
 * anywhere in it: the normal and the velocities are scaled by powers of
 * two to largest components in [1, 2) first, the result back.  Exact (the
 * same bits) wherever the unscaled evaluation neither overflows nor
 * underflows; elsewhere only components below 2^EMIN of the largest lose
 * bits, far inside the ~u^2 of the terms the double-double allows. */
C2D_COLD c2d_real c2d_normal_speed_scaled(const c2d_real_vec *dh, const c2d_real_vec *dl, c2d_real len,
                                          const c2d_real_vec *va, const c2d_real_vec *vb)
{
    c2d_real_vec h, l, a, b;
    int kn, kv;
    kn = c2d_sphere_scale_of(dh->x, dh->y, 0, 0);
    kv = c2d_sphere_scale_of(va->x, va->y, vb->x, vb->y);
    c2d_sphere_scale_vec(&h, dh, -kn);
    c2d_sphere_scale_vec(&l, dl, -kn);
    c2d_sphere_scale_vec(&a, va, -kv);
    c2d_sphere_scale_vec(&b, vb, -kv);
    if (!c2d_sphere_scaled_exact(&h, dh) || !c2d_sphere_scaled_exact(&l, dl) || !c2d_sphere_scaled_exact(&a, va) ||
        !c2d_sphere_scaled_exact(&b, vb))
        return c2d_normal_speed_dd(dh, dl, va, vb);
    /* a subnormal |n| (c2d_unit_normal's l m) has lost bits: from h again */
    len = len < c2d_pow2(C2D_R_EMIN) ? C2D_R_SQRT(h.x * h.x + h.y * h.y) : c2d_scale2(len, -kn);
    return c2d_sphere_keep_sign(c2d_dot2(&h, &l, &a, &b) / len, kv);
}

/* The plain value, or inside the window (ordinary: both balls and dh, and
 * here dl) the exact products unscaled: every term they form is a product
 * of at most two inputs or their rounding errors, within 2^+-(2 W + 4 MANT)
 * when nonzero, so no step over- or underflows and scaling by powers of two
 * would change no bit (c2d_normal_speed_scaled's result, for less). */
C2D_HOT c2d_real c2d_normal_speed(const c2d_real_vec *dh, const c2d_real_vec *dl, c2d_real len, c2d_real nx,
                                  c2d_real ny, const c2d_real_vec *va, const c2d_real_vec *vb, int ordinary)
{
    c2d_real dvx = vb->x - va->x, dvy = vb->y - va->y, gn = dvx * nx + dvy * ny;
    if (2 * c2d_abs(gn) >= c2d_abs(dvx) + c2d_abs(dvy)) return gn;
    if (ordinary != 0 && c2d_sphere_low_ordinary(dl)) {
#ifdef C2D_R_FUSED
        if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
            return c2d_sphere_dot2_fused(dh, dl, va, vb) / len;
#endif
        return c2d_dot2(dh, dl, va, vb) / len;
    }
    return c2d_normal_speed_scaled(dh, dl, len, va, vb);
}

/* |(x, y)| scaled by a power of two (the squares would over- or underflow). */
C2D_COLD c2d_real c2d_sphere_length_scaled(c2d_real x, c2d_real y)
{
    const int k = c2d_sphere_scale_of(x, y, 0, 0);
    x = c2d_scale2(x, -k);
    y = c2d_scale2(y, -k);
    return c2d_scale2(C2D_R_SQRT(x * x + y * y), k);
}

/* |(x, y)|: plainly, or scaled by a power of two where the squares would
 * overflow or underflow (the same bits wherever they do not); the plain
 * test inline, the scaled tier out of line. */
C2D_HOT c2d_real c2d_sphere_length(c2d_real x, c2d_real y)
{
    const c2d_real s = C2D_R_SQRT(x * x + y * y);
    if ((s <= C2D_R_MAX && s >= c2d_pow2(C2D_R_EMIN / 2)) || !c2d_finite4(x, y, 0, 0) || (x == 0 && y == 0))
        return s;
    return c2d_sphere_length_scaled(x, y);
}

static void c2d_ball_body(c2d_real_body *body, const c2d_real_ball *d)
{
    body->pos.x = d->pos.x;
    body->pos.y = d->pos.y;
    body->vel.x = d->vel.x;
    body->vel.y = d->vel.y;
    body->mass = d->mass;
}

/* The outputs of one ball, written only once all are known finite. */
typedef struct c2d_ball_out { c2d_real v[2], w[3]; } c2d_ball_out;

static int c2d_ball_out_finite(const c2d_ball_out *o)
{
    return c2d_finite4(o->v[0], o->v[1], o->w[0], o->w[1]) && c2d_finite4(o->w[2], 0, 0, 0);
}

static void c2d_ball_write(c2d_real_ball *d, const c2d_ball_out *o)
{
    d->vel.x = o->v[0];
    d->vel.y = o->v[1];
    d->spin[0] = o->w[0];
    d->spin[1] = o->w[1];
    d->spin[2] = o->w[2];
}

/* One ball's change under the friction sign (Jt t^ + Jz z^) at its lever
 * -sign R n^: v += sign Jt t^ / m and, the two signs cancelling,
 * w += R (Jz t^ - Jt z^) / I for both balls. */
static void c2d_ball_friction_apply(c2d_ball_out *o, const c2d_real_vec *v_normal, const c2d_real_ball *d,
                                    c2d_real inv_mass, c2d_real q, c2d_real nx, c2d_real ny, c2d_real jt,
                                    c2d_real jz, c2d_real sign)
{
    c2d_real dv = sign * jt * inv_mass;
    o->v[0] = v_normal->x - dv * ny;
    o->v[1] = v_normal->y + dv * nx;
    o->w[0] = d->spin[0] - q * jz * ny;
    o->w[1] = d->spin[1] + q * jz * nx;
    o->w[2] = d->spin[2] - q * jt;
}

/* x is finite and neither subnormal nor an underflow to zero of a product
 * of nonzero factors (p = x * y, or x alone with y = 1). */
static int c2d_sphere_fine(c2d_real p, c2d_real x, c2d_real y)
{
    return c2d_finite4(p, 0, 0, 0) && (p == 0 ? (x == 0 || y == 0) : c2d_abs(p) >= c2d_pow2(C2D_R_EMIN));
}

/* A subnormal spin loses bits in every product the plain path takes of it,
 * and R may make them count: such a ball takes the slow path. */
static int c2d_ball_spin_fine(const c2d_real_ball *d)
{
    return c2d_sphere_fine(d->spin[0], d->spin[0], 1) && c2d_sphere_fine(d->spin[1], d->spin[1], 1) &&
           c2d_sphere_fine(d->spin[2], d->spin[2], 1);
}

/* The slow path of both contacts: the same equations in double length with
 * an extended exponent (real/arith/dd.h), each output rounded once on top
 * of its start, so nothing over- or underflows on the way (masses,
 * inertias, radii, speeds and spins each anywhere in the range, an impulse
 * or R^2/I beyond it).  Taken only where the plain path's check (below)
 * finds a value out of the format's normal range: bit for bit the plain
 * path everywhere else. */
typedef struct c2d_dd_vec { c2d_dd x, y; } c2d_dd_vec;

/* r = x * k for a dd x and a working k. */
static void c2d_sphere_dd_times(c2d_dd *r, const c2d_dd *x, c2d_real k)
{
    c2d_dd dk;
    c2d_dd_of(&dk, k);
    c2d_dd_mul(r, x, &dk);
}

/* r = x * y of two working numbers, exactly. */
static void c2d_sphere_dd_prod(c2d_dd *r, c2d_real x, c2d_real y)
{
    c2d_dd dx;
    c2d_dd_of(&dx, x);
    c2d_sphere_dd_times(r, &dx, y);
}

/* r = a x + b y (dd t, working a and b). */
static void c2d_sphere_dd_dot(c2d_dd *r, const c2d_dd_vec *t, c2d_real a, c2d_real b)
{
    c2d_dd x, y;
    c2d_sphere_dd_times(&x, &t->x, a);
    c2d_sphere_dd_times(&y, &t->y, b);
    c2d_dd_add(r, &x, &y, 1);
}

/* |(x, y)| in dd. */
static void c2d_sphere_dd_hypot(c2d_dd *r, const c2d_dd *x, const c2d_dd *y)
{
    c2d_dd xx, yy;
    c2d_dd_mul(&xx, x, x);
    c2d_dd_mul(&yy, y, y);
    c2d_dd_add(&xx, &xx, &yy, 1);
    c2d_dd_sqrt(r, &xx);
}

/* 1/x and R^2/I style ratios: n / x, 0 for an infinite x. */
static void c2d_sphere_dd_over(c2d_dd *r, const c2d_dd *n, c2d_real x) { c2d_dd_ratio(r, n, x); }

/* The friction's size in dd: min(mu Jn, stop) (mu INFINITY: stop). */
static void c2d_sphere_dd_size(c2d_dd *lambda, c2d_real mu, const c2d_dd *normal_impulse, const c2d_dd *stop)
{
    c2d_dd cone;
    if (mu > C2D_R_MAX) {
        c2d_dd_copy(lambda, stop);
        return;
    }
    c2d_sphere_dd_times(&cone, normal_impulse, mu);
    c2d_dd_copy(lambda, c2d_dd_abs_greater(&cone, stop) ? stop : &cone);
}

/* mu(|g|) for a dd slip: c |g| in dd, saturated at C2D_R_MAX (where
 * exp(-c |g|) is 0). */
static c2d_real c2d_sphere_dd_mu(const c2d_real_ball_surface *s, const c2d_dd *g)
{
    c2d_dd x;
    if (s->friction_boost == 0) return s->friction;
    c2d_sphere_dd_times(&x, g, s->friction_decay);
    return s->friction +
           s->friction_boost * c2d_exp_neg(x.e >= C2D_R_EMAX ? (c2d_real)C2D_R_MAX : c2d_dd_value(&x));
}

/* One ball's outputs in dd: v += sign Jt t^ / m, w += R (Jz t^ - Jt z^) / I
 * (q = R / I), each rounded once on top of the normal result v0. */
static void c2d_ball_friction_apply_dd(c2d_ball_out *o, const c2d_real_vec *v0, const c2d_real_ball *d,
                                       const c2d_dd_vec *t, const c2d_dd *jt, const c2d_dd *jz, int sign)
{
    c2d_dd dv, q, x, one;
    c2d_dd_ratio(&dv, jt, d->mass);
    if (sign < 0) c2d_dd_negate(&dv);
    c2d_dd_mul(&x, &dv, &t->x);
    o->v[0] = c2d_plus(v0->x, &x);
    c2d_dd_mul(&x, &dv, &t->y);
    o->v[1] = c2d_plus(v0->y, &x);
    c2d_dd_of(&one, d->radius);
    c2d_sphere_dd_over(&q, &one, d->inertia);
    c2d_dd_mul(&dv, &q, jz);
    c2d_dd_mul(&x, &dv, &t->x);
    o->w[0] = c2d_plus(d->spin[0], &x);
    c2d_dd_mul(&x, &dv, &t->y);
    o->w[1] = c2d_plus(d->spin[1], &x);
    c2d_dd_mul(&x, &q, jt);
    c2d_dd_negate(&x);
    o->w[2] = c2d_plus(d->spin[2], &x);
}

/* The disk c2d_rough_contact_of reads: the spin about z (field by field:
 * no memcpy on small cores). */
static void c2d_ball_disk(c2d_real_disk *r, const c2d_real_ball *d)
{
    r->pos.x = d->pos.x;
    r->pos.y = d->pos.y;
    r->vel.x = d->vel.x;
    r->vel.y = d->vel.y;
    r->spin = d->spin[2];
    r->mass = d->mass;
    r->radius = d->radius;
    r->inertia = d->inertia;
}

/* Two balls' friction in dd (the slow path): the contact's geometry, gn and
 * gt as c2d_collide_rough takes them (exact sums, real/rough.h), gz from
 * the dd tangent t^ = (-n^y, n^x): gz = Ra (wxa tx + wya ty) + Rb (...). */
C2D_COLD c2d_status c2d_balls_friction_dd(c2d_real_ball *a, c2d_real_ball *b, const c2d_real_body *ta,
                                          const c2d_real_body *tb, const c2d_real_ball_surface *s)
{
    c2d_real_disk da, db;
    c2d_rough_contact c;
    c2d_dd_vec t;
    c2d_dd gz, x, g, one, ima, imb, inv_mn, inv_mt, jn, stop, lambda, f, jt, jz;
    c2d_ball_out oa, ob;
    c2d_ball_disk(&da, a);
    c2d_ball_disk(&db, b);
    c2d_rough_contact_of(&c, &da, &db, NULL);
    c2d_dd_copy(&t.x, &c.t[0]);
    c2d_dd_copy(&t.y, &c.t[1]);
    c2d_sphere_dd_dot(&gz, &t, a->spin[0], a->spin[1]);
    c2d_sphere_dd_times(&gz, &gz, a->radius);
    c2d_sphere_dd_dot(&x, &t, b->spin[0], b->spin[1]);
    c2d_sphere_dd_times(&x, &x, b->radius);
    c2d_dd_add(&gz, &gz, &x, 1);
    c2d_sphere_dd_hypot(&g, &c.gt, &gz);
    c2d_dd_of(&one, 1);
    c2d_sphere_dd_over(&ima, &one, a->mass);
    c2d_sphere_dd_over(&imb, &one, b->mass);
    c2d_dd_add(&inv_mn, &ima, &imb, 1);
    c2d_sphere_dd_prod(&x, a->radius, a->radius);
    c2d_sphere_dd_over(&x, &x, a->inertia);
    c2d_dd_add(&inv_mt, &inv_mn, &x, 1);
    c2d_sphere_dd_prod(&x, b->radius, b->radius);
    c2d_sphere_dd_over(&x, &x, b->inertia);
    c2d_dd_add(&inv_mt, &inv_mt, &x, 1);
    c2d_dd_of(&f, 0);
    if (g.h != 0 && c2d_dd_sign(&c.gn) < 0) {
        c2d_sphere_dd_times(&jn, &c.gn, -(1 + s->restitution)); /* Jn = -(1 + e) gn mn */
        c2d_dd_div(&jn, &jn, &inv_mn);
        c2d_dd_div(&stop, &g, &inv_mt);
        c2d_sphere_dd_size(&lambda, c2d_sphere_dd_mu(s, &g), &jn, &stop);
        c2d_dd_div(&f, &lambda, &g);
    }
    c2d_dd_mul(&jt, &f, &c.gt);
    c2d_dd_negate(&jt);
    c2d_dd_mul(&jz, &f, &gz);
    c2d_dd_negate(&jz);
    c2d_ball_friction_apply_dd(&oa, &ta->vel, a, &t, &jt, &jz, -1);
    c2d_ball_friction_apply_dd(&ob, &tb->vel, b, &t, &jt, &jz, 1);
    if (!c2d_ball_out_finite(&oa) || !c2d_ball_out_finite(&ob)) return C2D_RANGE;
    c2d_ball_write(a, &oa);
    c2d_ball_write(b, &ob);
    return C2D_OK;
}

/* The friction of two balls on top of c2d_collide's normal result (ta, tb):
 * plainly, each step checked (c2d_sphere_fine) for an overflow, a
 * subnormal or an underflow to zero, which would cost the result its
 * bound; any such sends the pair to the slow path. */
static c2d_status c2d_balls_friction(c2d_real_ball *a, c2d_real_ball *b, const c2d_real_body *ta,
                                     const c2d_real_body *tb, const c2d_real_ball_surface *s,
                                     const c2d_sphere_span *balls, int balls_ordinary)
{
    c2d_real nx, ny, gn, gt, gz, g, qa, qb, ia, ib, ka, kb, ima, imb, inv_mn, inv_mt, len, jn, f;
    c2d_real jt, jz;
    c2d_real dvx = b->vel.x - a->vel.x, dvy = b->vel.y - a->vel.y;
    c2d_real_vec dh, dl;
    c2d_ball_out oa, ob;
    int fine, fast;
    dh.x = c2d_two_sum(b->pos.x, -a->pos.x, &dl.x);
    dh.y = c2d_two_sum(b->pos.y, -a->pos.y, &dl.y);
    if (!c2d_finite4(dh.x, dh.y, 0, 0)) { /* the same direction, halved */
        dh.x = c2d_two_sum(b->pos.x * (c2d_real)0.5, -a->pos.x * (c2d_real)0.5, &dl.x);
        dh.y = c2d_two_sum(b->pos.y * (c2d_real)0.5, -a->pos.y * (c2d_real)0.5, &dl.y);
    }
    len = c2d_unit_normal(&nx, &ny, dh.x, dh.y);
    fast = balls_ordinary && c2d_balls_ordinary(balls, &dh);
    if (fast != 0) { /* finite masses and inertias: the same quotients */
        ia = 1 / a->inertia;
        ib = 1 / b->inertia;
        ima = 1 / a->mass;
        imb = 1 / b->mass;
    } else {
        ia = c2d_sphere_inverse(a->inertia);
        ib = c2d_sphere_inverse(b->inertia);
        ima = c2d_sphere_inverse(a->mass);
        imb = c2d_sphere_inverse(b->mass);
    }
    qa = a->radius * ia;
    qb = b->radius * ib;
    inv_mn = ima + imb;
    ka = a->radius * qa;
    kb = b->radius * qb;
    inv_mt = inv_mn + ka + kb;
    gn = c2d_normal_speed(&dh, &dl, len, nx, ny, &a->vel, &b->vel, fast);
    gt = (dvy * nx - dvx * ny) - (a->radius * a->spin[2] + b->radius * b->spin[2]);
    gz = -(a->radius * (a->spin[0] * ny - a->spin[1] * nx) + b->radius * (b->spin[0] * ny - b->spin[1] * nx));
    g = c2d_sphere_length(gt, gz);
    jn = gn < 0 ? -(1 + s->restitution) * gn / inv_mn : 0;
    fine = fast || (c2d_sphere_fine(ia, ia, 1) && c2d_sphere_fine(ib, ib, 1) && c2d_sphere_fine(qa, a->radius, ia) &&
           c2d_sphere_fine(qb, b->radius, ib) && c2d_sphere_fine(ima, ima, 1) && c2d_sphere_fine(imb, imb, 1) &&
           c2d_sphere_fine(ka, a->radius, qa) && c2d_sphere_fine(kb, b->radius, qb) &&
           c2d_finite4(inv_mt, g, 0, 0) && c2d_sphere_fine(gn, 1, 1) && c2d_sphere_fine(jn, 1, 1) &&
           c2d_ball_spin_fine(a) && c2d_ball_spin_fine(b));
    f = 0;
    if (fine && g != 0) {
        const c2d_real mu = c2d_ball_friction(s, g), cone = mu > C2D_R_MAX ? 1 : mu * jn, stop = g / inv_mt;
        f = c2d_friction_size(mu, jn, stop) / g;
        fast = fast && c2d_sphere_mu_ordinary(mu);
        fine = fast ||
               (c2d_sphere_fine(cone, mu, jn) && c2d_sphere_fine(stop, 1, 1) && c2d_sphere_fine(f, mu, 1));
    }
    jt = -f * gt;
    jz = -f * gz;
    fine = fine && (fast || (c2d_sphere_fine(jt, f, gt) && c2d_sphere_fine(jz, f, gz) &&
                             c2d_sphere_fine(qa * jt, qa, jt) && c2d_sphere_fine(qa * jz, qa, jz) &&
                             c2d_sphere_fine(qb * jt, qb, jt) && c2d_sphere_fine(qb * jz, qb, jz)));
    c2d_ball_friction_apply(&oa, &ta->vel, a, ima, qa, nx, ny, jt, jz, -1);
    c2d_ball_friction_apply(&ob, &tb->vel, b, imb, qb, nx, ny, jt, jz, 1);
    fine = fine && (fast || (c2d_ball_out_finite(&oa) && c2d_ball_out_finite(&ob)));
    if (!fine) return c2d_balls_friction_dd(a, b, ta, tb, s);
    c2d_ball_write(a, &oa);
    c2d_ball_write(b, &ob);
    return C2D_OK;
}

/* Both balls valid when both are in the window (every field but the
 * position finite, masses, inertias and radii positive): the positions
 * finite. */
static int c2d_balls_valid_ordinary(const c2d_real_ball *a, const c2d_real_ball *b)
{
    return c2d_finite4(a->pos.x, a->pos.y, b->pos.x, b->pos.y);
}

static c2d_status c2d_real_collide_balls(c2d_real_ball *a, c2d_real_ball *b, const c2d_real_ball_surface *s)
{
    c2d_real_body ta, tb;
    c2d_status st;
    c2d_sphere_span w;
    int valid, ordinary;
    if (a == NULL || b == NULL) return C2D_INVALID;
    c2d_span_start(&w);
    c2d_ball_span(&w, a);
    c2d_ball_span(&w, b);
    ordinary = c2d_span_ordinary(&w) && c2d_balls_sizes_ordinary(a, b);
    valid = ordinary ? c2d_balls_valid_ordinary(a, b) : (c2d_ball_valid(a) && c2d_ball_valid(b));
    if (!valid || !c2d_ball_surface_valid(s)) return C2D_INVALID;
    if (a == b) return C2D_DEGENERATE;
    c2d_ball_body(&ta, a);
    c2d_ball_body(&tb, b);
    st = c2d_real_collide(&ta, &tb, s->restitution);
    if (st != C2D_OK) return st;
    if (s->friction == 0 && s->friction_boost == 0) {
        a->vel.x = ta.vel.x;
        a->vel.y = ta.vel.y;
        b->vel.x = tb.vel.x;
        b->vel.y = tb.vel.y;
        return C2D_OK;
    }
    return c2d_balls_friction(a, b, &ta, &tb, s, &w, ordinary);
}

/* A rail: restitution in [0, 1], friction >= 0 (INFINITY: never slides),
 * height in [R, 2R], a finite normal. */
static int c2d_cushion_valid(const c2d_real_cushion *c, const c2d_real_ball *d)
{
    return c2d_finite4(c->normal.x, c->normal.y, c->height, 0) && c->restitution >= 0 && c->restitution <= 1 &&
           c->friction >= 0 && d->radius > 0 && d->mass <= C2D_R_MAX && c->height >= d->radius &&
           c->height <= 2 * d->radius;
}

/* The ball's change under P = -pn nu + f1 t^ + f2 e2 (the derivation above),
 * in the table's axes. */
static void c2d_cushion_apply(c2d_ball_out *o, const c2d_real_ball *d, c2d_real nx, c2d_real ny, c2d_real sn,
                              c2d_real cs, c2d_real pn, c2d_real f1, c2d_real f2)
{
    c2d_real im = 1 / d->mass, q = d->radius * c2d_sphere_inverse(d->inertia);
    c2d_real dvn = -(pn * cs + f2 * sn) * im, dvt = f1 * im;
    c2d_real dwn = -q * f1 * sn, dwt = -q * f2, dwz = q * f1 * cs;
    o->v[0] = d->vel.x + (dvn * nx - dvt * ny);
    o->v[1] = d->vel.y + (dvn * ny + dvt * nx);
    o->w[0] = d->spin[0] + (dwn * nx - dwt * ny);
    o->w[1] = d->spin[1] + (dwn * ny + dwt * nx);
    o->w[2] = d->spin[2] + dwz;
}

/* sin(th) = d / R, d = h - R (exact: R <= h <= 2R), and cos(th) =
 * sqrt((1 - sin)(1 + sin)).  Near h = 2R cos(th) is small and 1 - sin(th)
 * from the rounded sin would carry its u/2 over 1 - sin: a relative error
 * u / cos^2(th) in cos, which the sliding friction (mu Pn, Pn ~ cos) takes
 * to the spins.  So 1 - sin = (R - d) / R, R - d exact when d >= R/2
 * (Sterbenz) and 1 - sin >= 1/2 otherwise: cos within ~2u either way. */
static c2d_real c2d_cushion_tilt(c2d_real radius, c2d_real height, c2d_real *cs)
{
    c2d_real d = height - radius;
    *cs = C2D_R_SQRT(((radius - d) / radius) * (1 + d / radius));
    return d / radius;
}

/* A cushion's impact in dd (the slow path of c2d_collide_cushion; the
 * derivation above, every step in double length). */
C2D_COLD c2d_status c2d_cushion_dd(c2d_real_ball *d, const c2d_real_cushion *c)
{
    c2d_dd_vec n;
    c2d_dd x, y, len, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, a, stop, lambda, f, f1, f2, q, dvn, dvt, dwn, dwt, dwz;
    c2d_dd one;
    c2d_ball_out o;
    c2d_sphere_dd_prod(&x, c->normal.x, c->normal.x);
    c2d_sphere_dd_prod(&y, c->normal.y, c->normal.y);
    c2d_dd_add(&x, &x, &y, 1);
    c2d_dd_sqrt(&len, &x);
    c2d_dd_of(&x, c->normal.x);
    c2d_dd_div(&n.x, &x, &len);
    c2d_dd_of(&x, c->normal.y);
    c2d_dd_div(&n.y, &x, &len);
    c2d_dd_of(&one, 1);
    c2d_dd_of(&x, c->height - d->radius); /* exact: R <= h <= 2R */
    c2d_dd_of(&y, d->radius);
    c2d_dd_div(&sn, &x, &y);
    c2d_dd_add(&x, &one, &sn, -1); /* cos = sqrt((1 - sin)(1 + sin)) */
    c2d_dd_add(&y, &one, &sn, 1);
    c2d_dd_mul(&x, &x, &y);
    c2d_dd_sqrt(&cs, &x);
    c2d_sphere_dd_dot(&vn, &n, d->vel.x, d->vel.y);
    c2d_sphere_dd_dot(&vt, &n, d->vel.y, -d->vel.x);
    c2d_sphere_dd_dot(&wn, &n, d->spin[0], d->spin[1]);
    c2d_sphere_dd_dot(&wt, &n, d->spin[1], -d->spin[0]);
    c2d_dd_mul(&pn, &cs, &vn); /* Pn = (1 + e) m cos(th) vn */
    c2d_sphere_dd_times(&pn, &pn, d->mass);
    c2d_sphere_dd_times(&pn, &pn, 1 + c->restitution);
    c2d_sphere_dd_times(&x, &cs, d->spin[2]); /* s1 = vt + R (cs wz - sn wn) */
    c2d_dd_mul(&y, &sn, &wn);
    c2d_dd_add(&x, &x, &y, -1);
    c2d_sphere_dd_times(&x, &x, d->radius);
    c2d_dd_add(&s1, &vt, &x, 1);
    c2d_dd_mul(&x, &sn, &vn); /* s2 = -(sn vn + R wt) */
    c2d_sphere_dd_times(&y, &wt, d->radius);
    c2d_dd_add(&s2, &x, &y, 1);
    c2d_dd_negate(&s2);
    c2d_sphere_dd_hypot(&sl, &s1, &s2);
    c2d_dd_of(&f, 0);
    if (sl.h != 0) {
        c2d_sphere_dd_over(&a, &one, d->mass); /* A = 1/m + R^2/I */
        c2d_sphere_dd_prod(&x, d->radius, d->radius);
        c2d_sphere_dd_over(&x, &x, d->inertia);
        c2d_dd_add(&a, &a, &x, 1);
        c2d_dd_div(&stop, &sl, &a);
        c2d_sphere_dd_size(&lambda, c->friction, &pn, &stop);
        c2d_dd_div(&f, &lambda, &sl);
    }
    c2d_dd_mul(&f1, &f, &s1);
    c2d_dd_negate(&f1);
    c2d_dd_mul(&f2, &f, &s2);
    c2d_dd_negate(&f2);
    c2d_dd_mul(&x, &pn, &cs); /* dvn = -(pn cs + f2 sn) / m, dvt = f1 / m */
    c2d_dd_mul(&y, &f2, &sn);
    c2d_dd_add(&x, &x, &y, 1);
    c2d_dd_negate(&x);
    c2d_sphere_dd_over(&dvn, &x, d->mass);
    c2d_sphere_dd_over(&dvt, &f1, d->mass);
    c2d_dd_of(&x, d->radius); /* q = R / I; dwn = -q f1 sn, dwt = -q f2, dwz = q f1 cs */
    c2d_sphere_dd_over(&q, &x, d->inertia);
    c2d_dd_mul(&x, &q, &f1);
    c2d_dd_mul(&dwn, &x, &sn);
    c2d_dd_negate(&dwn);
    c2d_dd_mul(&dwz, &x, &cs);
    c2d_dd_mul(&dwt, &q, &f2);
    c2d_dd_negate(&dwt);
    c2d_dd_mul(&x, &dvn, &n.x); /* back to the table's axes: n^ = (nx, ny), t^ = (-ny, nx) */
    c2d_dd_mul(&y, &dvt, &n.y);
    c2d_dd_add(&x, &x, &y, -1);
    o.v[0] = c2d_plus(d->vel.x, &x);
    c2d_dd_mul(&x, &dvn, &n.y);
    c2d_dd_mul(&y, &dvt, &n.x);
    c2d_dd_add(&x, &x, &y, 1);
    o.v[1] = c2d_plus(d->vel.y, &x);
    c2d_dd_mul(&x, &dwn, &n.x);
    c2d_dd_mul(&y, &dwt, &n.y);
    c2d_dd_add(&x, &x, &y, -1);
    o.w[0] = c2d_plus(d->spin[0], &x);
    c2d_dd_mul(&x, &dwn, &n.y);
    c2d_dd_mul(&y, &dwt, &n.x);
    c2d_dd_add(&x, &x, &y, 1);
    o.w[1] = c2d_plus(d->spin[1], &x);
    o.w[2] = c2d_plus(d->spin[2], &dwz);
    if (!c2d_ball_out_finite(&o)) return C2D_RANGE;
    c2d_ball_write(d, &o);
    return C2D_OK;
}

/* Plainly, each step checked as for two balls; any value out of the
 * normal range sends the impact to c2d_cushion_dd. */
static c2d_status c2d_real_collide_cushion(c2d_real_ball *d, const c2d_real_cushion *c)
{
    c2d_real nx, ny, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, f, len, im, ii, rr, k, u, q, f1, f2, qf;
    c2d_real_vec zero = {0, 0};
    c2d_ball_out o;
    c2d_sphere_span w;
    int fine, fast, ordinary;
    if (d == NULL) return C2D_INVALID;
    c2d_span_start(&w);
    c2d_ball_span(&w, d);
    ordinary = c2d_span_ordinary(&w) && c2d_balls_sizes_ordinary(d, d);
    if (!(ordinary ? c2d_finite4(d->pos.x, d->pos.y, 0, 0) : c2d_ball_valid(d)) || !c2d_cushion_valid(c, d))
        return C2D_INVALID;
    if (c->normal.x == 0 && c->normal.y == 0) return C2D_DEGENERATE;
    len = c2d_unit_normal(&nx, &ny, c->normal.x, c->normal.y);
    sn = c2d_cushion_tilt(d->radius, c->height, &cs);
    c2d_span_add(&w, c->normal.x);
    c2d_span_add(&w, c->normal.y);
    c2d_span_add(&w, cs);
    fast = ordinary && c2d_span_ordinary(&w) && c2d_sphere_mu_ordinary(c->friction);
    vn = c2d_normal_speed(&c->normal, &zero, len, nx, ny, &zero, &d->vel, fast);
    if (!(vn > 0) || sn == 1) return C2D_SEPARATING; /* sn = 1 exactly when h = 2R */
    u = cs * vn;
    vt = d->vel.y * nx - d->vel.x * ny;
    wn = d->spin[0] * nx + d->spin[1] * ny;
    wt = d->spin[1] * nx - d->spin[0] * ny;
    pn = (1 + c->restitution) * d->mass * u;
    s1 = vt + d->radius * (cs * d->spin[2] - sn * wn);
    s2 = -sn * vn - d->radius * wt;
    sl = c2d_sphere_length(s1, s2);
    im = 1 / d->mass;
    ii = fast ? 1 / d->inertia : c2d_sphere_inverse(d->inertia);
    rr = d->radius * d->radius;
    k = rr * ii;
    q = d->radius * ii;
    fine = fast || (c2d_sphere_fine(vn, 1, 1) && c2d_sphere_fine(u, 1, 1) && c2d_sphere_fine(pn, 1, 1) &&
                    c2d_finite4(sl, 0, 0, 0) && c2d_sphere_fine(im, 1, 1) && c2d_sphere_fine(ii, ii, 1) &&
                    c2d_sphere_fine(rr, 1, 1) && c2d_sphere_fine(k, ii, 1) && c2d_sphere_fine(q, ii, 1) &&
                    c2d_ball_spin_fine(d));
    f = 0;
    if (fine && sl != 0) {
        const c2d_real stop = sl / (im + k);
        f = c2d_friction_size(c->friction, pn, stop) / sl;
        fine = fast || (c2d_sphere_fine(stop, 1, 1) && c2d_sphere_fine(f, c->friction, 1) &&
                        (c->friction > C2D_R_MAX || c2d_sphere_fine(c->friction * pn, c->friction, 1)));
    }
    f1 = -f * s1;
    f2 = -f * s2;
    qf = q * f1;
    fine = fine && (fast || (c2d_sphere_fine(f1, f, s1) && c2d_sphere_fine(f2, f, s2) && c2d_sphere_fine(qf, q, f1) &&
                             c2d_sphere_fine(q * f2, q, f2) && c2d_sphere_fine(pn * cs, 1, 1) &&
                             c2d_sphere_fine(f2 * sn, f2, sn)));
    c2d_cushion_apply(&o, d, nx, ny, sn, cs, pn, f1, f2);
    if (!fine || (!fast && !c2d_ball_out_finite(&o))) return c2d_cushion_dd(d, c);
    c2d_ball_write(d, &o);
    return C2D_OK;
}

#endif /* C2D_REAL_SPHERE_H */
