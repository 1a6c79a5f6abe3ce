/* SPDX-License-Identifier: MIT */
/* world/add.h - adding a disk (c2d_world_add).
 * Part of lib/world.c, which includes the parts once, in order. */

/* Disk i's box for the caller's broadphase, centred where it is now
 * (wrapped into a periodic box). */
static void c2d_w_set_box(c2d_world *w, uint32_t i, int moved)
{
    c2d_w_disk *p = &w->disk[i];
    c2d_body b;
    c2d_world_box box;
    c2d_w_body_at(p, w->now, &b);
    if (w->periodic) b.pos.x = c2d_w_wrap(b.pos.x, w->width), b.pos.y = c2d_w_wrap(b.pos.y, w->height);
    w->box[2 * (size_t)i] = b.pos.x, w->box[2 * (size_t)i + 1] = b.pos.y;
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
    size_t k;
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
        size_t l;
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
