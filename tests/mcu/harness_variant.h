/* One variant's checks, included by harness.c once per variant compiled in
 * (the same template technique as lib/collide2d.c).  The includer defines:
 *   R, VECTOR, BODY, VEC2      element, table-entry, body and vector types
 *   TABLE, COUNT, NAME         the shared table, its length, "double"...
 *   SFX(name)                  per-variant names for the static functions
 *   PUT_R(x)                   print one R exactly
 *   WITHIN(got, want, tol)     |got - want| <= tol (false for NaN)
 *   COLLIDE, COLLIDE_NORMAL, TOI   the functions under test
 *   PAIRS, BATCH               (optional) the batch entry point
 * and undefines them all at its end. */

static void SFX(load)(const VECTOR *v, BODY *a, BODY *b)
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

static int SFX(outputs_within)(const VECTOR *v, const R *got, int n)
{
    int i, ok = 1;
    for (i = 0; i < n; i++) {
        if (WITHIN(got[i], v->out[i], v->tol[i])) continue;
        c2d_fail_begin(NAME, v->name);
        c2d_put("out[");
        c2d_put_int(i);
        c2d_put("] = ");
        PUT_R(got[i]);
        c2d_put(", expected ");
        PUT_R(v->out[i]);
        c2d_put(" within ");
        PUT_R(v->tol[i]);
        c2d_put("\n");
        ok = 0;
    }
    return ok;
}

/* Positions and masses are never written; velocities only on C2D_OK. */
static int SFX(writes_allowed)(const VECTOR *v, int status, const BODY *a, const BODY *b)
{
    BODY a0, b0;
    SFX(load)(v, &a0, &b0);
    if (status != C2D_OK || v->kind == VEC_TOI) {
        if (c2d_same_bytes(a, &a0, sizeof *a) && c2d_same_bytes(b, &b0, sizeof *b)) return 1;
        c2d_fail_begin(NAME, v->name);
        c2d_put("bodies changed on a call that may not write them\n");
        return 0;
    }
    if (c2d_same_bytes(&a->pos, &a0.pos, sizeof a->pos) && c2d_same_bytes(&b->pos, &b0.pos, sizeof b->pos) &&
        c2d_same_bytes(&a->mass, &a0.mass, sizeof a->mass) && c2d_same_bytes(&b->mass, &b0.mass, sizeof b->mass))
        return 1;
    c2d_fail_begin(NAME, v->name);
    c2d_put("a position or mass was written\n");
    return 0;
}

#ifdef BATCH
/* The batch entry point must give c2d_collide's statuses and bits in every
 * lane.  19 identical pairs: a full block of its vector kernel (8 or 16
 * pairs) and a partial one, which takes the scalar path. */
#define C2D_LANES 19
static int SFX(batch_agrees)(const VECTOR *v, int status, const BODY *a, const BODY *b)
{
    R pax[C2D_LANES], pay[C2D_LANES], pbx[C2D_LANES], pby[C2D_LANES], vax[C2D_LANES], vay[C2D_LANES],
        vbx[C2D_LANES], vby[C2D_LANES], ma[C2D_LANES], mb[C2D_LANES];
    c2d_status st[C2D_LANES];
    PAIRS p;
    size_t i, done;
    for (i = 0; i < C2D_LANES; i++) {
        pax[i] = v->pa[0];
        pay[i] = v->pa[1];
        pbx[i] = v->pb[0];
        pby[i] = v->pb[1];
        vax[i] = v->va[0];
        vay[i] = v->va[1];
        vbx[i] = v->vb[0];
        vby[i] = v->vb[1];
        ma[i] = v->ma;
        mb[i] = v->mb;
    }
    p.pos_ax = pax;
    p.pos_ay = pay;
    p.pos_bx = pbx;
    p.pos_by = pby;
    p.vel_ax = vax;
    p.vel_ay = vay;
    p.vel_bx = vbx;
    p.vel_by = vby;
    p.mass_a = ma;
    p.mass_b = mb;
    done = BATCH(&p, C2D_LANES, v->e, st);
    for (i = 0; i < C2D_LANES; i++) {
        if ((int)st[i] == status && c2d_same_bytes(&vax[i], &a->vel.x, sizeof vax[i]) &&
            c2d_same_bytes(&vay[i], &a->vel.y, sizeof vay[i]) && c2d_same_bytes(&vbx[i], &b->vel.x, sizeof vbx[i]) &&
            c2d_same_bytes(&vby[i], &b->vel.y, sizeof vby[i]))
            continue;
        c2d_fail_begin(NAME, v->name);
        c2d_put("batch lane ");
        c2d_put_int((long)i);
        c2d_put(" differs from the single call\n");
        return 0;
    }
    if (done != (status == C2D_OK ? (size_t)C2D_LANES : 0u)) {
        c2d_fail_begin(NAME, v->name);
        c2d_put("batch returned a wrong count of resolved pairs\n");
        return 0;
    }
    return 1;
}
#undef C2D_LANES
#endif

static int SFX(run)(const VECTOR *v)
{
    BODY a, b;
    R got[4];
    R t = -1; /* never a valid time of impact: shows whether t was written */
    const R unwritten = -1;
    int status, ok = 1;
    SFX(load)(v, &a, &b);
    if (v->kind == VEC_COLLIDE) {
        status = (int)COLLIDE(&a, &b, v->e);
    } else if (v->kind == VEC_COLLIDE_NORMAL) {
        VEC2 n;
        n.x = v->n[0];
        n.y = v->n[1];
        status = (int)COLLIDE_NORMAL(&a, &b, n, v->e);
    } else if (v->kind == VEC_TOI) {
        status = (int)TOI(&a, &b, v->e, &t);
    } else {
        c2d_fail_begin(NAME, v->name);
        c2d_put("unknown kind\n");
        return 0;
    }
    if (status != v->status) {
        c2d_fail_begin(NAME, v->name);
        c2d_put("status ");
        c2d_put(c2d_status_string((c2d_status)status));
        c2d_put(", expected ");
        c2d_put(c2d_status_string((c2d_status)v->status));
        c2d_put("\n");
        ok = 0;
    }
    ok &= SFX(writes_allowed)(v, status, &a, &b);
    if (v->kind == VEC_TOI) {
        got[0] = t;
        if (status == C2D_OK) {
            ok &= SFX(outputs_within)(v, got, 1);
        } else if (!c2d_same_bytes(&t, &unwritten, sizeof t)) {
            c2d_fail_begin(NAME, v->name);
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
        ok &= SFX(outputs_within)(v, got, 4);
    }
#ifdef BATCH
    if (v->kind == VEC_COLLIDE) ok &= SFX(batch_agrees)(v, status, &a, &b);
#endif
    return ok;
}

static void SFX(run_table)(c2d_tally *tally)
{
    int i;
    for (i = 0; i < COUNT; i++) {
        if (SFX(run)(&TABLE[i])) {
            tally->passed++;
        } else {
            tally->failed++;
        }
    }
}

/* The parameters are this instantiation's only: clear them for the next. */
#undef R
#undef VECTOR
#undef BODY
#undef VEC2
#undef TABLE
#undef COUNT
#undef NAME
#undef SFX
#undef PUT_R
#undef WITHIN
#undef COLLIDE
#undef COLLIDE_NORMAL
#undef TOI
#undef PAIRS
#undef BATCH
