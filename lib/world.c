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

/* The hot candidate test, inlined into the cell scan (a call per
 * candidate was a fifth of its cost). */
#ifdef __GNUC__
#define C2D_W_HOT static __inline__ __attribute__((always_inline))
#else
#define C2D_W_HOT static
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
/* The partners of a C2D_W_CELL event: a cell side 0..3 (-x, +x, -y, +y),
 * the periodic rebase, or a side of the caller broadphase's box. */
enum { C2D_W_REBASE = 4, C2D_W_BOX = 5 };
/* A periodic disk's reference state is moved on (rebased) before its centre
 * has gone 1/24 of the box's smaller side from it: then the nearest image
 * of a pair at the later of their state times is the image they meet in
 * (derivation at c2d_w_pair_start). */
#define C2D_W_REBASE_FRACTION (1.0 / 24.0)
/* A caller's box is this much wider than radius + margin, for the rounding
 * of the centre's path against the box's sides. */
#define C2D_W_BOX_SLACK (1.0 + 1.0 / 1048576.0)

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
    uint32_t side;          /* its event is the cell crossing of this side (0..3), else C2D_W_NONE:
                               its event is the one of kind/partner (kept through crossings) */
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

/* A window entry: a disk's next event, its time and its tie key
 * (kind << 62 | lower index << 31 | higher index). */
typedef struct c2d_w_entry {
    double when;
    uint64_t tie;
    uint32_t disk, spare;
} c2d_w_entry;

/* A disk's place in the event queue: its event's time and tie key, its
 * neighbours in its bucket's or the overflow's list, and where it is (a
 * bucket, C2D_W_Q_WIN, C2D_W_Q_OVF or C2D_W_NONE: no event). */
typedef struct c2d_w_node {
    double when;
    uint64_t tie;
    double mwhen; /* the time of the disk's event other than a crossing (its kind, partner) */
    uint32_t prev, next, where, slot; /* slot: its place in the window while there */
} c2d_w_node;
#define C2D_W_Q_WIN 0xFFFFFFFEu
#define C2D_W_Q_OVF 0xFFFFFFFDu
#define C2D_W_PER_DAY 2.0 /* events per day of the calendar, on average */

struct c2d_world {
    c2d_w_disk *disk;
    double *box;       /* with a caller's broadphase: each disk's box centre (x, y) */
    c2d_w_entry *win;  /* the window: a binary min-heap on (when, tie, disk) */
    c2d_w_node *node;  /* each disk's place in the queue */
    uint32_t *bucket;  /* the calendar: each day's unsorted list, nbucket (a power of 2) days a round */
    size_t nwin, nbucket, inbuckets, inovf;
    uint32_t ovf;      /* the overflow's list: days beyond the round */
    uint64_t k0;       /* the current day: the window holds it and all before */
    uint64_t pull_day; /* the day the overflow is next pulled into the buckets */
    double day;        /* a day's length (infinite until the first measure) */
    double ovf_min;    /* <= every time in the overflow */
    double since;      /* the time of the last measure */
    unsigned long long pops; /* events since */
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
    int caller;      /* the caller's broadphase (bp) instead of the cells */
    c2d_world_broadphase bp;
    double rebase;   /* periodic: how far a centre goes from its reference before a rebase */
    double hmax;     /* the largest half-size of a box given to the caller's broadphase */
    c2d_world_stats stats;
};

/* ------------------------------------------------------------ layout */

/* A kind's place in the tie key (2 bits: an idle or gone disk shares the
 * timer's, never due). */
#define C2D_W_TIE_KIND(k) ((uint64_t)((k) > 3u ? 3u : (k)) << 62)

/* A coordinate and a velocity component dt after the state's time. */
static double c2d_w_at(double x, double v, double a, double dt) { return x + (v + 0.5 * a * dt) * dt; }
static double c2d_w_vel(double v, double a, double dt) { return v + a * dt; }

/* A coordinate of a periodic box back in [0, side) (a stored position goes
 * at most a rebase's distance out; x - side is then exact, Sterbenz). */
static double c2d_w_wrap(double x, double side)
{
    if (x < 0) {
        x += side;
        return x < side ? x : 0;
    }
    return x < side ? x : x - side;
}


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
    if (d->broadphase != NULL) {
        const c2d_world_broadphase *b = d->broadphase;
        if (b->insert == NULL || b->move == NULL || b->remove == NULL || b->query == NULL) return 0;
        if (!(b->margin >= 0) || !c2d_w_finite(b->margin)) return 0;
    }
    return 1;
}

/* Days in the calendar's round: the power of 2 at or above the capacity. */
static size_t c2d_w_buckets(size_t capacity)
{
    size_t b = 16;
    while (b < capacity) b *= 2;
    return b;
}

static size_t c2d_w_budget(const c2d_world_desc *d)
{
    return d->broadphase != NULL ? 0 : C2D_W_CELLS_PER_DISK * d->capacity + 16;
}

/* Offsets of the disks, the queue (window, nodes, calendar), the cells
 * (or the caller broadphase's box centres), the statics, the sensor
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
    size_t budget, off = C2D_W_ROUND8(sizeof(struct c2d_world)) + 56, n;
    if (capacity > (top - 16) / C2D_W_CELLS_PER_DISK / 2) return 0;
    budget = desc->broadphase != NULL ? 4 * capacity : c2d_w_budget(desc); /* boxes: 2 doubles = 4 cells' bytes */
    o->disks = off; /* the disks start on a 64-byte boundary within the 56 bytes before */
    if (capacity > (top - off) / sizeof(c2d_w_disk)) return 0;
    off += capacity * sizeof(c2d_w_disk);
    o->heap = off;
    if (capacity > (top - off) / (sizeof(c2d_w_entry) + sizeof(c2d_w_node) + 2 * sizeof(uint32_t))) return 0;
    n = capacity * (sizeof(c2d_w_entry) + sizeof(c2d_w_node)) + c2d_w_buckets(capacity) * sizeof(uint32_t);
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
        w->win = (c2d_w_entry *)(void *)(m + o.heap - back);
        w->node = (c2d_w_node *)(void *)(m + o.heap - back + desc->capacity * sizeof(c2d_w_entry));
        w->bucket = (uint32_t *)(void *)(m + o.heap - back + desc->capacity * (sizeof(c2d_w_entry) + sizeof(c2d_w_node)));
        w->head = (uint32_t *)(void *)(m + o.cells - back);
        w->box = (double *)(void *)(m + o.cells - back);
        w->stat = (c2d_w_static *)(void *)(m + o.stat - back);
        w->entered = desc->statics > 0 ? (c2d_w_entered *)(void *)(m + o.entered - back) : NULL;
        w->spin = desc->model == C2D_WORLD_ROUGH ? (double *)(void *)(m + o.spin - back) : NULL;
    }
    c2d_w_init_resolvers(w, desc);
    w->capacity = desc->capacity;
    w->scapacity = desc->statics;
    w->nstatic = 0;
    w->count = 0;
    w->budget = c2d_w_budget(desc);
    w->nwin = w->inbuckets = w->inovf = 0;
    w->nbucket = c2d_w_buckets(desc->capacity);
    w->ovf = C2D_W_NONE;
    w->k0 = 0;
    w->pull_day = 0;
    w->day = C2D_W_INF; /* one day: everything in the window until measured (the buckets untouched) */
    w->ovf_min = C2D_W_INF;
    w->since = 0;
    w->pops = 0;
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
    w->caller = desc->broadphase != NULL;
    if (w->caller) {
        w->bp = *desc->broadphase;
    } else {
        w->bp.insert = NULL, w->bp.move = NULL, w->bp.remove = NULL, w->bp.query = NULL;
        w->bp.user = NULL, w->bp.margin = 0;
    }
    w->rebase = C2D_W_REBASE_FRACTION * (desc->width < desc->height ? desc->width : desc->height);
    w->cw = w->ch = 0;
    w->rmax = 0;
    w->hmax = 0;
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

/* ------------------------------------------------------------ queue */

/* (when, tie, disk): a total order, so the events come out in the same
 * order whatever the queue's shape (both disks of a pair may hold the same
 * event: the lower index's copy first). */
static int c2d_w_before(const c2d_w_entry *a, const c2d_w_entry *b)
{
    return a->when < b->when || (a->when == b->when && (a->tie < b->tie || (a->tie == b->tie && a->disk < b->disk)));
}

/* The window: a binary heap of the events of the current day (and any
 * earlier), disk i at w->disk[i].slot. */
static void c2d_w_win_place(c2d_world *w, size_t s, c2d_w_entry e)
{
    c2d_w_entry *h = w->win;
    c2d_w_node *n = w->node;
    const size_t count = w->nwin;
    while (s > 0) {
        size_t up = (s - 1) / 2;
        if (!c2d_w_before(&e, &h[up])) break;
        h[s] = h[up];
        n[h[s].disk].slot = (uint32_t)s;
        s = up;
    }
    for (;;) {
        size_t l = 2 * s + 1, best = l;
        if (l >= count) break;
        if (l + 1 < count && c2d_w_before(&h[l + 1], &h[l])) best = l + 1;
        if (!c2d_w_before(&h[best], &e)) break;
        h[s] = h[best];
        n[h[s].disk].slot = (uint32_t)s;
        s = best;
    }
    h[s] = e;
    n[e.disk].slot = (uint32_t)s;
}

static void c2d_w_win_push(c2d_world *w, uint32_t i)
{
    c2d_w_entry e;
    e.when = w->node[i].when, e.tie = w->node[i].tie, e.disk = i, e.spare = 0;
    w->node[i].where = C2D_W_Q_WIN;
    w->nwin++;
    c2d_w_win_place(w, w->nwin - 1, e);
}

static void c2d_w_win_remove(c2d_world *w, uint32_t i)
{
    const size_t s = w->node[i].slot;
    w->nwin--;
    if (s < w->nwin) c2d_w_win_place(w, s, w->win[w->nwin]);
}

static void c2d_w_link(c2d_world *w, uint32_t *head, uint32_t i, uint32_t where)
{
    c2d_w_node *n = w->node;
    n[i].prev = C2D_W_NONE, n[i].next = *head, n[i].where = where;
    if (*head != C2D_W_NONE) n[*head].prev = i;
    *head = i;
}

static void c2d_w_unlink(c2d_world *w, uint32_t *head, uint32_t i)
{
    c2d_w_node *n = w->node;
    if (n[i].prev != C2D_W_NONE) n[n[i].prev].next = n[i].next;
    else *head = n[i].next;
    if (n[i].next != C2D_W_NONE) n[n[i].next].prev = n[i].prev;
}

/* The day of time t (days are w->day long; a time too far for 2^62 days
 * is in the last, which only the overflow holds). */
static uint64_t c2d_w_day(const c2d_world *w, double t)
{
    const double q = t / w->day;
    return q < 0x1p62 ? (uint64_t)q : (uint64_t)-1;
}

/* File disk i's event (node[i].when, tie): the window for the current day
 * and before, the day's bucket within the calendar's round, else the
 * overflow (its earliest time kept as a bound: ovf_min <= every time in
 * it).  No event (time infinite): nowhere. */
static void c2d_w_q_insert(c2d_world *w, uint32_t i)
{
    const double when = w->node[i].when;
    uint64_t day;
    if (!(when < C2D_W_INF)) {
        w->node[i].where = C2D_W_NONE;
        return;
    }
    day = c2d_w_day(w, when);
    if (day <= w->k0) {
        c2d_w_win_push(w, i);
    } else if (day < w->k0 + w->nbucket) {
        const uint32_t b = (uint32_t)(day & (w->nbucket - 1));
        c2d_w_link(w, &w->bucket[b], i, b);
        w->inbuckets++;
    } else {
        c2d_w_link(w, &w->ovf, i, C2D_W_Q_OVF);
        w->inovf++;
        if (when < w->ovf_min) w->ovf_min = when;
    }
}

static void c2d_w_q_remove(c2d_world *w, uint32_t i)
{
    const uint32_t where = w->node[i].where;
    if (where == C2D_W_NONE) return;
    if (where == C2D_W_Q_WIN) {
        c2d_w_win_remove(w, i);
    } else if (where == C2D_W_Q_OVF) {
        c2d_w_unlink(w, &w->ovf, i);
        w->inovf--;
    } else {
        c2d_w_unlink(w, &w->bucket[where], i);
        w->inbuckets--;
    }
    w->node[i].where = C2D_W_NONE;
}

/* Disk i's event is now (when, tie). */
static void c2d_w_q_set(c2d_world *w, uint32_t i, double when, uint64_t tie)
{
    c2d_w_q_remove(w, i);
    w->node[i].when = when, w->node[i].tie = tie;
    c2d_w_q_insert(w, i);
}

/* Overflow events whose day the calendar's round now reaches go to their
 * buckets (all of them when `all`); ovf_min is recomputed.  Done every
 * half round (pull_day): an event left has a day beyond k0 + nbucket, so
 * after the next pull, before its bucket is drained; the overflow is
 * scanned once per half round. */
static void c2d_w_q_pull(c2d_world *w, int all)
{
    uint32_t i = w->ovf;
    w->ovf_min = C2D_W_INF;
    w->pull_day = w->k0 + w->nbucket / 2;
    while (i != C2D_W_NONE) {
        const uint32_t next = w->node[i].next;
        const uint64_t day = c2d_w_day(w, w->node[i].when);
        if (all || day < w->k0 + w->nbucket) {
            c2d_w_unlink(w, &w->ovf, i);
            w->inovf--;
            if (all) c2d_w_win_push(w, i);
            else c2d_w_q_insert(w, i);
        } else if (w->node[i].when < w->ovf_min) {
            w->ovf_min = w->node[i].when;
        }
        i = next;
    }
}

/* The disk with the earliest event (C2D_W_NONE for none): the window's
 * top, after moving on day by day (each day's bucket into the window)
 * while the window is empty. */
static uint32_t c2d_w_q_top(c2d_world *w)
{
    while (w->nwin == 0) {
        uint32_t i;
        if (w->inbuckets == 0) {
            uint64_t day;
            if (w->inovf == 0) return C2D_W_NONE;
            day = c2d_w_day(w, w->ovf_min);
            if (day == (uint64_t)-1) {
                c2d_w_q_pull(w, 1);
                break;
            }
            if (day > w->k0 + 1) w->k0 = day - 1; /* skip the empty days */
            w->pull_day = w->k0 + 1;
        }
        w->k0++;
        if (w->inovf > 0 && w->k0 >= w->pull_day) c2d_w_q_pull(w, 0);
        {
            uint32_t *head = &w->bucket[w->k0 & (w->nbucket - 1)];
            while ((i = *head) != C2D_W_NONE) {
                *head = w->node[i].next;
                w->inbuckets--;
                c2d_w_win_push(w, i);
            }
        }
    }
    return w->win[0].disk;
}

/* Days of a new length (events per day about C2D_W_PER_DAY at the rate
 * measured): every event filed anew, O(N + buckets). */
static void c2d_w_q_rebuild(c2d_world *w, double day)
{
    size_t k;
    w->day = day;
    w->k0 = c2d_w_day(w, w->now);
    w->pull_day = w->k0 + w->nbucket / 2;
    for (k = 0; k < w->nbucket; k++) w->bucket[k] = C2D_W_NONE;
    w->ovf = C2D_W_NONE, w->ovf_min = C2D_W_INF;
    w->nwin = w->inbuckets = w->inovf = 0;
    for (k = 0; k < w->count; k++)
        if (w->node[k].where != C2D_W_NONE) c2d_w_q_insert(w, (uint32_t)k);
}

/* After each event: every nbucket events, the day's length measured
 * against the rate of events (no effect on their order). */
static void c2d_w_q_count(c2d_world *w)
{
    if (++w->pops < w->nbucket && w->pops < 4096) return;
    {
        const double span = w->now - w->since, day = span / (double)w->pops * C2D_W_PER_DAY;
        if (day > 0 && day < C2D_W_INF && day > 1e-300 && (!(day * 2 > w->day) || day > 2 * w->day)) c2d_w_q_rebuild(w, day);
    }
    w->pops = 0, w->since = w->now;
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

C2D_W_HOT void c2d_w_consider(c2d_w_best *b, double when, uint32_t kind, uint32_t partner, uint64_t pcount)
{
    if (when < b->when || (when == b->when && (kind < b->kind || (kind == b->kind && partner < b->partner)))) {
        b->when = when;
        b->kind = kind;
        b->partner = partner;
        b->pcount = pcount;
    }
}

/* The cells around coordinate c of m along one axis, each once (a
 * periodic grid wraps). */
C2D_W_HOT size_t c2d_w_neighbours(size_t c, size_t m, int periodic, size_t *cell)
{
    size_t n = 0;
    if (c > 0) cell[n++] = c - 1;
    else if (periodic) cell[n++] = m - 1;
    cell[n++] = c;
    if (c + 1 < m) cell[n++] = c + 1;
    else if (periodic) cell[n++] = 0;
    return n;
}

/* A caller broadphase's margin for disk p. */
static double c2d_w_margin(const c2d_world *w, const c2d_w_disk *p)
{
    return w->bp.margin > 0 ? w->bp.margin : 0.5 * p->radius;
}

/* The first time >= now at which a disk at x (time t) with speed v reaches
 * `to`. */
C2D_W_HOT double c2d_w_reach(double t, double x, double v, double to, double now)
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
    c2d_body ref;
    c2d_vec2 acc, zero;
    double when;
    if (dd < rr || (en->sensor == k + 1 && dd <= rr * (1 + 0x1p-25))) return;
    b.pos.x = st->ax, b.pos.y = st->ay, b.vel.x = b.vel.y = 0, b.mass = C2D_W_INF;
    ref.pos.x = p->x, ref.pos.y = p->y, ref.vel.x = p->vx, ref.vel.y = p->vy, ref.mass = p->mass;
    acc.x = p->ax, acc.y = p->ay, zero.x = zero.y = 0;
    /* From the reference state, as every static (the time then depends on
     * the state alone); an entry found there before now is one already
     * passed: a straight path enters a circle once, a curved one may enter
     * again, sought from now. */
    if (acc.x == 0 && acc.y == 0) {
        r = C2D_W_TOI(&ref, &b, st->radius, &toi);
        if (r != C2D_OK || !(p->t + toi >= w->now)) return;
        when = p->t + toi;
    } else {
        r = C2D_W_TOI_ACCEL(&ref, acc, &b, zero, st->radius, p->timer - p->t, &toi);
        if (r == C2D_OK && p->t + toi >= w->now) {
            when = p->t + toi;
        } else {
            r = C2D_W_TOI_ACCEL(a, acc, &b, zero, st->radius, p->timer - w->now, &toi);
            if (r != C2D_OK) return;
            when = w->now + toi;
        }
    }
    c2d_w_consider(best, when, C2D_W_WALL, (uint32_t)(4 + k), 0);
}

/* Disk p against every static, from its reference state (time p->t, so the
 * times depend on that state alone; an approach already due is clamped to
 * now): a circle (radius sum r + R), a segment's two ends (points) and its
 * interior (the normal coordinate reaching +-r, on the side the centre is
 * now, with the foot within the segment).  With acceleration the horizon is
 * the disk's timer, where its motion may change. */
static void c2d_w_predict_statics(const c2d_world *w, const c2d_w_disk *p, const c2d_body *a, c2d_w_best *best)
{
    const double now = w->now;
    size_t k;
    c2d_vec2 acc;
    c2d_body ref;
    ref.pos.x = p->x, ref.pos.y = p->y, ref.vel.x = p->vx, ref.vel.y = p->vy, ref.mass = p->mass;
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
            if (acc.x == 0 && acc.y == 0) r = C2D_W_TOI(&ref, &b, p->radius + st->radius, &toi);
            else {
                c2d_vec2 zero;
                zero.x = zero.y = 0;
                r = C2D_W_TOI_ACCEL(&ref, acc, &b, zero, p->radius + st->radius, p->timer - p->t, &toi);
            }
            if (r != C2D_OK) continue;
            when = p->t + toi;
            if (when <= now) {
                if (c2d_w_static_refused(st, a)) continue;
                when = now;
            }
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

/* Disk p as a body at time t (from its reference state). */
static void c2d_w_body_at(const c2d_w_disk *p, double t, c2d_body *b)
{
    const double dt = t - p->t;
    b->pos.x = c2d_w_at(p->x, p->vx, p->ax, dt), b->pos.y = c2d_w_at(p->y, p->vy, p->ay, dt);
    b->vel.x = c2d_w_vel(p->vx, p->ax, dt), b->vel.y = c2d_w_vel(p->vy, p->ay, dt);
    b->mass = p->mass;
}

/* The nearest periodic image of a displacement d along a side: the shift
 * (-side, 0 or side) to add.  Stored positions are within [0, side) and
 * rebased before they go side / 24 from it, so one shift is enough. */
C2D_W_HOT double c2d_w_image_shift(double d, double side)
{
    if (d > 0.5 * side) return -side;
    if (d < -0.5 * side) return side;
    return 0;
}

/* The canonical frame of pair (p, q), p the lower index: the later of
 * their state times t0 (returned), both extrapolated to it, q's image the
 * nearest to p there (*shift, added to q's positions).  It depends only on
 * the two stored states, so the pair's time of impact is the same bits
 * whoever predicts it, whenever and from whatever broadphase.
 * Why the nearest image at t0 is the one they meet in: at contact the
 * displacement's components are at most the radius sum <= width / 3 (the
 * box is at least 3 largest diameters); each disk stays within
 * e = side / 24 of its reference position per axis (the rebase), so from t0
 * to the contact the displacement changes by less than 3 e = side / 8 (the
 * later disk moves less than e from its reference at t0, the earlier one
 * less than 2 e); hence at t0 the contact image's components were below
 * side / 3 + side / 8 < side / 2: it is the nearest one. */
static double c2d_w_pair_start(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q, c2d_body *a, c2d_body *b,
                               c2d_vec2 *shift)
{
    const double t0 = p->t > q->t ? p->t : q->t;
    c2d_w_body_at(p, t0, a);
    c2d_w_body_at(q, t0, b);
    shift->x = shift->y = 0;
    if (w->periodic) {
        shift->x = c2d_w_image_shift(b->pos.x - a->pos.x, w->width);
        shift->y = c2d_w_image_shift(b->pos.y - a->pos.y, w->height);
        b->pos.x += shift->x, b->pos.y += shift->y;
    }
    return t0;
}

static int c2d_w_curved(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q)
{
    return w->accel && (p->ax != 0 || p->ay != 0 || q->ax != 0 || q->ay != 0);
}

/* q's image shift in pair (p, q), p the lower index, as its prediction
 * chose it: a straight pair from its relative position as
 * c2d_w_try_straight computes it, a curved one from c2d_w_pair_start's. */
static c2d_vec2 c2d_w_pair_shift(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q)
{
    c2d_vec2 shift;
    shift.x = shift.y = 0;
    if (!w->periodic) return shift;
    if (c2d_w_curved(w, p, q)) {
        c2d_body a, b;
        c2d_w_pair_start(w, p, q, &a, &b, &shift);
    } else {
        const double t0 = p->t > q->t ? p->t : q->t, sp = t0 - p->t, sq = t0 - q->t;
        shift.x = c2d_w_image_shift((q->x + q->vx * sq) - (p->x + p->vx * sp), w->width);
        shift.y = c2d_w_image_shift((q->y + q->vy * sq) - (p->y + p->vy * sp), w->height);
    }
    return shift;
}

/* The pair at time t as its impact sees it (q shifted to its image). */
static void c2d_w_pair_at(const c2d_w_disk *p, const c2d_w_disk *q, double t, c2d_vec2 shift, c2d_body *a, c2d_body *b)
{
    c2d_w_body_at(p, t, a);
    c2d_w_body_at(q, t, b);
    b->pos.x += shift.x, b->pos.y += shift.y;
}

/* A pair due at once (time <= now) that c2d_collide would refuse at now
 * (touching with no approach speed, pushed together by accelerations, or
 * a graze rounded into the past): no event, or the world would predict it
 * again and again. */
static int c2d_w_pair_refused_now(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q, c2d_vec2 shift)
{
    c2d_body a, b;
    c2d_w_pair_at(p, q, w->now, shift, &a, &b);
    return c2d_w_refused_now(&a, &b);
}

/* What a prediction keeps of its own disk i for its straight candidates. */
typedef struct c2d_w_self {
    double x, y, vx, vy, t, radius, now;
    double width, height, hw, hh; /* the box, and half of it (periodic) */
    int periodic;
    uint32_t i;
} c2d_w_self;

/* The nearest image of a pair's relative position (dx, dy): each
 * component shifted by the side once at most (see c2d_w_image_shift). */
C2D_W_HOT void c2d_w_nearest(const c2d_w_self *s, double *dx, double *dy)
{
    if (*dx > s->hw) *dx -= s->width;
    else if (*dx < -s->hw) *dx += s->width;
    if (*dy > s->hh) *dy -= s->height;
    else if (*dy < -s->hh) *dy += s->height;
}

/* A straight pair (no acceleration on either): its relative state in the
 * canonical frame is q minus p, both at t0 = the later state time (each
 * x + v s with s >= 0 its own age at t0: the same bits whichever disk
 * predicts), the nearest image.  Swapping p and q negates every component
 * exactly (rounding is symmetric), so the lower index's view is the
 * predictor's negated when the predictor is the higher index.  The time of
 * impact is c2d_time_of_impact of that relative state (a at the origin at
 * rest, b moving), when it can beat the best so far; the filters first,
 * each certain despite rounding (the estimates' errors are far below
 * 2^-40 of their terms, taken far from underflow): receding or no relative
 * motion; a miss (the discriminant negative); or no contact before the
 * best event so far.  The last: with h = -d.v, c = |d|^2 - rs^2 > 0, the
 * time is t = c / (h + sqrt(h^2 - |v|^2 c)) >= c / (2 h) (a bound tighter
 * by the square root rejected too few more to pay for it, measured).
 * c2d_time_of_impact's own time is within ulp(t) + ulp(|d|) / s of the
 * exact one (s the approach speed, about h / |d|): relative to t (at
 * least c / (2 h)) that is below 2^-52 + 2^-51 (|d|^2 + rs^2) / c, so
 * below 2^-40 when c > 2^-10 (|d|^2 + rs^2), and a margin 2^-40 then
 * covers it; nearer contact the test is not taken.  They see the same
 * numbers as the time of impact, and are symmetric in the sign. */
C2D_W_HOT void c2d_w_try_straight(const c2d_world *w, const c2d_w_self *self, uint32_t j, c2d_w_best *best)
{
    const c2d_w_disk *q = &w->disk[j];
    const double qt = q->t, t0 = qt > self->t ? qt : self->t, sp = t0 - self->t, sq = t0 - qt;
    const double rs = self->radius + q->radius;
    double dx = (q->x + q->vx * sq) - (self->x + self->vx * sp), dy = (q->y + q->vy * sq) - (self->y + self->vy * sp);
    double dvx = q->vx - self->vx, dvy = q->vy - self->vy, dot, mag, toi, when;
    c2d_body a, b;
    if (self->periodic) c2d_w_nearest(self, &dx, &dy);
    if (dvx == 0 && dvy == 0) return;
    dot = dx * dvx + dy * dvy;
    mag = C2D_W_FABS(dx * dvx) + C2D_W_FABS(dy * dvy);
    if (mag >= 0x1p-900 && mag <= 0x1p900) {
        double dd, err, c;
        if (dot > mag * 0x1p-40) return;
        dd = dx * dx + dy * dy;
        err = (dd + rs * rs) * 0x1p-40, c = (dd - rs * rs) - err;
        if (c > 0 && c <= 0x1p900 && err >= 0x1p-900) {
            const double dh = -dot + mag * 0x1p-40, vv = (dvx * dvx + dvy * dvy) * (1 - 0x1p-40);
            if (dh * dh < vv * c * (1 - 0x1p-40)) return;
            if (c > (dd + rs * rs) * 0x1p-10 && best->when - t0 < c / (2 * dh) * (1 - 0x1p-40)) return;
        }
    }
    if (j < self->i) dx = -dx, dy = -dy, dvx = -dvx, dvy = -dvy;
    a.pos.x = a.pos.y = a.vel.x = a.vel.y = 0, a.mass = 1;
    b.pos.x = dx, b.pos.y = dy, b.vel.x = dvx, b.vel.y = dvy, b.mass = 1; /* masses: ignored */
    if (C2D_W_TOI(&a, &b, rs, &toi) != C2D_OK) return;
    when = t0 + toi;
    if (when <= self->now) {
        const uint32_t lo = j < self->i ? j : self->i, hi = j < self->i ? self->i : j;
        if (c2d_w_pair_refused_now(w, &w->disk[lo], &w->disk[hi], c2d_w_pair_shift(w, &w->disk[lo], &w->disk[hi])))
            return;
        when = self->now;
    }
    c2d_w_consider(best, when, C2D_W_PAIR, j, q->count);
}

static void c2d_w_self_of(const c2d_world *w, uint32_t i, c2d_w_self *self)
{
    const c2d_w_disk *p = &w->disk[i];
    self->x = p->x, self->y = p->y, self->vx = p->vx, self->vy = p->vy, self->t = p->t, self->radius = p->radius;
    self->now = w->now, self->i = i;
    self->width = w->width, self->height = w->height, self->hw = 0.5 * w->width, self->hh = 0.5 * w->height;
    self->periodic = w->periodic;
}

/* Disk i's candidate j: their next impact in the canonical frame if it can
 * beat the best so far; curved paths by c2d_time_of_impact_accel (lower
 * index first, absolute positions at t0) with the earlier timer as the
 * horizon (where either motion may change; a timer's change makes the
 * other's prediction stale). */
static void c2d_w_try_pair(const c2d_world *w, const c2d_w_self *self, uint32_t j, c2d_w_best *best)
{
    const c2d_w_disk *d = w->disk;
    const uint32_t i = self->i, lo = i < j ? i : j, hi = i < j ? j : i;
    const c2d_w_disk *p = &d[lo], *q = &d[hi];
    c2d_body a, b;
    c2d_vec2 shift, pa, qa;
    double t0, toi, when;
    if (j == i || d[j].kind == C2D_W_GONE) return;
    if (!c2d_w_curved(w, p, q)) {
        c2d_w_try_straight(w, self, j, best);
        return;
    }
    t0 = c2d_w_pair_start(w, p, q, &a, &b, &shift);
    pa.x = p->ax, pa.y = p->ay, qa.x = q->ax, qa.y = q->ay;
    if (C2D_W_TOI_ACCEL(&a, pa, &b, qa, p->radius + q->radius, (p->timer < q->timer ? p->timer : q->timer) - t0, &toi) !=
        C2D_OK)
        return;
    when = t0 + toi;
    if (when <= w->now) {
        /* Refused now, unless pressed together (the pair rest rule). */
        c2d_w_pair_at(p, q, w->now, shift, &a, &b);
        if (c2d_w_refused_now(&a, &b) && !c2d_w_pressed(w, p, q, &a, &b)) return;
        when = w->now;
    }
    c2d_w_consider(best, when, C2D_W_PAIR, j, d[j].count);
}

/* The sides of a range [lo, hi] along one axis a disk's coordinate (x at
 * its time t, speed v, acceleration acc) leaves first: with acceleration
 * both sides (c2d_w_meet), straight only the one the velocity points to.
 * `has` says which sides exist (bit 0: lo, bit 1: hi); partners base + 0
 * (lo) and base + 1 (hi). */
C2D_W_HOT void c2d_w_leave(c2d_w_best *best, double t, double x, double v, double acc, double lo, double hi, unsigned has,
                        uint32_t base, double now)
{
    if (acc == 0) {
        if (v < 0 && (has & 1u)) c2d_w_consider(best, c2d_w_reach(t, x, v, lo, now), C2D_W_CELL, base, 0);
        if (v > 0 && (has & 2u)) c2d_w_consider(best, c2d_w_reach(t, x, v, hi, now), C2D_W_CELL, base + 1, 0);
        return;
    }
    if (has & 1u) c2d_w_consider(best, c2d_w_meet(t, x, v, acc, lo, -1, now), C2D_W_CELL, base, 0);
    if (has & 2u) c2d_w_consider(best, c2d_w_meet(t, x, v, acc, hi, 1, now), C2D_W_CELL, base + 1, 0);
}

/* The image of a range's start `lo` (and so of the range) in a disk's frame:
 * its stored position is in [0, side) up to a rebase's excursion, the
 * range's in [0, side), so the shift is the one that brings the range's
 * centre nearest the disk's centre x. */
C2D_W_HOT double c2d_w_frame_shift(double x, double lo, double hi, double side)
{
    return c2d_w_image_shift(0.5 * (lo + hi) - x, side);
}

/* Walls: the centre at radius from them (straight: only those the
 * velocity points to). */
static void c2d_w_predict_walls(const c2d_world *w, const c2d_w_disk *p, c2d_w_best *best)
{
    const double now = w->now, r = p->radius;
    if (p->ax == 0 && p->ay == 0) {
        if (p->vx < 0) c2d_w_consider(best, c2d_w_reach(p->t, p->x, p->vx, r, now), C2D_W_WALL, 0, 0);
        if (p->vx > 0) c2d_w_consider(best, c2d_w_reach(p->t, p->x, p->vx, w->width - r, now), C2D_W_WALL, 1, 0);
        if (p->vy < 0) c2d_w_consider(best, c2d_w_reach(p->t, p->y, p->vy, r, now), C2D_W_WALL, 2, 0);
        if (p->vy > 0) c2d_w_consider(best, c2d_w_reach(p->t, p->y, p->vy, w->height - r, now), C2D_W_WALL, 3, 0);
        return;
    }
    c2d_w_consider(best, c2d_w_meet(p->t, p->x, p->vx, p->ax, r, -1, now), C2D_W_WALL, 0, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->x, p->vx, p->ax, w->width - r, 1, now), C2D_W_WALL, 1, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->y, p->vy, p->ay, r, -1, now), C2D_W_WALL, 2, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->y, p->vy, p->ay, w->height - r, 1, now), C2D_W_WALL, 3, 0);
}

/* Periodic: the rebase, when the centre first goes `rebase` from its
 * reference position along either axis (straight: at rebase / max |v|). */
static void c2d_w_predict_rebase(const c2d_world *w, const c2d_w_disk *p, c2d_w_best *best)
{
    const double e = w->rebase, now = w->now;
    if (p->ax == 0 && p->ay == 0) {
        const double sx = C2D_W_FABS(p->vx), sy = C2D_W_FABS(p->vy), s = sx > sy ? sx : sy;
        if (s > 0) {
            const double when = p->t + e / s;
            c2d_w_consider(best, when < now ? now : when, C2D_W_CELL, C2D_W_REBASE, 0);
        }
        return;
    }
    c2d_w_consider(best, c2d_w_meet(p->t, p->x, p->vx, p->ax, p->x - e, -1, now), C2D_W_CELL, C2D_W_REBASE, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->x, p->vx, p->ax, p->x + e, 1, now), C2D_W_CELL, C2D_W_REBASE, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->y, p->vy, p->ay, p->y - e, -1, now), C2D_W_CELL, C2D_W_REBASE, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->y, p->vy, p->ay, p->y + e, 1, now), C2D_W_CELL, C2D_W_REBASE, 0);
}

/* The built-in broadphase: leaving the cell is an event, and the
 * candidates are the disks of the 3 x 3 cells around (fewer against
 * walls; each cell once). */
/* One cell along an axis beyond c (dir -1 or +1), wrapping when periodic:
 * 1 and *cell, or 0 at a wall. */
C2D_W_HOT size_t c2d_w_beyond(size_t c, size_t m, int periodic, int dir, size_t *cell)
{
    if (dir < 0) {
        if (c > 0) *cell = c - 1;
        else if (periodic) *cell = m - 1;
        else return 0;
        return 1;
    }
    if (c + 1 < m) *cell = c + 1;
    else if (periodic) *cell = 0;
    else return 0;
    return 1;
}

static void c2d_w_predict_cells(const c2d_world *w, uint32_t i, const c2d_body *a, c2d_w_best *best, c2d_w_best *cross,
                                uint32_t side)
{
    const c2d_w_disk *d = w->disk, *p = &d[i];
    const size_t mx = w->mx, my = w->my, cx = p->cell % mx, cy = p->cell / mx;
    const int per = w->periodic;
    size_t k, l, nc, nr, n = 0, col[3], row[3];
    uint32_t first[9];
    c2d_w_self self;
    {
        double x0 = (double)cx * w->cw, x1 = cx + 1 == mx ? w->width : (double)(cx + 1) * w->cw;
        double y0 = (double)cy * w->ch, y1 = cy + 1 == my ? w->height : (double)(cy + 1) * w->ch;
        if (per) {
            const double fx = c2d_w_frame_shift(a->pos.x, x0, x1, w->width);
            const double fy = c2d_w_frame_shift(a->pos.y, y0, y1, w->height);
            x0 += fx, x1 += fx, y0 += fy, y1 += fy;
        }
        c2d_w_leave(cross, p->t, p->x, p->vx, p->ax, x0, x1, (cx > 0 || per ? 1u : 0u) | (cx + 1 < mx || per ? 2u : 0u),
                    0, w->now);
        c2d_w_leave(cross, p->t, p->y, p->vy, p->ay, y0, y1, (cy > 0 || per ? 1u : 0u) | (cy + 1 < my || per ? 2u : 0u),
                    2, w->now);
    }
    /* All 3 x 3, or after a crossing the strip beyond the new cell. */
    if (side == C2D_W_NONE || side >= 2) nc = c2d_w_neighbours(cx, mx, per, col);
    else nc = c2d_w_beyond(cx, mx, per, side == 0 ? -1 : 1, col);
    if (side == C2D_W_NONE || side < 2) nr = c2d_w_neighbours(cy, my, per, row);
    else nr = c2d_w_beyond(cy, my, per, side == 2 ? -1 : 1, row);
    /* The cells' first disks, loaded (and their states fetched) all at
     * once before any is used: with many disks these are cache misses, and
     * independent ones overlap. */
    for (l = 0; l < nr; l++)
        for (k = 0; k < nc; k++) {
            const uint32_t j = w->head[row[l] * mx + col[k]];
            if (j == C2D_W_NONE) continue;
            first[n++] = j;
#ifdef __GNUC__
            __builtin_prefetch(&d[j]);
#endif
        }
    c2d_w_self_of(w, i, &self);
    if (!w->accel) { /* every pair straight, and no removed disk in a cell */
        for (k = 0; k < n; k++) {
            uint32_t j = first[k];
            do {
                if (j != i) c2d_w_try_straight(w, &self, j, best);
                j = d[j].next;
            } while (j != C2D_W_NONE);
        }
        return;
    }
    for (k = 0; k < n; k++) {
        uint32_t j;
        for (j = first[k]; j != C2D_W_NONE; j = d[j].next) c2d_w_try_pair(w, &self, j, best);
    }
}

/* The box a caller's broadphase gets for a disk centred at (x, y). */
static void c2d_w_box_of(const c2d_world *w, const c2d_w_disk *p, double x, double y, c2d_world_box *box)
{
    const double h = (p->radius + c2d_w_margin(w, p)) * C2D_W_BOX_SLACK;
    box->lo.x = x - h, box->lo.y = y - h, box->hi.x = x + h, box->hi.y = y + h;
}

typedef struct c2d_w_query {
    const c2d_world *w;
    c2d_w_self self;
    c2d_w_best *best;
} c2d_w_query;

static void c2d_w_report(void *context, size_t disk)
{
    const c2d_w_query *q = (const c2d_w_query *)context;
    if (disk < q->w->count) c2d_w_try_pair(q->w, &q->self, (uint32_t)disk, q->best);
}

/* Ask the caller's broadphase for the disks whose boxes overlap `box`, and
 * in a periodic box its images across each side it comes within the
 * largest half-size of a box of (a box near the other side may stick out
 * towards it across the wrap). */
static void c2d_w_query_images(const c2d_world *w, const c2d_world_box *box, c2d_world_report report, void *ctx)
{
    double sx[3], sy[3];
    size_t nx = 1, ny = 1, k, l;
    sx[0] = sy[0] = 0;
    if (w->periodic) {
        const double h = w->hmax;
        if (box->lo.x < h) sx[nx++] = w->width;
        if (box->hi.x > w->width - h) sx[nx++] = -w->width;
        if (box->lo.y < h) sy[ny++] = w->height;
        if (box->hi.y > w->height - h) sy[ny++] = -w->height;
    }
    for (l = 0; l < ny; l++)
        for (k = 0; k < nx; k++) {
            c2d_world_box b = *box;
            b.lo.x += sx[k], b.hi.x += sx[k], b.lo.y += sy[l], b.hi.y += sy[l];
            w->bp.query(w->bp.user, &b, report, ctx);
        }
}

/* The caller's broadphase: leaving the box's inner range (centre +-
 * margin) is an event, and the candidates are what it reports. */
static void c2d_w_predict_caller(const c2d_world *w, uint32_t i, const c2d_body *a, c2d_w_best *best)
{
    const c2d_w_disk *p = &w->disk[i];
    const double m = c2d_w_margin(w, p), bx = w->box[2 * i], by = w->box[2 * i + 1];
    double fx = 0, fy = 0;
    c2d_world_box box;
    c2d_w_query ctx;
    if (w->periodic) {
        fx = c2d_w_frame_shift(a->pos.x, bx, bx, w->width);
        fy = c2d_w_frame_shift(a->pos.y, by, by, w->height);
    }
    c2d_w_leave(best, p->t, p->x, p->vx, p->ax, bx + fx - m, bx + fx + m, 3u, C2D_W_BOX, w->now);
    c2d_w_leave(best, p->t, p->y, p->vy, p->ay, by + fy - m, by + fy + m, 3u, C2D_W_BOX, w->now);
    c2d_w_box_of(w, p, bx, by, &box);
    ctx.w = w, ctx.best = best;
    c2d_w_self_of(w, i, &ctx.self);
    c2d_w_query_images(w, &box, c2d_w_report, &ctx);
}

/* Disk i's event: the earlier of its best event other than a crossing
 * (kept, with its time, through the crossings) and its crossing. */
static void c2d_w_settle(c2d_world *w, uint32_t i, const c2d_w_best *best, const c2d_w_best *cross)
{
    c2d_w_disk *p = &w->disk[i];
    p->kind = best->kind;
    p->partner = best->partner;
    p->pcount = best->pcount;
    w->node[i].mwhen = best->when;
    if (cross->when < best->when ||
        (cross->when == best->when && (C2D_W_CELL < best->kind || (C2D_W_CELL == best->kind && cross->partner < best->partner)))) {
        p->side = cross->partner;
        c2d_w_q_set(w, i, cross->when, C2D_W_TIE_KIND(C2D_W_CELL) | (uint64_t)i << 31 | (uint64_t)i);
    } else if (best->kind == C2D_W_PAIR) {
        const uint64_t lo = i < best->partner ? i : best->partner, hi = i < best->partner ? best->partner : i;
        p->side = C2D_W_NONE;
        c2d_w_q_set(w, i, best->when, lo << 31 | hi); /* kind C2D_W_PAIR = 0 */
    } else {
        p->side = C2D_W_NONE;
        c2d_w_q_set(w, i, best->when, C2D_W_TIE_KIND(best->kind) | (uint64_t)i << 31 | (uint64_t)i);
    }
}

static void c2d_w_best_none(c2d_w_best *b)
{
    b->when = C2D_W_INF;
    b->kind = C2D_W_IDLE;
    b->partner = 0;
    b->pcount = 0;
}

/* Disk i's next event, predicted from scratch. */
static void c2d_w_predict(c2d_world *w, uint32_t i)
{
    c2d_w_disk *p = &w->disk[i];
    c2d_w_best best, cross;
    c2d_body a;
    c2d_w_best_none(&best);
    c2d_w_best_none(&cross);
    c2d_w_body_at(p, w->now, &a);
    if (!w->periodic) c2d_w_predict_walls(w, p, &best);
    else c2d_w_predict_rebase(w, p, &best);
    if (p->timer < C2D_W_INF) c2d_w_consider(&best, p->timer, C2D_W_TIMER, 0, 0);
    if (w->nstatic > 0) c2d_w_predict_statics(w, p, &a, &best);
    if (w->caller) c2d_w_predict_caller(w, i, &a, &best);
    else c2d_w_predict_cells(w, i, &a, &best, &cross, C2D_W_NONE);
    c2d_w_settle(w, i, &best, &cross);
}

/* Disk i's next event after crossing into a new cell by `side`: its
 * state is unchanged, so its best other event stands (unless it is an
 * impact whose partner has moved since: then from scratch), and only the
 * strip of 3 cells that has come into its 3 x 3 is new. */
static void c2d_w_predict_crossed(c2d_world *w, uint32_t i, uint32_t side)
{
    c2d_w_disk *p = &w->disk[i];
    c2d_w_best best, cross;
    c2d_body a;
    if (p->kind == C2D_W_PAIR && w->disk[p->partner].count != p->pcount) {
        c2d_w_predict(w, i);
        return;
    }
    best.when = w->node[i].mwhen, best.kind = p->kind, best.partner = p->partner, best.pcount = p->pcount;
    c2d_w_best_none(&cross);
    c2d_w_body_at(p, w->now, &a);
    c2d_w_predict_cells(w, i, &a, &best, &cross, side);
    c2d_w_settle(w, i, &best, &cross);
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
        double dt = w->now - p->t, x, y;
        size_t cx, cy;
        if (p->kind == C2D_W_GONE) continue;
        x = c2d_w_at(p->x, p->vx, p->ax, dt), y = c2d_w_at(p->y, p->vy, p->ay, dt);
        if (w->periodic) x = c2d_w_wrap(x, w->width), y = c2d_w_wrap(y, w->height);
        cx = c2d_w_cell_1d(x, w->cw, w->mx);
        cy = c2d_w_cell_1d(y, w->ch, w->my);
        c2d_w_cell_insert(w, (uint32_t)i, cy * w->mx + cx);
    }
    for (i = 0; i < w->count; i++)
        if (w->disk[i].kind != C2D_W_GONE) c2d_w_predict(w, (uint32_t)i);
}

/* ------------------------------------------------------------ adding */

/* Disk i's box for the caller's broadphase, centred where it is now
 * (wrapped into a periodic box). */
static void c2d_w_set_box(c2d_world *w, uint32_t i, int moved)
{
    c2d_w_disk *p = &w->disk[i];
    c2d_body b;
    c2d_world_box box;
    c2d_w_body_at(p, w->now, &b);
    if (w->periodic) b.pos.x = c2d_w_wrap(b.pos.x, w->width), b.pos.y = c2d_w_wrap(b.pos.y, w->height);
    w->box[2 * i] = b.pos.x, w->box[2 * i + 1] = b.pos.y;
    c2d_w_box_of(w, p, b.pos.x, b.pos.y, &box);
    if (box.hi.x - b.pos.x > w->hmax) w->hmax = box.hi.x - b.pos.x;
    if (moved) w->bp.move(w->bp.user, i, &box);
    else w->bp.insert(w->bp.user, i, &box);
}


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

typedef struct c2d_w_overlap_query {
    const c2d_world *w;
    double x, y, r;
    int found;
} c2d_w_overlap_query;

static void c2d_w_overlap_report(void *context, size_t disk)
{
    c2d_w_overlap_query *q = (c2d_w_overlap_query *)context;
    const c2d_world *w = q->w;
    if (disk < w->count && w->disk[disk].kind != C2D_W_GONE && c2d_w_overlaps(w, q->x, q->y, q->r, &w->disk[disk]))
        q->found = 1;
}

/* Does a disk at (x, y) of radius r overlap one in the world?  Every disk
 * when it is the first or the largest (the grid is rebuilt), else those of
 * the 3 x 3 cells around or the caller broadphase's (boxes overlapping
 * the disk's own box: a disk overlapping it has its centre within its
 * radius plus the sum, its box's centre within a margin more). */
static int c2d_w_overlaps_any(const c2d_world *w, double x, double y, double r, int all)
{
    size_t k, l;
    if (all) {
        for (k = 0; k < w->count; k++)
            if (w->disk[k].kind != C2D_W_GONE && c2d_w_overlaps(w, x, y, r, &w->disk[k])) return 1;
        return 0;
    }
    if (w->caller) {
        c2d_w_overlap_query q;
        c2d_world_box box;
        const double h = r * C2D_W_BOX_SLACK;
        q.w = w, q.x = x, q.y = y, q.r = r, q.found = 0;
        box.lo.x = x - h, box.lo.y = y - h, box.hi.x = x + h, box.hi.y = y + h;
        c2d_w_query_images(w, &box, c2d_w_overlap_report, &q);
        return q.found;
    }
    {
        const size_t mx = w->mx, my = w->my, cx = c2d_w_cell_1d(x, w->cw, mx), cy = c2d_w_cell_1d(y, w->ch, my);
        for (l = 0; l < 3; l++)
            for (k = 0; k < 3; k++) {
                size_t nx = cx + mx + k - 1, ny = cy + my + l - 1;
                uint32_t j;
                if (!w->periodic && (nx < mx || nx >= 2 * mx || ny < my || ny >= 2 * my)) continue;
                for (j = w->head[(ny % my) * mx + nx % mx]; j != C2D_W_NONE; j = w->disk[j].next)
                    if (c2d_w_overlaps(w, x, y, r, &w->disk[j])) return 1;
            }
    }
    return 0;
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
    rebuild = !w->caller && (w->count == 0 || radius > w->rmax);
    if (c2d_w_overlaps_any(w, x, y, radius, rebuild)) return C2D_INVALID;
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
    p->side = C2D_W_NONE;
    if (w->entered != NULL) w->entered[i].time = -C2D_W_INF, w->entered[i].sensor = 0, w->entered[i].spare = 0;
    if (w->spin != NULL) w->spin[i] = 0;
    w->node[i].when = w->node[i].mwhen = C2D_W_INF, w->node[i].tie = 0;
    w->node[i].prev = w->node[i].next = C2D_W_NONE;
    w->node[i].where = C2D_W_NONE, w->node[i].slot = 0;
    w->count++;
    if (index != NULL) *index = i;
    if (radius > w->rmax) w->rmax = radius;
    if (rebuild) {
        c2d_w_rebuild(w);
    } else if (w->caller) {
        c2d_w_set_box(w, i, 0);
        c2d_w_predict(w, i);
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

/* Disk p's reference state becomes (x, y, vx, vy) at the world's time,
 * wrapped into a periodic box. */
static void c2d_w_restate(const c2d_world *w, c2d_w_disk *p, double x, double y, double vx, double vy)
{
    if (w->periodic) x = c2d_w_wrap(x, w->width), y = c2d_w_wrap(y, w->height);
    p->x = x, p->y = y, p->vx = vx, p->vy = vy, p->t = w->now;
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
    const double now = w->now;
    double qx, qy, e = w->restitution, length, vqx, vqy;
    int collapsed = 0, resolved;
    c2d_world_contact c;
    c2d_body a, b;
    c2d_vec2 shift;
    if (d[partner].count != d[owner].pcount) { /* stale */
        c2d_w_predict(w, owner);
        return;
    }
    shift = c2d_w_pair_shift(w, p, q); /* the image the prediction used */
    c2d_w_body_at(p, now, &a);
    c2d_w_body_at(q, now, &b);
    qx = b.pos.x, qy = b.pos.y;
    b.pos.x += shift.x, b.pos.y += shift.y;
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
        c2d_w_restate(w, p, a.pos.x, a.pos.y, a.vel.x, a.vel.y);
        c2d_w_restate(w, q, qx, qy, b.vel.x, b.vel.y);
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
            c2d_w_restate(w, p, a.pos.x, a.pos.y, a.vel.x, a.vel.y);
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
    w->disk[i].count++; /* a horizon of its partners' predictions was the timer */
    if (w->on_event != NULL) {
        c2d_world_event ev;
        ev.kind = C2D_WORLD_TIMER, ev.time = w->now, ev.a = i, ev.b = 0;
        ev.impulse.x = ev.impulse.y = 0;
        c2d_w_emit(w, &ev);
    }
    c2d_w_repredict(w, i);
}

/* Periodic: disk i's reference state moved on to now (wrapped), its
 * partners' predictions stale. */
static void c2d_w_rebase(c2d_world *w, uint32_t i)
{
    c2d_w_disk *p = &w->disk[i];
    c2d_body b;
    c2d_w_body_at(p, w->now, &b);
    c2d_w_restate(w, p, b.pos.x, b.pos.y, b.vel.x, b.vel.y);
    p->count++;
    c2d_w_predict(w, i);
}

/* Disk i crosses into the next cell by `side`. */
static void c2d_w_cross_cell(c2d_world *w, uint32_t i, uint32_t side)
{
    c2d_w_disk *p = &w->disk[i];
    size_t cx = p->cell % w->mx, cy = p->cell / w->mx;
    c2d_w_cell_remove(w, i);
    switch (side) {
    case 0: cx = (cx == 0 ? w->mx : cx) - 1; break;
    case 1: cx = cx + 1 == w->mx ? 0 : cx + 1; break;
    case 2: cy = (cy == 0 ? w->my : cy) - 1; break;
    default: cy = cy + 1 == w->my ? 0 : cy + 1; break;
    }
    c2d_w_cell_insert(w, i, cy * w->mx + cx);
    c2d_w_predict_crossed(w, i, side);
}

/* A C2D_W_CELL event other than a crossing: a rebase, or the caller's
 * box left.  Only the rebase changes the disk's state, and the disk's own
 * state decides it, whatever the broadphase. */
static void c2d_w_cross(c2d_world *w, uint32_t i)
{
    if (w->disk[i].partner == C2D_W_REBASE) {
        c2d_w_rebase(w, i);
        return;
    }
    c2d_w_set_box(w, i, 1);
    c2d_w_predict(w, i);
}

c2d_status c2d_world_advance(c2d_world *world, double t)
{
    c2d_world *w = world;
    if (w == NULL || w->busy || !c2d_w_finite(t) || !(t >= w->now)) return C2D_INVALID;
    for (;;) {
        const uint32_t i = c2d_w_q_top(w);
        c2d_w_disk *p;
        if (i == C2D_W_NONE || !(w->win[0].when <= t)) break;
        p = &w->disk[i];
        w->now = w->win[0].when;
        w->stats.events++;
        c2d_w_q_count(w);
        if (p->side != C2D_W_NONE) c2d_w_cross_cell(w, i, p->side);
        else switch (p->kind) {
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
    if (world->periodic) x = c2d_w_wrap(x, world->width), y = c2d_w_wrap(y, world->height);
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
    c2d_w_restate(world, p, c2d_w_at(p->x, p->vx, p->ax, dt), c2d_w_at(p->y, p->vy, p->ay, dt), velocity.x, velocity.y);
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
    c2d_w_restate(world, p, c2d_w_at(p->x, p->vx, p->ax, dt), c2d_w_at(p->y, p->vy, p->ay, dt), vx, vy);
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
    if (w->count > 0) {
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
    p->count++; /* the horizon of its partners' curved predictions */
    c2d_w_predict(world, (uint32_t)index);
    return C2D_OK;
}

c2d_status c2d_world_remove(c2d_world *world, size_t index)
{
    c2d_w_disk *p;
    if (world == NULL || world->busy > 1 || index >= world->count) return C2D_INVALID;
    p = &world->disk[index];
    if (p->kind == C2D_W_GONE) return C2D_INVALID;
    if (world->caller) world->bp.remove(world->bp.user, index);
    else c2d_w_cell_remove(world, (uint32_t)index);
    p->cell = C2D_W_NONE, p->next = C2D_W_NONE;
    p->kind = C2D_W_GONE;
    p->count++;
    c2d_w_q_set(world, (uint32_t)index, C2D_W_INF, 0);
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
