/* SPDX-License-Identifier: MIT */
/* world/cells.h - the built-in broadphase's cells.
 * Part of lib/world.c, which includes the parts once, in order. */

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
