/* SPDX-License-Identifier: MIT */
/* The event-driven world (collide2d_world.h): exact dynamics as physical
 * properties (energy, momentum, no overlap, the pressure of a hard-disk
 * fluid), frame independence and determinism bit for bit, Newton's cradle,
 * inelastic collapse, and every refusal leaving the memory untouched. */
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "collide2d_world.h"
#include "world_fixture.h"

#define PI 3.14159265358979323846


static c2d_world_desc box_desc(size_t capacity, double width, double height, c2d_boundary boundary, double e,
                               double ew)
{
    c2d_world_desc d;
    memset(&d, 0, sizeof d);
    d.capacity = capacity, d.width = width, d.height = height, d.boundary = boundary;
    d.restitution = e, d.wall_restitution = ew;
    return d;
}


/* A gas: side x side disks on a lattice filling the box, random velocities
 * (zero total momentum), radii and masses varied when `mixed`. */
static void fill_gas(c2d_world *w, const c2d_world_desc *d, size_t side, double radius, int mixed, uint64_t seed)
{
    size_t i, n = side * side;
    double px = 0, py = 0;
    c2d_body *b = malloc(n * sizeof *b);
    double *r = malloc(n * sizeof *r);
    rng_state = seed;
    for (i = 0; i < n; i++) {
        b[i].pos.x = ((double)(i % side) + 0.5) * d->width / (double)side;
        b[i].pos.y = ((double)(i / side) + 0.5) * d->height / (double)side;
        b[i].vel.x = uniform(), b[i].vel.y = uniform();
        b[i].mass = mixed ? 1 + 0.9 * uniform() : 1;
        r[i] = mixed ? radius * (0.75 + 0.25 * uniform()) : radius;
        px += b[i].mass * b[i].vel.x, py += b[i].mass * b[i].vel.y;
    }
    for (i = 0; i < n; i++) {
        size_t k;
        b[i].vel.x -= px / ((double)n * b[i].mass), b[i].vel.y -= py / ((double)n * b[i].mass);
        assert_status(c2d_world_add(w, &b[i], r[i], &k), C2D_OK);
        assert_int_equal(k, i);
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
        assert_status(c2d_world_get(w, i, &b), C2D_OK);
        e += 0.5 * b.mass * (b.vel.x * b.vel.x + b.vel.y * b.vel.y);
    }
    return e;
}

static void momentum(const c2d_world *w, double *px, double *py, double *scale)
{
    size_t i, n = c2d_world_count(w);
    *px = *py = *scale = 0;
    for (i = 0; i < n; i++) {
        c2d_body b;
        assert_status(c2d_world_get(w, i, &b), C2D_OK);
        *px += b.mass * b.vel.x, *py += b.mass * b.vel.y;
        *scale += b.mass * (fabs(b.vel.x) + fabs(b.vel.y));
    }
}

static unsigned long long collisions(const c2d_world *w)
{
    c2d_world_stats s;
    c2d_world_get_stats(w, &s);
    return s.collisions;
}

/* ------------------------------------------------------------ the basics */

static void test_two_disks_meet_and_exchange_velocities(void **state)
{
    c2d_world_desc d = box_desc(2, 10, 2, C2D_WALLS, 1, 1);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    c2d_body a = {{1, 1}, {1, 0}, 1}, b = {{3, 1}, {0, 0}, 1};
    c2d_world_stats s;
    (void)state;
    assert_status(c2d_world_add(w, &a, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_advance(w, 2.0), C2D_OK);
    assert_status(c2d_world_get(w, 0, &a), C2D_OK);
    assert_status(c2d_world_get(w, 1, &b), C2D_OK);
    assert_true(a.vel.x == 0 && a.vel.y == 0 && a.pos.x == 2 && a.pos.y == 1);
    assert_true(b.vel.x == 1 && b.vel.y == 0 && b.pos.x == 4 && b.pos.y == 1);
    c2d_world_get_stats(w, &s);
    assert_true(s.collisions == 1 && s.wall_collisions == 0 && s.time == 2.0);
    assert_true(s.virial == 1.0); /* r_ij = (1, 0), dp_j = (1, 0) */
    free(mem);
}

static void test_a_wall_negates_the_normal_velocity_times_its_restitution(void **state)
{
    c2d_world_desc d = box_desc(1, 4, 4, C2D_WALLS, 1, 0.5);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    c2d_body a = {{2, 2}, {1, 0.25}, 3};
    c2d_world_stats s;
    (void)state;
    assert_status(c2d_world_add(w, &a, 1, NULL), C2D_OK);
    assert_status(c2d_world_advance(w, 2), C2D_OK); /* the wall at x = 3 (centre) at t = 1 */
    assert_status(c2d_world_get(w, 0, &a), C2D_OK);
    assert_true(a.vel.x == -0.5 && a.vel.y == 0.25 && a.pos.x == 2.5 && a.pos.y == 2.5 && a.mass == 3);
    c2d_world_get_stats(w, &s);
    assert_true(s.wall_collisions == 1 && s.collisions == 0);
    free(mem);
}

/* Newton's cradle: a striker against a row of touching equal disks, e = 1:
 * one impact per contact (N - 1 for N disks), and only the last disk moves,
 * at the striker's speed exactly. */
static void test_newtons_cradle_passes_the_striker_speed_to_the_last_disk(void **state)
{
    enum { N = 7 };
    c2d_world_desc d = box_desc(N, 40, 4, C2D_WALLS, 1, 1);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    c2d_body b;
    size_t i;
    (void)state;
    b.pos.x = 2, b.pos.y = 2, b.vel.x = 0.75, b.vel.y = 0, b.mass = 1;
    assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    for (i = 1; i < N; i++) {
        b.pos.x = 10 + (double)i, b.vel.x = 0;
        assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    }
    assert_status(c2d_world_advance(w, 12), C2D_OK); /* contact at t = 8: 7.5 / 0.75 - ... */
    assert_int_equal(collisions(w), N - 1);
    for (i = 0; i < N; i++) {
        assert_status(c2d_world_get(w, i, &b), C2D_OK);
        assert_true(b.vel.y == 0);
        assert_true(b.vel.x == (i == N - 1 ? 0.75 : 0));
    }
    free(mem);
}

/* ------------------------------------------------------------ physics */

static void test_an_elastic_gas_keeps_its_energy_over_a_hundred_thousand_impacts(void **state)
{
    c2d_world_desc d = box_desc(400, 30, 30, C2D_WALLS, 1, 1);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    double e0, e1, t = 0;
    (void)state;
    fill_gas(w, &d, 20, 0.5, 1, 3);
    e0 = kinetic(w);
    while (collisions(w) < 100000) assert_status(c2d_world_advance(w, t += 1), C2D_OK);
    e1 = kinetic(w);
    printf("test_world: elastic gas, %llu impacts: relative energy change %.2e\n", collisions(w), e1 / e0 - 1);
    assert_true(fabs(e1 / e0 - 1) < 1e-12);
    free(mem);
}

static void test_a_periodic_gas_keeps_its_momentum(void **state)
{
    c2d_world_desc d = box_desc(400, 30, 30, C2D_PERIODIC, 1, 0);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    double px0, py0, s0, px1, py1, s1, t = 0;
    (void)state;
    fill_gas(w, &d, 20, 0.5, 1, 4);
    momentum(w, &px0, &py0, &s0);
    while (collisions(w) < 50000) assert_status(c2d_world_advance(w, t += 1), C2D_OK);
    momentum(w, &px1, &py1, &s1);
    printf("test_world: periodic gas, %llu impacts: momentum change (%.2e, %.2e) of %.3g\n", collisions(w),
           px1 - px0, py1 - py0, s0);
    assert_true(fabs(px1 - px0) < 1e-12 * s0 && fabs(py1 - py0) < 1e-12 * s0);
    free(mem);
}

static void check_no_overlap(const c2d_world *w, const c2d_world_desc *d, const double *radius, double *worst)
{
    size_t i, j, n = c2d_world_count(w);
    for (i = 0; i < n; i++) {
        c2d_body a;
        assert_status(c2d_world_get(w, i, &a), C2D_OK);
        if (d->boundary == C2D_WALLS) {
            assert_true(a.pos.x >= radius[i] * (1 - 1e-12) && a.pos.x <= d->width - radius[i] * (1 - 1e-12));
            assert_true(a.pos.y >= radius[i] * (1 - 1e-12) && a.pos.y <= d->height - radius[i] * (1 - 1e-12));
        } else {
            assert_true(a.pos.x >= 0 && a.pos.x < d->width && a.pos.y >= 0 && a.pos.y < d->height);
        }
        for (j = i + 1; j < n; j++) {
            c2d_body b;
            double dx, dy, gap;
            assert_status(c2d_world_get(w, j, &b), C2D_OK);
            dx = b.pos.x - a.pos.x, dy = b.pos.y - a.pos.y;
            if (d->boundary == C2D_PERIODIC) {
                dx -= d->width * round(dx / d->width);
                dy -= d->height * round(dy / d->height);
            }
            gap = sqrt(dx * dx + dy * dy) / (radius[i] + radius[j]) - 1;
            if (gap < *worst) *worst = gap;
            assert_true(gap > -1e-9);
        }
    }
}

static void test_disks_never_overlap_nor_leave_the_box(void **state)
{
    int periodic;
    (void)state;
    for (periodic = 0; periodic <= 1; periodic++) {
        c2d_world_desc d = box_desc(64, 14, 11, periodic ? C2D_PERIODIC : C2D_WALLS, periodic ? 1 : 0.97, 1);
        void *mem;
        c2d_world *w = new_world(&d, &mem);
        double radius[64], worst = INFINITY;
        size_t i, k;
        rng_state = 9 + (uint64_t)periodic;
        for (i = 0; i < 64; i++) { /* radii growing and shrinking: the grid is rebuilt on the way */
            c2d_body b = {{((double)(i % 8) + 0.5) * 14 / 8, ((double)(i / 8) + 0.5) * 11 / 8}, {0, 0}, 1};
            b.vel.x = 3 * uniform(), b.vel.y = 3 * uniform(), b.mass = 1 + 0.5 * uniform();
            radius[i] = 0.3 + 0.3 * (double)(i % 5) / 4;
            assert_status(c2d_world_add(w, &b, radius[i], NULL), C2D_OK);
        }
        for (k = 1; k <= 400; k++) {
            assert_status(c2d_world_advance(w, 0.037 * (double)k), C2D_OK);
            check_no_overlap(w, &d, radius, &worst);
        }
        printf("test_world: %s, %llu impacts: closest gap %.2e of the radius sum\n", periodic ? "periodic" : "walls",
               collisions(w), worst);
        assert_true(collisions(w) > 1000);
        free(mem);
    }
}

/* The pressure of the hard-disk fluid at area fraction 0.3 from the
 * collision virial.  In two dimensions the virial theorem gives
 *     P A = N k T + (1 / (2 t)) sum over impacts of r_ij . dp_j
 * (r_ij from i to j at contact, dp_j the impulse on j: each term positive),
 * and N k T is the kinetic energy E, so Z = P A / (N k T) = 1 + V / (2 t E).
 * Henderson (1975): Z = (1 + eta^2 / 8) / (1 - eta)^2, within 0.1 % of the
 * virial series at 0.3.  Tolerance: 4 standard errors of 10 block means,
 * plus 0.2 % for the equation and N = 400's finite size. */
static void test_the_virial_pressure_at_eta_0_3_matches_henderson(void **state)
{
    enum { SIDE = 20, N = SIDE * SIDE, BLOCKS = 10 };
    const double eta = 0.3, box = sqrt(N * PI / (4 * eta));
    c2d_world_desc d = box_desc(N, box, box, C2D_PERIODIC, 1, 0);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    double z[BLOCKS], mean = 0, var = 0, err, ref = (1 + eta * eta / 8) / ((1 - eta) * (1 - eta)), e, t = 0;
    c2d_world_stats s0, s1;
    int k;
    (void)state;
    fill_gas(w, &d, SIDE, 0.5, 0, 5);
    e = kinetic(w);
    while (collisions(w) < 50ull * N) assert_status(c2d_world_advance(w, t += 1), C2D_OK);
    for (k = 0; k < BLOCKS; k++) {
        c2d_world_get_stats(w, &s0);
        while (collisions(w) < s0.collisions + 30ull * N) assert_status(c2d_world_advance(w, t += 1), C2D_OK);
        c2d_world_get_stats(w, &s1);
        z[k] = 1 + (s1.virial - s0.virial) / (2 * (s1.time - s0.time) * e);
        mean += z[k] / BLOCKS;
    }
    for (k = 0; k < BLOCKS; k++) var += (z[k] - mean) * (z[k] - mean) / (BLOCKS - 1);
    err = sqrt(var / BLOCKS);
    printf("test_world: eta 0.3, N %d: Z = %.4f +- %.4f, Henderson %.4f (%+.2f%%, %+.1f error bars); energy drift %.1e\n",
           N, mean, err, ref, 100 * (mean / ref - 1), (mean - ref) / err, kinetic(w) / e - 1);
    assert_true(fabs(mean - ref) <= 4 * err + 0.002 * ref);
    free(mem);
}

/* Inelastic collapse: a dense gas at e = 0.2 between walls of e = 0.5 cools
 * towards clusters in which impacts would come ever faster; the collapse
 * rule (by default: elastic when the pair closed less than 2^-20 of the
 * smaller radius since either disk's last impact, or after 16 impacts of a
 * disk at one instant; optionally within a time or below a speed) keeps
 * the number of events modest, and energy never grows. */
static void test_inelastic_collapse_never_hangs_and_energy_only_falls(void **state)
{
    int rule;
    (void)state;
    for (rule = 0; rule <= 2; rule++) {
        c2d_world_desc d = box_desc(100, 12, 12, C2D_WALLS, 0.2, 0.5);
        void *mem;
        c2d_world *w;
        double e0, prev, t;
        c2d_world_stats s;
        d.collapse_time = rule == 1 ? 1e-3 : 0;
        d.collapse_speed = rule == 2 ? 1e-2 : 0;
        w = new_world(&d, &mem);
        fill_gas(w, &d, 10, 0.55, 0, 6);
        e0 = prev = kinetic(w);
        for (t = 1; t <= 200; t += 1) {
            double e;
            assert_status(c2d_world_advance(w, t), C2D_OK);
            e = kinetic(w);
            assert_true(e <= prev * (1 + 1e-12));
            prev = e;
        }
        c2d_world_get_stats(w, &s);
        printf("test_world: e = 0.2, collapse rule %s: %llu impacts, %llu events by t = 200, energy left %.3e\n",
               rule == 0 ? "default (length 2^-20 r)" : rule == 1 ? "time 1e-3" : "speed 1e-2", s.collisions, s.events,
               prev / e0);
        assert_true(s.events < 1000000);
        free(mem);
    }
}

/* A light disk between a wall and a heavy one driving it towards the wall,
 * e = 0.5 everywhere: without a rule, infinitely many impacts in finite
 * time as the heavy disk comes to rest on the light one. */
static void test_a_disk_pinned_against_a_wall_by_a_heavy_one_does_not_hang(void **state)
{
    c2d_world_desc d = box_desc(2, 20, 4, C2D_WALLS, 0.5, 0.5);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    c2d_body light = {{3, 2}, {0, 0}, 1}, heavy = {{8, 2}, {-1, 0}, 100};
    c2d_world_stats s;
    (void)state;
    assert_status(c2d_world_add(w, &light, 1, NULL), C2D_OK);
    assert_status(c2d_world_add(w, &heavy, 1, NULL), C2D_OK);
    assert_status(c2d_world_advance(w, 100), C2D_OK);
    c2d_world_get_stats(w, &s);
    assert_status(c2d_world_get(w, 1, &heavy), C2D_OK);
    printf("test_world: pinned disk: %llu impacts, %llu at the wall, heavy disk at x = %.6f moving %.3e\n",
           s.collisions, s.wall_collisions, heavy.pos.x, heavy.vel.x);
    assert_true(s.events < 100000);
    assert_true(heavy.pos.x >= 3 - 1e-9);
    free(mem);
}

/* ------------------------------------------------------------ bits */

static void run_sliced(const c2d_world_desc *d, int slices, c2d_body *out, c2d_world_stats *stats, size_t n)
{
    void *mem;
    c2d_world *w = new_world(d, &mem);
    size_t i;
    fill_gas(w, d, 12, 0.45, 1, 7);
    if (slices == 1) {
        assert_status(c2d_world_advance(w, 40.0), C2D_OK);
    } else {
        double t = 0;
        rng_state = 99;
        while (t < 40.0) {
            c2d_body probe;
            t += 0.3 * (1 + uniform()); /* uneven, some tiny */
            if (t > 40.0) t = 40.0;
            assert_status(c2d_world_advance(w, t), C2D_OK);
            assert_status(c2d_world_advance(w, t), C2D_OK); /* again at the same time: nothing */
            assert_status(c2d_world_get(w, (size_t)(t * 7) % n, &probe), C2D_OK);
        }
    }
    for (i = 0; i < n; i++) assert_status(c2d_world_get(w, i, &out[i]), C2D_OK);
    c2d_world_get_stats(w, stats);
    free(mem);
}

static void test_one_advance_and_many_uneven_ones_give_the_same_bits(void **state)
{
    int periodic;
    (void)state;
    for (periodic = 0; periodic <= 1; periodic++) {
        c2d_world_desc d = box_desc(144, 16, 16, periodic ? C2D_PERIODIC : C2D_WALLS, periodic ? 1 : 0.85, 0.9);
        c2d_body one[144], many[144], again[144];
        c2d_world_stats s1, sm, sa;
        run_sliced(&d, 1, one, &s1, 144);
        run_sliced(&d, 2, many, &sm, 144);
        run_sliced(&d, 1, again, &sa, 144);
        assert_true(s1.collisions > 1000);
        assert_memory_equal(one, many, sizeof one);
        assert_memory_equal(&s1, &sm, sizeof s1);
        assert_memory_equal(one, again, sizeof one); /* deterministic */
        assert_memory_equal(&s1, &sa, sizeof s1);
    }
}

static void test_reading_a_world_changes_none_of_its_bytes(void **state)
{
    c2d_world_desc d = box_desc(100, 12, 12, C2D_PERIODIC, 1, 0);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    size_t bytes = c2d_world_bytes(&d), i;
    unsigned char *copy = malloc(bytes);
    c2d_world_stats s;
    (void)state;
    fill_gas(w, &d, 10, 0.5, 1, 8);
    assert_status(c2d_world_advance(w, 3.3), C2D_OK);
    memcpy(copy, mem, bytes);
    for (i = 0; i < 100; i++) {
        c2d_body b;
        assert_status(c2d_world_get(w, i, &b), C2D_OK);
    }
    c2d_world_get_stats(w, &s);
    assert_memory_equal(copy, mem, bytes);
    free(copy);
    free(mem);
}


/* ------------------------------------------------------------ control */

typedef struct event_log {
    int impacts, walls;
    double last_time;
    c2d_world_event first;
} event_log;

static void log_event(void *user, const c2d_world_event *e)
{
    event_log *log = user;
    if (log->impacts + log->walls == 0) log->first = *e;
    if (e->kind == C2D_WORLD_IMPACT) log->impacts++;
    else log->walls++;
    assert_true(e->time >= log->last_time);
    log->last_time = e->time;
}

static void test_the_event_callback_sees_every_impact_with_its_impulse(void **state)
{
    c2d_world_desc d = box_desc(100, 12, 12, C2D_WALLS, 0.9, 0.8);
    event_log log;
    void *mem;
    c2d_world *w;
    c2d_world_stats s;
    (void)state;
    memset(&log, 0, sizeof log);
    d.on_event = log_event, d.user = &log;
    w = new_world(&d, &mem);
    fill_gas(w, &d, 10, 0.5, 1, 12);
    assert_status(c2d_world_advance(w, 20), C2D_OK);
    c2d_world_get_stats(w, &s);
    assert_true(log.impacts > 0 && log.walls > 0);
    assert_int_equal(log.impacts, s.collisions);
    assert_int_equal(log.walls, s.wall_collisions);
    free(mem);
    /* Two disks: the impulse on b is b's momentum change. */
    {
        c2d_world_desc d2 = box_desc(2, 10, 4, C2D_WALLS, 0.5, 1);
        c2d_body a = {{1, 2}, {2, 0.5}, 1}, b = {{3, 2.5}, {0, 0}, 3};
        memset(&log, 0, sizeof log);
        d2.on_event = log_event, d2.user = &log;
        w = new_world(&d2, &mem);
        assert_status(c2d_world_add(w, &a, 0.5, NULL), C2D_OK);
        assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
        assert_status(c2d_world_advance(w, 1.2), C2D_OK);
        assert_int_equal(log.impacts, 1);
        assert_status(c2d_world_get(w, 1, &b), C2D_OK);
        assert_true(log.first.kind == C2D_WORLD_IMPACT && log.first.a == 0 && log.first.b == 1);
        assert_true(log.first.impulse.x == b.vel.x * 3 && log.first.impulse.y == b.vel.y * 3);
        free(mem);
    }
}

static void kick_run(const c2d_world_desc *d, int sliced, c2d_body *out, size_t n)
{
    void *mem;
    c2d_world *w = new_world(d, &mem);
    const double cuts[] = {0.7, 2.9, 5.0, 5.0, 6.13, 11.0, 14.9, 20.0};
    size_t i, k;
    c2d_vec2 v = {4, -3};
    fill_gas(w, d, 8, 0.4, 1, 13);
    for (k = 0; k < sizeof cuts / sizeof cuts[0]; k++) {
        if (sliced || cuts[k] == 5.0 || cuts[k] == 20.0) assert_status(c2d_world_advance(w, cuts[k]), C2D_OK);
        if (cuts[k] == 5.0 && (k == 2)) {
            assert_status(c2d_world_set_velocity(w, 17, v), C2D_OK);
            assert_status(c2d_world_remove(w, 40), C2D_OK);
        }
    }
    for (i = 0; i < n; i++) {
        if (i == 40) {
            assert_status(c2d_world_get(w, i, &out[i]), C2D_INVALID);
            memset(&out[i], 0, sizeof out[i]);
        } else {
            assert_status(c2d_world_get(w, i, &out[i]), C2D_OK);
        }
    }
    free(mem);
}

static void test_kicks_and_removals_keep_frame_independence(void **state)
{
    c2d_world_desc d = box_desc(64, 10, 10, C2D_PERIODIC, 1, 0);
    c2d_body one[64], many[64];
    (void)state;
    kick_run(&d, 0, one, 64);
    kick_run(&d, 1, many, 64);
    assert_memory_equal(one, many, sizeof one);
}

static void test_a_kicked_disk_moves_and_a_removed_one_is_passed_through(void **state)
{
    c2d_world_desc d = box_desc(3, 20, 4, C2D_WALLS, 1, 1);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    c2d_body a = {{2, 2}, {0, 0}, 1}, b = {{6, 2}, {0, 0}, 1}, c = {{10, 2}, {0, 0}, 1};
    c2d_vec2 go = {1, 0}, bad = {NAN, 0};
    size_t bytes = c2d_world_bytes(&d);
    unsigned char *copy = malloc(bytes);
    (void)state;
    assert_status(c2d_world_add(w, &a, 1, NULL), C2D_OK);
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_OK);
    assert_status(c2d_world_add(w, &c, 1, NULL), C2D_OK);
    assert_status(c2d_world_advance(w, 1), C2D_OK);
    assert_status(c2d_world_set_velocity(w, 0, go), C2D_OK); /* at t = 1 from x = 2: meets b at t = 3 */
    assert_status(c2d_world_remove(w, 1), C2D_OK);
    memcpy(copy, mem, bytes);
    assert_status(c2d_world_remove(w, 1), C2D_INVALID);
    assert_status(c2d_world_remove(w, 3), C2D_INVALID);
    assert_status(c2d_world_remove(NULL, 0), C2D_INVALID);
    assert_status(c2d_world_set_velocity(w, 1, go), C2D_INVALID);
    assert_status(c2d_world_set_velocity(w, 0, bad), C2D_INVALID);
    assert_status(c2d_world_set_velocity(w, 5, go), C2D_INVALID);
    assert_status(c2d_world_set_velocity(NULL, 0, go), C2D_INVALID);
    assert_status(c2d_world_get(w, 1, &b), C2D_INVALID);
    assert_memory_equal(copy, mem, bytes);
    assert_status(c2d_world_advance(w, 8), C2D_OK); /* passes where b was, meets c at t = 7 */
    assert_int_equal(collisions(w), 1);
    assert_status(c2d_world_get(w, 0, &a), C2D_OK);
    assert_status(c2d_world_get(w, 2, &c), C2D_OK);
    assert_true(a.vel.x == 0 && a.pos.x == 8 && c.vel.x == 1 && c.pos.x == 11);
    b.pos.x = 4, b.pos.y = 2; /* its place is free, but its capacity is not given back */
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
    free(copy);
    free(mem);
}

/* ------------------------------------------------------------ acceleration */

/* The library's motion formula (collide2d_world.h): x0 + (v0 + 0.5 a dt) dt. */
static double at(double x, double v, double a, double dt) { return x + (v + 0.5 * a * dt) * dt; }

typedef struct stopper {
    int timers, others;
    double when;
    size_t disk;
    c2d_world *w;
    c2d_vec2 vel, acc; /* set at the timer */
    int refused;       /* add, remove and advance refused from the callback */
} stopper;

static void stop_at_timer(void *user, const c2d_world_event *e)
{
    stopper *s = user;
    if (e->kind != C2D_WORLD_TIMER) {
        s->others++;
        return;
    }
    s->timers++, s->when = e->time, s->disk = e->a;
    assert_status(c2d_world_set_velocity(s->w, e->a, s->vel), C2D_OK);
    assert_status(c2d_world_set_acceleration(s->w, e->a, s->acc), C2D_OK);
    {
        c2d_body b = {{15, 3}, {0, 0}, 1};
        s->refused = c2d_world_advance(s->w, e->time + 1) == C2D_INVALID && c2d_world_add(s->w, &b, 0.5, NULL) == C2D_INVALID &&
                     c2d_world_add_sensor(s->w, b.pos, 0.5, NULL) == C2D_INVALID;
    }
}

static void test_a_decelerating_disk_stops_where_the_formula_says(void **state)
{
    c2d_world_desc d = box_desc(1, 20, 4, C2D_WALLS, 1, 1);
    const double x0 = 2.25, v = 2.7, dec = 0.9, ts = v / dec;
    const double want = at(x0, v, -dec, ts);
    stopper st;
    void *mem;
    c2d_world *w;
    c2d_body b = {{x0, 2}, {v, 0}, 1};
    c2d_vec2 acc = {-dec, 0}, got;
    int pass;
    (void)state;
    assert_close(want, x0 + v * v / (2 * dec), 4e-15 * want);
    for (pass = 0; pass < 2; pass++) { /* from the callback; by advancing to the timer */
        memset(&st, 0, sizeof st);
        if (pass == 0) d.on_event = stop_at_timer, d.user = &st;
        else d.on_event = NULL;
        w = new_world(&d, &mem);
        st.w = w;
        assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
        assert_status(c2d_world_set_acceleration(w, 0, acc), C2D_OK);
        assert_status(c2d_world_set_timer(w, 0, ts), C2D_OK);
        if (pass == 1) {
            c2d_vec2 zero = {0, 0};
            assert_status(c2d_world_advance(w, ts), C2D_OK);
            assert_status(c2d_world_set_velocity(w, 0, zero), C2D_OK);
            assert_status(c2d_world_set_acceleration(w, 0, zero), C2D_OK);
        }
        assert_status(c2d_world_advance(w, 10), C2D_OK);
        if (pass == 0) assert_true(st.timers == 1 && st.others == 0 && st.when == ts && st.disk == 0 && st.refused);
        assert_status(c2d_world_get(w, 0, &b), C2D_OK);
        assert_true(b.pos.x == want && b.pos.y == 2 && b.vel.x == 0 && b.vel.y == 0);
        assert_status(c2d_world_get_acceleration(w, 0, &got), C2D_OK);
        assert_true(got.x == 0 && got.y == 0);
        b.pos.x = x0, b.vel.x = v;
        free(mem);
    }
}

/* The setters called from on_event act as if called after advancing to
 * the event's time, bit for bit (the header's promise), now that a setter
 * on a disk of the event leaves the prediction to the world: a gas with
 * walls where every impact or wall hit damps the disks (velocity x 0.9
 * turned a little), gives them a deceleration and a timer (three setters
 * each, the pool game's pattern), and an impact also kicks a third disk,
 * not in the event (predicted at once); every due timer stops the
 * acceleration.  Run once with the callback, logging each event it acted
 * on, and once without, advancing to each logged time and doing the same
 * there: the final states and the counts agree exactly. */
enum { ACT_MAX = 6000 };
typedef struct act_event {
    c2d_world_event_kind kind;
    double time;
    size_t a, b;
} act_event;
typedef struct actor {
    c2d_world *w;
    int n;
    act_event ev[ACT_MAX];
} actor;

static void act_on(c2d_world *w, const act_event *e)
{
    const size_t n = c2d_world_count(w), disks[2] = {e->a, e->b};
    size_t k;
    if (e->kind == C2D_WORLD_TIMER) {
        c2d_vec2 zero = {0, 0};
        assert_status(c2d_world_set_acceleration(w, e->a, zero), C2D_OK);
        return;
    }
    for (k = 0; k < (e->kind == C2D_WORLD_IMPACT ? 2u : 1u); k++) {
        c2d_body d;
        c2d_vec2 v, acc;
        assert_status(c2d_world_get(w, disks[k], &d), C2D_OK);
        v.x = 0.9 * (d.vel.x - 0.05 * d.vel.y), v.y = 0.9 * (d.vel.y + 0.05 * d.vel.x);
        acc.x = -0.1 * v.x, acc.y = -0.1 * v.y;
        assert_status(c2d_world_set_velocity(w, disks[k], v), C2D_OK);
        assert_status(c2d_world_set_acceleration(w, disks[k], acc), C2D_OK);
        assert_status(c2d_world_set_timer(w, disks[k], e->time + 0.25 + 0.01 * (double)k), C2D_OK);
    }
    if (e->kind == C2D_WORLD_IMPACT) { /* a disk of no part in the event */
        size_t third = (e->a + 1) % n;
        c2d_body d;
        c2d_vec2 v;
        if (third == e->b) third = (third + 1) % n;
        assert_status(c2d_world_get(w, third, &d), C2D_OK);
        v.x = d.vel.x + 0.01, v.y = d.vel.y;
        assert_status(c2d_world_set_velocity(w, third, v), C2D_OK);
    }
}

static void act_in_callback(void *user, const c2d_world_event *e)
{
    actor *s = user;
    act_event *x;
    assert_true(s->n < ACT_MAX);
    x = &s->ev[s->n++];
    x->kind = e->kind, x->time = e->time, x->a = e->a, x->b = e->b;
    act_on(s->w, x);
}

static void test_setters_from_the_callback_act_as_after_advancing_to_the_event(void **state)
{
    const double end = 40;
    c2d_world_desc d = box_desc(25, 12, 12, C2D_WALLS, 0.95, 0.9);
    actor *s = calloc(1, sizeof *s);
    c2d_world *w[2];
    void *mem[2];
    c2d_world_stats st[2];
    int pass, k, distinct = 1;
    size_t i;
    (void)state;
    for (pass = 0; pass < 2; pass++) {
        d.on_event = pass == 0 ? act_in_callback : NULL, d.user = s;
        w[pass] = new_world(&d, &mem[pass]);
        fill_gas(w[pass], &d, 5, 0.4, 1, 2024);
    }
    s->w = w[0];
    assert_status(c2d_world_advance(w[0], end), C2D_OK);
    for (k = 1; k < s->n; k++) distinct &= s->ev[k].time > s->ev[k - 1].time;
    assert_true(distinct); /* one event an instant, so advancing to it stops right after it */
    for (k = 0; k < s->n; k++) {
        assert_status(c2d_world_advance(w[1], s->ev[k].time), C2D_OK);
        act_on(w[1], &s->ev[k]);
    }
    assert_status(c2d_world_advance(w[1], end), C2D_OK);
    for (pass = 0; pass < 2; pass++) c2d_world_get_stats(w[pass], &st[pass]);
    assert_true(st[0].collisions == st[1].collisions && st[0].wall_collisions == st[1].wall_collisions &&
                st[0].events == st[1].events && st[0].time == st[1].time);
    print_message("setters from the callback: %d events acted on, %llu impacts, %llu wall hits\n", s->n,
                  st[0].collisions, st[0].wall_collisions);
    assert_true(st[0].collisions >= 50 && st[0].wall_collisions >= 20);
    for (i = 0; i < c2d_world_count(w[0]); i++) {
        c2d_body a, b;
        assert_status(c2d_world_get(w[0], i, &a), C2D_OK);
        assert_status(c2d_world_get(w[1], i, &b), C2D_OK);
        assert_memory_equal(&a, &b, sizeof a);
    }
    free(mem[0]), free(mem[1]), free(s);
}

static void log_first_impact(void *user, const c2d_world_event *e)
{
    double *t = user;
    if (e->kind == C2D_WORLD_IMPACT && *t < 0) *t = e->time;
}

static void test_decelerating_disks_meet_when_the_accelerated_time_of_impact_says(void **state)
{
    c2d_world_desc d = box_desc(2, 20, 6, C2D_WALLS, 1, 1);
    c2d_body a = {{2, 3}, {3, 0.05}, 1}, b = {{9.5, 3.2}, {-2, -0.1}, 2};
    c2d_vec2 aa = {-0.5, 0.01}, ab = {0.3, -0.02};
    double want, got = -1;
    void *mem;
    c2d_world *w;
    c2d_body pa, pb;
    (void)state;
    assert_status(c2d_time_of_impact_accel(&a, aa, &b, ab, 1.0, INFINITY, &want), C2D_OK);
    d.on_event = log_first_impact, d.user = &got;
    w = new_world(&d, &mem);
    assert_status(c2d_world_add(w, &a, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_set_acceleration(w, 0, aa), C2D_OK);
    assert_status(c2d_world_set_acceleration(w, 1, ab), C2D_OK);
    assert_status(c2d_world_advance(w, want * 0.999), C2D_OK);
    assert_true(got < 0);
    assert_status(c2d_world_advance(w, want * 1.001), C2D_OK);
    assert_close(got, want, 1e-13);
    /* At the impact the centres are the radius sum apart. */
    free(mem);
    d.on_event = NULL;
    w = new_world(&d, &mem);
    assert_status(c2d_world_add(w, &a, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_set_acceleration(w, 0, aa), C2D_OK);
    assert_status(c2d_world_set_acceleration(w, 1, ab), C2D_OK);
    assert_status(c2d_world_advance(w, got), C2D_OK);
    assert_status(c2d_world_get(w, 0, &pa), C2D_OK);
    assert_status(c2d_world_get(w, 1, &pb), C2D_OK);
    assert_close(hypot(pb.pos.x - pa.pos.x, pb.pos.y - pa.pos.y), 1.0, 1e-13);
    assert_true((pb.vel.x - pa.vel.x) * (pb.pos.x - pa.pos.x) + (pb.vel.y - pa.vel.y) * (pb.pos.y - pa.pos.y) > 0);
    assert_int_equal(collisions(w), 1);
    free(mem);
}

static void kick_at_timer(void *user, const c2d_world_event *e)
{
    stopper *s = user;
    if (e->kind != C2D_WORLD_TIMER) return;
    s->timers++, s->when = e->time, s->disk = e->a;
    assert_status(c2d_world_set_velocity(s->w, e->a, s->vel), C2D_OK);
}

static void test_a_timer_fires_at_its_time_and_a_velocity_set_there_holds(void **state)
{
    c2d_world_desc d = box_desc(2, 20, 4, C2D_WALLS, 1, 1);
    stopper st;
    void *mem;
    c2d_world *w;
    c2d_body a = {{2, 2}, {0.5, 0}, 1}, b = {{17, 2}, {0, 0}, 1};
    const double t1 = 3.1;
    (void)state;
    memset(&st, 0, sizeof st);
    st.vel.x = -0.25, st.vel.y = 0.125;
    d.on_event = kick_at_timer, d.user = &st;
    w = new_world(&d, &mem);
    st.w = w;
    assert_status(c2d_world_add(w, &a, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_set_timer(w, 1, 100), C2D_OK);
    assert_status(c2d_world_set_timer(w, 1, INFINITY), C2D_OK); /* cancelled */
    assert_status(c2d_world_set_timer(w, 0, t1), C2D_OK);
    assert_status(c2d_world_advance(w, t1), C2D_OK); /* due at t1: fires */
    assert_true(st.timers == 1 && st.when == t1 && st.disk == 0);
    assert_status(c2d_world_advance(w, 6), C2D_OK);
    assert_int_equal(st.timers, 1);
    assert_status(c2d_world_get(w, 0, &a), C2D_OK);
    assert_true(a.vel.x == -0.25 && a.vel.y == 0.125);
    assert_true(a.pos.x == (2 + 0.5 * t1) + -0.25 * (6 - t1) && a.pos.y == 2 + 0.125 * (6 - t1));
    assert_status(c2d_world_advance(w, 200), C2D_OK);
    assert_int_equal(st.timers, 1);
    free(mem);
}

/* A gas with accelerations, timers that change them, kicks: one advance
 * or many uneven ones, the same bits. */
typedef struct gas_ctl {
    c2d_world *w;
    int timers;
} gas_ctl;

static void gas_timer(void *user, const c2d_world_event *e)
{
    gas_ctl *g = user;
    c2d_vec2 acc;
    if (e->kind != C2D_WORLD_TIMER) return;
    g->timers++;
    acc.x = 0.3 * (double)(e->a % 3) - 0.3, acc.y = -0.2;
    assert_status(c2d_world_set_acceleration(g->w, e->a, acc), C2D_OK);
    if (e->a % 2 == 0) assert_status(c2d_world_set_timer(g->w, e->a, e->time + 1.5), C2D_OK);
}

static void accel_run(int sliced, c2d_body *out, c2d_world_stats *stats, int *timers)
{
    c2d_world_desc d = box_desc(49, 10, 10, C2D_WALLS, 0.9, 0.7);
    gas_ctl g;
    void *mem;
    c2d_world *w;
    size_t i;
    double t;
    d.on_event = gas_timer, d.user = &g;
    w = new_world(&d, &mem);
    g.w = w, g.timers = 0;
    fill_gas(w, &d, 7, 0.4, 1, 21);
    for (i = 0; i < 49; i++) {
        c2d_vec2 acc;
        acc.x = 0.1 * uniform(), acc.y = 0.1 * uniform() - 0.05;
        assert_status(c2d_world_set_acceleration(w, i, acc), C2D_OK);
        assert_status(c2d_world_set_timer(w, i, 0.37 * (double)i), C2D_OK);
    }
    if (sliced)
        for (t = 0.013; t < 30; t = t * 1.7 + 0.01) assert_status(c2d_world_advance(w, t), C2D_OK);
    assert_status(c2d_world_advance(w, 30), C2D_OK);
    for (i = 0; i < 49; i++) assert_status(c2d_world_get(w, i, &out[i]), C2D_OK);
    c2d_world_get_stats(w, stats);
    *timers = g.timers;
    free(mem);
}

static void test_accelerations_and_timers_keep_frame_independence(void **state)
{
    c2d_body one[49], many[49];
    c2d_world_stats s1, s2;
    int t1, t2;
    size_t i;
    (void)state;
    accel_run(0, one, &s1, &t1);
    accel_run(1, many, &s2, &t2);
    assert_memory_equal(one, many, sizeof one);
    assert_true(s1.collisions == s2.collisions && s1.wall_collisions == s2.wall_collisions && s1.events == s2.events);
    assert_true(t1 == t2 && t1 > 49 && s1.collisions > 100);
    printf("test_world: accelerated gas: %llu impacts, %llu at walls, %d timers, %llu events by t = 30\n",
           s1.collisions, s1.wall_collisions, t1, s1.events);
    for (i = 0; i < 49; i++) /* inside the box (radii 0.2 to 0.4) */
        assert_true(one[i].pos.x >= 0.2 - 1e-9 && one[i].pos.x <= 9.8 + 1e-9 && one[i].pos.y >= 0.2 - 1e-9 &&
                    one[i].pos.y <= 9.8 + 1e-9);
}

static void test_a_disk_pressed_into_a_wall_rests_on_it(void **state)
{
    c2d_world_desc d = box_desc(2, 20, 8, C2D_WALLS, 1, 0.5);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    c2d_body a = {{5, 0.5}, {1, 0}, 1}, b = {{12, 6}, {0, 0}, 1};
    c2d_vec2 g = {0, -9.8}, got;
    c2d_world_stats s;
    (void)state;
    assert_status(c2d_world_add(w, &a, 0.5, NULL), C2D_OK); /* on the floor, sliding */
    assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_OK); /* dropped from 6 */
    assert_status(c2d_world_set_acceleration(w, 0, g), C2D_OK);
    assert_status(c2d_world_set_acceleration(w, 1, g), C2D_OK);
    assert_status(c2d_world_advance(w, 100), C2D_OK);
    c2d_world_get_stats(w, &s);
    /* a: one wall event, then the walls at x = 19.5 and 0.5 (sliding at
     * 1 / 0.5 ...); b: bounces at e = 0.5 until under collapse_length. */
    printf("test_world: pressed into the floor: %llu wall events by t = 100\n", s.wall_collisions);
    assert_true(s.wall_collisions < 60);
    assert_status(c2d_world_get(w, 0, &a), C2D_OK);
    assert_status(c2d_world_get(w, 1, &b), C2D_OK);
    assert_true(a.pos.y == 0.5 && a.vel.y == 0 && b.pos.y == 0.5 && b.vel.y == 0);
    assert_status(c2d_world_get_acceleration(w, 1, &got), C2D_OK);
    assert_true(got.x == 0 && got.y == 0);
    assert_status(c2d_world_advance(w, 1000), C2D_OK);
    {
        c2d_world_stats s2;
        c2d_world_get_stats(w, &s2);
        assert_true(s2.wall_collisions - s.wall_collisions < 20);
    }
    free(mem);
}

static void test_acceleration_and_timer_refusals_change_nothing(void **state)
{
    c2d_world_desc d = box_desc(3, 10, 10, C2D_WALLS, 1, 1);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    size_t bytes = c2d_world_bytes(&d);
    unsigned char *copy = malloc(bytes);
    c2d_body a = {{2, 2}, {1, 0}, 1}, b = {{6, 2}, {0, 0}, 1};
    c2d_vec2 ok = {0.5, -0.25}, nan2 = {NAN, 0}, inf2 = {0, INFINITY}, got;
    (void)state;
    assert_status(c2d_world_add(w, &a, 1, NULL), C2D_OK);
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_OK);
    assert_status(c2d_world_set_acceleration(w, 0, ok), C2D_OK);
    assert_status(c2d_world_set_timer(w, 0, 5), C2D_OK);
    assert_status(c2d_world_advance(w, 1), C2D_OK);
    assert_status(c2d_world_remove(w, 1), C2D_OK);
    memcpy(copy, mem, bytes);
    assert_status(c2d_world_set_acceleration(w, 0, nan2), C2D_INVALID);
    assert_status(c2d_world_set_acceleration(w, 0, inf2), C2D_INVALID);
    assert_status(c2d_world_set_acceleration(w, 1, ok), C2D_INVALID); /* removed */
    assert_status(c2d_world_set_acceleration(w, 2, ok), C2D_INVALID);
    assert_status(c2d_world_set_acceleration(NULL, 0, ok), C2D_INVALID);
    assert_status(c2d_world_set_timer(w, 0, 0.5), C2D_INVALID); /* before now */
    assert_status(c2d_world_set_timer(w, 0, NAN), C2D_INVALID);
    assert_status(c2d_world_set_timer(w, 0, -INFINITY), C2D_INVALID);
    assert_status(c2d_world_set_timer(w, 1, 3), C2D_INVALID);
    assert_status(c2d_world_set_timer(w, 7, 3), C2D_INVALID);
    assert_status(c2d_world_set_timer(NULL, 0, 3), C2D_INVALID);
    assert_status(c2d_world_get_acceleration(w, 1, &got), C2D_INVALID);
    assert_status(c2d_world_get_acceleration(w, 0, NULL), C2D_INVALID);
    assert_status(c2d_world_get_acceleration(NULL, 0, &got), C2D_INVALID);
    assert_status(c2d_world_get_acceleration(w, 0, &got), C2D_OK);
    assert_true(got.x == 0.5 && got.y == -0.25);
    assert_memory_equal(copy, mem, bytes);
    free(copy);
    free(mem);
}

/* ------------------------------------------------------------ statics */

typedef struct static_log {
    int hits;
    c2d_world_event first;
} static_log;

static void log_static(void *user, const c2d_world_event *e)
{
    static_log *l = user;
    if (e->kind != C2D_WORLD_STATIC) return;
    if (l->hits++ == 0) l->first = *e;
}

static c2d_world *static_world(c2d_world_desc *d, static_log *log, void **mem)
{
    *d = box_desc(4, 20, 20, C2D_WALLS, 1, 1);
    d->statics = 4;
    memset(log, 0, sizeof *log);
    d->on_event = log_static, d->user = log;
    return new_world(d, mem);
}

static void test_a_disk_bounces_off_a_tilted_segment_by_the_reflection_law(void **state)
{
    c2d_world_desc d;
    static_log log;
    void *mem;
    c2d_world *w = static_world(&d, &log, &mem);
    c2d_vec2 a = {5, 5}, b = {15, 9};
    c2d_body disk = {{9, 12}, {0.3, -1}, 2};
    const double len = sqrt(116), nx = -4 / len, ny = 10 / len, vn = 0.3 * nx - 1 * ny;
    const double wx = 0.3 - 2 * vn * nx, wy = -1 - 2 * vn * ny;
    size_t k = 9;
    double dist;
    (void)state;
    assert_status(c2d_world_add(w, &disk, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_add_segment(w, a, b, 1, &k), C2D_OK);
    assert_int_equal(k, 0);
    assert_status(c2d_world_advance(w, 6), C2D_OK); /* the line y = 5 + 0.4 (x - 5) at ~t = 4.3 */
    assert_int_equal(log.hits, 1);
    assert_true(log.first.a == 0 && log.first.b == 0);
    assert_status(c2d_world_advance(w, log.first.time), C2D_INVALID); /* in the past */
    assert_status(c2d_world_get(w, 0, &disk), C2D_OK);
    /* c2d_collide_normal's 16 ulp of the velocity scale (~1), the expected
     * values' own few roundings included. */
    assert_close(disk.vel.x, wx, 16 * DBL_EPSILON / 2);
    assert_close(disk.vel.y, wy, 16 * DBL_EPSILON / 2);
    assert_close(log.first.impulse.x, 2 * (wx - 0.3), 1e-15);
    /* At the impact the centre was the radius from the line. */
    free(mem);
    w = static_world(&d, &log, &mem);
    disk.pos.x = 9, disk.pos.y = 12, disk.vel.x = 0.3, disk.vel.y = -1;
    assert_status(c2d_world_add(w, &disk, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_add_segment(w, a, b, 1, NULL), C2D_OK);
    assert_status(c2d_world_advance(w, 4.0), C2D_OK);
    assert_int_equal(log.hits, 0);
    assert_status(c2d_world_advance(w, 6), C2D_OK);
    assert_int_equal(log.hits, 1);
    assert_status(c2d_world_get(w, 0, &disk), C2D_OK);
    {
        const double t = log.first.time, x = disk.pos.x - disk.vel.x * (6 - t), y = disk.pos.y - disk.vel.y * (6 - t);
        dist = nx * (x - 5) + ny * (y - 5);
    }
    assert_close(dist, 0.5, 1e-14);
    free(mem);
}

static void test_a_disk_bounces_off_a_segment_end_and_off_a_circle(void **state)
{
    c2d_world_desc d;
    static_log log;
    void *mem;
    c2d_world *w = static_world(&d, &log, &mem);
    c2d_vec2 a = {5, 5}, b = {10, 5}, c = {10, 14};
    c2d_body disk = {{12, 8}, {-1, -1.5}, 1}, other = {{10, 17}, {0, -2}, 1};
    (void)state;
    assert_status(c2d_world_add(w, &disk, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_add(w, &other, 0.5, NULL), C2D_OK);
    assert_status(c2d_world_add_segment(w, a, b, 1, NULL), C2D_OK);
    assert_status(c2d_world_add_circle(w, c, 1, 0.5, NULL), C2D_OK);
    /* Head-on at the end (10, 5) at t ~ 1.72: straight back; the circle: 1.5
     * below 17 at t = 0.75. */
    assert_status(c2d_world_advance(w, 2.5), C2D_OK);
    assert_int_equal(log.hits, 2);
    assert_true(log.first.b == 1 && log.first.a == 1 && log.first.time == 0.75);
    assert_status(c2d_world_get(w, 1, &other), C2D_OK);
    assert_true(other.vel.x == 0 && other.vel.y == 1); /* e = 0.5, axis-aligned: exact */
    assert_status(c2d_world_get(w, 0, &disk), C2D_OK);
    /* The normal is the end minus the rounded centre: ulp(10) / 0.5 of a
     * turn, ~4e-15, on top of c2d_collide_normal's rounding. */
    assert_close(disk.vel.x, 1, 1e-14);
    assert_close(disk.vel.y, 1.5, 1e-14);
    free(mem);
}

static void test_elastic_statics_keep_a_gas_energy_and_nothing_passes_through(void **state)
{
    c2d_world_desc d = box_desc(36, 12, 12, C2D_WALLS, 1, 1);
    void *mem;
    c2d_world *w;
    c2d_vec2 s0 = {3.1, 2.2}, s1 = {8.9, 4.1}, s2 = {2.0, 9.7}, s3 = {6.2, 7.3}, c0 = {9.4, 9.1};
    double e0, e1, t;
    c2d_world_stats st;
    int k;
    (void)state;
    d.statics = 3;
    w = new_world(&d, &mem);
    assert_status(c2d_world_add_segment(w, s0, s1, 1, NULL), C2D_OK);
    assert_status(c2d_world_add_segment(w, s2, s3, 1, NULL), C2D_OK);
    assert_status(c2d_world_add_circle(w, c0, 0.3, 1, NULL), C2D_OK);
    assert_status(c2d_world_add_circle(w, c0, 0.3, 1, NULL), C2D_INVALID); /* full */
    {
        /* A gas clear of the statics: a 6 x 6 lattice, the disks near them moved off. */
        size_t i, n = 0;
        rng_state = 5;
        for (i = 0; i < 36; i++) {
            c2d_body b;
            b.pos.x = ((double)(i % 6) + 0.5) * 2, b.pos.y = ((double)(i / 6) + 0.5) * 2;
            b.vel.x = uniform(), b.vel.y = uniform(), b.mass = 1;
            {
                const double ux = (b.pos.x - s0.x), uy = (b.pos.y - s0.y), lx = s1.x - s0.x, ly = s1.y - s0.y;
                const double vx = (b.pos.x - s2.x), vy = (b.pos.y - s2.y), mx = s3.x - s2.x, my = s3.y - s2.y;
                double u = (ux * lx + uy * ly) / (lx * lx + ly * ly), v = (vx * mx + vy * my) / (mx * mx + my * my);
                u = u < 0 ? 0 : u > 1 ? 1 : u, v = v < 0 ? 0 : v > 1 ? 1 : v;
                if (hypot(ux - u * lx, uy - u * ly) < 0.35 || hypot(vx - v * mx, vy - v * my) < 0.35 ||
                    hypot(b.pos.x - c0.x, b.pos.y - c0.y) < 0.65)
                    continue;
            }
            assert_status(c2d_world_add(w, &b, 0.3, NULL), C2D_OK);
            n++;
        }
        assert_true(n > 25);
    }
    e0 = kinetic(w);
    for (t = 0.5, k = 0; t <= 100; t += 0.5, k++) {
        size_t i;
        assert_status(c2d_world_advance(w, t), C2D_OK);
        for (i = 0; i < c2d_world_count(w); i++) { /* the same side of each segment as at the start */
            c2d_body b;
            double u, dist;
            assert_status(c2d_world_get(w, i, &b), C2D_OK);
            dist = hypot(b.pos.x - c0.x, b.pos.y - c0.y);
            assert_true(dist >= 0.6 - 1e-9);
            u = ((b.pos.x - s0.x) * (s1.x - s0.x) + (b.pos.y - s0.y) * (s1.y - s0.y)) / hypot(s1.x - s0.x, s1.y - s0.y);
            dist = fabs((s1.x - s0.x) * (b.pos.y - s0.y) - (s1.y - s0.y) * (b.pos.x - s0.x)) /
                   hypot(s1.x - s0.x, s1.y - s0.y);
            if (u >= 0 && u <= hypot(s1.x - s0.x, s1.y - s0.y)) assert_true(dist >= 0.3 - 1e-9);
        }
    }
    e1 = kinetic(w);
    c2d_world_get_stats(w, &st);
    printf("test_world: gas with 3 statics: %llu impacts, %llu at walls and statics: relative energy change %.2e\n",
           st.collisions, st.wall_collisions, e1 / e0 - 1);
    assert_close(e1 / e0, 1, 1e-12);
    free(mem);
    /* A fast small disk between a wall and a thin segment: never through. */
    {
        static_log log;
        c2d_vec2 p = {10, 0.5}, q = {10, 19.5};
        c2d_body b = {{2, 5}, {1e6, 3.3}, 1};
        w = static_world(&d, &log, &mem);
        assert_status(c2d_world_add_segment(w, p, q, 1, NULL), C2D_OK);
        assert_status(c2d_world_add(w, &b, 0.01, NULL), C2D_OK);
        for (k = 1; k <= 2000; k++) {
            assert_status(c2d_world_advance(w, (double)k * 0.7e-6), C2D_OK);
            assert_status(c2d_world_get(w, 0, &b), C2D_OK);
            assert_true(b.pos.x <= 10 - 0.01 + 1e-9 && b.pos.x >= 0.01 - 1e-9);
        }
        assert_true(log.hits > 50);
        free(mem);
    }
}

static void test_static_refusals_change_nothing(void **state)
{
    c2d_world_desc d = box_desc(2, 10, 10, C2D_WALLS, 1, 1);
    void *mem;
    c2d_world *w = new_world(&d, &mem);
    size_t bytes = c2d_world_bytes(&d);
    unsigned char *copy = malloc(bytes);
    c2d_vec2 a = {1, 1}, b = {4, 2}, bad = {NAN, 1}, inf = {1, INFINITY};
    (void)state;
    memcpy(copy, mem, bytes);
    assert_status(c2d_world_add_segment(w, a, b, 1, NULL), C2D_INVALID); /* desc.statics 0 */
    assert_status(c2d_world_add_circle(w, a, 1, 1, NULL), C2D_INVALID);
    assert_memory_equal(copy, mem, bytes);
    free(mem);
    d.statics = 2;
    assert_true(c2d_world_bytes(&d) > bytes);
    bytes = c2d_world_bytes(&d);
    free(copy);
    copy = malloc(bytes);
    w = new_world(&d, &mem);
    memcpy(copy, mem, bytes);
    assert_status(c2d_world_add_segment(w, a, a, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_segment(w, bad, b, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_segment(w, a, inf, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_segment(w, a, b, 1.5, NULL), C2D_INVALID);
    assert_status(c2d_world_add_segment(w, a, b, NAN, NULL), C2D_INVALID);
    assert_status(c2d_world_add_segment(NULL, a, b, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_circle(w, a, 0, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_circle(w, a, -1, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_circle(w, a, INFINITY, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_circle(w, bad, 1, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_circle(w, a, 1, -0.1, NULL), C2D_INVALID);
    assert_status(c2d_world_add_circle(NULL, a, 1, 1, NULL), C2D_INVALID);
    assert_memory_equal(copy, mem, bytes);
    d.statics = 0x10001;
    assert_int_equal(c2d_world_bytes(&d), 0);
    free(copy);
    free(mem);
}

/* ------------------------------------------------------------ refusals */

static void test_every_refusal_is_invalid_and_changes_nothing(void **state)
{
    c2d_world_desc d = box_desc(3, 10, 10, C2D_WALLS, 1, 1), bad;
    size_t bytes = c2d_world_bytes(&d), k;
    double *mem = malloc(bytes + 16), *copy = malloc(bytes + 16), nan = NAN, inf = INFINITY;
    c2d_world *w = NULL, *w0;
    c2d_body ok = {{2, 2}, {1, 0}, 1}, b;
    c2d_world_stats s;
    const double bad_values[] = {NAN, INFINITY, -INFINITY};
    (void)state;
    /* Descriptions */
    assert_int_equal(c2d_world_bytes(NULL), 0);
    for (k = 0; k < 16; k++) {
        bad = d;
        switch (k) {
        case 0: bad.capacity = 0; break;
        case 1: bad.width = 0; break;
        case 2: bad.height = -1; break;
        case 3: bad.width = nan; break;
        case 4: bad.height = inf; break;
        case 5: bad.boundary = (c2d_boundary)2; break;
        case 6: bad.restitution = 1.5; break;
        case 7: bad.restitution = nan; break;
        case 8: bad.wall_restitution = -0.1; break;
        case 9: bad.collapse_speed = -1; break;
        case 10: bad.collapse_speed = inf; break;
        case 11: bad.collapse_time = -1; break;
        case 12: bad.collapse_time = nan; break;
        case 13: bad.collapse_length = -1e-300; break;
        case 14: bad.collapse_length = inf; break;
        default: bad.capacity = (size_t)-1; break;
        }
        assert_int_equal(c2d_world_bytes(&bad), 0);
        memset(mem, 0x5A, bytes);
        memcpy(copy, mem, bytes);
        assert_status(c2d_world_init(&w, mem, bytes, &bad), C2D_INVALID);
        assert_null(w);
        assert_memory_equal(mem, copy, bytes);
    }
    /* Memory: too small, misaligned, NULL */
    assert_status(c2d_world_init(&w, mem, bytes - 1, &d), C2D_INVALID);
    assert_status(c2d_world_init(&w, (char *)mem + 4, bytes, &d), C2D_INVALID);
    assert_status(c2d_world_init(&w, NULL, bytes, &d), C2D_INVALID);
    assert_status(c2d_world_init(NULL, mem, bytes, &d), C2D_INVALID);
    assert_status(c2d_world_init(&w, mem, bytes, NULL), C2D_INVALID);
    assert_memory_equal(mem, copy, bytes);
    assert_null(w);
    assert_status(c2d_world_init(&w, mem, bytes, &d), C2D_OK);
    assert_non_null(w);
    assert_status(c2d_world_add(w, &ok, 1, NULL), C2D_OK);
    assert_status(c2d_world_advance(w, 1), C2D_OK);
    w0 = w;
    memcpy(copy, mem, bytes);
    /* Disks: NaN/Inf anywhere, mass or radius <= 0, outside, overlapping */
    for (k = 0; k < 3; k++) {
        int f;
        for (f = 0; f < 5; f++) {
            b = ok;
            b.pos.y = 8;
            if (f == 0) b.pos.x = bad_values[k];
            if (f == 1) b.pos.y = bad_values[k];
            if (f == 2) b.vel.x = bad_values[k];
            if (f == 3) b.vel.y = bad_values[k];
            if (f == 4) b.mass = bad_values[k];
            assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
        }
        b = ok, b.pos.y = 8;
        assert_status(c2d_world_add(w, &b, bad_values[k], NULL), C2D_INVALID);
    }
    b = ok, b.pos.y = 8;
    b.mass = 0;
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
    b.mass = -1;
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
    b.mass = 1;
    assert_status(c2d_world_add(w, &b, 0, NULL), C2D_INVALID);
    assert_status(c2d_world_add(w, &b, -1, NULL), C2D_INVALID);
    b.pos.x = 0.5; /* the wall cuts it */
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
    b.pos.x = 9.5;
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
    b.pos.x = 5, b.pos.y = 9.25;
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
    b.pos.x = 3, b.pos.y = 3.5; /* disk 0 is at (3, 2) now: distance 1.5 < 2 */
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
    b.pos.x = 3, b.pos.y = 3.5; /* larger than all: the brute-force check */
    assert_status(c2d_world_add(w, &b, 1.2, NULL), C2D_INVALID);
    assert_status(c2d_world_add(NULL, &b, 1, NULL), C2D_INVALID);
    assert_status(c2d_world_add(w, NULL, 1, NULL), C2D_INVALID);
    /* Times: NaN, Inf, before now */
    assert_status(c2d_world_advance(w, nan), C2D_INVALID);
    assert_status(c2d_world_advance(w, inf), C2D_INVALID);
    assert_status(c2d_world_advance(w, 0.5), C2D_INVALID);
    assert_status(c2d_world_advance(NULL, 2), C2D_INVALID);
    /* Reads: a disk that is not there */
    assert_status(c2d_world_get(w, 1, &b), C2D_INVALID);
    assert_status(c2d_world_get(NULL, 0, &b), C2D_INVALID);
    assert_status(c2d_world_get(w, 0, NULL), C2D_INVALID);
    c2d_world_get_stats(NULL, &s);
    assert_true(s.collisions == 0 && s.time == 0);
    c2d_world_get_stats(w, NULL);
    assert_memory_equal(mem, copy, bytes);
    /* A full world; periodic disks too large for the box, or outside it */
    b = ok, b.pos.x = 8, b.pos.y = 8;
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_OK); /* touching is fine */
    b.pos.x = 8, b.pos.y = 2;
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_OK);
    memcpy(copy, mem, bytes);
    b.pos.x = 5, b.pos.y = 5;
    assert_status(c2d_world_add(w, &b, 0.5, NULL), C2D_INVALID);
    assert_memory_equal(mem, copy, bytes);
    assert_ptr_equal(w, w0);
    d.boundary = C2D_PERIODIC;
    assert_status(c2d_world_init(&w, mem, bytes, &d), C2D_OK);
    memcpy(copy, mem, bytes);
    b.pos.x = 5, b.pos.y = 5;
    assert_status(c2d_world_add(w, &b, 1.7, NULL), C2D_INVALID); /* 3 diameters > 10 */
    b.pos.x = 10;
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
    b.pos.x = -0.0 - 1e-300;
    assert_status(c2d_world_add(w, &b, 1, NULL), C2D_INVALID);
    assert_memory_equal(mem, copy, bytes);
    b.pos.x = 0;
    assert_status(c2d_world_add(w, &b, 1.6, NULL), C2D_OK);
    free(mem);
    free(copy);
}

/* ------------------------------------------------------------ broadphase */

/* A caller's broadphase by brute force: every box kept, a query reports
 * every disk whose box overlaps (touching counts). */
#define NAIVE_MAX 256
typedef struct naive_bp {
    c2d_world_box box[NAIVE_MAX];
    int present[NAIVE_MAX];
    size_t top;
    unsigned long long inserts, moves, removes, queries;
} naive_bp;

static void naive_insert(void *user, size_t disk, const c2d_world_box *box)
{
    naive_bp *b = user;
    assert_true(disk < NAIVE_MAX && !b->present[disk]);
    assert_true(box->lo.x <= box->hi.x && box->lo.y <= box->hi.y);
    b->box[disk] = *box, b->present[disk] = 1, b->inserts++;
    if (disk >= b->top) b->top = disk + 1;
}

static void naive_move(void *user, size_t disk, const c2d_world_box *box)
{
    naive_bp *b = user;
    assert_true(disk < b->top && b->present[disk]);
    b->box[disk] = *box, b->moves++;
}

static void naive_remove(void *user, size_t disk)
{
    naive_bp *b = user;
    assert_true(disk < b->top && b->present[disk]);
    b->present[disk] = 0, b->removes++;
}

static void naive_query(void *user, const c2d_world_box *box, c2d_world_report report, void *context)
{
    naive_bp *b = user;
    size_t k;
    b->queries++;
    for (k = 0; k < b->top; k++)
        if (b->present[k] && b->box[k].lo.x <= box->hi.x && box->lo.x <= b->box[k].hi.x && b->box[k].lo.y <= box->hi.y &&
            box->lo.y <= b->box[k].hi.y)
            report(context, k);
}

/* Every event of a run, as bits, and what the scene's callback does. */
typedef struct scene_log {
    c2d_world *w;
    size_t n, cap;
    c2d_world_event *ev;
    int timers; /* the scene sets accelerations and timers at timers */
} scene_log;

static void log_scene_event(void *user, const c2d_world_event *e)
{
    scene_log *l = user;
    if (l->n < l->cap) l->ev[l->n] = *e;
    l->n++;
    if (l->timers && e->kind == C2D_WORLD_TIMER) {
        c2d_vec2 acc;
        acc.x = 0.3 * (double)(e->a % 3) - 0.3, acc.y = -0.2;
        assert_status(c2d_world_set_acceleration(l->w, e->a, acc), C2D_OK);
        if (e->a % 2 == 0) assert_status(c2d_world_set_timer(l->w, e->a, e->time + 1.5), C2D_OK);
    }
}

enum { SCENE_WALLS, SCENE_PERIODIC, SCENE_ACCEL, SCENE_STATICS, SCENES }; /* statics: segments, circles, sensors */

/* Scene s run to t = 30 with the built-in broadphase (nb NULL) or nb
 * (margin m): its events, final states and statistics. */
static void run_scene(int s, naive_bp *nb, double m, scene_log *log, c2d_body *out, c2d_world_stats *st)
{
    c2d_world_desc d = box_desc(144, 16, 16, s == SCENE_PERIODIC ? C2D_PERIODIC : C2D_WALLS, s == SCENE_PERIODIC ? 1 : 0.85,
                                0.9);
    c2d_world_broadphase bp;
    void *mem;
    c2d_world *w;
    size_t i;
    memset(&bp, 0, sizeof bp);
    if (nb != NULL) {
        memset(nb, 0, sizeof *nb);
        bp.insert = naive_insert, bp.move = naive_move, bp.remove = naive_remove, bp.query = naive_query;
        bp.user = nb, bp.margin = m;
        d.broadphase = &bp;
    }
    log->n = 0, log->cap = 200000, log->timers = s == SCENE_ACCEL;
    log->ev = malloc(log->cap * sizeof *log->ev);
    assert_non_null(log->ev);
    d.on_event = log_scene_event, d.user = log;
    d.statics = s == SCENE_STATICS ? 5 : 0;
    w = new_world(&d, &mem);
    log->w = w;
    if (s == SCENE_STATICS) {
        c2d_vec2 a = {-1, 5.05}, b = {17, 11.05}, c = {8.05, 3.05};
        assert_status(c2d_world_add_segment(w, a, b, 0.8, NULL), C2D_OK);
        assert_status(c2d_world_add_circle(w, c, 0.2, 1, NULL), C2D_OK);
        assert_status(c2d_world_add_circle(w, b, 0.5, 0.5, NULL), C2D_OK);
        { /* sensors: entries reported, nothing resolved */
            c2d_vec2 s0 = {4.1, 12.3}, s1 = {12.7, 4.4};
            assert_status(c2d_world_add_sensor(w, s0, 0.9, NULL), C2D_OK);
            assert_status(c2d_world_add_sensor(w, s1, 1.3, NULL), C2D_OK);
        }
        rng_state = 11;
        for (i = 0; i < 144; i++) { /* a lattice, the disks in the statics' way left out */
            c2d_body k;
            k.pos.x = ((double)(i % 12) + 0.5) * 16 / 12, k.pos.y = ((double)(i / 12) + 0.5) * 16 / 12;
            k.vel.x = uniform(), k.vel.y = uniform(), k.mass = 1 + 0.5 * uniform();
            if (fabs((k.pos.y - 5.05) - (k.pos.x + 1) / 3) < 1.3 || hypot(k.pos.x - 8.05, k.pos.y - 3.05) < 0.7) continue;
            assert_status(c2d_world_add(w, &k, 0.4, NULL), C2D_OK);
        }
    } else {
        fill_gas(w, &d, 12, 0.45, 1, 7 + (uint64_t)s);
    }
    if (s == SCENE_ACCEL)
        for (i = 0; i < 144; i++) {
            c2d_vec2 acc;
            acc.x = 0.1 * uniform(), acc.y = 0.1 * uniform() - 0.05;
            assert_status(c2d_world_set_acceleration(w, i, acc), C2D_OK);
            assert_status(c2d_world_set_timer(w, i, 0.37 * (double)i), C2D_OK);
        }
    assert_status(c2d_world_advance(w, 12), C2D_OK);
    assert_status(c2d_world_remove(w, 5), C2D_OK); /* the broadphase told of a removal */
    assert_status(c2d_world_advance(w, 30), C2D_OK);
    memset(out, 0, 144 * sizeof *out);
    for (i = 0; i < c2d_world_count(w); i++)
        if (i != 5) assert_status(c2d_world_get(w, i, &out[i]), C2D_OK);
    c2d_world_get_stats(w, st);
    if (nb != NULL) assert_true(nb->removes == 1 && nb->inserts == c2d_world_count(w));
    free(mem);
}

static int same_event(const c2d_world_event *a, const c2d_world_event *b)
{
    return a->kind == b->kind && memcmp(&a->time, &b->time, sizeof a->time) == 0 && a->a == b->a && a->b == b->b &&
           memcmp(&a->impulse, &b->impulse, sizeof a->impulse) == 0;
}

static void test_a_callers_broadphase_gives_the_same_bits_as_the_built_in_one(void **state)
{
    static naive_bp nb;
    const double margins[3] = {0, 0.05, 1.5};
    int s, m, runs = 0;
    (void)state;
    for (s = 0; s < SCENES; s++) {
        scene_log ref, got;
        c2d_body want[144], have[144];
        c2d_world_stats sw, sh;
        run_scene(s, NULL, 0, &ref, want, &sw);
        assert_true(ref.n <= ref.cap && sw.collisions > 300);
        for (m = 0; m < 3; m++) {
            size_t k;
            run_scene(s, &nb, margins[m], &got, have, &sh);
            assert_int_equal(got.n, ref.n);
            for (k = 0; k < ref.n; k++) assert_true(same_event(&ref.ev[k], &got.ev[k]));
            assert_memory_equal(want, have, sizeof want);
            assert_true(sw.collisions == sh.collisions && sw.wall_collisions == sh.wall_collisions);
            assert_memory_equal(&sw.virial, &sh.virial, sizeof sw.virial);
            assert_true(nb.moves > 0 && nb.queries > 0);
            if (m == 0) {
                size_t sensed = 0;
                for (k = 0; k < ref.n; k++) sensed += ref.ev[k].kind == C2D_WORLD_SENSOR;
                if (s == SCENE_STATICS) assert_true(sensed > 20);
                printf("test_world: scene %d: %zu events (%llu impacts, %zu sensor entries), the same bits with the "
                       "brute-force broadphase (%llu box moves, %llu queries)\n",
                       s, ref.n, sw.collisions, sensed, nb.moves, nb.queries);
            }
            free(got.ev);
            runs++;
        }
        free(ref.ev);
    }
    assert_int_equal(runs, SCENES * 3);
}

static void test_a_broadphase_without_its_functions_is_refused(void **state)
{
    c2d_world_desc d = box_desc(4, 10, 10, C2D_WALLS, 1, 1);
    c2d_world_broadphase bp;
    static double mem[1024];
    c2d_world *w = NULL;
    int k;
    (void)state;
    for (k = 0; k < 6; k++) {
        memset(&bp, 0, sizeof bp);
        bp.insert = naive_insert, bp.move = naive_move, bp.remove = naive_remove, bp.query = naive_query;
        if (k == 0) bp.insert = NULL;
        if (k == 1) bp.move = NULL;
        if (k == 2) bp.remove = NULL;
        if (k == 3) bp.query = NULL;
        if (k == 4) bp.margin = -1;
        if (k == 5) bp.margin = NAN;
        d.broadphase = &bp;
        assert_int_equal(c2d_world_bytes(&d), 0);
        assert_status(c2d_world_init(&w, mem, sizeof mem, &d), C2D_INVALID);
        assert_null(w);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_two_disks_meet_and_exchange_velocities),
        cmocka_unit_test(test_a_wall_negates_the_normal_velocity_times_its_restitution),
        cmocka_unit_test(test_newtons_cradle_passes_the_striker_speed_to_the_last_disk),
        cmocka_unit_test(test_an_elastic_gas_keeps_its_energy_over_a_hundred_thousand_impacts),
        cmocka_unit_test(test_a_periodic_gas_keeps_its_momentum),
        cmocka_unit_test(test_disks_never_overlap_nor_leave_the_box),
        cmocka_unit_test(test_the_virial_pressure_at_eta_0_3_matches_henderson),
        cmocka_unit_test(test_inelastic_collapse_never_hangs_and_energy_only_falls),
        cmocka_unit_test(test_a_disk_pinned_against_a_wall_by_a_heavy_one_does_not_hang),
        cmocka_unit_test(test_one_advance_and_many_uneven_ones_give_the_same_bits),
        cmocka_unit_test(test_reading_a_world_changes_none_of_its_bytes),
        cmocka_unit_test(test_the_event_callback_sees_every_impact_with_its_impulse),
        cmocka_unit_test(test_setters_from_the_callback_act_as_after_advancing_to_the_event),
        cmocka_unit_test(test_kicks_and_removals_keep_frame_independence),
        cmocka_unit_test(test_a_kicked_disk_moves_and_a_removed_one_is_passed_through),
        cmocka_unit_test(test_every_refusal_is_invalid_and_changes_nothing),
        cmocka_unit_test(test_a_decelerating_disk_stops_where_the_formula_says),
        cmocka_unit_test(test_decelerating_disks_meet_when_the_accelerated_time_of_impact_says),
        cmocka_unit_test(test_a_timer_fires_at_its_time_and_a_velocity_set_there_holds),
        cmocka_unit_test(test_accelerations_and_timers_keep_frame_independence),
        cmocka_unit_test(test_a_disk_pressed_into_a_wall_rests_on_it),
        cmocka_unit_test(test_acceleration_and_timer_refusals_change_nothing),
        cmocka_unit_test(test_a_disk_bounces_off_a_tilted_segment_by_the_reflection_law),
        cmocka_unit_test(test_a_disk_bounces_off_a_segment_end_and_off_a_circle),
        cmocka_unit_test(test_elastic_statics_keep_a_gas_energy_and_nothing_passes_through),
        cmocka_unit_test(test_static_refusals_change_nothing),
        cmocka_unit_test(test_a_callers_broadphase_gives_the_same_bits_as_the_built_in_one),
        cmocka_unit_test(test_a_broadphase_without_its_functions_is_refused),
    };
    const int total = (int)(sizeof tests / sizeof tests[0]);
    int failed = cmocka_run_group_tests_name("world", tests, NULL, NULL);
    c2d_tally tally;
    tally.passed = total - failed, tally.failed = failed;
    fflush(stdout);
    c2d_put_tally("test_world", &tally);
    return c2d_tally_status(&tally);
}
