/* real_batch.h - template: c2d_collide_batch over structure-of-arrays pairs.
 * Needs real_collide.h (and what it needs) first.
 *
 * HOW IT STAYS BIT-IDENTICAL TO THE SCALAR CALL
 *   Pairs are taken in blocks of C2D_BLOCK.  A full block runs the fast
 *   path's flag computation (c2d_fast_flags, the very function the scalar
 *   call inlines) for every lane in a loop with a fixed trip count and no
 *   branches, which the compiler vectorises: clang at -O2, gcc 12 for float
 *   on baseline x86-64 and for double from x86-64-v2 on (SSE2 has no 64-bit
 *   compare for the flag masks).  Then each lane's verdict is decoded: OK,
 *   SEPARATING and RANGE are final; the others go straight to the tier the
 *   verdict names, exactly as the scalar call would send them.  A partial
 *   block (the tail) and a bad restitution take the whole scalar call.
 */
#ifndef C2D_REAL_BATCH_H
#define C2D_REAL_BATCH_H

enum { C2D_BLOCK = 16 };

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

/* The fast path over one full block, from `base`: flags and results. */
static void c2d_batch_kernel(const c2d_real_pairs *p, size_t base, c2d_real e1,
                             c2d_real_bits flags[C2D_BLOCK], c2d_real out[4][C2D_BLOCK])
{
    const c2d_real *pax = p->pos_ax + base, *pay = p->pos_ay + base;
    const c2d_real *pbx = p->pos_bx + base, *pby = p->pos_by + base;
    const c2d_real *vax = p->vel_ax + base, *vay = p->vel_ay + base;
    const c2d_real *vbx = p->vel_bx + base, *vby = p->vel_by + base;
    const c2d_real *ma = p->mass_a + base, *mb = p->mass_b + base;
    size_t j;
    for (j = 0; j < C2D_BLOCK; j++) {
        c2d_real o[4];
        c2d_pair q;
        q.n.x = pbx[j] - pax[j];
        q.n.y = pby[j] - pay[j];
        q.va.x = vax[j];
        q.va.y = vay[j];
        q.vb.x = vbx[j];
        q.vb.y = vby[j];
        q.ma = ma[j];
        q.mb = mb[j];
        flags[j] = c2d_fast_flags(&q, e1, o);
        out[0][j] = o[0];
        out[1][j] = o[1];
        out[2][j] = o[2];
        out[3][j] = o[3];
    }
}

/* One lane the kernel did not settle (or did not run for): the tier the
 * verdict names, or the whole scalar call. */
static c2d_status c2d_batch_lane(const c2d_real_pairs *p, size_t i, int kernel_ran, c2d_verdict v, c2d_real restitution)
{
    c2d_real_body a, b;
    c2d_status s;
    c2d_batch_load(p, i, &a, &b);
    if (kernel_ran == 0)
        s = c2d_real_collide(&a, &b, restitution);
    else if (v == C2D_VERDICT_ACCURATE)
        s = c2d_collide_accurate(&a, &b, restitution);
    else
        s = c2d_collide_slow(&a, &b, restitution);
    if (s == C2D_OK) {
        p->vel_ax[i] = a.vel.x;
        p->vel_ay[i] = a.vel.y;
        p->vel_bx[i] = b.vel.x;
        p->vel_by[i] = b.vel.y;
    }
    return s;
}

static size_t c2d_real_collide_batch(const c2d_real_pairs *p, size_t count, c2d_real restitution, c2d_status *status)
{
    size_t base, done = 0;
    const int e_ok = restitution >= 0 && restitution <= 1;
    const c2d_real e1 = 1 + restitution;
    if (p == NULL) return 0;
    for (base = 0; base < count; base += C2D_BLOCK) {
        c2d_real out[4][C2D_BLOCK];
        c2d_real_bits flags[C2D_BLOCK];
        const size_t width = c2d_block_width(count - base);
        const int kernel_ran = width == (size_t)C2D_BLOCK && e_ok;
        size_t j;
        if (kernel_ran != 0) {
            c2d_batch_kernel(p, base, e1, flags, out);
        } else {
            for (j = 0; j < width; j++) flags[j] = 0; /* all to the scalar call */
        }
        for (j = 0; j < width; j++) {
            size_t i = base + j;
            c2d_verdict v = c2d_fast_verdict(flags[j]);
            c2d_status s;
            if (v == C2D_VERDICT_OK) {
                p->vel_ax[i] = out[0][j];
                p->vel_ay[i] = out[1][j];
                p->vel_bx[i] = out[2][j];
                p->vel_by[i] = out[3][j];
                s = C2D_OK;
            } else if (v == C2D_VERDICT_SEPARATING || v == C2D_VERDICT_RANGE) {
                s = c2d_verdict_status(v);
            } else {
                s = c2d_batch_lane(p, i, kernel_ran, v, restitution);
            }
            if (s == C2D_OK) done++;
            if (status != NULL) status[i] = s;
        }
    }
    return done;
}

#endif /* C2D_REAL_BATCH_H */
