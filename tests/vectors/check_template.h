/* SPDX-License-Identifier: MIT */
/* check_template.h - template: one variant's checks of the shared vector
 * table, the same on the host (test_vectors.c) and on microcontrollers
 * (tests/mcu/main.c).  Included once per translation unit (check_double.c,
 * check_float.c, check_fixed.c) after the variant's type header
 * (tests/harness/type_*.h), which names
 *   c2d_num, c2d_num_body, c2d_num_vec    value, body and vector types
 *   C2D_T_NAME, C2D_T_PUT(x), C2D_T_WITHIN(got, want, tol)
 *                                         "double"..., print one value
 *                                         exactly, |got - want| <= tol
 *   C2D_T_COLLIDE, C2D_T_COLLIDE_NORMAL, C2D_T_TIME_OF_IMPACT
 *   C2D_T_VECTOR, C2D_T_VECTORS, C2D_T_VECTOR_COUNT   the variant's table
 *   C2D_T_BATCH                           only where there is a batch entry
 *                                         point (soa_template.h first)
 * For each entry: the status, each output within the entry's tolerance, and
 * nothing written that may not be (bodies bit-for-bit untouched on any
 * refusal, positions and masses always, t on a refusal); where a batch
 * entry point exists, its lanes against the scalar call.  Each failure is
 * printed through c2d_put.  Freestanding: no C library, no allocation. */

typedef C2D_T_VECTOR c2d_num_vector;

static void c2d_vector_load(const c2d_num_vector *v, c2d_num_body *a, c2d_num_body *b)
{
    a->pos.x = v->pa[0];
    a->pos.y = v->pa[1];
    a->vel.x = v->va[0];
    a->vel.y = v->va[1];
    a->mass = v->ma;
    b->pos.x = v->pb[0];
    b->pos.y = v->pb[1];
    b->vel.x = v->vb[0];
    b->vel.y = v->vb[1];
    b->mass = v->mb;
}

/* Starts a failure line: "FAIL double seed_45_degree_equal_masses: ". */
static void c2d_vector_fail(const c2d_num_vector *v)
{
    c2d_put("FAIL " C2D_T_NAME " ");
    c2d_put(v->name);
    c2d_put(": ");
}

static int c2d_vector_outputs_within(const c2d_num_vector *v, const c2d_num *got, int n)
{
    int i, ok = 1;
    for (i = 0; i < n; i++) {
        if (C2D_T_WITHIN(got[i], v->out[i], v->tol[i])) continue;
        c2d_vector_fail(v);
        c2d_put("out[");
        c2d_put_int(i);
        c2d_put("] = ");
        C2D_T_PUT(got[i]);
        c2d_put(", expected ");
        C2D_T_PUT(v->out[i]);
        c2d_put(" within ");
        C2D_T_PUT(v->tol[i]);
        c2d_put("\n");
        ok = 0;
    }
    return ok;
}

/* Positions and masses are never written; velocities only on C2D_OK. */
static int c2d_vector_writes_allowed(const c2d_num_vector *v, int status, const c2d_num_body *a,
                                     const c2d_num_body *b)
{
    c2d_num_body a0, b0;
    c2d_vector_load(v, &a0, &b0);
    if (status != C2D_OK || v->kind == VEC_TOI) {
        if (c2d_same_bytes(a, &a0, sizeof *a) && c2d_same_bytes(b, &b0, sizeof *b)) return 1;
        c2d_vector_fail(v);
        c2d_put("bodies changed on a call that may not write them\n");
        return 0;
    }
    if (c2d_same_bytes(&a->pos, &a0.pos, sizeof a->pos) && c2d_same_bytes(&b->pos, &b0.pos, sizeof b->pos) &&
        c2d_same_bytes(&a->mass, &a0.mass, sizeof a->mass) && c2d_same_bytes(&b->mass, &b0.mass, sizeof b->mass))
        return 1;
    c2d_vector_fail(v);
    c2d_put("a position or mass was written\n");
    return 0;
}

#ifdef C2D_T_BATCH
/* The batch entry point must give the single call's statuses and bits in
 * every lane.  19 identical pairs: a full block of its vector kernel (8 or
 * 16 pairs) and a partial one, which takes the scalar path. */
#define C2D_LANES 19
static int c2d_vector_batch_agrees(const c2d_num_vector *v)
{
    c2d_num block[C2D_SOA_FIELDS * C2D_LANES];
    c2d_status status[C2D_LANES];
    const c2d_num_soa s = c2d_num_soa_in(block, C2D_LANES, status);
    c2d_batch_check check = {0, 0, 0};
    c2d_num_body a, b;
    size_t done;
    c2d_vector_load(v, &a, &b);
    done = c2d_num_check_copies(&check, &s, C2D_LANES, &a, &b, v->e);
    if (check.differing != 0) {
        c2d_vector_fail(v);
        c2d_put("batch lane ");
        c2d_put_int((long)check.first);
        c2d_put(" differs from the single call\n");
        return 0;
    }
    if (!c2d_batch_check_passed(&check, done)) {
        c2d_vector_fail(v);
        c2d_put("batch returned a wrong count of resolved pairs\n");
        return 0;
    }
    return 1;
}
#endif

static int c2d_vector_run(const c2d_num_vector *v)
{
    c2d_num_body a, b;
    c2d_num got[4];
    c2d_num t = -1; /* never a valid time of impact: shows whether t was written */
    const c2d_num unwritten = -1;
    int status, ok = 1;
    c2d_vector_load(v, &a, &b);
    if (v->kind == VEC_COLLIDE) {
        status = (int)C2D_T_COLLIDE(&a, &b, v->e);
    } else if (v->kind == VEC_COLLIDE_NORMAL) {
        c2d_num_vec n;
        n.x = v->n[0];
        n.y = v->n[1];
        status = (int)C2D_T_COLLIDE_NORMAL(&a, &b, n, v->e);
    } else if (v->kind == VEC_TOI) {
        status = (int)C2D_T_TIME_OF_IMPACT(&a, &b, v->e, &t);
    } else {
        c2d_vector_fail(v);
        c2d_put("unknown kind\n");
        return 0;
    }
    if (status != v->status) {
        c2d_vector_fail(v);
        c2d_put("status ");
        c2d_put(c2d_status_string((c2d_status)status));
        c2d_put(", expected ");
        c2d_put(c2d_status_string((c2d_status)v->status));
        c2d_put("\n");
        ok = 0;
    }
    ok &= c2d_vector_writes_allowed(v, status, &a, &b);
    if (v->kind == VEC_TOI) {
        got[0] = t;
        if (status == C2D_OK) {
            ok &= c2d_vector_outputs_within(v, got, 1);
        } else if (!c2d_same_bytes(&t, &unwritten, sizeof t)) {
            c2d_vector_fail(v);
            c2d_put("t written on a refusal\n");
            ok = 0;
        }
        return ok;
    }
    if (status == C2D_OK && v->status == C2D_OK) {
        got[0] = a.vel.x;
        got[1] = a.vel.y;
        got[2] = b.vel.x;
        got[3] = b.vel.y;
        ok &= c2d_vector_outputs_within(v, got, 4);
    }
#ifdef C2D_T_BATCH
    if (v->kind == VEC_COLLIDE) ok &= c2d_vector_batch_agrees(v);
#endif
    return ok;
}

static void c2d_vector_run_table(c2d_tally *tally)
{
    int i;
    for (i = 0; i < C2D_T_VECTOR_COUNT; i++) (void)c2d_tally_add(tally, c2d_vector_run(&C2D_T_VECTORS[i]));
}
