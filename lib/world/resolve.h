/* SPDX-License-Identifier: MIT */
/* world/resolve.h - resolving a contact: the callback, the collapse rule, the contact models, the caller's resolvers, the rest rules.
 * Part of lib/world.c, which includes the parts once, in order. */

/* Tell the caller, who may change velocities, accelerations and timers
 * (not add, remove or advance) meanwhile. */
static void c2d_w_emit(c2d_world *w, const c2d_world_event *ev)
{
    if (w->on_event == NULL) return;
    w->busy = 1;
    w->on_event(w->user, ev);
    w->busy = 0;
}

/* Report an event (at the world's time) to on_event, if any.  Every
 * caller predicts the event's disks again once this returns (c2d_w_repredict),
 * so meanwhile they are marked C2D_W_TOLD and the setters the callback
 * calls on them do not predict: the pool game sets two or three motions of
 * a ball at each of its events, each a full prediction against every static
 * and neighbour, all but the last overwritten unused.  The same bits: a
 * prediction changes nothing but the disk's own event (its kind, partner,
 * pcount, side and queue entry, all written again by the last one), the
 * queue pops in (time, tie) order whatever was inserted and replaced
 * before, and no event is popped inside the callback. */
static void c2d_w_tell(c2d_world *w, c2d_world_event_kind kind, size_t a, size_t b, double jx, double jy)
{
    c2d_world_event ev;
    if (w->on_event == NULL) return;
    w->disk[a].kind = C2D_W_TOLD;
    if (kind == C2D_WORLD_IMPACT) w->disk[b].kind = C2D_W_TOLD;
    ev.kind = kind, ev.time = w->now, ev.a = a, ev.b = b;
    ev.impulse.x = jx, ev.impulse.y = jy;
    c2d_w_emit(w, &ev);
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

/* Disk i (body b) as a rough disk d: its spin, radius and inertia k m r^2. */
static void c2d_w_rough_disk(const c2d_world *w, const c2d_body *b, size_t i, c2d_disk *d)
{
    const double r = w->disk[i].radius;
    c2d_w_vec_copy(&d->pos, &b->pos), c2d_w_vec_copy(&d->vel, &b->vel);
    d->spin = w->spin[i], d->mass = b->mass, d->radius = r;
    d->inertia = w->inertia_factor * b->mass * r * r;
}

/* The rough model's resolution of contact c (spins written on C2D_OK):
 * c2d_collide_rough between disks, c2d_collide_rough_normal against an
 * immovable point for walls and statics. */
static c2d_status c2d_w_rough(c2d_world *w, const c2d_world_contact *c, c2d_body *a, c2d_body *b)
{
    c2d_disk da, db;
    c2d_surface s;
    c2d_status r;
    c2d_w_rough_disk(w, a, c->a, &da);
    if (c->kind == C2D_WORLD_IMPACT) {
        c2d_w_rough_disk(w, b, c->b, &db);
        c2d_w_surface_copy(&s, &w->surface);
        s.restitution = c->restitution;
        r = C2D_W_COLLIDE_ROUGH(&da, &db, NULL, &s);
    } else {
        c2d_w_vec_copy(&db.pos, &b->pos), db.vel.x = db.vel.y = 0, db.spin = 0;
        db.mass = db.inertia = C2D_W_INF, db.radius = 0;
        c2d_w_surface_copy(&s, &w->wall_surface);
        s.restitution = c->restitution;
        r = C2D_W_COLLIDE_ROUGH(&da, &db, &c->normal, &s);
    }
    if (r != C2D_OK) return r;
    c2d_w_vec_copy(&a->vel, &da.vel), w->spin[c->a] = da.spin;
    if (c->kind == C2D_WORLD_IMPACT) c2d_w_vec_copy(&b->vel, &db.vel), w->spin[c->b] = db.spin;
    return C2D_OK;
}

/* The caller's resolution of contact c, taken (1) only when it says
 * C2D_OK with finite velocities no longer approaching along the normal:
 * so no resolver can hang the world (an approaching pair left so would
 * meet again at once) or put a NaN in it. */
static int c2d_w_caller_resolves(c2d_world *w, c2d_world_resolver fn, const c2d_world_contact *c, c2d_body *a,
                                 c2d_body *b)
{
    c2d_body ta, tb;
    int ok;
    double bx = 0, by = 0;
    if (fn == NULL) return 0;
    c2d_w_body_copy(&ta, a), c2d_w_body_copy(&tb, b);
    w->busy = 2;
    ok = fn(w->user, c, &ta, &tb) == C2D_OK;
    w->busy = 0;
    if (c->kind == C2D_WORLD_IMPACT) bx = tb.vel.x, by = tb.vel.y;
    if (!ok || !c2d_w_finite(ta.vel.x) || !c2d_w_finite(ta.vel.y) || !c2d_w_finite(bx) || !c2d_w_finite(by))
        return 0;
    if ((bx - ta.vel.x) * c->normal.x + (by - ta.vel.y) * c->normal.y < 0) return 0;
    c2d_w_vec_copy(&a->vel, &ta.vel);
    if (c->kind == C2D_WORLD_IMPACT) c2d_w_vec_copy(&b->vel, &tb.vel);
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
    return C2D_W_COLLIDE_NORMAL(a, b, &c->normal, c->restitution);
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
