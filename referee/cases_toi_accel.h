/* SPDX-License-Identifier: MIT */
/* cases_toi_accel.h - test-case families for the time of impact under
 * acceleration (the unit test, the fuzz seeds and the benchmark), and the
 * tie band of its contract as the tests check it. */
#ifndef C2D_CASES_TOI_ACCEL_H
#define C2D_CASES_TOI_ACCEL_H
#include <stdint.h>
#include "ref_toi_accel.h"
#include "rng.h"

/* The band (include/collide2d.h, c2d_time_of_impact_accel).  A case is in
 * it when a decisive exact quantity lies within its certified uncertainty:
 *   tie_f  <= EPS_F: |f| <= EPS_F (|d|^2 + R^2) at a minimum of f or at H;
 *   tie_g  <= EPS_G: |d.d'| <= EPS_G |d||d'| at an extremum of g where the
 *                    disks overlap or touch;
 *   tie_fs, tie_gs <= K_RES (accelerated, non-collinear motion only): the
 *                    same ties against the double-length time resolution,
 *                    a contact decided by less than one unit of 2^-2p t. */
#define TOIA_EPS_F_DOUBLE 0x1p-96
#define TOIA_EPS_F_FLOAT 0x1p-38
#define TOIA_EPS_G_DOUBLE 0x1p-96
#define TOIA_EPS_G_FLOAT 0x1p-38
#define TOIA_K_RES 0x1p12

/* 1 when the two accelerations differ (the relative motion is curved). */
int toia_accel_differs(const ref_toia_in *in);
/* 1 when the case lies in the band above (for the working format). */
int toia_in_band(const ref_toia_out *o, int is_float, const ref_toia_in *in);

typedef void (*case_gen)(c2d_rng *r, int prec, ref_toia_in *in);

typedef struct family {
    const char *name;
    case_gen gen;
} family;

extern const family toia_families[];
extern const int toia_n_families;

/* Pool balls touching to rounding, a pushed into b or sliding along it,
 * cloth decelerations (the benchmark's touching set; not in the families). */
void toia_gen_touching(c2d_rng *r, int prec, ref_toia_in *in);

/* a graze construction: the distance is stationary at tc with value exactly
 * R (1 + delta) (a minimum if want_min, else a maximum); big: far along the
 * path (delta >= 2^-(MANT-2) then) */
void case_graze(c2d_rng *r, int prec, ref_toia_in *in, double delta, int want_min, int big);

/* round every input to float (exactly representable values stay) */
void toia_case_to_float(ref_toia_in *in);
#endif /* C2D_CASES_TOI_ACCEL_H */
