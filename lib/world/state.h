/* SPDX-License-Identifier: MIT */
/* world/state.h - its constants and the state of a world: disks, statics, queue entries.
 * Part of lib/world.c, which includes the parts once, in order. */

/* The impact and the time of impact are the library's own calls
 * (double.c): one copy of their code in any build, the same bits.  Those
 * whose public form takes a vector by value are called by address
 * (internal.h: by value is a memcpy call on small cores). */
#define C2D_W_COLLIDE c2d_collide
#define C2D_W_TOI c2d_time_of_impact
#define C2D_W_TOI_ACCEL c2d_time_of_impact_accel_by_ref
#define C2D_W_COLLIDE_NORMAL c2d_collide_normal_by_ref
#define C2D_W_COLLIDE_ROUGH c2d_collide_rough_by_ref

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

/* The cell scan without gcc's SLP vectoriser, which pairs the x and y
 * halves of the candidate test and then shuffles them between registers:
 * 2 % fewer instructions per collision (bench/world.c).  The same IEEE
 * operations either way, so the same bits (-ffp-contract=off and
 * -fno-math-errno hold: the option list is the command line's plus this). */
#if defined(__GNUC__) && !defined(__clang__) && !defined(__INTEL_COMPILER)
#define C2D_W_NO_SLP __attribute__((optimize("no-tree-slp-vectorize")))
#else
#define C2D_W_NO_SLP
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
/* The kind of an event's disk while on_event runs: it is predicted again
 * when the callback returns (c2d_w_tell), so a setter need not. */
enum { C2D_W_TOLD = 6 };
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

/* ------------------------------------------------------------ copies
 * Member by member: gcc -Os turns a struct assignment of 16 bytes or more
 * into a memcpy call on Cortex-M0 and RV32 (so does a struct passed or
 * returned by value), and the library calls no C library. */

static void c2d_w_vec_copy(c2d_vec2 *to, const c2d_vec2 *from)
{
    to->x = from->x, to->y = from->y;
}

static void c2d_w_body_copy(c2d_body *to, const c2d_body *from)
{
    c2d_w_vec_copy(&to->pos, &from->pos), c2d_w_vec_copy(&to->vel, &from->vel), to->mass = from->mass;
}

static void c2d_w_surface_copy(c2d_surface *to, const c2d_surface *from)
{
    to->restitution = from->restitution, to->friction = from->friction;
    to->tangential_restitution = from->tangential_restitution;
}

static void c2d_w_entry_copy(c2d_w_entry *to, const c2d_w_entry *from)
{
    to->when = from->when, to->tie = from->tie, to->disk = from->disk, to->spare = from->spare;
}

static void c2d_w_static_copy(c2d_w_static *to, const c2d_w_static *from)
{
    to->ax = from->ax, to->ay = from->ay, to->bx = from->bx, to->by = from->by;
    to->nx = from->nx, to->ny = from->ny, to->len = from->len, to->radius = from->radius;
    to->restitution = from->restitution, to->shape = from->shape, to->spare = from->spare;
}

static void c2d_w_box_copy(c2d_world_box *to, const c2d_world_box *from)
{
    c2d_w_vec_copy(&to->lo, &from->lo), c2d_w_vec_copy(&to->hi, &from->hi);
}
