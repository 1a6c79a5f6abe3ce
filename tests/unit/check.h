/* SPDX-License-Identifier: MIT */
/* cmocka glue shared by the test programs: includes in the order cmocka
 * needs, plus the comparisons cmocka 1.1.5 lacks. */
#ifndef C2D_CHECK_H
#define C2D_CHECK_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "collide2d.h"
#include "cases.h"
#include "harness.h"
#include "referee.h"

/* |got - want| <= tol, printing both on failure (cmocka has no double compare). */
#define assert_close(got, want, tol)                                                          \
    do {                                                                                      \
        double got_ = (got), want_ = (want), tol_ = (tol);                                   \
        if (!(fabs(got_ - want_) <= tol_)) {                                                  \
            print_error("%s = %.17g, want %.17g (tolerance %.3g)\n", #got, got_, want_, tol_); \
            fail();                                                                           \
        }                                                                                     \
    } while (0)

#define assert_status(got, want)                                                            \
    do {                                                                                    \
        c2d_status g_ = (got), w_ = (want);                                                 \
        if (g_ != w_) {                                                                     \
            print_error("status %s, want %s\n", c2d_status_string(g_), c2d_status_string(w_)); \
            fail();                                                                         \
        }                                                                                   \
    } while (0)

#define assert_bits_equal(a, b) assert_memory_equal(&(a), &(b), sizeof(a))

#endif
