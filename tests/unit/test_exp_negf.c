/* SPDX-License-Identifier: MIT */
/* c2d_exp_neg (lib/real/sphere.h), the freestanding exp(-x) behind the
 * speed-dependent ball-ball friction: the float instance against mpfr_exp
 * (the body: exp_neg_check.h). */
#include "../../lib/internal.h" /* first: it asks the header for the library's internals */
#include "check.h"

#pragma GCC diagnostic ignored "-Wunused-function" /* the templates hold more than exp */

#include "../../lib/real/float.h"

#define EXP_PREC 24
#define EXP_NAME "exp_negf"
#include "exp_neg_check.h"
