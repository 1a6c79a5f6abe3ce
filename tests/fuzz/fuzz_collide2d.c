/* SPDX-License-Identifier: MIT */
/* fuzz_collide2d.c - libFuzzer harness for every public entry point.
 *
 * INPUT FORMAT (raw bytes; missing bytes read as 0)
 *   byte 0   entry point, modulo C2D_FUZZ_ENTRIES (see the enum in fuzz.h);
 *            C2D_FUZZ_SPHERE_TAG (255): a sphere contact, byte 2 mod 4
 *   byte 1   decoding mode (low 2 bits) and flags (high bits)
 *   rest     the arguments, field by field (decode.c).  In C2D_FUZZ_RAW
 *            every double/float/int32 is its bit pattern straight from the
 *            bytes, so NaN, Inf, subnormals and negative zero all occur.
 *            C2D_FUZZ_TAME reads small values (int16 / 256, positive masses,
 *            e in [0, 1]) so the accepting paths and the batch's vector
 *            kernel are reached too.  C2D_FUZZ_MIXED prefixes each field with
 *            a tag byte choosing raw bits, a tame value, a wide-range
 *            int16 * 2^k, or a special value.
 *
 * PROPERTIES (any violation prints the case and aborts)
 *   - the status is one of the enum's values and has a name;
 *   - on any status but OK both bodies are bit-for-bit untouched (memcmp),
 *     and time of impact leaves *t untouched;
 *   - on OK positions and masses are untouched, every output is finite, an
 *     immovable body keeps its velocity, momentum is conserved and kinetic
 *     energy is not gained within the bound the documented accuracy implies
 *     (bounds.c);
 *   - float and double agree: the float inputs, widened exactly to double,
 *     give the same status (RANGE aside, where the float result really is
 *     near FLT_MAX) and outputs within the sum of their documented bounds;
 *     likewise Q16.16 against double, with the Q16.16 bound;
 *   - time of impact: its status is the exact referee's (referee/, GMP
 *     rationals; RANGE when the exact t exceeds the format's largest
 *     value), and when OK t is within the documented 4 units (ulp(t) plus
 *     ulp(|d|) over the approach speed) of the exact time (Q16.16: agrees
 *     with the double answer within its documented bound);
 *   - rough contact (c2d_collide_rough(_normal)(f)): the status is the
 *     referee's (referee/ref_rough.c: exact, in the priority order) and on
 *     OK each output within 18 ulp of its body's scale; only velocities
 *     and spins written, never non-finite; an immovable body keeps its
 *     velocity, infinite inertia or a zero radius its spin; momentum kept
 *     and energy (with rotation) never gained beyond what 18 ulp allow;
 *     friction 0, and beta = -1, give c2d_collide(_normal)'s status and
 *     velocities bit for bit with the spins untouched (INVALID instead
 *     when a field only the rough contact reads is bad);
 *   - time of impact under acceleration: *t written only on OK, then
 *     0 <= t <= horizon; the status is the exact referee's
 *     (referee/ref_toi_accel.c, Sturm sequences over Q) outside the tie
 *     band the header states, and t within 1 unit of the exact time; with
 *     equal accelerations and no horizon, c2d_time_of_impact's status;
 *   - sphere contacts (c2d_collide_balls(f), c2d_collide_cushion(f)): on OK
 *     only velocities and spins written, never non-finite; an immovable
 *     ball keeps its velocity, infinite inertia or a zero radius its spin;
 *     momentum kept between finite masses, each ball's angular momentum at
 *     the contact along n^ and z^ kept, energy (translation and rotation)
 *     never gained, each within what the documented 24 (balls) or 16
 *     (cushion) ulp of the scale allow; inside the range the unit tests
 *     sweep, the status and outputs are the 512-bit referee's
 *     (referee/ref_sphere.c) within those bounds (fuzz_sphere_template.h);
 *   - the batch entry points give bit-identical outputs, statuses and count
 *     to scalar calls on the same pairs (tests/harness), each of which
 *     holds every property above.
 *
 * This file: the entry point and the failure report.  The checks of double
 * and float are one template (fuzz_template.h) instantiated by fuzz_double.c
 * and fuzz_float.c, as lib/ instantiates its own; Q16.16 is fuzz_fixed.c.
 */
#include "fuzz.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* ------------------------------------------------------------- failure */

static const char *c2d_fuzz_case = "";
static char c2d_fuzz_inputs[1024]; /* the decoded arguments, for the report */

void c2d_fuzz_fail(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "fuzz property violated (%s): ", c2d_fuzz_case);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n  inputs: %s\n", c2d_fuzz_inputs);
    abort();
}

void c2d_fuzz_check_status(c2d_status s)
{
    if (s != C2D_OK && s != C2D_SEPARATING && s != C2D_DEGENERATE && s != C2D_INVALID && s != C2D_RANGE)
        c2d_fuzz_fail("status %d is not an enum value", (int)s);
    if (c2d_status_string(s) == NULL || strcmp(c2d_status_string(s), "unknown") == 0)
        c2d_fuzz_fail("status %d has no name", (int)s);
}

void c2d_fuzz_check_untouched(const void *before, const void *after, size_t n, c2d_status s, const char *what)
{
    if (memcmp(before, after, n) != 0) c2d_fuzz_fail("status %s but %s was modified", c2d_status_string(s), what);
}

void c2d_fuzz_describe(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c2d_fuzz_inputs, sizeof c2d_fuzz_inputs, fmt, ap);
    va_end(ap);
}

void c2d_fuzz_describe_d(const c2d_body *a, const c2d_body *b, double nx, double ny, double e)
{
    c2d_fuzz_describe("a={{%a,%a},{%a,%a},%a} b={{%a,%a},{%a,%a},%a} n={%a,%a} e/r=%a", a->pos.x, a->pos.y, a->vel.x,
             a->vel.y, a->mass, b->pos.x, b->pos.y, b->vel.x, b->vel.y, b->mass, nx, ny, e);
}

void c2d_fuzz_describe_x(const c2d_bodyx *a, const c2d_bodyx *b, c2d_fixed nx, c2d_fixed ny, c2d_fixed e)
{
    c2d_fuzz_describe("a={{%d,%d},{%d,%d},%d} b={{%d,%d},{%d,%d},%d} n={%d,%d} e/r=%d", (int)a->pos.x, (int)a->pos.y,
             (int)a->vel.x, (int)a->vel.y, (int)a->mass, (int)b->pos.x, (int)b->pos.y, (int)b->vel.x,
             (int)b->vel.y, (int)b->mass, (int)nx, (int)ny, (int)e);
}

/* ------------------------------------------------------------- entry */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[C2D_FUZZ_ALL_ENTRIES] = {
        "c2d_collide", "c2d_collide_normal", "c2d_time_of_impact", "c2d_collidef", "c2d_collide_normalf",
        "c2d_time_of_impactf", "c2d_collidex", "c2d_collide_normalx", "c2d_time_of_impactx",
        "c2d_collide_batch", "c2d_collide_batchf", "c2d_collide_rough", "c2d_collide_rough_normal",
        "c2d_time_of_impact_accel", "c2d_collide_roughf", "c2d_collide_rough_normalf", "c2d_time_of_impact_accelf",
        "c2d_collide_balls", "c2d_collide_cushion", "c2d_collide_ballsf", "c2d_collide_cushionf"};
    c2d_fuzz_reader r;
    int entry, flags;
    r.p = data;
    r.n = size;
    r.mode = C2D_FUZZ_MIXED;
    entry = c2d_fuzz_read_byte(&r);
    flags = c2d_fuzz_read_byte(&r);
    entry = entry == C2D_FUZZ_SPHERE_TAG ? C2D_FUZZ_ENTRIES + c2d_fuzz_read_byte(&r) % 4 : entry % C2D_FUZZ_ENTRIES;
    r.mode = flags % 4 == 3 ? C2D_FUZZ_MIXED : flags % 4;
    c2d_fuzz_case = names[entry];
    switch (entry) {
    case C2D_FUZZ_COLLIDE: c2d_fuzz_collide(&r, 0); break;
    case C2D_FUZZ_COLLIDE_NORMAL: c2d_fuzz_collide(&r, 1); break;
    case C2D_FUZZ_TOI: c2d_fuzz_time_of_impact(&r); break;
    case C2D_FUZZ_COLLIDEF: c2d_fuzz_collidef(&r, 0); break;
    case C2D_FUZZ_COLLIDE_NORMALF: c2d_fuzz_collidef(&r, 1); break;
    case C2D_FUZZ_TOIF: c2d_fuzz_time_of_impactf(&r); break;
    case C2D_FUZZ_COLLIDEX: c2d_fuzz_collidex(&r, 0); break;
    case C2D_FUZZ_COLLIDE_NORMALX: c2d_fuzz_collidex(&r, 1); break;
    case C2D_FUZZ_TOIX: c2d_fuzz_time_of_impactx(&r); break;
    case C2D_FUZZ_BATCH: c2d_fuzz_batch(&r, flags); break;
    case C2D_FUZZ_BATCHF: c2d_fuzz_batchf(&r, flags); break;
    case C2D_FUZZ_ROUGH: c2d_fuzz_collide_rough(&r, 0); break;
    case C2D_FUZZ_ROUGH_NORMAL: c2d_fuzz_collide_rough(&r, 1); break;
    case C2D_FUZZ_TOI_ACCEL: c2d_fuzz_time_of_impact_accel(&r); break;
    case C2D_FUZZ_ROUGHF: c2d_fuzz_collide_roughf(&r, 0); break;
    case C2D_FUZZ_ROUGH_NORMALF: c2d_fuzz_collide_roughf(&r, 1); break;
    case C2D_FUZZ_TOI_ACCELF: c2d_fuzz_time_of_impact_accelf(&r); break;
    case C2D_FUZZ_BALLS: c2d_fuzz_collide_balls(&r); break;
    case C2D_FUZZ_CUSHION: c2d_fuzz_collide_cushion(&r); break;
    case C2D_FUZZ_BALLSF: c2d_fuzz_collide_ballsf(&r); break;
    default: c2d_fuzz_collide_cushionf(&r); break;
    }
    return 0;
}
