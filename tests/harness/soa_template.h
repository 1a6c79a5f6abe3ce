/* SPDX-License-Identifier: MIT */
/* soa_template.h - template: one floating type's structure-of-arrays
 * storage and the comparison of its batch entry point with scalar calls.
 * Included once per translation unit after the type's header
 * (type_double.h, type_float.h), which names the types c2d_num,
 * c2d_num_body, c2d_num_pairs, c2d_num_soa and the functions C2D_T_COLLIDE,
 * C2D_T_BATCH.  soa_double.c and soa_float.c give these functions their
 * public names (harness.h); the vector checks and the fuzz harness include
 * the template in their own translation units.  Freestanding.
 *
 * WHY
 *   The batch view is ten pointers into ten arrays; written out in each test
 *   it was built nine times, and "batch equals scalar" checked five times,
 *   each a little differently (some compared two of the four velocities, some
 *   not the returned count). */

/* The ten fields of a pair of bodies, in the order of the SoA fields. */
static inline void c2d_num_fields(c2d_num_body *a, c2d_num_body *b, c2d_num *f[C2D_SOA_FIELDS])
{
    f[C2D_SOA_POS_AX] = &a->pos.x, f[C2D_SOA_POS_AY] = &a->pos.y;
    f[C2D_SOA_POS_BX] = &b->pos.x, f[C2D_SOA_POS_BY] = &b->pos.y;
    f[C2D_SOA_VEL_AX] = &a->vel.x, f[C2D_SOA_VEL_AY] = &a->vel.y;
    f[C2D_SOA_VEL_BX] = &b->vel.x, f[C2D_SOA_VEL_BY] = &b->vel.y;
    f[C2D_SOA_MASS_A] = &a->mass, f[C2D_SOA_MASS_B] = &b->mass;
}

static inline c2d_num_soa c2d_num_soa_in(c2d_num *block, size_t capacity, c2d_status *status)
{
    c2d_num_soa s;
    size_t k;
    for (k = 0; k < C2D_SOA_FIELDS; k++) s.field[k] = block + k * capacity;
    s.status = status;
    return s;
}

static inline c2d_num_pairs c2d_num_soa_pairs(const c2d_num_soa *s)
{
    c2d_num_pairs p;
    p.pos_ax = s->field[C2D_SOA_POS_AX], p.pos_ay = s->field[C2D_SOA_POS_AY];
    p.pos_bx = s->field[C2D_SOA_POS_BX], p.pos_by = s->field[C2D_SOA_POS_BY];
    p.vel_ax = s->field[C2D_SOA_VEL_AX], p.vel_ay = s->field[C2D_SOA_VEL_AY];
    p.vel_bx = s->field[C2D_SOA_VEL_BX], p.vel_by = s->field[C2D_SOA_VEL_BY];
    p.mass_a = s->field[C2D_SOA_MASS_A], p.mass_b = s->field[C2D_SOA_MASS_B];
    return p;
}

static inline void c2d_num_soa_get(const c2d_num_soa *s, size_t i, c2d_num_body *a, c2d_num_body *b)
{
    c2d_num *f[C2D_SOA_FIELDS];
    size_t k;
    c2d_num_fields(a, b, f);
    for (k = 0; k < C2D_SOA_FIELDS; k++) *f[k] = s->field[k][i];
}

static inline void c2d_num_soa_put(const c2d_num_soa *s, size_t i, const c2d_num_body *a, const c2d_num_body *b)
{
    c2d_num_body a1 = *a, b1 = *b;
    c2d_num *f[C2D_SOA_FIELDS];
    size_t k;
    c2d_num_fields(&a1, &b1, f);
    for (k = 0; k < C2D_SOA_FIELDS; k++) s->field[k][i] = *f[k];
}

static inline void c2d_num_check_lane(c2d_batch_check *c, const c2d_num_soa *s, size_t i, c2d_status want,
                                      const c2d_num_body *a, const c2d_num_body *b)
{
    c2d_num_body lane_a, lane_b;
    int same;
    c2d_num_soa_get(s, i, &lane_a, &lane_b);
    same = (s->status == NULL || s->status[i] == want) && c2d_same_bytes(&lane_a.vel, &a->vel, sizeof a->vel) &&
           c2d_same_bytes(&lane_b.vel, &b->vel, sizeof b->vel);
    if (want == C2D_OK) c->resolved++;
    if (!same && c->differing++ == 0) c->first = i;
}

static inline size_t c2d_num_check_copies(c2d_batch_check *c, const c2d_num_soa *s, size_t lanes,
                                          const c2d_num_body *a, const c2d_num_body *b, c2d_num e)
{
    const c2d_num_pairs p = c2d_num_soa_pairs(s);
    c2d_num_body sa, sb; /* the scalar call's pair */
    c2d_status want;
    size_t i, done;
    for (i = 0; i < lanes; i++) c2d_num_soa_put(s, i, a, b);
    c2d_num_soa_get(s, 0, &sa, &sb);
    done = C2D_T_BATCH(&p, lanes, e, s->status);
    want = C2D_T_COLLIDE(&sa, &sb, e);
    for (i = 0; i < lanes; i++) c2d_num_check_lane(c, s, i, want, &sa, &sb);
    return done;
}
