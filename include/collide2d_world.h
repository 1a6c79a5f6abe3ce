/* SPDX-License-Identifier: MIT */
/* collide2d_world.h - an event-driven world of hard disks on collide2d.
 * C99, double precision, no allocation (the caller gives the memory), no
 * globals, freestanding (only sqrt).
 *
 * WHAT IT DOES
 *   Disks move in straight lines in a rectangular box [0, width) x
 *   [0, height) with walls or periodic boundaries.  The world jumps from one
 *   event to the next, exactly in time order: a disk-disk impact (predicted
 *   by c2d_time_of_impact, resolved by c2d_collide: frictionless, one
 *   coefficient of restitution), a disk meeting a wall (the velocity's
 *   normal component negated and multiplied by the wall restitution), or a
 *   disk's centre crossing into another cell of the world's own broadphase
 *   (or leaving its box in a broadphase the caller supplies, see
 *   c2d_world_broadphase).
 *   Nothing is integrated with a time step: between events every disk's
 *   motion is exact, and the state at any time is computed from the disk's
 *   last event.  A disk may have a constant acceleration (a parabola
 *   between events: a ball decelerating on cloth) and a timer (an event at
 *   which the caller changes its motion); static segments and circles, each
 *   with its own restitution, stand in the box (a table's cushions), and
 *   sensors report a centre entering a circle (its pockets).  Contacts are
 *   frictionless by default, rough disks with spin (c2d_collide_rough) as
 *   a choice, or resolved by the caller's own function per contact kind
 *   (a pool ball's 3-D spin), guarded so that no resolver can hang the
 *   world or put a NaN in it.
 *
 * EXAMPLE
 *   c2d_world_desc d = {0};
 *   c2d_world *w;
 *   static double mem[4096];                     // 8-byte aligned
 *   c2d_body a = {{1, 1}, {1, 0}, 1}, b = {{3, 1}, {0, 0}, 1};
 *   size_t ia, ib;
 *   d.capacity = 2, d.width = 10, d.height = 2, d.boundary = C2D_WALLS;
 *   d.restitution = 1, d.wall_restitution = 1;
 *   if (c2d_world_bytes(&d) <= sizeof mem && c2d_world_init(&w, mem, sizeof mem, &d) == C2D_OK) {
 *       c2d_world_add(w, &a, 0.5, &ia);
 *       c2d_world_add(w, &b, 0.5, &ib);
 *       c2d_world_advance(w, 2.0);              // they meet at t = 1
 *       c2d_world_get(w, ib, &b);               // b.vel == (1, 0), b.pos == (4, 1)
 *   }
 *
 * CONVENTIONS
 *   - Units: any consistent ones (lengths, times, masses; velocities are
 *     length per time).  Masses finite and > 0, radii finite and > 0.
 *   - A disk lies inside the box: with walls radius <= x <= width - radius
 *     (and the same in y); periodic: 0 <= x < width.  Disks may touch
 *     (distance == sum of radii) but not overlap.  Touching disks that
 *     approach collide at once (time of impact 0): Newton's cradle works.
 *   - Periodic boundaries: the pair's relative position is the nearest
 *     image (at the later of the two disks' state times: Determinism below),
 *     and width, height >= 3 x the largest diameter (x (1 + 2^-24)).  A
 *     disk's stored state is moved on (rebased: its position and velocity
 *     there become its reference, in [0, width) x [0, height)) at its
 *     impacts and whenever its centre has gone 1/24 of the box's smaller
 *     side from its reference, an event of its own (kind of a crossing):
 *     then the nearest image then is the image of any contact.
 *   - Every function returns C2D_INVALID for a NULL pointer, NaN or Inf in
 *     any input, a mass or radius <= 0, a disk outside the box or overlapping
 *     another, a time before the world's time, too small or misaligned a
 *     buffer, a full world; on any status but C2D_OK nothing is written
 *     (the world's memory is unchanged bit for bit).  Impacts themselves
 *     never fail: a pair that c2d_collide finds separating (a graze) is
 *     left alone, and a time of impact beyond DBL_MAX is no event.
 *   - Accuracy: each impact is c2d_collide's (energy and momentum to a few
 *     ulp; a gas at e = 1 keeps its energy to ~1e-15 relative over 10^5
 *     impacts); times are c2d_time_of_impact's from positions rounded once
 *     per extrapolation, so disks may overlap by rounding (a few ulp of
 *     their coordinates; an overlapping, approaching pair meets at once).
 *     Times are absolute doubles: a world run to time T resolves events
 *     ulp(T) apart.
 *   - Indices are given in order of addition from 0.
 *   - Determinism: the same calls give the same bits (events, states,
 *     statistics) on every target that evaluates double as double without
 *     FMA contraction (see collide2d.h).  Frame independence: advancing in
 *     one call or in many uneven ones gives the same bits; c2d_world_get
 *     extrapolates without storing anything.  A pair's time of impact
 *     depends only on the two disks' stored states, not on when or by
 *     which disk it is predicted: both are extrapolated to t0, the later
 *     of their two state times (each x + v s, s its age at t0; with
 *     accelerations the formula of c2d_world_set_acceleration), the
 *     relative position and velocity (higher index minus lower) taken at
 *     the nearest image by a fixed rule (each component shifted by the
 *     side when beyond half of it), and the time is t0 plus
 *     c2d_time_of_impact of that relative state (c2d_time_of_impact_accel
 *     of the two disks at t0, lower index first, for curved paths),
 *     exactly; a time rounded before the world's is the world's.  Walls
 *     and statics are met at times computed from the disk's own reference
 *     state.  So the broadphase (the built-in cells or the caller's) and
 *     its events (crossings, boxes left) change no bit of any impact or
 *     state: tests/unit/test_world.c runs the same scenes with both.  The
 *     world's statistics count events of every kind, so stats.events
 *     depends on the broadphase (collisions, wall_collisions and virial do
 *     not).
 *   - Simultaneous events are processed in the order: time, then kind
 *     (disk-disk impact, then wall or static, then a crossing: a cell
 *     crossed, a rebase or a box left, then timer), then the lower
 *     disk index, then the higher (for a wall or a crossing: x before y,
 *     low side before high side).  A pair is always resolved with the lower
 *     index as c2d_collide's a.  An impact at time t changes the disks'
 *     velocities at t; touching disks that approach then meet at once, so
 *     a chain of contacts is resolved one impact after the other at the
 *     same t (Newton's cradle: N - 1 impacts for N disks).
 *   - Inelastic collapse (restitution < 1): a cluster closing in can need
 *     infinitely many impacts in finite time.  An impact (disk-disk, or a
 *     disk with a wall of wall_restitution < 1) is resolved as elastic
 *     (e = 1) when
 *       - either disk has already had collapse_count impacts (default 16)
 *         at the very same time (the same double), or
 *       - the pair closed less than collapse_length since either disk's
 *         previous impact (approach speed x time since; default 2^-20 of
 *         the smaller radius: scale-free, and far below a gas's mean free
 *         path), or
 *       - either disk's previous impact was less than collapse_time ago
 *         (the "TC model" of Luding and McNamara, 1998; default none), or
 *       - they approach slower than collapse_speed (default none).
 *     tests/unit/test_world.c measures the effect: a dense gas at e = 0.2
 *     cools to 5e-5 to 9e-5 of its energy by t = 200 under each rule, with
 *     10^4 to 3 x 10^4 impacts; without a rule it stalls in clusters.
 *
 * ACCELERATION (c2d_world_set_acceleration, c2d_world_set_timer)
 *   - A wall, a cell side or a box side is met at the root of a quadratic, computed
 *     without cancellation (q = -(B + sign(B) sqrt(D)) / 2; roots q / A and
 *     C / q) from the disk's reference state, so the same state gives the
 *     same time whenever it is predicted.  Near a tangency the rounding of
 *     D decides: a path passing a wall by less than a few ulp of the
 *     coordinates may be taken as a touch (no event: the centre is then
 *     within those ulp beyond radius of the wall) or the reverse (an event
 *     with normal speed ~0).  A cell side so missed or taken is harmless:
 *     cells are 2^-24 of a diameter wider than needed, a caller's boxes
 *     2^-20 of their half-size.
 *   - Resting on a wall: at a wall event with the acceleration's normal
 *     component a_n pressing into the wall and the rebound (e vn after
 *     the wall restitution and the collapse rule) rising less than
 *     collapse_length ((e vn)^2 <= 2 a_n collapse_length, default 2^-20
 *     radius), the disk stays on the wall: its normal velocity and the
 *     normal component of its acceleration are set to 0
 *     (c2d_world_get_acceleration shows it; the tangential ones are kept).
 *     A disk at rest against a wall and pushed into it so has one wall
 *     event, then none; a bouncing one with e < 1 stops after about
 *     log(h / collapse_length) / log(1 / e^2) bounces.
 *   - Resting on another disk: touching disks whose accelerations press
 *     them together (relative normal acceleration closing, press) meet at
 *     once even with no approach speed, and at an impact that parts them
 *     slower than a rebound of collapse_length (sep^2 <= 2 press
 *     collapse_length along the unit normal) they rest on each other:
 *     their relative normal velocity is taken away (momentum kept) and
 *     each loses the component of its acceleration towards the other (as
 *     at a wall; c2d_world_get_acceleration shows it, set it anew when
 *     the situation changes).  So pressed disks never pass through each
 *     other, and one bouncing on another with e < 1 stops after about
 *     log(gap / collapse_length) / log(1 / e^2) impacts.  Reported as an
 *     impact (its impulse possibly 0).  Not after collapse_count impacts
 *     of one disk at one instant (rounding left by the projections cannot
 *     loop); statics have no such rule.
 *
 * MEMORY
 *   c2d_world_bytes(desc) bytes aligned to 8 bytes (any malloc result, or a
 *   static array of double/uint64_t); on 64-bit targets 648 bytes plus, per
 *   disk of capacity, 200 (the disk's state, 128 bytes: the array starts
 *   on a 64-byte boundary within the buffer, so one cache line holds what a
 *   prediction reads of a neighbour; its place in the event queue, 40, and
 *   in the window, 24; 2 cells of the grid, 4 each, at most
 *   2 x capacity + 16 cells) and 4 per day of the calendar (a power of 2 at
 *   or above the capacity, at least 16: 4 to 8 per disk): 204 to 208 bytes
 *   per disk (N = 1,024: 209,544 bytes; 100,489: 20.6 MB).  With a caller's
 *   broadphase no grid but each disk's box centre (16): 584 bytes plus 212
 *   to 216 per disk.  Statics: 80 bytes each of desc->statics (segments,
 *   circles and sensors), with 16 bytes per disk more when desc->statics > 0
 *   (its last sensor entry) and 8 when the model is C2D_WORLD_ROUGH (its
 *   spin).  The world
 *   lives entirely in that memory and points into it: do not move or copy
 *   it while in use (make a new world instead).  Nothing else is kept.
 *
 * BROADPHASE AND QUEUE
 *   Built in: a uniform grid of cells at least one largest diameter wide (at
 *   most 2 x capacity + 16 of them); a disk's next event is sought among
 *   the disks of the 3 x 3 cells around its own, and leaving its cell is an
 *   event (its state unchanged, so its best other event stands and only the
 *   3 cells that come into its neighbourhood are searched).  A caller's
 *   (desc->broadphase, see c2d_world_broadphase): each disk has a box,
 *   its centre's range +- margin grown by its radius; its next event is
 *   sought among the disks the caller reports for its box (in a periodic
 *   box also for its images across the sides it comes near), and leaving
 *   the range is an event at which the box is moved (one query, and the
 *   caller's move).  Either way a candidate is tested in plain double,
 *   every test certain despite rounding (receding, a miss, no contact
 *   before the best event so far), before c2d_time_of_impact.
 *   One pending event per disk, in a calendar queue: a binary heap (the
 *   window) on the current day's events, unsorted lists for the other days
 *   of the round (a power of 2 of them), an overflow beyond, pulled into
 *   the round every half round; a day is measured every round to hold
 *   about 2 events.  Events come out in exactly the order of the tie rule
 *   whatever the queue's shape.  An event whose partner has had an impact
 *   since it was predicted is stale (per-disk counters) and leads to a new
 *   prediction instead.
 *   Cost per event: O(1) for the queue (O(log) of a day's events), plus the
 *   predictions of its disks: O(disks in 9 cells) built in, the caller's
 *   query otherwise; adding a disk larger than all before rebuilds the grid
 *   (O(N)); every round the calendar may be re-filed (O(N), amortised O(1)).
 *   Measured (bench/world.c, periodic gas, e = 1, gcc -O2, x86-64):
 *   N = 1,024 at eta 0.5: 3,740 instructions per collision (callgrind;
 *   4,169 before the straight candidate's time of impact was inlined and
 *   the cell scan tightened), at eta 0.2 4,642 (5,008); about 84 % of them
 *   are the predictions (4.7 candidates each, 2.6 predictions per
 *   collision).  Collisions per CPU second: bench/RESULTS-world.md.
 *
 * CONFIGURATION
 *   C2D_NO_WORLD (when compiling the library): leave the world out.
 *   C2D_NO_DOUBLE leaves it out too (it is double precision).
 *
 * FREESTANDING: the world calls no C library function (not even memcpy:
 *   it copies no struct whole and passes none by value, which gcc -Os
 *   compiles into memcpy calls on Cortex-M0 and RV32; tests/mcu/sizes.sh
 *   fails on any), allocates nothing and does not recurse.  Its only
 *   indirect calls are the caller's: on_event, the resolvers and the
 *   broadphase's four, which run on the world's stack; the world's own
 *   depth under c2d_world_advance is about 5 KiB on Cortex-M0 and RV32
 *   (soft double), 4 KiB on Cortex-M7 (docs/SIZES.md, "+ callbacks"), and
 *   its code 22 to 41 KiB beyond the rest of the library (about 88 KiB with
 *   the collisions it calls, on Cortex-M0).  The firmware builds with
 *   double (tests/mcu: m0, m7, rv32) include it; the world's hash scenes
 *   (22.5 KiB of world memory) run on m7 and rv32 and give x86-64's bits
 *   (docs/DETERMINISM.md).
 *
 * THREAD SAFETY: the functions touch only their arguments; one world may
 * be read (c2d_world_get, c2d_world_get_stats) from several threads at once
 * while no thread changes it.
 */
#ifndef COLLIDE2D_WORLD_H
#define COLLIDE2D_WORLD_H

#include "collide2d.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifndef C2D_NO_DOUBLE

typedef struct c2d_world c2d_world;

typedef enum c2d_boundary { C2D_WALLS = 0, C2D_PERIODIC = 1 } c2d_boundary;

/* What c2d_world_desc.on_event receives after each impact. */
typedef enum c2d_world_event_kind {
    C2D_WORLD_IMPACT = 0,
    C2D_WORLD_WALL = 1,
    C2D_WORLD_TIMER = 2, /* a disk's timer (c2d_world_set_timer) is due */
    C2D_WORLD_STATIC = 3, /* a disk met a static segment or circle */
    C2D_WORLD_SENSOR = 4  /* a disk's centre entered a sensor (c2d_world_add_sensor) */
} c2d_world_event_kind;
typedef struct c2d_world_event {
    c2d_world_event_kind kind;
    double time;      /* when */
    size_t a, b;      /* IMPACT: the disks, a < b; WALL: the disk, and the wall
                         0..3 (x = 0, x = width, y = 0, y = height); TIMER: the
                         disk, and 0; STATIC and SENSOR: the disk, and the
                         static's index */
    c2d_vec2 impulse; /* IMPACT: on b (a gets its negative, unless a caller's
                         resolver says otherwise: then the change of b's
                         momentum); WALL: on the disk (0 when it comes to rest on
                         the wall at normal speed 0); STATIC: on the disk;
                         TIMER and SENSOR: 0 */
} c2d_world_event;

/* An axis-aligned box [lo.x, hi.x] x [lo.y, hi.y]: what a caller's
 * broadphase knows of a disk. */
typedef struct c2d_world_box {
    c2d_vec2 lo, hi;
} c2d_world_box;

/* A broadphase the caller supplies instead of the built-in cells
 * (c2d_world_desc.broadphase; see BROADPHASE AND QUEUE above).  The world
 * gives each disk a box, its shell: the disk's centre when the box was
 * set, +- (radius + margin) along each axis, a little more for rounding;
 * the disk keeps its centre within margin of the box's centre, and the
 * moment it would leave, the world moves its box (an event of its own).
 * The world calls
 *   insert(user, disk, box)  when a disk is added (disk = its index);
 *   move(user, disk, box)    when a disk's box moves (b2DynamicTree's MoveProxy);
 *   remove(user, disk)       when a disk is removed;
 *   query(user, box, report, context)  to find the disks that can meet a
 *                            disk: it must call report(context, disk) for
 *                            every disk whose box overlaps `box` (touching
 *                            counts).  More is harmless (a disk reported
 *                            twice, one whose box does not overlap, the
 *                            querying disk itself), fewer is a missed impact.
 * The callbacks must not call the world.  In a periodic box the boxes are
 * in [0, width) x [0, height) coordinates (the centre wrapped), a box may
 * stick out of the box by its half-size, and the world queries the images
 * of a box across every side it comes within the largest half-size of (a
 * box near the other side may stick out towards it; up to 9 queries).  The events and states are
 * the same bits whatever broadphase finds the candidates (a pair's time of
 * impact depends only on the two disks' states: CONVENTIONS, Determinism). */
/* What a broadphase's query calls for each disk it finds. */
typedef void (*c2d_world_report)(void *context, size_t disk);

typedef struct c2d_world_broadphase {
    void (*insert)(void *user, size_t disk, const c2d_world_box *box);
    void (*move)(void *user, size_t disk, const c2d_world_box *box);
    void (*remove)(void *user, size_t disk);
    void (*query)(void *user, const c2d_world_box *box, c2d_world_report report, void *context);
    void *user;    /* passed to the four */
    double margin; /* >= 0, finite: how far a centre moves before its box is moved
                      [0: half the disk's radius] */
} c2d_world_broadphase;

/* How the world resolves contacts (c2d_world_desc.model). */
typedef enum c2d_world_model {
    C2D_WORLD_SMOOTH = 0, /* frictionless: c2d_collide, c2d_collide_normal */
    C2D_WORLD_ROUGH = 1   /* rough disks with spin: c2d_collide_rough(_normal) */
} c2d_world_model;

/* A contact about to be resolved, as a caller's resolver sees it. */
typedef struct c2d_world_contact {
    c2d_world_event_kind kind; /* IMPACT, WALL or STATIC */
    double time;               /* the world's time (the contact's) */
    size_t a, b;               /* as in c2d_world_event */
    c2d_vec2 normal;           /* from a's centre towards b's (IMPACT), towards the
                                  wall (unit) or the static's contact point: not unit
                                  for IMPACT and STATIC */
    double restitution;        /* the world's coefficient for it, after the collapse
                                  rule */
    int collapsed;             /* 1 when the collapse rule made it elastic */
} c2d_world_contact;

/* A caller's resolution of one contact kind (c2d_world_desc.resolve_*):
 * given the contact and the bodies at its time (a: disk a; b: disk b for
 * an IMPACT, else an immovable body: mass INFINITY, velocity 0, at the
 * contact point), write the new velocities into a->vel (and b->vel) and
 * return C2D_OK.  Only velocities are taken.  Any other status, a NaN or
 * Inf velocity, or velocities still approaching along the normal
 * (relative normal speed < 0) make the world apply its own resolution
 * (the model's) instead, so a resolver can neither hang the world nor
 * poison it.  It may read the world (not change it) and keep its own
 * per-disk state (a ball's 3-D spin) by index. */
typedef c2d_status (*c2d_world_resolver)(void *user, const c2d_world_contact *contact, c2d_body *a, c2d_body *b);

typedef struct c2d_world_desc {
    size_t capacity;         /* most disks, 1 to 2^31 - 1 */
    double width, height;    /* the box [0, width) x [0, height): finite, > 0 */
    c2d_boundary boundary;   /* C2D_WALLS or C2D_PERIODIC */
    double restitution;      /* disk-disk, [0, 1] */
    double wall_restitution; /* the box's walls, [0, 1]; unused when periodic */
    /* More fields may follow: a zero field always means its documented default. */
    double collapse_speed;   /* >= 0, finite: impacts approaching slower are elastic [0: none] */
    unsigned collapse_count; /* impacts of one disk at one instant before the rest are elastic [0: 16] */
    double collapse_time;    /* >= 0, finite: an impact of a disk less than this after its
                                previous one is elastic (the TC model) [0: none] */
    double collapse_length;  /* >= 0, finite: an impact is elastic when the pair has closed
                                less than this (approach speed x time since either disk's
                                previous impact) [0: 2^-20 x the smaller radius] */
    /* Called after each event it reports (impacts, walls, statics, sensors,
     * due timers), during c2d_world_advance
     * [NULL: none].  It may read the world (c2d_world_get gives states at
     * the event's time) and call c2d_world_set_velocity,
     * c2d_world_set_acceleration, c2d_world_set_timer, c2d_world_set_spin
     * and c2d_world_remove on any disk (they act at the event's time; the
     * disks are predicted anew after, the event's own disks once however
     * many setters the callback calls on them); there c2d_world_add, the statics'
     * adders and c2d_world_advance return C2D_INVALID.  A timer set again and again to the event's own time
     * never lets the advance finish: that is the caller's loop. */
    void (*on_event)(void *user, const c2d_world_event *event);
    void *user;              /* passed to on_event */
    size_t statics;          /* most static segments, circles and sensors, 0 to 65536 [0: none] */
    c2d_world_model model;   /* C2D_WORLD_SMOOTH or C2D_WORLD_ROUGH [0: smooth] */
    double friction;         /* ROUGH: disk-disk Coulomb coefficient, >= 0 (INFINITY: no
                                sliding) [0] */
    double wall_friction;    /* ROUGH: the walls' and statics', >= 0 [0] */
    double tangential_restitution; /* ROUGH: beta in [-1, 1] (c2d_surface) [0] */
    double inertia_factor;   /* ROUGH: a disk's moment of inertia k m r^2, k in (0, 1]
                                [0: 1/2, a solid disk] */
    c2d_world_resolver resolve_impact; /* disk-disk [NULL: the model's] */
    c2d_world_resolver resolve_wall;   /* disk-box wall [NULL: the model's] */
    c2d_world_resolver resolve_static; /* disk-static [NULL: the model's] */
    /* The caller's broadphase, copied at c2d_world_init (the four functions
     * all given) [NULL: the built-in cells]. */
    const c2d_world_broadphase *broadphase;
} c2d_world_desc;

typedef struct c2d_world_stats {
    unsigned long long collisions, wall_collisions, events;
    double time;   /* the world's time */
    double virial; /* sum over disk-disk impacts of r_ij . dp_j (r_ij from i to j at
                      contact, nearest image; dp_j the impulse on j) */
} c2d_world_stats;

/* Bytes of memory a world with this description needs (aligned to 8);
 * 0 when desc is NULL or invalid (c2d_world_init would refuse it). */
size_t c2d_world_bytes(const c2d_world_desc *desc);

/* Make an empty world at time 0 in `memory` (bytes of it, aligned to 8,
 * at least c2d_world_bytes(desc)); *world points into memory.
 *   returns  C2D_OK, or C2D_INVALID (NULL pointer, invalid desc, a buffer
 *            too small or misaligned): then neither *world nor memory is
 *            written. */
c2d_status c2d_world_init(c2d_world **world, void *memory, size_t bytes, const c2d_world_desc *desc);

/* Add a disk at the world's time (no acceleration, no timer): disk->pos,
 * disk->vel, disk->mass and its radius; *index (if index is not NULL) receives its index (the number of
 * disks before it).
 *   returns  C2D_OK, or C2D_INVALID (NULL world or disk, NaN/Inf, mass or
 *            radius <= 0, outside the box, overlapping a disk (distance <
 *            sum of radii, computed in double at the world's time), the
 *            world full, or periodic and the diameter over a third of the
 *            box).
 *   cost     O(disks in 9 cells); O(N) when the disk is the largest yet
 *            (the grid is rebuilt); with a caller's broadphase one query of
 *            the disk's extent and its insert. */
c2d_status c2d_world_add(c2d_world *world, const c2d_body *disk, double radius, size_t *index);

/* Process every event with time <= t, in order, and set the world's time
 * to t.  Stored disk states stay at their last event (frame independence).
 *   returns  C2D_OK; C2D_INVALID for NULL, NaN/Inf t, or t before the
 *            world's time (nothing changes).
 *   cost     per event O(log N) plus the predictions of its disks. */
c2d_status c2d_world_advance(c2d_world *world, double t);

/* Disk `index` at the world's time: position (its last event's position
 * plus (velocity + acceleration x elapsed / 2) x elapsed time; in a
 * periodic box within [0, width) up to rounding), velocity (plus
 * acceleration x elapsed time) and mass.  Changes nothing.
 *   returns  C2D_OK, or C2D_INVALID (NULL, index >= number of disks, a
 *            removed disk). */
c2d_status c2d_world_get(const c2d_world *world, size_t index, c2d_body *disk);

/* The world's counters, time and virial sum (all zero for NULL world). */
void c2d_world_get_stats(const c2d_world *world, c2d_world_stats *stats);

/* The number of disks added (removed ones included: indices stay; 0 for
 * NULL). */
size_t c2d_world_count(const c2d_world *world);

/* Give disk `index` a new velocity at the world's time (a kick, a player's
 * control): its position there becomes its reference, its next event is
 * predicted anew, and its partners' predictions become stale.
 *   returns  C2D_OK; C2D_INVALID (NULL, index out of range or removed,
 *            NaN/Inf velocity; nothing changes).
 *   cost     one prediction (the disks of 9 cells) and a queue update; none
 *            from on_event for a disk of the event reported (the world
 *            predicts those once when the callback returns). */
c2d_status c2d_world_set_velocity(c2d_world *world, size_t index, c2d_vec2 velocity);

/* Take disk `index` out of the world at its time.  Its index is not reused
 * (nor its capacity); c2d_world_get and the other calls refuse it after.
 *   returns  C2D_OK; C2D_INVALID (NULL, index out of range or already removed).
 *   cost     O(disks in its cell) (the caller's remove) and a queue update. */
c2d_status c2d_world_remove(c2d_world *world, size_t index);

/* Give disk `index` a constant acceleration from the world's time on
 * (length per time^2; {0, 0} for straight lines again).  Its position and
 * velocity there become its reference (t0): until its next event
 * x(t) = x0 + (v0 + 0.5 acc (t - t0)) (t - t0), v(t) = v0 + acc (t - t0),
 * evaluated in double exactly so (c2d_world_get and the events use it).
 * Impacts between accelerated disks are predicted by
 * c2d_time_of_impact_accel with the earlier of the two disks' timers as the
 * horizon (where either motion may change; a timer set or due makes the
 * disk's partners' predictions stale); walls and cell crossings by the
 * roots of the quadratic (see
 * ACCELERATION above for the rules at rest and their accuracy).  A
 * decelerating ball does not stop by itself: the acceleration would turn
 * it back; set a timer at the stop (|v| / |acc|) and there set velocity
 * and acceleration to 0 (see c2d_world_set_timer).
 *   returns  C2D_OK; C2D_INVALID (NULL, index out of range or removed,
 *            NaN/Inf in acceleration; nothing changes).
 *   cost     one prediction and a queue update (none from on_event for a
 *            disk of the event reported, as c2d_world_set_velocity); a world that has ever had a
 *            non-zero acceleration reads its neighbours' accelerations in
 *            every prediction (a second cache line per neighbour) and pays
 *            c2d_time_of_impact_accel (a few hundred ns) for every pair
 *            with either disk accelerated. */
c2d_status c2d_world_set_acceleration(c2d_world *world, size_t index, c2d_vec2 acceleration);

/* Disk `index`'s acceleration (as set, or with the component into a wall
 * zeroed by the rest rule).
 *   returns  C2D_OK; C2D_INVALID (NULL, index out of range or removed). */
c2d_status c2d_world_get_acceleration(const c2d_world *world, size_t index, c2d_vec2 *acceleration);

/* Schedule disk `index`'s timer at absolute time t >= the world's time
 * (replacing any pending one; t = INFINITY cancels it).  When due, during
 * c2d_world_advance, the timer is cleared and on_event receives a
 * C2D_WORLD_TIMER event (a = index), from which the caller may set the
 * disk's velocity, acceleration or a new timer: the pool game's
 * slide -> roll -> stop.  Advancing to exactly t and calling the setters
 * after c2d_world_advance returns gives the same bits as calling them
 * from the callback.  A timer changes nothing by itself and is not an
 * impact (no counter but stats.events), but it is the horizon of the
 * disk's curved predictions: setting it, and its coming due, make its
 * partners' predictions stale.  Simultaneous events: impacts, walls,
 * crossings, then timers (lower disk first).
 *   returns  C2D_OK; C2D_INVALID (NULL, index out of range or removed, NaN,
 *            t before the world's time; nothing changes).
 *   cost     one prediction and a queue update (none from on_event for a
 *            disk of the event reported, as c2d_world_set_velocity). */
c2d_status c2d_world_set_timer(c2d_world *world, size_t index, double t);

/* Add a static (immovable) segment from a to b (a pool table's cushion),
 * with its own restitution in [0, 1]; *index (if not NULL) receives its
 * index among the statics (segments and circles, in order of addition
 * from 0; desc->statics of them at most).  A disk meets its interior
 * (the centre's distance to the line reaching the radius, the foot within
 * the segment: the time exactly from the normal coordinate, with
 * acceleration the quadratic's root) or either end (c2d_time_of_impact or
 * c2d_time_of_impact_accel against a point), and is resolved by
 * c2d_collide_normal against a body of mass INFINITY at rest with the
 * contact normal (the segment's unit normal, or end minus centre), so a
 * reflection is exact to c2d_collide_normal's accuracy and nothing passes
 * through a segment however thin or fast.  Elastic (e = 1) by the collapse
 * rule, as at a wall.  No rest rule: a disk at rest on a static and
 * pressed into it by its acceleration touches it with no approach speed
 * (no event, it sinks in until its next event), and one bouncing on a
 * static under an acceleration into it keeps bouncing, at e = 1 by the
 * collapse rule once the bounces are below collapse_length (an event
 * every sqrt(2 collapse_length / a)): stop such a disk from a timer, or
 * use the box's walls, which have the rest rule.  Statics are not checked against disks for overlap,
 * take no part in the broadphase and see no periodic images.  A
 * prediction tries only the statics whose boxes (a segment's ends, a
 * circle's or sensor's centre +- radius, derived from what is stored: no
 * memory of their own) meet the disk's reach until its next crossing: the
 * 3 x 3 cells around its own (at least a diameter beyond its cell), or
 * with a caller's broadphase its box grown by its radius; a static that
 * comes into reach at a cell crossing is tried there, a box left predicts
 * the disk anew; a segment's end is tried only when the end itself is in
 * reach, and a disk at rest (no velocity, no acceleration) tries none.
 * A static's time is computed from the disk's reference
 * state whenever it is tried, so the culling changes no time (the pool
 * table's 36 statics: the break 3x fewer instructions; exceptions, none
 * met in the tests: a static tried again at a later crossing and found
 * due at once, and a curved path's second entry into a sensor, which are
 * sought from the time of the try).  Every static is tested
 * against the reach (4 comparisons each): meant for a few dozen to a few
 * hundred.  Reported as C2D_WORLD_STATIC events and counted in
 * stats.wall_collisions.
 *   returns  C2D_OK; C2D_INVALID (NULL world, NaN/Inf, a == b, restitution
 *            outside [0, 1], the statics full, inside on_event; nothing
 *            changes).
 *   cost     every disk predicted anew: O(N (disks in 9 cells + statics)). */
c2d_status c2d_world_add_segment(c2d_world *world, c2d_vec2 a, c2d_vec2 b, double restitution, size_t *index);

/* Add a static circle (a cushion's nose, a post), centre and radius > 0,
 * with its own restitution: as c2d_world_add_segment (impacts by
 * c2d_time_of_impact with the radius sum, normal centre minus disk).
 *   returns  C2D_OK; C2D_INVALID (NULL world, NaN/Inf, radius <= 0,
 *            restitution outside [0, 1], the statics full, inside on_event).
 *   cost     as c2d_world_add_segment. */
c2d_status c2d_world_add_circle(c2d_world *world, c2d_vec2 centre, double radius, double restitution,
                                size_t *index);

/* Add a sensor: a circle (centre, radius > 0) that reports, and does not
 * resolve, a disk's centre entering it (a pool table's pocket).  Each
 * entry (the centre's distance to `centre` falling to `radius` from
 * outside, at c2d_time_of_impact's or c2d_time_of_impact_accel's time for
 * a point and the circle) is a C2D_WORLD_SENSOR event (a = the disk,
 * b = the sensor's index among the statics: sensors share desc->statics
 * and the index sequence of segments and circles), ordered with the
 * walls and statics; the disk moves on unchanged (remove it from on_event
 * to pocket it).  A disk already inside (added there, or not yet out
 * since its last entry) is not reported until it has left and comes back;
 * right after an entry, a centre within 2^-26 of the radius beyond the
 * circle by rounding counts as inside.  Sensors take no part in impacts,
 * counters other than stats.events, or the virial.
 *   returns  C2D_OK; C2D_INVALID (NULL world, NaN/Inf, radius <= 0, the
 *            statics full, inside on_event; nothing changes).
 *   cost     as c2d_world_add_segment; the world's memory holds 16 more
 *            bytes per disk when desc->statics > 0 (each disk's last entry). */
c2d_status c2d_world_add_sensor(c2d_world *world, c2d_vec2 centre, double radius, size_t *index);

/* Rough worlds (desc->model == C2D_WORLD_ROUGH): disk `index`'s spin
 * (angular velocity about +z, counter-clockwise, rad per time unit;
 * constant between its impacts).  Every disk starts with spin 0 and
 * inertia desc->inertia_factor x mass x radius^2.  Impacts are
 * c2d_collide_rough (disk-disk, surface {restitution, friction,
 * tangential_restitution}) and c2d_collide_rough_normal against an
 * immovable point (walls and statics: {their restitution, wall_friction,
 * tangential_restitution}); the collapse and rest rules act on the
 * restitution as in a smooth world.  Setting a spin changes no prediction
 * (paths do not depend on it).
 *   returns  C2D_OK; C2D_INVALID (NULL, a smooth world, index out of range
 *            or removed, NaN/Inf spin; nothing changes). */
c2d_status c2d_world_set_spin(c2d_world *world, size_t index, double spin);
c2d_status c2d_world_get_spin(const c2d_world *world, size_t index, double *spin);

#endif /* C2D_NO_DOUBLE */

#ifdef __cplusplus
}
#endif
#endif /* COLLIDE2D_WORLD_H */
