/* SPDX-License-Identifier: MIT */
/* real/rough.h - template: c2d_collide_rough, the impact of two rough disks
 * with friction and spin (Walton's model of rough inelastic disks).
 * Needs real/collide/collide.h, real/arith/sign.h and real/arith/dd.h first.
 *
 * THE MODEL
 *   n^ = n/|n| from a towards b, t^ = (-n^y, n^x) (n^ turned a quarter
 *   counter-clockwise).  Disk a touches at a.pos + ra n^, b at b.pos - rb n^;
 *   with spins w (counter-clockwise, about +z) the contact points move at
 *   va + wa ra t^ and vb - wb rb t^, so b's slides past a's at
 *       g = (vb - va) - (wa ra + wb rb) t^,   gn = g.n^,  gt = g.t^.
 *   An impulse J = Jn n^ + Jt t^ on b (and -J on a) changes
 *       va -= J / ma,  vb += J / mb,  wa -= ra Jt / Ia,  wb -= rb Jt / Ib
 *   (the torque of -J at ra n^ about a's centre is -ra Jt, of J at -rb n^
 *   about b's is -rb Jt), hence gn by Jn (1/ma + 1/mb) and gt by Jt / mt,
 *       1/mt = 1/ma + 1/mb + ra^2/Ia + rb^2/Ib.
 *   Normal: Newton's restitution, gn' = -e gn, only if gn < 0: exactly
 *   c2d_collide's impulse, so the velocities it computes are reused as they
 *   are.  Tangential: the sticking impulse that makes gt' = -beta gt,
 *       Js = -(1 + beta) gt mt,
 *   unless |Js| > mu Jn (Coulomb's cone); then Jt = -mu Jn sign(gt), sliding.
 *   mu = 0 or beta = -1 give Jt = 0: c2d_collide's velocities, bit for bit,
 *   spins untouched.  The choice is continuous (both are equal on the cone).
 *
 * CONSERVATION (exact arithmetic)
 *   Linear momentum: J and -J.  Angular momentum about any point P when the
 *   disks touch (|pb - pa| = ra + rb): the impulses act at the one contact
 *   point, so their moments about P cancel.  Energy: the normal part loses
 *   (1 - e^2) mn gn^2 / 2; the tangential part changes it by
 *   Jt (gt + gt') / 2, which is -(1 - beta^2) mt gt^2 / 2 <= 0 when sticking
 *   and negative when sliding (|Jt| < |Js| and opposite to gt): energy never
 *   grows, and e = beta = 1 keeps it all.
 *
 * ACCURACY
 *   gt vanishes for rolling contact however fast the disks move, so it is
 *   computed in double length (real/arith/dd.h) from exact sums: (vb - va).(-ny, nx)
 *   and wa ra + wb rb exactly, |n| to u^2, gt to u |gt| + O(u^2) of the
 *   speeds.  Each output is then the normal result plus the tangential change
 *   rounded once: within c2d_collide's bound plus 2 ulp of the body's scale.
 */
#ifndef C2D_REAL_ROUGH_H
#define C2D_REAL_ROUGH_H

static int c2d_disk_valid(const c2d_real_disk *d)
{
    return c2d_finite4(d->pos.x, d->pos.y, d->vel.x, d->vel.y) && c2d_finite4(d->spin, d->radius, 0, 0) &&
           d->mass > 0 && d->radius >= 0 && d->inertia > 0;
}

static int c2d_surface_valid(const c2d_real_surface *s)
{
    return s->restitution >= 0 && s->restitution <= 1 && s->friction >= 0 && s->tangential_restitution >= -1 &&
           s->tangential_restitution <= 1;
}

static void c2d_disk_body(c2d_real_body *body, const c2d_real_disk *d)
{
    body->pos.x = d->pos.x;
    body->pos.y = d->pos.y;
    body->vel.x = d->vel.x;
    body->vel.y = d->vel.y;
    body->mass = d->mass;
}

/* r = x / y, or 0 when y is infinite (an immovable body's inverse mass, a
 * spin that never changes). */
static void c2d_dd_ratio(c2d_dd *r, const c2d_dd *x, c2d_real y)
{
    c2d_dd dy;
    if (y > C2D_R_MAX) {
        c2d_dd_of(r, 0);
        return;
    }
    c2d_dd_of(&dy, y);
    c2d_dd_div(r, x, &dy);
}

/* r = x * y for a floating y. */
static void c2d_dd_scale(c2d_dd *r, const c2d_dd *x, c2d_real y)
{
    c2d_dd dy;
    c2d_dd_of(&dy, y);
    c2d_dd_mul(r, x, &dy);
}

/* The contact's geometry and slip, in double length. */
typedef struct c2d_rough_contact {
    c2d_dd t[2];   /* t^ = (-ny, nx) / |n| */
    c2d_dd gn, gt; /* normal and tangential slip speeds */
} c2d_rough_contact;

/* n (exact, hi + lo per axis, extended) and vb - va likewise. */
static void c2d_rough_vectors(c2d_ext n[2][2], c2d_ext r[2][2], const c2d_real_disk *a, const c2d_real_disk *b,
                              const c2d_real_vec *normal)
{
    if (normal != NULL) {
        c2d_ext_set(&n[0][0], normal->x, 0);
        c2d_ext_set(&n[1][0], normal->y, 0);
        c2d_ext_set(&n[0][1], 0, 0);
        c2d_ext_set(&n[1][1], 0, 0);
    } else {
        c2d_exact_diff(b->pos.x, a->pos.x, &n[0][0], &n[0][1]);
        c2d_exact_diff(b->pos.y, a->pos.y, &n[1][0], &n[1][1]);
    }
    c2d_exact_diff(b->vel.x, a->vel.x, &r[0][0], &r[0][1]);
    c2d_exact_diff(b->vel.y, a->vel.y, &r[1][0], &r[1][1]);
}

static void c2d_rough_contact_of(c2d_rough_contact *c, const c2d_real_disk *a, const c2d_real_disk *b,
                                 const c2d_real_vec *normal)
{
    c2d_ext n[2][2], r[2][2];
    c2d_acc acc;
    c2d_dd len, x, y;
    c2d_rough_vectors(n, r, a, b, normal);
    c2d_acc_clear(&acc); /* |n| */
    c2d_acc_pair_product(&acc, n[0], n[0], 1);
    c2d_acc_pair_product(&acc, n[1], n[1], 1);
    c2d_dd_of_acc(&x, &acc);
    c2d_dd_sqrt(&len, &x);
    c2d_acc_clear(&acc); /* gn = (vb - va).n / |n| */
    c2d_acc_pair_product(&acc, r[0], n[0], 1);
    c2d_acc_pair_product(&acc, r[1], n[1], 1);
    c2d_dd_of_acc(&x, &acc);
    c2d_dd_div(&c->gn, &x, &len);
    c2d_acc_clear(&acc); /* gt = (vb - va).(-ny, nx) / |n| - (wa ra + wb rb) */
    c2d_acc_pair_product(&acc, r[1], n[0], 1);
    c2d_acc_pair_product(&acc, r[0], n[1], -1);
    c2d_dd_of_acc(&x, &acc);
    c2d_dd_div(&x, &x, &len);
    c2d_acc_clear(&acc);
    c2d_acc_product_of(&acc, a->spin, a->radius, 1);
    c2d_acc_product_of(&acc, b->spin, b->radius, 1);
    c2d_dd_of_acc(&y, &acc);
    c2d_dd_add(&c->gt, &x, &y, -1);
    c2d_dd_set(&x, n[1][0].m, 0, n[1][0].e); /* t^ = (-ny, nx) / |n| */
    c2d_dd_set(&y, n[1][1].m, 0, n[1][1].e);
    c2d_dd_add(&x, &x, &y, 1);
    c2d_dd_negate(&x);
    c2d_dd_div(&c->t[0], &x, &len);
    c2d_dd_set(&x, n[0][0].m, 0, n[0][0].e);
    c2d_dd_set(&y, n[0][1].m, 0, n[0][1].e);
    c2d_dd_add(&x, &x, &y, 1);
    c2d_dd_div(&c->t[1], &x, &len);
}

/* jt = the tangential impulse: sticking, or sliding on Coulomb's cone. */
static void c2d_rough_impulse(c2d_dd *jt, const c2d_rough_contact *c, const c2d_real_disk *a, const c2d_real_disk *b,
                              const c2d_real_surface *s)
{
    c2d_dd one, ia, ib, ka, kb, mn_inv, mt_inv, x, cone;
    c2d_dd_of(&one, 1);
    c2d_dd_ratio(&ia, &one, a->mass); /* 1/ma, 1/mb, ra^2/Ia, rb^2/Ib */
    c2d_dd_ratio(&ib, &one, b->mass);
    c2d_dd_of(&x, a->radius);
    c2d_dd_scale(&x, &x, a->radius);
    c2d_dd_ratio(&ka, &x, a->inertia);
    c2d_dd_of(&x, b->radius);
    c2d_dd_scale(&x, &x, b->radius);
    c2d_dd_ratio(&kb, &x, b->inertia);
    c2d_dd_add(&mn_inv, &ia, &ib, 1);
    c2d_dd_add(&x, &ka, &kb, 1);
    c2d_dd_add(&mt_inv, &mn_inv, &x, 1);
    c2d_dd_scale(&x, &c->gt, 1 + s->tangential_restitution); /* sticking: -(1 + beta) gt mt */
    c2d_dd_div(jt, &x, &mt_inv);
    c2d_dd_negate(jt);
    if (s->friction > C2D_R_MAX) return; /* mu = INFINITY: never slides */
    c2d_dd_scale(&x, &c->gn, -(1 + s->restitution)); /* the cone: mu Jn = mu (1 + e) (-gn) mn */
    c2d_dd_scale(&x, &x, s->friction);
    c2d_dd_div(&cone, &x, &mn_inv);
    if (!c2d_dd_abs_greater(jt, &cone)) return;
    jt->h = cone.h; /* field by field: no memcpy */
    jt->l = cone.l;
    jt->e = cone.e;
    if (c2d_dd_sign(&c->gt) > 0) c2d_dd_negate(jt);
}

/* x + dv, rounded once; x itself when nothing changes (so -0 stays -0). */
static c2d_real c2d_plus(c2d_real x, const c2d_dd *dv)
{
    c2d_dd sum;
    if (dv->h == 0) return x;
    c2d_dd_of(&sum, x);
    c2d_dd_add(&sum, &sum, dv, 1);
    return c2d_dd_value(&sum);
}

/* The velocity and spin changes of one disk under the impulse sign * jt t^
 * at the contact, applied on top of the normal result v: out = {vx, vy, w}. */
static void c2d_rough_apply(c2d_real *out, const c2d_real_vec *v, const c2d_real_disk *d, const c2d_dd *jt, int sign,
                            const c2d_rough_contact *c)
{
    c2d_dd dv, x;
    c2d_dd_ratio(&dv, jt, d->mass);
    if (sign < 0) c2d_dd_negate(&dv);
    c2d_dd_mul(&x, &dv, &c->t[0]);
    out[0] = c2d_plus(v->x, &x);
    c2d_dd_mul(&x, &dv, &c->t[1]);
    out[1] = c2d_plus(v->y, &x);
    c2d_dd_scale(&x, jt, d->radius); /* both spins: -r Jt / I */
    c2d_dd_ratio(&x, &x, d->inertia);
    c2d_dd_negate(&x);
    out[2] = c2d_plus(d->spin, &x);
}

/* The tangential impulse applied on top of the normal result (ta, tb). */
C2D_COLD c2d_status c2d_rough_tangential(c2d_real_disk *a, c2d_real_disk *b, const c2d_real_body *ta,
                                         const c2d_real_body *tb, const c2d_real_vec *normal,
                                         const c2d_real_surface *s)
{
    c2d_rough_contact c;
    c2d_dd jt;
    c2d_real oa[3], ob[3];
    c2d_rough_contact_of(&c, a, b, normal);
    c2d_rough_impulse(&jt, &c, a, b, s);
    c2d_rough_apply(oa, &ta->vel, a, &jt, -1, &c);
    c2d_rough_apply(ob, &tb->vel, b, &jt, 1, &c);
    if (!c2d_finite4(oa[0], oa[1], oa[2], 0) || !c2d_finite4(ob[0], ob[1], ob[2], 0)) return C2D_RANGE;
    a->vel.x = oa[0];
    a->vel.y = oa[1];
    a->spin = oa[2];
    b->vel.x = ob[0];
    b->vel.y = ob[1];
    b->spin = ob[2];
    return C2D_OK;
}

/* c2d_collide_rough (normal NULL: the line of centres) and
 * c2d_collide_rough_normal. */
static c2d_status c2d_real_collide_rough(c2d_real_disk *a, c2d_real_disk *b, const c2d_real_vec *normal,
                                         const c2d_real_surface *s)
{
    c2d_real_body ta, tb;
    c2d_status st;
    if (a == NULL || b == NULL || !c2d_disk_valid(a) || !c2d_disk_valid(b) || !c2d_surface_valid(s)) return C2D_INVALID;
    if (normal != NULL && !c2d_finite4(normal->x, normal->y, 0, 0)) return C2D_INVALID;
    if (a == b) return C2D_DEGENERATE;
    c2d_disk_body(&ta, a);
    c2d_disk_body(&tb, b);
    st = normal == NULL ? c2d_real_collide(&ta, &tb, s->restitution)
                        : c2d_real_collide_normal(&ta, &tb, normal, s->restitution);
    if (st != C2D_OK) return st;
    if (s->friction == 0 || s->tangential_restitution == -1) {
        a->vel.x = ta.vel.x;
        a->vel.y = ta.vel.y;
        b->vel.x = tb.vel.x;
        b->vel.y = tb.vel.y;
        return C2D_OK;
    }
    return c2d_rough_tangential(a, b, &ta, &tb, normal, s);
}

#endif /* C2D_REAL_ROUGH_H */
