/* SPDX-License-Identifier: MIT */
/* fuzz_sphere_template.h - template: the fuzz checks of the sphere contacts
 * (c2d_collide_balls, c2d_collide_cushion) in one floating type.  Included
 * after fuzz_template.h by fuzz_double.c and fuzz_float.c; the type header
 * names, besides fuzz_template.h's,
 *   C2D_T_BALL, C2D_T_BALL_SURFACE, C2D_T_CUSHION
 *   C2D_T_COLLIDE_BALLS, C2D_T_COLLIDE_CUSHION
 *   C2D_T_READ_FRICTION                    decoder (decode.c)
 *
 * Why these checks.  The header promises: a status of the enum, nothing
 * written unless C2D_OK (bit for bit); on OK only velocities and spins
 * written, all finite; an immovable ball keeps its velocity, an infinite
 * inertia or a zero radius its spin (as values: the update adds a zero
 * change, so -0 may come back +0); each output within 24 ulp of the pair's
 * scale (balls: c2d_collide's 16 plus the friction part's 8) or 16 of the
 * ball's (cushion), the largest |vx|, |vy|, |R w| before and after.  From
 * those bounds, with delta the bound in units and S the scale:
 *   momentum   |sum m v' - sum m v| <= sum m delta per axis (finite masses);
 *   energy     per velocity component m (v'^2 - v^2) <= m delta (2 S + delta),
 *              per spin component (error <= delta / R, |R w| <= S)
 *              I (w'^2 - w^2) <= (I / R^2) delta (2 S + delta);
 *              in the frame of an immovable ball if there is one; none when
 *              a ball of infinite inertia spins with a radius (a motor);
 *   L at the contact, along n^ and z^ (lib/real/sphere.h, CONSERVATION):
 *              I w.n^ moves by at most 2 I delta / R, the lever term
 *              R m (n^ x v) by 2 R m delta plus R m S 4u for the direction
 *              (long double here, the library's to a few u);
 * all sums in long double with 8 LDBL_EPSILON of slack, as bounds.c.  And
 * against the referee (referee/ref_sphere.c, 512-bit MPFR from the model's
 * equations) when every input is within 2^+-C2D_FUZZ_SPHERE_SPAN, the
 * range tests/unit/test_sphere.c sweeps (beyond it the referee's 512 bits
 * are not a certificate): the status (OK or SEPARATING) and the bound. */

#define C2D_FUZZ_BALLS_BOUND_ULP 24
#define C2D_FUZZ_CUSHION_BOUND_ULP 16
#define C2D_FUZZ_SPHERE_SPAN (C2D_T_IS_FLOAT ? 30 : 300)

static void c2d_num_read_ball(c2d_fuzz_reader *r, C2D_T_BALL *d)
{
    int i;
    d->pos.x = C2D_T_READ(r);
    d->pos.y = C2D_T_READ(r);
    d->vel.x = C2D_T_READ(r);
    d->vel.y = C2D_T_READ(r);
    for (i = 0; i < 3; i++) d->spin[i] = C2D_T_READ(r);
    d->mass = C2D_T_READ_MASS(r);
    d->radius = C2D_T_READ(r);
    d->inertia = C2D_T_READ_MASS(r);
    if (r->mode == C2D_FUZZ_TAME) d->radius = C2D_T_FABS(d->radius);
}

static void C2D_T_BALL_to_ref(const C2D_T_BALL *d, ref_ball *o)
{
    int i;
    o->pos[0] = d->pos.x, o->pos[1] = d->pos.y, o->vel[0] = d->vel.x, o->vel[1] = d->vel.y;
    for (i = 0; i < 3; i++) o->w[i] = d->spin[i];
    o->m = d->mass, o->r = d->radius, o->inertia = d->inertia;
}

static void c2d_num_describe_ball(char *out, size_t n, const C2D_T_BALL *d)
{
    snprintf(out, n, "{{%a,%a},{%a,%a},w=(%a,%a,%a),m=%a,r=%a,I=%a}", (double)d->pos.x, (double)d->pos.y,
             (double)d->vel.x, (double)d->vel.y, (double)d->spin[0], (double)d->spin[1], (double)d->spin[2],
             (double)d->mass, (double)d->radius, (double)d->inertia);
}

/* On OK: only velocities and spins written, finite; the immovable, the
 * never-turning and the radius-less keep theirs. */
static void c2d_num_check_ball_written(const C2D_T_BALL *d0, const C2D_T_BALL *d, char name)
{
    C2D_T_BALL back = *d;
    int i;
    back.vel = d0->vel;
    for (i = 0; i < 3; i++) back.spin[i] = d0->spin[i];
    if (memcmp(&back, d0, sizeof back) != 0) c2d_fuzz_fail("OK but %c's position, mass, radius or inertia was written", name);
    if (!isfinite(d->vel.x) || !isfinite(d->vel.y) || !isfinite(d->spin[0]) || !isfinite(d->spin[1]) ||
        !isfinite(d->spin[2]))
        c2d_fuzz_fail("OK with a non-finite output in %c", name);
    if (isinf(d0->mass) && (d->vel.x != d0->vel.x || d->vel.y != d0->vel.y))
        c2d_fuzz_fail("immovable ball %c's velocity changed", name);
    for (i = 0; i < 3; i++)
        if ((isinf(d0->inertia) || d0->radius == 0) && d->spin[i] != d0->spin[i])
            c2d_fuzz_fail("%c's spin %d changed (inertia %a, radius %a)", name, i, (double)d0->inertia,
                          (double)d0->radius);
}

/* The largest |vx|, |vy|, |R w| of a ball before and after, into s. */
static long double c2d_num_ball_scale(const C2D_T_BALL *d0, const C2D_T_BALL *d, long double s)
{
    const long double r = d0->radius;
    int i;
    s = fmaxl(s, c2d_fuzz_maxabs4(d0->vel.x, d0->vel.y, d->vel.x, d->vel.y));
    for (i = 0; i < 3; i++) s = fmaxl(s, fmaxl(fabsl(r * d0->spin[i]), fabsl(r * d->spin[i])));
    return s;
}

/* A ball that spins with a radius and never changes its spin drives the
 * contact like a motor: its energy is infinite and it may give some. */
static int c2d_num_ball_is_motor(const C2D_T_BALL *d)
{
    return isinf(d->inertia) && d->radius != 0 && (d->spin[0] != 0 || d->spin[1] != 0 || d->spin[2] != 0);
}

/* Twice the kinetic energy of a ball in the frame, before and after, and
 * the bound of its increase; ke[0], ke[1], bound accumulate. */
static void c2d_num_ball_energy(const C2D_T_BALL *d0, const C2D_T_BALL *d, const long double frame[2],
                                long double delta, long double scale, long double ke[2], long double *bound)
{
    const long double m = d0->mass, I = d0->inertia, r = d0->radius, grow = delta * (2 * scale + delta);
    int i;
    if (!isinf(d0->mass)) {
        for (i = 0; i < 2; i++) {
            const long double v = (i ? d0->vel.y : d0->vel.x) - frame[i], w = (i ? d->vel.y : d->vel.x) - frame[i];
            ke[0] += m * v * v, ke[1] += m * w * w;
        }
        *bound += 2 * m * grow;
    }
    if (isinf(d0->inertia)) return;
    for (i = 0; i < 3; i++) ke[0] += I * (long double)d0->spin[i] * d0->spin[i], ke[1] += I * (long double)d->spin[i] * d->spin[i];
    if (r > 0) *bound += 3 * I / (r * r) * grow;
}

static void c2d_num_check_energy_bound(const long double ke[2], long double bound, const char *what)
{
    bound += 8 * LDBL_EPSILON * (ke[0] + ke[1]);
    if (!(ke[1] - ke[0] <= bound))
        c2d_fuzz_fail("%s energy gained: 2KE %.21Lg -> %.21Lg (+%.3Lg > bound %.3Lg)", what, ke[0], ke[1], ke[1] - ke[0],
                      bound);
}

/* L about the contact point along n^ and z^ of a ball: I w.n^ and
 * I wz + lever R m (n^ x v) (balls: lever -sign, cushion: the tilt's). */
static void c2d_num_contact_momenta(const C2D_T_BALL *d, long double nx, long double ny, long double lever_n,
                                    long double lever_z, const C2D_T_BALL *m0, long double out[2])
{
    const long double I = m0->inertia, rm = (long double)m0->radius * m0->mass;
    const long double vt = nx * d->vel.y - ny * d->vel.x;
    out[0] = I * (nx * d->spin[0] + ny * d->spin[1]) + lever_n * rm * vt;
    out[1] = I * d->spin[2] + lever_z * rm * vt;
}

static void c2d_num_check_contact_momenta(const C2D_T_BALL *d0, const C2D_T_BALL *d, long double nx, long double ny,
                                          long double lever_n, long double lever_z, long double delta,
                                          long double scale, char name)
{
    long double l0[2], l1[2], tol;
    int k;
    if (isinf(d0->inertia) || isinf(d0->mass) || d0->radius == 0) return;
    c2d_num_contact_momenta(d0, nx, ny, lever_n, lever_z, d0, l0);
    c2d_num_contact_momenta(d, nx, ny, lever_n, lever_z, d0, l1);
    tol = 2 * (long double)d0->inertia / d0->radius * delta +
          (long double)d0->radius * d0->mass * (2 * delta + 4 * scale * c2d_fuzz_ulp(1, c2d_num_fmt));
    for (k = 0; k < 2; k++) {
        const long double t = tol + 8 * LDBL_EPSILON * (fabsl(l0[k]) + fabsl(l1[k]));
        if (!(fabsl(l1[k] - l0[k]) <= t))
            c2d_fuzz_fail("%c's angular momentum at the contact along %s: %.21Lg -> %.21Lg (bound %.3Lg)", name,
                          k ? "z" : "n", l0[k], l1[k], t);
    }
}

/* Every input's magnitude 0 or within 2^+-span (INFINITY allowed where
 * valid): the range the referee is run in. */
static int c2d_num_sphere_tame(const c2d_num *x, int n)
{
    const long double lo = ldexpl(1, -C2D_FUZZ_SPHERE_SPAN), hi = ldexpl(1, C2D_FUZZ_SPHERE_SPAN);
    int i;
    for (i = 0; i < n; i++) {
        const long double a = fabsl((long double)x[i]);
        if (a != 0 && !isinf(x[i]) && (a < lo || a > hi)) return 0;
    }
    return 1;
}

static int c2d_num_ball_tame(const C2D_T_BALL *d)
{
    const c2d_num x[10] = {d->pos.x, d->pos.y, d->vel.x, d->vel.y, d->spin[0], d->spin[1], d->spin[2],
                           d->mass, d->radius, d->inertia};
    return c2d_num_sphere_tame(x, 10);
}

/* The referee's verdict in this format: its status, the error in *err. */
static c2d_status c2d_num_ref_balls(const ref_balls_case *c, const double *got, double *err)
{
    ref_sphere_verdict v;
    ref_balls(c, got, C2D_T_PREC, C2D_T_IS_FLOAT ? -126 : -1022, C2D_T_IS_FLOAT ? (double)FLT_MAX : DBL_MAX, &v);
    *err = v.err_ulp;
    return v.status;
}

static c2d_status c2d_num_ref_cushion(const ref_cushion_case *c, const double *got, double *err)
{
    ref_sphere_verdict v;
    ref_cushion(c, got, C2D_T_PREC, C2D_T_IS_FLOAT ? -126 : -1022, C2D_T_IS_FLOAT ? (double)FLT_MAX : DBL_MAX, &v);
    *err = v.err_ulp;
    return v.status;
}

static void c2d_num_check_sphere_referee(c2d_status st, c2d_status exact, double err, int bound)
{
    if (st != exact) c2d_fuzz_fail("sphere status %s, referee %s", c2d_status_string(st), c2d_status_string(exact));
    if (st == C2D_OK && !(err <= bound))
        c2d_fuzz_fail("sphere output %.3g ulp of the scale from the referee's (bound %d)", err, bound);
}

static void c2d_num_balls_physics(const C2D_T_BALL *a0, const C2D_T_BALL *b0, const C2D_T_BALL *a,
                                  const C2D_T_BALL *b)
{
    const long double s = c2d_num_ball_scale(b0, b, c2d_num_ball_scale(a0, a, 0));
    const long double delta = C2D_FUZZ_BALLS_BOUND_ULP * c2d_fuzz_ulp(s, c2d_num_fmt);
    long double frame[2] = {0, 0}, ke[2] = {0, 0}, bound = 0, nx, ny, len;
    int i;
    if (!isinf(a0->mass) && !isinf(b0->mass))
        for (i = 0; i < 2; i++) {
            const long double ma = a0->mass, mb = b0->mass;
            const long double p0 = ma * (i ? a0->vel.y : a0->vel.x) + mb * (i ? b0->vel.y : b0->vel.x);
            const long double p1 = ma * (i ? a->vel.y : a->vel.x) + mb * (i ? b->vel.y : b->vel.x);
            const long double t = (ma + mb) * delta + 8 * LDBL_EPSILON * (fabsl(p0) + fabsl(p1) + (ma + mb) * s);
            if (!(fabsl(p1 - p0) <= t))
                c2d_fuzz_fail("balls' momentum %c: %.21Lg -> %.21Lg (bound %.3Lg)", "xy"[i], p0, p1, t);
        }
    if (!c2d_num_ball_is_motor(a0) && !c2d_num_ball_is_motor(b0)) {
        if (isinf(a0->mass)) frame[0] = a0->vel.x, frame[1] = a0->vel.y;
        if (isinf(b0->mass)) frame[0] = b0->vel.x, frame[1] = b0->vel.y;
        c2d_num_ball_energy(a0, a, frame, delta, s, ke, &bound);
        c2d_num_ball_energy(b0, b, frame, delta, s, ke, &bound);
        c2d_num_check_energy_bound(ke, bound, "balls'");
    }
    nx = (long double)b0->pos.x - a0->pos.x, ny = (long double)b0->pos.y - a0->pos.y, len = hypotl(nx, ny);
    if (!(len > 0) || isinf(len)) return;
    nx /= len, ny /= len;
    c2d_num_check_contact_momenta(a0, a, nx, ny, 0, -1, delta, s, 'a');
    c2d_num_check_contact_momenta(b0, b, nx, ny, 0, 1, delta, s, 'b');
}

static void c2d_num_fuzz_collide_balls(c2d_fuzz_reader *r)
{
    C2D_T_BALL a, b, a0, b0;
    C2D_T_BALL_SURFACE s;
    c2d_status st;
    char da[320], db[320];
    c2d_num_read_ball(r, &a);
    c2d_num_read_ball(r, &b);
    s.restitution = C2D_T_READ_RESTITUTION(r);
    s.friction = C2D_T_READ_FRICTION(r);
    s.friction_boost = C2D_T_READ_FRICTION(r);
    s.friction_decay = C2D_T_READ_FRICTION(r);
    c2d_num_describe_ball(da, sizeof da, &a);
    c2d_num_describe_ball(db, sizeof db, &b);
    c2d_fuzz_describe("a=%s b=%s e=%a mu=%a boost=%a decay=%a", da, db, (double)s.restitution, (double)s.friction,
                      (double)s.friction_boost, (double)s.friction_decay);
    a0 = a, b0 = b;
    st = C2D_T_COLLIDE_BALLS(&a, &b, s);
    c2d_fuzz_check_status(st);
    if (st != C2D_OK) {
        c2d_fuzz_check_untouched(&a0, &a, sizeof a, st, "a");
        c2d_fuzz_check_untouched(&b0, &b, sizeof b, st, "b");
    } else {
        c2d_num_check_ball_written(&a0, &a, 'a');
        c2d_num_check_ball_written(&b0, &b, 'b');
        c2d_num_balls_physics(&a0, &b0, &a, &b);
    }
    if ((st == C2D_OK || st == C2D_SEPARATING) && c2d_num_ball_tame(&a0) && c2d_num_ball_tame(&b0)) {
        const c2d_num x[3] = {s.friction, s.friction_boost, s.friction_decay};
        ref_balls_case c;
        double got[2 * REF_BALL_OUT], err = 0;
        int i;
        if (!c2d_num_sphere_tame(x, 3)) return;
        C2D_T_BALL_to_ref(&a0, &c.a);
        C2D_T_BALL_to_ref(&b0, &c.b);
        c.e = s.restitution, c.mu = s.friction, c.boost = s.friction_boost, c.decay = s.friction_decay;
        got[0] = a.vel.x, got[1] = a.vel.y, got[5] = b.vel.x, got[6] = b.vel.y;
        for (i = 0; i < 3; i++) got[2 + i] = a.spin[i], got[7 + i] = b.spin[i];
        c2d_num_check_sphere_referee(st, c2d_num_ref_balls(&c, got, &err), err, C2D_FUZZ_BALLS_BOUND_ULP);
    }
}

static void c2d_num_cushion_physics(const C2D_T_BALL *d0, const C2D_T_BALL *d, const C2D_T_CUSHION *k)
{
    const long double s = c2d_num_ball_scale(d0, d, 0);
    const long double delta = C2D_FUZZ_CUSHION_BOUND_ULP * c2d_fuzz_ulp(s, c2d_num_fmt);
    const long double sn = ((long double)k->height - d0->radius) / d0->radius, cs = sqrtl(1 - sn * sn);
    const long double len = hypotl(k->normal.x, k->normal.y);
    long double frame[2] = {0, 0}, ke[2] = {0, 0}, bound = 0;
    c2d_num_ball_energy(d0, d, frame, delta, s, ke, &bound);
    if (!isinf(d0->inertia)) c2d_num_check_energy_bound(ke, bound, "cushion");
    if (!(len > 0) || isinf(len)) return;
    c2d_num_check_contact_momenta(d0, d, k->normal.x / len, k->normal.y / len, sn, -cs, delta, s, 'a');
}

static void c2d_num_fuzz_collide_cushion(c2d_fuzz_reader *r)
{
    C2D_T_BALL a, a0;
    C2D_T_CUSHION k;
    c2d_status st;
    char da[320];
    c2d_num_read_ball(r, &a);
    k.normal.x = C2D_T_READ(r);
    k.normal.y = C2D_T_READ(r);
    /* the height as a fraction of [R, 2R] in tame mode, so most are valid */
    k.height = r->mode == C2D_FUZZ_TAME ? a.radius * (1 + (c2d_num)c2d_fuzz_read_byte(r) / 255) : C2D_T_READ(r);
    k.restitution = C2D_T_READ_RESTITUTION(r);
    k.friction = C2D_T_READ_FRICTION(r);
    c2d_num_describe_ball(da, sizeof da, &a);
    c2d_fuzz_describe("a=%s n={%a,%a} h=%a e=%a mu=%a", da, (double)k.normal.x, (double)k.normal.y,
                      (double)k.height, (double)k.restitution, (double)k.friction);
    a0 = a;
    st = C2D_T_COLLIDE_CUSHION(&a, k);
    c2d_fuzz_check_status(st);
    if (st != C2D_OK) {
        c2d_fuzz_check_untouched(&a0, &a, sizeof a, st, "the ball");
    } else {
        c2d_num_check_ball_written(&a0, &a, 'a');
        c2d_num_cushion_physics(&a0, &a, &k);
    }
    if ((st == C2D_OK || st == C2D_SEPARATING) && c2d_num_ball_tame(&a0)) {
        const c2d_num x[3] = {k.normal.x, k.normal.y, k.height};
        ref_cushion_case c;
        double got[REF_BALL_OUT], err = 0;
        int i;
        if (!c2d_num_sphere_tame(x, 3)) return;
        C2D_T_BALL_to_ref(&a0, &c.a);
        c.n[0] = k.normal.x, c.n[1] = k.normal.y, c.h = k.height, c.e = k.restitution, c.mu = k.friction;
        got[0] = a.vel.x, got[1] = a.vel.y;
        for (i = 0; i < 3; i++) got[2 + i] = a.spin[i];
        c2d_num_check_sphere_referee(st, c2d_num_ref_cushion(&c, got, &err), err, C2D_FUZZ_CUSHION_BOUND_ULP);
    }
}
