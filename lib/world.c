/* SPDX-License-Identifier: MIT */
/* world.c - the event-driven world of disks (include/collide2d_world.h).
 *
 * State: each disk keeps (x, y, vx, vy, t) from its last impact (or the
 * wrap of a periodic box), so its position at any time is x + vx (now - t):
 * advancing the world moves nothing, and the same events give the same bits
 * however the caller slices time.
 *
 * Events: one pending event per disk (its earliest: an impact with a disk in
 * the 3 x 3 cells around it, a wall, or leaving its cell), kept in a binary
 * heap ordered by (time, tie) with tie = kind << 62 | lower index << 31 |
 * higher index.  An impact event remembers its partner's impact counter
 * when predicted; if the partner has had an impact since, the event is
 * stale and the disk predicts again.  Correctness of one event per disk:
 * whenever a disk's motion changes it predicts against all its neighbours,
 * so every pair whose next contact is earlier than both disks' own events
 * is held by one of them.
 *
 * Cells are at least one largest diameter (x (1 + 2^-24)) wide, so disks in
 * contact are always in neighbouring cells; a disk is filed by the cell its
 * centre is in, and its crossing times are computed from the same cell
 * boundaries, so a rounding that puts a centre a hair outside its cell
 * only makes the crossing due at once.  In a periodic box the image of a
 * neighbour is the one the cell offset says (at least 3 cells a side), the
 * nearest image at contact.
 */
#include "internal.h"

#if !defined(C2D_NO_DOUBLE) && !defined(C2D_NO_WORLD)

#ifndef C2D_WORLD_HEADER
#define C2D_WORLD_HEADER "../include/collide2d_world.h"
#endif
#include C2D_WORLD_HEADER

/* The impact and the time of impact are the library's own public calls
 * (double.c): one copy of their code in any build, the same bits. */
#define C2D_W_COLLIDE c2d_collide
#define C2D_W_TOI c2d_time_of_impact
#define C2D_W_TOI_ACCEL c2d_time_of_impact_accel
#define C2D_W_COLLIDE_NORMAL c2d_collide_normal

#ifdef __GNUC__
#define C2D_W_SQRT __builtin_sqrt
#define C2D_W_FABS __builtin_fabs
#else
#define C2D_W_SQRT sqrt
#define C2D_W_FABS(x) ((x) < 0 ? -(x) : (x))
#endif

#define C2D_W_NONE 0xFFFFFFFFu
#define C2D_W_MAX_DISKS 0x7FFFFFFFu /* indices fit 31 bits of the tie key */
#define C2D_W_INF (DBL_MAX * 2.0)
#define C2D_W_MARGIN (1.0 + 1.0 / 16777216.0) /* cell width over the largest diameter */
#define C2D_W_COLLAPSE_COUNT 16u
#define C2D_W_MAX_STATICS 0x10000u /* statics are partners 4 + k of a wall event */
#ifndef C2D_W_CELLS_PER_DISK
#define C2D_W_CELLS_PER_DISK 2u /* the grid's budget: cells per disk of capacity (+ 16) */
#endif
#ifndef C2D_W_CELL_SCALE
#define C2D_W_CELL_SCALE 1.0 /* cell side over the largest diameter, at least */
#endif

/* Kinds in the order simultaneous events are processed (a timer's tie key
 * is 3 like an idle disk's: idle ones are never due). */
enum { C2D_W_PAIR = 0, C2D_W_WALL = 1, C2D_W_CELL = 2, C2D_W_TIMER = 3, C2D_W_IDLE = 4, C2D_W_GONE = 5 };

/* 128 bytes, the first cache line what a prediction reads of a neighbour. */
typedef struct c2d_w_disk {
    double x, y, vx, vy, t; /* the state at time t (its last impact); position at
                               time s: x + (vx + 0.5 ax (s - t)) (s - t) */
    double radius;
    uint64_t count;         /* impacts so far */
    uint32_t next, cell;    /* the next disk in its cell, its cell */
    double mass;
    double last;            /* the time of its last impact */
    uint64_t pcount;        /* the partner's count when the event was predicted */
    uint32_t partner;       /* a disk (impact), or a side 0..3: -x, +x, -y, +y */
    uint32_t slot;          /* its place in the heap */
    uint32_t kind;          /* C2D_W_PAIR ... C2D_W_IDLE */
    uint32_t same;          /* impacts at time `last` */
    double ax, ay;          /* its constant acceleration since t */
    double timer;           /* its timer's time, C2D_W_INF for none */
} c2d_w_disk;
typedef char c2d_w_disk_is_128_bytes[sizeof(c2d_w_disk) == 128 ? 1 : -1];

/* A static segment (a to b, unit normal n, length len), circle (centre
 * a, radius), both immovable, or sensor (centre a, radius). */
enum { C2D_W_SEGMENT = 0, C2D_W_CIRCLE = 1, C2D_W_SENSOR = 2 };
typedef struct c2d_w_static {
    double ax, ay, bx, by, nx, ny, len, radius, restitution;
    uint32_t shape, spare;
} c2d_w_static;

/* A disk's last sensor entry (kept only in worlds with statics): the
 * sensor's index + 1 (0: none) and when. */
typedef struct c2d_w_entered {
    double time;
    uint32_t sensor, spare;
} c2d_w_entered;



/* A heap entry: a disk's next event, its time and its tie key
 * (kind << 62 | lower index << 31 | higher index). */
typedef struct c2d_w_entry {
    double when;
    uint64_t tie;
    uint32_t disk, spare;
} c2d_w_entry;

struct c2d_world {
    c2d_w_disk *disk;
    c2d_w_entry *heap; /* a min-heap on (when, tie) */
    uint32_t *head;  /* first disk of each cell, C2D_W_NONE for none */
    c2d_w_static *stat;
    c2d_w_entered *entered; /* per disk, when statics are allowed (else NULL) */
    double *spin;           /* per disk, rough worlds only (else NULL) */
    c2d_world_resolver resolve_impact, resolve_wall, resolve_static; /* the caller's (NULL: the model's) */
    c2d_surface surface, wall_surface; /* rough worlds (restitution unused) */
    double inertia_factor;
    size_t capacity, count, budget, scapacity, nstatic;
    size_t mx, my;   /* cells per side (0 until the first disk) */
    double width, height, restitution, wall_restitution, collapse_speed, collapse_time, collapse_length;
    double cw, ch;   /* cell sides */
    double rmax;     /* the largest radius */
    double now;      /* the world's time (also the current event's, while advancing) */
    unsigned collapse_count;
    int periodic;
    int accel;       /* a disk has had a non-zero acceleration */
    int busy;        /* 1 inside on_event, 2 inside a caller's resolver */
    void (*on_event)(void *user, const c2d_world_event *event);
    void *user;
    c2d_world_stats stats;
};

/* ------------------------------------------------------------ layout */

/* A kind's place in the tie key (2 bits: an idle or gone disk shares the
 * timer's, never due). */
#define C2D_W_TIE_KIND(k) ((uint64_t)((k) > 3u ? 3u : (k)) << 62)

/* A coordinate and a velocity component dt after the state's time. */
static double c2d_w_at(double x, double v, double a, double dt) { return x + (v + 0.5 * a * dt) * dt; }
static double c2d_w_vel(double v, double a, double dt) { return v + a * dt; }

#define C2D_W_ROUND8(n) (((n) + 7u) / 8u * 8u)

static int c2d_w_finite(double x) { return x == x && x - x == 0; }

static int c2d_w_desc_ok(const c2d_world_desc *d)
{
    if (d == NULL) return 0;
    if (d->capacity < 1 || d->capacity > C2D_W_MAX_DISKS) return 0;
    if (d->statics > C2D_W_MAX_STATICS) return 0;
    if (!c2d_w_finite(d->width) || !c2d_w_finite(d->height) || !(d->width > 0) || !(d->height > 0)) return 0;
    if (d->boundary != C2D_WALLS && d->boundary != C2D_PERIODIC) return 0;
    if (!(d->restitution >= 0 && d->restitution <= 1)) return 0;
    if (!(d->wall_restitution >= 0 && d->wall_restitution <= 1)) return 0;
    if (!(d->collapse_speed >= 0) || !c2d_w_finite(d->collapse_speed)) return 0;
    if (!(d->collapse_time >= 0) || !c2d_w_finite(d->collapse_time)) return 0;
    if (!(d->collapse_length >= 0) || !c2d_w_finite(d->collapse_length)) return 0;
    if (d->model != C2D_WORLD_SMOOTH && d->model != C2D_WORLD_ROUGH) return 0;
    if (!(d->friction >= 0) || !(d->wall_friction >= 0)) return 0; /* INFINITY allowed */
    if (!(d->tangential_restitution >= -1 && d->tangential_restitution <= 1)) return 0;
    if (!(d->inertia_factor >= 0 && d->inertia_factor <= 1)) return 0;
    return 1;
}

/* Offsets of the disks, the heap, the cells, the statics, the sensor
 * entries and the spins in the memory, and the total; 0 if the sizes
 * overflow size_t.  A world pays only for what its desc allows: no
 * statics, no entries; smooth, no spins. */
typedef struct c2d_w_offsets {
    size_t disks, heap, cells, stat, entered, spin;
} c2d_w_offsets;

static size_t c2d_w_layout(const c2d_world_desc *desc, c2d_w_offsets *o)
{
    const size_t capacity = desc->capacity, statics = desc->statics;
    const size_t top = (size_t)-1;
    size_t budget = C2D_W_CELLS_PER_DISK * capacity + 16, off = C2D_W_ROUND8(sizeof(struct c2d_world)) + 56, n;
    if (capacity > (top - 16) / C2D_W_CELLS_PER_DISK) return 0;
    o->disks = off; /* the disks start on a 64-byte boundary within the 56 bytes before */
    if (capacity > (top - off) / sizeof(c2d_w_disk)) return 0;
    off += capacity * sizeof(c2d_w_disk);
    o->heap = off;
    if (capacity > (top - off) / sizeof(c2d_w_entry)) return 0;
    n = capacity * sizeof(c2d_w_entry);
    off += n;
    o->cells = off;
    if (budget > top / 8 || budget * sizeof(uint32_t) > top - off - 8) return 0;
    off = C2D_W_ROUND8(off + budget * sizeof(uint32_t));
    o->stat = off;
    if (statics > (top - off) / sizeof(c2d_w_static)) return 0;
    off += statics * sizeof(c2d_w_static);
    o->entered = off;
    if (statics > 0) {
        if (capacity > (top - off) / sizeof(c2d_w_entered)) return 0;
        off += capacity * sizeof(c2d_w_entered);
    }
    o->spin = off;
    if (desc->model == C2D_WORLD_ROUGH) {
        if (capacity > (top - off) / sizeof(double)) return 0;
        off += capacity * sizeof(double);
    }
    return off;
}

size_t c2d_world_bytes(const c2d_world_desc *desc)
{
    c2d_w_offsets o;
    if (!c2d_w_desc_ok(desc)) return 0;
    return c2d_w_layout(desc, &o);
}

/* The contact model: the caller's resolvers and the rough surfaces. */
static void c2d_w_init_resolvers(c2d_world *w, const c2d_world_desc *d)
{
    w->resolve_impact = d->resolve_impact;
    w->resolve_wall = d->resolve_wall;
    w->resolve_static = d->resolve_static;
    w->surface.restitution = d->restitution;
    w->surface.friction = d->friction;
    w->surface.tangential_restitution = d->tangential_restitution;
    w->wall_surface = w->surface;
    w->wall_surface.friction = d->wall_friction;
    w->inertia_factor = d->inertia_factor > 0 ? d->inertia_factor : 0.5;
}

c2d_status c2d_world_init(c2d_world **world, void *memory, size_t bytes, const c2d_world_desc *desc)
{
    c2d_w_offsets o;
    size_t total;
    unsigned char *m = (unsigned char *)memory;
    c2d_world *w;
    if (world == NULL || memory == NULL || !c2d_w_desc_ok(desc)) return C2D_INVALID;
    if ((uintptr_t)memory % 8u != 0) return C2D_INVALID;
    total = c2d_w_layout(desc, &o);
    if (total == 0 || bytes < total) return C2D_INVALID;
    w = (c2d_world *)memory;
    {
        size_t skew = (size_t)(((uintptr_t)m + o.disks) % 64u), back = skew; /* a multiple of 8, up to 56 */
        w->disk = (c2d_w_disk *)(void *)(m + o.disks - back);
        w->heap = (c2d_w_entry *)(void *)(m + o.heap - back);
        w->head = (uint32_t *)(void *)(m + o.cells - back);
        w->stat = (c2d_w_static *)(void *)(m + o.stat - back);
        w->entered = desc->statics > 0 ? (c2d_w_entered *)(void *)(m + o.entered - back) : NULL;
        w->spin = desc->model == C2D_WORLD_ROUGH ? (double *)(void *)(m + o.spin - back) : NULL;
    }
    c2d_w_init_resolvers(w, desc);
    w->capacity = desc->capacity;
    w->scapacity = desc->statics;
    w->nstatic = 0;
    w->count = 0;
    w->budget = C2D_W_CELLS_PER_DISK * desc->capacity + 16;
    w->mx = w->my = 0;
    w->width = desc->width;
    w->height = desc->height;
    w->restitution = desc->restitution;
    w->wall_restitution = desc->wall_restitution;
    w->collapse_speed = desc->collapse_speed;
    w->collapse_time = desc->collapse_time;
    w->collapse_length = desc->collapse_length;
    w->collapse_count = desc->collapse_count == 0 ? C2D_W_COLLAPSE_COUNT : desc->collapse_count;
    w->periodic = desc->boundary == C2D_PERIODIC;
    w->accel = 0;
    w->busy = 0;
    w->on_event = desc->on_event;
    w->user = desc->user;
    w->cw = w->ch = 0;
    w->rmax = 0;
    w->now = 0;
    w->stats.collisions = w->stats.wall_collisions = w->stats.events = 0;
    w->stats.time = 0;
    w->stats.virial = 0;
    *world = w;
    return C2D_OK;
}

size_t c2d_world_count(const c2d_world *world)
{
    return world == NULL ? 0 : world->count;
}

/* ------------------------------------------------------------ heap */

/* (when, tie, disk): a total order, so the events come out in the same
 * order whatever the heap's shape (both disks of a pair may hold the same
 * event: the lower index's copy first). */
static int c2d_w_before(const c2d_w_entry *a, const c2d_w_entry *b)
{
    return a->when < b->when || (a->when == b->when && (a->tie < b->tie || (a->tie == b->tie && a->disk < b->disk)));
}

/* Disk i's event is now (when, tie): move its entry to its place in the
 * 4-ary heap (children of slot s: 4 s + 1 ... 4 s + 4, contiguous). */
static void c2d_w_heap_fix(c2d_world *w, uint32_t i, double when, uint64_t tie)
{
    c2d_w_entry *h = w->heap, e;
    c2d_w_disk *d = w->disk;
    size_t s = d[i].slot, n = w->count;
    e.when = when, e.tie = tie, e.disk = i, e.spare = 0;
    while (s > 0) {
        size_t up = (s - 1) / 4;
        if (!c2d_w_before(&e, &h[up])) break;
        h[s] = h[up];
        d[h[s].disk].slot = (uint32_t)s;
        s = up;
    }
    for (;;) {
        size_t l = 4 * s + 1, best, k, end;
        if (l >= n) break;
        best = l;
        end = l + 4 < n ? l + 4 : n;
        for (k = l + 1; k < end; k++)
            if (c2d_w_before(&h[k], &h[best])) best = k;
        if (!c2d_w_before(&h[best], &e)) break;
        h[s] = h[best];
        d[h[s].disk].slot = (uint32_t)s;
        s = best;
    }
    h[s] = e;
    d[i].slot = (uint32_t)s;
}

/* ------------------------------------------------------------ cells */

static size_t c2d_w_cell_1d(double x, double side, size_t m)
{
    double q;
    if (!(x >= side)) return 0;
    q = x / side;
    return q >= (double)m ? m - 1 : (size_t)q;
}

static void c2d_w_cell_insert(c2d_world *w, uint32_t i, size_t c)
{
    w->disk[i].cell = (uint32_t)c;
    w->disk[i].next = w->head[c];
    w->head[c] = i;
}

static void c2d_w_cell_remove(c2d_world *w, uint32_t i)
{
    uint32_t *p = &w->head[w->disk[i].cell];
    while (*p != i) p = &w->disk[*p].next;
    *p = w->disk[i].next;
}

/* ------------------------------------------------------------ prediction */

typedef struct c2d_w_best {
    double when;
    uint32_t kind, partner;
    uint64_t pcount;
} c2d_w_best;

static void c2d_w_consider(c2d_w_best *b, double when, uint32_t kind, uint32_t partner, uint64_t pcount)
{
    if (when < b->when || (when == b->when && (kind < b->kind || (kind == b->kind && partner < b->partner)))) {
        b->when = when;
        b->kind = kind;
        b->partner = partner;
        b->pcount = pcount;
    }
}

/* The image offset of a neighbour's cell coordinate cj from ci: -1 (its
 * image lies one box to the left), 0 or 1. */
static double c2d_w_image(size_t ci, size_t cj)
{
    if (cj > ci + 1) return -1.0;
    if (ci > cj + 1) return 1.0;
    return 0.0;
}

/* The cells around coordinate c of m along one axis, each once, and the
 * shift of each one's image (periodic: +-side across the wrap). */
static size_t c2d_w_neighbours(size_t c, size_t m, int periodic, double side, size_t *cell, double *shift)
{
    size_t n = 0;
    if (c > 0) cell[n] = c - 1, shift[n++] = 0;
    else if (periodic) cell[n] = m - 1, shift[n++] = -side;
    cell[n] = c, shift[n++] = 0;
    if (c + 1 < m) cell[n] = c + 1, shift[n++] = 0;
    else if (periodic) cell[n] = 0, shift[n++] = side;
    return n;
}

/* The first time >= now at which a disk at x (time t) with speed v reaches
 * `to`. */
static double c2d_w_reach(double t, double x, double v, double to, double now)
{
    double when = t + (to - x) / v;
    return when < now ? now : when;
}

/* The first time >= now at which a coordinate x + v s + a s^2 / 2 (s the
 * time since t) passes `to` moving in direction dir (+1: upwards, -1:
 * downwards): g(s) = dir (x(s) - to) rising through 0.  C2D_W_INF for never.
 * With a == 0 it is c2d_w_reach's time (the same bits).  Otherwise the roots
 * of A s^2 + B s + C come from the cancellation-free pair q / A, C / q
 * (q = -(B + sign(B) sqrt(D)) / 2); g already past 0 (rounding) and rising
 * is due at once, past 0 and falling back is no event (else a disk that
 * just crossed into a cell could cross back and forth at one instant); a
 * double root with A < 0 only touches (no event), with A > 0 it passes.  Errors: a few ulp of the root, plus near a tangency (D ~ 0) the
 * rounding of D: a path that in exact arithmetic passes `to` by less than
 * a few ulp of the coordinates may be taken as a touch and the reverse. */
static double c2d_w_meet(double t, double x, double v, double a, double to, double dir, double now)
{
    double A, B, C, D, q, r1, r2, lo, hi, vertex;
    if (a == 0) return dir * v > 0 ? c2d_w_reach(t, x, v, to, now) : C2D_W_INF;
    A = dir * (0.5 * a), B = dir * v, C = dir * (x - to);
    D = B * B - 4 * A * C;
    vertex = t + -B / (2 * A);
    if (!(D >= 0)) { /* A > 0: g > 0 throughout (past already): at its lowest */
        if (A < 0) return C2D_W_INF;
        return vertex < now ? now : vertex;
    }
    if (D == 0 && A < 0) return C2D_W_INF;
    q = -0.5 * (B + (B >= 0 ? C2D_W_SQRT(D) : -C2D_W_SQRT(D)));
    r1 = q / A;
    r2 = q != 0 ? C / q : r1;
    lo = r1 < r2 ? r1 : r2, hi = r1 < r2 ? r2 : r1;
    if (A > 0) return t + hi < now ? now : t + hi;
    if (t + lo >= now) return t + lo;
    /* Past the rising root: beyond `to` and still rising (rounding) is due at
     * once; past the top, g falls back and never rises again. */
    return now < vertex ? now : C2D_W_INF;
}

/* An impact that leaves both velocities as they were (an approach speed
 * so small that even the elastic impulse rounds away) changes nothing, so
 * it is no impact either. */
static int c2d_w_unchanged(const c2d_body *a0, const c2d_body *a, const c2d_body *b0, const c2d_body *b)
{
    return a->vel.x == a0->vel.x && a->vel.y == a0->vel.y && b->vel.x == b0->vel.x && b->vel.y == b0->vel.y;
}

/* A pair's contact at the very time `now` that c2d_collide would refuse
 * (touching with no approach speed, pushed together by accelerations) or
 * resolve to the same velocities even at e = 1: no event, or the world
 * would predict it again and again at one instant (the collapse rule
 * makes an impact elastic after collapse_count of them, so a pair whose
 * elastic impact changes something always ends). */
static int c2d_w_refused_now(const c2d_body *a, const c2d_body *b)
{
    c2d_body ta = *a, tb = *b;
    return C2D_W_COLLIDE(&ta, &tb, 1.0) != C2D_OK || c2d_w_unchanged(a, &ta, b, &tb);
}

/* Disk p has had collapse_count impacts at this very instant (the
 * collapse rule, c2d_w_collapses). */
static int c2d_w_crowded(const c2d_world *w, const c2d_w_disk *p, double now)
{
    return p->last == now && p->same >= w->collapse_count;
}

/* Touching disks p (body a) and q (b) that c2d_collide refuses now but
 * whose accelerations press together (relative normal acceleration
 * closing) meet now all the same, for the pair rest rule (c2d_w_pair):
 * else they would pass through each other.  Not once either has had
 * collapse_count impacts at this instant, so rounding left in the rule's
 * projections cannot loop. */
static int c2d_w_pressed(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q, const c2d_body *a,
                         const c2d_body *b)
{
    const double nx = b->pos.x - a->pos.x, ny = b->pos.y - a->pos.y;
    if (c2d_w_crowded(w, p, w->now) || c2d_w_crowded(w, q, w->now)) return 0;
    return (p->ax - q->ax) * nx + (p->ay - q->ay) * ny > 0;
}

/* The contact point and normal (from the disk towards the static) of a
 * disk centred at (px, py) against static k: a circle's centre; a
 * segment's end when the centre's foot on its line lies beyond it, else
 * the foot, the normal then the segment's own normal (signed).  The
 * prediction and the impact use the same, so they agree on refusals. */
static void c2d_w_static_contact(const c2d_w_static *st, double px, double py, c2d_vec2 *point, c2d_vec2 *normal)
{
    if (st->shape == C2D_W_SEGMENT) {
        const double tx = (st->bx - st->ax) / st->len, ty = (st->by - st->ay) / st->len;
        const double u = tx * (px - st->ax) + ty * (py - st->ay);
        if (u > 0 && u < st->len) {
            const double side = st->nx * (px - st->ax) + st->ny * (py - st->ay) >= 0 ? -1.0 : 1.0;
            point->x = st->ax + tx * u, point->y = st->ay + ty * u;
            normal->x = side * st->nx, normal->y = side * st->ny;
            return;
        }
        if (!(u > 0)) point->x = st->ax, point->y = st->ay;
        else point->x = st->bx, point->y = st->by;
    } else {
        point->x = st->ax, point->y = st->ay;
    }
    normal->x = point->x - px, normal->y = point->y - py;
}

static int c2d_w_static_refused(const c2d_w_static *st, const c2d_body *a)
{
    c2d_body ta = *a, tb;
    c2d_vec2 n;
    c2d_w_static_contact(st, a->pos.x, a->pos.y, &tb.pos, &n);
    tb.vel.x = tb.vel.y = 0, tb.mass = C2D_W_INF;
    return C2D_W_COLLIDE_NORMAL(&ta, &tb, n, 1.0) != C2D_OK || (ta.vel.x == a->vel.x && ta.vel.y == a->vel.y);
}

/* Disk p (at a, now) entering sensor k: a point meeting a circle, from
 * outside only.  Inside, or just entered and a hair outside by rounding
 * (within 2^-26 of the radius: (1 + 2^-26)^2 < 1 + 2^-25), is no event:
 * otherwise the entry would repeat at once. */
static void c2d_w_predict_sensor(const c2d_world *w, const c2d_w_disk *p, const c2d_body *a, size_t k,
                                 c2d_w_best *best)
{
    const c2d_w_static *st = &w->stat[k];
    const c2d_w_entered *en = &w->entered[p - w->disk];
    const double dx = a->pos.x - st->ax, dy = a->pos.y - st->ay, dd = dx * dx + dy * dy, rr = st->radius * st->radius;
    c2d_body b;
    double toi;
    c2d_status r;
    if (dd < rr || (en->sensor == k + 1 && dd <= rr * (1 + 0x1p-25))) return;
    b.pos.x = st->ax, b.pos.y = st->ay, b.vel.x = b.vel.y = 0, b.mass = C2D_W_INF;
    if (p->ax == 0 && p->ay == 0) {
        r = C2D_W_TOI(a, &b, st->radius, &toi);
    } else {
        c2d_vec2 acc, zero;
        acc.x = p->ax, acc.y = p->ay, zero.x = zero.y = 0;
        r = C2D_W_TOI_ACCEL(a, acc, &b, zero, st->radius, best->when - w->now, &toi);
    }
    if (r == C2D_OK) c2d_w_consider(best, w->now + toi, C2D_W_WALL, (uint32_t)(4 + k), 0);
}

/* Disk p (at a, now) against every static: a circle (radius sum r + R), a
 * segment's two ends (points) and its interior (the normal coordinate
 * reaching +-r with the foot within the segment). */
static void c2d_w_predict_statics(const c2d_world *w, const c2d_w_disk *p, const c2d_body *a, c2d_w_best *best)
{
    const double now = w->now;
    size_t k;
    c2d_vec2 acc;
    acc.x = p->ax, acc.y = p->ay;
    for (k = 0; k < w->nstatic; k++) {
        const c2d_w_static *st = &w->stat[k];
        const uint32_t partner = (uint32_t)(4 + k);
        int end;
        if (st->shape == C2D_W_SENSOR) {
            c2d_w_predict_sensor(w, p, a, k, best);
            continue;
        }
        for (end = 0; end < (st->shape == C2D_W_CIRCLE ? 1 : 2); end++) {
            c2d_body b;
            double toi, when;
            c2d_status r;
            b.pos.x = end ? st->bx : st->ax, b.pos.y = end ? st->by : st->ay;
            b.vel.x = b.vel.y = 0, b.mass = C2D_W_INF;
            if (acc.x == 0 && acc.y == 0) r = C2D_W_TOI(a, &b, p->radius + st->radius, &toi);
            else {
                c2d_vec2 zero;
                zero.x = zero.y = 0;
                r = C2D_W_TOI_ACCEL(a, acc, &b, zero, p->radius + st->radius, best->when - now, &toi);
            }
            if (r != C2D_OK) continue;
            when = now + toi;
            if (when == now && c2d_w_static_refused(st, a)) continue;
            c2d_w_consider(best, when, C2D_W_WALL, partner, 0);
        }
        if (st->shape == C2D_W_SEGMENT) {
            const double d0 = st->nx * (p->x - st->ax) + st->ny * (p->y - st->ay);
            const double vn = st->nx * p->vx + st->ny * p->vy, an = st->nx * acc.x + st->ny * acc.y;
            const double dnow = st->nx * (a->pos.x - st->ax) + st->ny * (a->pos.y - st->ay);
            const double when = dnow >= 0 ? c2d_w_meet(p->t, d0, vn, an, p->radius, -1, now)
                                          : c2d_w_meet(p->t, d0, vn, an, -p->radius, 1, now);
            if (when < C2D_W_INF) {
                const double dt = when - p->t;
                const double x = c2d_w_at(p->x, p->vx, acc.x, dt), y = c2d_w_at(p->y, p->vy, acc.y, dt);
                const double u = ((st->bx - st->ax) * (x - st->ax) + (st->by - st->ay) * (y - st->ay)) / st->len;
                if (u >= 0 && u <= st->len && !(when == now && c2d_w_static_refused(st, a)))
                    c2d_w_consider(best, when, C2D_W_WALL, partner, 0);
            }
        }
    }
}

static void c2d_w_predict(c2d_world *w, uint32_t i)
{
    c2d_w_disk *d = w->disk, *p = &d[i];
    const double now = w->now, dt = now - p->t, pax = p->ax, pay = p->ay;
    const double px = c2d_w_at(p->x, p->vx, pax, dt), py = c2d_w_at(p->y, p->vy, pay, dt);
    const size_t mx = w->mx, my = w->my, cx = p->cell % mx, cy = p->cell / mx;
    const int accel = w->accel;
    c2d_w_best best;
    c2d_body a;
    size_t k, l, nc, nr, col[3], row[3];
    uint32_t first[9];
    double colshift[3], rowshift[3];
    best.when = C2D_W_INF;
    best.kind = C2D_W_IDLE;
    best.partner = 0;
    best.pcount = 0;
    /* Walls (the centre at radius from them), then the cell's sides (with no
     * acceleration along an axis, c2d_w_meet is c2d_w_reach for the sides
     * the velocity points to). */
    if (pax == 0 && pay == 0) { /* straight: only the sides the velocity points to */
        if (!w->periodic) {
            if (p->vx < 0) c2d_w_consider(&best, c2d_w_reach(p->t, p->x, p->vx, p->radius, now), C2D_W_WALL, 0, 0);
            if (p->vx > 0)
                c2d_w_consider(&best, c2d_w_reach(p->t, p->x, p->vx, w->width - p->radius, now), C2D_W_WALL, 1, 0);
            if (p->vy < 0) c2d_w_consider(&best, c2d_w_reach(p->t, p->y, p->vy, p->radius, now), C2D_W_WALL, 2, 0);
            if (p->vy > 0)
                c2d_w_consider(&best, c2d_w_reach(p->t, p->y, p->vy, w->height - p->radius, now), C2D_W_WALL, 3, 0);
        }
        if (p->vx < 0 && (cx > 0 || w->periodic))
            c2d_w_consider(&best, c2d_w_reach(p->t, p->x, p->vx, (double)cx * w->cw, now), C2D_W_CELL, 0, 0);
        if (p->vx > 0 && (cx + 1 < mx || w->periodic))
            c2d_w_consider(&best,
                           c2d_w_reach(p->t, p->x, p->vx, cx + 1 == mx ? w->width : (double)(cx + 1) * w->cw, now),
                           C2D_W_CELL, 1, 0);
        if (p->vy < 0 && (cy > 0 || w->periodic))
            c2d_w_consider(&best, c2d_w_reach(p->t, p->y, p->vy, (double)cy * w->ch, now), C2D_W_CELL, 2, 0);
        if (p->vy > 0 && (cy + 1 < my || w->periodic))
            c2d_w_consider(&best,
                           c2d_w_reach(p->t, p->y, p->vy, cy + 1 == my ? w->height : (double)(cy + 1) * w->ch, now),
                           C2D_W_CELL, 3, 0);
    } else {
        if (!w->periodic) {
            c2d_w_consider(&best, c2d_w_meet(p->t, p->x, p->vx, pax, p->radius, -1, now), C2D_W_WALL, 0, 0);
            c2d_w_consider(&best, c2d_w_meet(p->t, p->x, p->vx, pax, w->width - p->radius, 1, now), C2D_W_WALL, 1, 0);
            c2d_w_consider(&best, c2d_w_meet(p->t, p->y, p->vy, pay, p->radius, -1, now), C2D_W_WALL, 2, 0);
            c2d_w_consider(&best, c2d_w_meet(p->t, p->y, p->vy, pay, w->height - p->radius, 1, now), C2D_W_WALL, 3, 0);
        }
        if (cx > 0 || w->periodic)
            c2d_w_consider(&best, c2d_w_meet(p->t, p->x, p->vx, pax, (double)cx * w->cw, -1, now), C2D_W_CELL, 0, 0);
        if (cx + 1 < mx || w->periodic)
            c2d_w_consider(&best,
                           c2d_w_meet(p->t, p->x, p->vx, pax, cx + 1 == mx ? w->width : (double)(cx + 1) * w->cw, 1, now),
                           C2D_W_CELL, 1, 0);
        if (cy > 0 || w->periodic)
            c2d_w_consider(&best, c2d_w_meet(p->t, p->y, p->vy, pay, (double)cy * w->ch, -1, now), C2D_W_CELL, 2, 0);
        if (cy + 1 < my || w->periodic)
            c2d_w_consider(&best,
                           c2d_w_meet(p->t, p->y, p->vy, pay, cy + 1 == my ? w->height : (double)(cy + 1) * w->ch, 1, now),
                           C2D_W_CELL, 3, 0);
    }
    if (p->timer < C2D_W_INF) c2d_w_consider(&best, p->timer, C2D_W_TIMER, 0, 0);
    a.pos.x = px, a.pos.y = py, a.mass = p->mass;
    a.vel.x = c2d_w_vel(p->vx, pax, dt), a.vel.y = c2d_w_vel(p->vy, pay, dt);
    if (w->nstatic > 0) c2d_w_predict_statics(w, p, &a, &best);
    /* The 3 x 3 cells around, each once (fewer against walls), with the
     * image shift a periodic wrap gives each column and row. */
    nc = c2d_w_neighbours(cx, mx, w->periodic, w->width, col, colshift);
    nr = c2d_w_neighbours(cy, my, w->periodic, w->height, row, rowshift);
    /* The cells' first disks, loaded (and their states fetched) all at
     * once before any is used: with many disks these are cache misses, and
     * independent ones overlap. */
    for (l = 0; l < nr; l++)
        for (k = 0; k < nc; k++) {
            uint32_t j = w->head[row[l] * mx + col[k]];
            first[l * 3 + k] = j;
#ifdef __GNUC__
            if (j != C2D_W_NONE) __builtin_prefetch(&d[j]);
#endif
        }
    for (l = 0; l < nr; l++) {
        const double sy = rowshift[l];
        for (k = 0; k < nc; k++) {
            const double sx = colshift[k];
            uint32_t j = first[l * 3 + k];
            for (; j != C2D_W_NONE; j = d[j].next) {
                const c2d_w_disk *q = &d[j];
                double qdt, dx, dy, dvx, dvy, dot, mag, toi;
                c2d_body b;
                if (j == i) continue;
                qdt = now - q->t;
                if (accel && (pax != 0 || pay != 0 || q->ax != 0 || q->ay != 0)) {
                    /* Curved paths: until this disk's own next event so far
                     * (beyond it, it predicts again; a partner whose motion
                     * changes first makes this event stale). */
                    c2d_vec2 qa;
                    double when;
                    qa.x = q->ax, qa.y = q->ay;
                    b.pos.x = c2d_w_at(q->x, q->vx, qa.x, qdt) + sx;
                    b.pos.y = c2d_w_at(q->y, q->vy, qa.y, qdt) + sy;
                    b.vel.x = c2d_w_vel(q->vx, qa.x, qdt), b.vel.y = c2d_w_vel(q->vy, qa.y, qdt), b.mass = q->mass;
                    {
                        c2d_vec2 pa;
                        pa.x = pax, pa.y = pay;
                        if (C2D_W_TOI_ACCEL(&a, pa, &b, qa, p->radius + q->radius, best.when - now, &toi) != C2D_OK)
                            continue;
                    }
                    when = now + toi;
                    if (when == now && c2d_w_refused_now(&a, &b) && !c2d_w_pressed(w, p, q, &a, &b)) continue;
                    c2d_w_consider(&best, when, C2D_W_PAIR, j, q->count);
                    continue;
                }
                b.pos.x = (q->x + q->vx * qdt) + sx;
                b.pos.y = (q->y + q->vy * qdt) + sy;
                /* Filters, each certain despite rounding (the estimates'
                 * errors are far below 2^-40 of their terms, taken far
                 * from underflow): receding or no relative motion; a miss
                 * (the discriminant negative); or no contact before the
                 * best event so far (the time of impact is at least
                 * c / (2 |dot|), c = |d|^2 - rs^2 > 0). */
                dx = b.pos.x - px, dy = b.pos.y - py, dvx = q->vx - p->vx, dvy = q->vy - p->vy;
                dot = dx * dvx + dy * dvy;
                mag = C2D_W_FABS(dx * dvx) + C2D_W_FABS(dy * dvy);
                if (dvx == 0 && dvy == 0) continue;
                if (mag >= 0x1p-900 && mag <= 0x1p900) {
                    double rs, dd, err, c;
                    if (dot > mag * 0x1p-40) continue;
                    rs = p->radius + q->radius, dd = dx * dx + dy * dy;
                    err = (dd + rs * rs) * 0x1p-40, c = (dd - rs * rs) - err;
                    if (c > 0 && c <= 0x1p900 && err >= 0x1p-900) {
                        const double dh = -dot + mag * 0x1p-40, vv = (dvx * dvx + dvy * dvy) * (1 - 0x1p-40);
                        if (dh * dh < vv * c * (1 - 0x1p-40)) continue;
                        if (best.when - now < c / (2 * dh) * (1 - 0x1p-40)) continue;
                    }
                }
                b.vel.x = q->vx, b.vel.y = q->vy, b.mass = q->mass;
                if (C2D_W_TOI(&a, &b, p->radius + q->radius, &toi) != C2D_OK) continue;
                if (toi == 0 && c2d_w_refused_now(&a, &b)) continue;
                c2d_w_consider(&best, now + toi, C2D_W_PAIR, j, q->count);
            }
        }
    }
    p->kind = best.kind;
    p->partner = best.partner;
    p->pcount = best.pcount;
    if (best.kind == C2D_W_PAIR) {
        uint64_t lo = i < best.partner ? i : best.partner, hi = i < best.partner ? best.partner : i;
        c2d_w_heap_fix(w, i, best.when, lo << 31 | hi); /* kind C2D_W_PAIR = 0 */
    } else {
        c2d_w_heap_fix(w, i, best.when, C2D_W_TIE_KIND(best.kind) | (uint64_t)i << 31 | (uint64_t)i);
    }
}

/* ------------------------------------------------------------ grid */

/* Cells for the largest radius r: as many as fit at 2 r (1 + 2^-24) wide,
 * at most the budget. */
static void c2d_w_grid_size(const c2d_world *w, double r, size_t *mx, size_t *my)
{
    const double s = 2 * r * C2D_W_MARGIN * C2D_W_CELL_SCALE, budget = (double)w->budget;
    const size_t lo = w->periodic ? 3 : 1;
    double fx = w->width / s, fy = w->height / s;
    size_t x, y;
    if (!(fx < budget)) fx = budget;
    if (!(fy < budget)) fy = budget;
    x = fx < 1 ? 1 : (size_t)fx;
    y = fy < 1 ? 1 : (size_t)fy;
    if ((double)x * (double)y > budget) {
        double f = C2D_W_SQRT(budget / ((double)x * (double)y));
        x = (size_t)((double)x * f), y = (size_t)((double)y * f);
        if (x < lo) x = lo;
        if (y < lo) y = lo;
    }
    while (x * y > w->budget) {
        if ((x >= y && x > lo) || y <= lo) x--;
        else y--;
    }
    *mx = x, *my = y;
}

/* File every disk anew (at its position now) and predict every event. */
static void c2d_w_rebuild(c2d_world *w)
{
    size_t c, i;
    c2d_w_grid_size(w, w->rmax, &w->mx, &w->my);
    w->cw = w->width / (double)w->mx;
    w->ch = w->height / (double)w->my;
    for (c = 0; c < w->mx * w->my; c++) w->head[c] = C2D_W_NONE;
    for (i = 0; i < w->count; i++) {
        c2d_w_disk *p = &w->disk[i];
        double dt = w->now - p->t;
        size_t cx, cy;
        if (p->kind == C2D_W_GONE) continue;
        cx = c2d_w_cell_1d(c2d_w_at(p->x, p->vx, p->ax, dt), w->cw, w->mx);
        cy = c2d_w_cell_1d(c2d_w_at(p->y, p->vy, p->ay, dt), w->ch, w->my);
        c2d_w_cell_insert(w, (uint32_t)i, cy * w->mx + cx);
    }
    for (i = 0; i < w->count; i++)
        if (w->disk[i].kind != C2D_W_GONE) c2d_w_predict(w, (uint32_t)i);
}

/* ------------------------------------------------------------ adding */

static int c2d_w_overlaps(const c2d_world *w, double x, double y, double r, const c2d_w_disk *q)
{
    double dt = w->now - q->t, dx = c2d_w_at(q->x, q->vx, q->ax, dt) - x, dy = c2d_w_at(q->y, q->vy, q->ay, dt) - y;
    double rs = r + q->radius;
    if (w->periodic) {
        if (dx > 0.5 * w->width) dx -= w->width;
        if (dx < -0.5 * w->width) dx += w->width;
        if (dy > 0.5 * w->height) dy -= w->height;
        if (dy < -0.5 * w->height) dy += w->height;
    }
    return dx * dx + dy * dy < rs * rs;
}

c2d_status c2d_world_add(c2d_world *world, const c2d_body *disk, double radius, size_t *index)
{
    c2d_world *w = world;
    double x, y;
    int rebuild;
    uint32_t i;
    c2d_w_disk *p;
    if (w == NULL || disk == NULL || w->busy || w->count >= w->capacity) return C2D_INVALID;
    x = disk->pos.x, y = disk->pos.y;
    if (!c2d_w_finite(x) || !c2d_w_finite(y) || !c2d_w_finite(disk->vel.x) || !c2d_w_finite(disk->vel.y) ||
        !c2d_w_finite(disk->mass) || !(disk->mass > 0) || !c2d_w_finite(radius) || !(radius > 0))
        return C2D_INVALID;
    if (w->periodic) {
        if (!(x >= 0 && x < w->width && y >= 0 && y < w->height)) return C2D_INVALID;
        if (!(3 * (2 * radius * C2D_W_MARGIN) <= w->width && 3 * (2 * radius * C2D_W_MARGIN) <= w->height))
            return C2D_INVALID;
    } else {
        if (!(x >= radius && x <= w->width - radius && y >= radius && y <= w->height - radius)) return C2D_INVALID;
    }
    rebuild = w->count == 0 || radius > w->rmax;
    if (rebuild) {
        size_t k;
        for (k = 0; k < w->count; k++)
            if (w->disk[k].kind != C2D_W_GONE && c2d_w_overlaps(w, x, y, radius, &w->disk[k])) return C2D_INVALID;
    } else {
        const size_t mx = w->mx, my = w->my, cx = c2d_w_cell_1d(x, w->cw, mx), cy = c2d_w_cell_1d(y, w->ch, my);
        size_t k, l;
        for (l = 0; l < 3; l++)
            for (k = 0; k < 3; k++) {
                size_t nx = cx + mx + k - 1, ny = cy + my + l - 1;
                uint32_t j;
                if (!w->periodic && (nx < mx || nx >= 2 * mx || ny < my || ny >= 2 * my)) continue;
                for (j = w->head[(ny % my) * mx + nx % mx]; j != C2D_W_NONE; j = w->disk[j].next)
                    if (c2d_w_overlaps(w, x, y, radius, &w->disk[j])) return C2D_INVALID;
            }
    }
    i = (uint32_t)w->count;
    p = &w->disk[i];
    p->x = x, p->y = y, p->vx = disk->vel.x, p->vy = disk->vel.y, p->t = w->now;
    p->mass = disk->mass, p->radius = radius;
    p->last = -C2D_W_INF;
    p->ax = p->ay = 0;
    p->timer = C2D_W_INF;
    p->count = p->pcount = 0;
    p->partner = 0;
    p->kind = C2D_W_IDLE;
    p->same = 0;
    p->slot = i;
    if (w->entered != NULL) w->entered[i].time = -C2D_W_INF, w->entered[i].sensor = 0, w->entered[i].spare = 0;
    if (w->spin != NULL) w->spin[i] = 0;
    w->heap[i].when = C2D_W_INF;
    w->heap[i].tie = C2D_W_TIE_KIND(C2D_W_IDLE);
    w->heap[i].disk = i;
    w->heap[i].spare = 0;
    w->count++;
    if (index != NULL) *index = i;
    if (rebuild) {
        w->rmax = radius;
        c2d_w_rebuild(w);
    } else {
        c2d_w_cell_insert(w, i, c2d_w_cell_1d(y, w->ch, w->my) * w->mx + c2d_w_cell_1d(x, w->cw, w->mx));
        c2d_w_predict(w, i);
    }
    return C2D_OK;
}

/* ------------------------------------------------------------ events */

/* Tell the caller, who may change velocities, accelerations and timers
 * (not add, remove or advance) meanwhile. */
static void c2d_w_emit(c2d_world *w, const c2d_world_event *ev)
{
    if (w->on_event == NULL) return;
    w->busy = 1;
    w->on_event(w->user, ev);
    w->busy = 0;
}

/* The collapse rule (collide2d_world.h), one place for pairs, walls and
 * statics: an impact is elastic when a disk of it has had collapse_count
 * impacts at this very instant (crowded), its previous impact is less than
 * collapse_time ago, it approaches slower than collapse_speed, or it has
 * closed less than collapse_length since.  vn and the thresholds are
 * scaled by nn, the normal's length (1 for a wall, which scales nothing). */

static int c2d_w_collapses(const c2d_world *w, int crowded, double since, double vn, double nn, double length)
{
    return crowded || since < w->collapse_time || vn < w->collapse_speed * nn || vn * since < length * nn;
}

static void c2d_w_impact_clock(c2d_w_disk *p, double now)
{
    if (p->last == now) {
        p->same++;
    } else {
        p->last = now;
        p->same = 1;
    }
    p->count++;
}

/* ------------------------------------------------------------ resolution */

/* Disk i (body b) as a rough disk: its spin, radius and inertia k m r^2. */
static c2d_disk c2d_w_rough_disk(const c2d_world *w, const c2d_body *b, size_t i)
{
    c2d_disk d;
    const double r = w->disk[i].radius;
    d.pos = b->pos, d.vel = b->vel, d.spin = w->spin[i], d.mass = b->mass, d.radius = r;
    d.inertia = w->inertia_factor * b->mass * r * r;
    return d;
}

/* The rough model's resolution of contact c (spins written on C2D_OK):
 * c2d_collide_rough between disks, c2d_collide_rough_normal against an
 * immovable point for walls and statics. */
static c2d_status c2d_w_rough(c2d_world *w, const c2d_world_contact *c, c2d_body *a, c2d_body *b)
{
    c2d_disk da = c2d_w_rough_disk(w, a, c->a), db;
    c2d_surface s;
    c2d_status r;
    if (c->kind == C2D_WORLD_IMPACT) {
        db = c2d_w_rough_disk(w, b, c->b);
        s = w->surface;
        s.restitution = c->restitution;
        r = c2d_collide_rough(&da, &db, s);
    } else {
        db.pos = b->pos, db.vel.x = db.vel.y = 0, db.spin = 0;
        db.mass = db.inertia = C2D_W_INF, db.radius = 0;
        s = w->wall_surface;
        s.restitution = c->restitution;
        r = c2d_collide_rough_normal(&da, &db, c->normal, s);
    }
    if (r != C2D_OK) return r;
    a->vel = da.vel, w->spin[c->a] = da.spin;
    if (c->kind == C2D_WORLD_IMPACT) b->vel = db.vel, w->spin[c->b] = db.spin;
    return C2D_OK;
}

/* The caller's resolution of contact c, taken (1) only when it says
 * C2D_OK with finite velocities no longer approaching along the normal:
 * so no resolver can hang the world (an approaching pair left so would
 * meet again at once) or put a NaN in it. */
static int c2d_w_caller_resolves(c2d_world *w, c2d_world_resolver fn, const c2d_world_contact *c, c2d_body *a,
                                 c2d_body *b)
{
    c2d_body ta = *a, tb = *b;
    int ok;
    double bx = 0, by = 0;
    if (fn == NULL) return 0;
    w->busy = 2;
    ok = fn(w->user, c, &ta, &tb) == C2D_OK;
    w->busy = 0;
    if (c->kind == C2D_WORLD_IMPACT) bx = tb.vel.x, by = tb.vel.y;
    if (!ok || !c2d_w_finite(ta.vel.x) || !c2d_w_finite(ta.vel.y) || !c2d_w_finite(bx) || !c2d_w_finite(by))
        return 0;
    if ((bx - ta.vel.x) * c->normal.x + (by - ta.vel.y) * c->normal.y < 0) return 0;
    a->vel = ta.vel;
    if (c->kind == C2D_WORLD_IMPACT) b->vel = tb.vel;
    return 1;
}

/* Contact c resolved: by the caller's resolver, else the model's (rough,
 * then smooth should the rough call refuse). */
static c2d_status c2d_w_resolve(c2d_world *w, c2d_world_resolver fn, const c2d_world_contact *c, c2d_body *a,
                                c2d_body *b)
{
    if (c2d_w_caller_resolves(w, fn, c, a, b)) return C2D_OK;
    if (w->spin != NULL && c2d_w_rough(w, c, a, b) == C2D_OK) return C2D_OK;
    if (c->kind == C2D_WORLD_IMPACT) return C2D_W_COLLIDE(a, b, c->restitution);
    return C2D_W_COLLIDE_NORMAL(a, b, c->normal, c->restitution);
}

/* After an event: predict disk i again, unless on_event removed it. */
static void c2d_w_repredict(c2d_world *w, uint32_t i)
{
    if (w->disk[i].kind != C2D_W_GONE) c2d_w_predict(w, i);
}

/* The pair rest rule (collide2d_world.h): disks p (body a) and q (b),
 * touching, pressed together by their accelerations (closing at press /
 * |n| along the unit normal) and parting at sep / |n| after the impact,
 * rebound less than collapse_length high ((sep / |n|)^2 / (2 press / |n|)
 * <= length): they rest on each other.  Their relative normal velocity
 * is taken away, momentum kept (dv_a = +m_b / (m_a + m_b) sep n / |n|^2,
 * dv_b = -m_a / (m_a + m_b) sep n / |n|^2), and each loses the component
 * of its acceleration towards the other (as a disk on a wall loses the
 * one into the wall): 1 if it applies, the velocities in a, b and the
 * accelerations in p, q written. */
static int c2d_w_pair_rests(c2d_w_disk *p, c2d_w_disk *q, c2d_body *a, c2d_body *b, double length)
{
    const double nx = b->pos.x - a->pos.x, ny = b->pos.y - a->pos.y, nn2 = nx * nx + ny * ny;
    const double ap = p->ax * nx + p->ay * ny, aq = q->ax * nx + q->ay * ny, press = ap - aq;
    const double sep = (b->vel.x - a->vel.x) * nx + (b->vel.y - a->vel.y) * ny;
    if (!(press > 0) || !(nn2 > 0) || sep * sep > 2 * press * length * C2D_W_SQRT(nn2)) return 0;
    if (sep > 0) {
        const double ka = b->mass / (a->mass + b->mass) * (sep / nn2), kb = a->mass / (a->mass + b->mass) * (sep / nn2);
        a->vel.x += ka * nx, a->vel.y += ka * ny;
        b->vel.x -= kb * nx, b->vel.y -= kb * ny;
    }
    if (ap > 0) p->ax -= ap / nn2 * nx, p->ay -= ap / nn2 * ny;
    if (aq < 0) q->ax -= aq / nn2 * nx, q->ay -= aq / nn2 * ny;
    return 1;
}

/* The impact event of disk `owner`: stale, or resolved with the lower
 * index as c2d_collide's a (so either disk's copy of the event gives the
 * same bits). */
static void c2d_w_pair(c2d_world *w, uint32_t owner)
{
    c2d_w_disk *d = w->disk;
    const uint32_t partner = d[owner].partner;
    const uint32_t i = owner < partner ? owner : partner, j = owner < partner ? partner : owner;
    c2d_w_disk *p = &d[i], *q = &d[j];
    const double now = w->now, dp = now - p->t, dq = now - q->t;
    double qx, qy, sx = 0, sy = 0, e = w->restitution, length, vqx, vqy;
    int collapsed = 0, resolved;
    c2d_world_contact c;
    c2d_body a, b;
    if (d[partner].count != d[owner].pcount) { /* stale */
        c2d_w_predict(w, owner);
        return;
    }
    if (w->periodic) {
        sx = c2d_w_image(p->cell % w->mx, q->cell % w->mx) * w->width;
        sy = c2d_w_image(p->cell / w->mx, q->cell / w->mx) * w->height;
    }
    qx = c2d_w_at(q->x, q->vx, q->ax, dq), qy = c2d_w_at(q->y, q->vy, q->ay, dq);
    a.pos.x = c2d_w_at(p->x, p->vx, p->ax, dp), a.pos.y = c2d_w_at(p->y, p->vy, p->ay, dp), a.mass = p->mass;
    a.vel.x = c2d_w_vel(p->vx, p->ax, dp), a.vel.y = c2d_w_vel(p->vy, p->ay, dp);
    b.pos.x = qx + sx, b.pos.y = qy + sy, b.mass = q->mass;
    b.vel.x = c2d_w_vel(q->vx, q->ax, dq), b.vel.y = c2d_w_vel(q->vy, q->ay, dq);
    vqx = b.vel.x, vqy = b.vel.y; /* before the impact (the rest rule changes q's acceleration) */
    length = w->collapse_length > 0 ? w->collapse_length : 0x1p-20 * (p->radius < q->radius ? p->radius : q->radius);
    if (e < 1) {
        /* The collapse rule (collide2d_world.h): elastic after collapse_count
         * impacts at this instant, within collapse_time of the last impact,
         * below collapse_speed, or when the pair has closed less than
         * collapse_length since either disk's last impact. */
        const double since = now - (p->last > q->last ? p->last : q->last);
        const double nx = b.pos.x - a.pos.x, ny = b.pos.y - a.pos.y;
        const double vn = -((b.vel.x - a.vel.x) * nx + (b.vel.y - a.vel.y) * ny), nn = C2D_W_SQRT(nx * nx + ny * ny);
        collapsed = c2d_w_collapses(w, c2d_w_crowded(w, p, now) || c2d_w_crowded(w, q, now), since, vn, nn, length);
        if (collapsed) e = 1;
    }
    c.kind = C2D_WORLD_IMPACT, c.time = now, c.a = i, c.b = j;
    c.normal.x = b.pos.x - a.pos.x, c.normal.y = b.pos.y - a.pos.y;
    c.restitution = e, c.collapsed = collapsed;
    resolved = c2d_w_resolve(w, w->resolve_impact, &c, &a, &b) == C2D_OK;
    /* Resting (refused or not): only where accelerations press the pair. */
    if (w->accel && c2d_w_pair_rests(p, q, &a, &b, length)) resolved = 1;
    if (resolved) {
        w->stats.virial += ((b.pos.x - a.pos.x) * (b.vel.x - vqx) + (b.pos.y - a.pos.y) * (b.vel.y - vqy)) * q->mass;
        p->x = a.pos.x, p->y = a.pos.y, p->vx = a.vel.x, p->vy = a.vel.y, p->t = now;
        q->x = qx, q->y = qy, q->vx = b.vel.x, q->vy = b.vel.y, q->t = now;
        c2d_w_impact_clock(p, now);
        c2d_w_impact_clock(q, now);
        w->stats.collisions++;
        if (w->on_event != NULL) {
            c2d_world_event ev;
            ev.kind = C2D_WORLD_IMPACT, ev.time = now, ev.a = i, ev.b = j;
            ev.impulse.x = (b.vel.x - vqx) * q->mass, ev.impulse.y = (b.vel.y - vqy) * q->mass;
            c2d_w_emit(w, &ev);
        }
        c2d_w_repredict(w, i);
        c2d_w_repredict(w, j);
    } else {
        c2d_w_predict(w, owner);
    }
}

/* Disk i meets static k: c2d_collide_normal against an immovable body at
 * the contact point, the static's restitution (elastic by the collapse
 * rule, as at a wall). */
static void c2d_w_static_hit(c2d_world *w, uint32_t i, size_t k)
{
    c2d_w_disk *p = &w->disk[i];
    const c2d_w_static *st = &w->stat[k];
    const double now = w->now, dt = now - p->t;
    double e = st->restitution;
    int collapsed = 0;
    c2d_world_contact c;
    c2d_body a, b;
    c2d_vec2 n;
    a.pos.x = c2d_w_at(p->x, p->vx, p->ax, dt), a.pos.y = c2d_w_at(p->y, p->vy, p->ay, dt), a.mass = p->mass;
    a.vel.x = c2d_w_vel(p->vx, p->ax, dt), a.vel.y = c2d_w_vel(p->vy, p->ay, dt);
    c2d_w_static_contact(st, a.pos.x, a.pos.y, &b.pos, &n);
    b.vel.x = b.vel.y = 0, b.mass = C2D_W_INF;
    if (e < 1) { /* the collapse rule, as for a wall */
        /* n points towards the static: vn > 0 approaching */
        const double nn = C2D_W_SQRT(n.x * n.x + n.y * n.y), vn = a.vel.x * n.x + a.vel.y * n.y;
        const double length = w->collapse_length > 0 ? w->collapse_length : 0x1p-20 * p->radius;
        const double since = now - p->last;
        collapsed = c2d_w_collapses(w, c2d_w_crowded(w, p, now), since, vn, nn, length);
        if (collapsed) e = 1;
    }
    c.kind = C2D_WORLD_STATIC, c.time = now, c.a = i, c.b = k;
    c.normal = n, c.restitution = e, c.collapsed = collapsed;
    {
        const double vx0 = a.vel.x, vy0 = a.vel.y;
        if (c2d_w_resolve(w, w->resolve_static, &c, &a, &b) == C2D_OK) {
            p->x = a.pos.x, p->y = a.pos.y, p->vx = a.vel.x, p->vy = a.vel.y, p->t = now;
            c2d_w_impact_clock(p, now);
            w->stats.wall_collisions++;
            if (w->on_event != NULL) {
                c2d_world_event ev;
                ev.kind = C2D_WORLD_STATIC, ev.time = now, ev.a = i, ev.b = k;
                ev.impulse.x = (a.vel.x - vx0) * p->mass, ev.impulse.y = (a.vel.y - vy0) * p->mass;
                c2d_w_emit(w, &ev);
            }
        }
    }
    c2d_w_repredict(w, i);
}

/* Disk i's centre entered sensor k: remembered (c2d_w_predict_sensor),
 * told, nothing resolved. */
static void c2d_w_sensor(c2d_world *w, uint32_t i, size_t k)
{
    w->entered[i].time = w->now, w->entered[i].sensor = (uint32_t)(k + 1);
    if (w->on_event != NULL) {
        c2d_world_event ev;
        ev.kind = C2D_WORLD_SENSOR, ev.time = w->now, ev.a = i, ev.b = k;
        ev.impulse.x = ev.impulse.y = 0;
        c2d_w_emit(w, &ev);
    }
    c2d_w_repredict(w, i);
}

/* A box wall met by a caller's resolver or the rough model, at the snapped
 * centre (x, y); 1 if it resolved the contact (the velocity written). */
static int c2d_w_wall_resolved(c2d_world *w, uint32_t i, double x, double y, double e, int collapsed)
{
    c2d_w_disk *p = &w->disk[i];
    const uint32_t side = p->partner;
    c2d_world_contact c;
    c2d_body a, b;
    a.pos.x = x, a.pos.y = y, a.vel.x = p->vx, a.vel.y = p->vy, a.mass = p->mass;
    b.pos.x = side == 0 ? 0 : side == 1 ? w->width : x;
    b.pos.y = side == 2 ? 0 : side == 3 ? w->height : y;
    b.vel.x = b.vel.y = 0, b.mass = C2D_W_INF;
    c.kind = C2D_WORLD_WALL, c.time = w->now, c.a = i, c.b = side;
    c.normal.x = side == 0 ? -1.0 : side == 1 ? 1.0 : 0.0;
    c.normal.y = side == 2 ? -1.0 : side == 3 ? 1.0 : 0.0;
    c.restitution = e, c.collapsed = collapsed;
    if (!c2d_w_caller_resolves(w, w->resolve_wall, &c, &a, &b) &&
        (w->spin == NULL || c2d_w_rough(w, &c, &a, &b) != C2D_OK))
        return 0;
    p->vx = a.vel.x, p->vy = a.vel.y;
    return 1;
}

static void c2d_w_wall(c2d_world *w, uint32_t i)
{
    c2d_w_disk *p = &w->disk[i];
    const double now = w->now, dt = now - p->t, since = now - p->last;
    double x = c2d_w_at(p->x, p->vx, p->ax, dt), y = c2d_w_at(p->y, p->vy, p->ay, dt), e = w->wall_restitution, vn, an;
    const double vx0 = c2d_w_vel(p->vx, p->ax, dt), vy0 = c2d_w_vel(p->vy, p->ay, dt);
    const double length = w->collapse_length > 0 ? w->collapse_length : 0x1p-20 * p->radius;
    double *v, *acc;
    int collapsed = 0;
    if (p->partner >= 4) {
        const size_t k = p->partner - 4u;
        if (w->stat[k].shape == C2D_W_SENSOR) c2d_w_sensor(w, i, k);
        else c2d_w_static_hit(w, i, k);
        return;
    }
    p->vx = vx0, p->vy = vy0;
    v = p->partner < 2 ? &p->vx : &p->vy;
    acc = p->partner < 2 ? &p->ax : &p->ay;
    vn = *v < 0 ? -*v : *v;
    an = p->partner % 2 == 0 ? -*acc : *acc; /* > 0: pressing into the wall */
    if (e < 1) { /* the collapse rule, as for a pair (the wall's "radius" 0) */
        collapsed = c2d_w_collapses(w, c2d_w_crowded(w, p, now), since, vn, 1.0, length);
        if (collapsed) e = 1;
    }
    switch (p->partner) {
    case 0: x = p->radius; break;
    case 1: x = w->width - p->radius; break;
    case 2: y = p->radius; break;
    default: y = w->height - p->radius; break;
    }
    /* The rest rule: pressed into the wall and rebounding less than
     * collapse_length high ((e vn)^2 / (2 an)), the disk stays on it: its
     * normal velocity and acceleration become 0. */
    if (c2d_w_wall_resolved(w, i, x, y, e, collapsed)) {
        if (an > 0 && *v * *v <= 2 * an * length) *v = 0, *acc = 0;
    } else if (an > 0 && (e * vn) * (e * vn) <= 2 * an * length) {
        *v = 0, *acc = 0;
    } else if (p->partner % 2 == 0 ? *v < 0 : *v > 0) {
        *v = -e * *v; /* (not one already leaving) */
    }
    p->x = x, p->y = y, p->t = now;
    c2d_w_impact_clock(p, now);
    w->stats.wall_collisions++;
    if (w->on_event != NULL) {
        c2d_world_event ev;
        ev.kind = C2D_WORLD_WALL, ev.time = now, ev.a = i, ev.b = p->partner;
        ev.impulse.x = (p->vx - vx0) * p->mass, ev.impulse.y = (p->vy - vy0) * p->mass;
        c2d_w_emit(w, &ev);
    }
    c2d_w_repredict(w, i);
}

/* A disk's timer: cleared, then told (the callback may set it again). */
static void c2d_w_timer(c2d_world *w, uint32_t i)
{
    w->disk[i].timer = C2D_W_INF;
    if (w->on_event != NULL) {
        c2d_world_event ev;
        ev.kind = C2D_WORLD_TIMER, ev.time = w->now, ev.a = i, ev.b = 0;
        ev.impulse.x = ev.impulse.y = 0;
        c2d_w_emit(w, &ev);
    }
    c2d_w_repredict(w, i);
}

static void c2d_w_cross(c2d_world *w, uint32_t i)
{
    c2d_w_disk *p = &w->disk[i];
    size_t cx = p->cell % w->mx, cy = p->cell / w->mx;
    c2d_w_cell_remove(w, i);
    switch (p->partner) {
    case 0:
        if (cx == 0) cx = w->mx, p->x += w->width;
        cx--;
        break;
    case 1:
        cx++;
        if (cx == w->mx) cx = 0, p->x -= w->width;
        break;
    case 2:
        if (cy == 0) cy = w->my, p->y += w->height;
        cy--;
        break;
    default:
        cy++;
        if (cy == w->my) cy = 0, p->y -= w->height;
        break;
    }
    c2d_w_cell_insert(w, i, cy * w->mx + cx);
    c2d_w_predict(w, i);
}

c2d_status c2d_world_advance(c2d_world *world, double t)
{
    c2d_world *w = world;
    if (w == NULL || w->busy || !c2d_w_finite(t) || !(t >= w->now)) return C2D_INVALID;
    while (w->count > 0) {
        uint32_t i = w->heap[0].disk;
        c2d_w_disk *p = &w->disk[i];
        if (!(w->heap[0].when <= t)) break;
        w->now = w->heap[0].when;
        w->stats.events++;
        switch (p->kind) {
        case C2D_W_PAIR: c2d_w_pair(w, i); break;
        case C2D_W_WALL: c2d_w_wall(w, i); break;
        case C2D_W_TIMER: c2d_w_timer(w, i); break;
        default: c2d_w_cross(w, i); break;
        }
    }
    w->now = t;
    w->stats.time = t;
    return C2D_OK;
}

c2d_status c2d_world_get(const c2d_world *world, size_t index, c2d_body *disk)
{
    const c2d_w_disk *p;
    double dt, x, y;
    if (world == NULL || disk == NULL || index >= world->count) return C2D_INVALID;
    p = &world->disk[index];
    if (p->kind == C2D_W_GONE) return C2D_INVALID;
    dt = world->now - p->t;
    x = c2d_w_at(p->x, p->vx, p->ax, dt), y = c2d_w_at(p->y, p->vy, p->ay, dt);
    if (world->periodic) {
        if (x < 0) x += world->width;
        if (x >= world->width) x -= world->width;
        if (y < 0) y += world->height;
        if (y >= world->height) y -= world->height;
    }
    disk->pos.x = x, disk->pos.y = y;
    disk->vel.x = c2d_w_vel(p->vx, p->ax, dt), disk->vel.y = c2d_w_vel(p->vy, p->ay, dt);
    disk->mass = p->mass;
    return C2D_OK;
}

c2d_status c2d_world_set_velocity(c2d_world *world, size_t index, c2d_vec2 velocity)
{
    c2d_w_disk *p;
    double dt;
    if (world == NULL || world->busy > 1 || index >= world->count || !c2d_w_finite(velocity.x) ||
        !c2d_w_finite(velocity.y))
        return C2D_INVALID;
    p = &world->disk[index];
    if (p->kind == C2D_W_GONE) return C2D_INVALID;
    dt = world->now - p->t;
    p->x = c2d_w_at(p->x, p->vx, p->ax, dt), p->y = c2d_w_at(p->y, p->vy, p->ay, dt), p->t = world->now;
    p->vx = velocity.x, p->vy = velocity.y;
    p->count++; /* the partners' predictions with it are stale */
    c2d_w_predict(world, (uint32_t)index);
    return C2D_OK;
}

c2d_status c2d_world_set_acceleration(c2d_world *world, size_t index, c2d_vec2 acceleration)
{
    c2d_w_disk *p;
    double dt, vx, vy;
    if (world == NULL || world->busy > 1 || index >= world->count || !c2d_w_finite(acceleration.x) ||
        !c2d_w_finite(acceleration.y))
        return C2D_INVALID;
    p = &world->disk[index];
    if (p->kind == C2D_W_GONE) return C2D_INVALID;
    dt = world->now - p->t;
    vx = c2d_w_vel(p->vx, p->ax, dt), vy = c2d_w_vel(p->vy, p->ay, dt);
    p->x = c2d_w_at(p->x, p->vx, p->ax, dt), p->y = c2d_w_at(p->y, p->vy, p->ay, dt), p->t = world->now;
    p->vx = vx, p->vy = vy;
    p->ax = acceleration.x, p->ay = acceleration.y;
    if (acceleration.x != 0 || acceleration.y != 0) world->accel = 1;
    p->count++;
    c2d_w_predict(world, (uint32_t)index);
    return C2D_OK;
}

static c2d_status c2d_w_add_static(c2d_world *w, const c2d_w_static *st, size_t *index)
{
    w->stat[w->nstatic] = *st;
    if (index != NULL) *index = w->nstatic;
    w->nstatic++;
    if (w->mx > 0) {
        size_t i;
        for (i = 0; i < w->count; i++)
            if (w->disk[i].kind != C2D_W_GONE) c2d_w_predict(w, (uint32_t)i);
    }
    return C2D_OK;
}

c2d_status c2d_world_add_segment(c2d_world *world, c2d_vec2 a, c2d_vec2 b, double restitution, size_t *index)
{
    c2d_w_static st;
    double dx, dy;
    if (world == NULL || world->busy || world->nstatic >= world->scapacity) return C2D_INVALID;
    if (!c2d_w_finite(a.x) || !c2d_w_finite(a.y) || !c2d_w_finite(b.x) || !c2d_w_finite(b.y)) return C2D_INVALID;
    if (!(restitution >= 0 && restitution <= 1)) return C2D_INVALID;
    dx = b.x - a.x, dy = b.y - a.y;
    st.len = C2D_W_SQRT(dx * dx + dy * dy);
    if (!(st.len > 0) || !c2d_w_finite(st.len)) return C2D_INVALID;
    st.ax = a.x, st.ay = a.y, st.bx = b.x, st.by = b.y;
    st.nx = -dy / st.len, st.ny = dx / st.len;
    st.radius = 0, st.restitution = restitution, st.shape = C2D_W_SEGMENT, st.spare = 0;
    return c2d_w_add_static(world, &st, index);
}

c2d_status c2d_world_add_circle(c2d_world *world, c2d_vec2 centre, double radius, double restitution, size_t *index)
{
    c2d_w_static st;
    if (world == NULL || world->busy || world->nstatic >= world->scapacity) return C2D_INVALID;
    if (!c2d_w_finite(centre.x) || !c2d_w_finite(centre.y) || !c2d_w_finite(radius) || !(radius > 0))
        return C2D_INVALID;
    if (!(restitution >= 0 && restitution <= 1)) return C2D_INVALID;
    st.ax = st.bx = centre.x, st.ay = st.by = centre.y;
    st.nx = st.ny = st.len = 0;
    st.radius = radius, st.restitution = restitution, st.shape = C2D_W_CIRCLE, st.spare = 0;
    return c2d_w_add_static(world, &st, index);
}

c2d_status c2d_world_add_sensor(c2d_world *world, c2d_vec2 centre, double radius, size_t *index)
{
    c2d_w_static st;
    if (world == NULL || world->busy || world->nstatic >= world->scapacity) return C2D_INVALID;
    if (!c2d_w_finite(centre.x) || !c2d_w_finite(centre.y) || !c2d_w_finite(radius) || !(radius > 0))
        return C2D_INVALID;
    st.ax = st.bx = centre.x, st.ay = st.by = centre.y;
    st.nx = st.ny = st.len = 0;
    st.radius = radius, st.restitution = 0, st.shape = C2D_W_SENSOR, st.spare = 0;
    return c2d_w_add_static(world, &st, index);
}

c2d_status c2d_world_set_spin(c2d_world *world, size_t index, double spin)
{
    if (world == NULL || world->busy > 1 || world->spin == NULL || index >= world->count || !c2d_w_finite(spin))
        return C2D_INVALID;
    if (world->disk[index].kind == C2D_W_GONE) return C2D_INVALID;
    world->spin[index] = spin;
    return C2D_OK;
}

c2d_status c2d_world_get_spin(const c2d_world *world, size_t index, double *spin)
{
    if (world == NULL || spin == NULL || world->spin == NULL || index >= world->count) return C2D_INVALID;
    if (world->disk[index].kind == C2D_W_GONE) return C2D_INVALID;
    *spin = world->spin[index];
    return C2D_OK;
}

c2d_status c2d_world_get_acceleration(const c2d_world *world, size_t index, c2d_vec2 *acceleration)
{
    const c2d_w_disk *p;
    if (world == NULL || acceleration == NULL || index >= world->count) return C2D_INVALID;
    p = &world->disk[index];
    if (p->kind == C2D_W_GONE) return C2D_INVALID;
    acceleration->x = p->ax, acceleration->y = p->ay;
    return C2D_OK;
}

c2d_status c2d_world_set_timer(c2d_world *world, size_t index, double t)
{
    c2d_w_disk *p;
    if (world == NULL || world->busy > 1 || index >= world->count || t != t || !(t >= world->now)) return C2D_INVALID;
    p = &world->disk[index];
    if (p->kind == C2D_W_GONE) return C2D_INVALID;
    p->timer = t < C2D_W_INF ? t : C2D_W_INF;
    c2d_w_predict(world, (uint32_t)index);
    return C2D_OK;
}

c2d_status c2d_world_remove(c2d_world *world, size_t index)
{
    c2d_w_disk *p;
    if (world == NULL || world->busy > 1 || index >= world->count) return C2D_INVALID;
    p = &world->disk[index];
    if (p->kind == C2D_W_GONE) return C2D_INVALID;
    c2d_w_cell_remove(world, (uint32_t)index);
    p->cell = C2D_W_NONE, p->next = C2D_W_NONE;
    p->kind = C2D_W_GONE;
    p->count++;
    c2d_w_heap_fix(world, (uint32_t)index, C2D_W_INF, C2D_W_TIE_KIND(C2D_W_IDLE) | (uint64_t)index);
    return C2D_OK;
}

void c2d_world_get_stats(const c2d_world *world, c2d_world_stats *stats)
{
    if (stats == NULL) return;
    if (world == NULL) {
        stats->collisions = stats->wall_collisions = stats->events = 0;
        stats->time = 0;
        stats->virial = 0;
        return;
    }
    *stats = world->stats;
}

#endif /* !C2D_NO_DOUBLE && !C2D_NO_WORLD */
