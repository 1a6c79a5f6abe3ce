/* SPDX-License-Identifier: MIT */
/* collide2d.h - exact, robust 2-D collisions between disks.  C99, no
 * dependencies, no allocation, no globals, freestanding-clean.
 *
 * WHAT IT DOES
 *   Given two disks (position, velocity, mass) that touch, it replaces their
 *   velocities by the post-impact ones: the velocity components along the unit
 *   normal undergo a 1-D collision with a coefficient of restitution, the
 *   tangential components are kept.  Masses may differ by any ratio and may be
 *   INFINITY (an immovable wall).  It also computes the time of impact of two
 *   moving disks.  Double, float and Q16.16 fixed-point variants, plus batch
 *   entry points over structure-of-arrays data.  For scenes that need them
 *   (a pool table, granular matter): friction and spin at contact
 *   (c2d_collide_rough, Walton's rough disks), pool balls as spheres with
 *   three-component spin and cushions above the centre (c2d_collide_balls,
 *   c2d_collide_cushion) and the time of impact under constant
 *   acceleration (c2d_time_of_impact_accel); a scene pays only for
 *   the model it calls.  Axis-aligned impacts are correctly rounded (an
 *   equal-mass swap and a wall's sign flip are exact).
 *
 * EXAMPLE
 *   c2d_body a = { {0.0, 0.0}, {1.0, 0.0}, 1.0 };      // pos, vel, mass
 *   c2d_body b = { {1.0, 1.0}, {0.0, 0.0}, 1.0 };
 *   if (c2d_collide(&a, &b, 1.0) == C2D_OK) {
 *       // a.vel == (0.5, -0.5), b.vel == (0.5, 0.5): momentum and energy kept
 *   }
 *
 * CONVENTIONS
 *   - Any consistent units (SI: m, m/s, kg, s).  Masses > 0; INFINITY means
 *     immovable.  Restitution e in [0, 1]: 1 = elastic, 0 = perfectly plastic.
 *   - The normal points FROM a TOWARDS b.  c2d_collide uses b.pos - a.pos;
 *     c2d_collide_normal takes any finite non-zero vector of any length.
 *   - Only velocities are written; positions and masses never.  Any status but
 *     C2D_OK leaves both bodies bit-for-bit untouched.
 *   - "Velocity scale" of a body: the largest |component| of its velocity
 *     before and after the call.  Accuracy is stated in ulp of that scale.
 *   - Results are deterministic: the same inputs give the same bits on every
 *     IEEE-754 target that evaluates float/double in their own precision
 *     (FLT_EVAL_METHOD 0) and does not contract a*b+c into an FMA
 *     (build with -ffp-contract=off; see docs/DETERMINISM.md).
 *
 * CONFIGURATION (define when compiling the library; defaults in [])
 *   C2D_NO_DOUBLE  [undefined]  drop the double-precision API
 *   C2D_NO_FLOAT   [undefined]  drop the single-precision API
 *   C2D_NO_FIXED   [undefined]  drop the Q16.16 fixed-point API
 *   C2D_NO_DISPATCH [undefined] no run-time choice of CPU-specific code (gcc,
 *                  hosted x86-64 only: the batch kernel's SSE2/SSE4.2/AVX2/
 *                  AVX-512 versions and the FMA double-double tier; same bits
 *                  either way).  Implied under ThreadSanitizer, which cannot
 *                  run the loader's choice (an ifunc resolver) before main.
 *   C2D_SMALL      [1 under -Os/-Oz, else 0]  code size before speed: one copy
 *                  of each collision tier (no separate accept test before the
 *                  fast path, no batch kernel); the same bits either way.
 *   C2D_ALLOW_FAST_MATH [undefined]  build the library even under -ffast-math
 *                  or -ffinite-math-only, which otherwise stop its build with
 *                  an #error.  At your own risk: those flags let the compiler
 *                  assume no NaN or Inf and reassociate, and the library's
 *                  checks and exact arithmetic rely on neither happening; then
 *                  NaN/Inf inputs may be accepted, C2D_OK come with NaN
 *                  outputs, statuses be wrong, bits differ between builds.
 *                  Your own code may use them: the library is compiled apart,
 *                  and the inline front ends (C2D_INLINE, below) become plain
 *                  calls of the library under either flag.
 *   C2D_HEADER     ["../include/collide2d.h" from lib/; "collide2d.h" from the
 *                  amalgamation]  how the library's sources find this file,
 *                  e.g. -DC2D_HEADER='"collide2d.h"' when both sit in one
 *                  firmware folder
 *   The library is the .c files of lib/ (one per variant: collide2d.c,
 *   double.c, float.c, fixed.c; `cc -std=c99 -c` on them builds it with no
 *   other flag), or the single file `make amalgamate` writes to
 *   build/collide2d_all.c: the same code, the same options, the same bits.
 *   Build with -ffp-contract=off for reproducible bits, and -fno-math-errno
 *   so the time of impact's square roots are the FPU instruction.
 *
 * THREAD SAFETY: every function is reentrant; it touches only its arguments.
 */
#ifndef COLLIDE2D_H
#define COLLIDE2D_H

#include <stddef.h>
#include <stdint.h>

#define C2D_VERSION_MAJOR 1
#define C2D_VERSION_MINOR 1
#define C2D_VERSION_PATCH 0
/* MAJOR * 10000 + MINOR * 100 + PATCH, the value c2d_version() returns. */
#define C2D_VERSION \
    (C2D_VERSION_MAJOR * 10000L + C2D_VERSION_MINOR * 100L + C2D_VERSION_PATCH)

#ifdef __cplusplus
extern "C" {
#endif

typedef enum c2d_status {
    C2D_OK = 0,          /* velocities updated */
    C2D_SEPARATING = 1,  /* not approaching along the normal (relative normal velocity >= 0) */
    C2D_DEGENERATE = 2,  /* zero normal (coincident centres) or both bodies immovable */
    C2D_INVALID = 3,     /* NaN or Inf anywhere, mass <= 0 or NaN, restitution outside [0,1] */
    C2D_RANGE = 4        /* the result would overflow */
} c2d_status;

/* Library version as MAJOR * 10000 + MINOR * 100 + PATCH (== C2D_VERSION of
 * the header the library was built with). */
long c2d_version(void);

/* A static English name for a status ("ok", "separating", ...); "unknown" for
 * a value outside the enum.  Never NULL. */
const char *c2d_status_string(c2d_status status);

/* ------------------------------------------------------------------ double */
#ifndef C2D_NO_DOUBLE
typedef struct c2d_vec2 { double x, y; } c2d_vec2;
typedef struct c2d_body { c2d_vec2 pos; c2d_vec2 vel; double mass; } c2d_body; /* mass > 0; INFINITY = immovable */

/* Resolve an impact between disks a and b along the line of centres
 * (normal = b.pos - a.pos, computed exactly: no rounding of the difference
 * enters the result).
 *   restitution  in [0, 1]; relative normal velocity after = -restitution x before.
 *   returns      C2D_OK (velocities written), C2D_SEPARATING (relative normal
 *                velocity >= 0, including exactly 0), C2D_DEGENERATE (a.pos ==
 *                b.pos, or both masses INFINITY), C2D_INVALID (any NaN/Inf in a
 *                position or velocity, a mass <= 0 or NaN, restitution outside
 *                [0,1] or NaN, a or b NULL), C2D_RANGE (always when a result
 *                would exceed DBL_MAX; possibly when a result or a velocity
 *                change exceeds DBL_MAX/8).  Priority INVALID > DEGENERATE
 *                > SEPARATING > RANGE > OK; on any status but OK nothing is written.
 *   accuracy     every finite input over the whole double range: each output
 *                component within 16 ulp of its body's velocity scale (measured
 *                worst: see docs/ACCURACY.md); momentum conserved and energy
 *                conserved at e = 1 to that accuracy; the relative normal
 *                velocity is reversed exactly in sign (no false SEPARATING).
 *   axis-aligned when the centres share an x or a y coordinate exactly, every
 *                output is correctly rounded (the representable value
 *                nearest the exact result, ties to even): equal masses at
 *                e = 1 swap their normal components exactly, an immovable
 *                wall at e = 1 negates it exactly, the other component is
 *                returned bit for bit (Newton's cradle: docs/ACCURACY.md).
 *   a == b (same pointer) is C2D_DEGENERATE. */
c2d_status c2d_collide(c2d_body *a, c2d_body *b, double restitution);

/* As c2d_collide, with the contact normal given: any finite non-zero vector
 * of any length (subnormal to DBL_MAX), pointing from a towards b.  Positions
 * are ignored apart from validation (they must be finite).  A zero normal is
 * C2D_DEGENERATE.  Use it for walls: b.mass = INFINITY, normal = wall normal.
 * A normal with one zero component gives correctly rounded outputs, as
 * c2d_collide's axis-aligned case. */
c2d_status c2d_collide_normal(c2d_body *a, c2d_body *b, c2d_vec2 normal, double restitution);

/* Time of impact of two disks moving with constant velocity: the earliest
 * t >= 0 with |(b.pos - a.pos) + (b.vel - a.vel) t| = radius_sum while they
 * approach.  Masses are ignored.
 *   radius_sum   >= 0 (sum of the two radii; same length unit as positions).
 *   *t           written only on C2D_OK, in the time unit of the velocities.
 *   returns      C2D_OK (t >= 0 finite; overlapping and approaching gives t = 0),
 *                C2D_SEPARATING (receding, missing, no relative motion, or a
 *                graze: a miss distance of exactly radius_sum, where the
 *                disks touch with no approach speed, as c2d_collide says),
 *                C2D_INVALID (NaN/Inf in a position or velocity, radius_sum < 0
 *                or not finite, a NULL pointer), C2D_RANGE (t exceeds DBL_MAX).
 *   status       exact (decided by exact arithmetic wherever rounding could
 *                change it), magnitudes anywhere in the range and in any
 *                ratio.  One bounded-memory exception, never met in testing:
 *                a near-graze whose exact test needs more than 40 terms
 *                (all four differences pb - pa, vb - va inexact with their
 *                rounding errors at scattered exponents) is decided to
 *                2^-52 (float 2^-23) relative accuracy instead.
 *   accuracy     4 ulp of t plus 4 times the time one rounding (1 ulp) of the
 *                centre distance is worth at contact (ulp(|d|) divided by the
 *                approach speed at contact); no cancellation for disks far
 *                apart relative to their size; positions, radii and speeds
 *                anywhere in the double range (no overflow in |d|^2 or |v|^2).
 *                Needs sqrt from the C library.
 *   cost         (x86-64, -O2, callgrind) ~190 instructions for an ordinary
 *                pair; touching pairs (|d| = radius_sum to rounding: pool
 *                balls resting in contact) ~130 receding, ~2,200 on average
 *                approaching (those with |d| <= radius_sum exactly, a hit
 *                now, ~430; the rest need the exact time, ~4,200). */
c2d_status c2d_time_of_impact(const c2d_body *a, const c2d_body *b, double radius_sum, double *t);

/* Time of impact of two disks moving with constant accelerations:
 * p(t) = pos + vel t + acc t^2 / 2 for each (a ball decelerating on cloth,
 * a puck under a constant force).  The earliest t in [0, horizon] at which
 * they touch or overlap (|pb(t) - pa(t)| <= radius_sum) while approaching
 * ((pb - pa).(vb - va) < 0 just after t).  Masses are ignored.
 *   acc_a, acc_b   accelerations, finite (same units as vel per time unit)
 *   radius_sum     >= 0 and finite
 *   horizon        >= 0, INFINITY allowed: the time until either body's
 *                  motion changes (a piecewise path is checked piece by piece)
 *   *t             written only on C2D_OK; 0 <= *t <= horizon.  Overlapping and
 *                  approaching at 0 gives 0; a pair that overlaps, recedes and
 *                  turns back gives the turn.
 *   returns        C2D_OK; C2D_SEPARATING (no contact in [0, horizon],
 *                  including a tangential graze: touching with no approach
 *                  speed, and no relative motion at all); C2D_INVALID (NaN/Inf
 *                  in a position, velocity or acceleration, radius_sum < 0 or
 *                  not finite, horizon < 0 or NaN, a NULL pointer); C2D_RANGE
 *                  (the contact lies within the horizon but beyond DBL_MAX).
 *   status         exact for decisions at t = 0 (touching pairs that stay in
 *                  contact, separate or are pushed together), otherwise
 *                  certified by three tiers of evaluation (plain, double
 *                  length, exact); what even exact evaluation of d(t) at a
 *                  working-precision time cannot certify is a band of width
 *                  ~2^-96 (float 2^-38) relative: a graze or a touch at the
 *                  horizon whose distance is within that of radius_sum, a turn
 *                  while overlapping whose radial speed is within it of zero,
 *                  and passes shorter than ~2^-106 of the elapsed time on a
 *                  curved path.  Ties there resolve as exact ties: a graze is
 *                  no contact, a touch at the horizon is a contact at it.
 *                  With equal accelerations (zero ones included) the relative
 *                  path is straight and the answer is c2d_time_of_impact's,
 *                  status and bits, at every magnitude, the horizon only
 *                  cutting (a contact beyond it is none; RANGE only with an
 *                  infinite horizon).
 *   accuracy       within 1 unit of ulp(t) + ulp(|d|) / s, s the approach speed
 *                  at contact (c2d_time_of_impact's unit; measured worst 0.5);
 *                  with equal accelerations c2d_time_of_impact's 4 units
 *                  (measured worst 2.2).
 *   cost           a few hundred ns for ordinary pairs (~1,800 instructions on
 *                  billiard pairs, x86-64 -O2, callgrind); microseconds near a
 *                  tie (exact evaluation): 9,000-22,000 instructions for
 *                  touching pool balls (side by side, pressed together,
 *                  rolling apart); stack up to ~3 KB (x86-64 double),
 *                  1.8 KB (Cortex-M4F float). */
c2d_status c2d_time_of_impact_accel(const c2d_body *a, c2d_vec2 acc_a, const c2d_body *b, c2d_vec2 acc_b,
                                    double radius_sum, double horizon, double *t);

/* Batch: resolve `count` independent pairs stored as structure of arrays.
 * Pair i is (pos_ax[i], pos_ay[i], vel_ax[i], vel_ay[i], mass_a[i]) against
 * the same fields of b.  Every pair is resolved exactly as c2d_collide would
 * (bit-identical results and statuses); pairs in the well-scaled common case
 * (walls included) run through a branch-free kernel in blocks of 16 that -O2
 * vectorises, those whose normal speed cancels through a second vector pass
 * (the scalar call's double-double tier, 16 such pairs at a time), the others
 * take the scalar call.  Built by gcc for hosted x86-64, the kernel
 * is chosen at load time for the CPU (SSE2, SSE4.2, AVX2 or AVX-512;
 * C2D_NO_DISPATCH turns this off); clang vectorises it at baseline.  Arrays
 * must not overlap.
 *   status       NULL, or an array of `count` statuses to fill.
 *   returns      the number of pairs with status C2D_OK; 0 if p is NULL. */
typedef struct c2d_pairs {
    const double *pos_ax, *pos_ay, *pos_bx, *pos_by;
    double *vel_ax, *vel_ay, *vel_bx, *vel_by;
    const double *mass_a, *mass_b;
} c2d_pairs;
size_t c2d_collide_batch(const c2d_pairs *p, size_t count, double restitution, c2d_status *status);

/* Rough disks: friction and spin at contact (Walton's model of rough
 * inelastic disks; docs/METHOD.md).  A scene that calls only c2d_collide
 * pays nothing for this model.
 *   spin     angular velocity about +z (counter-clockwise), rad per time unit
 *   mass     > 0; INFINITY = immovable (its velocity never changes)
 *   radius   >= 0 and finite: the contact point is at a.pos + a.radius n^
 *            (0 for a wall or a point)
 *   inertia  moment of inertia about the centre, > 0 (a solid disk
 *            m r^2 / 2, a billiard ball 2/5 m r^2); INFINITY = its spin never
 *            changes */
typedef struct c2d_disk { c2d_vec2 pos, vel; double spin, mass, radius, inertia; } c2d_disk;

/* The contact's surface:
 *   restitution             e in [0, 1]: normal slip speed after = -e x before
 *   friction                mu >= 0 (Coulomb; INFINITY: never slides)
 *   tangential_restitution  beta in [-1, 1]: tangential slip speed after =
 *                           -beta x before while sticking (-1: smooth,
 *                           0: the contact point stops, 1: perfectly rough) */
typedef struct c2d_surface { double restitution, friction, tangential_restitution; } c2d_surface;

/* Resolve an impact of two rough disks along the line of centres (normal =
 * b.pos - a.pos, taken exactly).  Normal impulse as c2d_collide (an impact
 * only if the normal slip speed is < 0); tangential impulse: the one that
 * makes the tangential slip speed g_t' = -beta g_t, unless its size exceeds
 * mu times the normal impulse, then mu times the normal impulse against the
 * slip.  g_t = (vb - va).t^ - (a.spin a.radius + b.spin b.radius),
 * t^ = (-n^y, n^x).  Both spins change by the torque of the tangential
 * impulse; velocities and spins are written, nothing else.
 *   returns      C2D_OK; C2D_SEPARATING, C2D_DEGENERATE and C2D_RANGE for the
 *                normal part exactly as c2d_collide; C2D_INVALID also for a
 *                NaN/Inf spin or radius, radius < 0, inertia <= 0 or NaN,
 *                friction < 0 or NaN, beta outside [-1, 1]; C2D_RANGE also
 *                when a velocity or spin result would exceed DBL_MAX.  Same
 *                priority; a == b is C2D_DEGENERATE; nothing is written
 *                unless C2D_OK.
 *   identities   mu = 0 or beta = -1: exactly c2d_collide's velocities, bit
 *                for bit, spins untouched.
 *   physics      linear momentum conserved between finite masses; angular
 *                momentum about any point when the disks touch
 *                (|b.pos - a.pos| = ra + rb); kinetic energy (with rotation,
 *                I w^2 / 2) never grows, and is kept at e = 1, beta = 1.
 *   accuracy     each velocity component and spin x radius within
 *                c2d_collide's bound plus 2 ulp of the body's scale: the
 *                largest of |vx|, |vy|, |spin radius| before and after.  The
 *                slip speed is carried in double length, so rolling contact
 *                (g_t ~ 0) at any speed stays accurate. */
c2d_status c2d_collide_rough(c2d_disk *a, c2d_disk *b, c2d_surface s);

/* As c2d_collide_rough with the contact normal given (any finite non-zero
 * vector from a towards b, as c2d_collide_normal).  For cushions and walls:
 * b.mass = b.inertia = INFINITY, b.radius = 0, normal = the wall's normal
 * pointing away from a. */
c2d_status c2d_collide_rough_normal(c2d_disk *a, c2d_disk *b, c2d_vec2 normal, c2d_surface s);

/* Pool balls as spheres on a table (lib/real/sphere.h has the derivation):
 * x, y the table's plane, z up; the centres stay on the table.  Friction
 * acts on the full 3-D slip at the contact (top and back spin too), and a
 * cushion touches the ball above its centre.  Each impact is the impulse of
 * free balls (Han 2005; Alciatore, technical proof A.14) after which the
 * cloth takes the vertical velocity away (a reaction through the centre).
 *   pos, vel  the centre's position and velocity in the table's plane
 *   spin      angular velocity (wx, wy, wz), rad per time unit, right-handed
 *             about +x, +y, +z (z up: wz > 0 counter-clockwise seen from above)
 *   mass      > 0; INFINITY = immovable (not for a cushion)
 *   radius    >= 0 and finite (> 0 for a cushion)
 *   inertia   about the centre, > 0: 2/5 m R^2 for a solid ball; INFINITY =
 *             its spin never changes */
typedef struct c2d_ball { c2d_vec2 pos, vel; double spin[3]; double mass, radius, inertia; } c2d_ball;

/* Ball-ball surface: restitution e in [0, 1]; friction
 *   mu(v) = friction + friction_boost exp(-friction_decay v),
 * v the sliding speed at the contact before the impact (|slip| in the
 * tangential plane).  friction >= 0 (INFINITY: never slides); boost and
 * decay >= 0 and finite; boost 0 = constant mu.  Alciatore's fit for
 * phenolic balls (technical proof A.14, SI units): 9.951e-3, 0.108, 1.088. */
typedef struct c2d_ball_surface { double restitution, friction, friction_boost, friction_decay; } c2d_ball_surface;

/* Resolve an impact of two balls touching at their equators (normal n^ =
 * b.pos - a.pos, horizontal).  Normal impulse exactly c2d_collide's (an
 * impact only if the normal slip speed is < 0).  Friction: against the
 * slip g = vb - va - (Ra wa + Rb wb) x n^ of b's contact point past a's,
 * in its horizontal (t^ = (-n^y, n^x)) and vertical parts, of size
 * min(mu(|g|) Jn, mt |g|), 1/mt = 1/ma + 1/mb + Ra^2/Ia + Rb^2/Ib: sliding
 * all through the impact, or until the slip stops.  The horizontal part
 * changes velocities and wz; the vertical part only wx, wy (the table takes
 * the vertical velocity).
 *   returns      C2D_OK; C2D_SEPARATING, C2D_DEGENERATE and C2D_RANGE for the
 *                normal part exactly as c2d_collide; C2D_INVALID also for a
 *                NaN/Inf spin or radius, radius < 0, inertia <= 0 or NaN, a
 *                surface field outside its range; C2D_RANGE also when an
 *                output would exceed DBL_MAX (allowed from DBL_MAX / 8 of
 *                an exact output or change, as c2d_collide's); an impulse,
 *                slip, R/I or R^2/I beyond the format is no RANGE (a
 *                double-length slow path takes such pairs).  Same
 *                priority; a == b is C2D_DEGENERATE; nothing is written
 *                unless C2D_OK.
 *   identities   friction = friction_boost = 0: c2d_collide's velocities bit
 *                for bit, spins untouched.  wx = wy = 0 (both balls) with
 *                constant mu: c2d_collide_rough with beta = 0, to this
 *                function's accuracy (tested).
 *   physics      linear momentum conserved between finite masses; each
 *                ball's angular momentum about the contact point along n^
 *                and along z^; kinetic energy with rotation (I |w|^2 / 2)
 *                never grows, kept at e = 1 without friction.
 *   accuracy     each velocity component and spin x radius within
 *                c2d_collide's bound plus 8 ulp of the PAIR's scale (the
 *                largest |vx|, |vy|, |R w| of both balls before and after;
 *                measured against a 512-bit MPFR referee, all parts in,
 *                tests/unit/test_sphere.c: worst 8.3 ulp double, 7.1 float
 *                at unit scale (pool pairs 4.4, 5.0); 5.5 and 6.0 over
 *                2^+-300 (float 2^+-30); over the whole range, every
 *                position, velocity and spin component, mass, radius and
 *                inertia at its own exponent from the smallest subnormal
 *                to the largest binade, 3.5 double, 4.2 float; sliding and
 *                sticking).  A spin whose exact value is subnormal while
 *                R w is not is held to its own rounding (no format value
 *                does better).  The friction part is plain arithmetic
 *                where no step leaves the normal range (double length
 *                otherwise): a light ball brushed by a much faster one
 *                gets an error of the fast one's scale.
 *   cost         c2d_collide's plus ~100 floating-point operations (exp
 *                adds ~40 when friction_boost != 0) and a branch-free
 *                range test of the inputs, exact products for a glancing
 *                normal speed only, double length where a step over- or
 *                underflows: 688 instructions per pool pair against 248
 *                for a plain transcription, 2.8x (make bench-sphere; the
 *                float twin 1,307: float's window, 2^+-7, holds no pool
 *                ball's inertia, so its checks run). */
c2d_status c2d_collide_balls(c2d_ball *a, c2d_ball *b, c2d_ball_surface s);

/* A cushion (rail): normal = any finite non-zero horizontal vector from the
 * ball towards the rail; height = the nose's contact height above the cloth,
 * R <= height <= 2R (0.635 D on a standard pool table, Mathavan et al.
 * 2010; h = R is a wall at the centre's height); restitution in [0, 1];
 * friction >= 0 (INFINITY: never slides) between ball and rail. */
typedef struct c2d_cushion { c2d_vec2 normal; double height, restitution, friction; } c2d_cushion;

/* Resolve a ball's impact on a still cushion.  The contact is at R nu,
 * nu = cos th n^ + sin th z^, sin th = (height - R) / R.  Normal impulse
 * Pn = (1 + e) m cos th (v.n^) along -nu (an impact only if v.n^ > 0);
 * friction against the contact point's slip in the plane perpendicular to
 * nu, of size min(mu Pn, |slip| / (1/m + R^2/I)); then the table takes the
 * vertical velocity.  Han 2005's closed form with the friction along the
 * slip (Coulomb's law); the cloth's friction during the impact is neglected
 * (as Han; Mathavan et al. 2010 integrate it).
 *   returns      C2D_OK; C2D_INVALID for NULL, a bad ball (as above; also an
 *                infinite mass or radius 0), a NaN/Inf normal, height outside
 *                [R, 2R], restitution or friction outside its range;
 *                C2D_DEGENERATE for a zero normal; C2D_SEPARATING when
 *                v.n^ <= 0 exactly (or height = 2R); C2D_RANGE when an
 *                output would exceed DBL_MAX (allowed from DBL_MAX / 8 of
 *                an exact output); an impulse, slip or R/I beyond the
 *                format is no RANGE (double length then).  Priority
 *                INVALID > DEGENERATE > SEPARATING > RANGE > OK; nothing is
 *                written unless C2D_OK.
 *   identities   height = R and wx = wy = 0: c2d_collide_rough_normal against
 *                a wall (b immovable, radius 0, beta = 0), to this
 *                function's accuracy (tested).
 *   physics      energy never grows; the ball's angular momentum about the
 *                contact point along n^ and z^ is kept.
 *   accuracy     each output within 16 ulp of the ball's scale (largest |vx|,
 *                |vy|, |R w| before and after; plain arithmetic, cos(th)
 *                from h's distance to 2R so it keeps a few u near the top;
 *                measured against the MPFR referee: worst 9.3 double, 9.0
 *                float at unit scale, 9.7 and 7.9 over 2^+-300 / 2^+-30,
 *                5.3 and 4.1 over the whole range, every field at its own
 *                exponent; a subnormal exact spin as for two balls).
 *   cost         ~70 floating-point operations, two square roots, a range
 *                test of the inputs; double length where a step over- or
 *                underflows: 424 instructions per pool rail impact (make
 *                bench-sphere; the float twin 937). */
c2d_status c2d_collide_cushion(c2d_ball *ball, c2d_cushion c);
#endif

/* ------------------------------------------------------------------- float */
#ifndef C2D_NO_FLOAT
typedef struct c2d_vec2f { float x, y; } c2d_vec2f;
typedef struct c2d_bodyf { c2d_vec2f pos; c2d_vec2f vel; float mass; } c2d_bodyf;

/* Float twins of the double functions: same semantics, statuses and
 * accuracy in ulp of float (FLT_MAX/8 for C2D_RANGE); computed in float only
 * (no double arithmetic is used or linked: suitable for single-precision FPUs
 * such as Cortex-M4F).  c2d_time_of_impactf needs sqrtf. */
c2d_status c2d_collidef(c2d_bodyf *a, c2d_bodyf *b, float restitution);
c2d_status c2d_collide_normalf(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f normal, float restitution);
c2d_status c2d_time_of_impactf(const c2d_bodyf *a, const c2d_bodyf *b, float radius_sum, float *t);
c2d_status c2d_time_of_impact_accelf(const c2d_bodyf *a, c2d_vec2f acc_a, const c2d_bodyf *b, c2d_vec2f acc_b,
                                     float radius_sum, float horizon, float *t);

typedef struct c2d_pairsf {
    const float *pos_ax, *pos_ay, *pos_bx, *pos_by;
    float *vel_ax, *vel_ay, *vel_bx, *vel_by;
    const float *mass_a, *mass_b;
} c2d_pairsf;
size_t c2d_collide_batchf(const c2d_pairsf *p, size_t count, float restitution, c2d_status *status);

typedef struct c2d_diskf { c2d_vec2f pos, vel; float spin, mass, radius, inertia; } c2d_diskf;
typedef struct c2d_surfacef { float restitution, friction, tangential_restitution; } c2d_surfacef;
c2d_status c2d_collide_roughf(c2d_diskf *a, c2d_diskf *b, c2d_surfacef s);
c2d_status c2d_collide_rough_normalf(c2d_diskf *a, c2d_diskf *b, c2d_vec2f normal, c2d_surfacef s);

typedef struct c2d_ballf { c2d_vec2f pos, vel; float spin[3]; float mass, radius, inertia; } c2d_ballf;
typedef struct c2d_ball_surfacef { float restitution, friction, friction_boost, friction_decay; } c2d_ball_surfacef;
typedef struct c2d_cushionf { c2d_vec2f normal; float height, restitution, friction; } c2d_cushionf;
c2d_status c2d_collide_ballsf(c2d_ballf *a, c2d_ballf *b, c2d_ball_surfacef s);
c2d_status c2d_collide_cushionf(c2d_ballf *ball, c2d_cushionf c);
#endif

/* ------------------------------------------------------------ Q16.16 fixed */
#ifndef C2D_NO_FIXED
/* Q16.16: value = raw / 65536.  Range [-32768, 32768 - 2^-16], step 2^-16.
 * Integer arithmetic only (int32/int64; on 32-bit cores the compiler's
 * 64-bit helpers from libgcc), no floating point at all. */
typedef int32_t c2d_fixed;
#define C2D_FIXED_ONE ((c2d_fixed)65536)
/* A mass of C2D_FIXED_INFINITE_MASS (INT32_MAX) is immovable. */
#define C2D_FIXED_INFINITE_MASS ((c2d_fixed)INT32_MAX)
typedef struct c2d_vec2x { c2d_fixed x, y; } c2d_vec2x;
typedef struct c2d_bodyx { c2d_vec2x pos; c2d_vec2x vel; c2d_fixed mass; } c2d_bodyx;

/* Q16.16 twins of c2d_collide / c2d_collide_normal.
 *   mass         > 0 (raw >= 1), or C2D_FIXED_INFINITE_MASS.
 *   restitution  in [0, C2D_FIXED_ONE].
 *   returns      the same statuses with the same priority: C2D_INVALID for
 *                mass <= 0 or restitution outside [0, 1]; C2D_SEPARATING when
 *                the approach speed rounds to less than one step (2^-16) -
 *                it is computed within the accuracy bound below, so near the
 *                range limit an approach slower than 2^-24 S may also count;
 *                C2D_RANGE when a result leaves the Q16.16 range (never wraps).
 *   accuracy     |error| <= 3 steps (3 * 2^-16) + 2^-24 x S per component,
 *                against the exact result of the same inputs, where S is the
 *                largest |velocity component| of either body before or after
 *                (the unit normal is carried in Q2.28). */
c2d_status c2d_collidex(c2d_bodyx *a, c2d_bodyx *b, c2d_fixed restitution);
c2d_status c2d_collide_normalx(c2d_bodyx *a, c2d_bodyx *b, c2d_vec2x normal, c2d_fixed restitution);

/* Q16.16 time of impact: same semantics as c2d_time_of_impact; *t in Q16.16
 * seconds, C2D_RANGE when t > 32767.  radius_sum >= 0.
 *   accuracy     |error| <= 2 steps + the time the pair needs at contact to
 *                close 2^-16 + |d| 2^-27 of distance (|d| the centre distance:
 *                beyond 2^13 units it is carried with 29 significant bits). */
c2d_status c2d_time_of_impactx(const c2d_bodyx *a, const c2d_bodyx *b, c2d_fixed radius_sum, c2d_fixed *t);
#endif

/* ----------------------------------------- opt-in inline front ends
 * #define C2D_INLINE before including this header to get
 *   c2d_collide_inline, c2d_collide_normal_inline (double) and
 *   c2d_collidef_inline, c2d_collide_normalf_inline (float):
 * static inline front ends with the library's own input-only accept test,
 * which resolve the common case at the call site and call c2d_collide (or
 * its twin) for everything else: some 0.4-0.5 kB of code per call site
 * (gcc 12 -O2, x86-64; bench/callsite.c), against 5 bytes for the call.
 * Same statuses, same bits as the library call (tests/unit/test_inline.c
 * checks it), provided the compiler evaluates them as written: no
 * -ffast-math or -ffinite-math-only (under which the compiler may drop the
 * NaN tests the accept test relies on) and no FMA contraction.  Under
 * either flag they are plain calls, right whatever the caller's flags: the
 * header neither warns nor stops (your code may want fast math, and the
 * library is compiled apart; its own build refuses the flags, see
 * C2D_ALLOW_FAST_MATH).  The header turns them on
 * (C2D_INLINE_AS_WRITTEN 1) only where it can tell: clang (the
 * functions switch contraction off themselves), gcc in strict ISO mode
 * (-std=c99, c11, c++11...: contraction off by default) or for a target
 * without FMA; elsewhere they are plain calls of the library functions.
 * One case no macro shows: -ffp-contract=fast given explicitly with -std=c99
 * on gcc for an FMA target.  Don't combine it with C2D_INLINE.
 *   Query: C2D_INLINE_AS_WRITTEN is 1 where the front ends are inline, 0
 * where they are plain calls.  Diagnostic: #define C2D_INLINE_REQUIRED as
 * well, and a translation unit whose flags would make them plain calls
 * fails to compile, with #error naming the flags that enable them.
 *   Flags that enable them: clang with any flags but -ffast-math or
 * -ffinite-math-only; gcc with -std=c99 (c11, c17, c++11...) or, in its GNU
 * modes (the default), for a target without FMA (x86-64 baseline: plain
 * `cc -O2` is inline; -march=native or -march=x86-64-v3 there is not). */
#if defined(C2D_INLINE)
#if !defined(__FAST_MATH__) && !(defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__) && (defined(__clang__) || (defined(__GNUC__) && (defined(__STRICT_ANSI__) || \
    !(defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF)))))
#define C2D_INLINE_AS_WRITTEN 1
#else
#define C2D_INLINE_AS_WRITTEN 0
#endif
#if defined(C2D_INLINE_REQUIRED) && !C2D_INLINE_AS_WRITTEN
#error "C2D_INLINE_REQUIRED: the inline front ends would be plain calls under these flags (fast math, or gcc's GNU mode on an FMA target): compile with -std=c99 (or c11, c++11) and without -ffast-math, or use clang"
#endif

#endif /* C2D_INLINE */

/* ------------------------------------------------------- the accept test
 * The one definition of the frictionless input-only accept test, for the
 * inline front ends (below) and the library's own front end (c2d_quick in
 * lib/real/collide/fast.h, which derives it: window, proof that the fast
 * path would accept, same operations in the same order).  Internal: not
 * part of the API, defined only for C2D_INLINE's front ends and for the
 * library's sources (C2D_BUILDING_LIBRARY, lib/internal.h).
 *
 * Why here, as one macro instantiated for double and float, rather than
 * generated from the template or kept in a second header: this header is
 * the one file a user installs or copies beside the amalgamation
 * (C2D_HEADER), and the library's sources already include it, so the
 * library and its users compile the very same lines, with no generator to
 * run and no freshness check to keep, and installs (make, CMake) stay one
 * file.  tests/unit/test_inline.c still checks the bits and statuses.
 *
 * C2D_ACCEPT_DEFINE_(name, real, hi, lo) defines
 *   int name(nx, ny, vax, vay, vbx, vby, fa, fb, msum, lighter, e1, out)
 * for the normal (nx, ny) from a towards b, the velocities, the masses as
 * the formula weighs them (fa, fb: the bodies' masses, or the pair (0, 1) /
 * (1, 0) for a wall), and the masses as the window sees them (msum and
 * lighter: fa + fb and the smaller, or 0 and 1 for a wall, whose window
 * leaves the masses out).  Returns C2D_ACCEPT_OK (out = {va'x, va'y, vb'x,
 * vb'y}), C2D_ACCEPT_SEPARATING, C2D_ACCEPT_UNDECIDED (inside the window,
 * d cancels) or C2D_ACCEPT_OUTSIDE (outside the window, or on an axis).
 * The window is [lo, hi] = [2^-200, 2^200] (double), [2^-20, 2^20] (float).
 * |p| is the compiler's fabs (gcc, clang), else max(p, -p); the conditions are
 * 0/1 values joined with &: one branch on all of them, not a jump per
 * condition on data the predictor cannot learn. */
#if defined(C2D_BUILDING_LIBRARY)
#define C2D_ACCEPT_WANTED_ 1
#elif defined(C2D_INLINE)
#define C2D_ACCEPT_WANTED_ C2D_INLINE_AS_WRITTEN
#else
#define C2D_ACCEPT_WANTED_ 0
#endif
#if C2D_ACCEPT_WANTED_
enum { C2D_ACCEPT_OUTSIDE = 0, C2D_ACCEPT_OK = 1, C2D_ACCEPT_SEPARATING = 2, C2D_ACCEPT_UNDECIDED = 3 };
#define C2D_ACCEPT_HI 1.6069380442589903e60  /* 2^200 */
#define C2D_ACCEPT_LO 6.2230152778611417e-61 /* 2^-200 */
#define C2D_ACCEPT_HIF 1048576.0f            /* 2^20 */
#define C2D_ACCEPT_LOF 9.5367431640625e-07f  /* 2^-20 */
#ifdef __clang__
#define C2D_ACCEPT_AS_WRITTEN_ _Pragma("clang fp contract(off)")
#else
#define C2D_ACCEPT_AS_WRITTEN_
#endif
#ifdef __GNUC__
#define C2D_ACCEPT_INLINE_ static inline __attribute__((always_inline))
#define C2D_ACCEPT_FABS_ __builtin_fabs /* one andpd; <math.h> is not assumed */
#define C2D_ACCEPT_FABSF_ __builtin_fabsf
#else
#define C2D_ACCEPT_INLINE_ static inline
#define C2D_ACCEPT_FABS_(x) ((x) > -(x) ? (x) : -(x)) /* |x| for a plain variable; NaN: a NaN */
#define C2D_ACCEPT_FABSF_(x) ((x) > -(x) ? (x) : -(x))
#endif
/* NOLINTBEGIN(bugprone-macro-parentheses): `real` and `body` are types */
#define C2D_ACCEPT_DEFINE_(name, real, fabs, hi, lo)                                                                   \
    C2D_ACCEPT_INLINE_ int name(real nx, real ny, real vax, real vay, real vbx, real vby, real fa, real fb,           \
                                real msum, real lighter, real e1, real *out)                                           \
    {                                                                                                                  \
        C2D_ACCEPT_AS_WRITTEN_                                                                                         \
        const real px = (vbx - vax) * nx, py = (vby - vay) * ny;                                                       \
        const real d = px + py, k = fabs(px) + fabs(py), nn = nx * nx + ny * ny;                                       \
        const real geometry = k < nn ? k : nn;                                                                         \
        const real least = geometry < lighter ? geometry : lighter;                                                    \
        const unsigned window = (unsigned)(nx != 0) & (unsigned)(ny != 0) & (unsigned)((k + nn) + msum <= (hi)) &      \
                                (unsigned)(least >= (lo));                                                             \
        if (window == 0u) return C2D_ACCEPT_OUTSIDE;                                                                   \
        if (4 * d + k <= 0) {                                                                                          \
            const real den = nn * (fa + fb);                                                                           \
            const real c = e1 * d / den;                                                                               \
            const real la = c * fb, lb = c * fa;                                                                       \
            out[0] = vax + la * nx;                                                                                    \
            out[1] = vay + la * ny;                                                                                    \
            out[2] = vbx - lb * nx;                                                                                    \
            out[3] = vby - lb * ny;                                                                                    \
            return C2D_ACCEPT_OK;                                                                                      \
        }                                                                                                              \
        return 4 * d - k >= 0 ? C2D_ACCEPT_SEPARATING : C2D_ACCEPT_UNDECIDED;                                          \
    }
/* NOLINTEND(bugprone-macro-parentheses) */
#ifndef C2D_NO_DOUBLE
C2D_ACCEPT_DEFINE_(c2d_accept, double, C2D_ACCEPT_FABS_, C2D_ACCEPT_HI, C2D_ACCEPT_LO)
#endif
#ifndef C2D_NO_FLOAT
C2D_ACCEPT_DEFINE_(c2d_acceptf, float, C2D_ACCEPT_FABSF_, C2D_ACCEPT_HIF, C2D_ACCEPT_LOF)
#endif

/* The inline front ends' use of it: a pair of bodies off the axes, not a
 * wall (a mass INFINITY leaves the window: the library call takes it); 1
 * with *st set when it decides (velocities written on OK). */
/* NOLINTBEGIN(bugprone-macro-parentheses): `real` and `body` are types */
#define C2D_INLINE_FRONT_DEFINE_(name, accept, real, body)                                                             \
    C2D_ACCEPT_INLINE_ int name(real nx, real ny, body *a, body *b, real e1, c2d_status *st)                           \
    {                                                                                                                  \
        real out[4];                                                                                                   \
        const int r = accept(nx, ny, a->vel.x, a->vel.y, b->vel.x, b->vel.y, a->mass, b->mass, a->mass + b->mass,      \
                             a->mass < b->mass ? a->mass : b->mass, e1, out);                                          \
        if (r == C2D_ACCEPT_OK) {                                                                                      \
            a->vel.x = out[0];                                                                                         \
            a->vel.y = out[1];                                                                                         \
            b->vel.x = out[2];                                                                                         \
            b->vel.y = out[3];                                                                                         \
            *st = C2D_OK;                                                                                              \
            return 1;                                                                                                  \
        }                                                                                                              \
        if (r == C2D_ACCEPT_SEPARATING) {                                                                              \
            *st = C2D_SEPARATING;                                                                                      \
            return 1;                                                                                                  \
        }                                                                                                              \
        return 0;                                                                                                      \
    }
/* NOLINTEND(bugprone-macro-parentheses) */
#endif /* C2D_ACCEPT_WANTED_ */

#if defined(C2D_INLINE)
#if C2D_INLINE_AS_WRITTEN && !defined(C2D_NO_DOUBLE)
C2D_INLINE_FRONT_DEFINE_(c2d_inline_front, c2d_accept, double, c2d_body)

static inline c2d_status c2d_collide_inline(c2d_body *a, c2d_body *b, double restitution)
{
    c2d_status st;
    if (a != NULL && b != NULL && restitution >= 0 && restitution <= 1 &&
        c2d_inline_front(b->pos.x - a->pos.x, b->pos.y - a->pos.y, a, b, 1 + restitution, &st))
        return st;
    return c2d_collide(a, b, restitution);
}

static inline c2d_status c2d_collide_normal_inline(c2d_body *a, c2d_body *b, c2d_vec2 normal, double restitution)
{
    c2d_status st;
    if (a != NULL && b != NULL && a != b && restitution >= 0 && restitution <= 1 &&
        ((a->pos.x - a->pos.x) + (a->pos.y - a->pos.y)) + ((b->pos.x - b->pos.x) + (b->pos.y - b->pos.y)) == 0 &&
        c2d_inline_front(normal.x, normal.y, a, b, 1 + restitution, &st))
        return st;
    return c2d_collide_normal(a, b, normal, restitution);
}
#elif !defined(C2D_NO_DOUBLE)
static inline c2d_status c2d_collide_inline(c2d_body *a, c2d_body *b, double restitution)
{
    return c2d_collide(a, b, restitution);
}

static inline c2d_status c2d_collide_normal_inline(c2d_body *a, c2d_body *b, c2d_vec2 normal, double restitution)
{
    return c2d_collide_normal(a, b, normal, restitution);
}
#endif

#if C2D_INLINE_AS_WRITTEN && !defined(C2D_NO_FLOAT)
C2D_INLINE_FRONT_DEFINE_(c2d_inline_frontf, c2d_acceptf, float, c2d_bodyf)

static inline c2d_status c2d_collidef_inline(c2d_bodyf *a, c2d_bodyf *b, float restitution)
{
    c2d_status st;
    if (a != NULL && b != NULL && restitution >= 0 && restitution <= 1 &&
        c2d_inline_frontf(b->pos.x - a->pos.x, b->pos.y - a->pos.y, a, b, 1 + restitution, &st))
        return st;
    return c2d_collidef(a, b, restitution);
}

static inline c2d_status c2d_collide_normalf_inline(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f normal, float restitution)
{
    c2d_status st;
    if (a != NULL && b != NULL && a != b && restitution >= 0 && restitution <= 1 &&
        ((a->pos.x - a->pos.x) + (a->pos.y - a->pos.y)) + ((b->pos.x - b->pos.x) + (b->pos.y - b->pos.y)) == 0 &&
        c2d_inline_frontf(normal.x, normal.y, a, b, 1 + restitution, &st))
        return st;
    return c2d_collide_normalf(a, b, normal, restitution);
}
#elif !defined(C2D_NO_FLOAT)
static inline c2d_status c2d_collidef_inline(c2d_bodyf *a, c2d_bodyf *b, float restitution)
{
    return c2d_collidef(a, b, restitution);
}

static inline c2d_status c2d_collide_normalf_inline(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f normal, float restitution)
{
    return c2d_collide_normalf(a, b, normal, restitution);
}
#endif
#endif /* C2D_INLINE */

#ifdef __cplusplus
}
#endif
#endif /* COLLIDE2D_H */
