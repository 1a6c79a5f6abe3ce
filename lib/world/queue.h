/* SPDX-License-Identifier: MIT */
/* world/queue.h - the event queue.
 * Part of lib/world.c, which includes the parts once, in order. */

/* (when, tie, disk): a total order, so the events come out in the same
 * order whatever the queue's shape (both disks of a pair may hold the same
 * event: the lower index's copy first). */
static int c2d_w_before(const c2d_w_entry *a, const c2d_w_entry *b)
{
    return a->when < b->when || (a->when == b->when && (a->tie < b->tie || (a->tie == b->tie && a->disk < b->disk)));
}

/* The window: a binary heap of the events of the current day (and any
 * earlier), disk i at w->disk[i].slot. */
static void c2d_w_win_place(c2d_world *w, size_t s, const c2d_w_entry *placed)
{
    c2d_w_entry *h = w->win;
    c2d_w_node *n = w->node;
    const size_t count = w->nwin;
    c2d_w_entry e;
    c2d_w_entry_copy(&e, placed);
    while (s > 0) {
        size_t up = (s - 1) / 2;
        if (!c2d_w_before(&e, &h[up])) break;
        c2d_w_entry_copy(&h[s], &h[up]);
        n[h[s].disk].slot = (uint32_t)s;
        s = up;
    }
    for (;;) {
        size_t l = 2 * s + 1, best = l;
        if (l >= count) break;
        if (l + 1 < count && c2d_w_before(&h[l + 1], &h[l])) best = l + 1;
        if (!c2d_w_before(&h[best], &e)) break;
        c2d_w_entry_copy(&h[s], &h[best]);
        n[h[s].disk].slot = (uint32_t)s;
        s = best;
    }
    c2d_w_entry_copy(&h[s], &e);
    n[e.disk].slot = (uint32_t)s;
}

static void c2d_w_win_push(c2d_world *w, uint32_t i)
{
    c2d_w_entry e;
    e.when = w->node[i].when, e.tie = w->node[i].tie, e.disk = i, e.spare = 0;
    w->node[i].where = C2D_W_Q_WIN;
    w->nwin++;
    c2d_w_win_place(w, w->nwin - 1, &e);
}

static void c2d_w_win_remove(c2d_world *w, uint32_t i)
{
    const size_t s = w->node[i].slot;
    w->nwin--;
    if (s < w->nwin) c2d_w_win_place(w, s, &w->win[w->nwin]);
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
            uint32_t *head = &w->bucket[w->k0 & (w->nbucket - 1)], i;
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
