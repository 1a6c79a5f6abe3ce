/* SPDX-License-Identifier: MIT */
/* ref_toi_accel.h - exact referee for the time of impact under constant
 * accelerations (host only: GMP rationals, MPFR).
 *
 * The inputs are doubles (floats convert exactly), so d(t) = d0 + v t +
 * a t^2/2 has dyadic-rational coefficients and f(t) = |d|^2 - R^2,
 * g = f'/2 are polynomials over Q.  The status is decided exactly:
 * the real roots of the square-free part of f g in (0, H) (Sturm sequences
 * over Q, isolating intervals by bisection) cut (0, H) into open intervals
 * on which f and g have constant signs, read at a rational sample point;
 * the contact time is the left end of the first interval with f < 0 and
 * g < 0 (0 included), else H if f(H) <= 0 and g < 0 just after H (the
 * first nonzero derivative of g at H), else none.  The time is refined by
 * exact bisection to ~400 bits and handed to MPFR (1024 bits).
 *
 * Band diagnostics (not part of the exact answer): the smallest relative
 * tie distances
 *   tie_f = min |f| / (|d|^2 + R^2) over the minima of f in (0, H) (roots
 *           of g where g goes from - to +) and over H itself, both only
 *           up to the contact time when there is one;
 *   tie_g = min |g| / (|d| |d'|) over the extrema of g in (0, H) (roots of
 *           h = g') and H where the disks overlap or nearly touch
 *           (f <= tie scale), likewise only up to the contact time;
 *   tie_fs, tie_gs: the same values measured against what the working
 *           precision's double-length time resolution (2^-2p t) is worth
 *           there (see lib/real/toia/README.md, "The band").
 */
#ifndef C2D_REF_TOI_ACCEL_H
#define C2D_REF_TOI_ACCEL_H

#include <mpfr.h>
#include "collide2d.h"

typedef struct ref_toia_in {
    double pa[2], va[2], aa[2], pb[2], vb[2], ab[2];
    double r, h; /* radius sum, horizon (may be INFINITY) */
} ref_toia_in;

enum ref_toia_kind {
    REF_TOIA_AT0 = 0,    /* touching/overlapping and approaching at t = 0 */
    REF_TOIA_CROSS = 1,  /* down-crossing of f (the disks come into contact) */
    REF_TOIA_TURN = 2,   /* overlapping, radial velocity turns to approach (root of g) */
    REF_TOIA_AT_H = 3    /* fresh entry exactly at the horizon */
};

typedef struct ref_toia_out {
    c2d_status status; /* exact: OK, SEPARATING, RANGE or INVALID */
    int kind;          /* enum ref_toia_kind, when OK/RANGE */
    mpfr_t t;          /* the exact contact time (1024 bits) */
    double td;         /* t rounded to double */
    double unit;       /* accuracy unit at t for precision prec: ulp(t) + ulp(|d|)/s,
                          or for a turn ulp(t) + ulp(|d||d'|)/|g'| */
    double tie_f, tie_g; /* band diagnostics (INFINITY when no such point) */
    double tie_fs, tie_gs; /* the same ties against the time-resolution terms:
                              |f(c)| / ((|d'|^2 + |d||a|) (2^-2p c)^2) at minima of f,
                              |g(q)| / (|h'(q)| (2^-2p q)^2) at extrema of g */
} ref_toia_out;

void ref_toia_init(ref_toia_out *o);
void ref_toia_clear(ref_toia_out *o);

/* Decide and compute.  prec, emin: the working format (53, -1022 or 24,
 * -126) for the units and for RANGE (t > the format's max). */
void ref_toia(const ref_toia_in *in, int prec, int emin, ref_toia_out *o);

/* |got - t| / unit, computed in MPFR (INFINITY for a non-finite got). */
double ref_toia_err(const ref_toia_out *o, double got);

#endif
