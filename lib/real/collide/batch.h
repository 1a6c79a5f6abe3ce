/* SPDX-License-Identifier: MIT */
/* real/collide/batch.h - template: c2d_collide_batch over structure-of-arrays pairs.
 * Needs real/collide/collide.h (and what it needs) first.
 *
 * HOW IT STAYS BIT-IDENTICAL TO THE SCALAR CALL
 *   Pairs are taken in blocks of C2D_BLOCK.  A full block runs the scalar
 *   call's input-only accept test (real/collide/fast.h, "front end") for every lane
 *   in a loop with a fixed trip count and no branches, which the compiler
 *   vectorises: the test and the arithmetic it accepts are the very
 *   operations of c2d_quick, so an accepted lane has the scalar call's bits,
 *   and a separating lane its status; a wall takes c2d_quick's mass pair by
 *   a bit-mask select.  Every other lane (cancelling d, the axes, anything
 *   outside the window, bad input) takes the whole scalar call.
 *   An accepted lane's velocities are committed with a bit-mask select that
 *   leaves the others untouched, so the scalar call sees them as they were.
 *   A partial block (the tail) and a bad restitution take the scalar call.
 *
 * RUN-TIME DISPATCH
 *   On hosted x86-64 ELF with gcc (C2D_DISPATCH, internal.h; off with
 *   C2D_NO_DISPATCH, and never in freestanding or MCU builds nor under
 *   ThreadSanitizer, whose gcc instrumentation breaks the resolver) the
 *   kernel is compiled four times by target_clones and the loader picks one
 *   (ifunc): baseline x86-64 (SSE2: float vectorises, double does not, for
 *   want of 64-bit compares), x86-64-v2 (SSE4.2: double too), x86-64-v3
 *   (AVX2: four doubles or eight floats a vector), x86-64-v4 (AVX-512:
 *   eight or sixteen; the double kernel is bound by the division's
 *   throughput, so the widest vectors pay most).  Contraction stays off in
 *   every clone (-ffp-contract=off; nothing here calls fma), and division
 *   and square root are correctly rounded at any width: same bits.
 */
#ifndef C2D_REAL_BATCH_H
#define C2D_REAL_BATCH_H

enum { C2D_BLOCK = 16 };

/* What the kernel found for a lane. */
enum { C2D_LANE_SCALAR = 0, C2D_LANE_OK = 1, C2D_LANE_SEPARATING = 2 };

/* Pairs in the block that starts `left` pairs before the end. */
static size_t c2d_block_width(size_t left) { return left < (size_t)C2D_BLOCK ? left : (size_t)C2D_BLOCK; }

/* Lane i of the pairs as two bodies. */
static void c2d_batch_load(const c2d_real_pairs *p, size_t i, c2d_real_body *a, c2d_real_body *b)
{
    a->pos.x = p->pos_ax[i];
    a->pos.y = p->pos_ay[i];
    a->vel.x = p->vel_ax[i];
    a->vel.y = p->vel_ay[i];
    a->mass = p->mass_a[i];
    b->pos.x = p->pos_bx[i];
    b->pos.y = p->pos_by[i];
    b->vel.x = p->vel_bx[i];
    b->vel.y = p->vel_by[i];
    b->mass = p->mass_b[i];
}

/* v[j] = x[j] where keep[j] is all ones, else unchanged: a bit-mask select
 * (and/andnot/or or a blend once vectorised), never a memcpy call.  Inlined
 * into the kernel, so it is vectorised with the kernel's target. */
static inline void c2d_batch_commit(c2d_real *v, const c2d_real *x, const c2d_real_bits *keep)
{
    size_t j;
    for (j = 0; j < (size_t)C2D_BLOCK; j++)
        v[j] = c2d_from_bits((c2d_bits(x[j]) & keep[j]) | (c2d_bits(v[j]) & ~keep[j]));
}

/* The front end over one full block from `base`: each lane's C2D_LANE_*,
 * and the accepted lanes' velocities committed in place.  c2d_quick's
 * arithmetic with & in place of its branches, walls included.  Results go to local arrays first, so nothing the
 * main loop writes can alias what it reads; each commit loop then touches
 * one array. */
#ifdef C2D_DISPATCH
__attribute__((target_clones("default", "arch=x86-64-v2", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
static void c2d_batch_kernel(const c2d_real_pairs *p, size_t base, c2d_real e1, c2d_real_bits *restrict lane)
{
    c2d_real out[4][C2D_BLOCK];
    c2d_real_bits keep_a[C2D_BLOCK], keep_b[C2D_BLOCK];
    const c2d_real hi = C2D_R_QUICK_HI, lo = C2D_R_QUICK_LO;
    const c2d_real *pax = p->pos_ax + base, *pay = p->pos_ay + base;
    const c2d_real *pbx = p->pos_bx + base, *pby = p->pos_by + base;
    const c2d_real *vax = p->vel_ax + base, *vay = p->vel_ay + base;
    const c2d_real *vbx = p->vel_bx + base, *vby = p->vel_by + base;
    const c2d_real *ma = p->mass_a + base, *mb = p->mass_b + base;
    size_t j;
    for (j = 0; j < (size_t)C2D_BLOCK; j++) {
        const c2d_real nx = pbx[j] - pax[j], ny = pby[j] - pay[j];
        const c2d_real px = (vbx[j] - vax[j]) * nx, py = (vby[j] - vay[j]) * ny;
        const c2d_real d = px + py;
        const c2d_real k = c2d_abs(px) + c2d_abs(py);
        const c2d_real nn = nx * nx + ny * ny;
        const c2d_real geometry = k < nn ? k : nn, lighter = ma[j] < mb[j] ? ma[j] : mb[j];
        const c2d_real least = geometry < lighter ? geometry : lighter;
        /* A wall (one mass INFINITY) takes c2d_finish's mass pair, (0, 1) or
         * (1, 0): fa + fb = 1.  With `lighter` finite (which refuses two
         * immovable bodies, and NaN: then lighter is NaN or INFINITY) the
         * window below then implies c2d_quick_wall's, since the other mass is
         * `lighter` and (k + nn) + 1 <= W implies k + nn <= W; without a wall
         * it is c2d_quick's own.  So the kernel accepts only what c2d_quick
         * accepts, with the same fa and fb. */
        const c2d_real_bits ia = (c2d_real_bits)(ma[j] > C2D_R_MAX), ib = (c2d_real_bits)(mb[j] > C2D_R_MAX);
        const c2d_real_bits movable = (c2d_real_bits)0 - ((ia | ib) ^ 1u);
        const c2d_real fa = c2d_pick(ma[j], movable, (c2d_real_bits)0 - (ia & (ib ^ 1u)));
        const c2d_real fb = c2d_pick(mb[j], movable, (c2d_real_bits)0 - (ib & (ia ^ 1u)));
        /* Truth values in the floating type's width (c2d_real_bits), combined
         * with & and |: no branch, and no narrowing of a comparison's mask. */
        const c2d_real_bits window = (c2d_real_bits)((k + nn) + (fa + fb) <= hi) & (c2d_real_bits)(least >= lo) &
                                     (c2d_real_bits)(lighter <= C2D_R_MAX) & (c2d_real_bits)(nx != 0) &
                                     (c2d_real_bits)(ny != 0); /* axes: scalar */
        const c2d_real_bits ok = window & (c2d_real_bits)(4 * d + k <= 0);
        const c2d_real den = nn * (fa + fb);
        const c2d_real c = e1 * d / den;
        const c2d_real la = c * fb, lb = c * fa;
        out[0][j] = vax[j] + la * nx;
        out[1][j] = vay[j] + la * ny;
        out[2][j] = vbx[j] - lb * nx;
        out[3][j] = vby[j] - lb * ny;
        /* An accepted lane's immovable body keeps its velocity's bits
         * (its change is a signed zero: -0 + +0 would be +0). */
        keep_a[j] = (c2d_real_bits)0 - (ok & (ia ^ 1u));
        keep_b[j] = (c2d_real_bits)0 - (ok & (ib ^ 1u));
        lane[j] = ok | (window & (c2d_real_bits)(4 * d - k >= 0)) << 1;
    }
    c2d_batch_commit(&p->vel_ax[base], &out[0][0], keep_a);
    c2d_batch_commit(&p->vel_ay[base], &out[1][0], keep_a);
    c2d_batch_commit(&p->vel_bx[base], &out[2][0], keep_b);
    c2d_batch_commit(&p->vel_by[base], &out[3][0], keep_b);
}

/* One lane the kernel did not settle: the whole scalar call. */
static c2d_status c2d_batch_lane(const c2d_real_pairs *p, size_t i, c2d_real restitution)
{
    c2d_real_body a, b;
    c2d_status s;
    c2d_batch_load(p, i, &a, &b);
    s = c2d_real_collide(&a, &b, restitution);
    if (s == C2D_OK) {
        p->vel_ax[i] = a.vel.x;
        p->vel_ay[i] = a.vel.y;
        p->vel_bx[i] = b.vel.x;
        p->vel_by[i] = b.vel.y;
    }
    return s;
}

/* Each lane's status (the scalar call for the lanes the kernel left);
 * returns how many are OK. */
static size_t c2d_batch_finish_block(const c2d_real_pairs *p, size_t base, size_t width, const c2d_real_bits *lane,
                                     c2d_real restitution, c2d_status *status)
{
    size_t j, done = 0;
    c2d_real_bits all = (c2d_real_bits)C2D_LANE_OK;
    for (j = 0; j < width; j++) all &= lane[j];
    if (width == (size_t)C2D_BLOCK && all == (c2d_real_bits)C2D_LANE_OK) {
        /* Every lane accepted: C2D_OK is 0 = C2D_LANE_OK - 1, written lane by
         * lane (a constant store would become a memset call). */
        if (status != NULL)
            for (j = 0; j < (size_t)C2D_BLOCK; j++) status[base + j] = (c2d_status)(lane[j] - 1u);
        return (size_t)C2D_BLOCK;
    }
    for (j = 0; j < width; j++) {
        const size_t i = base + j;
        c2d_status s;
        if (lane[j] == (c2d_real_bits)C2D_LANE_OK)
            s = C2D_OK;
        else if (lane[j] == (c2d_real_bits)C2D_LANE_SEPARATING)
            s = C2D_SEPARATING;
        else
            s = c2d_batch_lane(p, i, restitution);
        if (s == C2D_OK) done++;
        if (status != NULL) status[i] = s;
    }
    return done;
}

static size_t c2d_real_collide_batch(const c2d_real_pairs *p, size_t count, c2d_real restitution, c2d_status *status)
{
    size_t base, done = 0;
    const int e_ok = restitution >= 0 && restitution <= 1;
    const c2d_real e1 = 1 + restitution;
    if (p == NULL) return 0;
    for (base = 0; base < count; base += C2D_BLOCK) {
        c2d_real_bits lane[C2D_BLOCK];
        const size_t width = c2d_block_width(count - base);
        /* Optimising for size (C2D_SMALL, internal.h), every lane takes the
         * scalar call, whose bits the kernel's lanes have: no kernel code. */
        if (!C2D_SMALL && width == (size_t)C2D_BLOCK && e_ok != 0) {
            c2d_batch_kernel(p, base, e1, lane);
        } else {
            size_t j;
            for (j = 0; j < width; j++) lane[j] = (c2d_real_bits)C2D_LANE_SCALAR;
        }
        done += c2d_batch_finish_block(p, base, width, lane, restitution, status);
    }
    return done;
}

#endif /* C2D_REAL_BATCH_H */
