/* SPDX-License-Identifier: MIT */
/* rng.h - the one random number generator of the tests, the benchmark and
 * the determinism hash: splitmix64 (Steele, Lea, Flood 2014), tiny, fast and
 * good enough to drive test cases.  Header-only and dependency-free (no GMP,
 * no C library), so freestanding programs can use it too.
 *
 * Every stream is fixed by its seed, and the doubles it gives are made with
 * exact operations only (a shift, a conversion of a 53-bit integer, a
 * multiplication by 2^-53), so a case set is the same bits under any
 * compiler and optimisation level. */
#ifndef C2D_RNG_H
#define C2D_RNG_H

#include <stdint.h>

typedef struct c2d_rng { uint64_t s; } c2d_rng;

static inline uint64_t c2d_rng_next(c2d_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1). */
static inline double c2d_rng_unit(c2d_rng *r) { return (double)(c2d_rng_next(r) >> 11) * 0x1p-53; }

/* Uniform in [lo, hi) (one rounding in the multiply-add). */
static inline double c2d_rng_range(c2d_rng *r, double lo, double hi) { return lo + (hi - lo) * c2d_rng_unit(r); }

#endif
