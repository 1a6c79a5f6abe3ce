/* SPDX-License-Identifier: MIT */
/* world/grid.h - the built-in grid's size and rebuild.
 * Part of lib/world.c, which includes the parts once, in order. */

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
