/* SPDX-License-Identifier: MIT */
/* How the world resolves and reports contacts (collide2d_world.h): sensors
 * that report a centre entering and resolve nothing, disks removed from
 * the event callback (a pocketed ball), caller resolvers per contact kind
 * and the guard that overrules a bad one, and the rough model (spins)
 * checked against the conservation laws of Walton's rough disks. */
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "collide2d_world.h"
#include "world_fixture.h"


static c2d_world_desc walled(size_t capacity, double width, double height, size_t statics)
{
    c2d_world_desc d;
    memset(&d, 0, sizeof d);
    d.capacity = capacity, d.width = width, d.height = height, d.boundary = C2D_WALLS;
    d.restitution = 1, d.wall_restitution = 1, d.statics = statics;
    return d;
}


static void add(c2d_world *w, double x, double y, double vx, double vy, double mass, double radius)
{
    c2d_body b;
    b.pos.x = x, b.pos.y = y, b.vel.x = vx, b.vel.y = vy, b.mass = mass;
    assert_status(c2d_world_add(w, &b, radius, NULL), C2D_OK);
}

static c2d_body state(const c2d_world *w, size_t i)
{
    c2d_body b;
    assert_status(c2d_world_get(w, i, &b), C2D_OK);
    return b;
}

/* Every event, kept. */
typedef struct journal {
    c2d_world *w;
    int n, remove_at_sensor;
    c2d_world_event ev[64];
} journal;

static void keep(void *user, const c2d_world_event *e)
{
    journal *j = user;
    if (j->n < 64) j->ev[j->n] = *e;
    j->n++;
    if (e->kind == C2D_WORLD_SENSOR && j->remove_at_sensor) assert_status(c2d_world_remove(j->w, e->a), C2D_OK);
}

static int count_kind(const journal *j, c2d_world_event_kind kind)
{
    int k, n = 0;
    for (k = 0; k < j->n && k < 64; k++) n += j->ev[k].kind == kind;
    return n;
}

/* ------------------------------------------------------------ sensors */

static void test_a_sensor_reports_each_entry_of_a_centre_and_changes_no_motion(void **state_)
{
    /* A disk at x = 1 moving at +2 crosses a sensor of radius 1 at x = 5:
     * its centre enters at x = 4 (t = 1.5), leaves at x = 6, bounces off
     * the wall at x = 10 - 0.5 (t = 4.25) and enters again at x = 6
     * (t = 4.25 + 3.5 / 2 = 6). */
    c2d_world_desc d = walled(1, 10, 4, 1);
    journal j;
    void *mem;
    c2d_world *w;
    c2d_vec2 centre = {5, 2};
    size_t k;
    c2d_body b;
    (void)state_;
    memset(&j, 0, sizeof j);
    d.on_event = keep, d.user = &j;
    w = new_world(&d, &mem);
    j.w = w;
    assert_status(c2d_world_add_sensor(w, centre, 1, &k), C2D_OK);
    assert_int_equal(k, 0);
    add(w, 1, 2, 2, 0, 1, 0.5);
    assert_status(c2d_world_advance(w, 7), C2D_OK);
    assert_int_equal(j.n, 3);
    assert_true(j.ev[0].kind == C2D_WORLD_SENSOR && j.ev[0].time == 1.5 && j.ev[0].a == 0 && j.ev[0].b == 0);
    assert_true(j.ev[0].impulse.x == 0 && j.ev[0].impulse.y == 0);
    assert_true(j.ev[1].kind == C2D_WORLD_WALL && j.ev[1].time == 4.25);
    assert_true(j.ev[2].kind == C2D_WORLD_SENSOR && j.ev[2].time == 6);
    b = state(w, 0);
    assert_true(b.pos.x == 4 && b.pos.y == 2 && b.vel.x == -2 && b.vel.y == 0);
    {
        c2d_world_stats s;
        c2d_world_get_stats(w, &s);
        assert_true(s.collisions == 0 && s.wall_collisions == 1);
    }
    free(mem);
}

static void test_a_disk_starting_inside_a_sensor_is_reported_only_once_it_comes_back(void **state_)
{
    c2d_world_desc d = walled(1, 10, 4, 1);
    journal j;
    void *mem;
    c2d_world *w;
    c2d_vec2 centre = {2, 2};
    (void)state_;
    memset(&j, 0, sizeof j);
    d.on_event = keep, d.user = &j;
    w = new_world(&d, &mem);
    j.w = w;
    assert_status(c2d_world_add_sensor(w, centre, 1, NULL), C2D_OK);
    add(w, 2, 2, 1, 0, 1, 0.5); /* inside, leaving at t = 1, wall at t = 7.5, back at 3 when t = 14 */
    assert_status(c2d_world_advance(w, 13.5), C2D_OK);
    assert_int_equal(count_kind(&j, C2D_WORLD_SENSOR), 0);
    assert_status(c2d_world_advance(w, 15), C2D_OK);
    assert_int_equal(count_kind(&j, C2D_WORLD_SENSOR), 1);
    assert_true(j.ev[j.n - 1].time == 14);
    free(mem);
}

static void test_an_accelerated_disk_entering_a_sensor_is_reported_when_its_parabola_says(void **state_)
{
    /* x(t) = 1 + 3 t - t^2 / 2 (a = -1) reaches 4 (the sensor's edge) at
     * t^2 - 6 t + 6 = 0: t = 3 - sqrt(3). */
    c2d_world_desc d = walled(1, 20, 4, 1);
    journal j;
    void *mem;
    c2d_world *w;
    c2d_vec2 centre = {5, 2}, acc = {-1, 0};
    (void)state_;
    memset(&j, 0, sizeof j);
    d.on_event = keep, d.user = &j;
    w = new_world(&d, &mem);
    j.w = w;
    assert_status(c2d_world_add_sensor(w, centre, 1, NULL), C2D_OK);
    add(w, 1, 2, 3, 0, 1, 0.5);
    assert_status(c2d_world_set_acceleration(w, 0, acc), C2D_OK);
    assert_status(c2d_world_advance(w, 2), C2D_OK);
    assert_int_equal(j.n, 1);
    assert_close(j.ev[0].time, 3 - sqrt(3.0), 4e-16 * 3);
    free(mem);
}

static void test_a_disk_removed_at_its_sensor_event_is_gone_and_the_others_move_on(void **state_)
{
    /* A pocket: disk 0 enters it at t = 0.5 and is taken out; disk 1,
     * which would have hit disk 0 at t = 1.25 (centres 1 apart closing at
     * 2 from 3.5 apart), sails on to the wall. */
    c2d_world_desc d = walled(2, 12, 4, 1);
    journal j;
    void *mem;
    c2d_world *w;
    c2d_vec2 centre = {2, 2};
    c2d_body b;
    (void)state_;
    memset(&j, 0, sizeof j);
    j.remove_at_sensor = 1;
    d.on_event = keep, d.user = &j;
    w = new_world(&d, &mem);
    j.w = w;
    assert_status(c2d_world_add_sensor(w, centre, 0.5, NULL), C2D_OK);
    add(w, 3, 2, -1, 0, 1, 0.5);
    add(w, 6.5, 2, -3, 0, 1, 0.5);
    assert_status(c2d_world_advance(w, 1.9), C2D_OK);
    assert_int_equal(j.n, 2);
    assert_true(j.ev[0].kind == C2D_WORLD_SENSOR && j.ev[0].a == 0 && j.ev[0].time == 0.5);
    assert_true(j.ev[1].kind == C2D_WORLD_SENSOR && j.ev[1].a == 1);
    assert_close(j.ev[1].time, 4.0 / 3.0, 4e-16 * 2);
    assert_status(c2d_world_get(w, 0, &b), C2D_INVALID);
    assert_status(c2d_world_get(w, 1, &b), C2D_INVALID);
    free(mem);
}

static void test_sensor_refusals_change_nothing(void **state_)
{
    c2d_world_desc d = walled(1, 10, 4, 1), smooth = walled(1, 10, 4, 0);
    void *mem, *mem2, *copy;
    c2d_world *w = NULL, *w2;
    const size_t bytes = c2d_world_bytes(&d);
    c2d_vec2 c = {5, 2}, bad = {NAN, 2};
    double spin = 7;
    (void)state_;
    w = new_world(&d, &mem);
    w2 = new_world(&smooth, &mem2);
    add(w, 1, 1, 1, 0, 1, 0.5);
    copy = malloc(bytes);
    memcpy(copy, mem, bytes);
    assert_status(c2d_world_add_sensor(NULL, c, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_sensor(w, bad, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_sensor(w, c, 0, NULL), C2D_INVALID);
    assert_status(c2d_world_add_sensor(w, c, -1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_sensor(w, c, INFINITY, NULL), C2D_INVALID);
    assert_status(c2d_world_set_spin(w, 0, 1), C2D_INVALID); /* a smooth world has no spins */
    assert_status(c2d_world_get_spin(w, 0, &spin), C2D_INVALID);
    assert_true(spin == 7);
    assert_memory_equal(copy, mem, bytes);
    assert_status(c2d_world_add_sensor(w2, c, 1, NULL), C2D_INVALID); /* no statics allowed */
    assert_status(c2d_world_add_sensor(w, c, 1, NULL), C2D_OK);
    assert_status(c2d_world_add_sensor(w, c, 1, NULL), C2D_INVALID); /* full */
    free(copy);
    free(mem);
    free(mem2);
}

/* ------------------------------------------------------------ resolvers */

typedef struct judge {
    int calls, mode, inside_refused;
    c2d_world *w;
    c2d_world_contact last;
} judge;

enum { STICK, GIVE_NAN, KEEP_APPROACHING, REFUSE, HALF_BOUNCE };

/* STICK: both take the centre-of-mass velocity (e = 0 along every axis);
 * HALF_BOUNCE (walls): the normal velocity reversed at half the speed. */
static c2d_status judge_resolve(void *user, const c2d_world_contact *c, c2d_body *a, c2d_body *b)
{
    judge *j = user;
    const c2d_vec2 nothing = {0, 0};
    j->calls++;
    j->last = *c;
    j->inside_refused +=
        c2d_world_set_velocity(j->w, c->a, nothing) == C2D_INVALID && c2d_world_remove(j->w, c->a) == C2D_INVALID;
    switch (j->mode) {
    case STICK: {
        const double m = a->mass + b->mass;
        const double vx = (a->mass * a->vel.x + b->mass * b->vel.x) / m,
                     vy = (a->mass * a->vel.y + b->mass * b->vel.y) / m;
        a->vel.x = b->vel.x = vx, a->vel.y = b->vel.y = vy;
        return C2D_OK;
    }
    case GIVE_NAN: a->vel.x = NAN; return C2D_OK;
    case KEEP_APPROACHING: return C2D_OK; /* velocities unchanged: still approaching */
    case HALF_BOUNCE:
        if (c->normal.x != 0) a->vel.x = -0.5 * a->vel.x;
        else a->vel.y = -0.5 * a->vel.y;
        return C2D_OK;
    default: return C2D_INVALID;
    }
}

static void test_a_callers_impact_resolver_decides_the_velocities(void **state_)
{
    /* Masses 1 and 3 closing at 4 stick: both at (1 * 3 + 3 * -1) / 4 = 0. */
    c2d_world_desc d = walled(2, 10, 4, 0);
    judge j;
    void *mem;
    c2d_world *w;
    c2d_body a, b;
    (void)state_;
    memset(&j, 0, sizeof j);
    j.mode = STICK;
    d.resolve_impact = judge_resolve, d.user = &j;
    w = new_world(&d, &mem);
    j.w = w;
    add(w, 2, 2, 3, 0, 1, 0.5);
    add(w, 7, 2, -1, 0, 3, 0.5); /* they meet at t = 1, at x = 5 and 6 */
    assert_status(c2d_world_advance(w, 2), C2D_OK);
    assert_int_equal(j.calls, 1);
    assert_int_equal(j.inside_refused, 1);
    assert_true(j.last.kind == C2D_WORLD_IMPACT && j.last.time == 1 && j.last.a == 0 && j.last.b == 1);
    assert_true(j.last.normal.x == 1 && j.last.normal.y == 0 && j.last.restitution == 1 && j.last.collapsed == 0);
    a = state(w, 0), b = state(w, 1);
    assert_true(a.vel.x == 0 && b.vel.x == 0 && a.pos.x == 5 && b.pos.x == 6);
    free(mem);
}

static void test_a_bad_resolver_is_overruled_by_the_models_own_impact(void **state_)
{
    /* Equal masses head on at e = 1 exchange velocities (c2d_collide's
     * result, the world's own), whatever the resolver got wrong. */
    int mode, ran = 0;
    (void)state_;
    for (mode = GIVE_NAN; mode <= REFUSE; mode++) {
        c2d_world_desc d = walled(2, 10, 4, 0);
        judge j;
        void *mem;
        c2d_world *w;
        c2d_body a, b;
        c2d_world_stats s;
        memset(&j, 0, sizeof j);
        j.mode = mode;
        d.resolve_impact = judge_resolve, d.user = &j;
        w = new_world(&d, &mem);
        j.w = w;
        add(w, 2, 2, 2, 0, 1, 0.5);
        add(w, 6, 2, -1, 0, 1, 0.5); /* meet at t = 1 */
        assert_status(c2d_world_advance(w, 1.5), C2D_OK);
        a = state(w, 0), b = state(w, 1);
        c2d_world_get_stats(w, &s);
        assert_true(j.calls == 1 && s.collisions == 1);
        assert_true(a.vel.x == -1 && b.vel.x == 2 && a.pos.x == 3.5 && b.pos.x == 6);
        free(mem);
        ran++;
    }
    assert_int_equal(ran, 3);
}

static void test_a_callers_wall_resolver_gives_the_rebound(void **state_)
{
    c2d_world_desc d = walled(1, 10, 4, 0);
    judge j;
    void *mem;
    c2d_world *w;
    c2d_body b;
    (void)state_;
    memset(&j, 0, sizeof j);
    j.mode = HALF_BOUNCE;
    d.resolve_wall = judge_resolve, d.user = &j;
    w = new_world(&d, &mem);
    j.w = w;
    add(w, 5, 2, 0, 3, 1, 0.5); /* the top wall (y = 3.5) at t = 0.5 */
    assert_status(c2d_world_advance(w, 1), C2D_OK);
    assert_true(j.calls == 1 && j.last.kind == C2D_WORLD_WALL && j.last.b == 3 && j.last.time == 0.5);
    assert_true(j.last.normal.x == 0 && j.last.normal.y == 1);
    b = state(w, 0);
    assert_true(b.vel.y == -1.5 && b.pos.y == 3.5 - 0.75 && b.pos.x == 5);
    free(mem);
}

static void test_a_callers_static_resolver_sees_the_contact_normal(void **state_)
{
    c2d_world_desc d = walled(1, 10, 10, 1);
    judge j;
    void *mem;
    c2d_world *w;
    c2d_vec2 centre = {5, 8};
    c2d_body b;
    (void)state_;
    memset(&j, 0, sizeof j);
    j.mode = HALF_BOUNCE;
    d.resolve_static = judge_resolve, d.user = &j;
    w = new_world(&d, &mem);
    j.w = w;
    assert_status(c2d_world_add_circle(w, centre, 1, 1, NULL), C2D_OK);
    add(w, 5, 2, 0, 2, 1, 0.5); /* meets the post (radius sum 1.5) at y = 6.5, t = 2.25 */
    assert_status(c2d_world_advance(w, 3), C2D_OK);
    assert_true(j.calls == 1 && j.last.kind == C2D_WORLD_STATIC && j.last.b == 0 && j.last.time == 2.25);
    assert_true(j.last.normal.x == 0 && j.last.normal.y > 0);
    b = state(w, 0);
    assert_true(b.vel.y == -1 && b.vel.x == 0);
    free(mem);
}

/* ------------------------------------------------------------ rough disks */

static double rough_energy(const c2d_world *w, double k)
{
    size_t i, n = c2d_world_count(w);
    double e = 0;
    for (i = 0; i < n; i++) {
        c2d_body b = state(w, i);
        double spin, r = 0.3;
        assert_status(c2d_world_get_spin(w, i, &spin), C2D_OK);
        e += 0.5 * b.mass * (b.vel.x * b.vel.x + b.vel.y * b.vel.y) + 0.5 * k * b.mass * r * r * spin * spin;
    }
    return e;
}

static void test_a_perfectly_rough_elastic_gas_keeps_its_energy_with_rotation(void **state_)
{
    /* Walton's model at e = 1, beta = 1 (and no sliding: mu = INFINITY)
     * keeps kinetic energy, translation plus rotation, exactly; the
     * periodic box keeps linear momentum.  Spins are exchanged with the
     * translation: the translational energy alone does not stay. */
    c2d_world_desc d;
    void *mem;
    c2d_world *w;
    size_t i, side = 12;
    double e0, e1, trans0 = 0, trans1 = 0, px = 0, py = 0, scale = 0;
    const double k = 0.4;
    c2d_world_stats s;
    (void)state_;
    memset(&d, 0, sizeof d);
    d.capacity = side * side, d.width = d.height = 12, d.boundary = C2D_PERIODIC;
    d.restitution = 1, d.model = C2D_WORLD_ROUGH, d.friction = INFINITY, d.tangential_restitution = 1;
    d.inertia_factor = k;
    w = new_world(&d, &mem);
    rng_state = 11;
    for (i = 0; i < side * side; i++) {
        add(w, (double)(i % side) + 0.5, (double)(i / side) + 0.5, uniform(), uniform(), 1, 0.3);
        assert_status(c2d_world_set_spin(w, i, 3 * uniform()), C2D_OK);
    }
    for (i = 0; i < side * side; i++) {
        c2d_body b = state(w, i);
        trans0 += 0.5 * (b.vel.x * b.vel.x + b.vel.y * b.vel.y);
        px += b.vel.x, py += b.vel.y;
    }
    e0 = rough_energy(w, k);
    assert_status(c2d_world_advance(w, 40), C2D_OK);
    c2d_world_get_stats(w, &s);
    assert_true(s.collisions > 5000);
    e1 = rough_energy(w, k);
    assert_close(e1, e0, 1e-12 * e0);
    for (i = 0; i < side * side; i++) {
        c2d_body b = state(w, i);
        trans1 += 0.5 * (b.vel.x * b.vel.x + b.vel.y * b.vel.y);
        px -= b.vel.x, py -= b.vel.y, scale += fabs(b.vel.x) + fabs(b.vel.y);
    }
    assert_true(fabs(px) < 1e-12 * scale && fabs(py) < 1e-12 * scale);
    assert_true(fabs(trans1 - trans0) > 1e-3 * e0);
    free(mem);
}

static void test_a_rough_wall_turns_slip_into_spin_by_coulombs_law(void **state_)
{
    /* A disk (m 1, r 0.5, I = m r^2 / 2) hits the floor at vy = -2 with
     * vx = 1, no spin, e = 1, beta = 0, mu = 0.1.  The contact point's
     * slip vx + spin r = 1 is stopped by a tangential impulse J with
     * dvx = -J / m, dspin = -J r / I: 1 - J (1 + r^2 m / I) = 0, J = 1/3,
     * within Coulomb's mu x (normal impulse 4) = 0.4, so it sticks:
     * vx = 2/3, spin r = -2/3 (rolling). */
    c2d_world_desc d = walled(1, 10, 4, 0);
    void *mem;
    c2d_world *w;
    c2d_body b;
    double spin;
    (void)state_;
    d.model = C2D_WORLD_ROUGH, d.wall_friction = 0.1;
    w = new_world(&d, &mem);
    add(w, 5, 2, 1, -2, 1, 0.5); /* the floor at t = 0.75 */
    assert_status(c2d_world_advance(w, 0.75), C2D_OK);
    b = state(w, 0);
    assert_status(c2d_world_get_spin(w, 0, &spin), C2D_OK);
    assert_close(b.vel.y, 2, 4e-16 * 2);
    assert_close(b.vel.x, 2.0 / 3.0, 4e-16 * 2);
    assert_close(spin * 0.5, -2.0 / 3.0, 4e-16 * 2); /* rolling: vx + spin r = 0, spin clockwise */
    free(mem);
}

/* ------------------------------------------------------------ resting */

/* Two unit-radius-half disks on the x axis, the right one dx further than
 * touching, accelerated towards each other at 1 each (relative 2). */
static c2d_world *pressed_pair(void **mem, double e, double dx, double mass_b)
{
    c2d_world_desc d = walled(2, 10, 4, 0);
    c2d_world *w;
    c2d_vec2 right = {1, 0}, left = {-1, 0};
    d.restitution = e;
    w = new_world(&d, mem);
    add(w, 4.5, 2, 0, 0, 1, 0.5);
    add(w, 5.5 + dx, 2, 0, 0, mass_b, 0.5);
    assert_status(c2d_world_set_acceleration(w, 0, right), C2D_OK);
    assert_status(c2d_world_set_acceleration(w, 1, left), C2D_OK);
    return w;
}

static void test_touching_disks_pressed_together_by_their_accelerations_never_pass_through(void **state_)
{
    double mass_b[2] = {1, 3};
    int k;
    (void)state_;
    for (k = 0; k < 2; k++) {
        void *mem;
        c2d_world *w = pressed_pair(&mem, 1, 0, mass_b[k]);
        c2d_body a, b;
        c2d_vec2 acc;
        c2d_world_stats s;
        assert_status(c2d_world_advance(w, 5), C2D_OK);
        a = state(w, 0), b = state(w, 1);
        c2d_world_get_stats(w, &s);
        assert_true(a.pos.x == 4.5 && b.pos.x == 5.5 && a.vel.x == 0 && b.vel.x == 0);
        assert_true(s.collisions == 1);
        assert_status(c2d_world_get_acceleration(w, 0, &acc), C2D_OK);
        assert_true(acc.x == 0 && acc.y == 0);
        assert_status(c2d_world_get_acceleration(w, 1, &acc), C2D_OK);
        assert_true(acc.x == 0 && acc.y == 0);
        free(mem);
    }
}

static void test_a_disk_bouncing_on_another_under_its_acceleration_comes_to_rest(void **state_)
{
    /* Gap g = 0.1 closing at relative acceleration 2: each impact at
     * e = 0.5 leaves e^2 of the last rebound's height, so it rests once
     * g e^(2n) <= collapse_length = 2^-20 x 0.5: n = ceil(log(g / L) /
     * log(1 / e^2)) impacts, one more for rounding at the boundary. */
    const double e = 0.5, g = 0.1, length = 0x1p-20 * 0.5;
    const double n = ceil(log(g / length) / log(1 / (e * e)));
    void *mem;
    c2d_world *w = pressed_pair(&mem, e, g, 1);
    c2d_world_stats s, later;
    c2d_body a, b;
    (void)state_;
    assert_status(c2d_world_advance(w, 5), C2D_OK);
    c2d_world_get_stats(w, &s);
    assert_true((double)s.collisions >= n && (double)s.collisions <= n + 1);
    a = state(w, 0), b = state(w, 1);
    assert_true(a.vel.x == 0 && b.vel.x == 0);
    assert_close(b.pos.x - a.pos.x, 1, 4e-16);
    assert_status(c2d_world_advance(w, 50), C2D_OK);
    c2d_world_get_stats(w, &later);
    assert_true(later.collisions == s.collisions && later.events == s.events);
    free(mem);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_sensor_reports_each_entry_of_a_centre_and_changes_no_motion),
        cmocka_unit_test(test_a_disk_starting_inside_a_sensor_is_reported_only_once_it_comes_back),
        cmocka_unit_test(test_an_accelerated_disk_entering_a_sensor_is_reported_when_its_parabola_says),
        cmocka_unit_test(test_a_disk_removed_at_its_sensor_event_is_gone_and_the_others_move_on),
        cmocka_unit_test(test_sensor_refusals_change_nothing),
        cmocka_unit_test(test_a_callers_impact_resolver_decides_the_velocities),
        cmocka_unit_test(test_a_bad_resolver_is_overruled_by_the_models_own_impact),
        cmocka_unit_test(test_a_callers_wall_resolver_gives_the_rebound),
        cmocka_unit_test(test_a_callers_static_resolver_sees_the_contact_normal),
        cmocka_unit_test(test_a_perfectly_rough_elastic_gas_keeps_its_energy_with_rotation),
        cmocka_unit_test(test_a_rough_wall_turns_slip_into_spin_by_coulombs_law),
        cmocka_unit_test(test_touching_disks_pressed_together_by_their_accelerations_never_pass_through),
        cmocka_unit_test(test_a_disk_bouncing_on_another_under_its_acceleration_comes_to_rest),
    };
    const int total = (int)(sizeof tests / sizeof tests[0]);
    int failed = cmocka_run_group_tests_name("world contacts", tests, NULL, NULL);
    c2d_tally tally;
    tally.passed = total - failed, tally.failed = failed;
    fflush(stdout);
    c2d_put_tally("test_world_contacts", &tally);
    return c2d_tally_status(&tally);
}
