/* SPDX-License-Identifier: MIT */
/* world.c - the event-driven world of disks (include/collide2d_world.h),
 * one translation unit over the parts in lib/world/.
 *
 * State: each disk keeps (x, y, vx, vy, ax, ay, t) from its last change of
 * motion (an impact, a caller's call, the rebase of a periodic box), so
 * its position at any time is x + (vx + ax (s - t) / 2) (s - t): advancing
 * the world moves nothing, and the same events give the same bits however
 * the caller slices time.
 *
 * Events: one pending event per disk (its earliest: an impact, a wall, a
 * static, a sensor, leaving its cell or its broadphase box, its timer) in
 * a calendar queue (queue.h) ordered by (time, tie), tie = kind << 62 |
 * lower index << 31 | higher index.  An impact remembers its partner's
 * counter when predicted; if the partner's motion has changed since, the
 * event is stale and the disk predicts again.  Correctness of one event
 * per disk: whenever a disk's motion changes it predicts against all its
 * candidates, so every pair whose next contact is earlier than both
 * disks' own events is held by one of them.
 *
 * Determinism: a pair's time comes from a canonical frame (both disks at
 * the later of their state times, the lower index first, the nearest image
 * there; predict.h), a wall's, a static's and a sensor's from the disk's
 * own state, so no prediction depends on when or by whom it is made: the
 * broadphase (the built-in cells, cells.h and grid.h, or the caller's)
 * changes no bit.
 *
 * Contacts (resolve.h): the model's call (c2d_collide, c2d_collide_normal,
 * or c2d_collide_rough(_normal) with spins) or the caller's resolver,
 * guarded; the collapse rule for e < 1; the rest rules for disks pressed
 * into a wall or into each other by their accelerations.
 */
#include "internal.h"

#if !defined(C2D_NO_DOUBLE) && !defined(C2D_NO_WORLD)

#ifndef C2D_WORLD_HEADER
#define C2D_WORLD_HEADER "../include/collide2d_world.h"
#endif
#include C2D_WORLD_HEADER

/* The parts, in the order their definitions need. */
#include "world/state.h"
#include "world/layout.h"
#include "world/queue.h"
#include "world/cells.h"
#include "world/predict.h"
#include "world/grid.h"
#include "world/add.h"
#include "world/resolve.h"
#include "world/events.h"
#include "world/calls.h"

#endif /* !C2D_NO_DOUBLE && !C2D_NO_WORLD */
