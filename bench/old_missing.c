/* SPDX-License-Identifier: MIT */
/* Stand-in for the old library when its sources cannot be had (a tree
 * without git history): the same names, renamed old_* like the real one
 * (bench/bench.mk), every call refusing.  c2d_version() == 0 tells the
 * benchmark to leave the before/after table out. */
#include "collide2d.h"

long c2d_version(void) { return 0; }

c2d_status c2d_collide(c2d_body *a, c2d_body *b, double restitution)
{
    (void)a, (void)b, (void)restitution;
    return C2D_INVALID;
}

c2d_status c2d_collide_normal(c2d_body *a, c2d_body *b, c2d_vec2 normal, double restitution)
{
    (void)a, (void)b, (void)normal, (void)restitution;
    return C2D_INVALID;
}

c2d_status c2d_time_of_impact(const c2d_body *a, const c2d_body *b, double radius_sum, double *t)
{
    (void)a, (void)b, (void)radius_sum, (void)t;
    return C2D_INVALID;
}

size_t c2d_collide_batch(const c2d_pairs *p, size_t count, double restitution, c2d_status *status)
{
    (void)p, (void)count, (void)restitution, (void)status;
    return 0;
}

c2d_status c2d_collidef(c2d_bodyf *a, c2d_bodyf *b, float restitution)
{
    (void)a, (void)b, (void)restitution;
    return C2D_INVALID;
}

c2d_status c2d_collide_normalf(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f normal, float restitution)
{
    (void)a, (void)b, (void)normal, (void)restitution;
    return C2D_INVALID;
}

c2d_status c2d_time_of_impactf(const c2d_bodyf *a, const c2d_bodyf *b, float radius_sum, float *t)
{
    (void)a, (void)b, (void)radius_sum, (void)t;
    return C2D_INVALID;
}

size_t c2d_collide_batchf(const c2d_pairsf *p, size_t count, float restitution, c2d_status *status)
{
    (void)p, (void)count, (void)restitution, (void)status;
    return 0;
}
