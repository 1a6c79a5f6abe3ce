/* SPDX-License-Identifier: MIT */
/* double.c - the double-precision API: binary64's parameters, the shared
 * templates instantiated for it (real/, derivations there), and the
 * public functions written out by name.  C2D_NO_DOUBLE leaves it empty. */
#include "internal.h"

#ifndef C2D_NO_DOUBLE

#include "real/double.h"

c2d_status c2d_collide(c2d_body *a, c2d_body *b, double restitution)
{
    return c2d_real_collide(a, b, restitution);
}

/* The normal as two scalars (real/collide/collide.h, c2d_collide_normal_front):
 * by address, gcc passes the 16-byte c2d_vec2 through memory; and its
 * fields taken in registers (C2D_IN_REGISTER, internal.h), since gcc -O3
 * otherwise stores the argument and reloads it as one vector. */
c2d_status c2d_collide_normal(c2d_body *a, c2d_body *b, c2d_vec2 normal, double restitution)
{
    double nx = normal.x;
    double ny = normal.y;
    C2D_IN_REGISTER(nx);
    C2D_IN_REGISTER(ny);
    return c2d_collide_normal_front(a, b, nx, ny, restitution);
}

c2d_status c2d_time_of_impact(const c2d_body *a, const c2d_body *b, double radius_sum, double *t)
{
    return c2d_real_time_of_impact(a, b, radius_sum, t);
}

size_t c2d_collide_batch(const c2d_pairs *p, size_t count, double restitution, c2d_status *status)
{
    return c2d_real_collide_batch(p, count, restitution, status);
}

c2d_status c2d_collide_rough(c2d_disk *a, c2d_disk *b, c2d_surface s)
{
    return c2d_real_collide_rough(a, b, NULL, &s);
}

c2d_status c2d_collide_rough_normal(c2d_disk *a, c2d_disk *b, c2d_vec2 normal, c2d_surface s)
{
    return c2d_real_collide_rough(a, b, &normal, &s);
}

c2d_status c2d_collide_balls(c2d_ball *a, c2d_ball *b, c2d_ball_surface s)
{
    return c2d_real_collide_balls(a, b, &s);
}

c2d_status c2d_collide_cushion(c2d_ball *ball, c2d_cushion c)
{
    return c2d_real_collide_cushion(ball, &c);
}

c2d_status c2d_time_of_impact_accel(const c2d_body *a, c2d_vec2 acc_a, const c2d_body *b, c2d_vec2 acc_b,
                                    double radius_sum, double horizon, double *t)
{
    return c2d_toia_solve(a, &acc_a, b, &acc_b, radius_sum, horizon, t);
}

#ifndef C2D_NO_WORLD
/* The world's by-address forms of three of the above (internal.h). */
c2d_status c2d_collide_normal_by_ref(c2d_body *a, c2d_body *b, const c2d_vec2 *normal, double restitution)
{
    return c2d_real_collide_normal(a, b, normal, restitution);
}

c2d_status c2d_collide_rough_by_ref(c2d_disk *a, c2d_disk *b, const c2d_vec2 *normal, const c2d_surface *s)
{
    return c2d_real_collide_rough(a, b, normal, s);
}

c2d_status c2d_time_of_impact_accel_by_ref(const c2d_body *a, const c2d_vec2 *acc_a, const c2d_body *b,
                                           const c2d_vec2 *acc_b, double radius_sum, double horizon, double *t)
{
    return c2d_toia_solve(a, acc_a, b, acc_b, radius_sum, horizon, t);
}
#endif /* C2D_NO_WORLD */

#endif /* C2D_NO_DOUBLE */
