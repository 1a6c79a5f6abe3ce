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

#endif
