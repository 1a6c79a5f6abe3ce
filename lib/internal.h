/* SPDX-License-Identifier: MIT */
/* internal.h - what every translation unit of the library shares: the public
 * header, the compiler hints, and the fast path's internal verdicts.
 *
 * The library is one translation unit per variant (collide2d.c: version and
 * status names; double.c, float.c: the floating-point API; fixed.c: Q16.16).
 * double.c and float.c include real/double.h and real/float.h, which define
 * their type's parameters (C2D_R_*) and include the same template headers
 * (real/), written once against the names c2d_real, c2d_real_body, ...;
 * every static function they define is local to its translation unit, so
 * both instances use the same names and every public function is written
 * out by name in double.c and float.c.
 */
#ifndef C2D_INTERNAL_H
#define C2D_INTERNAL_H

/* The header's internal definitions the library shares with its inline
 * front ends (the accept test, real/collide/fast.h). */
#define C2D_BUILDING_LIBRARY 1
#ifdef C2D_HEADER
#include C2D_HEADER
#else
#include "../include/collide2d.h"
#endif
#ifndef C2D_ACCEPT_HI
#error "collide2d.h was included before lib/internal.h, so without the accept test the library needs: include internal.h first (a white-box test too)"
#endif
#include <float.h>

/* The time of impact's square roots.  gcc and clang get the FPU instruction
 * through __builtin_sqrt (with -fno-math-errno); other compilers call the C
 * library, declared here rather than through <math.h>, which a freestanding
 * build does not have. */
#ifndef __GNUC__
#ifndef C2D_NO_DOUBLE
double sqrt(double x);
#endif
#ifndef C2D_NO_FLOAT
float sqrtf(float x);
#endif
#endif

/* C2D_SMALL: code size before speed, on by default where the compiler
 * optimises for size (-Os, -Oz: gcc's and clang's __OPTIMIZE_SIZE__), 0 or 1
 * to choose.  The same bits either way: it only drops routes that repeat
 * another's arithmetic (real/collide/collide.h: the front end's accept test
 * before the fast path that gives the same answer, tier 2's copy without the
 * window checks) and lets the compiler decide what to inline (C2D_HOT), so a
 * firmware linking c2d_collidef carries each tier once (docs/SIZES.md). */
#ifndef C2D_SMALL
#ifdef __OPTIMIZE_SIZE__
#define C2D_SMALL 1
#else
#define C2D_SMALL 0
#endif
#endif

/* The fast path must inline into each caller: called, it passes a dozen
 * floating values, more than the registers hold, and costs a third of the
 * work.  The cold tiers stay out of line so the fast path keeps no frame.
 * Optimising for size (C2D_SMALL), the compiler chooses. */
#if defined(__GNUC__) && !C2D_SMALL
#define C2D_HOT static inline __attribute__((always_inline))
#define C2D_COLD static __attribute__((noinline))
#elif defined(__GNUC__)
#define C2D_HOT static inline
#define C2D_COLD static __attribute__((noinline))
#else
#define C2D_HOT static inline
#define C2D_COLD static
#endif

/* C2D_IN_REGISTER(x): x, a double or float variable, is in an SSE register
 * here, as far as the compiler knows computed by the (empty) asm.  A
 * struct parameter's fields taken this way are cut from the struct's
 * memory: gcc 12 -O3 otherwise stores a by-value c2d_vec2 argument,
 * which arrives in two registers, to the stack as two 8-byte halves and
 * reads it back as one 16-byte vector, a load the store buffer cannot
 * forward (real/collide/collide.h, c2d_collide_normal_front; docs/SPEED.md).
 * No instruction; x86-64 gcc and clang only ("x" is their SSE register
 * constraint), elsewhere nothing. */
#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE2__)
#define C2D_IN_REGISTER(x) __asm__("" : "+x"(x))
#else
#define C2D_IN_REGISTER(x) ((void)0)
#endif

/* The library's arithmetic is IEEE-754's as written: NaN fails every
 * comparison (that is how the fast path refuses NaN and Inf inputs), x - x
 * is 0 only for finite x, and the exact sums rely on every rounding being
 * where the source puts it.  -ffast-math and -ffinite-math-only take all of
 * that away (C2D_OK with NaN outputs, NaN and Inf inputs
 * accepted, wrong statuses), so they stop the build here, unless the
 * builder says with C2D_ALLOW_FAST_MATH that wrong results are acceptable
 * (include/collide2d.h, CONFIGURATION).  -fassociative-math,
 * -freciprocal-math and -fno-signed-zeros alone define no macro and cannot
 * be caught: don't use them for lib/ either. */
#if (defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)) && \
    !defined(C2D_ALLOW_FAST_MATH)
#error "collide2d: lib/ must not be built with -ffast-math or -ffinite-math-only: its NaN/Inf checks and exact arithmetic need IEEE-754 semantics (else C2D_OK with NaN outputs, NaN/Inf inputs accepted, wrong statuses). Build lib/ without them (your own code may keep them), or define C2D_ALLOW_FAST_MATH to accept wrong results."
#endif

/* Built with ThreadSanitizer (gcc: __SANITIZE_THREAD__; clang:
 * __has_feature(thread_sanitizer)): no run-time dispatch.  gcc instruments
 * target_clones' ifunc resolver, which the loader runs while it relocates
 * the program, before the TSan run time exists: any program that links
 * the library segfaulted before main (tests/build/tsan.sh).  ASan and UBSan
 * instrument the resolver harmlessly (checked with gcc 12), and gcc has no
 * MSan; clang does not dispatch (below). */
#if defined(__SANITIZE_THREAD__)
#define C2D_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define C2D_TSAN 1
#endif
#endif

/* Run-time dispatch (real/collide/batch.h: gcc's target_clones, an ifunc resolved
 * by the loader; real/collide/collide.h: the FMA tier): only gcc on hosted x86-64
 * ELF builds, off with C2D_NO_DISPATCH, never in freestanding or MCU
 * builds nor under ThreadSanitizer (C2D_TSAN, above).  Not clang: clang 14
 * gives a static function's target_clones resolver a global name, so
 * double.c's and float.c's kernels would clash at link time. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__) && \
    defined(__STDC_HOSTED__) && __STDC_HOSTED__ == 1 && !defined(C2D_NO_DISPATCH) && !defined(C2D_TSAN)
#define C2D_DISPATCH 1
#endif

/* The world's way into double.c (lib/world.c is a translation unit of its
 * own): the public calls that take a c2d_vec2 or c2d_surface by value, with
 * it by address instead, the same code and bits.  gcc -Os copies a struct
 * argument of 16 bytes or more with a memcpy call on Cortex-M0 and RV32, and
 * the library calls no C library (tests/mcu/sizes.sh fails on it).  Hidden
 * where the object format allows, so not in the shared library's ABI;
 * sizes.sh leaves hidden functions out of the size table. */
#if defined(__GNUC__) && defined(__ELF__)
#define C2D_LIBRARY_ONLY __attribute__((visibility("hidden")))
#else
#define C2D_LIBRARY_ONLY
#endif
#if !defined(C2D_NO_DOUBLE) && !defined(C2D_NO_WORLD)
C2D_LIBRARY_ONLY c2d_status c2d_collide_normal_by_ref(c2d_body *a, c2d_body *b, const c2d_vec2 *normal,
                                                      double restitution);
C2D_LIBRARY_ONLY c2d_status c2d_collide_rough_by_ref(c2d_disk *a, c2d_disk *b, const c2d_vec2 *normal,
                                                     const c2d_surface *s);
C2D_LIBRARY_ONLY c2d_status c2d_time_of_impact_accel_by_ref(const c2d_body *a, const c2d_vec2 *acc_a,
                                                            const c2d_body *b, const c2d_vec2 *acc_b,
                                                            double radius_sum, double horizon, double *t);
#endif

/* What the fast path (and tier 2) concluded.  Internal only: never mixed
 * with the public c2d_status; c2d_verdict_status (real/collide/fast.h) converts the
 * final ones. */
typedef enum c2d_verdict {
    C2D_VERDICT_OK,         /* resolved: the results are ready */
    C2D_VERDICT_SEPARATING, /* valid, not approaching */
    C2D_VERDICT_RANGE,      /* valid, a result overflows */
    C2D_VERDICT_ACCURATE,   /* valid and in the window, but d cancels: recompute d in double-double */
    C2D_VERDICT_GENERAL,    /* outside the window: validate in full and take the general path */
    C2D_VERDICT_AXIS        /* the normal has a zero component: correctly rounded (real/collide/axis.h) */
} c2d_verdict;

/* "No exponent": the exponent reported for a zero vector (int is >= 16 bits;
 * real exponents stay within +-2300). */
enum { C2D_NO_EXP = -32767 };

#endif /* C2D_INTERNAL_H */
