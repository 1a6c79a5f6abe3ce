/* SPDX-License-Identifier: MIT */
/* fuzz.h - what the translation units of the fuzz harness share (the input
 * format and the properties are described in fuzz_collide2d.c):
 *   fuzz_collide2d.c   the entry point and the failure report
 *   decode.c           the input bytes decoded into arguments
 *   bounds.c           the bounds the documented accuracy implies
 *   fuzz_template.h    the checks of one floating type, instantiated by
 *                      fuzz_double.c and fuzz_float.c (as lib/ does);
 *                      fuzz_rough_template.h, fuzz_accel_template.h and
 *                      fuzz_sphere_template.h likewise for the rough
 *                      contact, the time of impact under acceleration and
 *                      the sphere contacts
 *   fuzz_fixed.c       the Q16.16 checks */
#ifndef C2D_FUZZ_H
#define C2D_FUZZ_H

#include <stddef.h>
#include <stdint.h>

#include "collide2d.h"
#include "harness.h"

/* The entry points, in the order of the input's first byte. */
enum {
    C2D_FUZZ_COLLIDE,
    C2D_FUZZ_COLLIDE_NORMAL,
    C2D_FUZZ_TOI,
    C2D_FUZZ_COLLIDEF,
    C2D_FUZZ_COLLIDE_NORMALF,
    C2D_FUZZ_TOIF,
    C2D_FUZZ_COLLIDEX,
    C2D_FUZZ_COLLIDE_NORMALX,
    C2D_FUZZ_TOIX,
    C2D_FUZZ_BATCH,
    C2D_FUZZ_BATCHF,
    C2D_FUZZ_ROUGH,
    C2D_FUZZ_ROUGH_NORMAL,
    C2D_FUZZ_TOI_ACCEL,
    C2D_FUZZ_ROUGHF,
    C2D_FUZZ_ROUGH_NORMALF,
    C2D_FUZZ_TOI_ACCELF,
    C2D_FUZZ_ENTRIES,
    /* Byte 0 = C2D_FUZZ_SPHERE_TAG: these, chosen by byte 2 (the other 255
     * values of byte 0 keep their entries, so the corpus keeps its meaning). */
    C2D_FUZZ_BALLS = C2D_FUZZ_ENTRIES,
    C2D_FUZZ_CUSHION,
    C2D_FUZZ_BALLSF,
    C2D_FUZZ_CUSHIONF,
    C2D_FUZZ_ALL_ENTRIES
};
#define C2D_FUZZ_SPHERE_TAG 255

enum { C2D_FUZZ_MIXED = 0, C2D_FUZZ_TAME = 1, C2D_FUZZ_RAW = 2 };
#define C2D_FUZZ_NULL_STATUS 0x04 /* batch: pass status == NULL */

/* ------------------------------------------------ failure (fuzz_collide2d.c) */

/* Prints the property violated, the entry point and the decoded inputs,
 * then aborts (libFuzzer saves the input). */
void c2d_fuzz_fail(const char *fmt, ...);
/* Records the decoded arguments for the report (e/r: restitution or radius). */
void c2d_fuzz_describe_d(const c2d_body *a, const c2d_body *b, double nx, double ny, double e);
void c2d_fuzz_describe_x(const c2d_bodyx *a, const c2d_bodyx *b, c2d_fixed nx, c2d_fixed ny, c2d_fixed e);
/* Records any text as the decoded arguments. */
void c2d_fuzz_describe(const char *fmt, ...);
/* The status is one of the enum's values and has a name. */
void c2d_fuzz_check_status(c2d_status s);
/* n bytes unchanged by a call that returned s. */
void c2d_fuzz_check_untouched(const void *before, const void *after, size_t n, c2d_status s, const char *what);

/* ---------------------------------------------------------- input (decode.c) */

typedef struct c2d_fuzz_reader {
    const uint8_t *p;
    size_t n;
    int mode;
} c2d_fuzz_reader;

uint8_t c2d_fuzz_read_byte(c2d_fuzz_reader *r);
double c2d_fuzz_read_double(c2d_fuzz_reader *r);
double c2d_fuzz_read_mass(c2d_fuzz_reader *r);
double c2d_fuzz_read_restitution(c2d_fuzz_reader *r);
float c2d_fuzz_read_float(c2d_fuzz_reader *r);
float c2d_fuzz_read_massf(c2d_fuzz_reader *r);
float c2d_fuzz_read_restitutionf(c2d_fuzz_reader *r);
c2d_fixed c2d_fuzz_read_fixed(c2d_fuzz_reader *r);
c2d_fixed c2d_fuzz_read_massx(c2d_fuzz_reader *r);
c2d_fixed c2d_fuzz_read_restitutionx(c2d_fuzz_reader *r);
double c2d_fuzz_read_friction(c2d_fuzz_reader *r);
double c2d_fuzz_read_beta(c2d_fuzz_reader *r);
double c2d_fuzz_read_horizon(c2d_fuzz_reader *r);
float c2d_fuzz_read_frictionf(c2d_fuzz_reader *r);
float c2d_fuzz_read_betaf(c2d_fuzz_reader *r);
float c2d_fuzz_read_horizonf(c2d_fuzz_reader *r);

/* --------------------------------------------------------- bounds (bounds.c) */

typedef struct c2d_fuzz_fmt {
    int prec, emin; /* 53/-1022 double, 24/-126 float */
} c2d_fuzz_fmt;

extern const c2d_fuzz_fmt c2d_fuzz_fmt_double;

long double c2d_fuzz_ulp(long double s, c2d_fuzz_fmt f);
long double c2d_fuzz_maxabs4(long double a, long double b, long double c, long double d);

/* A response in long double, the same for all three types: v[0..3] before
 * (vax, vay, vbx, vby), w[0..3] after, masses (immovable flagged), the
 * normal, and the per-body error delta each output may carry. */
typedef struct c2d_fuzz_response {
    long double v[4], w[4], m[2], n[2];
    int immovable[2];
    long double delta[2], scale[2];
} c2d_fuzz_response;

/* scale[] and delta[] of a floating type's response (16 ulp of the scale). */
void c2d_fuzz_fill_scales(c2d_fuzz_response *x, c2d_fuzz_fmt f);
/* Direction, momentum, energy and immovable bodies within the bounds. */
void c2d_fuzz_check_conservation(const c2d_fuzz_response *x);

/* ------------------------------------------------------------- the variants */

void c2d_fuzz_collide(c2d_fuzz_reader *r, int with_normal);
void c2d_fuzz_time_of_impact(c2d_fuzz_reader *r);
void c2d_fuzz_batch(c2d_fuzz_reader *r, int flags);
void c2d_fuzz_collidef(c2d_fuzz_reader *r, int with_normal);
void c2d_fuzz_time_of_impactf(c2d_fuzz_reader *r);
void c2d_fuzz_batchf(c2d_fuzz_reader *r, int flags);
void c2d_fuzz_collidex(c2d_fuzz_reader *r, int with_normal);
void c2d_fuzz_time_of_impactx(c2d_fuzz_reader *r);
void c2d_fuzz_collide_rough(c2d_fuzz_reader *r, int with_normal);
void c2d_fuzz_time_of_impact_accel(c2d_fuzz_reader *r);
void c2d_fuzz_collide_roughf(c2d_fuzz_reader *r, int with_normal);
void c2d_fuzz_time_of_impact_accelf(c2d_fuzz_reader *r);
void c2d_fuzz_collide_balls(c2d_fuzz_reader *r);
void c2d_fuzz_collide_cushion(c2d_fuzz_reader *r);
void c2d_fuzz_collide_ballsf(c2d_fuzz_reader *r);
void c2d_fuzz_collide_cushionf(c2d_fuzz_reader *r);

/* The double answer the float and Q16.16 checks compare with
 * (fuzz_double.c): the call made and checked as c2d_fuzz_collide does
 * (n NULL: c2d_collide), the time of impact's checks, and the response's
 * bounds. */
c2d_status c2d_fuzz_collide_checked(c2d_body *a, c2d_body *b, const c2d_vec2 *n, double e);
void c2d_fuzz_check_time_of_impact(c2d_status s, double t, double t0);
c2d_fuzz_response c2d_fuzz_response_of(const c2d_body *a0, const c2d_body *b0, const c2d_body *a, const c2d_body *b,
                                       long double nx, long double ny);

#endif
