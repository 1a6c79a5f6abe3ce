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

/* ------------------------------------------------------------ the models
 *
 * Their own splitmix64 stream (another seed), so the variants' stream and
 * hashes above stay as recorded.  A rough scene is a pair of disks near
 * contact at unit scale (friction, spin, finite and infinite masses and
 * inertias, wall-like bodies) or every field anywhere in the range; an
 * accelerated scene is a pair of unit-scale disks under accelerations
 * (decelerating balls, bodies pushed together, grazes, a horizon that may
 * end before the contact) or every field anywhere in the range.  The
 * inputs are made as the variants' are: exact or single correctly rounded
 * operations only. */

typedef struct hv_disk { double pos[2], vel[2], spin, mass, radius, inertia; } hv_disk;
typedef struct hv_model_scene {
    hv_disk a, b;
    double n[2], e, mu, beta;                        /* rough: given normal, surface */
    double pa[2], va[2], aa[2], pb[2], vb[2], ab[2]; /* accelerated time of impact */
    double radius_sum, horizon;
    double normal_given; /* 0 or 1: c2d_collide_rough or _normal */
} hv_model_scene;

const char *const c2d_hv_model_name[C2D_HV_MODELS] = {"rough-double", "rough-float", "accel-double", "accel-float"};

static c2d_hv_models_hash *models_out;

static void mix_model(int model, const void *p, size_t n)
{
    if (sink != NULL) sink(p, n);
    fnv(&models_out->model[model], p, n);
}

static void mix_model_status(int model, c2d_status s)
{
    unsigned char c = (unsigned char)s;
    mix_model(model, &c, 1);
}

static double infinity(void) { return from_bits(0x7FF0000000000000ull); }

/* Friction: none, some, sticking at any force, or never sliding. */
static double friction(void)
{
    switch (next() % 6) {
    case 0: return 0.0;
    case 1: return 1e6;
    case 2: return infinity();
    default: return uniform(0, 1);
    }
}

static double tangential_restitution(void)
{
    switch (next() % 6) {
    case 0: return -1.0;
    case 1: return 1.0;
    case 2: return 0.0;
    default: return uniform(-1, 1);
    }
}

static void rough_disk_plain(hv_disk *d, double x, double y)
{
    d->pos[0] = x, d->pos[1] = y;
    d->vel[0] = uniform(-10, 10), d->vel[1] = uniform(-10, 10);
    d->radius = next() % 16 == 0 ? 0.0 : uniform(0.1, 1);
    d->spin = uniform(-20, 20);
    d->mass = next() % 12 == 0 ? infinity() : uniform(0.1, 10);
    d->inertia = next() % 8 == 0 ? infinity() : d->mass * uniform(0.01, 1);
}

static void rough_disk_wide(hv_disk *d)
{
    d->pos[0] = extreme(), d->pos[1] = extreme(), d->vel[0] = extreme(), d->vel[1] = extreme();
    d->spin = extreme(), d->mass = absolute_sometimes(extreme());
    d->radius = absolute_sometimes(extreme()), d->inertia = absolute_sometimes(extreme());
}

static void make_rough(hv_model_scene *s)
{
    if (next() % 4 != 0) {
        /* one draw per statement: the order in which a call's arguments
         * are evaluated is unspecified, and differs between targets */
        const double x = uniform(-10, 10);
        const double y = uniform(-10, 10);
        const double dx = uniform(-2, 2);
        const double dy = uniform(-2, 2);
        rough_disk_plain(&s->a, x, y);
        rough_disk_plain(&s->b, x + dx, y + dy);
        s->n[0] = s->b.pos[0] - s->a.pos[0], s->n[1] = s->b.pos[1] - s->a.pos[1];
        s->e = restitution(), s->mu = friction(), s->beta = tangential_restitution();
    } else {
        rough_disk_wide(&s->a);
        rough_disk_wide(&s->b);
        s->n[0] = extreme(), s->n[1] = extreme();
        s->e = next() % 4 == 0 ? extreme() : restitution();
        s->mu = next() % 4 == 0 ? extreme() : friction();
        s->beta = next() % 4 == 0 ? extreme() : tangential_restitution();
    }
    s->normal_given = (double)(next() % 2);
}

static void make_accel(hv_model_scene *s)
{
    int i;
    switch (next() % 4) {
    case 0: /* anywhere in the range */
        for (i = 0; i < 2; i++) {
            s->pa[i] = extreme(), s->va[i] = extreme(), s->aa[i] = extreme();
            s->pb[i] = extreme(), s->vb[i] = extreme(), s->ab[i] = extreme();
        }
        s->radius_sum = absolute_sometimes(extreme());
        s->horizon = next() % 2 ? infinity() : absolute_sometimes(extreme());
        return;
    case 1: /* balls decelerating on cloth: acceleration against the velocity */
        for (i = 0; i < 2; i++) {
            s->pa[i] = uniform(-5, 5), s->pb[i] = s->pa[i] + uniform(-4, 4);
            s->va[i] = uniform(-4, 4), s->vb[i] = uniform(-4, 4);
            s->aa[i] = -s->va[i] * 0.25, s->ab[i] = -s->vb[i] * 0.25;
        }
        break;
    default: /* unit scale, any accelerations, sometimes equal */
        for (i = 0; i < 2; i++) {
            s->pa[i] = uniform(-5, 5), s->pb[i] = s->pa[i] + uniform(-4, 4);
            s->va[i] = uniform(-4, 4), s->vb[i] = uniform(-4, 4);
            s->aa[i] = uniform(-2, 2), s->ab[i] = next() % 8 == 0 ? s->aa[i] : uniform(-2, 2);
        }
        break;
    }
    s->radius_sum = uniform(0, 3);
    s->horizon = next() % 2 ? infinity() : uniform(0, 8);
}

#ifndef C2D_NO_DOUBLE
static void disk_to_double(const hv_disk *h, c2d_disk *d)
{
    d->pos.x = h->pos[0], d->pos.y = h->pos[1], d->vel.x = h->vel[0], d->vel.y = h->vel[1];
    d->spin = h->spin, d->mass = h->mass, d->radius = h->radius, d->inertia = h->inertia;
}

static void run_models_double(const hv_model_scene *s)
{
    c2d_disk a, b;
    c2d_surface f;
    c2d_vec2 n, aa, ab;
    c2d_body pa, pb;
    double t = -1;
    disk_to_double(&s->a, &a), disk_to_double(&s->b, &b);
    f.restitution = s->e, f.friction = s->mu, f.tangential_restitution = s->beta;
    n.x = s->n[0], n.y = s->n[1];
    mix_model_status(C2D_HV_ROUGH_DOUBLE,
                     s->normal_given != 0 ? c2d_collide_rough_normal(&a, &b, n, f) : c2d_collide_rough(&a, &b, f));
    mix_model(C2D_HV_ROUGH_DOUBLE, &a.vel, sizeof a.vel), mix_model(C2D_HV_ROUGH_DOUBLE, &a.spin, sizeof a.spin);
    mix_model(C2D_HV_ROUGH_DOUBLE, &b.vel, sizeof b.vel), mix_model(C2D_HV_ROUGH_DOUBLE, &b.spin, sizeof b.spin);
    pa.pos.x = s->pa[0], pa.pos.y = s->pa[1], pa.vel.x = s->va[0], pa.vel.y = s->va[1], pa.mass = 1;
    pb.pos.x = s->pb[0], pb.pos.y = s->pb[1], pb.vel.x = s->vb[0], pb.vel.y = s->vb[1], pb.mass = 1;
    aa.x = s->aa[0], aa.y = s->aa[1], ab.x = s->ab[0], ab.y = s->ab[1];
    mix_model_status(C2D_HV_ACCEL_DOUBLE, c2d_time_of_impact_accel(&pa, aa, &pb, ab, s->radius_sum, s->horizon, &t));
    mix_model(C2D_HV_ACCEL_DOUBLE, &t, sizeof t);
}
#endif

#ifndef C2D_NO_FLOAT
static void disk_to_float(const hv_disk *h, c2d_diskf *d)
{
    d->pos.x = to_float(h->pos[0]), d->pos.y = to_float(h->pos[1]);
    d->vel.x = to_float(h->vel[0]), d->vel.y = to_float(h->vel[1]);
    d->spin = to_float(h->spin), d->mass = to_float(h->mass);
    d->radius = to_float(h->radius), d->inertia = to_float(h->inertia);
}

static void run_models_float(const hv_model_scene *s)
{
    c2d_diskf a, b;
    c2d_surfacef f;
    c2d_vec2f n, aa, ab;
    c2d_bodyf pa, pb;
    float t = -1;
    disk_to_float(&s->a, &a), disk_to_float(&s->b, &b);
    f.restitution = to_float(s->e), f.friction = to_float(s->mu), f.tangential_restitution = to_float(s->beta);
    n.x = to_float(s->n[0]), n.y = to_float(s->n[1]);
    mix_model_status(C2D_HV_ROUGH_FLOAT,
                     s->normal_given != 0 ? c2d_collide_rough_normalf(&a, &b, n, f) : c2d_collide_roughf(&a, &b, f));
    mix_model(C2D_HV_ROUGH_FLOAT, &a.vel, sizeof a.vel), mix_model(C2D_HV_ROUGH_FLOAT, &a.spin, sizeof a.spin);
    mix_model(C2D_HV_ROUGH_FLOAT, &b.vel, sizeof b.vel), mix_model(C2D_HV_ROUGH_FLOAT, &b.spin, sizeof b.spin);
    pa.pos.x = to_float(s->pa[0]), pa.pos.y = to_float(s->pa[1]);
    pa.vel.x = to_float(s->va[0]), pa.vel.y = to_float(s->va[1]), pa.mass = 1;
    pb.pos.x = to_float(s->pb[0]), pb.pos.y = to_float(s->pb[1]);
    pb.vel.x = to_float(s->vb[0]), pb.vel.y = to_float(s->vb[1]), pb.mass = 1;
    aa.x = to_float(s->aa[0]), aa.y = to_float(s->aa[1]), ab.x = to_float(s->ab[0]), ab.y = to_float(s->ab[1]);
    mix_model_status(C2D_HV_ACCEL_FLOAT,
                     c2d_time_of_impact_accelf(&pa, aa, &pb, ab, to_float(s->radius_sum), to_float(s->horizon), &t));
    mix_model(C2D_HV_ACCEL_FLOAT, &t, sizeof t);
}
#endif

void c2d_hv_run_models(unsigned long count, c2d_hv_models_hash *h, void (*bytes)(const void *p, size_t n))
{
    static hv_model_scene s; /* static: off a microcontroller's small stack */
    unsigned long done;
    int m;
    rng.s = 0x6A09E667F3BCC909ull; /* not the variants' seed: its own stream */
    models_out = h, sink = bytes;
    h->inputs = 0xCBF29CE484222325ull;
    for (m = 0; m < C2D_HV_MODELS; m++) h->model[m] = 0xCBF29CE484222325ull, h->present[m] = 0;
#ifndef C2D_NO_DOUBLE
    h->present[C2D_HV_ROUGH_DOUBLE] = h->present[C2D_HV_ACCEL_DOUBLE] = 1;
#endif
#ifndef C2D_NO_FLOAT
    h->present[C2D_HV_ROUGH_FLOAT] = h->present[C2D_HV_ACCEL_FLOAT] = 1;
#endif
    for (done = 0; done < count; done++) {
        make_rough(&s);
        make_accel(&s);
        fnv(&h->inputs, &s, sizeof s);
#ifndef C2D_NO_DOUBLE
        run_models_double(&s);
#endif
#ifndef C2D_NO_FLOAT
        run_models_float(&s);
#endif
    }
}

uint64_t c2d_hv_models_combined(const c2d_hv_models_hash *h)
{
    uint64_t all = 0xCBF29CE484222325ull;
    int m;
    for (m = 0; m < C2D_HV_MODELS; m++)
        if (h->present[m]) fnv(&all, &h->model[m], sizeof h->model[m]);
    return all;
}

/* ------------------------------------------------------------ the world
 *
 * Scenes of the event-driven world, each driven through uneven slices of
 * c2d_world_advance (zero-length and tiny ones among them) from its own
 * splitmix64 stream; the event callback hashes every event as it comes
 * (kind as one byte, time, a and b as 8 little-endian bytes, the impulse),
 * every call's status is hashed, and at the end every disk's state and
 * acceleration and the statistics.  The memory is static: a world of 100
 * disks needs about 17 KiB (less with 4-byte pointers), so the host and the
 * firmware builds with double and room for it (m7, rv32) run it. */
#if !defined(C2D_NO_DOUBLE) && !defined(C2D_NO_WORLD)
#include "collide2d_world.h"

enum { HV_WORLD_CAPACITY = 100, HV_WORLD_STATICS = 4 };

typedef struct hv_world_run {
    c2d_world *world;
    int control; /* the callback changes the motion at timers */
} hv_world_run;

static c2d_hv_world_hash *world_out;
static uint64_t world_memory[2816]; /* 22.5 KiB, 8-aligned: c2d_world_bytes is checked against it */

static void mix_world(const void *p, size_t n)
{
    if (sink != NULL) sink(p, n);
    fnv(&world_out->hash, p, n);
    fnv(&world_out->portable, p, n);
}

static void mix_world_status(c2d_status s)
{
    unsigned char c = (unsigned char)s;
    mix_world(&c, 1);
}

static void little_endian(uint64_t k, unsigned char b[8])
{
    int i;
    for (i = 0; i < 8; i++) b[i] = (unsigned char)(k >> (8 * i));
}

static void mix_world_count(uint64_t k)
{
    unsigned char b[8];
    little_endian(k, b);
    mix_world(b, sizeof b);
}

/* c2d_world_bytes depends on the pointer size (the world's header holds
 * pointers): in "world", not in "world-portable". */
static void mix_world_bytes(size_t bytes)
{
    unsigned char b[8];
    little_endian(bytes, b);
    if (sink != NULL) sink(b, sizeof b);
    fnv(&world_out->hash, b, sizeof b);
}

/* At a timer (control scenes): a new acceleration from the disk's index
 * and the time's parity, a kick for every third disk, a new timer for the
 * even ones; every status hashed. */
static void world_control(c2d_world *w, const c2d_world_event *e)
{
    c2d_vec2 acc, kick;
    const double phase = (double)(e->a % 5) - 2;
    acc.x = 0.15 * phase, acc.y = e->a % 2 ? -0.3 : 0.2;
    mix_world_status(c2d_world_set_acceleration(w, e->a, acc));
    if (e->a % 3 == 0) {
        kick.x = -0.5 * phase, kick.y = 0.75;
        mix_world_status(c2d_world_set_velocity(w, e->a, kick));
    }
    if (e->a % 2 == 0) mix_world_status(c2d_world_set_timer(w, e->a, e->time + 0.8125 + 0.0625 * (double)(e->a % 7)));
    /* Refused inside the callback, and so hashed as refused. */
    mix_world_status(c2d_world_advance(w, e->time + 1));
    mix_world_status(c2d_world_remove(w, e->a));
}

static void world_event(void *user, const c2d_world_event *e)
{
    hv_world_run *run = (hv_world_run *)user;
    const unsigned char kind = (unsigned char)e->kind;
    mix_world(&kind, 1);
    mix_world(&e->time, sizeof e->time);
    mix_world_count(e->a);
    mix_world_count(e->b);
    mix_world(&e->impulse, sizeof e->impulse);
    world_out->events++;
    if (run->control && e->kind == C2D_WORLD_TIMER) world_control(run->world, e);
}

static c2d_world *world_make(c2d_world_desc *d, hv_world_run *run)
{
    c2d_world *w = NULL;
    const size_t bytes = c2d_world_bytes(d);
    d->on_event = world_event, d->user = run;
    mix_world_bytes(bytes);
    if (bytes == 0 || bytes > sizeof world_memory) return NULL;
    mix_world_status(c2d_world_init(&w, world_memory, sizeof world_memory, d));
    run->world = w;
    return w;
}

/* side x rows disks on a lattice over [0, width) x [0, height), radii in
 * [rmin, rmax), masses in [0.5, 2), speeds up to vmax per component. */
static void world_fill(c2d_world *w, unsigned side, unsigned rows, double width, double height, double rmin,
                       double rmax, double vmax)
{
    unsigned i;
    for (i = 0; i < side * rows; i++) {
        c2d_body b;
        double r;
        b.pos.x = ((double)(i % side) + 0.5) * width / (double)side;
        b.pos.y = ((double)(i / side) + 0.5) * height / (double)rows;
        b.vel.x = uniform(-vmax, vmax);
        b.vel.y = uniform(-vmax, vmax);
        b.mass = uniform(0.5, 2);
        r = uniform(rmin, rmax);
        mix_world_status(c2d_world_add(w, &b, r, NULL));
    }
}

/* Uneven slices to `end`: mostly 0.05 to 0.6, one in eight tiny, one in
 * sixteen of length zero (the same time again); every `kick_every`-th
 * slice (0: never) kicks a disk and, once, removes one. */
static void world_slices(c2d_world *w, double end, unsigned kick_every)
{
    double t = 0;
    unsigned k = 0;
    while (t < end) {
        const uint64_t r = next();
        double step = uniform(0.05, 0.6);
        if (r % 8 == 0) step = 1e-9 * step;
        if (r % 16 == 1) step = 0;
        t = t + step > end ? end : t + step;
        mix_world_status(c2d_world_advance(w, t));
        if (kick_every != 0 && ++k % kick_every == 0) {
            const size_t n = c2d_world_count(w);
            c2d_vec2 v;
            v.x = uniform(-2, 2);
            v.y = uniform(-2, 2);
            mix_world_status(c2d_world_set_velocity(w, (size_t)(r >> 32) % n, v));
            if (k == 3 * kick_every) mix_world_status(c2d_world_remove(w, (size_t)(r >> 40) % n));
        }
    }
}

static void world_finish(const c2d_world *w)
{
    const size_t n = c2d_world_count(w);
    c2d_world_stats s;
    size_t i;
    mix_world_count(n);
    for (i = 0; i < n; i++) {
        c2d_body b;
        c2d_vec2 acc;
        const c2d_status got = c2d_world_get(w, i, &b);
        mix_world_status(got);
        if (got == C2D_OK) mix_world(&b.pos, sizeof b.pos), mix_world(&b.vel, sizeof b.vel), mix_world(&b.mass, sizeof b.mass);
        if (c2d_world_get_acceleration(w, i, &acc) == C2D_OK) mix_world(&acc, sizeof acc);
    }
    c2d_world_get_stats(w, &s);
    mix_world_count(s.collisions);
    mix_world_count(s.wall_collisions);
    mix_world_count(s.events);
    mix_world(&s.time, sizeof s.time);
    mix_world(&s.virial, sizeof s.virial);
}

static c2d_world_desc world_desc(size_t capacity, double width, double height, c2d_boundary boundary, double e,
                                 double ew)
{
    c2d_world_desc d;
    unsigned char *p = (unsigned char *)&d;
    size_t i;
    for (i = 0; i < sizeof d; i++) p[i] = 0; /* every field's default, padding included */
    d.capacity = capacity, d.width = width, d.height = height, d.boundary = boundary;
    d.restitution = e, d.wall_restitution = ew;
    return d;
}

/* Walls with e < 1: a dense gas cooling into clusters, resolved by the
 * collapse rule; by default, then with its time and speed rules. */
static void world_collapse(int rules)
{
    hv_world_run run = {NULL, 0};
    c2d_world_desc d = world_desc(64, 9, 9, C2D_WALLS, 0.3, 0.5);
    c2d_world *w;
    d.collapse_time = rules ? 1e-3 : 0;
    d.collapse_speed = rules ? 1e-2 : 0;
    if ((w = world_make(&d, &run)) == NULL) return;
    world_fill(w, 8, 8, 9, 9, 0.35, 0.55, 2);
    world_slices(w, 25, 0);
    world_finish(w);
}

/* A periodic elastic gas of mixed radii and masses, kicked now and then,
 * one disk removed. */
static void world_periodic(void)
{
    hv_world_run run = {NULL, 0};
    c2d_world_desc d = world_desc(HV_WORLD_CAPACITY, 14, 12, C2D_PERIODIC, 1, 0);
    c2d_world *w;
    if ((w = world_make(&d, &run)) == NULL) return;
    world_fill(w, 10, 10, 14, 12, 0.25, 0.5, 1.5);
    world_slices(w, 30, 9);
    world_finish(w);
}

/* Accelerations and timers (the callback changes them), walls, two
 * segments and two circles to the right of the disks, which the
 * accelerations drive into them. */
static void world_statics(void)
{
    hv_world_run run = {NULL, 1};
    c2d_world_desc d = world_desc(36, 16, 12, C2D_WALLS, 0.9, 0.8);
    c2d_world *w;
    c2d_vec2 p, q;
    unsigned i;
    d.statics = HV_WORLD_STATICS;
    if ((w = world_make(&d, &run)) == NULL) return;
    world_fill(w, 6, 6, 10, 12, 0.25, 0.4, 1);
    p.x = 11, p.y = 2, q.x = 15, q.y = 5;
    mix_world_status(c2d_world_add_segment(w, p, q, 0.7, NULL));
    p.x = 12, p.y = 10.5, q.x = 15.5, q.y = 8;
    mix_world_status(c2d_world_add_segment(w, p, q, 1, NULL));
    p.x = 13.5, p.y = 6.5;
    mix_world_status(c2d_world_add_circle(w, p, 0.6, 0.5, NULL));
    p.x = 11.5, p.y = 7.25;
    mix_world_status(c2d_world_add_circle(w, p, 0.3, 1, NULL));
    for (i = 0; i < 36; i++) {
        c2d_vec2 acc;
        acc.x = uniform(0, 0.6);
        acc.y = uniform(-0.4, 0.2);
        mix_world_status(c2d_world_set_acceleration(w, i, acc));
        mix_world_status(c2d_world_set_timer(w, i, 0.375 * (double)i + 0.25));
    }
    world_slices(w, 30, 13);
    world_finish(w);
}

void c2d_hv_run_world(c2d_hv_world_hash *h, void (*bytes)(const void *p, size_t n))
{
    rng.s = 0xBB67AE8584CAA73Bull; /* the world's own stream */
    world_out = h, sink = bytes;
    h->hash = h->portable = 0xCBF29CE484222325ull, h->events = 0, h->present = 1;
    world_collapse(0);
    world_collapse(1);
    world_periodic();
    world_statics();
}
#else
void c2d_hv_run_world(c2d_hv_world_hash *h, void (*bytes)(const void *p, size_t n))
{
    (void)bytes;
    h->hash = h->portable = 0xCBF29CE484222325ull, h->events = 0, h->present = 0;
}
#endif
