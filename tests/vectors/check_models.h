/* SPDX-License-Identifier: MIT */
/* check_models.h - template: one variant's checks of the models' vector
 * tables (vectors.h: c2d_collide_rough and _normal, c2d_time_of_impact_accel),
 * the same on the host (test_vectors.c) and on microcontrollers
 * (tests/mcu/main.c).  Included after check_template.h by check_double.c and
 * check_float.c, with the variant's type header (tests/harness/type_*.h)
 * naming the model's types, entry points and tables (C2D_T_DISK ...
 * C2D_T_ACCEL_VECTOR_COUNT).
 * Rough contact, for each entry: the status; nothing written unless C2D_OK
 * (bodies bit for bit as given); positions, masses, radii and inertias never
 * written; on C2D_OK both velocities and spins within the entry's
 * tolerances.  Time of impact: the status; t not written unless C2D_OK;
 * on C2D_OK 0 <= t <= horizon and t within its tolerance.  Each failure is
 * printed through c2d_put.  Freestanding: no C library, no allocation. */

typedef C2D_T_ROUGH_VECTOR c2d_num_rough_vector;
typedef C2D_T_ACCEL_VECTOR c2d_num_accel_vector;
typedef C2D_T_DISK c2d_num_disk;

/* Starts a failure line: "FAIL double rough rolling_ball_hits_resting_ball: ". */
static void c2d_model_fail(const char *model, const char *name)
{
    c2d_put("FAIL " C2D_T_NAME " ");
    c2d_put(model);
    c2d_put(" ");
    c2d_put(name);
    c2d_put(": ");
}

static int c2d_model_status_is(const char *model, const char *name, int status, int expected)
{
    if (status == expected) return 1;
    c2d_model_fail(model, name);
    c2d_put("status ");
    c2d_put(c2d_status_string((c2d_status)status));
    c2d_put(", expected ");
    c2d_put(c2d_status_string((c2d_status)expected));
    c2d_put("\n");
    return 0;
}

static int c2d_model_within(const char *model, const char *name, const char *what, c2d_num got, c2d_num want,
                            c2d_num tol)
{
    if (C2D_T_WITHIN(got, want, tol)) return 1;
    c2d_model_fail(model, name);
    c2d_put(what);
    c2d_put(" = ");
    C2D_T_PUT(got);
    c2d_put(", expected ");
    C2D_T_PUT(want);
    c2d_put(" within ");
    C2D_T_PUT(tol);
    c2d_put("\n");
    return 0;
}

/* {pos.x, pos.y, vel.x, vel.y, spin, mass, radius, inertia} */
static void c2d_disk_load(const c2d_num *x, c2d_num_disk *d)
{
    d->pos.x = x[0];
    d->pos.y = x[1];
    d->vel.x = x[2];
    d->vel.y = x[3];
    d->spin = x[4];
    d->mass = x[5];
    d->radius = x[6];
    d->inertia = x[7];
}

/* What may not be written is not: everything unless C2D_OK, otherwise
 * everything but the velocities and spins. */
static int c2d_rough_writes_allowed(const c2d_num_rough_vector *v, int status, const c2d_num_disk *a,
                                    const c2d_num_disk *b)
{
    c2d_num_disk a0, b0;
    c2d_disk_load(v->a, &a0);
    c2d_disk_load(v->b, &b0);
    if (status != C2D_OK) {
        if (c2d_same_bytes(a, &a0, sizeof *a) && c2d_same_bytes(b, &b0, sizeof *b)) return 1;
        c2d_model_fail("rough", v->name);
        c2d_put("disks changed on a refusal\n");
        return 0;
    }
    a0.vel = a->vel, a0.spin = a->spin;
    b0.vel = b->vel, b0.spin = b->spin;
    if (c2d_same_bytes(a, &a0, sizeof *a) && c2d_same_bytes(b, &b0, sizeof *b)) return 1;
    c2d_model_fail("rough", v->name);
    c2d_put("a position, mass, radius or inertia was written\n");
    return 0;
}

static int c2d_rough_run(const c2d_num_rough_vector *v)
{
    static const char *const what[6] = {"a.vel.x", "a.vel.y", "b.vel.x", "b.vel.y", "a.spin", "b.spin"};
    c2d_num_disk a, b;
    C2D_T_SURFACE s;
    c2d_num got[6];
    int status, ok, i;
    c2d_disk_load(v->a, &a);
    c2d_disk_load(v->b, &b);
    s.restitution = v->s[0];
    s.friction = v->s[1];
    s.tangential_restitution = v->s[2];
    if (v->normal_given) {
        c2d_num_vec n;
        n.x = v->n[0];
        n.y = v->n[1];
        status = (int)C2D_T_COLLIDE_ROUGH_NORMAL(&a, &b, n, s);
    } else {
        status = (int)C2D_T_COLLIDE_ROUGH(&a, &b, s);
    }
    ok = c2d_model_status_is("rough", v->name, status, v->status);
    ok &= c2d_rough_writes_allowed(v, status, &a, &b);
    if (status != C2D_OK || v->status != C2D_OK) return ok;
    got[0] = a.vel.x, got[1] = a.vel.y, got[2] = b.vel.x, got[3] = b.vel.y, got[4] = a.spin, got[5] = b.spin;
    for (i = 0; i < 6; i++) ok &= c2d_model_within("rough", v->name, what[i], got[i], v->out[i], v->tol[i]);
    return ok;
}

static int c2d_accel_run(const c2d_num_accel_vector *v)
{
    const c2d_num unwritten = -1; /* never a valid time of impact */
    c2d_num_body a, b;
    c2d_num_vec aa, ab;
    c2d_num t = unwritten;
    int status, ok;
    a.pos.x = v->pa[0], a.pos.y = v->pa[1], a.vel.x = v->va[0], a.vel.y = v->va[1], a.mass = 1;
    b.pos.x = v->pb[0], b.pos.y = v->pb[1], b.vel.x = v->vb[0], b.vel.y = v->vb[1], b.mass = 1;
    aa.x = v->aa[0], aa.y = v->aa[1];
    ab.x = v->ab[0], ab.y = v->ab[1];
    status = (int)C2D_T_TIME_OF_IMPACT_ACCEL(&a, aa, &b, ab, v->radius_sum, v->horizon, &t);
    ok = c2d_model_status_is("accel", v->name, status, v->status);
    if (status != C2D_OK) {
        if (c2d_same_bytes(&t, &unwritten, sizeof t)) return ok;
        c2d_model_fail("accel", v->name);
        c2d_put("t written on a refusal\n");
        return 0;
    }
    if (!(t >= 0 && t <= v->horizon)) {
        c2d_model_fail("accel", v->name);
        c2d_put("t = ");
        C2D_T_PUT(t);
        c2d_put(" outside [0, horizon]\n");
        ok = 0;
    }
    if (v->status == C2D_OK) ok &= c2d_model_within("accel", v->name, "t", t, v->t, v->tol);
    return ok;
}

static void c2d_rough_run_table(c2d_tally *tally)
{
    int i;
    for (i = 0; i < C2D_T_ROUGH_VECTOR_COUNT; i++) (void)c2d_tally_add(tally, c2d_rough_run(&C2D_T_ROUGH_VECTORS[i]));
}

static void c2d_accel_run_table(c2d_tally *tally)
{
    int i;
    for (i = 0; i < C2D_T_ACCEL_VECTOR_COUNT; i++) (void)c2d_tally_add(tally, c2d_accel_run(&C2D_T_ACCEL_VECTORS[i]));
}
