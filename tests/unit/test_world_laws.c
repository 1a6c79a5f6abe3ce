/* SPDX-License-Identifier: MIT */
/* The world's laws that tests/unit/test_world.c leaves to examples: every
 * impact of a gas against an independent calculation (momentum, energy,
 * the impulse, the restitution or the collapse rule's e = 1), Newton's
 * cradle for every length from 2 to 12, both axes and directions and
 * several masses and speeds, perfectly inelastic (e = 0) clusters that
 * finish, the same events in one advance and in uneven slices with statics,
 * timers and walls, and every refusal, on a busy world and from inside the
 * event callback, leaving every byte as it was. */
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "collide2d_world.h"
#include "world_fixture.h"


static c2d_world_desc box_desc(size_t capacity, double width, double height, c2d_boundary boundary, double e, double ew)
{
    c2d_world_desc d;
    memset(&d, 0, sizeof d);
    d.capacity = capacity, d.width = width, d.height = height, d.boundary = boundary;
    d.restitution = e, d.wall_restitution = ew;
    return d;
}


/* side x side disks on a lattice filling [0, width) x [0, height), radii
 * in [0.6, 1) x radius and masses in [0.1, 1.9) unless `equal`, velocities
 * up to 1 a component with the mean momentum taken out. */
static void fill_gas(c2d_world *w, const c2d_world_desc *d, size_t side, double radius, int equal, uint64_t seed)
{
    size_t i, n = side * side;
    double px = 0, py = 0, m = 0;
    c2d_body *b = malloc(n * sizeof *b);
    double *r = malloc(n * sizeof *r);
    assert_non_null(b);
    assert_non_null(r);
    rng_state = seed;
    for (i = 0; i < n; i++) {
        b[i].pos.x = ((double)(i % side) + 0.5) * d->width / (double)side;
        b[i].pos.y = ((double)(i / side) + 0.5) * d->height / (double)side;
        b[i].vel.x = uniform();
        b[i].vel.y = uniform();
        b[i].mass = equal ? 1 : 1 + 0.9 * uniform();
        r[i] = equal ? radius : radius * (0.8 + 0.2 * uniform());
        px += b[i].mass * b[i].vel.x, py += b[i].mass * b[i].vel.y, m += b[i].mass;
    }
    for (i = 0; i < n; i++) {
        b[i].vel.x -= px / m, b[i].vel.y -= py / m;
        assert_status(c2d_world_add(w, &b[i], r[i], NULL), C2D_OK);
    }
    free(b);
    free(r);
}

static double kinetic(const c2d_world *w)
{
    size_t i, n = c2d_world_count(w);
    double e = 0;
    for (i = 0; i < n; i++) {
        c2d_body b;
        if (c2d_world_get(w, i, &b) != C2D_OK) continue; /* removed */
        e += 0.5 * b.mass * (b.vel.x * b.vel.x + b.vel.y * b.vel.y);
    }
    return e;
}

/* ------------------------------------------------------------ every impact */

/* The callback keeps each disk's velocity after its last event: the
 * velocity before its next one (no accelerations here). */
typedef struct impact_audit {
    c2d_world *w;
    c2d_world_desc d;
    c2d_vec2 *vel;
    long impacts, with_desc_e, walls, wall_inelastic;
    double worst_v, worst_p, worst_e, worst_j; /* in units of their tolerances */
} impact_audit;

static double nearest(double d, double box, int periodic) { return periodic ? d - box * round(d / box) : d; }

/* Impact of a and b: the independent calculation in long double from the
 * states before (the audit's velocities) and the contact positions.  With
 * n the unit normal from a to b, u = (v_b - v_a) . n < 0 and
 * mu = m_a m_b / (m_a + m_b), the impulse on b is J = -(1 + e) mu u n,
 * the energy change -(1 - e^2) mu u^2 / 2, the momentum unchanged.  The
 * world resolves with the desc's e or, by the collapse rule, e = 1: the
 * outcome must be one of the two. */
static void audit_impact(impact_audit *au, const c2d_world_event *ev)
{
    c2d_body a, b;
    long double nx, ny, len, u, mu, va[2], vb[2], best = INFINITY;
    double scale, pscale, escale, e_used = -1;
    int k;
    assert_status(c2d_world_get(au->w, ev->a, &a), C2D_OK);
    assert_status(c2d_world_get(au->w, ev->b, &b), C2D_OK);
    nx = nearest(b.pos.x - a.pos.x, au->d.width, au->d.boundary == C2D_PERIODIC);
    ny = nearest(b.pos.y - a.pos.y, au->d.height, au->d.boundary == C2D_PERIODIC);
    len = sqrtl(nx * nx + ny * ny), nx /= len, ny /= len;
    va[0] = au->vel[ev->a].x, va[1] = au->vel[ev->a].y, vb[0] = au->vel[ev->b].x, vb[1] = au->vel[ev->b].y;
    u = (vb[0] - va[0]) * nx + (vb[1] - va[1]) * ny;
    mu = (long double)a.mass * b.mass / ((long double)a.mass + b.mass);
    assert_true(u < 0);
    /* c2d_collide's 16 ulp of the velocity scale, and the normal from
     * coordinates rounded to ulp(box): box / |n| of those. */
    scale = (fabs((double)va[0]) + fabs((double)va[1]) + fabs((double)vb[0]) + fabs((double)vb[1])) *
            (16 + au->d.width / (double)len) * DBL_EPSILON;
    pscale = 8 * DBL_EPSILON * (a.mass + b.mass) * (fabs(a.vel.x) + fabs(a.vel.y) + fabs(b.vel.x) + fabs(b.vel.y));
    escale = 32 * DBL_EPSILON *
             (a.mass * (double)(va[0] * va[0] + va[1] * va[1]) + b.mass * (double)(vb[0] * vb[0] + vb[1] * vb[1]));
    for (k = 0; k < 2; k++) {
        const double e = k == 0 ? au->d.restitution : 1;
        const long double j = -(1 + (long double)e) * mu * u;
        const long double ax = va[0] - j * nx / a.mass, ay = va[1] - j * ny / a.mass;
        const long double bx = vb[0] + j * nx / b.mass, by = vb[1] + j * ny / b.mass;
        long double dev = fabsl(a.vel.x - ax);
        if (fabsl(a.vel.y - ay) > dev) dev = fabsl(a.vel.y - ay);
        if (fabsl(b.vel.x - bx) > dev) dev = fabsl(b.vel.x - bx);
        if (fabsl(b.vel.y - by) > dev) dev = fabsl(b.vel.y - by);
        if (dev < best) {
            const long double de =
                0.5L * (a.mass * ((long double)a.vel.x * a.vel.x + (long double)a.vel.y * a.vel.y) +
                        b.mass * ((long double)b.vel.x * b.vel.x + (long double)b.vel.y * b.vel.y)) -
                0.5L * (a.mass * (va[0] * va[0] + va[1] * va[1]) + b.mass * (vb[0] * vb[0] + vb[1] * vb[1]));
            const long double de_want = -(1 - (long double)e * e) * mu * u * u / 2;
            const long double dj = fmaxl(fabsl(ev->impulse.x - j * nx), fabsl(ev->impulse.y - j * ny));
            best = dev, e_used = e;
            au->worst_e = fmax(au->worst_e, (double)(fabsl(de - de_want) / escale));
            au->worst_j = fmax(au->worst_j, (double)(dj / (b.mass * scale)));
        }
    }
    au->worst_v = fmax(au->worst_v, (double)(best / scale));
    {
        const long double dpx =
            (a.mass * (long double)a.vel.x + b.mass * (long double)b.vel.x) - (a.mass * va[0] + b.mass * vb[0]);
        const long double dpy =
            (a.mass * (long double)a.vel.y + b.mass * (long double)b.vel.y) - (a.mass * va[1] + b.mass * vb[1]);
        au->worst_p = fmax(au->worst_p, (double)(fmaxl(fabsl(dpx), fabsl(dpy)) / pscale));
    }
    au->impacts++;
    au->with_desc_e += e_used == au->d.restitution;
    au->vel[ev->a] = a.vel, au->vel[ev->b] = b.vel;
}

/* A wall: the normal component negated and times the wall's restitution
 * (or 1, the collapse rule), exactly; the other unchanged, exactly. */
static void audit_wall(impact_audit *au, const c2d_world_event *ev)
{
    c2d_body a;
    const int axis = (int)(ev->b / 2);
    const double vn = axis == 0 ? au->vel[ev->a].x : au->vel[ev->a].y,
                 vt = axis == 0 ? au->vel[ev->a].y : au->vel[ev->a].x;
    double got_n, got_t;
    assert_status(c2d_world_get(au->w, ev->a, &a), C2D_OK);
    got_n = axis == 0 ? a.vel.x : a.vel.y, got_t = axis == 0 ? a.vel.y : a.vel.x;
    assert_true(got_t == vt);
    assert_true(got_n == -au->d.wall_restitution * vn || got_n == -vn);
    assert_true(ev->b % 2 == 0 ? vn < 0 && got_n >= 0 : vn > 0 && got_n <= 0);
    au->walls++;
    au->wall_inelastic += got_n != -vn;
    au->vel[ev->a] = a.vel;
}

static void audit_event(void *user, const c2d_world_event *ev)
{
    impact_audit *au = user;
    if (ev->kind == C2D_WORLD_IMPACT) audit_impact(au, ev);
    else if (ev->kind == C2D_WORLD_WALL) audit_wall(au, ev);
    else fail(); /* no timers, no statics here */
}

static void test_every_impact_of_a_gas_agrees_with_the_independent_collision_law(void **state)
{
    int periodic;
    (void)state;
    for (periodic = 0; periodic <= 1; periodic++) {
        impact_audit au;
        void *mem;
        size_t i;
        memset(&au, 0, sizeof au);
        au.d = box_desc(100, 16, 14, periodic ? C2D_PERIODIC : C2D_WALLS, periodic ? 1 : 0.9, 0.7);
        au.d.on_event = audit_event, au.d.user = &au;
        au.vel = malloc(100 * sizeof *au.vel);
        assert_non_null(au.vel);
        au.w = new_world(&au.d, &mem);
        fill_gas(au.w, &au.d, 10, 0.5, 0, 31 + (uint64_t)periodic);
        for (i = 0; i < 100; i++) {
            c2d_body b;
            assert_status(c2d_world_get(au.w, i, &b), C2D_OK);
            au.vel[i] = b.vel;
        }
        assert_status(c2d_world_advance(au.w, 40), C2D_OK);
        printf("test_world_laws: %s, %ld impacts (%ld at e = %g, the rest at e = 1 by the collapse rule), %ld at walls "
               "(%ld inelastic): worst velocity %.2f, momentum %.2f, energy %.2f, impulse %.2f of their tolerances\n",
               periodic ? "periodic e = 1" : "walls e = 0.9", au.impacts, au.with_desc_e, au.d.restitution, au.walls,
               au.wall_inelastic, au.worst_v, au.worst_p, au.worst_e, au.worst_j);
        assert_true(au.impacts > 1000);
        assert_true(au.worst_v <= 1 && au.worst_p <= 1 && au.worst_e <= 1 && au.worst_j <= 1);
        if (!periodic) {
            /* A gas cooling for 40 time units stays far from collapse:
             * nearly every impact keeps the desc's restitution. */
            assert_true(au.with_desc_e > au.impacts * 9 / 10);
            assert_true(au.walls > 100 && au.wall_inelastic > au.walls * 9 / 10);
        }
        free(au.vel);
        free(mem);
    }
}

/* ------------------------------------------------------------ the cradle */

/* A striker (index 0) 4 gaps away from a row of n - 1 touching disks
 * (indices 1..n-1, centres 1 apart, radius 0.5) along `axis`, moving at
 * `speed` towards it from the low side (dir +1) or the high side (-1); all
 * of mass m.  After the impacts only the disk at the far end of the row
 * moves, with the striker's velocity exactly: n - 1 impacts. */
static void run_cradle(size_t n, int axis, int dir, double m, double speed)
{
    c2d_world_desc d =
        box_desc(n, axis == 0 ? 2.0 * (double)n + 30 : 6, axis == 0 ? 6 : 2.0 * (double)n + 30, C2D_WALLS, 1, 1);
    const double base = 15, start = dir > 0 ? base - 4 : base + (double)n + 4;
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    c2d_world_stats s;
    c2d_body b;
    size_t i, leaver = dir > 0 ? n - 1 : 1;
    for (i = 0; i < n; i++) {
        const double along = i == 0 ? start : base + (double)i, across = 3;
        b.pos.x = axis == 0 ? along : across, b.pos.y = axis == 0 ? across : along;
        b.vel.x = i == 0 && axis == 0 ? dir * speed : 0, b.vel.y = i == 0 && axis == 1 ? dir * speed : 0;
        b.mass = m;
        assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    }
    assert_status(c2d_world_advance(w, 7 / speed), C2D_OK); /* the contacts at 4 / speed, then 3 free */
    c2d_world_get_stats(w, &s);
    assert_int_equal(s.collisions, n - 1);
    assert_int_equal(s.wall_collisions, 0);
    for (i = 0; i < n; i++) {
        const double want = i == leaver ? dir * speed : 0;
        assert_status(c2d_world_get(w, i, &b), C2D_OK);
        assert_true((axis == 0 ? b.vel.x : b.vel.y) == want);
        assert_true((axis == 0 ? b.vel.y : b.vel.x) == 0);
    }
    free(mem);
}

static void test_a_cradle_of_n_equal_disks_has_n_minus_1_impacts_and_passes_the_speed_exactly(void **state)
{
    const double masses[] = {1, 0.37, 1e3, 3e-4}, speeds[] = {0.75, 3.125, 0.1};
    size_t n, mi, si;
    int axis, dir, runs = 0;
    (void)state;
    for (n = 2; n <= 12; n++)
        for (axis = 0; axis <= 1; axis++)
            for (dir = -1; dir <= 1; dir += 2)
                for (mi = 0; mi < sizeof masses / sizeof masses[0]; mi++)
                    for (si = 0; si < sizeof speeds / sizeof speeds[0]; si++, runs++)
                        run_cradle(n, axis, dir, masses[mi], speeds[si]);
    assert_cases_checked(runs, 11 * 2 * 2 * 4 * 3);
}

/* ------------------------------------------------------------ collapse */

/* Events of one advance, failing the test (rather than hanging it) past
 * `limit`: a world that never finishes an advance. */
typedef struct event_budget {
    long events, limit;
    void *mem; /* the world's, freed before failing: the advance never returns to free it */
} event_budget;

static void spend_event(void *user, const c2d_world_event *e)
{
    event_budget *b = user;
    if (++b->events > b->limit) {
        const c2d_world_event last = *e;
        free(b->mem);
        fail_msg("more than %ld events: the advance does not finish (the last of kind %d at t = %.17g between %lu "
                 "and %lu, impulse (%g, %g))",
                 b->limit, (int)last.kind, last.time, (unsigned long)last.a, (unsigned long)last.b, last.impulse.x,
                 last.impulse.y);
    }
}

/* A 5 x 5 square cluster of touching disks (centres 1 apart) in a box
 * with walls, e = 0 everywhere, struck at a corner (and, the second time,
 * at the opposite corner at the same instant): perfectly inelastic, so
 * without a rule the impacts would never end.  It must finish with few
 * events, lose energy at every step and nothing overlap. */
static void run_cluster(int strikers)
{
    c2d_world_desc d = box_desc(27, 20, 20, C2D_WALLS, 0, 0);
    event_budget budget = {0, 100000, NULL};
    void *mem;
    c2d_world *w;
    c2d_body b = {{0, 0}, {0, 0}, 1};
    c2d_world_stats s;
    double prev, t;
    size_t i, j;
    d.on_event = spend_event, d.user = &budget;
    w = new_world(&d, &mem);
    budget.mem = mem;
    for (i = 0; i < 25; i++) {
        b.pos.x = 8 + (double)(i % 5), b.pos.y = 8 + (double)(i / 5);
        assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    }
    b.pos.x = 5, b.pos.y = 5.25, b.vel.x = 2, b.vel.y = 2, b.mass = 3;
    assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    if (strikers == 2) {
        b.pos.x = 15, b.pos.y = 14.75, b.vel.x = -2, b.vel.y = -2;
        assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    }
    prev = kinetic(w);
    for (t = 0.25; t <= 60; t += 0.25) {
        double e;
        assert_status(c2d_world_advance(w, t), C2D_OK);
        e = kinetic(w);
        assert_true(e <= prev * (1 + 1e-12));
        prev = e;
        for (i = 0; i < c2d_world_count(w); i++)
            for (j = i + 1; j < c2d_world_count(w); j++) {
                c2d_body p, q;
                assert_status(c2d_world_get(w, i, &p), C2D_OK);
                assert_status(c2d_world_get(w, j, &q), C2D_OK);
                assert_true(hypot(q.pos.x - p.pos.x, q.pos.y - p.pos.y) >= 1 - 1e-9);
            }
    }
    c2d_world_get_stats(w, &s);
    printf("test_world_laws: e = 0 cluster, %d striker%s: %llu impacts, %llu at walls, %llu events by t = 60, "
           "energy left %.3e\n",
           strikers, strikers == 2 ? "s" : "", s.collisions, s.wall_collisions, s.events, prev / (strikers * 12.0));
    assert_true(s.collisions > 25 && s.events < 100000);
    assert_true(prev < strikers * 12.0);
    free(mem);
}

static void test_a_touching_cluster_at_e_0_struck_at_a_corner_finishes_and_only_loses_energy(void **state)
{
    (void)state;
    run_cluster(1);
}

/* The two strikers meet the cluster's opposite corners at the same
 * instant; at t = 5.63 disks 2 and 9 then meet so slowly that even the
 * elastic impulse rounds away, which once made one zero-impulse impact
 * follow the other at that instant for ever (e = 0 only): the world takes
 * an impact that changes nothing as no impact. */
static void test_a_touching_cluster_at_e_0_struck_at_opposite_corners_at_once_finishes(void **state)
{
    (void)state;
    run_cluster(2);
}

/* ------------------------------------------------------------ bits */

/* FNV-1a over every event's bytes, kept by the callback; timers change the
 * motion (acceleration from the index, a kick for every third disk, a new
 * timer for the even ones). */
typedef struct event_hash {
    c2d_world *w;
    uint64_t h;
    long events, timers, statics;
} event_hash;

static void fnv(uint64_t *h, const void *p, size_t n)
{
    const unsigned char *c = p;
    size_t i;
    for (i = 0; i < n; i++) *h = (*h ^ c[i]) * 0x100000001B3ull;
}

static void hash_event(void *user, const c2d_world_event *e)
{
    event_hash *eh = user;
    uint64_t idx[2];
    idx[0] = e->a, idx[1] = e->b;
    fnv(&eh->h, &e->kind, sizeof e->kind);
    fnv(&eh->h, &e->time, sizeof e->time);
    fnv(&eh->h, idx, sizeof idx);
    fnv(&eh->h, &e->impulse, sizeof e->impulse);
    eh->events++;
    eh->statics += e->kind == C2D_WORLD_STATIC;
    if (e->kind == C2D_WORLD_TIMER) {
        c2d_vec2 acc, kick;
        eh->timers++;
        acc.x = 0.15 * (double)(e->a % 5) - 0.3, acc.y = e->a % 2 ? -0.3 : 0.2;
        assert_status(c2d_world_set_acceleration(eh->w, e->a, acc), C2D_OK);
        if (e->a % 3 == 0) {
            kick.x = 0.5, kick.y = -0.25 * (double)(e->a % 4);
            assert_status(c2d_world_set_velocity(eh->w, e->a, kick), C2D_OK);
        }
        if (e->a % 2 == 0) assert_status(c2d_world_set_timer(eh->w, e->a, e->time + 0.8125), C2D_OK);
    }
}

static void statics_run(int sliced, event_hash *eh, c2d_body *out, c2d_world_stats *stats)
{
    c2d_world_desc d = box_desc(36, 16, 12, C2D_WALLS, 0.9, 0.6);
    void *mem;
    c2d_world *w;
    c2d_vec2 p = {11, 2}, q = {15, 5}, r = {12, 10.5}, s = {15.5, 8}, c = {13.5, 6.5};
    size_t i;
    d.statics = 3, d.on_event = hash_event, d.user = eh;
    memset(eh, 0, sizeof *eh);
    eh->h = 0xCBF29CE484222325ull;
    w = new_world(&d, &mem);
    eh->w = w;
    rng_state = 41;
    for (i = 0; i < 36; i++) {
        c2d_body b;
        c2d_vec2 acc;
        b.pos.x = ((double)(i % 6) + 0.5) * 10 / 6, b.pos.y = ((double)(i / 6) + 0.5) * 2;
        b.vel.x = uniform(), b.vel.y = uniform(), b.mass = 1.2 + uniform();
        assert_status(c2d_world_add(w, &b, 0.3 + 0.1 * uniform(), NULL), C2D_OK);
        acc.x = 0.3 + 0.3 * uniform(), acc.y = 0.2 * uniform() - 0.1;
        assert_status(c2d_world_set_acceleration(w, i, acc), C2D_OK);
        assert_status(c2d_world_set_timer(w, i, 0.375 * (double)i + 0.25), C2D_OK);
    }
    assert_status(c2d_world_add_segment(w, p, q, 0.7, NULL), C2D_OK);
    assert_status(c2d_world_add_segment(w, r, s, 1, NULL), C2D_OK);
    assert_status(c2d_world_add_circle(w, c, 0.6, 0.5, NULL), C2D_OK);
    if (sliced) {
        double t = 0;
        rng_state = 43;
        while (t < 30) {
            const double u = uniform();
            t += u < -0.75 ? 0 : u < -0.5 ? 1e-9 : 0.3 * (1 + u); /* some repeated, some tiny */
            if (t > 30) t = 30;
            assert_status(c2d_world_advance(w, t), C2D_OK);
        }
    }
    assert_status(c2d_world_advance(w, 30), C2D_OK);
    for (i = 0; i < 36; i++) assert_status(c2d_world_get(w, i, &out[i]), C2D_OK);
    c2d_world_get_stats(w, stats);
    free(mem);
}

static void test_statics_timers_and_walls_give_the_same_events_in_one_advance_and_in_uneven_slices(void **state)
{
    event_hash one, many;
    c2d_body a[36], b[36];
    c2d_world_stats sa, sb;
    (void)state;
    statics_run(0, &one, a, &sa);
    statics_run(1, &many, b, &sb);
    printf("test_world_laws: statics, timers, walls: %ld events (%ld timers, %ld at statics), hash %016llx\n",
           one.events, one.timers, one.statics, (unsigned long long)one.h);
    assert_true(one.timers > 36 && one.statics > 10 && sa.collisions > 50);
    assert_true(one.h == many.h && one.events == many.events);
    assert_memory_equal(a, b, sizeof a);
    assert_memory_equal(&sa, &sb, sizeof sa);
}

/* ------------------------------------------------------------ refusals */

/* Every refused call, with every kind of bad argument, on a world that
 * has moved, accelerated disks, pending timers, statics (full), a removed
 * disk and no capacity left. */
static void refuse_everything(c2d_world *w, double now)
{
    const double bad[] = {NAN, INFINITY, -INFINITY};
    c2d_body b, got;
    c2d_vec2 ok = {0.5, 0.5}, v;
    c2d_world_stats s;
    const c2d_vec2 far = {2, 1};
    size_t k;
    int f;
    for (k = 0; k < 3; k++) {
        for (f = 0; f < 6; f++) {
            b.pos.x = 1.5, b.pos.y = 1.5, b.vel.x = 0, b.vel.y = 0, b.mass = 1;
            if (f == 0) b.pos.x = bad[k];
            if (f == 1) b.pos.y = bad[k];
            if (f == 2) b.vel.x = bad[k];
            if (f == 3) b.vel.y = bad[k];
            if (f == 4) b.mass = bad[k];
            assert_status(c2d_world_add(w, &b, f == 5 ? bad[k] : 0.1, NULL), C2D_INVALID);
        }
        v.x = bad[k], v.y = 0;
        assert_status(c2d_world_set_velocity(w, 0, v), C2D_INVALID);
        assert_status(c2d_world_set_acceleration(w, 0, v), C2D_INVALID);
        v.x = 0, v.y = bad[k];
        assert_status(c2d_world_set_velocity(w, 0, v), C2D_INVALID);
        assert_status(c2d_world_set_acceleration(w, 0, v), C2D_INVALID);
        assert_status(c2d_world_advance(w, bad[k]), C2D_INVALID);
        assert_status(c2d_world_add_segment(w, v, ok, 1, NULL), C2D_INVALID);
        assert_status(c2d_world_add_circle(w, v, 1, 1, NULL), C2D_INVALID);
        assert_status(c2d_world_add_circle(w, ok, bad[k], 1, NULL), C2D_INVALID);
        assert_status(c2d_world_add_segment(w, ok, far, bad[k], NULL), C2D_INVALID);
    }
    assert_status(c2d_world_set_timer(w, 0, NAN), C2D_INVALID);
    assert_status(c2d_world_set_timer(w, 0, -INFINITY), C2D_INVALID);
    assert_status(c2d_world_set_timer(w, 0, now - 0.5), C2D_INVALID);
    b.pos.x = 5, b.pos.y = 5, b.vel.x = 0, b.vel.y = 0, b.mass = 1;
    assert_status(c2d_world_add(w, &b, 0.1, NULL), C2D_INVALID); /* full (or inside the callback) */
    assert_status(c2d_world_add(w, &b, 0, NULL), C2D_INVALID);
    b.mass = 0;
    assert_status(c2d_world_add(w, &b, 0.1, NULL), C2D_INVALID);
    assert_status(c2d_world_add(NULL, &b, 0.1, NULL), C2D_INVALID);
    assert_status(c2d_world_add(w, NULL, 0.1, NULL), C2D_INVALID);
    assert_status(c2d_world_advance(w, now - 1e-9), C2D_INVALID);
    assert_status(c2d_world_advance(NULL, now + 1), C2D_INVALID);
    for (k = 1; k <= 2; k++) { /* 1: removed, 2: out of range */
        const size_t i = k == 1 ? 3 : c2d_world_count(w);
        assert_status(c2d_world_get(w, i, &got), C2D_INVALID);
        assert_status(c2d_world_get_acceleration(w, i, &v), C2D_INVALID);
        assert_status(c2d_world_set_velocity(w, i, ok), C2D_INVALID);
        assert_status(c2d_world_set_acceleration(w, i, ok), C2D_INVALID);
        assert_status(c2d_world_set_timer(w, i, now + 1), C2D_INVALID);
        assert_status(c2d_world_remove(w, i), C2D_INVALID);
    }
    assert_status(c2d_world_remove(NULL, 0), C2D_INVALID);
    assert_status(c2d_world_set_velocity(NULL, 0, ok), C2D_INVALID);
    assert_status(c2d_world_set_acceleration(NULL, 0, ok), C2D_INVALID);
    assert_status(c2d_world_set_timer(NULL, 0, now + 1), C2D_INVALID);
    assert_status(c2d_world_get(w, 0, NULL), C2D_INVALID);
    assert_status(c2d_world_get_acceleration(w, 0, NULL), C2D_INVALID);
    assert_status(c2d_world_add_segment(w, ok, ok, 1, NULL), C2D_INVALID); /* a == b */
    assert_status(c2d_world_add_segment(w, ok, far, 1.5, NULL), C2D_INVALID);
    assert_status(c2d_world_add_segment(w, ok, far, 1, NULL), C2D_INVALID); /* the statics full */
    assert_status(c2d_world_add_circle(w, ok, 0, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_circle(w, ok, 1, -0.5, NULL), C2D_INVALID);
    assert_status(c2d_world_add_circle(w, ok, 1, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_segment(NULL, ok, far, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_circle(NULL, ok, 1, 1, NULL), C2D_INVALID);
    /* Reads that succeed change nothing either. */
    assert_status(c2d_world_get(w, 0, &got), C2D_OK);
    assert_status(c2d_world_get_acceleration(w, 0, &v), C2D_OK);
    c2d_world_get_stats(w, &s);
    assert_true(c2d_world_count(w) == 16);
}

typedef struct refusal_probe {
    c2d_world *w;
    const void *mem;
    size_t bytes;
    unsigned char *copy;
    int probed;
} refusal_probe;

/* From inside the callback, at the first timer: the world's memory as it
 * is mid-advance must not change by any refused call, nor by the calls
 * the callback may not make (add, a static, advance; removing is allowed,
 * for pockets). */
static void probe_refusals(void *user, const c2d_world_event *e)
{
    refusal_probe *p = user;
    if (e->kind != C2D_WORLD_TIMER || p->probed) return;
    memcpy(p->copy, p->mem, p->bytes);
    refuse_everything(p->w, e->time);
    {
        const c2d_vec2 centre = {6, 6};
        assert_status(c2d_world_add_sensor(p->w, centre, 1, NULL), C2D_INVALID);
    }
    assert_status(c2d_world_advance(p->w, e->time + 1), C2D_INVALID);
    assert_status(c2d_world_advance(p->w, e->time), C2D_INVALID);
    assert_memory_equal(p->copy, p->mem, p->bytes);
    p->probed = 1;
}

static void test_every_refusal_on_a_busy_world_and_inside_its_callback_changes_no_byte(void **state)
{
    c2d_world_desc d = box_desc(16, 12, 12, C2D_WALLS, 0.9, 0.8);
    refusal_probe probe;
    void *mem;
    c2d_world *w;
    c2d_vec2 p = {5.5, 5.5}, q = {6.5, 6.5}, c = {3, 3}, g = {0, -0.5}; /* clear of the lattice's disks */
    size_t i, bytes;
    (void)state;
    d.statics = 2, d.on_event = probe_refusals, d.user = &probe;
    w = new_world(&d, &mem);
    bytes = c2d_world_bytes(&d);
    probe.w = w, probe.mem = mem, probe.bytes = bytes, probe.copy = malloc(bytes), probe.probed = 0;
    assert_non_null(probe.copy);
    fill_gas(w, &d, 4, 0.6, 0, 51);
    assert_status(c2d_world_add_segment(w, p, q, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_add_circle(w, c, 0.4, 1, NULL), C2D_OK);
    for (i = 0; i < 16; i++) {
        assert_status(c2d_world_set_acceleration(w, i, g), C2D_OK);
        assert_status(c2d_world_set_timer(w, i, 2.5 + (double)i), C2D_OK);
    }
    assert_status(c2d_world_remove(w, 3), C2D_OK); /* refuse_everything's removed disk */
    assert_status(c2d_world_advance(w, 3.7), C2D_OK);
    assert_true(probe.probed);
    memcpy(probe.copy, mem, bytes);
    refuse_everything(w, 3.7);
    {
        /* init over the live world with a bad description, or too little memory */
        c2d_world_desc bad = d;
        c2d_world *other = NULL;
        bad.restitution = 2;
        assert_status(c2d_world_init(&other, mem, bytes, &bad), C2D_INVALID);
        assert_status(c2d_world_init(&other, mem, bytes - 8, &d), C2D_INVALID);
        assert_null(other);
    }
    assert_memory_equal(probe.copy, mem, bytes);
    free(probe.copy);
    free(mem);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_impact_of_a_gas_agrees_with_the_independent_collision_law),
        cmocka_unit_test(test_a_cradle_of_n_equal_disks_has_n_minus_1_impacts_and_passes_the_speed_exactly),
        cmocka_unit_test(test_a_touching_cluster_at_e_0_struck_at_a_corner_finishes_and_only_loses_energy),
        cmocka_unit_test(test_a_touching_cluster_at_e_0_struck_at_opposite_corners_at_once_finishes),
        cmocka_unit_test(test_statics_timers_and_walls_give_the_same_events_in_one_advance_and_in_uneven_slices),
        cmocka_unit_test(test_every_refusal_on_a_busy_world_and_inside_its_callback_changes_no_byte),
    };
    return c2d_run_tests("test_world_laws", tests);
}
