/* SPDX-License-Identifier: MIT */
/* hash_cases.c - the determinism hash's cases and runners (hash_cases.h).
 *
 * The cases come from a fixed splitmix64 stream (referee/rng.h): unit-scale
 * scenes, grazing impacts, whole-range extremes (every binade, subnormals,
 * zeros, NaN, Inf, mass ratios up to the full range, immovable bodies), and
 * Q16.16 scenes (converted, or raw random int32 fields).  Each case runs
 * through every scalar entry point compiled in, and every CHUNK cases
 * through the batch entry points.  Only exact operations and single
 * correctly rounded ones make the inputs (contraction off), so every
 * IEEE-754 target generates the same bits; a NaN is converted to float by
 * its bits, not by the target's conversion (RISC-V makes every NaN the
 * canonical one).  Streaming, with CHUNK cases in memory at most: it fits a
 * microcontroller's 16 KiB of RAM. */
#include "hash_cases.h"

#include "collide2d.h"
#include "harness.h"
#include "rng.h"

#define CHUNK 32 /* pairs per batch call: two blocks of the kernel */

const char *const c2d_hv_name[C2D_HV_VARIANTS] = {"double", "float", "Q16.16"};

/* The scene in double whatever is compiled in (c2d_body may not be). */
typedef struct hv_vec2 { double x, y; } hv_vec2;
typedef struct hv_body { hv_vec2 pos, vel; double mass; } hv_body;
typedef struct hv_scene {
    hv_body a, b;
    hv_vec2 n;
    double e, radius;
    /* Q16.16: the fields of a, b, n, e, radius in that order, raw or
     * converted from the above (hv_fixed_fields). */
    int32_t x[14];
} hv_scene;

static c2d_rng rng;

static uint64_t next(void) { return c2d_rng_next(&rng); }

static double from_bits(uint64_t u)
{
    union { uint64_t u; double d; } p;
    p.u = u;
    return p.d;
}

static double uniform(double lo, double hi) { return c2d_rng_range(&rng, lo, hi); }

/* Any finite double, exponent uniform over the whole range (subnormals
 * included), or occasionally a special value. */
static double extreme(void)
{
    uint64_t r = next();
    switch (r % 32) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return from_bits(0x7FF8000000000000ull); /* NaN */
    case 3: return from_bits(0x7FF0000000000000ull); /* Inf */
    default: {
        uint64_t exp = (next() % 2047); /* 0 (subnormal) .. 2046 */
        uint64_t sign = (r >> 63) << 63;
        return from_bits(sign | (exp << 52) | (next() & 0xFFFFFFFFFFFFFull));
    }
    }
}

static double restitution(void)
{
    switch (next() % 4) {
    case 0: return 1.0;
    case 1: return 0.0;
    default: return uniform(0, 1);
    }
}

static void plain(hv_scene *s)
{
    s->a.pos.x = uniform(-10, 10), s->a.pos.y = uniform(-10, 10);
    s->b.pos.x = s->a.pos.x + uniform(-2, 2), s->b.pos.y = s->a.pos.y + uniform(-2, 2);
    s->a.vel.x = uniform(-10, 10), s->a.vel.y = uniform(-10, 10);
    s->b.vel.x = uniform(-10, 10), s->b.vel.y = uniform(-10, 10);
    s->a.mass = uniform(0.1, 10), s->b.mass = next() % 16 == 0 ? from_bits(0x7FF0000000000000ull) : uniform(0.1, 10);
    s->n.x = s->b.pos.x - s->a.pos.x, s->n.y = s->b.pos.y - s->a.pos.y;
    s->radius = uniform(0, 3);
}

/* Relative velocity almost perpendicular to the normal: d cancels. */
static void grazing(hv_scene *s)
{
    double k = uniform(-1e-9, 1e-9);
    plain(s);
    s->b.vel.x = s->a.vel.x - s->n.y * 3 + s->n.x * k;
    s->b.vel.y = s->a.vel.y + s->n.x * 3 + s->n.y * k;
}

static double absolute_sometimes(double v) { return next() % 2 && v < 0 ? -v : v; }

static void wide(hv_scene *s)
{
    s->a.pos.x = extreme(), s->a.pos.y = extreme(), s->b.pos.x = extreme(), s->b.pos.y = extreme();
    s->a.vel.x = extreme(), s->a.vel.y = extreme(), s->b.vel.x = extreme(), s->b.vel.y = extreme();
    s->a.mass = extreme(), s->b.mass = extreme();
    s->a.mass = absolute_sometimes(s->a.mass);
    s->b.mass = absolute_sometimes(s->b.mass);
    s->n.x = extreme(), s->n.y = extreme();
    s->radius = absolute_sometimes(extreme());
}

/* Q16.16 from a double: truncated, saturated, NaN as INT32_MIN. */
static int32_t to_fixed(double v)
{
    double r = v * 65536.0;
    if (!(r > -2147483648.0)) return INT32_MIN;
    if (!(r < 2147483647.0)) return INT32_MAX;
    return (int32_t)r;
}

/* One case in four takes raw random int32 fields (a random restitution in
 * half of those), the others the double scene's fields converted. */
static void fixed_fields(hv_scene *s)
{
    const double from[14] = {s->a.pos.x, s->a.pos.y, s->a.vel.x, s->a.vel.y, s->a.mass, s->b.pos.x, s->b.pos.y,
                             s->b.vel.x, s->b.vel.y, s->b.mass, s->n.x,     s->n.y,     s->e,       s->radius};
    int raw = next() % 4 == 0, i;
    for (i = 0; i < 14; i++) {
        int draw = raw && (i != 12 || next() % 2);
        s->x[i] = draw ? (int32_t)(uint32_t)next() : to_fixed(from[i]);
    }
}

static void make_scene(hv_scene *s)
{
    uint64_t k = next() % 8;
    if (k < 4) plain(s);
    else if (k < 5) grazing(s);
    else wide(s);
    s->e = next() % 64 == 0 ? extreme() : restitution();
    fixed_fields(s);
}

/* ------------------------------------------------------------------ hash */

static c2d_hv_hash *out;
static void (*sink)(const void *, size_t);

static void fnv(uint64_t *h, const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; i++) {
        *h ^= b[i];
        *h *= 0x100000001B3ull;
    }
}

static void mix(int variant, const void *p, size_t n)
{
    if (sink != NULL) sink(p, n);
    fnv(&out->variant[variant], p, n);
}

/* A status as one byte, a count as 8 little-endian bytes: the same on
 * targets whose enums and size_t differ in size. */
static void mix_status(int variant, c2d_status s)
{
    unsigned char c = (unsigned char)s;
    mix(variant, &c, 1);
}

static void mix_count(int variant, size_t k)
{
    unsigned char b[8];
    int i;
    for (i = 0; i < 8; i++) b[i] = (unsigned char)((uint64_t)k >> (8 * i));
    mix(variant, b, sizeof b);
}

/* ------------------------------------------------------------ runners */

#ifndef C2D_NO_DOUBLE
static c2d_body to_double(const hv_body *h)
{
    c2d_body b;
    b.pos.x = h->pos.x, b.pos.y = h->pos.y, b.vel.x = h->vel.x, b.vel.y = h->vel.y, b.mass = h->mass;
    return b;
}

static void run_double(const hv_scene *s)
{
    const c2d_body a0 = to_double(&s->a), b0 = to_double(&s->b);
    c2d_body a = a0, b = b0;
    c2d_vec2 n;
    double t = -1;
    n.x = s->n.x, n.y = s->n.y;
    mix_status(C2D_HV_DOUBLE, c2d_collide(&a, &b, s->e));
    mix(C2D_HV_DOUBLE, &a.vel, sizeof a.vel), mix(C2D_HV_DOUBLE, &b.vel, sizeof b.vel);
    a = a0, b = b0;
    mix_status(C2D_HV_DOUBLE, c2d_collide_normal(&a, &b, n, s->e));
    mix(C2D_HV_DOUBLE, &a.vel, sizeof a.vel), mix(C2D_HV_DOUBLE, &b.vel, sizeof b.vel);
    mix_status(C2D_HV_DOUBLE, c2d_time_of_impact(&a0, &b0, s->radius, &t));
    mix(C2D_HV_DOUBLE, &t, sizeof t);
}
#endif

#ifndef C2D_NO_FLOAT
/* double to float by the target's conversion, but NaN (the scenes hold one,
 * 0x7FF8000000000000) as the default NaN's bits: what a conversion makes of
 * a NaN is not the same on every architecture (RISC-V gives the canonical
 * NaN, x86-64 and Arm keep the payload). */
static float to_float(double d)
{
    union { uint32_t u; float f; } p;
    if (d == d) return (float)d;
    p.u = 0x7FC00000u;
    return p.f;
}

static c2d_bodyf to_bodyf(const hv_body *h)
{
    c2d_bodyf f;
    f.pos.x = to_float(h->pos.x), f.pos.y = to_float(h->pos.y);
    f.vel.x = to_float(h->vel.x), f.vel.y = to_float(h->vel.y);
    f.mass = to_float(h->mass);
    return f;
}

static void run_float(const hv_scene *s)
{
    const c2d_bodyf a0 = to_bodyf(&s->a), b0 = to_bodyf(&s->b);
    c2d_bodyf a = a0, b = b0;
    c2d_vec2f n;
    float e = to_float(s->e), t = -1;
    n.x = to_float(s->n.x), n.y = to_float(s->n.y);
    mix_status(C2D_HV_FLOAT, c2d_collidef(&a, &b, e));
    mix(C2D_HV_FLOAT, &a.vel, sizeof a.vel), mix(C2D_HV_FLOAT, &b.vel, sizeof b.vel);
    a = a0, b = b0;
    mix_status(C2D_HV_FLOAT, c2d_collide_normalf(&a, &b, n, e));
    mix(C2D_HV_FLOAT, &a.vel, sizeof a.vel), mix(C2D_HV_FLOAT, &b.vel, sizeof b.vel);
    mix_status(C2D_HV_FLOAT, c2d_time_of_impactf(&a0, &b0, to_float(s->radius), &t));
    mix(C2D_HV_FLOAT, &t, sizeof t);
}
#endif

#ifndef C2D_NO_FIXED
static void run_fixed(const hv_scene *s)
{
    const int32_t *x = s->x;
    c2d_bodyx a0, b0, a, b;
    c2d_vec2x n;
    c2d_fixed t = -1;
    a0.pos.x = x[0], a0.pos.y = x[1], a0.vel.x = x[2], a0.vel.y = x[3], a0.mass = x[4];
    b0.pos.x = x[5], b0.pos.y = x[6], b0.vel.x = x[7], b0.vel.y = x[8], b0.mass = x[9];
    n.x = x[10], n.y = x[11];
    a = a0, b = b0;
    mix_status(C2D_HV_FIXED, c2d_collidex(&a, &b, x[12]));
    mix(C2D_HV_FIXED, &a.vel, sizeof a.vel), mix(C2D_HV_FIXED, &b.vel, sizeof b.vel);
    a = a0, b = b0;
    mix_status(C2D_HV_FIXED, c2d_collide_normalx(&a, &b, n, x[12]));
    mix(C2D_HV_FIXED, &a.vel, sizeof a.vel), mix(C2D_HV_FIXED, &b.vel, sizeof b.vel);
    mix_status(C2D_HV_FIXED, c2d_time_of_impactx(&a0, &b0, x[13], &t));
    mix(C2D_HV_FIXED, &t, sizeof t);
}
#endif

/* The batch entry points over a chunk of cases, restitution 0.9: the count
 * resolved, the statuses, then the four velocity arrays in c2d_pairs'
 * order. */
#if !defined(C2D_NO_DOUBLE) || !defined(C2D_NO_FLOAT)
static c2d_status chunk_status[CHUNK];

static void mix_statuses(int variant, size_t count, size_t resolved)
{
    size_t i;
    mix_count(variant, resolved);
    for (i = 0; i < count; i++) mix_status(variant, chunk_status[i]);
}
#endif

static void run_batches(const hv_scene *set, size_t count)
{
    size_t i, k;
#ifndef C2D_NO_DOUBLE
    {
        static double block[C2D_SOA_FIELDS * CHUNK];
        const c2d_soa s = c2d_soa_in(block, count, chunk_status);
        const c2d_pairs p = c2d_soa_pairs(&s);
        for (i = 0; i < count; i++) {
            const c2d_body a = to_double(&set[i].a), b = to_double(&set[i].b);
            c2d_soa_put(&s, i, &a, &b);
        }
        mix_statuses(C2D_HV_DOUBLE, count, c2d_collide_batch(&p, count, 0.9, chunk_status));
        for (k = C2D_SOA_VEL_AX; k <= C2D_SOA_VEL_BY; k++) mix(C2D_HV_DOUBLE, s.field[k], count * sizeof *block);
    }
#endif
#ifndef C2D_NO_FLOAT
    {
        static float block[C2D_SOA_FIELDS * CHUNK];
        const c2d_soaf s = c2d_soa_inf(block, count, chunk_status);
        const c2d_pairsf p = c2d_soa_pairsf(&s);
        for (i = 0; i < count; i++) {
            const c2d_bodyf a = to_bodyf(&set[i].a), b = to_bodyf(&set[i].b);
            c2d_soa_putf(&s, i, &a, &b);
        }
        mix_statuses(C2D_HV_FLOAT, count, c2d_collide_batchf(&p, count, 0.9f, chunk_status));
        for (k = C2D_SOA_VEL_AX; k <= C2D_SOA_VEL_BY; k++) mix(C2D_HV_FLOAT, s.field[k], count * sizeof *block);
    }
#endif
    (void)set, (void)count, (void)i, (void)k;
}

void c2d_hv_run(unsigned long count, c2d_hv_hash *h, void (*bytes)(const void *p, size_t n))
{
    static hv_scene chunk[CHUNK];
    unsigned long done = 0;
    size_t fill = 0;
    int v;
    rng.s = 0x2545F4914F6CDD1Dull;
    out = h, sink = bytes;
    h->inputs = 0xCBF29CE484222325ull; /* FNV-1a 64 offset basis */
    for (v = 0; v < C2D_HV_VARIANTS; v++) h->variant[v] = 0xCBF29CE484222325ull, h->present[v] = 0;
#ifndef C2D_NO_DOUBLE
    h->present[C2D_HV_DOUBLE] = 1;
#endif
#ifndef C2D_NO_FLOAT
    h->present[C2D_HV_FLOAT] = 1;
#endif
#ifndef C2D_NO_FIXED
    h->present[C2D_HV_FIXED] = 1;
#endif
    for (done = 0; done < count; done++) {
        hv_scene *s = &chunk[fill++];
        make_scene(s);
        fnv(&h->inputs, s, sizeof *s);
#ifndef C2D_NO_DOUBLE
        run_double(s);
#endif
#ifndef C2D_NO_FLOAT
        run_float(s);
#endif
#ifndef C2D_NO_FIXED
        run_fixed(s);
#endif
        if (fill == CHUNK || done + 1 == count) {
            run_batches(chunk, fill);
            fill = 0;
        }
    }
}

uint64_t c2d_hv_combined(const c2d_hv_hash *h)
{
    uint64_t all = 0xCBF29CE484222325ull;
    int v;
    for (v = 0; v < C2D_HV_VARIANTS; v++)
        if (h->present[v]) fnv(&all, &h->variant[v], sizeof h->variant[v]);
    return all;
}

void c2d_hv_hex(uint64_t v, char hex[17])
{
    static const char digit[] = "0123456789abcdef";
    int i;
    for (i = 15; i >= 0; i--, v >>= 4) hex[i] = digit[v & 0xFu];
    hex[16] = '\0';
}
