/* SPDX-License-Identifier: MIT */
/* Referee for c2d_collide_rough: the status exactly (the normal part is
 * c2d_collide's, decided by ref_collide in rationals; the extra validation
 * by the contract), the outputs in MPFR at REF_ROUGH_BITS bits: enough that
 * every input difference is exact and the slip speed's cancellation costs
 * nothing at the accuracy measured. */
#ifndef C2D_REF_ROUGH_H
#define C2D_REF_ROUGH_H

#include <mpfr.h>
#include "referee.h"

typedef struct ref_disk { double pos[2], vel[2], spin, mass, radius, inertia; } ref_disk;

typedef struct ref_rough_case {
    ref_disk a, b;
    double n[2];    /* used when has_normal; else b.pos - a.pos exactly */
    int has_normal;
    double e, mu, beta;
} ref_rough_case;

/* Outputs {va.x, va.y, vb.x, vb.y, spin a, spin b}. */
typedef struct ref_rough_answer {
    c2d_status status;
    int range_allowed;   /* C2D_RANGE is acceptable (a result near the limit) */
    int range_required;  /* a result is beyond the limit */
    double scale[2];     /* each body's scale: max |vx|, |vy|, |spin r| before and after */
    mpfr_t out[6];
} ref_rough_answer;

void ref_rough_init(ref_rough_answer *r);
void ref_rough_clear(ref_rough_answer *r);
void ref_rough(const ref_rough_case *c, double range_limit, ref_rough_answer *r);

/* Worst error of got[6] in ulp of each body's scale (spins as spin x radius). */
double ref_rough_err(const ref_rough_case *c, const ref_rough_answer *r, const double got[6], int prec, int emin);

/* Kinetic energy (with rotation) and the three momenta of the pair, before
 * (got == NULL) or after, in MPFR: {energy, px, py, L about the origin}. */
void ref_rough_invariants(const ref_rough_case *c, const double *got, double out[4]);

#endif
