/* SPDX-License-Identifier: MIT */
/* Box2D 2.4.1's own contact solver as a contender: one b2World holding two
 * circles, restitution e, restitution threshold 0, no friction, no gravity,
 * warm starting off; each collision places the two disks touching with the
 * given positions, velocities and masses and runs exactly one Step. */
#ifndef C2D_BENCH_BOX2D_H
#define C2D_BENCH_BOX2D_H

#include "collide2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Create / destroy the world the contender reuses (one per process). */
void bench_box2d_init(void);
void bench_box2d_fini(void);

/* C2D_OK if Box2D changed a velocity, C2D_SEPARATING if it left both alone. */
c2d_status bench_box2d(c2d_body *a, c2d_body *b, double restitution);

#ifdef __cplusplus
}
#endif
#endif
