/* SPDX-License-Identifier: MIT */
/* float.c - the single-precision API: binary32's parameters, the shared
 * templates instantiated for it (real/, derivations there), and the
 * public functions written out by name.  Float arithmetic only: nothing here
 * uses or links double, so single-precision FPUs (Cortex-M4F) run it in
 * hardware.  C2D_NO_FLOAT leaves it empty. */
#include "internal.h"

#ifndef C2D_NO_FLOAT

#include "real/float.h"

c2d_status c2d_collidef(c2d_bodyf *a, c2d_bodyf *b, float restitution)
{
    return c2d_real_collide(a, b, restitution);
}

/* The normal by address, unlike double.c: gcc inlines the whole front end
 * here, and the 8-byte c2d_vec2f forwards from the store to its loads;
 * given as two floats, gcc unpacks them through an integer register. */
c2d_status c2d_collide_normalf(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f normal, float restitution)
{
    return c2d_real_collide_normal(a, b, &normal, restitution);
}

c2d_status c2d_time_of_impactf(const c2d_bodyf *a, const c2d_bodyf *b, float radius_sum, float *t)
{
    return c2d_real_time_of_impact(a, b, radius_sum, t);
}

size_t c2d_collide_batchf(const c2d_pairsf *p, size_t count, float restitution, c2d_status *status)
{
    return c2d_real_collide_batch(p, count, restitution, status);
}

c2d_status c2d_collide_roughf(c2d_diskf *a, c2d_diskf *b, c2d_surfacef s)
{
    return c2d_real_collide_rough(a, b, NULL, &s);
}

c2d_status c2d_collide_rough_normalf(c2d_diskf *a, c2d_diskf *b, c2d_vec2f normal, c2d_surfacef s)
{
    return c2d_real_collide_rough(a, b, &normal, &s);
}

c2d_status c2d_collide_ballsf(c2d_ballf *a, c2d_ballf *b, c2d_ball_surfacef s)
{
    return c2d_real_collide_balls(a, b, &s);
}

c2d_status c2d_collide_cushionf(c2d_ballf *ball, c2d_cushionf c)
{
    return c2d_real_collide_cushion(ball, &c);
}

c2d_status c2d_time_of_impact_accelf(const c2d_bodyf *a, c2d_vec2f acc_a, const c2d_bodyf *b, c2d_vec2f acc_b,
                                    float radius_sum, float horizon, float *t)
{
    return c2d_toia_solve(a, &acc_a, b, &acc_b, radius_sum, horizon, t);
}

#endif /* C2D_NO_FLOAT */
