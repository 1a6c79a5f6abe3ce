/* SPDX-License-Identifier: MIT */
/* world/layout.h - where the parts of a world lie in the caller's memory; the description's checks; c2d_world_bytes, c2d_world_init.
 * Part of lib/world.c, which includes the parts once, in order. */

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
    c2d_w_surface_copy(&w->wall_surface, &w->surface);
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
        const c2d_world_broadphase *bp = desc->broadphase;
        w->bp.insert = bp->insert, w->bp.move = bp->move, w->bp.remove = bp->remove, w->bp.query = bp->query;
        w->bp.user = bp->user, w->bp.margin = bp->margin;
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
