/* Shared by the tests and the benchmark: a deterministic RNG and generators
 * of collision cases, plain (unit-scale scenes) and extreme (the whole range). */
#ifndef C2D_SUPPORT_H
#define C2D_SUPPORT_H

#include <stdint.h>
#include "referee.h"

typedef struct rng { uint64_t s; } rng;

uint64_t rng_next(rng *r);
double rng_unit(rng *r);                 /* uniform in [0, 1) */
double rng_range(rng *r, double lo, double hi);

/* Unit-scale scene: positions within 10, centres ~1 apart, speeds <= 10,
 * masses 0.1..10, restitution in [0, 1] (0 and 1 included often). */
void gen_plain(rng *r, ref_case *c);

/* Anywhere in the format: each magnitude 2^k with k uniform over the whole
 * exponent range (subnormals included), zeros, mass ratios up to the full
 * range and INFINITY masses.  `prec`/`emin`/`emax` select double (53, -1022,
 * 1023) or float (24, -126, 127); values are exactly representable there. */
void gen_extreme(rng *r, ref_case *c, int prec, int emin, int emax);

/* A random value 2^k * (1 + mantissa) with k uniform in [kmin, kmax] and a
 * random sign, rounded to `prec` bits. */
double gen_magnitude(rng *r, int kmin, int kmax, int prec);

/* Copy a case into library bodies. */
void case_to_bodies(const ref_case *c, c2d_body *a, c2d_body *b);
void case_to_bodiesf(const ref_case *c, c2d_bodyf *a, c2d_bodyf *b);

#endif
