/* SPDX-License-Identifier: MIT */
/* make_seeds.c - writes the hand-made seed inputs of the fuzz corpus
 * (make fuzz-seeds).  Each seed is one meaningful scene per entry point in
 * the harness's input format (see fuzz_collide2d.c): head-on, oblique, wall,
 * separating, coincident, unequal masses, plus special values (NaN, Inf,
 * DBL_MAX, subnormal, zero mass, bad restitution); for the rough contact
 * spin, english off a cushion, rolling, the smooth identities, and its own
 * bad fields; for the time of impact under acceleration a ball slowing on
 * cloth, a puck pushed, zero and equal accelerations, a horizon before and
 * after the contact, touching at 0, a graze, and bad accelerations and
 * horizons; for the sphere contacts (byte 0 C2D_FUZZ_SPHERE_TAG, byte 2 the
 * contact) stun, follow and draw, a cut with side spin, Alciatore's mu(v),
 * sticking, an immovable ball, rails at R, 0.635 D and 2R with running
 * english, and bad fields.  Usage: make_seeds DIR */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fuzz.h" /* the entry points and modes */

static unsigned char buf[4096];
static size_t len;
static const char *dir;

static void byte(int b) { buf[len++] = (unsigned char)b; }
static void i16(long v)
{
    byte((int)(v & 0xFF));
    byte((int)((v >> 8) & 0xFF));
}
static void start(int entry, int flags)
{
    len = 0;
    byte(entry);
    byte(flags);
}
static void save(const char *name)
{
    char path[512];
    FILE *f;
    snprintf(path, sizeof path, "%s/seed-%s", dir, name);
    f = fopen(path, "wb");
    if (f == NULL || fwrite(buf, 1, len, f) != len || fclose(f) != 0) {
        perror(path);
        return;
    }
}

/* A tame body: positions and velocities in 1/256 units (1/16 steps for
 * Q16.16 entries, so `unit` is 256 or 4096), mass index m (0xFFFF immovable). */
static void tame_body(double px, double py, double vx, double vy, long m, double unit)
{
    i16((long)(px * unit));
    i16((long)(py * unit));
    i16((long)(vx * unit));
    i16((long)(vy * unit));
    i16(m);
}

/* Mixed-mode fields: tag 5 picks a special value, tag 7 a small integer. */
static void special(int k) { byte(5); byte(k); }
static void small(int v) { byte(7); byte(v & 0xFF); }

static void scene_pair(int entry, const char *name, double unit)
{
    char full[256];
    static const struct {
        const char *what;
        double a[4], b[4];
        long ma, mb;
        double nx, ny;
        int e;
    } s[] = {
        {"headon", {0, 0, 1, 0}, {1, 0, 0, 0}, 255, 255, 1, 0, 255},
        {"oblique", {0, 0, 1, 0}, {1, 1, 0, 0}, 255, 255, 1, 1, 255},
        {"wall", {0, 0, 2, -1}, {1, 0, 0, 0}, 100, 0xFFFF, 1, 0, 200},
        {"separating", {0, 0, -1, 0}, {1, 0, 1, 0}, 255, 255, 1, 0, 255},
        {"coincident", {1, 1, 1, 0}, {1, 1, 0, 0}, 255, 255, 0, 0, 255},
        {"unequal", {0, 0, 3, 1}, {0.5, 0.9, -1, 0}, 10, 3000, 0.5, 0.9, 128},
    };
    size_t i;
    for (i = 0; i < sizeof s / sizeof s[0]; i++) {
        start(entry, C2D_FUZZ_TAME);
        tame_body(s[i].a[0], s[i].a[1], s[i].a[2], s[i].a[3], s[i].ma, unit);
        tame_body(s[i].b[0], s[i].b[1], s[i].b[2], s[i].b[3], s[i].mb, unit);
        if (entry == C2D_FUZZ_TOI || entry == C2D_FUZZ_TOIF || entry == C2D_FUZZ_TOIX) {
            i16((long)(0.5 * unit)); /* radius_sum */
        } else {
            i16((long)(s[i].nx * unit));
            i16((long)(s[i].ny * unit));
            if (entry == C2D_FUZZ_COLLIDEX || entry == C2D_FUZZ_COLLIDE_NORMALX) byte(0); /* tag */
            byte(s[i].e);
        }
        snprintf(full, sizeof full, "%s-%s", name, s[i].what);
        save(full);
    }
}

/* Special values for the floating entry points: NaN velocity (252), Inf
 * position (250), DBL_MAX position (6), subnormal velocity (10), zero mass (0),
 * restitution raw from tag 0 (a NaN-free but > 1 value via special 5 = 2.0). */
static void scene_special(int entry, const char *name)
{
    static const struct { const char *what; int field, value; } s[] = {
        {"nan-vel", 2, 252}, {"inf-pos", 0, 250}, {"max-pos", 5, 6}, {"subnormal-vel", 3, 10},
        {"zero-mass", 4, 0}, {"huge-vel", 7, 13},
    };
    char full[256];
    size_t i;
    int f;
    for (i = 0; i < sizeof s / sizeof s[0]; i++) {
        static const int base[10] = {0, 0, 1, 0, 1, 1, 0, 0, 0, 1};
        start(entry, C2D_FUZZ_MIXED);
        for (f = 0; f < 10; f++) {
            if (f == s[i].field) special(s[i].value);
            else small(base[f]);
        }
        small(1); /* normal x or radius_sum */
        small(0);
        byte(2);  /* restitution tag: 1.0 */
        snprintf(full, sizeof full, "%s-%s", name, s[i].what);
        save(full);
    }
    start(entry, C2D_FUZZ_MIXED);
    for (f = 0; f < 12; f++) small(f % 3 - 1);
    byte(0); /* restitution from a full value: */
    special(5); /* 2.0: invalid */
    snprintf(full, sizeof full, "%s-bad-restitution", name);
    save(full);
}

static void scene_batch(int entry, const char *name)
{
    char full[256];
    int i, count = 19; /* two kernel blocks and a tail */
    start(entry, C2D_FUZZ_TAME);
    byte(count);
    byte(230);
    for (i = 0; i < count; i++) {
        double d = 0.5 + 0.1 * (i % 7);
        tame_body(0, 0, 1 + 0.25 * (i % 5), 0.5 - 0.1 * i, 100 + 40 * i, 256);
        tame_body(d, 0.3 * (i % 3 - 1), -1, 0.2 * (i % 4), i == 7 ? 0xFFFF : 300 - 10 * i, 256);
    }
    snprintf(full, sizeof full, "%s-mixed19", name);
    save(full);
    start(entry, C2D_FUZZ_TAME | C2D_FUZZ_NULL_STATUS);
    byte(8);
    byte(255);
    for (i = 0; i < 8; i++) {
        tame_body(0, 0, 1, 0, 255, 256);
        tame_body(1, 0.125 * i, 0, 0, 255, 256);
    }
    snprintf(full, sizeof full, "%s-block8-nullstatus", name);
    save(full);
}

/* A tame rough disk: as tame_body plus spin and radius (1/256 units) and
 * inertia index (0xFFFF: INFINITY). */
static void tame_disk(const double d[6], long m, long inertia)
{
    i16((long)(d[0] * 256));
    i16((long)(d[1] * 256));
    i16((long)(d[2] * 256));
    i16((long)(d[3] * 256));
    i16((long)(d[4] * 256)); /* spin */
    i16(m);
    i16((long)(d[5] * 256)); /* radius */
    i16(inertia);
}

/* Tame surfaces: e byte / 255, friction byte / 64 (255: INFINITY), beta
 * byte mapped onto [-1, 1] (0: -1, 255: 1). */
static void scene_rough(int entry, const char *name)
{
    static const struct {
        const char *what;
        double a[6], b[6]; /* pos, vel, spin, radius */
        long ma, mb, ia, ib;
        double nx, ny;
        int e, mu, beta;
    } s[] = {
        {"spin-headon", {0, 0, 1, 0, 3, 0.5}, {1, 0, 0, 0, -2, 0.5}, 256, 256, 25, 25, 1, 0, 230, 13, 180},
        {"oblique-stick", {0, 0, 1, 0.5, 0, 0.5}, {0.6, 0.8, -1, 0, 0, 0.5}, 256, 512, 40, 80, 0.6, 0.8, 255, 255, 255},
        {"cushion-english", {0, 0, 2, -1, 8, 0.25}, {0.25, 0, 0, 0, 0, 0}, 100, 0xFFFF, 3, 0xFFFF, 1, 0, 200, 13, 128},
        {"separating", {0, 0, -1, 0, 5, 0.5}, {1, 0, 1, 0, 5, 0.5}, 256, 256, 25, 25, 1, 0, 255, 64, 255},
        {"coincident", {1, 1, 1, 0, 0, 0.5}, {1, 1, 0, 0, 0, 0.5}, 256, 256, 25, 25, 0, 0, 255, 64, 255},
        {"rolling", {0, 0, 0, 0.004, 0, 0.5}, {1, 0, -0.004, 64, -128, 0.5}, 1, 60000, 1, 60000, 1, 0, 230, 19, 191},
        {"frictionless", {0, 0, 1, 0.3, 4, 0.5}, {0.8, 0.6, 0, 0, -4, 0.5}, 256, 256, 25, 25, 0.8, 0.6, 255, 0, 255},
        {"smooth-beta", {0, 0, 1, 0.3, 4, 0.5}, {0.8, 0.6, 0, 0, -4, 0.5}, 256, 256, 25, 25, 0.8, 0.6, 128, 64, 0},
        {"inf-inertia", {0, 0, 1, 0, 2, 0.5}, {1, 0, -1, 1, 1, 0.5}, 256, 256, 0xFFFF, 25, 1, 0, 255, 255, 255},
        {"points", {0, 0, 1, 0, 2, 0}, {1, 0, -1, 1, 1, 0}, 256, 256, 25, 25, 1, 0, 255, 64, 255},
    };
    char full[256];
    size_t i;
    for (i = 0; i < sizeof s / sizeof s[0]; i++) {
        start(entry, C2D_FUZZ_TAME);
        tame_disk(s[i].a, s[i].ma, s[i].ia);
        tame_disk(s[i].b, s[i].mb, s[i].ib);
        i16((long)(s[i].nx * 256));
        i16((long)(s[i].ny * 256));
        byte(s[i].e);
        byte(s[i].mu);
        byte(s[i].beta);
        snprintf(full, sizeof full, "%s-%s", name, s[i].what);
        save(full);
    }
}

/* Mixed-mode rough disks with one bad field each: NaN spin, Inf radius,
 * radius -1, inertia 0, and a surface with NaN friction or beta 2. */
static void scene_rough_bad(int entry, const char *name)
{
    static const struct { const char *what; int field, value, mu_tag, beta_tag; } s[] = {
        {"nan-spin", 4, 252, 1, 1}, {"inf-radius", 6, 250, 1, 1}, {"negative-radius", 6, 3, 1, 1},
        {"zero-inertia", 7, 0, 1, 1}, {"nan-friction", -1, 0, 0, 1}, {"beta-2", -1, 0, 1, 0},
    };
    static const int base[16] = {0, 0, 1, 0, 1, 1, 1, 1, 1, 0, 0, 0, -1, 1, 1, 1};
    char full[256];
    size_t i;
    int f;
    for (i = 0; i < sizeof s / sizeof s[0]; i++) {
        start(entry, C2D_FUZZ_MIXED);
        for (f = 0; f < 16; f++) {
            if (f == s[i].field) special(s[i].value);
            else small(base[f]);
        }
        small(1); /* normal */
        small(0);
        byte(2); /* restitution 1 */
        byte(s[i].mu_tag);
        if (s[i].mu_tag == 0) special(252); /* NaN friction */
        else byte(64);                      /* friction 1 */
        byte(s[i].beta_tag);
        if (s[i].beta_tag == 0) special(5); /* beta 2.0 */
        else byte(200);
        snprintf(full, sizeof full, "%s-%s", name, s[i].what);
        save(full);
    }
}

/* A tame ball (1/256 units): pos, vel, spin (3), radius; mass and inertia
 * indices as tame_disk's. */
static void tame_ball(const double d[8], long m, long inertia)
{
    int i;
    for (i = 0; i < 7; i++) i16((long)(d[i] * 256));
    i16(m);
    i16((long)(d[7] * 256));
    i16(inertia);
}

static void start_sphere(int entry, int mode)
{
    start(C2D_FUZZ_SPHERE_TAG, mode);
    byte(entry - C2D_FUZZ_ENTRIES);
}

/* Tame ball-ball surfaces: e byte / 255, friction, boost and decay bytes
 * / 64 (friction 255: INFINITY).  Balls of radius 0.25, mass 1, inertia
 * 25/256 (~ 2/5 m R^2). */
static void scene_balls(int entry, const char *name)
{
    static const struct {
        const char *what;
        double a[8], b[8]; /* pos, vel, spin x y z, radius */
        long ma, mb;
        int e, mu, boost, decay;
    } s[] = {
        {"stun", {0, 0, 2, 0, 0, 0, 0, 0.25}, {0.5, 0, 0, 0, 0, 0, 0, 0.25}, 255, 255, 242, 3, 0, 0},
        {"follow", {0, 0, 2, 0, 0, 8, 0, 0.25}, {0.5, 0, 0, 0, 0, 0, 0, 0.25}, 255, 255, 242, 3, 0, 0},
        {"draw-cut", {0, 0, 2, 0, 0, -6, 3, 0.25}, {0.35, 0.35, 0, 0, 0, 0, 0, 0.25}, 255, 255, 242, 13, 0, 0},
        {"alciatore", {0, 0, 1, 0.5, 2, 4, -4, 0.25}, {0.4, 0.3, -1, 0, 0, 0, 1, 0.25}, 255, 255, 242, 1, 7, 70},
        {"stick", {0, 0, 1, 0, 0, 0, 8, 0.25}, {0.3, 0.4, 0, 0, 0, 0, 0, 0.25}, 255, 255, 255, 255, 0, 0},
        {"immovable", {0, 0, 1, 0.5, 4, 0, 2, 0.25}, {0.5, 0, 0, 0, 1, 1, 1, 0.25}, 255, 0xFFFF, 204, 51, 0, 0},
        {"separating", {0, 0, -1, 0, 0, 4, 0, 0.25}, {0.5, 0, 1, 0, 0, 0, 0, 0.25}, 255, 255, 242, 3, 0, 0},
    };
    char full[256];
    size_t i;
    for (i = 0; i < sizeof s / sizeof s[0]; i++) {
        start_sphere(entry, C2D_FUZZ_TAME);
        tame_ball(s[i].a, s[i].ma, 24);
        tame_ball(s[i].b, s[i].mb, 24);
        byte(s[i].e);
        byte(s[i].mu);
        byte(s[i].boost);
        byte(s[i].decay);
        snprintf(full, sizeof full, "%s-%s", name, s[i].what);
        save(full);
    }
}

/* Tame rails: normal, height byte (R (1 + k / 255)), e byte, friction byte. */
static void scene_cushion(int entry, const char *name)
{
    static const struct {
        const char *what;
        double a[8], nx, ny;
        int h, e, mu;
    } s[] = {
        {"rolling-table-height", {0, 0, 1.5, 0, 0, 6, 0, 0.25}, 1, 0, 69, 204, 13},
        {"english-30deg", {0, 0, 1.3, 0.75, 0, 5, 4, 0.25}, 1, 0, 69, 204, 13},
        {"centre-height", {0, 0, 1, 1, 0, 0, -4, 0.25}, 0.6, 0.8, 0, 204, 13},
        {"top", {0, 0, 1, 0, 2, 0, 0, 0.25}, 1, 0, 255, 204, 13},
        {"stick", {0, 0, 1, -1, 3, -3, 3, 0.25}, 0, -1, 128, 255, 255},
        {"separating", {0, 0, -1, 0, 0, 4, 0, 0.25}, 1, 0, 69, 204, 13},
    };
    char full[256];
    size_t i;
    for (i = 0; i < sizeof s / sizeof s[0]; i++) {
        start_sphere(entry, C2D_FUZZ_TAME);
        tame_ball(s[i].a, 255, 24);
        i16((long)(s[i].nx * 256));
        i16((long)(s[i].ny * 256));
        byte(s[i].h);
        byte(s[i].e);
        byte(s[i].mu);
        snprintf(full, sizeof full, "%s-%s", name, s[i].what);
        save(full);
    }
}

/* Mixed-mode balls with one bad field each (NaN spin, Inf radius, inertia
 * 0), the rest small integers; then a good surface (e 1, friction 1). */
static void scene_sphere_bad(int entry, const char *name)
{
    static const struct { const char *what; int field, value; } s[] = {
        {"nan-spin", 5, 252}, {"inf-radius", 8, 250}, {"zero-inertia", 9, 0},
    };
    static const int base[20] = {0, 0, 1, 0, 1, 1, 1, 1, 1, 1, 2, 0, -1, 0, 0, 0, 0, 1, 1, 1};
    char full[256];
    size_t i;
    int f;
    for (i = 0; i < sizeof s / sizeof s[0]; i++) {
        start_sphere(entry, C2D_FUZZ_MIXED);
        for (f = 0; f < 20; f++) {
            if (f == s[i].field) special(s[i].value);
            else small(base[f]);
        }
        byte(2); /* restitution 1 */
        byte(1), byte(64); /* friction 1 */
        byte(2), byte(2); /* boost and decay 0 */
        snprintf(full, sizeof full, "%s-%s", name, s[i].what);
        save(full);
    }
}

/* Tame accelerated pairs (1/256 units); horizon < 0: INFINITY. */
static void scene_accel(int entry, const char *name)
{
    static const struct {
        const char *what;
        double a[4], b[4], aa[2], ab[2], r, h;
    } s[] = {
        {"cloth", {0, 0, 2, 0}, {1.5, 0.05, 0, 0}, {-0.25, 0}, {0, 0}, 0.125, -1},
        {"cloth-stops-short", {0, 0, 1, 0}, {3, 0, 0, 0}, {-0.25, 0}, {0, 0}, 0.125, -1},
        {"pushed", {0, 0, 0, 1}, {2, 0, 0, -1}, {0.5, 0}, {0, 0}, 0.5, -1},
        {"zero-accel", {0, 0, 1, 0}, {2, 0.25, -1, 0}, {0, 0}, {0, 0}, 0.5, -1},
        {"equal-accel", {0, 0, 1, 0}, {2, 0.25, -1, 0}, {0.5, -2}, {0.5, -2}, 0.5, -1},
        {"horizon-short", {0, 0, 1, 0}, {3, 0, 0, 0}, {0, 0}, {0, 0}, 0.5, 2},
        {"horizon-long", {0, 0, 1, 0}, {3, 0, 0, 0}, {0, 0}, {0, 0}, 0.5, 3},
        {"touching", {0, 0, 1, 0}, {0.5, 0, 0, 0}, {0, 0}, {0, 0}, 0.5, -1},
        {"overlap-turn", {0, 0, -1, 0}, {0.25, 0, 0, 0}, {4, 0}, {0, 0}, 0.5, -1},
        {"graze", {0, 0, 1, 0}, {3, 0.5, 0, 0}, {0, 0}, {0, 0}, 0.5, -1},
    };
    char full[256];
    size_t i;
    for (i = 0; i < sizeof s / sizeof s[0]; i++) {
        start(entry, C2D_FUZZ_TAME);
        tame_body(s[i].a[0], s[i].a[1], s[i].a[2], s[i].a[3], 255, 256);
        tame_body(s[i].b[0], s[i].b[1], s[i].b[2], s[i].b[3], 255, 256);
        i16((long)(s[i].aa[0] * 256));
        i16((long)(s[i].aa[1] * 256));
        i16((long)(s[i].ab[0] * 256));
        i16((long)(s[i].ab[1] * 256));
        i16((long)(s[i].r * 256));
        if (s[i].h < 0) {
            byte(0);
        } else {
            byte(1);
            i16((long)(s[i].h * 256));
        }
        snprintf(full, sizeof full, "%s-%s", name, s[i].what);
        save(full);
    }
}

/* Mixed-mode accelerated pairs with a bad argument: NaN or Inf
 * acceleration, horizon -1 or NaN. */
static void scene_accel_bad(int entry, const char *name)
{
    static const struct { const char *what; int field, value; } s[] = {
        {"nan-accel", 10, 252}, {"inf-accel", 13, 250}, {"negative-horizon", 15, 3}, {"nan-horizon", 15, 252},
    };
    static const int base[15] = {0, 0, 1, 0, 1, 2, 0, -1, 0, 1, 0, 0, 0, 0, 1};
    char full[256];
    size_t i;
    int f;
    for (i = 0; i < sizeof s / sizeof s[0]; i++) {
        start(entry, C2D_FUZZ_MIXED);
        for (f = 0; f < 15; f++) {
            if (f == s[i].field) special(s[i].value);
            else small(base[f]);
        }
        byte(1); /* horizon: a value follows */
        if (s[i].field == 15) special(s[i].value);
        else small(4);
        snprintf(full, sizeof full, "%s-%s", name, s[i].what);
        save(full);
    }
}

/* Raw-mode fields: a double's or a float's bit pattern, little-endian. */
static void raw64(uint64_t v)
{
    int k;
    for (k = 0; k < 8; k++) byte((int)((v >> (8 * k)) & 0xFF));
}
static void raw32(uint32_t v)
{
    int k;
    for (k = 0; k < 4; k++) byte((int)((v >> (8 * k)) & 0xFF));
}

/* The time-of-impact cases the audit of the statuses found, at extreme
 * magnitude ratios (the miss distance, the radius and d.v underflowing or
 * rounding together after the scaling): two misses that must be SEPARATING
 * and an overlap that must be OK at 0. */
static void scene_toi_ratios(void)
{
    static const uint64_t d[2][6] = {
        /* a.vel.x, b.pos.x, b.pos.y, R: a.pos = b.vel = 0, masses 1 */
        {0x3ff0000000000000u, 0x7e70000000000000u, 0x39b0000000000000u, 0x3910000000000000u, 0, 0},
        {0x5f30000000000000u, 0x1a70000000000000u, 0x5f30000000000000u, 0x5f40000000000000u, 0, 0},
    };
    static const char *const dname[2] = {"time_of_impact-ratio-miss", "time_of_impact-ratio-overlap"};
    const uint64_t one = 0x3ff0000000000000u;
    int i;
    for (i = 0; i < 2; i++) {
        start(C2D_FUZZ_TOI, C2D_FUZZ_RAW);
        raw64(0), raw64(0), raw64(d[i][0]), raw64(0), raw64(one); /* a */
        raw64(d[i][1]), raw64(d[i][2]), raw64(0), raw64(0), raw64(one); /* b */
        raw64(d[i][3]);
        save(dname[i]);
    }
    start(C2D_FUZZ_TOIF, C2D_FUZZ_RAW);
    raw32(0), raw32(0), raw32(0x3f800000u), raw32(0), raw32(0x3f800000u);
    raw32(0x71800000u), raw32(0x21800000u), raw32(0), raw32(0), raw32(0x3f800000u);
    raw32(0x1c800000u);
    save("time_of_impactf-ratio-miss");
}

int main(int argc, char **argv)
{
    static const char *names[] = {"collide", "collide_normal", "time_of_impact", "collidef", "collide_normalf",
                                  "time_of_impactf", "collidex", "collide_normalx", "time_of_impactx"};
    int e;
    if (argc != 2) {
        fprintf(stderr, "usage: make_seeds DIR\n");
        return 2;
    }
    dir = argv[1];
    for (e = C2D_FUZZ_COLLIDE; e <= C2D_FUZZ_TOIX; e++) {
        scene_pair(e, names[e], e >= C2D_FUZZ_COLLIDEX ? 4096 : 256);
        if (e < C2D_FUZZ_COLLIDEX) scene_special(e, names[e]);
    }
    scene_batch(C2D_FUZZ_BATCH, "collide_batch");
    scene_batch(C2D_FUZZ_BATCHF, "collide_batchf");
    scene_toi_ratios();
    scene_rough(C2D_FUZZ_ROUGH, "collide_rough");
    scene_rough(C2D_FUZZ_ROUGH_NORMAL, "collide_rough_normal");
    scene_rough(C2D_FUZZ_ROUGHF, "collide_roughf");
    scene_rough(C2D_FUZZ_ROUGH_NORMALF, "collide_rough_normalf");
    scene_rough_bad(C2D_FUZZ_ROUGH, "collide_rough");
    scene_rough_bad(C2D_FUZZ_ROUGHF, "collide_roughf");
    scene_accel(C2D_FUZZ_TOI_ACCEL, "time_of_impact_accel");
    scene_accel(C2D_FUZZ_TOI_ACCELF, "time_of_impact_accelf");
    scene_accel_bad(C2D_FUZZ_TOI_ACCEL, "time_of_impact_accel");
    scene_accel_bad(C2D_FUZZ_TOI_ACCELF, "time_of_impact_accelf");
    scene_balls(C2D_FUZZ_BALLS, "collide_balls");
    scene_balls(C2D_FUZZ_BALLSF, "collide_ballsf");
    scene_cushion(C2D_FUZZ_CUSHION, "collide_cushion");
    scene_cushion(C2D_FUZZ_CUSHIONF, "collide_cushionf");
    scene_sphere_bad(C2D_FUZZ_BALLS, "collide_balls");
    scene_sphere_bad(C2D_FUZZ_BALLSF, "collide_ballsf");
    return 0;
}
