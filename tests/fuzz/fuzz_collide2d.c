/* fuzz_collide2d.c - libFuzzer harness for every public entry point.
 *
 * INPUT FORMAT (raw bytes; missing bytes read as 0)
 *   byte 0   entry point, modulo C2D_FUZZ_ENTRIES (see enum below)
 *   byte 1   decoding mode (low 2 bits) and flags (high bits)
 *   rest     the arguments, field by field.  In MODE_RAW every double/float/
 *            int32 is its bit pattern straight from the bytes, so NaN, Inf,
 *            subnormals and negative zero all occur.  MODE_TAME reads small
 *            values (int16 / 256, positive masses, e in [0, 1]) so the
 *            accepting paths and the batch's vector kernel are reached too.
 *            MODE_MIXED prefixes each field with a tag byte choosing raw bits,
 *            a tame value, a wide-range int16 * 2^k, or a special value.
 *
 * PROPERTIES (any violation prints the case and aborts)
 *   - the status is one of the enum's values and has a name;
 *   - on any status but OK both bodies are bit-for-bit untouched (memcmp),
 *     and time of impact leaves *t untouched;
 *   - on OK positions and masses are untouched, every output is finite, an
 *     immovable body keeps its velocity, momentum is conserved and kinetic
 *     energy is not gained within the bound the documented accuracy implies
 *     (see c2d_fuzz_bounds below);
 *   - float and double agree: the float inputs, widened exactly to double,
 *     give the same status (RANGE aside, where the float result really is
 *     near FLT_MAX) and outputs within the sum of their documented bounds;
 *     likewise Q16.16 against double, with the Q16.16 bound;
 *   - time of impact, when OK, is finite and >= 0 (Q16.16: also agrees with
 *     the double answer within its documented bound);
 *   - the batch entry points give bit-identical outputs, statuses and count
 *     to scalar calls on the same pairs.
 */
#include "collide2d.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum {
    E_COLLIDE,
    E_COLLIDE_NORMAL,
    E_TOI,
    E_COLLIDEF,
    E_COLLIDE_NORMALF,
    E_TOIF,
    E_COLLIDEX,
    E_COLLIDE_NORMALX,
    E_TOIX,
    E_BATCH,
    E_BATCHF,
    C2D_FUZZ_ENTRIES
};

enum { MODE_MIXED = 0, MODE_TAME = 1, MODE_RAW = 2 };
#define FLAG_NULL_STATUS 0x04 /* batch: pass status == NULL */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* ------------------------------------------------------------- failure */

static const char *c2d_fuzz_case = "";
static char c2d_fuzz_inputs[1024]; /* the decoded arguments, for the report */

static void fail(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "fuzz property violated (%s): ", c2d_fuzz_case);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n  inputs: %s\n", c2d_fuzz_inputs);
    abort();
}

static void check_status(c2d_status s)
{
    if (s != C2D_OK && s != C2D_SEPARATING && s != C2D_DEGENERATE && s != C2D_INVALID && s != C2D_RANGE)
        fail("status %d is not an enum value", (int)s);
    if (c2d_status_string(s) == NULL || strcmp(c2d_status_string(s), "unknown") == 0)
        fail("status %d has no name", (int)s);
}

static void describe(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c2d_fuzz_inputs, sizeof c2d_fuzz_inputs, fmt, ap);
    va_end(ap);
}

static void describe_d(const c2d_body *a, const c2d_body *b, double nx, double ny, double e)
{
    describe("a={{%a,%a},{%a,%a},%a} b={{%a,%a},{%a,%a},%a} n={%a,%a} e/r=%a", a->pos.x, a->pos.y, a->vel.x,
             a->vel.y, a->mass, b->pos.x, b->pos.y, b->vel.x, b->vel.y, b->mass, nx, ny, e);
}

static void describe_x(const c2d_bodyx *a, const c2d_bodyx *b, c2d_fixed nx, c2d_fixed ny, c2d_fixed e)
{
    describe("a={{%d,%d},{%d,%d},%d} b={{%d,%d},{%d,%d},%d} n={%d,%d} e/r=%d", (int)a->pos.x, (int)a->pos.y,
             (int)a->vel.x, (int)a->vel.y, (int)a->mass, (int)b->pos.x, (int)b->pos.y, (int)b->vel.x,
             (int)b->vel.y, (int)b->mass, (int)nx, (int)ny, (int)e);
}

/* -------------------------------------------------------------- reader */

typedef struct reader {
    const uint8_t *p;
    size_t n;
    int mode;
} reader;

static uint8_t rd_byte(reader *r)
{
    if (r->n == 0) return 0;
    r->n--;
    return *r->p++;
}

static void rd_bytes(reader *r, void *out, size_t k)
{
    uint8_t *o = out;
    size_t i;
    for (i = 0; i < k; i++) o[i] = rd_byte(r);
}

static int16_t rd_i16(reader *r)
{
    uint16_t u = (uint16_t)(rd_byte(r) | (rd_byte(r) << 8));
    return (int16_t)u;
}

static double special_double(uint8_t k)
{
    static const double table[] = {0.0, -0.0, 1.0, -1.0, 0.5, 2.0, DBL_MAX, -DBL_MAX, DBL_MIN,
                                   -DBL_MIN, 4.9406564584124654e-324, DBL_MAX / 8, DBL_EPSILON,
                                   1e300, -1e300, 1e-300, FLT_MAX, FLT_MIN};
    const size_t n = sizeof table / sizeof table[0];
    if (k == 250) return INFINITY;
    if (k == 251) return -INFINITY;
    if (k == 252) return NAN;
    return table[k % n];
}

static double rd_double(reader *r)
{
    double d;
    float f;
    uint8_t tag;
    if (r->mode == MODE_RAW) {
        rd_bytes(r, &d, sizeof d);
        return d;
    }
    if (r->mode == MODE_TAME) return rd_i16(r) / 256.0;
    tag = rd_byte(r);
    switch (tag % 8) {
    case 3: return rd_i16(r) / 256.0;
    case 4: {
        int16_t m = rd_i16(r);
        return ldexp(m, (int8_t)rd_byte(r) * 9); /* spans the whole range */
    }
    case 5: return special_double(rd_byte(r));
    case 6:
        rd_bytes(r, &f, sizeof f);
        return f;
    case 7: return (int8_t)rd_byte(r);
    default:
        rd_bytes(r, &d, sizeof d);
        return d;
    }
}

static double rd_mass(reader *r)
{
    if (r->mode == MODE_TAME) {
        uint16_t u = (uint16_t)rd_i16(r);
        return u == 0xFFFF ? INFINITY : (1.0 + u) / 256.0;
    }
    return rd_double(r);
}

static double rd_restitution(reader *r)
{
    uint8_t tag;
    if (r->mode == MODE_TAME) return rd_byte(r) / 255.0;
    if (r->mode == MODE_RAW) return rd_double(r);
    tag = rd_byte(r);
    switch (tag % 4) {
    case 1: return rd_byte(r) / 255.0;
    case 2: return 1.0;
    case 3: return 0.0;
    default: return rd_double(r);
    }
}

/* Floats: the same decoding, rounded (raw mode: the float's own bits). */
static float rd_float(reader *r)
{
    float f;
    if (r->mode == MODE_RAW) {
        rd_bytes(r, &f, sizeof f);
        return f;
    }
    return (float)rd_double(r);
}

static float rd_massf(reader *r) { return r->mode == MODE_RAW ? rd_float(r) : (float)rd_mass(r); }

static float rd_restitutionf(reader *r)
{
    return r->mode == MODE_RAW ? rd_float(r) : (float)rd_restitution(r);
}

static c2d_fixed rd_fixed(reader *r)
{
    static const c2d_fixed special[] = {0, 1, -1, C2D_FIXED_ONE, -C2D_FIXED_ONE, INT32_MAX, INT32_MIN,
                                        INT32_MAX / 2, INT32_MIN / 2};
    uint8_t tag;
    int32_t v;
    if (r->mode == MODE_TAME) return (c2d_fixed)rd_i16(r) * 16;
    if (r->mode == MODE_MIXED) {
        tag = rd_byte(r);
        if (tag % 4 == 1) return (c2d_fixed)((uint32_t)(int32_t)rd_i16(r) << (tag / 4 % 16));
        if (tag % 4 == 2) return special[rd_byte(r) % (sizeof special / sizeof special[0])];
    }
    rd_bytes(r, &v, sizeof v);
    return v;
}

static c2d_fixed rd_massx(reader *r)
{
    if (r->mode == MODE_TAME) {
        uint16_t u = (uint16_t)rd_i16(r);
        return u == 0xFFFF ? C2D_FIXED_INFINITE_MASS : 1 + (c2d_fixed)u * 16;
    }
    return rd_fixed(r);
}

static c2d_fixed rd_restitutionx(reader *r)
{
    uint8_t tag;
    if (r->mode == MODE_RAW) return rd_fixed(r);
    tag = rd_byte(r);
    if (r->mode == MODE_TAME || tag % 4 == 1) return (c2d_fixed)((int32_t)rd_byte(r) * 65536 / 255);
    if (tag % 4 == 2) return C2D_FIXED_ONE;
    if (tag % 4 == 3) return 0;
    return rd_fixed(r);
}

static void rd_body(reader *r, c2d_body *b)
{
    b->pos.x = rd_double(r);
    b->pos.y = rd_double(r);
    b->vel.x = rd_double(r);
    b->vel.y = rd_double(r);
    b->mass = rd_mass(r);
}

static void rd_bodyf(reader *r, c2d_bodyf *b)
{
    b->pos.x = rd_float(r);
    b->pos.y = rd_float(r);
    b->vel.x = rd_float(r);
    b->vel.y = rd_float(r);
    b->mass = rd_massf(r);
}

static void rd_bodyx(reader *r, c2d_bodyx *b)
{
    b->pos.x = rd_fixed(r);
    b->pos.y = rd_fixed(r);
    b->vel.x = rd_fixed(r);
    b->vel.y = rd_fixed(r);
    b->mass = rd_massx(r);
}

/* -------------------------------------------------------------- bounds */

/* Why these bounds.  The header promises each output component within
 * 16 ulp of its body's velocity scale S (largest |component| before or
 * after).  The exact response changes each velocity along the normal only,
 * conserves momentum exactly (both masses finite: an immovable body absorbs
 * momentum) and kinetic energy (e = 1) or loses it (e < 1).  So with
 * delta = 16 ulp(S) per component:
 *   direction: the part of v' - v across the unit normal is the output error
 *             projected, <= sqrt(2) delta (we allow 1.5 delta);
 *   momentum: |sum m v - sum m v'| <= sum of m delta;
 *   energy:   m v'^2 - m v_exact^2 = m (v' - v_exact)(v' + v_exact)
 *             <= m delta (2 S + delta) per component, so with the 1/2 and two
 *             components, KE' - KE <= sum of m delta (2 S + delta).
 * The sums are formed in long double (64-bit significand, exponent range to
 * 1e4932: m v^2 neither overflows nor underflows for any double input); each
 * of its few roundings is <= LDBL_EPSILON of the magnitudes involved, hence
 * the extra 8 LDBL_EPSILON x (sum of |terms|).  For Q16.16 the documented
 * error is delta = 3 steps + 2^-24 S (in raw units).  Nothing here is tuned:
 * the only constants are the header's. */
typedef struct fmt {
    int prec, emin; /* 53/-1022 double, 24/-126 float */
} fmt;

static const fmt FMT_D = {53, -1022};
static const fmt FMT_F = {24, -126};

static long double ulp_of(long double s, fmt f)
{
    int ex;
    if (!(s >= ldexpl(1.0L, f.emin))) return ldexpl(1.0L, f.emin - f.prec + 1);
    (void)frexpl(s, &ex); /* s = g 2^ex, g in [0.5, 1) */
    return ldexpl(1.0L, ex - f.prec);
}

static long double maxabs4(long double a, long double b, long double c, long double d)
{
    long double m = fabsl(a);
    if (fabsl(b) > m) m = fabsl(b);
    if (fabsl(c) > m) m = fabsl(c);
    if (fabsl(d) > m) m = fabsl(d);
    return m;
}

/* A response in long double, the same for all three types: v[0..3] before
 * (vax, vay, vbx, vby), w[0..3] after, masses (immovable flagged), and the
 * per-body error delta each output may carry. */
typedef struct response {
    long double v[4], w[4], m[2], n[2];
    int immovable[2];
    long double delta[2], scale[2];
} response;

static void check_conservation(const response *x)
{
    long double ke0 = 0, ke1 = 0, ke_bound = 0, ke_mag = 0, frame[2];
    long double big = fabsl(x->n[0]) > fabsl(x->n[1]) ? fabsl(x->n[0]) : fabsl(x->n[1]);
    long double ux = x->n[0] / big, uy = x->n[1] / big, len = sqrtl(ux * ux + uy * uy);
    int i, j;
    for (j = 0; j < 2; j++) {
        long double dx = x->w[2 * j] - x->v[2 * j], dy = x->w[2 * j + 1] - x->v[2 * j + 1];
        long double across = fabsl(dx * uy - dy * ux) / len;
        long double bound = 1.5L * x->delta[j] + 8 * LDBL_EPSILON * (fabsl(dx) + fabsl(dy));
        if (!(across <= bound))
            fail("body %c: velocity change has %.3Lg across the normal > bound %.3Lg", "ab"[j], across, bound);
    }
    for (i = 0; i < 2 && !x->immovable[0] && !x->immovable[1]; i++) {
        long double p0 = 0, p1 = 0, bound = 0, mag = 0;
        for (j = 0; j < 2; j++) {
            p0 += x->m[j] * x->v[2 * j + i];
            p1 += x->m[j] * x->w[2 * j + i];
            bound += x->m[j] * x->delta[j];
            mag += fabsl(x->m[j] * x->v[2 * j + i]) + fabsl(x->m[j] * x->w[2 * j + i]);
        }
        bound += 8 * LDBL_EPSILON * mag;
        if (!(fabsl(p1 - p0) <= bound))
            fail("momentum %c: before %.21Lg after %.21Lg, |diff| %.3Lg > bound %.3Lg", "xy"[i], p0, p1,
                 fabsl(p1 - p0), bound);
    }
    /* Energy in the frame of an immovable body, if any: a moving wall does
     * work on what it hits, but the response is Galilean invariant. */
    frame[0] = frame[1] = 0;
    for (j = 0; j < 2; j++) {
        if (!x->immovable[j]) continue;
        if (x->w[2 * j] != x->v[2 * j] || x->w[2 * j + 1] != x->v[2 * j + 1])
            fail("immovable body %c moved", "ab"[j]);
        frame[0] = x->v[2 * j], frame[1] = x->v[2 * j + 1];
    }
    for (j = 0; j < 2; j++) {
        long double scale = 0;
        if (x->immovable[j]) continue;
        for (i = 0; i < 2; i++) {
            long double v = x->v[2 * j + i] - frame[i], w = x->w[2 * j + i] - frame[i];
            ke0 += x->m[j] * v * v;
            ke1 += x->m[j] * w * w;
            if (fabsl(v) > scale) scale = fabsl(v);
            if (fabsl(w) > scale) scale = fabsl(w);
        }
        ke_bound += 2 * x->m[j] * x->delta[j] * (2 * scale + x->delta[j]);
    }
    ke_mag = ke0 + ke1;
    ke_bound += 8 * LDBL_EPSILON * ke_mag;
    /* ke0, ke1 are 2 KE: compare doubled energies against the doubled bound. */
    if (!(ke1 - ke0 <= ke_bound))
        fail("energy gained: 2KE %.21Lg -> %.21Lg (+%.3Lg > bound %.3Lg)", ke0, ke1, ke1 - ke0, ke_bound);
}

static void fill_scales(response *x, fmt f)
{
    int j;
    for (j = 0; j < 2; j++) {
        x->scale[j] = maxabs4(x->v[2 * j], x->v[2 * j + 1], x->w[2 * j], x->w[2 * j + 1]);
        x->delta[j] = 16 * ulp_of(x->scale[j], f);
    }
}

static response response_d(const c2d_body *a0, const c2d_body *b0, const c2d_body *a, const c2d_body *b,
                           long double nx, long double ny)
{
    response x;
    x.n[0] = nx, x.n[1] = ny;
    x.v[0] = a0->vel.x, x.v[1] = a0->vel.y, x.v[2] = b0->vel.x, x.v[3] = b0->vel.y;
    x.w[0] = a->vel.x, x.w[1] = a->vel.y, x.w[2] = b->vel.x, x.w[3] = b->vel.y;
    x.m[0] = a0->mass, x.m[1] = b0->mass;
    x.immovable[0] = isinf(a0->mass), x.immovable[1] = isinf(b0->mass);
    fill_scales(&x, FMT_D);
    return x;
}

static response response_f(const c2d_bodyf *a0, const c2d_bodyf *b0, const c2d_bodyf *a, const c2d_bodyf *b,
                           long double nx, long double ny)
{
    response x;
    x.n[0] = nx, x.n[1] = ny;
    x.v[0] = a0->vel.x, x.v[1] = a0->vel.y, x.v[2] = b0->vel.x, x.v[3] = b0->vel.y;
    x.w[0] = a->vel.x, x.w[1] = a->vel.y, x.w[2] = b->vel.x, x.w[3] = b->vel.y;
    x.m[0] = a0->mass, x.m[1] = b0->mass;
    x.immovable[0] = isinf(a0->mass), x.immovable[1] = isinf(b0->mass);
    fill_scales(&x, FMT_F);
    return x;
}

/* Raw Q16.16 units throughout (momentum and energy scale uniformly). */
static response response_x(const c2d_bodyx *a0, const c2d_bodyx *b0, const c2d_bodyx *a, const c2d_bodyx *b,
                           long double nx, long double ny)
{
    response x;
    x.n[0] = nx, x.n[1] = ny;
    int j;
    x.v[0] = a0->vel.x, x.v[1] = a0->vel.y, x.v[2] = b0->vel.x, x.v[3] = b0->vel.y;
    x.w[0] = a->vel.x, x.w[1] = a->vel.y, x.w[2] = b->vel.x, x.w[3] = b->vel.y;
    x.m[0] = a0->mass, x.m[1] = b0->mass;
    x.immovable[0] = a0->mass == C2D_FIXED_INFINITE_MASS;
    x.immovable[1] = b0->mass == C2D_FIXED_INFINITE_MASS;
    for (j = 0; j < 2; j++) x.scale[j] = maxabs4(x.v[2 * j], x.v[2 * j + 1], x.w[2 * j], x.w[2 * j + 1]);
    /* The header's S is the largest component of EITHER body. */
    for (j = 0; j < 2; j++) x.delta[j] = 3 + ldexpl(x.scale[0] > x.scale[1] ? x.scale[0] : x.scale[1], -24);
    return x;
}

/* ------------------------------------------------------ double checks */

static void check_untouched(const void *before, const void *after, size_t n, c2d_status s, const char *what)
{
    if (memcmp(before, after, n) != 0) fail("status %s but %s was modified", c2d_status_string(s), what);
}

static void check_ok_d(const c2d_body *a0, const c2d_body *b0, const c2d_body *a, const c2d_body *b,
                       long double nx, long double ny)
{
    response x;
    if (memcmp(&a0->pos, &a->pos, sizeof a->pos) != 0 || memcmp(&b0->pos, &b->pos, sizeof b->pos) != 0 ||
        memcmp(&a0->mass, &a->mass, sizeof a->mass) != 0 || memcmp(&b0->mass, &b->mass, sizeof b->mass) != 0)
        fail("OK but a position or mass was written");
    if (!isfinite(a->vel.x) || !isfinite(a->vel.y) || !isfinite(b->vel.x) || !isfinite(b->vel.y))
        fail("OK with a non-finite output (%a %a %a %a)", a->vel.x, a->vel.y, b->vel.x, b->vel.y);
    x = response_d(a0, b0, a, b, nx, ny);
    check_conservation(&x);
}

static void check_result_d(c2d_status s, const c2d_body *a0, const c2d_body *b0, const c2d_body *a,
                           const c2d_body *b, long double nx, long double ny)
{
    check_status(s);
    if (s == C2D_OK) {
        check_ok_d(a0, b0, a, b, nx, ny);
    } else {
        check_untouched(a0, a, sizeof *a, s, "a");
        check_untouched(b0, b, sizeof *b, s, "b");
    }
}

static c2d_status run_collide_d(c2d_body *a, c2d_body *b, const c2d_vec2 *n, double e)
{
    c2d_body a0 = *a, b0 = *b;
    c2d_status s = n ? c2d_collide_normal(a, b, *n, e) : c2d_collide(a, b, e);
    long double nx = n ? (long double)n->x : (long double)b0.pos.x - a0.pos.x;
    long double ny = n ? (long double)n->y : (long double)b0.pos.y - a0.pos.y;
    check_result_d(s, &a0, &b0, a, b, nx, ny);
    return s;
}

static void fuzz_collide(reader *r, int with_normal)
{
    c2d_body a, b;
    c2d_vec2 n;
    double e;
    rd_body(r, &a);
    rd_body(r, &b);
    n.x = rd_double(r);
    n.y = rd_double(r);
    e = rd_restitution(r);
    describe_d(&a, &b, n.x, n.y, e);
    (void)run_collide_d(&a, &b, with_normal ? &n : NULL, e);
}

static void check_toi_d(c2d_status s, double t, double t0)
{
    check_status(s);
    if (s == C2D_OK && !(isfinite(t) && t >= 0)) fail("time of impact OK but t = %a", t);
    if (s != C2D_OK && memcmp(&t, &t0, sizeof t) != 0) fail("time of impact %s but *t written", c2d_status_string(s));
}

static void fuzz_toi(reader *r)
{
    c2d_body a, b, a0, b0;
    double rad, t, t0;
    c2d_status s;
    rd_body(r, &a);
    rd_body(r, &b);
    rad = rd_double(r);
    if (r->mode == MODE_TAME) rad = fabs(rad);
    describe_d(&a, &b, 0, 0, rad);
    a0 = a, b0 = b;
    t = t0 = -12345.0;
    s = c2d_time_of_impact(&a, &b, rad, &t);
    check_toi_d(s, t, t0);
    check_untouched(&a0, &a, sizeof a, s, "a (const)");
    check_untouched(&b0, &b, sizeof b, s, "b (const)");
}

/* ------------------------------------------------------- float checks */

static void widen(const c2d_bodyf *f, c2d_body *d)
{
    d->pos.x = f->pos.x, d->pos.y = f->pos.y;
    d->vel.x = f->vel.x, d->vel.y = f->vel.y;
    d->mass = f->mass;
}

static int float_result_near_limit(const c2d_body *a0, const c2d_body *b0, const c2d_body *a, const c2d_body *b)
{
    const double lim = FLT_MAX / 8 * (1 - 1e-6); /* the double result is itself 16 ulp off */
    const double *v0[2] = {&a0->vel.x, &b0->vel.x}, *v1[2] = {&a->vel.x, &b->vel.x};
    int j, i;
    for (j = 0; j < 2; j++)
        for (i = 0; i < 2; i++)
            if (fabs(v1[j][i]) >= lim || fabs(v1[j][i] - v0[j][i]) >= lim) return 1;
    return 0;
}

/* The float answer against the double answer for the same (widened)
 * inputs: both within their documented bound of the exact result. */
static void compare_float_double(c2d_status sf, c2d_status sd, const c2d_bodyf *af, const c2d_bodyf *bf,
                                 const c2d_bodyf *af0, const c2d_bodyf *bf0, const c2d_body *ad,
                                 const c2d_body *bd, const c2d_body *ad0, const c2d_body *bd0)
{
    const double vf[4] = {af->vel.x, af->vel.y, bf->vel.x, bf->vel.y};
    const double vd[4] = {ad->vel.x, ad->vel.y, bd->vel.x, bd->vel.y};
    response xf, xd;
    int i;
    if (sf == C2D_RANGE && sd == C2D_OK) {
        if (!float_result_near_limit(ad0, bd0, ad, bd)) fail("float RANGE where the result is far below FLT_MAX/8");
        return;
    }
    if (sf != sd) fail("float status %s, double status %s", c2d_status_string(sf), c2d_status_string(sd));
    if (sf != C2D_OK) return;
    xf = response_f(af0, bf0, af, bf, 1, 0); /* only the deltas are used */
    xd = response_d(ad0, bd0, ad, bd, 1, 0);
    for (i = 0; i < 4; i++) {
        long double bound = xf.delta[i / 2] + xd.delta[i / 2];
        if (!(fabsl((long double)vf[i] - vd[i]) <= bound))
            fail("float/double disagree in output %d: %a vs %a (bound %La)", i, vf[i], vd[i], bound);
    }
}

static void fuzz_collidef(reader *r, int with_normal)
{
    c2d_bodyf a, b, a0, b0;
    c2d_body ad, bd, ad0, bd0;
    c2d_vec2f n;
    c2d_vec2 nd;
    float e;
    c2d_status s, sd;
    rd_bodyf(r, &a);
    rd_bodyf(r, &b);
    n.x = rd_float(r);
    n.y = rd_float(r);
    e = rd_restitutionf(r);
    widen(&a, &ad);
    widen(&b, &bd);
    describe_d(&ad, &bd, n.x, n.y, e);
    a0 = a, b0 = b;
    s = with_normal ? c2d_collide_normalf(&a, &b, n, e) : c2d_collidef(&a, &b, e);
    check_status(s);
    if (s == C2D_OK) {
        response x;
        if (memcmp(&a0.pos, &a.pos, sizeof a.pos) != 0 || memcmp(&b0.pos, &b.pos, sizeof b.pos) != 0 ||
            memcmp(&a0.mass, &a.mass, sizeof a.mass) != 0 || memcmp(&b0.mass, &b.mass, sizeof b.mass) != 0)
            fail("OK but a position or mass was written (float)");
        if (!isfinite(a.vel.x) || !isfinite(a.vel.y) || !isfinite(b.vel.x) || !isfinite(b.vel.y))
            fail("OK with a non-finite float output");
        x = response_f(&a0, &b0, &a, &b, with_normal ? (long double)n.x : (long double)b.pos.x - a.pos.x,
                       with_normal ? (long double)n.y : (long double)b.pos.y - a.pos.y);
        check_conservation(&x);
    } else {
        check_untouched(&a0, &a, sizeof a, s, "a");
        check_untouched(&b0, &b, sizeof b, s, "b");
    }
    widen(&a0, &ad);
    widen(&b0, &bd);
    nd.x = n.x, nd.y = n.y;
    ad0 = ad, bd0 = bd;
    sd = run_collide_d(&ad, &bd, with_normal ? &nd : NULL, e);
    compare_float_double(s, sd, &a, &b, &a0, &b0, &ad, &bd, &ad0, &bd0);
}

static void fuzz_toif(reader *r)
{
    c2d_bodyf a, b, a0, b0;
    float rad, t, t0;
    c2d_status s;
    rd_bodyf(r, &a);
    rd_bodyf(r, &b);
    rad = rd_float(r);
    if (r->mode == MODE_TAME) rad = fabsf(rad);
    {
        c2d_body ad, bd;
        widen(&a, &ad);
        widen(&b, &bd);
        describe_d(&ad, &bd, 0, 0, rad);
    }
    a0 = a, b0 = b;
    t = t0 = -12345.0f;
    s = c2d_time_of_impactf(&a, &b, rad, &t);
    check_status(s);
    if (s == C2D_OK && !(isfinite(t) && t >= 0)) fail("float time of impact OK but t = %a", (double)t);
    if (s != C2D_OK && memcmp(&t, &t0, sizeof t) != 0) fail("float time of impact %s but *t written", c2d_status_string(s));
    check_untouched(&a0, &a, sizeof a, s, "a (const)");
    check_untouched(&b0, &b, sizeof b, s, "b (const)");
}

/* ---------------------------------------------------------- Q16.16 */

static void to_double_x(const c2d_bodyx *x, c2d_body *d)
{
    d->pos.x = x->pos.x / 65536.0, d->pos.y = x->pos.y / 65536.0;
    d->vel.x = x->vel.x / 65536.0, d->vel.y = x->vel.y / 65536.0;
    d->mass = x->mass == C2D_FIXED_INFINITE_MASS ? INFINITY : x->mass / 65536.0;
}

/* Approach speed along the normal in steps (2^-16 per time unit). */
static long double approach_steps(const c2d_body *a, const c2d_body *b, long double nx, long double ny)
{
    long double d = ((long double)b->vel.x - a->vel.x) * nx + ((long double)b->vel.y - a->vel.y) * ny;
    return -d / sqrtl(nx * nx + ny * ny) * 65536;
}

/* Q16.16 against double on the same (exactly converted) inputs.  The double
 * answer is within 16 ulp of exact, the Q16.16 one within 3 steps + 2^-24 S;
 * the Q16.16 status may differ only where the documented rounding allows:
 * SEPARATING when the approach speed rounds below one step, RANGE when a
 * result leaves the Q16.16 range. */
static void compare_fixed_double(c2d_status sx, c2d_status sd, const c2d_bodyx *ax, const c2d_bodyx *bx,
                                 const c2d_bodyx *ax0, const c2d_bodyx *bx0, const c2d_body *ad,
                                 const c2d_body *bd, long double nx, long double ny)
{
    const long double vd[4] = {ad->vel.x * 65536.0L, ad->vel.y * 65536.0L, bd->vel.x * 65536.0L,
                               bd->vel.y * 65536.0L};
    const long double vx[4] = {ax->vel.x, ax->vel.y, bx->vel.x, bx->vel.y};
    response x;
    int i;
    if (sx == sd && sx != C2D_OK) return;
    if (sx != sd) {
        c2d_body a0, b0;
        long double speed;
        to_double_x(ax0, &a0);
        to_double_x(bx0, &b0);
        speed = approach_steps(&a0, &b0, nx, ny);
        /* The approach speed is rounded to a step (< 1 step) after the Q2.28
         * unit normal, whose error the header bounds by 2^-24 S (S: largest
         * velocity component of either body); beyond that the statuses must
         * agree. */
        if ((sx == C2D_SEPARATING && sd == C2D_OK) || (sx == C2D_OK && sd == C2D_SEPARATING)) {
            long double s_in = maxabs4(ax0->vel.x, ax0->vel.y, bx0->vel.x, bx0->vel.y);
            if (speed <= 1 + ldexpl(s_in, -24)) return;
            fail("Q16.16 %s, double %s, approach speed %.6Lg steps", c2d_status_string(sx),
                 c2d_status_string(sd), speed);
        }
        if (sx == C2D_RANGE && sd == C2D_OK) {
            for (i = 0; i < 4; i++)
                if (fabsl(vd[i]) > INT32_MAX - 4 - ldexpl(fabsl(vd[i]), -23)) return;
            fail("Q16.16 RANGE but the double result fits (%.1Lf %.1Lf %.1Lf %.1Lf)", vd[0], vd[1], vd[2], vd[3]);
        }
        fail("Q16.16 status %s, double status %s", c2d_status_string(sx), c2d_status_string(sd));
    }
    x = response_x(ax0, bx0, ax, bx, nx, ny);
    for (i = 0; i < 4; i++) {
        long double bound = x.delta[i / 2] + 16 * ulp_of(x.scale[i / 2], FMT_D) * 65536;
        if (!(fabsl(vx[i] - vd[i]) <= bound))
            fail("Q16.16 output %d = %.0Lf steps, double says %.6Lf (bound %.4Lg)", i, vx[i], vd[i], bound);
    }
}

static void fuzz_collidex(reader *r, int with_normal)
{
    c2d_bodyx a, b, a0, b0;
    c2d_body ad, bd;
    c2d_vec2x n;
    c2d_vec2 nd;
    c2d_fixed e;
    c2d_status s, sd;
    long double nx, ny;
    rd_bodyx(r, &a);
    rd_bodyx(r, &b);
    n.x = rd_fixed(r);
    n.y = rd_fixed(r);
    e = rd_restitutionx(r);
    describe_x(&a, &b, n.x, n.y, e);
    a0 = a, b0 = b;
    s = with_normal ? c2d_collide_normalx(&a, &b, n, e) : c2d_collidex(&a, &b, e);
    check_status(s);
    if (s == C2D_OK) {
        response x;
        if (memcmp(&a0.pos, &a.pos, sizeof a.pos) != 0 || memcmp(&b0.pos, &b.pos, sizeof b.pos) != 0 ||
            a0.mass != a.mass || b0.mass != b.mass)
            fail("OK but a position or mass was written (Q16.16)");
        x = response_x(&a0, &b0, &a, &b, with_normal ? (long double)n.x : (long double)b.pos.x - a.pos.x,
                       with_normal ? (long double)n.y : (long double)b.pos.y - a.pos.y);
        check_conservation(&x);
    } else {
        check_untouched(&a0, &a, sizeof a, s, "a");
        check_untouched(&b0, &b, sizeof b, s, "b");
    }
    if (e < 0 || e > C2D_FIXED_ONE || a0.mass <= 0 || b0.mass <= 0) {
        if (s != C2D_INVALID) fail("Q16.16 invalid mass or restitution gave %s", c2d_status_string(s));
        return;
    }
    to_double_x(&a0, &ad);
    to_double_x(&b0, &bd);
    nd.x = n.x, nd.y = n.y;
    nx = with_normal ? (long double)n.x : (long double)b0.pos.x - a0.pos.x;
    ny = with_normal ? (long double)n.y : (long double)b0.pos.y - a0.pos.y;
    sd = run_collide_d(&ad, &bd, with_normal ? &nd : NULL, e / 65536.0);
    compare_fixed_double(s, sd, &a, &b, &a0, &b0, &ad, &bd, nx, ny);
}

/* Q16.16 time of impact against double: the documented bound is 2 steps plus
 * the time to close one step (2^-16) of distance at the approach speed at
 * contact; the double answer adds 4 ulp of t plus 4 ulp of the contact
 * distance's worth of time.  FINDING (reported, regress-toix-far): for
 * centres more than 2^29 steps apart the library rounds d and radius_sum to
 * 29 bits, i.e. up to |d| 2^-29 per component and radius, so the distance
 * error allowed here is 1 step + |d|max 2^-27 steps (three such roundings,
 * rounded up) until the header states it or the library keeps d exact. */
static void compare_toi_fixed_double(c2d_fixed tx, double td, const c2d_body *a, const c2d_body *b, double rad)
{
    long double dmax = 65536 * maxabs4((long double)b->pos.x - a->pos.x, (long double)b->pos.y - a->pos.y, 0, 0);
    long double px = (long double)b->pos.x - a->pos.x + ((long double)b->vel.x - a->vel.x) * td;
    long double py = (long double)b->pos.y - a->pos.y + ((long double)b->vel.y - a->vel.y) * td;
    long double vx = (long double)b->vel.x - a->vel.x, vy = (long double)b->vel.y - a->vel.y;
    long double dist = sqrtl(px * px + py * py);
    long double vc = dist > 0 ? -(px * vx + py * vy) / dist : sqrtl(vx * vx + vy * vy);
    long double bound, err;
    if (!(vc > 0)) return; /* tangential contact: the bound is unbounded */
    bound = 2 + (1 + ldexpl(dmax, -27)) / vc + (4 * ulp_of(td, FMT_D) + 4 * ulp_of(rad, FMT_D) / vc) * 65536;
    err = fabsl((long double)tx - (long double)td * 65536);
    if (!(err <= bound))
        fail("Q16.16 time of impact %d steps, double %.6Lf steps (bound %.4Lg)", (int)tx, (long double)td * 65536,
             bound);
}

static void fuzz_toix(reader *r)
{
    c2d_bodyx a, b, a0, b0;
    c2d_body ad, bd;
    c2d_fixed rad, t, t0;
    double td = -1;
    c2d_status s, sd;
    rd_bodyx(r, &a);
    rd_bodyx(r, &b);
    rad = rd_fixed(r);
    if (r->mode == MODE_TAME && rad < 0) rad = (c2d_fixed)(-(int64_t)rad > INT32_MAX ? INT32_MAX : -rad);
    describe_x(&a, &b, 0, 0, rad);
    a0 = a, b0 = b;
    t = t0 = -12345;
    s = c2d_time_of_impactx(&a, &b, rad, &t);
    check_status(s);
    if (s == C2D_OK && t < 0) fail("Q16.16 time of impact OK but t = %d", (int)t);
    if (s != C2D_OK && t != t0) fail("Q16.16 time of impact %s but *t written", c2d_status_string(s));
    check_untouched(&a0, &a, sizeof a, s, "a (const)");
    check_untouched(&b0, &b, sizeof b, s, "b (const)");
    if (rad < 0) {
        if (s != C2D_INVALID) fail("Q16.16 time of impact with radius_sum < 0 gave %s", c2d_status_string(s));
        return;
    }
    to_double_x(&a0, &ad);
    to_double_x(&b0, &bd);
    sd = c2d_time_of_impact(&ad, &bd, rad / 65536.0, &td);
    check_toi_d(sd, td, -1);
    if (s == C2D_OK && sd == C2D_OK) compare_toi_fixed_double(t, td, &ad, &bd, rad / 65536.0);
}

/* ------------------------------------------------------------ batch */

#define MAX_PAIRS 24 /* three kernel blocks, so full blocks and a tail both occur */

typedef struct soa_d {
    double ax[MAX_PAIRS], ay[MAX_PAIRS], bx[MAX_PAIRS], by[MAX_PAIRS];
    double avx[MAX_PAIRS], avy[MAX_PAIRS], bvx[MAX_PAIRS], bvy[MAX_PAIRS], ma[MAX_PAIRS], mb[MAX_PAIRS];
} soa_d;

typedef struct soa_f {
    float ax[MAX_PAIRS], ay[MAX_PAIRS], bx[MAX_PAIRS], by[MAX_PAIRS];
    float avx[MAX_PAIRS], avy[MAX_PAIRS], bvx[MAX_PAIRS], bvy[MAX_PAIRS], ma[MAX_PAIRS], mb[MAX_PAIRS];
} soa_f;

static void fuzz_batch(reader *r, int flags)
{
    static soa_d s;
    c2d_status st[MAX_PAIRS];
    c2d_body a[MAX_PAIRS], b[MAX_PAIRS];
    c2d_pairs p;
    size_t count = (size_t)(rd_byte(r) % (MAX_PAIRS + 1)), i, done, want_done = 0;
    double e = rd_restitution(r);
    for (i = 0; i < count; i++) {
        rd_body(r, &a[i]);
        rd_body(r, &b[i]);
        s.ax[i] = a[i].pos.x, s.ay[i] = a[i].pos.y, s.avx[i] = a[i].vel.x, s.avy[i] = a[i].vel.y;
        s.bx[i] = b[i].pos.x, s.by[i] = b[i].pos.y, s.bvx[i] = b[i].vel.x, s.bvy[i] = b[i].vel.y;
        s.ma[i] = a[i].mass, s.mb[i] = b[i].mass;
        st[i] = (c2d_status)-1;
    }
    p.pos_ax = s.ax, p.pos_ay = s.ay, p.pos_bx = s.bx, p.pos_by = s.by;
    p.vel_ax = s.avx, p.vel_ay = s.avy, p.vel_bx = s.bvx, p.vel_by = s.bvy;
    p.mass_a = s.ma, p.mass_b = s.mb;
    done = c2d_collide_batch(&p, count, e, (flags & FLAG_NULL_STATUS) ? NULL : st);
    for (i = 0; i < count; i++) {
        c2d_status want;
        describe_d(&a[i], &b[i], 0, 0, e);
        want = run_collide_d(&a[i], &b[i], NULL, e);
        if (want == C2D_OK) want_done++;
        if (!(flags & FLAG_NULL_STATUS) && st[i] != want)
            fail("batch pair %zu status %s, scalar %s", i, c2d_status_string(st[i]), c2d_status_string(want));
        if (memcmp(&s.avx[i], &a[i].vel.x, sizeof(double)) || memcmp(&s.avy[i], &a[i].vel.y, sizeof(double)) ||
            memcmp(&s.bvx[i], &b[i].vel.x, sizeof(double)) || memcmp(&s.bvy[i], &b[i].vel.y, sizeof(double)))
            fail("batch pair %zu differs from the scalar call", i);
    }
    if (done != want_done) fail("batch returned %zu, scalar calls gave %zu OK", done, want_done);
    if (c2d_collide_batch(NULL, count, e, st) != 0) fail("batch with p == NULL did not return 0");
}

static void fuzz_batchf(reader *r, int flags)
{
    static soa_f s;
    c2d_status st[MAX_PAIRS];
    c2d_bodyf a[MAX_PAIRS], b[MAX_PAIRS];
    c2d_pairsf p;
    size_t count = (size_t)(rd_byte(r) % (MAX_PAIRS + 1)), i, done, want_done = 0;
    float e = rd_restitutionf(r);
    for (i = 0; i < count; i++) {
        rd_bodyf(r, &a[i]);
        rd_bodyf(r, &b[i]);
        s.ax[i] = a[i].pos.x, s.ay[i] = a[i].pos.y, s.avx[i] = a[i].vel.x, s.avy[i] = a[i].vel.y;
        s.bx[i] = b[i].pos.x, s.by[i] = b[i].pos.y, s.bvx[i] = b[i].vel.x, s.bvy[i] = b[i].vel.y;
        s.ma[i] = a[i].mass, s.mb[i] = b[i].mass;
        st[i] = (c2d_status)-1;
    }
    p.pos_ax = s.ax, p.pos_ay = s.ay, p.pos_bx = s.bx, p.pos_by = s.by;
    p.vel_ax = s.avx, p.vel_ay = s.avy, p.vel_bx = s.bvx, p.vel_by = s.bvy;
    p.mass_a = s.ma, p.mass_b = s.mb;
    done = c2d_collide_batchf(&p, count, e, (flags & FLAG_NULL_STATUS) ? NULL : st);
    for (i = 0; i < count; i++) {
        c2d_bodyf a0 = a[i], b0 = b[i];
        c2d_body ad, bd;
        c2d_status want;
        widen(&a0, &ad);
        widen(&b0, &bd);
        describe_d(&ad, &bd, 0, 0, e);
        want = c2d_collidef(&a[i], &b[i], e);
        check_status(want);
        if (want != C2D_OK) {
            check_untouched(&a0, &a[i], sizeof a0, want, "a");
            check_untouched(&b0, &b[i], sizeof b0, want, "b");
        }
        if (want == C2D_OK) want_done++;
        if (!(flags & FLAG_NULL_STATUS) && st[i] != want)
            fail("batchf pair %zu status %s, scalar %s", i, c2d_status_string(st[i]), c2d_status_string(want));
        if (memcmp(&s.avx[i], &a[i].vel.x, sizeof(float)) || memcmp(&s.avy[i], &a[i].vel.y, sizeof(float)) ||
            memcmp(&s.bvx[i], &b[i].vel.x, sizeof(float)) || memcmp(&s.bvy[i], &b[i].vel.y, sizeof(float)))
            fail("batchf pair %zu differs from the scalar call", i);
    }
    if (done != want_done) fail("batchf returned %zu, scalar calls gave %zu OK", done, want_done);
    if (c2d_collide_batchf(NULL, count, e, st) != 0) fail("batchf with p == NULL did not return 0");
}

/* ------------------------------------------------------------- entry */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[C2D_FUZZ_ENTRIES] = {
        "c2d_collide", "c2d_collide_normal", "c2d_time_of_impact", "c2d_collidef", "c2d_collide_normalf",
        "c2d_time_of_impactf", "c2d_collidex", "c2d_collide_normalx", "c2d_time_of_impactx",
        "c2d_collide_batch", "c2d_collide_batchf"};
    reader r;
    int entry, flags;
    r.p = data;
    r.n = size;
    r.mode = MODE_MIXED;
    entry = rd_byte(&r) % C2D_FUZZ_ENTRIES;
    flags = rd_byte(&r);
    r.mode = flags % 4 == 3 ? MODE_MIXED : flags % 4;
    c2d_fuzz_case = names[entry];
    switch (entry) {
    case E_COLLIDE: fuzz_collide(&r, 0); break;
    case E_COLLIDE_NORMAL: fuzz_collide(&r, 1); break;
    case E_TOI: fuzz_toi(&r); break;
    case E_COLLIDEF: fuzz_collidef(&r, 0); break;
    case E_COLLIDE_NORMALF: fuzz_collidef(&r, 1); break;
    case E_TOIF: fuzz_toif(&r); break;
    case E_COLLIDEX: fuzz_collidex(&r, 0); break;
    case E_COLLIDE_NORMALX: fuzz_collidex(&r, 1); break;
    case E_TOIX: fuzz_toix(&r); break;
    case E_BATCH: fuzz_batch(&r, flags); break;
    default: fuzz_batchf(&r, flags); break;
    }
    return 0;
}
