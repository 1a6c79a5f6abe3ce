/* hash_vectors.c - hash the bits of every output and status of the library
 * over a fixed, generated set of cases, for tests/build/determinism.sh.
 *
 * Standalone on purpose (no GMP, no cmocka; the shared helper of
 * tests/harness/ for the batch arrays): it is compiled once, with gcc -O2,
 * and linked against the library built by gcc and clang at several
 * optimisation levels.
 * The cases come from a fixed splitmix64 stream (referee/rng.h, header-only):
 * unit-scale scenes, grazing impacts, whole-range extremes (every binade,
 * subnormals, zeros, NaN, Inf, mass ratios up to the full range, immovable
 * bodies), and Q16.16 scenes; each case runs through every entry point
 * (double, float, Q16.16, time of impact, and the batch kernels over the
 * whole set).
 * Usage: hash_vectors [COUNT [DUMP]]  prints "hash_vectors: COUNT cases,
 * hash H"; DUMP receives the raw bytes hashed, to locate differences (cmp -l). */
#include "collide2d.h"
#include "harness.h"
#include "rng.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DEFAULT_COUNT 100000

typedef struct scene {
    c2d_body a, b;
    c2d_vec2 n;
    double e, radius;
} scene;

static c2d_rng rng = {0x2545F4914F6CDD1Dull};

static uint64_t next(void) { return c2d_rng_next(&rng); }

static double from_bits(uint64_t u)
{
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

/* Uniform in [lo, hi): only + - * on exactly produced values, so the inputs
 * themselves are the same bits whatever the compiler does. */
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
        uint64_t exp = (next() % 2047);         /* 0 (subnormal) .. 2046 */
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

static void plain(scene *s)
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
static void grazing(scene *s)
{
    double k = uniform(-1e-9, 1e-9);
    plain(s);
    s->b.vel.x = s->a.vel.x - s->n.y * 3 + s->n.x * k;
    s->b.vel.y = s->a.vel.y + s->n.x * 3 + s->n.y * k;
}

static void wide(scene *s)
{
    s->a.pos.x = extreme(), s->a.pos.y = extreme(), s->b.pos.x = extreme(), s->b.pos.y = extreme();
    s->a.vel.x = extreme(), s->a.vel.y = extreme(), s->b.vel.x = extreme(), s->b.vel.y = extreme();
    s->a.mass = extreme(), s->b.mass = extreme();
    if (next() % 2) s->a.mass = s->a.mass < 0 ? -s->a.mass : s->a.mass;
    if (next() % 2) s->b.mass = s->b.mass < 0 ? -s->b.mass : s->b.mass;
    s->n.x = extreme(), s->n.y = extreme();
    s->radius = extreme();
    if (next() % 2) s->radius = s->radius < 0 ? -s->radius : s->radius;
}

static void make_scene(scene *s)
{
    uint64_t k = next() % 8;
    if (k < 4) plain(s);
    else if (k < 5) grazing(s);
    else wide(s);
    s->e = next() % 64 == 0 ? extreme() : restitution();
}

/* -------------------------------------------------------------- hash */

static uint64_t hash = 0xCBF29CE484222325ull; /* FNV-1a 64 */
static FILE *dump;                              /* optional: every output record */

static void mix(const void *p, size_t n)
{
    const unsigned char *b = p;
    size_t i;
    if (dump != NULL && fwrite(p, 1, n, dump) != n) dump = NULL;
    for (i = 0; i < n; i++) {
        hash ^= b[i];
        hash *= 0x100000001B3ull;
    }
}

static void mix_status(c2d_status s)
{
    unsigned char c = (unsigned char)s;
    mix(&c, 1);
}

/* ------------------------------------------------------------ runners */

static void run_double(const scene *s)
{
    c2d_body a = s->a, b = s->b;
    double t = -1;
    mix_status(c2d_collide(&a, &b, s->e));
    mix(&a.vel, sizeof a.vel), mix(&b.vel, sizeof b.vel);
    a = s->a, b = s->b;
    mix_status(c2d_collide_normal(&a, &b, s->n, s->e));
    mix(&a.vel, sizeof a.vel), mix(&b.vel, sizeof b.vel);
    mix_status(c2d_time_of_impact(&s->a, &s->b, s->radius, &t));
    mix(&t, sizeof t);
}

static c2d_bodyf to_float(const c2d_body *b)
{
    c2d_bodyf f;
    f.pos.x = (float)b->pos.x, f.pos.y = (float)b->pos.y;
    f.vel.x = (float)b->vel.x, f.vel.y = (float)b->vel.y;
    f.mass = (float)b->mass;
    return f;
}

static void run_float(const scene *s)
{
    c2d_bodyf a0 = to_float(&s->a), b0 = to_float(&s->b), a = a0, b = b0;
    c2d_vec2f n;
    float e = (float)s->e, t = -1;
    n.x = (float)s->n.x, n.y = (float)s->n.y;
    mix_status(c2d_collidef(&a, &b, e));
    mix(&a.vel, sizeof a.vel), mix(&b.vel, sizeof b.vel);
    a = a0, b = b0;
    mix_status(c2d_collide_normalf(&a, &b, n, e));
    mix(&a.vel, sizeof a.vel), mix(&b.vel, sizeof b.vel);
    mix_status(c2d_time_of_impactf(&a0, &b0, (float)s->radius, &t));
    mix(&t, sizeof t);
}

/* Q16.16: unit-scale scenes converted, or raw random int32 fields. */
static c2d_fixed to_fixed(double v)
{
    double r = v * 65536.0;
    if (!(r > -2147483648.0)) return INT32_MIN;
    if (!(r < 2147483647.0)) return INT32_MAX;
    return (c2d_fixed)r;
}

static void run_fixed(const scene *s)
{
    c2d_bodyx a0, b0, a, b;
    c2d_vec2x n;
    c2d_fixed e, t = -1, rad;
    int raw = next() % 4 == 0;
    const c2d_body *src[2] = {&s->a, &s->b};
    c2d_bodyx *dst[2] = {&a0, &b0};
    int j;
    for (j = 0; j < 2; j++) {
        dst[j]->pos.x = raw ? (c2d_fixed)next() : to_fixed(src[j]->pos.x);
        dst[j]->pos.y = raw ? (c2d_fixed)next() : to_fixed(src[j]->pos.y);
        dst[j]->vel.x = raw ? (c2d_fixed)next() : to_fixed(src[j]->vel.x);
        dst[j]->vel.y = raw ? (c2d_fixed)next() : to_fixed(src[j]->vel.y);
        dst[j]->mass = raw ? (c2d_fixed)next() : to_fixed(src[j]->mass);
    }
    n.x = raw ? (c2d_fixed)next() : to_fixed(s->n.x);
    n.y = raw ? (c2d_fixed)next() : to_fixed(s->n.y);
    e = raw && next() % 2 ? (c2d_fixed)next() : to_fixed(s->e);
    rad = raw ? (c2d_fixed)next() : to_fixed(s->radius);
    a = a0, b = b0;
    mix_status(c2d_collidex(&a, &b, e));
    mix(&a.vel, sizeof a.vel), mix(&b.vel, sizeof b.vel);
    a = a0, b = b0;
    mix_status(c2d_collide_normalx(&a, &b, n, e));
    mix(&a.vel, sizeof a.vel), mix(&b.vel, sizeof b.vel);
    mix_status(c2d_time_of_impactx(&a0, &b0, rad, &t));
    mix(&t, sizeof t);
}

/* The batch entry points over the whole set, one restitution per call:
 * statuses, then the four velocity arrays in c2d_pairs' order. */
static void run_batches(const scene *set, size_t count)
{
    double *d = malloc(C2D_SOA_FIELDS * count * sizeof *d);
    float *f = malloc(C2D_SOA_FIELDS * count * sizeof *f);
    c2d_status *st = malloc(count * sizeof *st);
    c2d_soa s;
    c2d_soaf sf;
    c2d_pairs p;
    c2d_pairsf pf;
    size_t i, k;
    if (d == NULL || f == NULL || st == NULL) {
        fprintf(stderr, "hash_vectors: out of memory\n");
        exit(2);
    }
    s = c2d_soa_in(d, count, st);
    sf = c2d_soa_inf(f, count, st);
    p = c2d_soa_pairs(&s);
    pf = c2d_soa_pairsf(&sf);
    for (i = 0; i < count; i++) {
        const c2d_bodyf a = to_float(&set[i].a), b = to_float(&set[i].b);
        c2d_soa_put(&s, i, &set[i].a, &set[i].b);
        c2d_soa_putf(&sf, i, &a, &b);
    }
    k = c2d_collide_batch(&p, count, 0.9, st);
    mix(&k, sizeof k), mix(st, count * sizeof *st);
    for (i = C2D_SOA_VEL_AX; i <= C2D_SOA_VEL_BY; i++) mix(s.field[i], count * sizeof *d);
    k = c2d_collide_batchf(&pf, count, 0.9f, st);
    mix(&k, sizeof k), mix(st, count * sizeof *st);
    for (i = C2D_SOA_VEL_AX; i <= C2D_SOA_VEL_BY; i++) mix(sf.field[i], count * sizeof *f);
    free(d);
    free(f);
    free(st);
}

int main(int argc, char **argv)
{
    size_t count = argc > 1 ? (size_t)strtoul(argv[1], NULL, 10) : DEFAULT_COUNT, i;
    scene *set = malloc((count ? count : 1) * sizeof *set);
    if (set == NULL) {
        fprintf(stderr, "hash_vectors: out of memory\n");
        return 2;
    }
    for (i = 0; i < count; i++) make_scene(&set[i]);
    mix(set, count * sizeof *set); /* the inputs too: a changed input set shows as such */
    printf("hash_vectors: inputs hash %016llx\n", (unsigned long long)hash);
    if (argc > 2 && (dump = fopen(argv[2], "wb")) == NULL) {
        perror(argv[2]);
        return 2;
    }
    for (i = 0; i < count; i++) {
        run_double(&set[i]);
        run_float(&set[i]);
        run_fixed(&set[i]);
    }
    run_batches(set, count);
    printf("hash_vectors: %zu cases, hash %016llx\n", count, (unsigned long long)hash);
    free(set);
    if (dump != NULL && fclose(dump) != 0) return 2;
    return 0;
}
