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
 *   a bit-mask select.  Every other lane (the axes, anything outside the
 *   window, bad input) takes the whole scalar call, and so do cancelling
 *   lanes the second pass (below) does not settle.  An accepted lane's
 *   velocities are committed with a bit-mask select that leaves the others
 *   untouched, so the scalar call sees them as they were.  The kernel also
 *   writes the settled lanes' statuses and counts them, so a block with
 *   nothing left needs no per-lane code outside the vector loop.  A partial
 *   block (the tail) and a bad restitution take the scalar call.
 *
 * CANCELLING LANES: A SECOND VECTOR PASS
 *   A lane inside the window whose d cancels (neither 4d + k <= 0 nor
 *   4d - k >= 0: kappa > 4) is the scalar call's C2D_VERDICT_ACCURATE, which
 *   c2d_real_collide hands to c2d_quick_cancelling (real/collide/collide.h)
 *   at some 250 instructions with branches the predictor cannot learn (9 %
 *   of a gas's pairs, 22 % of a random mix).  The batch queues such lanes
 *   (their indices, branch-free) and, C2D_BLOCK at a time, gathers them and
 *   runs that tier's arithmetic over them in one branch-free loop
 *   (c2d_batch_cancel_as): the exact normal nh + nl (TwoSum of the
 *   positions; nh is the kernel's n, bit for bit), d as c2d_dot2_as's
 *   double-double in its order of operations, and the tests that keep
 *   c2d_cancelling_as on its own route (the split bound 2^(EMAX/2) and the
 *   trust test |d| 2^KAPPA2 >= k) as flags.  A lane passing both takes the
 *   tier's result: SEPARATING for d >= 0, else c = (1+e) d / (n.n (fa + fb))
 *   and the velocities from nh, c2d_cancelling_as's operations (fa, fb and
 *   n.n are the kernel's values), the immovable body's bits kept by a
 *   select.  A lane failing one (the general tier's pairs) takes the whole
 *   scalar call, as before.  The scalar tier forms TwoProduct by FMA where
 *   the CPU has it, the pass too on x86-64-v3 and -v4 and by Veltkamp's
 *   split elsewhere (or C2D_R_FMA where the build has it): the product's
 *   error a*b - p exactly either way (real/arith/exact.h; why the halves
 *   stay exact here: c2d_batch_cancel_as), so the same bits.  Lanes are
 *   independent, so settling them a few blocks late changes nothing.
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
 *   throughput, so the widest vectors pay most).  The cancelling pass is
 *   compiled for x86-64-v4 and -v3 with FMA and chosen by
 *   __builtin_cpu_supports (as the scalar tier chooses its FMA version),
 *   else cloned for baseline and x86-64-v2.  Contraction stays off
 *   everywhere (-ffp-contract=off; only the pass's TwoProduct calls fma),
 *   and division and square root are correctly rounded at any width: same
 *   bits.
 */
#ifndef C2D_REAL_BATCH_H
#define C2D_REAL_BATCH_H

enum { C2D_BLOCK = 16 };

/* The cancelling pass only where the kernel vectorises (x86-64's SSE2,
 * AArch64's NEON): on cores without vectors it is the scalar tier's
 * arithmetic again, at some 3 KB more code and 2 KB more stack
 * (docs/SIZES.md), so there a cancelling lane takes the scalar call. */
#if defined(__SSE2__) || defined(__ARM_NEON)
#define C2D_BATCH_PASS 1
#endif

/* What the kernel found for a lane.  OK - 1 and SEPARATING - 1 are the
 * public statuses C2D_OK and C2D_SEPARATING (lane >> 1). */
enum { C2D_LANE_SCALAR = 0, C2D_LANE_OK = 1, C2D_LANE_SEPARATING = 2, C2D_LANE_CANCELS = 4 };

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

/* The front end over one full block from `base`: c2d_quick's arithmetic
 * with & in place of its branches, walls included.  Each lane's C2D_LANE_*
 * code decides its status (written to st[0..C2D_BLOCK) for the settled
 * lanes) and whether its velocities are committed in place.  Returns the
 * count of OK lanes; *left gets the lanes left unsettled as bits, the
 * cancelling ones at bit j, those for the scalar call at bit C2D_BLOCK + j
 * (32 bits: fits either type).  Results go to local arrays first, so
 * nothing the main loop writes can alias what it reads; each commit loop
 * then touches one array. */
#ifdef C2D_DISPATCH
__attribute__((target_clones("default", "arch=x86-64-v2", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
static c2d_real_bits c2d_batch_kernel(const c2d_real_pairs *p, size_t base, c2d_real e1, c2d_status *restrict st,
                                      c2d_real_bits *restrict left)
{
    /* 2^j for lane j, from a table, not 1 << j: SSE4.2 has no per-lane shift */
    static const c2d_real_bits lane_bit[C2D_BLOCK] = {0x1u,   0x2u,   0x4u,   0x8u,    0x10u,   0x20u,   0x40u,   0x80u,
                                                      0x100u, 0x200u, 0x400u, 0x800u, 0x1000u, 0x2000u, 0x4000u, 0x8000u};
    c2d_real_bits ok_count = 0, unsettled = 0;
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
        const c2d_real_bits approach = (c2d_real_bits)(4 * d + k <= 0), sep = (c2d_real_bits)(4 * d - k >= 0);
        const c2d_real_bits ok = window & approach;
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
        const c2d_real_bits cancels = window & ((approach | sep) ^ 1u);
        const c2d_real_bits code = ok | (window & sep) << 1 | cancels << 2;
        st[j] = (c2d_status)(code >> 1); /* C2D_OK or C2D_SEPARATING where settled */
        ok_count += ok;
#ifdef C2D_BATCH_PASS
        unsettled |= (((c2d_real_bits)0 - cancels) & lane_bit[j]) |
                     (((c2d_real_bits)0 - ((ok | (window & sep) | cancels) ^ 1u)) & lane_bit[j]) << (unsigned)C2D_BLOCK;
#else
        unsettled |= (((c2d_real_bits)0 - ((ok | (window & sep)) ^ 1u)) & lane_bit[j]) << (unsigned)C2D_BLOCK;
#endif
    }
    c2d_batch_commit(&p->vel_ax[base], &out[0][0], keep_a);
    c2d_batch_commit(&p->vel_ay[base], &out[1][0], keep_a);
    c2d_batch_commit(&p->vel_bx[base], &out[2][0], keep_b);
    c2d_batch_commit(&p->vel_by[base], &out[3][0], keep_b);
    *left = unsettled;
    return ok_count;
}

#ifdef C2D_BATCH_PASS
/* Up to C2D_BLOCK cancelling lanes gathered from the pairs: the pass's
 * input, one array per field (index C2D_G_*), and its output. */
enum { C2D_G_PAX = 0, C2D_G_PAY = 1, C2D_G_PBX = 2, C2D_G_PBY = 3, C2D_G_VAX = 4 };
enum { C2D_G_VAY = 5, C2D_G_VBX = 6, C2D_G_VBY = 7, C2D_G_MA = 8, C2D_G_MB = 9, C2D_G_FIELDS = 10 };
typedef struct c2d_batch_gathered {
    c2d_real in[C2D_G_FIELDS][C2D_BLOCK];
    c2d_real out[4][C2D_BLOCK];    /* {va'x, va'y, vb'x, vb'y}, the inputs where not OK */
    c2d_real_bits code[C2D_BLOCK]; /* C2D_LANE_OK, C2D_LANE_SEPARATING or C2D_LANE_SCALAR */
} c2d_batch_gathered;

/* The second pass (header: "cancelling lanes"): c2d_cancelling_as for
 * every gathered lane, branch-free.  The lanes are inside the kernel's
 * window, so c2d_quick_cancelling's bound on the positions holds: a
 * coordinate of magnitude 2^(EMAX-4) or more makes that component of
 * n = pb - pa zero or at least 2^(EMAX-4-MANT) (its ulp), beyond the
 * window's |n_i| <= W^(1/2), and n_i = 0 is the axes' case.  What is left
 * is the split bound and the trust test, as flags.  In a cancelling lane
 * |px| and |py| both exceed 3k/8 >= 3/8 W^-1, so with the split bound the
 * TwoProducts' halves and errors stay normal: Veltkamp's split and FMA give
 * the same exact error.  `fused` as for c2d_two_prod_as. */
C2D_HOT void c2d_batch_cancel_as(c2d_batch_gathered *g, c2d_real e1, int fused)
{
    const c2d_real split_max = c2d_pow2(C2D_R_EMAX / 2), kappa2 = c2d_pow2(C2D_R_EXP_KAPPA2);
    size_t j;
    for (j = 0; j < (size_t)C2D_BLOCK; j++) {
        const c2d_real pax = g->in[C2D_G_PAX][j], pay = g->in[C2D_G_PAY][j];
        const c2d_real pbx = g->in[C2D_G_PBX][j], pby = g->in[C2D_G_PBY][j];
        const c2d_real vax = g->in[C2D_G_VAX][j], vay = g->in[C2D_G_VAY][j];
        const c2d_real vbx = g->in[C2D_G_VBX][j], vby = g->in[C2D_G_VBY][j];
        const c2d_real ma = g->in[C2D_G_MA][j], mb = g->in[C2D_G_MB][j];
        c2d_real nlx, nly, rlx, rly, ex, ey, t;
        /* c2d_exact_normal, then c2d_cancelling_as: k, split, c2d_dot2_as
         * in its order of operations (rhx, rhy are rx, ry; px, py its
         * products, so k is the tier's). */
        const c2d_real nhx = c2d_two_sum(pbx, -pax, &nlx), nhy = c2d_two_sum(pby, -pay, &nly);
        const c2d_real rhx = c2d_two_sum(vbx, -vax, &rlx), rhy = c2d_two_sum(vby, -vay, &rly);
        const c2d_real px = c2d_two_prod_as(rhx, nhx, &ex, fused), py = c2d_two_prod_as(rhy, nhy, &ey, fused);
        const c2d_real k = c2d_abs(px) + c2d_abs(py);
        const c2d_real split = c2d_abs(rhx) + c2d_abs(rhy) + c2d_abs(nhx) + c2d_abs(nhy);
        const c2d_real s = c2d_two_sum(px, py, &t);
        const c2d_real lower = ((rhx * nlx + rlx * nhx) + (rhy * nly + rly * nhy)) + (rlx * nlx + rly * nly);
        const c2d_real d = s + (t + ((ex + ey) + lower));
        const c2d_real_bits settles =
            (c2d_real_bits)(split <= split_max) & (c2d_real_bits)(c2d_abs(d) * kappa2 >= k);
        const c2d_real_bits separating = (c2d_real_bits)(d >= 0), ok = settles & (separating ^ 1u);
        /* The tier's masses (the kernel's pick: the same values for a
         * lane in the window) and update; an immovable body, and every
         * lane not OK, keeps its velocity's bits. */
        const c2d_real_bits ia = (c2d_real_bits)(ma > C2D_R_MAX), ib = (c2d_real_bits)(mb > C2D_R_MAX);
        const c2d_real_bits movable = (c2d_real_bits)0 - ((ia | ib) ^ 1u);
        const c2d_real fa = c2d_pick(ma, movable, (c2d_real_bits)0 - (ia & (ib ^ 1u)));
        const c2d_real fb = c2d_pick(mb, movable, (c2d_real_bits)0 - (ib & (ia ^ 1u)));
        const c2d_real den = (nhx * nhx + nhy * nhy) * (fa + fb);
        const c2d_real c = e1 * d / den;
        const c2d_real la = c * fb, lb = c * fa;
        const c2d_real_bits keep_a = (c2d_real_bits)0 - (ok & (ia ^ 1u)), keep_b = (c2d_real_bits)0 - (ok & (ib ^ 1u));
        g->out[0][j] = c2d_from_bits((c2d_bits(vax + la * nhx) & keep_a) | (c2d_bits(vax) & ~keep_a));
        g->out[1][j] = c2d_from_bits((c2d_bits(vay + la * nhy) & keep_a) | (c2d_bits(vay) & ~keep_a));
        g->out[2][j] = c2d_from_bits((c2d_bits(vbx - lb * nhx) & keep_b) | (c2d_bits(vbx) & ~keep_b));
        g->out[3][j] = c2d_from_bits((c2d_bits(vby - lb * nhy) & keep_b) | (c2d_bits(vby) & ~keep_b));
        g->code[j] = ok | (settles & separating) << 1;
    }
}

/* The pass compiled for each target: under C2D_DISPATCH with FMA for
 * x86-64-v4 and -v3 (chosen when the CPU has them, as the scalar tier
 * chooses c2d_cancelling_fused), target_clones without it below; the same
 * bits everywhere. */
#ifdef C2D_R_FUSED
__attribute__((target("arch=x86-64-v4"))) C2D_COLD void c2d_batch_cancel_v4(c2d_batch_gathered *g, c2d_real e1)
{
    c2d_batch_cancel_as(g, e1, 1);
}

__attribute__((target("arch=x86-64-v3"))) C2D_COLD void c2d_batch_cancel_v3(c2d_batch_gathered *g, c2d_real e1)
{
    c2d_batch_cancel_as(g, e1, 1);
}
#endif

#ifdef C2D_DISPATCH
__attribute__((target_clones("default", "arch=x86-64-v2")))
#endif
C2D_COLD void c2d_batch_cancel_plain(c2d_batch_gathered *g, c2d_real e1)
{
    c2d_batch_cancel_as(g, e1, 0);
}

static void c2d_batch_cancel(c2d_batch_gathered *g, c2d_real e1)
{
#ifdef C2D_R_FUSED
    if (__builtin_cpu_supports("x86-64-v4")) {
        c2d_batch_cancel_v4(g, e1);
        return;
    }
    if (__builtin_cpu_supports("x86-64-v3")) {
        c2d_batch_cancel_v3(g, e1);
        return;
    }
#endif
    c2d_batch_cancel_plain(g, e1);
}
#endif /* C2D_BATCH_PASS */

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

/* The cancelling lanes waiting for the pass: pair indices in a ring of
 * 2 C2D_BLOCK (a block adds at most C2D_BLOCK to fewer than C2D_BLOCK). */
enum { C2D_QUEUE = 2 * C2D_BLOCK };
typedef struct c2d_batch_queue {
    size_t at[C2D_QUEUE];
    size_t head, count;
} c2d_batch_queue;

#ifdef C2D_BATCH_PASS
/* The first n <= C2D_BLOCK queued lanes through the pass (the rest of its
 * width repeats the first lane, computed and dropped), their velocities and
 * statuses stored, the scalar call for those the pass leaves; returns how
 * many are OK. */
static size_t c2d_batch_flush(const c2d_real_pairs *p, c2d_batch_queue *q, size_t n, c2d_real e1, c2d_real restitution,
                              c2d_status *status)
{
    c2d_batch_gathered g;
    size_t j, done = 0;
    for (j = 0; j < (size_t)C2D_BLOCK; j++) {
        const size_t i = q->at[(q->head + (j < n ? j : 0)) % (size_t)C2D_QUEUE];
        g.in[C2D_G_PAX][j] = p->pos_ax[i];
        g.in[C2D_G_PAY][j] = p->pos_ay[i];
        g.in[C2D_G_PBX][j] = p->pos_bx[i];
        g.in[C2D_G_PBY][j] = p->pos_by[i];
        g.in[C2D_G_VAX][j] = p->vel_ax[i];
        g.in[C2D_G_VAY][j] = p->vel_ay[i];
        g.in[C2D_G_VBX][j] = p->vel_bx[i];
        g.in[C2D_G_VBY][j] = p->vel_by[i];
        g.in[C2D_G_MA][j] = p->mass_a[i];
        g.in[C2D_G_MB][j] = p->mass_b[i];
    }
    c2d_batch_cancel(&g, e1);
    for (j = 0; j < n; j++) {
        const size_t i = q->at[(q->head + j) % (size_t)C2D_QUEUE];
        c2d_status s = (c2d_status)(g.code[j] >> 1);
        /* Stored whatever the code: a lane not OK gets its own bits back. */
        p->vel_ax[i] = g.out[0][j];
        p->vel_ay[i] = g.out[1][j];
        p->vel_bx[i] = g.out[2][j];
        p->vel_by[i] = g.out[3][j];
        if (g.code[j] == (c2d_real_bits)C2D_LANE_SCALAR) s = c2d_batch_lane(p, i, restitution);
        if (s == C2D_OK) done++;
        if (status != NULL) status[i] = s;
    }
    q->head = (q->head + n) % (size_t)C2D_QUEUE;
    q->count -= n;
    return done;
}
#endif /* C2D_BATCH_PASS */

/* The lowest set bit of m != 0 (the masks have 32 bits).  The builtin
 * only with the pass: on small cores it is a libgcc call. */
static unsigned c2d_lowest_bit(c2d_real_bits m)
{
#if defined(__GNUC__) && defined(C2D_BATCH_PASS)
    return (unsigned)__builtin_ctzl((unsigned long)m);
#else
    c2d_real_bits rest = m;
    unsigned j = 0;
    while ((rest & 1u) == 0u) {
        rest >>= 1;
        j++;
    }
    return j;
#endif
}

/* The lanes of a full block the kernel left unsettled (`left`, as it
 * returns them): the cancelling ones queued for the pass (their status is
 * written then), the scalar call for the rest; returns how many of those
 * are OK.  Only the set bits cost anything. */
static size_t c2d_batch_unsettled(const c2d_real_pairs *p, size_t base, c2d_real_bits left, c2d_real restitution,
                                  c2d_status *status, c2d_batch_queue *q)
{
    size_t done = 0;
    c2d_real_bits m;
#ifdef C2D_BATCH_PASS
    m = left & (((c2d_real_bits)1 << (unsigned)C2D_BLOCK) - 1u);
    while (m != 0u) {
        q->at[(q->head + q->count) % (size_t)C2D_QUEUE] = base + c2d_lowest_bit(m);
        q->count++;
        m &= m - 1u;
    }
#else
    (void)q;
#endif
    m = left >> (unsigned)C2D_BLOCK;
    while (m != 0u) {
        const size_t i = base + c2d_lowest_bit(m);
        const c2d_status s = c2d_batch_lane(p, i, restitution);
        if (s == C2D_OK) done++;
        if (status != NULL) status[i] = s;
        m &= m - 1u;
    }
    return done;
}

static size_t c2d_real_collide_batch(const c2d_real_pairs *p, size_t count, c2d_real restitution, c2d_status *status)
{
    size_t base, done = 0;
    const int e_ok = restitution >= 0 && restitution <= 1;
    const c2d_real e1 = 1 + restitution;
    c2d_batch_queue q;
    if (p == NULL) return 0;
    q.head = 0;
    q.count = 0;
    for (base = 0; base < count; base += C2D_BLOCK) {
        const size_t width = c2d_block_width(count - base);
        /* Optimising for size (C2D_SMALL, internal.h), every lane takes the
         * scalar call, whose bits the kernel's lanes have: no kernel code. */
        if (!C2D_SMALL && width == (size_t)C2D_BLOCK && e_ok != 0) {
            c2d_status scratch[C2D_BLOCK];
            c2d_real_bits left;
            done += (size_t)c2d_batch_kernel(p, base, e1, status != NULL ? status + base : scratch, &left);
            if (left != 0u) {
                done += c2d_batch_unsettled(p, base, left, restitution, status, &q);
#ifdef C2D_BATCH_PASS
                if (q.count >= (size_t)C2D_BLOCK)
                    done += c2d_batch_flush(p, &q, (size_t)C2D_BLOCK, e1, restitution, status);
#endif
            }
        } else {
            size_t j;
            for (j = 0; j < width; j++) {
                const c2d_status s = c2d_batch_lane(p, base + j, restitution);
                if (s == C2D_OK) done++;
                if (status != NULL) status[base + j] = s;
            }
        }
    }
#ifdef C2D_BATCH_PASS
    if (!C2D_SMALL && q.count > 0) done += c2d_batch_flush(p, &q, q.count, e1, restitution, status);
#endif
    return done;
}

#endif /* C2D_REAL_BATCH_H */
