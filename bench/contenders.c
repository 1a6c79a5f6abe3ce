/* SPDX-License-Identifier: MIT */
#include "bench.h"

#include <math.h>
#include <string.h>

#include "approaches.h"
#include "box2d_contender.h"

const contender bench_contenders[] = {
    {"c2d_collide (double)", "c2d_collide", KIND_DOUBLE, c2d_collide, 0, 1},
    {"c2d_collide_normal (double)", "c2d_collide_normal", KIND_NORMAL, NULL, 0, 1},
    {"c2d_collidef (float)", "c2d_collidef", KIND_FLOAT, NULL, 0, 1},
    {"c2d_collidex (Q16.16)", "c2d_collidex", KIND_FIXED, NULL, 0, 0},
    {"c2d_collide_batch (double)", "c2d_collide_batch", KIND_BATCH, NULL, 0, 1},
    {"c2d_collide_batchf (float)", "c2d_collide_batchf", KIND_BATCHF, NULL, 0, 1},
    {"seed transcription (equal masses)", "seed_equal", KIND_DOUBLE, bench_seed_equal, 1, 1},
    {"seed transcription (1-D formula, any masses)", "seed_masses", KIND_DOUBLE, bench_seed_masses, 0, 1},
    {"seed summary formulas as printed", "seed_summary", KIND_DOUBLE, bench_seed_summary, 1, 1},
    {"trigonometric (atan2, rotate)", "trig", KIND_DOUBLE, bench_trig, 0, 1},
    {"Box2D 2.4.1 solver (one step)", "box2d", KIND_BOX2D, bench_box2d, 0, 0},
};
const int bench_ncontenders = (int)(sizeof bench_contenders / sizeof bench_contenders[0]);

static c2d_fixed to_fixed(double v)
{
    if (isinf(v)) return C2D_FIXED_INFINITE_MASS;
    return (c2d_fixed)lrint(v * 65536.0);
}

static void to_bodyx(const double p[2], const double v[2], double m, c2d_bodyx *b)
{
    b->pos.x = to_fixed(p[0]);
    b->pos.y = to_fixed(p[1]);
    b->vel.x = to_fixed(v[0]);
    b->vel.y = to_fixed(v[1]);
    b->mass = to_fixed(m);
}

static c2d_status run_fixed(const ref_case *c, double got[4])
{
    c2d_bodyx a, b;
    c2d_status s;
    to_bodyx(c->pa, c->va, c->ma, &a);
    to_bodyx(c->pb, c->vb, c->mb, &b);
    s = c2d_collidex(&a, &b, to_fixed(c->e));
    got[0] = a.vel.x / 65536.0;
    got[1] = a.vel.y / 65536.0;
    got[2] = b.vel.x / 65536.0;
    got[3] = b.vel.y / 65536.0;
    return s;
}

static c2d_status run_float(const ref_case *c, double got[4])
{
    c2d_bodyf a, b;
    c2d_status s;
    case_to_bodiesf(c, &a, &b);
    s = c2d_collidef(&a, &b, (float)c->e);
    got[0] = a.vel.x;
    got[1] = a.vel.y;
    got[2] = b.vel.x;
    got[3] = b.vel.y;
    return s;
}

/* A batch contender sees the case sixteen times (the library's block), so
 * the pair goes through the vector kernel rather than the scalar tail.
 * Lane 0's answer is the contender's; every lane is also checked against
 * the scalar call on the same pair (tests/harness). */
#define PAD 16

typedef struct batch_run {
    c2d_batch_check check;
    size_t done; /* the batch call's return value */
    c2d_status status;
    double got[4];
} batch_run;

static void run_batch(const ref_case *c, batch_run *o)
{
    double block[C2D_SOA_FIELDS * PAD];
    c2d_status st[PAD];
    const c2d_soa s = c2d_soa_in(block, PAD, st);
    c2d_body a, b;
    case_to_bodies(c, &a, &b);
    o->done = c2d_batch_check_copies(&o->check, &s, PAD, &a, &b, c->e);
    c2d_soa_get(&s, 0, &a, &b);
    o->got[0] = a.vel.x, o->got[1] = a.vel.y, o->got[2] = b.vel.x, o->got[3] = b.vel.y, o->status = st[0];
}

static void run_batchf(const ref_case *c, batch_run *o)
{
    float block[C2D_SOA_FIELDS * PAD];
    c2d_status st[PAD];
    const c2d_soaf s = c2d_soa_inf(block, PAD, st);
    c2d_bodyf a, b;
    case_to_bodiesf(c, &a, &b);
    o->done = c2d_batch_check_copiesf(&o->check, &s, PAD, &a, &b, (float)c->e);
    c2d_soa_getf(&s, 0, &a, &b);
    o->got[0] = a.vel.x, o->got[1] = a.vel.y, o->got[2] = b.vel.x, o->got[3] = b.vel.y, o->status = st[0];
}

/* k is a batch contender: run it once. */
static void run_batch_kind(const contender *k, const ref_case *c, batch_run *o)
{
    memset(o, 0, sizeof *o);
    if (k->kind == KIND_BATCH) {
        run_batch(c, o);
    } else {
        run_batchf(c, o);
    }
}

int contender_batch_agrees(const contender *k, const ref_case *c)
{
    batch_run o;
    if (k->kind != KIND_BATCH && k->kind != KIND_BATCHF) return 1;
    run_batch_kind(k, c, &o);
    return c2d_batch_check_passed(&o.check, o.done);
}

c2d_status contender_run(const contender *k, const ref_case *c, double got[4])
{
    c2d_body a, b;
    c2d_status s;
    switch (k->kind) {
    case KIND_FLOAT: return run_float(c, got);
    case KIND_FIXED: return run_fixed(c, got);
    case KIND_BATCH:
    case KIND_BATCHF: {
        batch_run o;
        run_batch_kind(k, c, &o);
        memcpy(got, o.got, sizeof o.got);
        return o.status;
    }
    default: break;
    }
    case_to_bodies(c, &a, &b);
    if (k->kind == KIND_NORMAL) {
        c2d_vec2 n;
        n.x = c->n[0];
        n.y = c->n[1];
        s = c2d_collide_normal(&a, &b, n, c->e);
    } else {
        s = k->fn(&a, &b, c->e);
    }
    got[0] = a.vel.x, got[1] = a.vel.y, got[2] = b.vel.x, got[3] = b.vel.y;
    return s;
}
