/* SPDX-License-Identifier: MIT */
/* firmware.c - collide2d in float-only firmware: a Cortex-M4F (single-
 * precision FPU) built with -DC2D_NO_DOUBLE, so no double code is compiled
 * or linked (no __aeabi_d* helpers), no C library call, no allocation.
 *
 * An air-hockey table ticking at 100 Hz: two pucks and four cushions.  Each
 * tick is cut at the contacts inside it: the pucks' next contact from
 * c2d_time_of_impactf, the cushions' in closed form; pucks meet with
 * c2d_collidef (restitution 0.95), cushions are INFINITY-mass bodies met with
 * c2d_collide_normalf (0.9).  After 20 s of play it checks that energy never
 * grew, that no puck left the table or overlapped the other, and that both
 * kinds of impact happened.
 *
 * Built and run by `make test` (examples/examples.mk) under QEMU
 * (mps2-an386, semihosting): the start-up code and console are the MCU test
 * harness's (tests/mcu/startup_arm.c: c2d_mcu_puts, exit status of main).
 * On real hardware they are your vendor's start-up and a UART. */
#include "collide2d.h"
#include "mcu.h"

#define TICK 0.01f     /* s: a 100 Hz loop */
#define TICKS 2000     /* 20 s */
#define TABLE_W 1.0f   /* m */
#define TABLE_H 0.5f   /* m */
#define RADIUS 0.03f   /* m */
#define MAX_EVENTS 16  /* contacts resolved in one tick at most */

enum { LEFT, RIGHT, BOTTOM, TOP };
static const c2d_vec2f cushion_normal[4] = {{-1.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, -1.0f}, {0.0f, 1.0f}};

static c2d_bodyf puck[2] = {
    {{0.25f, 0.25f}, {1.8f, 0.7f}, 0.02f},   /* position m, velocity m/s, mass kg */
    {{0.75f, 0.30f}, {-0.9f, -0.4f}, 0.02f},
};
static unsigned long puck_hits, cushion_hits, checks_passed, checks_failed;

/* ------------------------------------------------------------ console */

static void put_uint(unsigned long v)
{
    char buf[12];
    int i = (int)sizeof buf - 1;
    buf[i] = '\0';
    do {
        buf[--i] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0u);
    c2d_mcu_puts(&buf[i]);
}

/* v >= 0 with three decimals, no printf. */
static void put_milli(float v)
{
    unsigned long m = (unsigned long)(v * 1000.0f + 0.5f);
    char frac[5] = {'.', '0', '0', '0', '\0'};
    put_uint(m / 1000u);
    frac[1] = (char)('0' + (int)(m / 100u % 10u));
    frac[2] = (char)('0' + (int)(m / 10u % 10u));
    frac[3] = (char)('0' + (int)(m % 10u));
    c2d_mcu_puts(frac);
}

/* ------------------------------------------------------------ physics */

static float energy(void)
{
    float e = 0.0f;
    int i;
    for (i = 0; i < 2; i++)
        e += 0.5f * puck[i].mass * (puck[i].vel.x * puck[i].vel.x + puck[i].vel.y * puck[i].vel.y);
    return e;
}

/* Time until puck p's edge reaches cushion k, or a negative value if it
 * is moving away from it. */
static float cushion_time(const c2d_bodyf *p, int k)
{
    switch (k) {
    case LEFT: return p->vel.x < 0.0f ? (RADIUS - p->pos.x) / p->vel.x : -1.0f;
    case RIGHT: return p->vel.x > 0.0f ? (TABLE_W - RADIUS - p->pos.x) / p->vel.x : -1.0f;
    case BOTTOM: return p->vel.y < 0.0f ? (RADIUS - p->pos.y) / p->vel.y : -1.0f;
    default: return p->vel.y > 0.0f ? (TABLE_H - RADIUS - p->pos.y) / p->vel.y : -1.0f;
    }
}

static void move_all(float dt)
{
    int i;
    for (i = 0; i < 2; i++) {
        puck[i].pos.x += puck[i].vel.x * dt;
        puck[i].pos.y += puck[i].vel.y * dt;
    }
}

/* One tick: move to each contact inside it in turn and resolve it.
 * Returns 0 if a resolution failed (it never should). */
static int tick(void)
{
    /* An infinite mass is immovable (no math.h here: the compiler's own). */
    static const c2d_bodyf wall_at_rest = {{0.0f, 0.0f}, {0.0f, 0.0f}, __builtin_inff()};
    float left = TICK;
    int n;
    for (n = 0; n < MAX_EVENTS; n++) {
        float first = left, t;
        int who = -1, k, i; /* -1: nothing; 0..7: puck i, cushion k; 8: the pucks */
        if (c2d_time_of_impactf(&puck[0], &puck[1], 2.0f * RADIUS, &t) == C2D_OK && t <= first) first = t, who = 8;
        for (i = 0; i < 2; i++)
            for (k = 0; k < 4; k++) {
                t = cushion_time(&puck[i], k);
                if (t >= 0.0f && t < first) first = t, who = 4 * i + k;
            }
        move_all(first);
        left -= first;
        if (who < 0) return 1;
        if (who == 8) {
            if (c2d_collidef(&puck[0], &puck[1], 0.95f) != C2D_OK) return 0;
            puck_hits++;
        } else {
            c2d_bodyf wall = wall_at_rest;
            c2d_status s = c2d_collide_normalf(&puck[who / 4], &wall, cushion_normal[who % 4], 0.9f);
            if (s == C2D_OK) cushion_hits++;
            else if (s != C2D_SEPARATING) return 0; /* touching and leaving */
        }
    }
    move_all(left);
    return 1;
}

static int inside(const c2d_bodyf *p)
{
    const float slack = 1e-4f;
    return p->pos.x >= RADIUS - slack && p->pos.x <= TABLE_W - RADIUS + slack && p->pos.y >= RADIUS - slack &&
           p->pos.y <= TABLE_H - RADIUS + slack;
}

static void check(int ok, const char *failure)
{
    if (ok) {
        checks_passed++;
    } else {
        c2d_mcu_puts(failure);
        checks_failed++;
    }
}

int main(void)
{
    float e0 = energy(), e = e0, closest = 1.0f;
    int n, ok = 1, grew = 0, escaped = 0;
    for (n = 0; n < TICKS && ok; n++) {
        float dx, dy, now;
        ok = tick();
        now = energy();
        grew |= now > e * (1.0f + 1e-5f);
        e = now;
        escaped |= !inside(&puck[0]) || !inside(&puck[1]);
        dx = puck[1].pos.x - puck[0].pos.x, dy = puck[1].pos.y - puck[0].pos.y;
        if (dx * dx + dy * dy < closest) closest = dx * dx + dy * dy;
    }
    c2d_mcu_puts("firmware: ");
    put_uint((unsigned long)n);
    c2d_mcu_puts(" ticks, ");
    put_uint(puck_hits);
    c2d_mcu_puts(" puck impacts, ");
    put_uint(cushion_hits);
    c2d_mcu_puts(" cushion impacts, energy ");
    put_milli(e / e0);
    c2d_mcu_puts(" of the start, closest centres ");
    put_milli(closest / (4.0f * RADIUS * RADIUS));
    c2d_mcu_puts(" diameters squared\n");
    check(ok, "FAIL a collision was refused\n");
    check(!grew, "FAIL energy grew\n");
    check(!escaped, "FAIL a puck left the table\n");
    check(closest >= 4.0f * RADIUS * RADIUS * 0.999f, "FAIL the pucks overlapped\n");
    check(puck_hits > 0 && cushion_hits > 0, "FAIL no puck or no cushion impact\n");
    c2d_mcu_puts("firmware: ");
    put_uint(checks_passed);
    c2d_mcu_puts(" passed, ");
    put_uint(checks_failed);
    c2d_mcu_puts(" failed\n");
    return checks_failed == 0 ? 0 : 1;
}
