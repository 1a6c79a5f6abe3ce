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
 *   7.9).
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
    return s->restitution >= 0 && s->restitution <= 1 && s->friction >= 0 &&
           c2d_finite4(s->friction_boost, s->friction_decay, 0, 0) && s->friction_boost >= 0 &&
           s->friction_decay >= 0;
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

/* (vb - va).n^ to a few u of itself.  A glancing impact's normal speed is a
 * cancelling sum, and the normal impulse it gives reaches the spins through
 * mu Jn R^2 / I, which the pair's scale does not bound: plainly (error
 * ~3u (|dvx| + |dvy|)) only when that is within 6u of the result, else
 * from d = dh + dl exactly with exact products (c2d_dot2,
 * real/arith/exact.h), to ~1 ulp. */
static c2d_real c2d_normal_speed(const c2d_real_vec *dh, const c2d_real_vec *dl, c2d_real len, c2d_real nx,
                                 c2d_real ny, const c2d_real_vec *va, const c2d_real_vec *vb)
{
    c2d_real dvx = vb->x - va->x, dvy = vb->y - va->y, gn = dvx * nx + dvy * ny;
    if (2 * c2d_abs(gn) >= c2d_abs(dvx) + c2d_abs(dvy)) return gn;
    return c2d_dot2(dh, dl, va, vb) / len;
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

/* The friction of two balls on top of c2d_collide's normal result (ta, tb). */
static c2d_status c2d_balls_friction(c2d_real_ball *a, c2d_real_ball *b, const c2d_real_body *ta,
                                     const c2d_real_body *tb, const c2d_real_ball_surface *s)
{
    c2d_real nx, ny, gn, gt, gz, g, qa, qb, ima, imb, inv_mn, inv_mt, len, jn, f;
    c2d_real dvx = b->vel.x - a->vel.x, dvy = b->vel.y - a->vel.y;
    c2d_real_vec dh, dl;
    c2d_ball_out oa, ob;
    dh.x = c2d_two_sum(b->pos.x, -a->pos.x, &dl.x);
    dh.y = c2d_two_sum(b->pos.y, -a->pos.y, &dl.y);
    if (!c2d_finite4(dh.x, dh.y, 0, 0)) { /* the same direction, halved */
        dh.x = c2d_two_sum(b->pos.x * (c2d_real)0.5, -a->pos.x * (c2d_real)0.5, &dl.x);
        dh.y = c2d_two_sum(b->pos.y * (c2d_real)0.5, -a->pos.y * (c2d_real)0.5, &dl.y);
    }
    len = c2d_unit_normal(&nx, &ny, dh.x, dh.y);
    qa = a->radius * c2d_sphere_inverse(a->inertia);
    qb = b->radius * c2d_sphere_inverse(b->inertia);
    ima = c2d_sphere_inverse(a->mass);
    imb = c2d_sphere_inverse(b->mass);
    inv_mn = ima + imb;
    inv_mt = inv_mn + a->radius * qa + b->radius * qb;
    gn = c2d_normal_speed(&dh, &dl, len, nx, ny, &a->vel, &b->vel);
    gt = (dvy * nx - dvx * ny) - (a->radius * a->spin[2] + b->radius * b->spin[2]);
    gz = -(a->radius * (a->spin[0] * ny - a->spin[1] * nx) + b->radius * (b->spin[0] * ny - b->spin[1] * nx));
    g = C2D_R_SQRT(gt * gt + gz * gz);
    jn = gn < 0 ? -(1 + s->restitution) * gn / inv_mn : 0;
    if (!c2d_finite4(g, jn, inv_mt, 0)) return C2D_RANGE;
    if (g == 0 || jn == 0) {
        f = 0;
    } else {
        f = c2d_friction_size(c2d_ball_friction(s, g), jn, g / inv_mt) / g;
    }
    c2d_ball_friction_apply(&oa, &ta->vel, a, ima, qa, nx, ny, -f * gt, -f * gz, -1);
    c2d_ball_friction_apply(&ob, &tb->vel, b, imb, qb, nx, ny, -f * gt, -f * gz, 1);
    if (!c2d_ball_out_finite(&oa) || !c2d_ball_out_finite(&ob)) return C2D_RANGE;
    c2d_ball_write(a, &oa);
    c2d_ball_write(b, &ob);
    return C2D_OK;
}

static c2d_status c2d_real_collide_balls(c2d_real_ball *a, c2d_real_ball *b, const c2d_real_ball_surface *s)
{
    c2d_real_body ta, tb;
    c2d_status st;
    if (a == NULL || b == NULL || !c2d_ball_valid(a) || !c2d_ball_valid(b) || !c2d_ball_surface_valid(s))
        return C2D_INVALID;
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
    return c2d_balls_friction(a, b, &ta, &tb, s);
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

static c2d_status c2d_real_collide_cushion(c2d_real_ball *d, const c2d_real_cushion *c)
{
    c2d_real nx, ny, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, f, len;
    c2d_real_vec zero = {0, 0};
    c2d_ball_out o;
    if (d == NULL || !c2d_ball_valid(d) || !c2d_cushion_valid(c, d)) return C2D_INVALID;
    if (c->normal.x == 0 && c->normal.y == 0) return C2D_DEGENERATE;
    len = c2d_unit_normal(&nx, &ny, c->normal.x, c->normal.y);
    sn = c2d_cushion_tilt(d->radius, c->height, &cs);
    vn = c2d_normal_speed(&c->normal, &zero, len, nx, ny, &zero, &d->vel);
    if (!(cs * vn > 0)) return C2D_SEPARATING;
    vt = d->vel.y * nx - d->vel.x * ny;
    wn = d->spin[0] * nx + d->spin[1] * ny;
    wt = d->spin[1] * nx - d->spin[0] * ny;
    pn = (1 + c->restitution) * d->mass * (cs * vn);
    s1 = vt + d->radius * (cs * d->spin[2] - sn * wn);
    s2 = -sn * vn - d->radius * wt;
    sl = C2D_R_SQRT(s1 * s1 + s2 * s2);
    if (!c2d_finite4(pn, sl, 0, 0)) return C2D_RANGE;
    if (sl == 0) {
        f = 0;
    } else {
        f = c2d_friction_size(c->friction, pn, sl / (1 / d->mass + d->radius * d->radius *
                                                             c2d_sphere_inverse(d->inertia))) /
            sl;
    }
    c2d_cushion_apply(&o, d, nx, ny, sn, cs, pn, -f * s1, -f * s2);
    if (!c2d_ball_out_finite(&o)) return C2D_RANGE;
    c2d_ball_write(d, &o);
    return C2D_OK;
}

#endif /* C2D_REAL_SPHERE_H */
