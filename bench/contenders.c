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

/* The batch entry point sees the case sixteen times, so the pair goes through
 * the block kernel rather than the scalar tail. */
#define PAD 16 /* the library's block: each case runs through the vector kernel */

static c2d_status run_batch(const ref_case *c, double got[4])
{
    double pax[PAD], pay[PAD], pbx[PAD], pby[PAD], vax[PAD], vay[PAD], vbx[PAD], vby[PAD], ma[PAD], mb[PAD];
    c2d_status st[PAD];
    c2d_pairs p = {pax, pay, pbx, pby, vax, vay, vbx, vby, ma, mb};
    int i;
    for (i = 0; i < PAD; i++) {
        pax[i] = c->pa[0], pay[i] = c->pa[1], pbx[i] = c->pb[0], pby[i] = c->pb[1];
        vax[i] = c->va[0], vay[i] = c->va[1], vbx[i] = c->vb[0], vby[i] = c->vb[1];
        ma[i] = c->ma, mb[i] = c->mb;
    }
    (void)c2d_collide_batch(&p, PAD, c->e, st);
    got[0] = vax[0], got[1] = vay[0], got[2] = vbx[0], got[3] = vby[0];
    return st[0];
}

static c2d_status run_batchf(const ref_case *c, double got[4])
{
    float pax[PAD], pay[PAD], pbx[PAD], pby[PAD], vax[PAD], vay[PAD], vbx[PAD], vby[PAD], ma[PAD], mb[PAD];
    c2d_status st[PAD];
    c2d_pairsf p = {pax, pay, pbx, pby, vax, vay, vbx, vby, ma, mb};
    int i;
    for (i = 0; i < PAD; i++) {
        pax[i] = (float)c->pa[0], pay[i] = (float)c->pa[1], pbx[i] = (float)c->pb[0], pby[i] = (float)c->pb[1];
        vax[i] = (float)c->va[0], vay[i] = (float)c->va[1], vbx[i] = (float)c->vb[0], vby[i] = (float)c->vb[1];
        ma[i] = (float)c->ma, mb[i] = (float)c->mb;
    }
    (void)c2d_collide_batchf(&p, PAD, (float)c->e, st);
    got[0] = vax[0], got[1] = vay[0], got[2] = vbx[0], got[3] = vby[0];
    return st[0];
}

c2d_status contender_run(const contender *k, const ref_case *c, double got[4])
{
    c2d_body a, b;
    c2d_status s;
    switch (k->kind) {
    case KIND_FLOAT: return run_float(c, got);
    case KIND_FIXED: return run_fixed(c, got);
    case KIND_BATCH: return run_batch(c, got);
    case KIND_BATCHF: return run_batchf(c, got);
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
