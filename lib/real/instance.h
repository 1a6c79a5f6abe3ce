/* SPDX-License-Identifier: MIT */
/* instance.h - the shared templates in the order they build on each other,
 * instantiated for the format whose parameters (C2D_R_*) the includer has
 * defined: double.h and float.h, beside this file.  The one list of them, so
 * a template added here reaches both formats (and the amalgamation).
 *
 *   arith/    numbers: bits and extended exponents, exact sums and products,
 *             exact signs, correctly rounded quotients, double length
 *   collide/  the frictionless collision: fast path, general path, tiers,
 *             axis-aligned impacts, the batch kernel
 *   toi.h     the time of impact;  rough.h  rough disks;  sphere.h  pool
 *             balls (3-D spin, cushions above the centre)
 *   toia/     the time of impact under constant acceleration (README.md)
 *
 * No include guard of its own: each format includes it once. */

#include "arith/bits.h"
#include "arith/exact.h"
#include "arith/sign.h"
#include "arith/round.h"
#include "collide/fast.h"
#include "collide/general.h"
#include "collide/collide.h"
#include "collide/axis.h"
#include "collide/batch.h"
#include "toi.h"
#include "arith/dd.h"
#include "rough.h"
#include "sphere.h"
#include "toia/num.h"
#include "toia/problem.h"
#include "toia/eval.h"
#include "toia/newton.h"
#include "toia/turns.h"
#include "toia/scan.h"
#include "toia/solve.h"
