/* SPDX-License-Identifier: MIT */
/* fuzz_accel_template.h - template: the fuzz checks of the time of impact
 * under constant acceleration (c2d_time_of_impact_accel) in one floating
 * type.  Included after fuzz_template.h by fuzz_double.c and fuzz_float.c;
 * the type header names, besides fuzz_template.h's,
 *   C2D_T_TIME_OF_IMPACT_ACCEL, C2D_T_READ_HORIZON, C2D_T_IS_FLOAT
 *
 * Why these checks.  The header promises: *t written only on OK, then
 * 0 <= t <= horizon; the bodies are const; the status exact outside a tie
 * band it states, and t within 1 unit (ulp(t) + ulp(|d|) / s) of the exact
 * time; with equal accelerations, c2d_time_of_impact's answer (status and
 * bits, within its 4 units).  The
 * exact referee (referee/ref_toi_accel.c: Sturm sequences over the
 * rationals, the time in MPFR) decides the status and measures the band
 * (toia_in_band, shared with tests/unit/test_toi_accel.c): a wrong status
 * or time is forgiven there and nowhere else.  The comparison with
 * c2d_time_of_impact is made with no horizon (INFINITY), where both
 * functions ask the same question.
 *
 * Cost.  The referee's rationals carry about twice as many bits as the
 * inputs' binary exponents span, and its Sturm sequences cost grows faster
 * than that: measured under this harness, well under 1 ms for ordinary
 * inputs, up to ~50 ms for a span of 300 binades, 0.1 to 1.2 s beyond 1000
 * (x86-64, -O2).  So it is consulted when the finite non-zero inputs span
 * at most C2D_FUZZ_ACCEL_REFEREE_SPAN binades: every float case (its span
 * is at most 277) and every double case but the wildest ratios, which keep
 * the other checks; tests/unit/test_toi_accel.c's "extreme ratios" family
 * covers those against the referee. */

#define C2D_FUZZ_TOI_ACCEL_BOUND_UNITS 1.0
/* Equal accelerations: the answer is c2d_time_of_impact's, within its bound. */
#define C2D_FUZZ_TOI_STRAIGHT_BOUND_UNITS 4.0
#define C2D_FUZZ_ACCEL_REFEREE_SPAN 300

typedef struct c2d_num_accel_call {
    c2d_num_body a, b;
    c2d_num_vec aa, ab;
    c2d_num rad, horizon;
} c2d_num_accel_call;

static void c2d_num_read_accel_call(c2d_fuzz_reader *r, c2d_num_accel_call *c)
{
    c2d_num_read_body(r, &c->a);
    c2d_num_read_body(r, &c->b);
    c->aa.x = C2D_T_READ(r);
    c->aa.y = C2D_T_READ(r);
    c->ab.x = C2D_T_READ(r);
    c->ab.y = C2D_T_READ(r);
    c->rad = C2D_T_READ(r);
    c->horizon = C2D_T_READ_HORIZON(r);
    if (r->mode == C2D_FUZZ_TAME) c->rad = C2D_T_FABS(c->rad);
    c2d_fuzz_describe("pa=(%a,%a) va=(%a,%a) aa=(%a,%a) pb=(%a,%a) vb=(%a,%a) ab=(%a,%a) R=%a H=%a",
                      (double)c->a.pos.x, (double)c->a.pos.y, (double)c->a.vel.x, (double)c->a.vel.y,
                      (double)c->aa.x, (double)c->aa.y, (double)c->b.pos.x, (double)c->b.pos.y, (double)c->b.vel.x,
                      (double)c->b.vel.y, (double)c->ab.x, (double)c->ab.y, (double)c->rad, (double)c->horizon);
}

static void c2d_num_accel_to_ref(const c2d_num_accel_call *c, ref_toia_in *in)
{
    in->pa[0] = c->a.pos.x, in->pa[1] = c->a.pos.y, in->va[0] = c->a.vel.x, in->va[1] = c->a.vel.y;
    in->pb[0] = c->b.pos.x, in->pb[1] = c->b.pos.y, in->vb[0] = c->b.vel.x, in->vb[1] = c->b.vel.y;
    in->aa[0] = c->aa.x, in->aa[1] = c->aa.y, in->ab[0] = c->ab.x, in->ab[1] = c->ab.y;
    in->r = c->rad, in->h = c->horizon;
}

static void c2d_num_check_accel_result(const c2d_num_accel_call *c, c2d_status s, c2d_num t, c2d_num t0)
{
    c2d_fuzz_check_status(s);
    if (s != C2D_OK && memcmp(&t, &t0, sizeof t) != 0)
        c2d_fuzz_fail("time of impact %s but *t written", c2d_status_string(s));
    if (s == C2D_OK && !(isfinite(t) && t >= 0 && t <= c->horizon))
        c2d_fuzz_fail("time of impact OK but t = %a outside [0, horizon]", (double)t);
}

/* The span of binary exponents over the finite non-zero inputs. */
static int c2d_num_accel_span(const ref_toia_in *in)
{
    const double v[14] = {in->pa[0], in->pa[1], in->pb[0], in->pb[1], in->va[0], in->va[1], in->vb[0],
                          in->vb[1], in->aa[0], in->aa[1], in->ab[0], in->ab[1], in->r, in->h};
    int lo = INT_MAX, hi = INT_MIN, k, e;
    for (k = 0; k < 14; k++) {
        if (v[k] == 0 || !isfinite(v[k])) continue;
        (void)frexp(v[k], &e);
        if (e < lo) lo = e;
        if (e > hi) hi = e;
    }
    return hi < lo ? 0 : hi - lo;
}

/* Against the exact referee, outside the band; returns whether the case
 * is in it (or too costly to decide, see above). */
static int c2d_num_check_accel_referee(const c2d_num_accel_call *c, c2d_status s, c2d_num t)
{
    static ref_toia_out o;
    static int ready;
    ref_toia_in in;
    double err, bound;
    if (!ready) ref_toia_init(&o), ready = 1;
    c2d_num_accel_to_ref(c, &in);
    if (c2d_num_accel_span(&in) > C2D_FUZZ_ACCEL_REFEREE_SPAN) return 1;
    ref_toia(&in, C2D_T_PREC, C2D_T_EMIN, &o);
    if (toia_in_band(&o, C2D_T_IS_FLOAT, &in)) return 1;
    if (s != o.status)
        c2d_fuzz_fail("time of impact %s, exact %s (t = %a, exact %a)", c2d_status_string(s), c2d_status_string(o.status),
                      (double)t, o.td);
    if (s != C2D_OK) return 0;
    err = ref_toia_err(&o, t);
    bound = c->aa.x == c->ab.x && c->aa.y == c->ab.y ? C2D_FUZZ_TOI_STRAIGHT_BOUND_UNITS : C2D_FUZZ_TOI_ACCEL_BOUND_UNITS;
    if (!(err <= bound)) c2d_fuzz_fail("time of impact t = %a, exact %a: %.3g units > %g", (double)t, o.td, err, bound);
    return 0;
}

/* Equal finite accelerations and no horizon: the straight-line question,
 * answered by c2d_time_of_impact itself (status and bits). */
static void c2d_num_check_accel_linear(const c2d_num_accel_call *c, c2d_status s, c2d_num ts)
{
    c2d_num t = -1;
    c2d_status lin;
    if (!isinf(c->horizon) || c->horizon < 0 || !isfinite(c->aa.x) || !isfinite(c->aa.y) || c->aa.x != c->ab.x ||
        c->aa.y != c->ab.y)
        return;
    lin = C2D_T_TIME_OF_IMPACT(&c->a, &c->b, c->rad, &t);
    if (s != lin)
        c2d_fuzz_fail("equal accelerations: status %s, c2d_time_of_impact %s", c2d_status_string(s),
                      c2d_status_string(lin));
    if (s == C2D_OK && memcmp(&t, &ts, sizeof t) != 0)
        c2d_fuzz_fail("equal accelerations: t = %a, c2d_time_of_impact %a", (double)ts, (double)t);
}

static void c2d_num_fuzz_time_of_impact_accel(c2d_fuzz_reader *r)
{
    c2d_num_accel_call c, c0;
    c2d_num t, t0;
    c2d_status s;
    c2d_num_read_accel_call(r, &c);
    c0 = c;
    t = t0 = -12345;
    s = C2D_T_TIME_OF_IMPACT_ACCEL(&c.a, c.aa, &c.b, c.ab, c.rad, c.horizon, &t);
    c2d_num_check_accel_result(&c, s, t, t0);
    c2d_fuzz_check_untouched(&c0.a, &c.a, sizeof c.a, s, "a (const)");
    c2d_fuzz_check_untouched(&c0.b, &c.b, sizeof c.b, s, "b (const)");
    (void)c2d_num_check_accel_referee(&c, s, t);
    c2d_num_check_accel_linear(&c, s, t);
}
