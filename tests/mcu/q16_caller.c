/* SPDX-License-Identifier: MIT */
/* `make cross` links this with -nostdlib -lgcc against the library built with
 * C2D_NO_DOUBLE and C2D_NO_FLOAT: the link succeeding is the proof that the
 * Q16.16 path needs nothing but the compiler's own runtime on a Cortex-M0. */
#include "collide2d.h"

int c2d_q16_entry(void);

int c2d_q16_entry(void)
{
    c2d_bodyx a = {{0, 0}, {C2D_FIXED_ONE, 0}, C2D_FIXED_ONE};
    c2d_bodyx b = {{C2D_FIXED_ONE, 0}, {0, 0}, C2D_FIXED_INFINITE_MASS};
    c2d_vec2x n = {C2D_FIXED_ONE, 0};
    c2d_fixed t = 0;
    int s = (int)c2d_time_of_impactx(&a, &b, C2D_FIXED_ONE / 2, &t);
    s += (int)c2d_collidex(&a, &b, C2D_FIXED_ONE);
    s += (int)c2d_collide_normalx(&a, &b, n, C2D_FIXED_ONE);
    return s + (int)c2d_version() + (int)c2d_status_string(C2D_OK)[0] + (int)t;
}
