/* SPDX-License-Identifier: MIT */
/* The filter in front of the exact rounding of axis-aligned impacts, double
 * (body in axis_filter.h): the library's templates instantiated here with
 * lib/double.c's parameters (lib/real/double.h), so the filter's decisions can
 * be counted. */
/* internal.h first: it asks the public header for the internals it shares
 * with the library (C2D_BUILDING_LIBRARY), which check.h's include of it
 * would otherwise leave out (include guard). */
#include "../../lib/internal.h"
#include "check.h"

#pragma GCC diagnostic ignored "-Wunused-function" /* the templates hold more than the filter */

#include "../../lib/real/double.h"

#define FILTER_FLOAT 0
#include "axis_filter.h"
