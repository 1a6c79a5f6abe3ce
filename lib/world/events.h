/* SPDX-License-Identifier: MIT */
/* world/events.h - processing each kind of event; c2d_world_advance.
 * Part of lib/world.c, which includes the parts once, in order. */

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
    c2d_w_pair_shift(w, p, q, &shift); /* the image the prediction used */
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
        c2d_w_tell(w, C2D_WORLD_IMPACT, i, j, (b.vel.x - vqx) * q->mass, (b.vel.y - vqy) * q->mass);
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
    c2d_w_vec_copy(&c.normal, &n), c.restitution = e, c.collapsed = collapsed;
    {
        const double vx0 = a.vel.x, vy0 = a.vel.y;
        if (c2d_w_resolve(w, w->resolve_static, &c, &a, &b) == C2D_OK) {
            c2d_w_restate(w, p, a.pos.x, a.pos.y, a.vel.x, a.vel.y);
            c2d_w_impact_clock(p, now);
            w->stats.wall_collisions++;
            c2d_w_tell(w, C2D_WORLD_STATIC, i, k, (a.vel.x - vx0) * p->mass, (a.vel.y - vy0) * p->mass);
        }
    }
    c2d_w_repredict(w, i);
}

/* Disk i's centre entered sensor k: remembered (c2d_w_predict_sensor),
 * told, nothing resolved. */
static void c2d_w_sensor(c2d_world *w, uint32_t i, size_t k)
{
    w->entered[i].time = w->now, w->entered[i].sensor = (uint32_t)(k + 1);
    c2d_w_tell(w, C2D_WORLD_SENSOR, i, k, 0, 0);
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
    c2d_w_tell(w, C2D_WORLD_WALL, i, p->partner, (p->vx - vx0) * p->mass, (p->vy - vy0) * p->mass);
    c2d_w_repredict(w, i);
}

/* A disk's timer: cleared, then told (the callback may set it again). */
static void c2d_w_timer(c2d_world *w, uint32_t i)
{
    w->disk[i].timer = C2D_W_INF;
    w->disk[i].count++; /* a horizon of its partners' predictions was the timer */
    c2d_w_tell(w, C2D_WORLD_TIMER, i, 0, 0, 0);
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
