/* SPDX-License-Identifier: MIT */
/* harness.h - the one helper the test programs share: the pass/fail tally
 * and its closing line, exact printing of numbers, the structure-of-arrays
 * storage the batch entry points take, and the check that a batch call gives
 * what scalar calls give on the same pairs.
 *
 * Its users are the host tests (tests/unit, tests/vectors), the fuzz
 * harness, the benchmark, the determinism hash and the bare-metal MCU
 * harness, so it is freestanding: only the compiler's own headers and the
 * library's, no C library, no allocation.  Text goes out through c2d_put,
 * which each program supplies (put_stdio.c on a host, the semihosting
 * console on a microcontroller).
 *
 * harness.c holds what does not depend on the number type; the rest is a
 * template (soa_template.h) that soa_double.c and soa_float.c instantiate
 * and name, as lib/double.c and lib/float.c do for the library. */
#ifndef C2D_HARNESS_H
#define C2D_HARNESS_H

#include <stddef.h>
#include <stdint.h>
#include "collide2d.h"

#define C2D_ABS(x) ((x) < 0 ? -(x) : (x))

/* -------------------------------------------------------------- output */

/* Writes a string: supplied by the program (host: put_stdio.c). */
void c2d_put(const char *s);
void c2d_put_int(long v);
#ifndef C2D_NO_DOUBLE
void c2d_put_double(double x); /* C99 %a form (0x1.8p+1): the exact bits */
#endif
#ifndef C2D_NO_FLOAT
void c2d_put_float(float x);
#endif
#ifndef C2D_NO_FIXED
void c2d_put_fixed(c2d_fixed x); /* raw/65536 */
#endif

/* Byte-for-byte equality (memcmp without the C library). */
int c2d_same_bytes(const void *x, const void *y, size_t n);

/* ----------------------------------------------------------- pass/fail */

/* Every test program ends with one line "NAME: N passed, N failed" (the
 * MCU runner and the make rules read it). */
typedef struct c2d_tally { int passed, failed; } c2d_tally;

/* Counts one check; returns ok, so it can stand in a condition. */
int c2d_tally_add(c2d_tally *t, int ok);
/* The closing line; without "NAME: " when name is NULL. */
void c2d_put_tally(const char *name, const c2d_tally *t);
/* The exit status that goes with it: 0 when nothing failed. */
int c2d_tally_status(const c2d_tally *t);

/* -------------------------------------------------- structure of arrays */

/* The arrays of a batch call, in c2d_pairs' order. */
enum {
    C2D_SOA_POS_AX, C2D_SOA_POS_AY, C2D_SOA_POS_BX, C2D_SOA_POS_BY,
    C2D_SOA_VEL_AX, C2D_SOA_VEL_AY, C2D_SOA_VEL_BX, C2D_SOA_VEL_BY,
    C2D_SOA_MASS_A, C2D_SOA_MASS_B, C2D_SOA_FIELDS
};

/* Where a batch call's pairs live: field k of pair i is field[k][i] (the
 * velocity fields are written), and status receives the statuses (NULL:
 * none asked for).  c2d_soa_in lays the fields out in one block of
 * C2D_SOA_FIELDS x capacity elements; a caller that allocates each field on
 * its own fills field[] itself.  The batch call takes c2d_soa_pairs(&s). */
#ifndef C2D_NO_DOUBLE
typedef struct c2d_soa { double *field[C2D_SOA_FIELDS]; c2d_status *status; } c2d_soa;
#endif
#ifndef C2D_NO_FLOAT
typedef struct c2d_soaf { float *field[C2D_SOA_FIELDS]; c2d_status *status; } c2d_soaf;
#endif

/* ------------------------------------------------ batch against scalar */

/* The batch entry points promise, lane by lane, c2d_collide's status and
 * bits, and a return value that counts the lanes resolved (C2D_OK). */
typedef struct c2d_batch_check {
    size_t resolved;  /* lanes the scalar call resolved: what the batch must return */
    size_t differing; /* lanes whose status or velocity bits differ */
    size_t first;     /* the first of those, when there is one */
} c2d_batch_check;

/* Everything agreed, and `done`, the batch call's return value, too. */
static inline int c2d_batch_check_passed(const c2d_batch_check *c, size_t done)
{
    return c->differing == 0 && done == c->resolved;
}

/* Per floating type (soa_double.c, soa_float.c):
 *   c2d_soa_in(block, capacity, status)   the storage over one block
 *   c2d_soa_pairs(s)                      the library's view of it
 *   c2d_soa_put(s, i, a, b), c2d_soa_get  pair i from / into two bodies
 *   c2d_batch_check_lane(c, s, i, want, a, b)
 *       lane i of a batch call just made on s against the scalar call that
 *       returned `want` and left a, b (its status unless s->status is NULL,
 *       and the four velocities bit for bit); counts into *c
 *   c2d_batch_check_copies(c, s, lanes, a, b, e)
 *       the batch call over `lanes` (>= 1) copies of the pair (a, b) in s,
 *       each lane checked against one scalar call; returns the batch's
 *       return value (compare with c2d_batch_check_passed) */
#ifndef C2D_NO_DOUBLE
c2d_soa c2d_soa_in(double *block, size_t capacity, c2d_status *status);
c2d_pairs c2d_soa_pairs(const c2d_soa *s);
void c2d_soa_put(const c2d_soa *s, size_t i, const c2d_body *a, const c2d_body *b);
void c2d_soa_get(const c2d_soa *s, size_t i, c2d_body *a, c2d_body *b);
void c2d_batch_check_lane(c2d_batch_check *c, const c2d_soa *s, size_t i, c2d_status want, const c2d_body *a,
                          const c2d_body *b);
size_t c2d_batch_check_copies(c2d_batch_check *c, const c2d_soa *s, size_t lanes, const c2d_body *a,
                              const c2d_body *b, double e);
#endif
#ifndef C2D_NO_FLOAT
c2d_soaf c2d_soa_inf(float *block, size_t capacity, c2d_status *status);
c2d_pairsf c2d_soa_pairsf(const c2d_soaf *s);
void c2d_soa_putf(const c2d_soaf *s, size_t i, const c2d_bodyf *a, const c2d_bodyf *b);
void c2d_soa_getf(const c2d_soaf *s, size_t i, c2d_bodyf *a, c2d_bodyf *b);
void c2d_batch_check_lanef(c2d_batch_check *c, const c2d_soaf *s, size_t i, c2d_status want, const c2d_bodyf *a,
                           const c2d_bodyf *b);
size_t c2d_batch_check_copiesf(c2d_batch_check *c, const c2d_soaf *s, size_t lanes, const c2d_bodyf *a,
                               const c2d_bodyf *b, float e);
#endif

#endif
