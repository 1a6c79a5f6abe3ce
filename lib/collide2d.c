/* SPDX-License-Identifier: MIT */
/* collide2d.c - what does not depend on a number format: the version and the
 * names of the statuses.  The collisions live in double.c, float.c and
 * fixed.c; docs/METHOD.md derives them. */
#include "internal.h"

long c2d_version(void) { return C2D_VERSION; }

const char *c2d_status_string(c2d_status status)
{
    switch (status) {
    case C2D_OK: return "ok";
    case C2D_SEPARATING: return "separating";
    case C2D_DEGENERATE: return "degenerate";
    case C2D_INVALID: return "invalid";
    case C2D_RANGE: return "range";
    default: return "unknown";
    }
}
