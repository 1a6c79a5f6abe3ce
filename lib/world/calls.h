/* SPDX-License-Identifier: MIT */
/* world/calls.h - the caller's other calls on a world: reading it, changing a disk's motion, statics, sensors, spins, removal, statistics.
 * Part of lib/world.c, which includes the parts once, in order. */

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

/* After a setter: disk i's next event, unless on_event is running for an
 * event of i's, after which the world predicts i anyway (c2d_w_tell). */
static void c2d_w_predict_unless_told(c2d_world *w, uint32_t i)
{
    if (!(w->busy == 1 && w->disk[i].kind == C2D_W_TOLD)) c2d_w_predict(w, i);
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
    c2d_w_predict_unless_told(world, (uint32_t)index);
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
    c2d_w_predict_unless_told(world, (uint32_t)index);
    return C2D_OK;
}

static c2d_status c2d_w_add_static(c2d_world *w, const c2d_w_static *st, size_t *index)
{
    c2d_w_static_copy(&w->stat[w->nstatic], st);
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
    c2d_w_predict_unless_told(world, (uint32_t)index);
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
    stats->collisions = world->stats.collisions, stats->wall_collisions = world->stats.wall_collisions;
    stats->events = world->stats.events, stats->time = world->stats.time, stats->virial = world->stats.virial;
}
