/* SPDX-License-Identifier: MIT */
/* fuzz_rough_template.h - template: the fuzz checks of the rough contact
 * (c2d_collide_rough, c2d_collide_rough_normal) in one floating type.
 * Included after fuzz_template.h (its body helpers) by fuzz_double.c and
 * fuzz_float.c; the type header names, besides fuzz_template.h's,
 *   C2D_T_DISK, C2D_T_SURFACE
 *   C2D_T_COLLIDE_ROUGH, C2D_T_COLLIDE_ROUGH_NORMAL
 *   C2D_T_READ_FRICTION, C2D_T_READ_BETA   decoders (decode.c)
 *   C2D_T_LIMIT                            the largest finite value
 *
 * Why these checks.  The header promises: the status of c2d_collide for the
 * normal part, INVALID also for a bad field only the rough contact reads,
 * in the same priority (the referee, referee/ref_rough.c, decides it
 * exactly); on OK only velocities and spins written, each component and
 * spin x radius within 18 ulp of the body's scale (16 of c2d_collide plus
 * 2); an immovable body keeps its velocity and an infinite inertia its
 * spin; mu = 0 or beta = -1 is c2d_collide bit for bit, spins untouched;
 * momentum conserved and energy never gained.  Momentum and energy follow
 * from the 18 ulp as in bounds.c, with delta = 18 ulp of the scale S:
 *   momentum:  |sum m v' - sum m v| <= sum m delta per axis;
 *   energy:    per velocity component m (v'^2 - v^2) <= m delta (2 S + delta),
 *              per spin (its error <= delta / r, |w r| <= S)
 *              I (w'^2 - w^2) <= (I / r^2) delta (2 S + delta);
 * in the frame of an immovable body if there is one (the response depends
 * only on relative velocities).  A body of infinite inertia that spins (with
 * a radius) drives the contact point like a motor: its energy I w^2 / 2 is
 * infinite and it may give the other body energy, so no energy check then.
 * A zero radius feels no torque: its spin is unchanged.  Sums in long double with 8 LDBL_EPSILON of slack, as bounds.c. */

#define C2D_FUZZ_ROUGH_BOUND_ULP 18

static void c2d_num_read_disk(c2d_fuzz_reader *r, C2D_T_DISK *d)
{
    d->pos.x = C2D_T_READ(r);
    d->pos.y = C2D_T_READ(r);
    d->vel.x = C2D_T_READ(r);
    d->vel.y = C2D_T_READ(r);
    d->spin = C2D_T_READ(r);
    d->mass = C2D_T_READ_MASS(r);
    d->radius = C2D_T_READ(r);
    d->inertia = C2D_T_READ_MASS(r);
    if (r->mode == C2D_FUZZ_TAME) d->radius = C2D_T_FABS(d->radius);
}

static void C2D_T_DISK_to_ref(const C2D_T_DISK *d, ref_disk *o)
{
    o->pos[0] = d->pos.x, o->pos[1] = d->pos.y, o->vel[0] = d->vel.x, o->vel[1] = d->vel.y;
    o->spin = d->spin, o->mass = d->mass, o->radius = d->radius, o->inertia = d->inertia;
}

static void C2D_T_DISK_to_body(const C2D_T_DISK *d, c2d_num_body *o)
{
    o->pos = d->pos, o->vel = d->vel, o->mass = d->mass;
}

static void c2d_num_describe_rough(const C2D_T_DISK *a, const C2D_T_DISK *b, const c2d_num_vec *n,
                                   C2D_T_SURFACE s)
{
    c2d_fuzz_describe("a={{%a,%a},{%a,%a},w=%a,m=%a,r=%a,I=%a} b={{%a,%a},{%a,%a},w=%a,m=%a,r=%a,I=%a} n=%s{%a,%a} "
                      "e=%a mu=%a beta=%a",
                      (double)a->pos.x, (double)a->pos.y, (double)a->vel.x, (double)a->vel.y, (double)a->spin,
                      (double)a->mass, (double)a->radius, (double)a->inertia, (double)b->pos.x, (double)b->pos.y,
                      (double)b->vel.x, (double)b->vel.y, (double)b->spin, (double)b->mass, (double)b->radius,
                      (double)b->inertia, n ? "" : "(line of centres) ", n ? (double)n->x : 0.0,
                      n ? (double)n->y : 0.0, (double)s.restitution, (double)s.friction,
                      (double)s.tangential_restitution);
}

static c2d_status c2d_num_rough_call(C2D_T_DISK *a, C2D_T_DISK *b, const c2d_num_vec *n, C2D_T_SURFACE s)
{
    return n ? C2D_T_COLLIDE_ROUGH_NORMAL(a, b, *n, s) : C2D_T_COLLIDE_ROUGH(a, b, s);
}

/* The fields c2d_collide does not read are valid (the surface's friction
 * and beta included), so the rough status is the smooth one. */
static int c2d_num_rough_fields_valid(const C2D_T_DISK *a, const C2D_T_DISK *b, C2D_T_SURFACE s)
{
    const C2D_T_DISK *d[2];
    int j;
    d[0] = a, d[1] = b;
    for (j = 0; j < 2; j++)
        if (!isfinite(d[j]->spin) || !isfinite(d[j]->radius) || !(d[j]->radius >= 0) || !(d[j]->inertia > 0))
            return 0;
    return s.friction >= 0 && s.tangential_restitution >= -1 && s.tangential_restitution <= 1;
}

/* friction 0 or beta -1: c2d_collide's status and velocities, bit for
 * bit, the spins untouched. */
static void c2d_num_check_rough_identity(const C2D_T_DISK *a0, const C2D_T_DISK *b0, const c2d_num_vec *n,
                                         C2D_T_SURFACE s, const char *which)
{
    C2D_T_DISK a = *a0, b = *b0;
    c2d_num_body ba, bb;
    c2d_status rough, smooth;
    C2D_T_DISK_to_body(a0, &ba);
    C2D_T_DISK_to_body(b0, &bb);
    rough = c2d_num_rough_call(&a, &b, n, s);
    smooth = n ? C2D_T_COLLIDE_NORMAL(&ba, &bb, *n, s.restitution) : C2D_T_COLLIDE(&ba, &bb, s.restitution);
    if (!c2d_num_rough_fields_valid(a0, b0, s)) {
        if (rough != C2D_INVALID) c2d_fuzz_fail("%s: a bad rough field but status %s", which, c2d_status_string(rough));
        return;
    }
    if (rough != smooth)
        c2d_fuzz_fail("%s: status %s, c2d_collide %s", which, c2d_status_string(rough), c2d_status_string(smooth));
    if (rough != C2D_OK) return;
    if (memcmp(&a.vel, &ba.vel, sizeof a.vel) != 0 || memcmp(&b.vel, &bb.vel, sizeof b.vel) != 0)
        c2d_fuzz_fail("%s: velocities (%a,%a) (%a,%a) differ from c2d_collide's (%a,%a) (%a,%a)", which,
                      (double)a.vel.x, (double)a.vel.y, (double)b.vel.x, (double)b.vel.y, (double)ba.vel.x,
                      (double)ba.vel.y, (double)bb.vel.x, (double)bb.vel.y);
    if (memcmp(&a.spin, &a0->spin, sizeof a.spin) != 0 || memcmp(&b.spin, &b0->spin, sizeof b.spin) != 0)
        c2d_fuzz_fail("%s: a spin was written", which);
}

/* On OK: only velocities and spins written, all finite; immovable bodies
 * keep their velocity, infinite inertia or no radius their spin, bit for
 * bit: a velocity or spin of -0 comes back -0 (it used to come
 * back +0, which regress-roughf-immovable-negative-zero records). */
static void c2d_num_check_rough_written(const C2D_T_DISK *a0, const C2D_T_DISK *b0, const C2D_T_DISK *a,
                                        const C2D_T_DISK *b)
{
    const C2D_T_DISK *d0[2], *d[2];
    int j;
    d0[0] = a0, d0[1] = b0, d[0] = a, d[1] = b;
    for (j = 0; j < 2; j++) {
        C2D_T_DISK back = *d[j];
        back.vel = d0[j]->vel, back.spin = d0[j]->spin;
        if (memcmp(&back, d0[j], sizeof back) != 0) c2d_fuzz_fail("OK but %c's position, mass, radius or inertia was written", "ab"[j]);
        if (!isfinite(d[j]->vel.x) || !isfinite(d[j]->vel.y) || !isfinite(d[j]->spin))
            c2d_fuzz_fail("OK with a non-finite output in %c", "ab"[j]);
        if (isinf(d0[j]->mass) && memcmp(&d[j]->vel, &d0[j]->vel, sizeof d[j]->vel) != 0)
            c2d_fuzz_fail("immovable body %c's velocity changed (bits)", "ab"[j]);
        if ((isinf(d0[j]->inertia) || d0[j]->radius == 0) && memcmp(&d[j]->spin, &d0[j]->spin, sizeof d[j]->spin) != 0)
            c2d_fuzz_fail("%c's spin changed (inertia %a, radius %a)", "ab"[j], (double)d0[j]->inertia,
                          (double)d0[j]->radius);
    }
}

/* Body j's scale (largest of |vx|, |vy|, |spin r| before and after) and
 * the 18-ulp error its outputs may carry. */
static long double c2d_num_rough_delta(const C2D_T_DISK *d0, const C2D_T_DISK *d, long double *scale)
{
    const long double r = d0->radius;
    long double s = c2d_fuzz_maxabs4(d0->vel.x, d0->vel.y, d->vel.x, d->vel.y);
    if (fabsl(d0->spin * r) > s) s = fabsl(d0->spin * r);
    if (fabsl(d->spin * r) > s) s = fabsl(d->spin * r);
    *scale = s;
    return C2D_FUZZ_ROUGH_BOUND_ULP * c2d_fuzz_ulp(s, c2d_num_fmt);
}

static void c2d_num_check_rough_momentum(const C2D_T_DISK *d0[2], const C2D_T_DISK *d[2], const long double delta[2])
{
    int i, j;
    if (isinf(d0[0]->mass) || isinf(d0[1]->mass)) return;
    for (i = 0; i < 2; i++) {
        long double p0 = 0, p1 = 0, bound = 0, mag = 0;
        for (j = 0; j < 2; j++) {
            const long double m = d0[j]->mass, v = i ? d0[j]->vel.y : d0[j]->vel.x, w = i ? d[j]->vel.y : d[j]->vel.x;
            p0 += m * v, p1 += m * w, bound += m * delta[j], mag += fabsl(m * v) + fabsl(m * w);
        }
        bound += 8 * LDBL_EPSILON * mag;
        if (!(fabsl(p1 - p0) <= bound))
            c2d_fuzz_fail("rough momentum %c: %.21Lg -> %.21Lg (|diff| %.3Lg > bound %.3Lg)", "xy"[i], p0, p1,
                          fabsl(p1 - p0), bound);
    }
}

/* Twice the kinetic energy, translation (in the frame) and rotation. */
static void c2d_num_check_rough_energy(const C2D_T_DISK *d0[2], const C2D_T_DISK *d[2], const long double delta[2],
                                       const long double scale[2])
{
    long double frame[2] = {0, 0}, ke0 = 0, ke1 = 0, bound = 0;
    int i, j;
    for (j = 0; j < 2; j++)
        if (isinf(d0[j]->inertia) && d0[j]->spin != 0 && d0[j]->radius != 0) return;
    for (j = 0; j < 2; j++)
        if (isinf(d0[j]->mass)) frame[0] = d0[j]->vel.x, frame[1] = d0[j]->vel.y;
    for (j = 0; j < 2; j++) {
        const long double m = d0[j]->mass, I = d0[j]->inertia, r = d0[j]->radius;
        if (!isinf(d0[j]->mass)) {
            for (i = 0; i < 2; i++) {
                const long double v = (i ? d0[j]->vel.y : d0[j]->vel.x) - frame[i];
                const long double w = (i ? d[j]->vel.y : d[j]->vel.x) - frame[i];
                ke0 += m * v * v, ke1 += m * w * w;
            }
            bound += 2 * m * delta[j] * (2 * scale[j] + delta[j]);
        }
        if (!isinf(d0[j]->inertia) && r > 0) {
            ke0 += I * (long double)d0[j]->spin * d0[j]->spin;
            ke1 += I * (long double)d[j]->spin * d[j]->spin;
            bound += I / (r * r) * delta[j] * (2 * scale[j] + delta[j]);
        }
    }
    bound += 8 * LDBL_EPSILON * (ke0 + ke1);
    if (!(ke1 - ke0 <= bound))
        c2d_fuzz_fail("rough energy gained: 2KE %.21Lg -> %.21Lg (+%.3Lg > bound %.3Lg)", ke0, ke1, ke1 - ke0, bound);
}

static void c2d_num_check_rough_physics(const C2D_T_DISK *a0, const C2D_T_DISK *b0, const C2D_T_DISK *a,
                                        const C2D_T_DISK *b)
{
    const C2D_T_DISK *d0[2], *d[2];
    long double delta[2], scale[2];
    d0[0] = a0, d0[1] = b0, d[0] = a, d[1] = b;
    delta[0] = c2d_num_rough_delta(a0, a, &scale[0]);
    delta[1] = c2d_num_rough_delta(b0, b, &scale[1]);
    c2d_num_check_rough_momentum(d0, d, delta);
    c2d_num_check_rough_energy(d0, d, delta, scale);
}

/* Status and accuracy against the referee (exact status; outputs in MPFR),
 * RANGE accepted where the referee allows it, as tests/unit/test_rough.c. */
static void c2d_num_check_rough_referee(const C2D_T_DISK *a0, const C2D_T_DISK *b0, const c2d_num_vec *n,
                                        C2D_T_SURFACE s, c2d_status st, const C2D_T_DISK *a, const C2D_T_DISK *b)
{
    static ref_rough_answer ans;
    static int ready;
    ref_rough_case c;
    c2d_status exact;
    double got[6], err;
    if (!ready) ref_rough_init(&ans), ready = 1;
    C2D_T_DISK_to_ref(a0, &c.a);
    C2D_T_DISK_to_ref(b0, &c.b);
    c.has_normal = n != NULL;
    c.n[0] = n ? n->x : 0, c.n[1] = n ? n->y : 0;
    c.e = s.restitution, c.mu = s.friction, c.beta = s.tangential_restitution;
    ref_rough(&c, C2D_T_LIMIT, &ans);
    exact = ans.status;
    if (st == C2D_RANGE && exact == C2D_OK && ans.range_allowed) return;
    if (st == C2D_OK && exact == C2D_RANGE && !ans.range_required) exact = C2D_OK;
    if (st != exact) c2d_fuzz_fail("rough status %s, exact %s", c2d_status_string(st), c2d_status_string(exact));
    if (st != C2D_OK) return;
    got[0] = a->vel.x, got[1] = a->vel.y, got[2] = b->vel.x, got[3] = b->vel.y, got[4] = a->spin, got[5] = b->spin;
    err = ref_rough_err(&c, &ans, got, C2D_T_PREC, C2D_T_EMIN);
    if (!(err <= C2D_FUZZ_ROUGH_BOUND_ULP))
        c2d_fuzz_fail("rough output %.3g ulp of the body's scale from the exact one (bound %d)", err,
                      C2D_FUZZ_ROUGH_BOUND_ULP);
}

static void c2d_num_fuzz_collide_rough(c2d_fuzz_reader *r, int with_normal)
{
    C2D_T_DISK a, b, a0, b0;
    c2d_num_vec n;
    C2D_T_SURFACE s, smooth;
    c2d_status st;
    c2d_num_read_disk(r, &a);
    c2d_num_read_disk(r, &b);
    n.x = C2D_T_READ(r);
    n.y = C2D_T_READ(r);
    s.restitution = C2D_T_READ_RESTITUTION(r);
    s.friction = C2D_T_READ_FRICTION(r);
    s.tangential_restitution = C2D_T_READ_BETA(r);
    c2d_num_describe_rough(&a, &b, with_normal ? &n : NULL, s);
    a0 = a, b0 = b;
    st = c2d_num_rough_call(&a, &b, with_normal ? &n : NULL, s);
    c2d_fuzz_check_status(st);
    if (st == C2D_OK) {
        c2d_num_check_rough_written(&a0, &b0, &a, &b);
        c2d_num_check_rough_physics(&a0, &b0, &a, &b);
    } else {
        c2d_fuzz_check_untouched(&a0, &a, sizeof a, st, "a");
        c2d_fuzz_check_untouched(&b0, &b, sizeof b, st, "b");
    }
    c2d_num_check_rough_referee(&a0, &b0, with_normal ? &n : NULL, s, st, &a, &b);
    smooth = s, smooth.friction = 0;
    c2d_num_check_rough_identity(&a0, &b0, with_normal ? &n : NULL, smooth, "friction 0");
    smooth = s, smooth.tangential_restitution = -1;
    c2d_num_check_rough_identity(&a0, &b0, with_normal ? &n : NULL, smooth, "beta -1");
}
