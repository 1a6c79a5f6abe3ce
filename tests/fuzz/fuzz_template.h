/* SPDX-License-Identifier: MIT */
/* fuzz_template.h - template: the fuzz checks of one floating type, every
 * property of fuzz_collide2d.c's list that does not compare types.
 * Included once per translation unit (fuzz_double.c, fuzz_float.c) after
 * the type's header (tests/harness/type_*.h) and soa_template.h; the type
 * header names
 *   c2d_num, c2d_num_body, c2d_num_vec, c2d_num_pairs, c2d_num_soa
 *   C2D_T_PREC, C2D_T_EMIN, C2D_T_LIMIT    the format, for the bounds and
 *                                          the referee (referee.h)
 *   C2D_T_FABS                             |x| in the type
 *   C2D_T_READ, C2D_T_READ_MASS, C2D_T_READ_RESTITUTION   decoders (decode.c)
 *   C2D_T_COLLIDE, C2D_T_COLLIDE_NORMAL, C2D_T_TIME_OF_IMPACT, C2D_T_BATCH
 * The translation unit names what it exports; the float one adds its
 * comparison with double. */

#define C2D_FUZZ_MAX_PAIRS 24 /* three kernel blocks, so full blocks and a tail both occur */

static const c2d_fuzz_fmt c2d_num_fmt = {C2D_T_PREC, C2D_T_EMIN};

static void c2d_num_read_body(c2d_fuzz_reader *r, c2d_num_body *b)
{
    b->pos.x = C2D_T_READ(r);
    b->pos.y = C2D_T_READ(r);
    b->vel.x = C2D_T_READ(r);
    b->vel.y = C2D_T_READ(r);
    b->mass = C2D_T_READ_MASS(r);
}

/* The body in double: exact (float widens without rounding). */
static void c2d_num_widen(const c2d_num_body *f, c2d_body *d)
{
    d->pos.x = f->pos.x, d->pos.y = f->pos.y;
    d->vel.x = f->vel.x, d->vel.y = f->vel.y;
    d->mass = f->mass;
}

static void c2d_num_describe(const c2d_num_body *a, const c2d_num_body *b, double nx, double ny, double e)
{
    c2d_body ad, bd;
    c2d_num_widen(a, &ad);
    c2d_num_widen(b, &bd);
    c2d_fuzz_describe_d(&ad, &bd, nx, ny, e);
}

static c2d_fuzz_response c2d_num_response(const c2d_num_body *a0, const c2d_num_body *b0, const c2d_num_body *a,
                                          const c2d_num_body *b, long double nx, long double ny)
{
    c2d_fuzz_response x;
    x.n[0] = nx, x.n[1] = ny;
    x.v[0] = a0->vel.x, x.v[1] = a0->vel.y, x.v[2] = b0->vel.x, x.v[3] = b0->vel.y;
    x.w[0] = a->vel.x, x.w[1] = a->vel.y, x.w[2] = b->vel.x, x.w[3] = b->vel.y;
    x.m[0] = a0->mass, x.m[1] = b0->mass;
    x.immovable[0] = isinf(a0->mass), x.immovable[1] = isinf(b0->mass);
    c2d_fuzz_fill_scales(&x, c2d_num_fmt);
    return x;
}

/* On OK: positions and masses untouched, finite outputs, the bounds. */
static void c2d_num_check_ok(const c2d_num_body *a0, const c2d_num_body *b0, const c2d_num_body *a,
                             const c2d_num_body *b, long double nx, long double ny)
{
    c2d_fuzz_response x;
    if (memcmp(&a0->pos, &a->pos, sizeof a->pos) != 0 || memcmp(&b0->pos, &b->pos, sizeof b->pos) != 0 ||
        memcmp(&a0->mass, &a->mass, sizeof a->mass) != 0 || memcmp(&b0->mass, &b->mass, sizeof b->mass) != 0)
        c2d_fuzz_fail("OK but a position or mass was written");
    if (!isfinite(a->vel.x) || !isfinite(a->vel.y) || !isfinite(b->vel.x) || !isfinite(b->vel.y))
        c2d_fuzz_fail("OK with a non-finite output (%a %a %a %a)", (double)a->vel.x, (double)a->vel.y,
                      (double)b->vel.x, (double)b->vel.y);
    /* An immovable body's velocity as given, bits included (-0 stays -0;
     * bounds.c compares values only). */
    if ((isinf(a0->mass) && memcmp(&a0->vel, &a->vel, sizeof a->vel) != 0) ||
        (isinf(b0->mass) && memcmp(&b0->vel, &b->vel, sizeof b->vel) != 0))
        c2d_fuzz_fail("OK but an immovable body's velocity changed (bits)");
    x = c2d_num_response(a0, b0, a, b, nx, ny);
    c2d_fuzz_check_conservation(&x);
}

/* One collision made and checked; n NULL: the line of centres. */
static c2d_status c2d_num_collide_checked(c2d_num_body *a, c2d_num_body *b, const c2d_num_vec *n, c2d_num e)
{
    const c2d_num_body a0 = *a, b0 = *b;
    const c2d_status s = n ? C2D_T_COLLIDE_NORMAL(a, b, *n, e) : C2D_T_COLLIDE(a, b, e);
    c2d_fuzz_check_status(s);
    if (s == C2D_OK) {
        c2d_num_check_ok(&a0, &b0, a, b, n ? (long double)n->x : (long double)b0.pos.x - a0.pos.x,
                         n ? (long double)n->y : (long double)b0.pos.y - a0.pos.y);
    } else {
        c2d_fuzz_check_untouched(&a0, a, sizeof *a, s, "a");
        c2d_fuzz_check_untouched(&b0, b, sizeof *b, s, "b");
    }
    return s;
}

/* A decoded call and its result, kept for the variant's own cross-checks. */
typedef struct c2d_num_call {
    c2d_num_body a0, b0, a, b; /* before and after */
    c2d_num_vec n;
    c2d_num e;
    int with_normal;
    c2d_status s;
} c2d_num_call;

static void c2d_num_fuzz_collide(c2d_fuzz_reader *r, int with_normal, c2d_num_call *c)
{
    c2d_num_read_body(r, &c->a);
    c2d_num_read_body(r, &c->b);
    c->n.x = C2D_T_READ(r);
    c->n.y = C2D_T_READ(r);
    c->e = C2D_T_READ_RESTITUTION(r);
    c->with_normal = with_normal;
    c2d_num_describe(&c->a, &c->b, c->n.x, c->n.y, c->e);
    c->a0 = c->a, c->b0 = c->b;
    c->s = c2d_num_collide_checked(&c->a, &c->b, with_normal ? &c->n : NULL, c->e);
}

static void c2d_num_check_time_of_impact(c2d_status s, c2d_num t, c2d_num t0)
{
    c2d_fuzz_check_status(s);
    if (s == C2D_OK && !(isfinite(t) && t >= 0)) c2d_fuzz_fail("time of impact OK but t = %a", (double)t);
    if (s != C2D_OK && memcmp(&t, &t0, sizeof t) != 0)
        c2d_fuzz_fail("time of impact %s but *t written", c2d_status_string(s));
}

/* The status against the exact referee (rationals: exact over the whole
 * range), RANGE where the exact t exceeds the format's largest value; on OK
 * t within the header's 4 units of the exact time. */
#define C2D_FUZZ_TOI_BOUND_UNITS 4.0

static void c2d_num_check_toi_referee(const c2d_num_body *a, const c2d_num_body *b, c2d_num rad, c2d_status s,
                                      c2d_num t)
{
    ref_case c;
    double want = 0, unit = 0, err;
    c2d_status exact;
    c.pa[0] = a->pos.x, c.pa[1] = a->pos.y, c.pb[0] = b->pos.x, c.pb[1] = b->pos.y;
    c.va[0] = a->vel.x, c.va[1] = a->vel.y, c.vb[0] = b->vel.x, c.vb[1] = b->vel.y;
    exact = ref_time_of_impact(&c, rad, &want, &unit, C2D_T_PREC, C2D_T_EMIN);
    if (exact == C2D_OK && want > C2D_T_LIMIT) exact = C2D_RANGE;
    if (s != exact)
        c2d_fuzz_fail("time of impact %s, exact %s (t = %a, exact %a)", c2d_status_string(s),
                      c2d_status_string(exact), (double)t, want);
    if (s != C2D_OK) return;
    err = fabs((double)t - want) / unit;
    if (!(err <= C2D_FUZZ_TOI_BOUND_UNITS))
        c2d_fuzz_fail("time of impact t = %a, exact %a: %.3g units > %g", (double)t, want, err,
                      C2D_FUZZ_TOI_BOUND_UNITS);
}

static void c2d_num_fuzz_time_of_impact(c2d_fuzz_reader *r)
{
    c2d_num_body a, b, a0, b0;
    c2d_num rad, t, t0;
    c2d_status s;
    c2d_num_read_body(r, &a);
    c2d_num_read_body(r, &b);
    rad = C2D_T_READ(r);
    if (r->mode == C2D_FUZZ_TAME) rad = C2D_T_FABS(rad);
    c2d_num_describe(&a, &b, 0, 0, rad);
    a0 = a, b0 = b;
    t = t0 = -12345;
    s = C2D_T_TIME_OF_IMPACT(&a, &b, rad, &t);
    c2d_num_check_time_of_impact(s, t, t0);
    c2d_fuzz_check_untouched(&a0, &a, sizeof a, s, "a (const)");
    c2d_fuzz_check_untouched(&b0, &b, sizeof b, s, "b (const)");
    c2d_num_check_toi_referee(&a, &b, rad, s, t);
}

/* The batch over up to C2D_FUZZ_MAX_PAIRS decoded pairs against a checked
 * scalar call on each (tests/harness compares the lanes). */
static void c2d_num_fuzz_batch(c2d_fuzz_reader *r, int flags)
{
    static c2d_num block[C2D_SOA_FIELDS * C2D_FUZZ_MAX_PAIRS];
    c2d_status st[C2D_FUZZ_MAX_PAIRS];
    const c2d_num_soa s = c2d_num_soa_in(block, C2D_FUZZ_MAX_PAIRS, (flags & C2D_FUZZ_NULL_STATUS) ? NULL : st);
    const c2d_num_pairs p = c2d_num_soa_pairs(&s);
    c2d_num_body a[C2D_FUZZ_MAX_PAIRS], b[C2D_FUZZ_MAX_PAIRS];
    c2d_batch_check check = {0, 0, 0};
    size_t count = (size_t)(c2d_fuzz_read_byte(r) % (C2D_FUZZ_MAX_PAIRS + 1)), i, done;
    c2d_num e = C2D_T_READ_RESTITUTION(r);
    for (i = 0; i < count; i++) {
        c2d_num_read_body(r, &a[i]);
        c2d_num_read_body(r, &b[i]);
        c2d_num_soa_put(&s, i, &a[i], &b[i]);
        st[i] = (c2d_status)-1;
    }
    done = C2D_T_BATCH(&p, count, e, s.status);
    for (i = 0; i < count; i++) {
        c2d_status want;
        c2d_num_describe(&a[i], &b[i], 0, 0, e);
        want = c2d_num_collide_checked(&a[i], &b[i], NULL, e);
        c2d_num_check_lane(&check, &s, i, want, &a[i], &b[i]);
    }
    if (check.differing != 0) c2d_fuzz_fail("batch pair %zu differs from the scalar call", check.first);
    if (done != check.resolved) c2d_fuzz_fail("batch returned %zu, scalar calls gave %zu OK", done, check.resolved);
    if (C2D_T_BATCH(NULL, count, e, st) != 0) c2d_fuzz_fail("batch with p == NULL did not return 0");
}
