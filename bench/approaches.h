/* SPDX-License-Identifier: MIT */
/* Reference approaches a user might write instead of calling collide2d,
 * transcribed for the benchmark only (never shipped).  Each takes the
 * library's body type so every contender sees the same inputs, writes the
 * velocities in place and returns the status it would report. */
#ifndef C2D_BENCH_APPROACHES_H
#define C2D_BENCH_APPROACHES_H

#include "collide2d.h"

/* The seed document's method as written: unit normal and tangent with sqrt,
 * equal masses (the normal components are swapped), e = 1, no checks at all
 * (always C2D_OK, even when the bodies separate). */
c2d_status bench_seed_equal(c2d_body *a, c2d_body *b, double restitution);

/* The same method with the seed's own 1-D formula for unequal masses,
 * v1nf = [v1n (m1 - m2) + 2 m2 v2n] / (m1 + m2), with restitution folded in
 * the same style (m1 - e m2, (1 + e) m2); identical to the seed at e = 1.
 * No checks. */
c2d_status bench_seed_masses(c2d_body *a, c2d_body *b, double restitution);

/* The seed's final summary formulas exactly as printed (equal masses,
 * e = 1), including the erratum in the tangential terms. */
c2d_status bench_seed_summary(c2d_body *a, c2d_body *b, double restitution);

/* Trigonometric textbook version: phi = atan2(ny, nx), rotate both
 * velocities into the collision frame, 1-D collision along the normal
 * (unequal masses, restitution), rotate back.  Reports C2D_SEPARATING when
 * the bodies do not approach, C2D_OK otherwise; no other checks. */
c2d_status bench_trig(c2d_body *a, c2d_body *b, double restitution);

/* An empty call with the same signature: the loop and call overhead that
 * every scalar contender's timing includes. */
c2d_status bench_noop(c2d_body *a, c2d_body *b, double restitution);

/* The speed goals' baselines, transcribed as plainly as a user would write them. */

/* bench_seed_equal in float (sqrtf), and both with the normal (nx, ny)
 * given instead of b.pos - a.pos (the seed's method fed the same normal as
 * c2d_collide_normal).  The normal comes as two scalars, in the registers a
 * c2d_vec2 by value would use: gcc 12 stores a by-value c2d_vec2 to the
 * stack and reloads it as one 16-byte vector, which cannot be forwarded
 * from the two 8-byte stores (a stall of some 10 cycles in the callee);
 * bench_seed_equal_normal_v is the by-value form, timed once to show it. */
c2d_status bench_seed_equalf(c2d_bodyf *a, c2d_bodyf *b, float restitution);
c2d_status bench_seed_equal_normal(c2d_body *a, c2d_body *b, double nx, double ny, double restitution);
c2d_status bench_seed_equal_normalf(c2d_bodyf *a, c2d_bodyf *b, float nx, float ny, float restitution);
c2d_status bench_seed_equal_normal_v(c2d_body *a, c2d_body *b, c2d_vec2 normal, double restitution);

/* The bare impulse formula as a user writes it (issue 22's baseline):
 * n = d / |d|, the normal approach g = (vb - va).n, and when approaching
 * the impulse j = -(1 + e) g / (1/ma + 1/mb) along n; no other checks (a
 * zero distance or a NaN gives NaN velocities, two immovable bodies too).
 * One text for the out-of-line calls (bench_bare, bench_baref) and the pass
 * that expands it into the loop (bench/ratio.c). */
#define BENCH_BARE(T, SQRT, a, b, e, status)                                                      \
    do {                                                                                         \
        const T nx_ = (b)->pos.x - (a)->pos.x, ny_ = (b)->pos.y - (a)->pos.y;                    \
        const T len_ = SQRT(nx_ * nx_ + ny_ * ny_);                                              \
        const T ux_ = nx_ / len_, uy_ = ny_ / len_;                                              \
        const T g_ = ((b)->vel.x - (a)->vel.x) * ux_ + ((b)->vel.y - (a)->vel.y) * uy_;          \
        if (g_ < 0) {                                                                            \
            const T ia_ = 1 / (a)->mass, ib_ = 1 / (b)->mass;                                    \
            const T j_ = -(1 + (e)) * g_ / (ia_ + ib_);                                          \
            (a)->vel.x -= j_ * ia_ * ux_, (a)->vel.y -= j_ * ia_ * uy_;                          \
            (b)->vel.x += j_ * ib_ * ux_, (b)->vel.y += j_ * ib_ * uy_;                          \
            (status) = C2D_OK;                                                                   \
        } else {                                                                                 \
            (status) = C2D_SEPARATING;                                                           \
        }                                                                                        \
    } while (0)
c2d_status bench_bare(c2d_body *a, c2d_body *b, double restitution);
c2d_status bench_baref(c2d_bodyf *a, c2d_bodyf *b, float restitution);

/* The textbook time of impact: d = pb - pa, v = vb - va, a = v.v, b = d.v,
 * c = d.d - R^2, disc = b^2 - ac, t = (-b - sqrt(disc)) / a, with the
 * obvious early outs (b >= 0: SEPARATING; c <= 0: t = 0; disc <= 0:
 * SEPARATING).  No scaling, no care: overflow, underflow and cancellation
 * as they come. */
c2d_status bench_toi_textbook(const c2d_body *a, const c2d_body *b, double radius_sum, double *t);
c2d_status bench_toi_textbookf(const c2d_bodyf *a, const c2d_bodyf *b, float radius_sum, float *t);

/* Walton's rough-disk model transcribed plainly in double: unit normal and
 * tangent with sqrt, slip velocity, normal impulse -(1+e) gn / (1/ma + 1/mb),
 * sticking impulse -(1+beta) gt mt capped at mu Jn (Coulomb), velocities and
 * spins updated.  Reports SEPARATING when gn >= 0, OK otherwise; no other
 * checks, normal = b.pos - a.pos. */
c2d_status bench_walton(c2d_disk *a, c2d_disk *b, c2d_surface s);

/* The time of impact under constant acceleration the textbook ways
 * (bench/quartic.c): the quartic in closed form (Ferrari) and by Sturm
 * sequence and bisection; the interface of c2d_time_of_impact_accel. */
c2d_status bench_toia_ferrari(const c2d_body *a, c2d_vec2 aa, const c2d_body *b, c2d_vec2 ab, double R, double H,
                              double *t);
c2d_status bench_toia_sturm(const c2d_body *a, c2d_vec2 aa, const c2d_body *b, c2d_vec2 ab, double R, double H,
                            double *t);

#endif
