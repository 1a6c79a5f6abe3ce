/* SPDX-License-Identifier: MIT */
/* decode.c - the fuzz input's bytes decoded into arguments (the format is
 * described in fuzz_collide2d.c).  Missing bytes read as 0. */
#include "fuzz.h"

#include <float.h>
#include <math.h>

uint8_t c2d_fuzz_read_byte(c2d_fuzz_reader *r)
{
    if (r->n == 0) return 0;
    r->n--;
    return *r->p++;
}

static void read_bytes(c2d_fuzz_reader *r, void *out, size_t k)
{
    uint8_t *o = out;
    size_t i;
    for (i = 0; i < k; i++) o[i] = c2d_fuzz_read_byte(r);
}

static int16_t read_i16(c2d_fuzz_reader *r)
{
    uint16_t u = (uint16_t)(c2d_fuzz_read_byte(r) | (c2d_fuzz_read_byte(r) << 8));
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

double c2d_fuzz_read_double(c2d_fuzz_reader *r)
{
    double d;
    float f;
    uint8_t tag;
    if (r->mode == C2D_FUZZ_RAW) {
        read_bytes(r, &d, sizeof d);
        return d;
    }
    if (r->mode == C2D_FUZZ_TAME) return read_i16(r) / 256.0;
    tag = c2d_fuzz_read_byte(r);
    switch (tag % 8) {
    case 3: return read_i16(r) / 256.0;
    case 4: {
        int16_t m = read_i16(r);
        return ldexp(m, (int8_t)c2d_fuzz_read_byte(r) * 9); /* spans the whole range */
    }
    case 5: return special_double(c2d_fuzz_read_byte(r));
    case 6:
        read_bytes(r, &f, sizeof f);
        return f;
    case 7: return (int8_t)c2d_fuzz_read_byte(r);
    default:
        read_bytes(r, &d, sizeof d);
        return d;
    }
}

double c2d_fuzz_read_mass(c2d_fuzz_reader *r)
{
    if (r->mode == C2D_FUZZ_TAME) {
        uint16_t u = (uint16_t)read_i16(r);
        return u == 0xFFFF ? INFINITY : (1.0 + u) / 256.0;
    }
    return c2d_fuzz_read_double(r);
}

double c2d_fuzz_read_restitution(c2d_fuzz_reader *r)
{
    uint8_t tag;
    if (r->mode == C2D_FUZZ_TAME) return c2d_fuzz_read_byte(r) / 255.0;
    if (r->mode == C2D_FUZZ_RAW) return c2d_fuzz_read_double(r);
    tag = c2d_fuzz_read_byte(r);
    switch (tag % 4) {
    case 1: return c2d_fuzz_read_byte(r) / 255.0;
    case 2: return 1.0;
    case 3: return 0.0;
    default: return c2d_fuzz_read_double(r);
    }
}

/* Floats: the same decoding, rounded (raw mode: the float's own bits). */
float c2d_fuzz_read_float(c2d_fuzz_reader *r)
{
    float f;
    if (r->mode == C2D_FUZZ_RAW) {
        read_bytes(r, &f, sizeof f);
        return f;
    }
    return (float)c2d_fuzz_read_double(r);
}

float c2d_fuzz_read_massf(c2d_fuzz_reader *r)
{
    return r->mode == C2D_FUZZ_RAW ? c2d_fuzz_read_float(r) : (float)c2d_fuzz_read_mass(r);
}

float c2d_fuzz_read_restitutionf(c2d_fuzz_reader *r)
{
    return r->mode == C2D_FUZZ_RAW ? c2d_fuzz_read_float(r) : (float)c2d_fuzz_read_restitution(r);
}

c2d_fixed c2d_fuzz_read_fixed(c2d_fuzz_reader *r)
{
    static const c2d_fixed special[] = {0, 1, -1, C2D_FIXED_ONE, -C2D_FIXED_ONE, INT32_MAX, INT32_MIN,
                                        INT32_MAX / 2, INT32_MIN / 2};
    uint8_t tag;
    int32_t v;
    if (r->mode == C2D_FUZZ_TAME) return (c2d_fixed)read_i16(r) * 16;
    if (r->mode == C2D_FUZZ_MIXED) {
        tag = c2d_fuzz_read_byte(r);
        if (tag % 4 == 1) return (c2d_fixed)((uint32_t)(int32_t)read_i16(r) << (tag / 4 % 16));
        if (tag % 4 == 2) return special[c2d_fuzz_read_byte(r) % (sizeof special / sizeof special[0])];
    }
    read_bytes(r, &v, sizeof v);
    return v;
}

c2d_fixed c2d_fuzz_read_massx(c2d_fuzz_reader *r)
{
    if (r->mode == C2D_FUZZ_TAME) {
        uint16_t u = (uint16_t)read_i16(r);
        return u == 0xFFFF ? C2D_FIXED_INFINITE_MASS : 1 + (c2d_fixed)u * 16;
    }
    return c2d_fuzz_read_fixed(r);
}

c2d_fixed c2d_fuzz_read_restitutionx(c2d_fuzz_reader *r)
{
    uint8_t tag;
    if (r->mode == C2D_FUZZ_RAW) return c2d_fuzz_read_fixed(r);
    tag = c2d_fuzz_read_byte(r);
    if (r->mode == C2D_FUZZ_TAME || tag % 4 == 1) return (c2d_fixed)((int32_t)c2d_fuzz_read_byte(r) * 65536 / 255);
    if (tag % 4 == 2) return C2D_FIXED_ONE;
    if (tag % 4 == 3) return 0;
    return c2d_fuzz_read_fixed(r);
}

/* The rough contact's surface.  Friction: tame a byte (0: none, 255:
 * INFINITY, else k/64), mixed a tag choosing raw bits, that byte, 0 or
 * INFINITY (the identities and the never-sliding contact come often).
 * beta: tame a byte mapped onto [-1, 1] with both ends exact, mixed raw
 * bits, that byte, 1 or -1. */
double c2d_fuzz_read_friction(c2d_fuzz_reader *r)
{
    uint8_t k;
    if (r->mode == C2D_FUZZ_RAW) return c2d_fuzz_read_double(r);
    if (r->mode == C2D_FUZZ_MIXED) {
        const uint8_t tag = c2d_fuzz_read_byte(r);
        if (tag % 4 == 0) return c2d_fuzz_read_double(r);
        if (tag % 4 == 2) return 0.0;
        if (tag % 4 == 3) return INFINITY;
    }
    k = c2d_fuzz_read_byte(r);
    return k == 255 ? INFINITY : k / 64.0;
}

double c2d_fuzz_read_beta(c2d_fuzz_reader *r)
{
    if (r->mode == C2D_FUZZ_RAW) return c2d_fuzz_read_double(r);
    if (r->mode == C2D_FUZZ_MIXED) {
        const uint8_t tag = c2d_fuzz_read_byte(r);
        if (tag % 4 == 0) return c2d_fuzz_read_double(r);
        if (tag % 4 == 2) return 1.0;
        if (tag % 4 == 3) return -1.0;
    }
    return c2d_fuzz_read_byte(r) * 2 / 255.0 - 1.0;
}

/* The time of impact's horizon: INFINITY often (a tag byte's low bit in tame
 * mode, a quarter of the tags in mixed mode), else a length (tame: >= 0). */
double c2d_fuzz_read_horizon(c2d_fuzz_reader *r)
{
    uint8_t tag;
    if (r->mode == C2D_FUZZ_RAW) return c2d_fuzz_read_double(r);
    tag = c2d_fuzz_read_byte(r);
    if (r->mode == C2D_FUZZ_TAME) return tag % 2 == 0 ? INFINITY : fabs(c2d_fuzz_read_double(r));
    return tag % 4 == 0 ? INFINITY : c2d_fuzz_read_double(r);
}

float c2d_fuzz_read_frictionf(c2d_fuzz_reader *r)
{
    return r->mode == C2D_FUZZ_RAW ? c2d_fuzz_read_float(r) : (float)c2d_fuzz_read_friction(r);
}

float c2d_fuzz_read_betaf(c2d_fuzz_reader *r)
{
    return r->mode == C2D_FUZZ_RAW ? c2d_fuzz_read_float(r) : (float)c2d_fuzz_read_beta(r);
}

float c2d_fuzz_read_horizonf(c2d_fuzz_reader *r)
{
    return r->mode == C2D_FUZZ_RAW ? c2d_fuzz_read_float(r) : (float)c2d_fuzz_read_horizon(r);
}
