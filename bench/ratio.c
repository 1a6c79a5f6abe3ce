/* SPDX-License-Identifier: MIT */
/* Interleaved ratios (the speed goals, the axis-aligned branch, the rough
 * model and the library before and after): each comparison is a group of
 * passes over the same in-cache pairs, timed one after another in every
 * round (the order rotated from round to round, inputs restored untimed
 * before each pass); a ratio is the median over the rounds of the per-round
 * ratio of two passes, and its spread the quartiles of that ratio.  Under
 * callgrind (--callgrind) each pass runs once between client requests
 * instead, named "<group>/<pass>".
 *
 * Compiled with C2D_INLINE, so c2d_collide_inline and its twins are the
 * header's inline front ends, expanded into the timed loops.
 *
 * For looking into it (bench --ratios-only ROUNDS prints the main figures):
 * BENCH_ONLY=<prefix> registers only the groups whose id starts so;
 * BENCH_CANARY=1 prints the canary's distribution and the unsteady medians
 * to stderr. */
#define _POSIX_C_SOURCE 199309L
#define C2D_INLINE
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "callgrind.h"

#include "approaches.h"
#include "old.h"

volatile double ratio_sink;

/* ------------------------------------------------------------ the data */

/* What a pass writes, hence what is restored (untimed) before it: always
 * every input the pass reads, so each pass starts with its data in cache. */
typedef enum writes { W_BODY, W_BODYF, W_SOA, W_SOAF, W_DISK } writes;

typedef struct rset {
    int n;
    double e;                      /* restitution of every collision call */
    c2d_body *a0, *b0, *a, *b;     /* pristine and working copies */
    c2d_bodyf *af0, *bf0, *af, *bf;
    c2d_vec2 *nrm;                 /* the normal for the _normal calls */
    c2d_vec2f *nrmf;
    double *rad;                   /* radius sums (time of impact) */
    float *radf;
    c2d_soa soa;
    c2d_soaf soaf;
    c2d_pairs pairs;
    c2d_pairsf pairsf;
    double *v0[C2D_SOA_FIELDS]; /* pristine copies of every field */
    float *vf0[C2D_SOA_FIELDS];
    c2d_status *st;
    c2d_disk *da0, *db0, *da, *db; /* rough sets only */
    c2d_diskf *dfa0, *dfb0, *dfa, *dfb;
    c2d_surface *surf;
    c2d_surfacef *surff;
} rset;

#define ALLOC(p, n) ((p) = calloc((size_t)(n), sizeof *(p)))

/* cd: the double cases; cf: what the float calls get (NULL: cd rounded);
 * rad, radf: radius sums or NULL (radf NULL: rad rounded). */
static rset *rset_make(const ref_case *cd, const ref_case *cf, const double *rad, const double *radf, int n, double e)
{
    rset *s = calloc(1, sizeof *s);
    int i, k;
    s->n = n;
    s->e = e;
    ALLOC(s->a0, n), ALLOC(s->b0, n), ALLOC(s->a, n), ALLOC(s->b, n);
    ALLOC(s->af0, n), ALLOC(s->bf0, n), ALLOC(s->af, n), ALLOC(s->bf, n);
    ALLOC(s->nrm, n), ALLOC(s->nrmf, n), ALLOC(s->rad, n), ALLOC(s->radf, n), ALLOC(s->st, n);
    for (k = 0; k < C2D_SOA_FIELDS; k++) ALLOC(s->soa.field[k], n), ALLOC(s->soaf.field[k], n);
    for (k = 0; k < C2D_SOA_FIELDS; k++) ALLOC(s->v0[k], n), ALLOC(s->vf0[k], n);
    s->soa.status = s->soaf.status = s->st;
    s->pairs = c2d_soa_pairs(&s->soa);
    s->pairsf = c2d_soa_pairsf(&s->soaf);
    for (i = 0; i < n; i++) {
        const ref_case *c = &cd[i], *f = cf ? &cf[i] : &cd[i];
        case_to_bodies(c, &s->a0[i], &s->b0[i]);
        case_to_bodiesf(f, &s->af0[i], &s->bf0[i]);
        s->nrm[i].x = c->has_normal ? c->n[0] : c->pb[0] - c->pa[0];
        s->nrm[i].y = c->has_normal ? c->n[1] : c->pb[1] - c->pa[1];
        s->nrmf[i].x = f->has_normal ? (float)f->n[0] : s->bf0[i].pos.x - s->af0[i].pos.x;
        s->nrmf[i].y = f->has_normal ? (float)f->n[1] : s->bf0[i].pos.y - s->af0[i].pos.y;
        s->rad[i] = rad ? rad[i] : 1;
        s->radf[i] = (float)(radf ? radf[i] : s->rad[i]);
        c2d_soa_put(&s->soa, (size_t)i, &s->a0[i], &s->b0[i]);
        c2d_soa_putf(&s->soaf, (size_t)i, &s->af0[i], &s->bf0[i]);
        for (k = 0; k < C2D_SOA_FIELDS; k++) {
            s->v0[k][i] = s->soa.field[k][i];
            s->vf0[k][i] = s->soaf.field[k][i];
        }
    }
    memcpy(s->a, s->a0, (size_t)n * sizeof *s->a), memcpy(s->b, s->b0, (size_t)n * sizeof *s->b);
    memcpy(s->af, s->af0, (size_t)n * sizeof *s->af), memcpy(s->bf, s->bf0, (size_t)n * sizeof *s->bf);
    return s;
}

/* A rough set: the disks, their surfaces, and the frictionless bodies of
 * the same pairs (normal = b.pos - a.pos for every call). */
static rset *rset_rough(const ref_rough_case *rc, int n)
{
    ref_case *c = calloc((size_t)n, sizeof *c);
    rset *s;
    int i;
    for (i = 0; i < n; i++) {
        int k;
        for (k = 0; k < 2; k++) {
            c[i].pa[k] = rc[i].a.pos[k], c[i].pb[k] = rc[i].b.pos[k];
            c[i].va[k] = rc[i].a.vel[k], c[i].vb[k] = rc[i].b.vel[k];
        }
        c[i].ma = rc[i].a.mass, c[i].mb = rc[i].b.mass, c[i].e = 1, c[i].has_normal = 0;
    }
    s = rset_make(c, NULL, NULL, NULL, n, 1.0);
    free(c);
    ALLOC(s->da0, n), ALLOC(s->db0, n), ALLOC(s->da, n), ALLOC(s->db, n);
    ALLOC(s->dfa0, n), ALLOC(s->dfb0, n), ALLOC(s->dfa, n), ALLOC(s->dfb, n);
    ALLOC(s->surf, n), ALLOC(s->surff, n);
    for (i = 0; i < n; i++) {
        rough_disk_of(&s->da0[i], &rc[i].a), rough_disk_of(&s->db0[i], &rc[i].b);
        rough_diskf_of(&s->dfa0[i], &rc[i].a), rough_diskf_of(&s->dfb0[i], &rc[i].b);
        s->surf[i] = rough_surface_of(&rc[i]);
        s->surff[i].restitution = (float)rc[i].e, s->surff[i].friction = (float)rc[i].mu;
        s->surff[i].tangential_restitution = (float)rc[i].beta;
    }
    return s;
}

static void rset_free(rset *s)
{
    int k;
    if (s == NULL) return;
    free(s->a0), free(s->b0), free(s->a), free(s->b), free(s->af0), free(s->bf0), free(s->af), free(s->bf);
    free(s->nrm), free(s->nrmf), free(s->rad), free(s->radf), free(s->st);
    for (k = 0; k < C2D_SOA_FIELDS; k++) free(s->soa.field[k]), free(s->soaf.field[k]);
    for (k = 0; k < C2D_SOA_FIELDS; k++) free(s->v0[k]), free(s->vf0[k]);
    free(s->da0), free(s->db0), free(s->da), free(s->db), free(s->dfa0), free(s->dfb0), free(s->dfa), free(s->dfb);
    free(s->surf), free(s->surff);
    free(s);
}

static void restore(rset *s, writes w)
{
    const size_t n = (size_t)s->n;
    int k;
    switch (w) {
    case W_BODY: memcpy(s->a, s->a0, n * sizeof *s->a), memcpy(s->b, s->b0, n * sizeof *s->b); break;
    case W_BODYF: memcpy(s->af, s->af0, n * sizeof *s->af), memcpy(s->bf, s->bf0, n * sizeof *s->bf); break;
    case W_SOA: /* every field, as the scalar passes' bodies: all inputs in cache alike */
        for (k = 0; k < C2D_SOA_FIELDS; k++) memcpy(s->soa.field[k], s->v0[k], n * sizeof(double));
        break;
    case W_SOAF:
        for (k = 0; k < C2D_SOA_FIELDS; k++) memcpy(s->soaf.field[k], s->vf0[k], n * sizeof(float));
        break;
    case W_DISK:
        memcpy(s->da, s->da0, n * sizeof *s->da), memcpy(s->db, s->db0, n * sizeof *s->db);
        memcpy(s->dfa, s->dfa0, n * sizeof *s->dfa), memcpy(s->dfb, s->dfb0, n * sizeof *s->dfb);
        memcpy(s->a, s->a0, n * sizeof *s->a), memcpy(s->b, s->b0, n * sizeof *s->b);
        break;
    default: break;
    }
}

/* ------------------------------------------------------------ the passes */

/* The seed's method as a user's own inline code (the same text as
 * bench_seed_equal, expanded into the loop like the C2D_INLINE forms). */
#define SEED_INLINE(T, SQRT, a, b, NX, NY)                                                                   \
    do {                                                                                                   \
        const T nx_ = (NX), ny_ = (NY);                                                                    \
        const T len_ = SQRT(nx_ * nx_ + ny_ * ny_);                                                        \
        const T unx_ = nx_ / len_, uny_ = ny_ / len_, utx_ = -ny_ / len_, uty_ = nx_ / len_;               \
        const T v1n_ = unx_ * (a)->vel.x + uny_ * (a)->vel.y, v1t_ = utx_ * (a)->vel.x + uty_ * (a)->vel.y; \
        const T v2n_ = unx_ * (b)->vel.x + uny_ * (b)->vel.y, v2t_ = utx_ * (b)->vel.x + uty_ * (b)->vel.y; \
        (a)->vel.x = v2n_ * unx_ + v1t_ * utx_;                                                            \
        (a)->vel.y = v2n_ * uny_ + v1t_ * uty_;                                                            \
        (b)->vel.x = v1n_ * unx_ + v2t_ * utx_;                                                            \
        (b)->vel.y = v1n_ * uny_ + v2t_ * uty_;                                                            \
    } while (0)

#define PASS(name, call)                                     \
    static void name(rset *s)                                \
    {                                                        \
        unsigned acc = 0;                                    \
        int i;                                               \
        for (i = 0; i < s->n; i++) acc += (unsigned)(call);  \
        ratio_sink += acc;                                   \
    }

PASS(p_noop, bench_noop(&s->a[i], &s->b[i], s->e))
PASS(p_collide, c2d_collide(&s->a[i], &s->b[i], s->e))
PASS(p_collide_old, old_c2d_collide(&s->a[i], &s->b[i], s->e))
PASS(p_collide_inl, c2d_collide_inline(&s->a[i], &s->b[i], s->e))
PASS(p_seed, bench_seed_equal(&s->a[i], &s->b[i], s->e))
PASS(p_collidef, c2d_collidef(&s->af[i], &s->bf[i], (float)s->e))
PASS(p_collidef_old, old_c2d_collidef(&s->af[i], &s->bf[i], (float)s->e))
PASS(p_collidef_inl, c2d_collidef_inline(&s->af[i], &s->bf[i], (float)s->e))
PASS(p_seedf, bench_seed_equalf(&s->af[i], &s->bf[i], (float)s->e))
PASS(p_normal, c2d_collide_normal(&s->a[i], &s->b[i], s->nrm[i], s->e))
PASS(p_normal_old, old_c2d_collide_normal(&s->a[i], &s->b[i], s->nrm[i], s->e))
PASS(p_normal_inl, c2d_collide_normal_inline(&s->a[i], &s->b[i], s->nrm[i], s->e))
PASS(p_seed_normal, bench_seed_equal_normal(&s->a[i], &s->b[i], s->nrm[i].x, s->nrm[i].y, s->e))
PASS(p_seed_normal_v, bench_seed_equal_normal_v(&s->a[i], &s->b[i], s->nrm[i], s->e))
PASS(p_normalf, c2d_collide_normalf(&s->af[i], &s->bf[i], s->nrmf[i], (float)s->e))
PASS(p_normalf_old, old_c2d_collide_normalf(&s->af[i], &s->bf[i], s->nrmf[i], (float)s->e))
PASS(p_normalf_inl, c2d_collide_normalf_inline(&s->af[i], &s->bf[i], s->nrmf[i], (float)s->e))
PASS(p_seed_normalf, bench_seed_equal_normalf(&s->af[i], &s->bf[i], s->nrmf[i].x, s->nrmf[i].y, (float)s->e))
PASS(p_rough, c2d_collide_rough(&s->da[i], &s->db[i], s->surf[i]))
PASS(p_roughf, c2d_collide_roughf(&s->dfa[i], &s->dfb[i], s->surff[i]))
PASS(p_walton, bench_walton(&s->da[i], &s->db[i], s->surf[i]))

PASS(p_bare, bench_bare(&s->a[i], &s->b[i], s->e))
PASS(p_baref, bench_baref(&s->af[i], &s->bf[i], (float)s->e))

/* The bare formula expanded into the loop (approaches.h). */
static void p_bare_inl(rset *s)
{
    unsigned acc = 0;
    int i;
    for (i = 0; i < s->n; i++) {
        c2d_status st;
        BENCH_BARE(double, sqrt, &s->a[i], &s->b[i], s->e, st);
        acc += (unsigned)st;
    }
    ratio_sink += acc;
}

static void p_baref_inl(rset *s)
{
    const float e = (float)s->e;
    unsigned acc = 0;
    int i;
    for (i = 0; i < s->n; i++) {
        c2d_status st;
        BENCH_BARE(float, sqrtf, &s->af[i], &s->bf[i], e, st);
        acc += (unsigned)st;
    }
    ratio_sink += acc;
}

/* The bare formula as a plain loop over the batch's own arrays (the same
 * fields c2d_collide_batch reads and writes, the status stored too). */
#define BARE_SOA_LOOP(T, SQRT, F, ST, N, E)                                                                     \
    do {                                                                                                         \
        int i_;                                                                                                  \
        for (i_ = 0; i_ < (N); i_++) {                                                                           \
            const T nx_ = F[C2D_SOA_POS_BX][i_] - F[C2D_SOA_POS_AX][i_];                                         \
            const T ny_ = F[C2D_SOA_POS_BY][i_] - F[C2D_SOA_POS_AY][i_];                                         \
            const T len_ = SQRT(nx_ * nx_ + ny_ * ny_), ux_ = nx_ / len_, uy_ = ny_ / len_;                      \
            const T g_ = (F[C2D_SOA_VEL_BX][i_] - F[C2D_SOA_VEL_AX][i_]) * ux_ +                                 \
                         (F[C2D_SOA_VEL_BY][i_] - F[C2D_SOA_VEL_AY][i_]) * uy_;                                  \
            if (g_ < 0) {                                                                                        \
                const T ia_ = 1 / F[C2D_SOA_MASS_A][i_], ib_ = 1 / F[C2D_SOA_MASS_B][i_];                        \
                const T j_ = -(1 + (E)) * g_ / (ia_ + ib_);                                                      \
                F[C2D_SOA_VEL_AX][i_] -= j_ * ia_ * ux_, F[C2D_SOA_VEL_AY][i_] -= j_ * ia_ * uy_;                \
                F[C2D_SOA_VEL_BX][i_] += j_ * ib_ * ux_, F[C2D_SOA_VEL_BY][i_] += j_ * ib_ * uy_;                \
                ST[i_] = C2D_OK;                                                                                 \
            } else {                                                                                             \
                ST[i_] = C2D_SEPARATING;                                                                         \
            }                                                                                                    \
        }                                                                                                        \
    } while (0)

static void p_bare_soa(rset *s)
{
    BARE_SOA_LOOP(double, sqrt, s->soa.field, s->st, s->n, s->e);
    ratio_sink += (double)s->st[0];
}

static void p_bare_soaf(rset *s)
{
    const float e = (float)s->e;
    BARE_SOA_LOOP(float, sqrtf, s->soaf.field, s->st, s->n, e);
    ratio_sink += (double)s->st[0];
}

static void p_seed_inl(rset *s)
{
    int i;
    for (i = 0; i < s->n; i++)
        SEED_INLINE(double, sqrt, &s->a[i], &s->b[i], s->b[i].pos.x - s->a[i].pos.x, s->b[i].pos.y - s->a[i].pos.y);
    ratio_sink += s->a[0].vel.x;
}

static void p_seedf_inl(rset *s)
{
    int i;
    for (i = 0; i < s->n; i++)
        SEED_INLINE(float, sqrtf, &s->af[i], &s->bf[i], s->bf[i].pos.x - s->af[i].pos.x, s->bf[i].pos.y - s->af[i].pos.y);
    ratio_sink += s->af[0].vel.x;
}

static void p_seed_normal_inl(rset *s)
{
    int i;
    for (i = 0; i < s->n; i++) SEED_INLINE(double, sqrt, &s->a[i], &s->b[i], s->nrm[i].x, s->nrm[i].y);
    ratio_sink += s->a[0].vel.x;
}

static void p_seed_normalf_inl(rset *s)
{
    int i;
    for (i = 0; i < s->n; i++) SEED_INLINE(float, sqrtf, &s->af[i], &s->bf[i], s->nrmf[i].x, s->nrmf[i].y);
    ratio_sink += s->af[0].vel.x;
}

#define TOI_PASS(name, call, T)                                    \
    static void name(rset *s)                                      \
    {                                                              \
        unsigned acc = 0;                                          \
        T t = 0, sum = 0;                                          \
        int i;                                                     \
        for (i = 0; i < s->n; i++) acc += (unsigned)(call), sum += t; \
        ratio_sink += acc + (double)sum;                           \
    }

/* The time of impact writes nothing: its passes read the working copies,
 * which the restore before each pass brings into cache like any other. */
TOI_PASS(p_toi, c2d_time_of_impact(&s->a[i], &s->b[i], s->rad[i], &t), double)
TOI_PASS(p_toi_old, old_c2d_time_of_impact(&s->a[i], &s->b[i], s->rad[i], &t), double)
TOI_PASS(p_toi_text, bench_toi_textbook(&s->a[i], &s->b[i], s->rad[i], &t), double)
TOI_PASS(p_toif, c2d_time_of_impactf(&s->af[i], &s->bf[i], s->radf[i], &t), float)
TOI_PASS(p_toif_old, old_c2d_time_of_impactf(&s->af[i], &s->bf[i], s->radf[i], &t), float)
TOI_PASS(p_toif_text, bench_toi_textbookf(&s->af[i], &s->bf[i], s->radf[i], &t), float)

static void p_batch(rset *s) { ratio_sink += (double)c2d_collide_batch(&s->pairs, (size_t)s->n, s->e, s->st); }
static void p_batch_old(rset *s) { ratio_sink += (double)old_c2d_collide_batch(&s->pairs, (size_t)s->n, s->e, s->st); }
static void p_batchf(rset *s)
{
    ratio_sink += (double)c2d_collide_batchf(&s->pairsf, (size_t)s->n, (float)s->e, s->st);
}
static void p_batchf_old(rset *s)
{
    ratio_sink += (double)old_c2d_collide_batchf(&s->pairsf, (size_t)s->n, (float)s->e, s->st);
}

/* ------------------------------------------------------------ the timer */

typedef struct pass {
    const char *id;
    void (*run)(rset *);
    rset *s;
    writes w;
} pass;

static int g_callgrind;

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* Quantile q of v[0..n) (sorts v); NAN when n == 0. */
static double quantile(double *v, int n, double q)
{
    if (n <= 0) return NAN;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return v[(int)floor(q * (n - 1) + 0.5)];
}

/* A comparison: up to MAXP passes, timed in every round. */
#define MAXP 8
#define MAXG 96
typedef struct group_def {
    pass p[MAXP];
    int k;
    rstat *out;
    double *t;      /* t[j * rounds + r]: ns per call of pass j in round r */
    double *canary; /* the canary's ns per call just before round r */
} group_def;

static group_def g_groups[MAXG];
static int g_ngroups;

/* Register a group (timed later by run_groups); out[j] is pass j's, its
 * ratio to pass 0.  Under callgrind: each pass once, dumped as
 * "<gid>/<id>", right away. */
static void group(const char *gid, const pass *p, int k, rstat *out)
{
    int j;
    for (j = 0; j < k; j++) {
        memset(&out[j], 0, sizeof out[j]);
        snprintf(out[j].id, sizeof out[j].id, "%s/%s", gid, p[j].id);
        out[j].n = p[j].s->n;
    }
    if (g_callgrind) {
        for (j = 0; j < k; j++) {
            restore(p[j].s, p[j].w);
            CALLGRIND_ZERO_STATS;
            p[j].run(p[j].s);
            CALLGRIND_DUMP_STATS_AT(out[j].id);
        }
        return;
    }
    if (getenv("BENCH_ONLY") && strncmp(gid, getenv("BENCH_ONLY"), strlen(getenv("BENCH_ONLY"))) != 0) return;
    if (g_ngroups == MAXG || k > MAXP) abort();
    memcpy(g_groups[g_ngroups].p, p, (size_t)k * sizeof *p);
    g_groups[g_ngroups].k = k;
    g_groups[g_ngroups].out = out;
    g_ngroups++;
}

static double time_pass(const pass *p)
{
    double t0, t1;
    restore(p->s, p->w);
    t0 = bench_now_ns();
    p->run(p->s);
    t1 = bench_now_ns();
    return (t1 - t0) / p->s->n;
}

/* Every registered group, round after round: in each round every group
 * once, its passes one after another (order rotated), each group preceded
 * by the canary (the seed transcription on pairs of its own: no branch on
 * the data, nothing any pass could learn from), whose time tells a quiet
 * machine from a busy one.  With some 60 groups between two passes of one
 * group, no branch predictor keeps the outcomes of a pass's 4096 pairs from
 * one round to the next, as it would if the same pairs ran back to back:
 * data-dependent branches cost what they cost on fresh data.  Then each
 * pass's statistics. */
typedef struct run_info {
    double canary_best; /* in: the best seen before (INFINITY: none); out: with this run's */
    double quiet_share; /* out: share of quiet group-rounds */
    double max_halves;  /* out */
} run_info;

static void run_groups(int rounds, const pass *canary, int back_to_back, run_info *info)
{
    double *q = malloc((size_t)rounds * sizeof *q), *h = malloc((size_t)rounds * sizeof *h);
    double cmin = info->canary_best, quiet_limit;
    int g, r, j, quiet_rounds = 0, total = 0;
    for (g = 0; g < g_ngroups; g++) {
        group_def *d = &g_groups[g];
        d->t = malloc((size_t)(d->k * rounds) * sizeof *d->t);
        d->canary = malloc((size_t)rounds * sizeof *d->canary);
        for (j = 0; j < d->k; j++) time_pass(&d->p[j]); /* warm up: caches, predictors, lazy binding */
    }
    for (r = 0; r < rounds * g_ngroups; r++) {
        /* interleaved: round by round, every group in each; back to back:
         * group by group, all its rounds in a row */
        const int gr = back_to_back ? r / rounds : r % g_ngroups, rr = back_to_back ? r % rounds : r / g_ngroups;
        group_def *d = &g_groups[gr];
        d->canary[rr] = time_pass(canary);
        if (d->canary[rr] < cmin) cmin = d->canary[rr];
        for (j = 0; j < d->k; j++) {
            const int idx = (j + rr) % d->k; /* rotate: no pass always runs first */
            d->t[idx * rounds + rr] = time_pass(&d->p[idx]);
        }
    }
    quiet_limit = 1.10 * cmin;
    if (getenv("BENCH_CANARY")) { /* debugging: the canary's distribution */
        double *all = malloc((size_t)(g_ngroups * rounds) * sizeof *all);
        int m = 0;
        for (g = 0; g < g_ngroups; g++)
            for (r = 0; r < rounds; r++) all[m++] = g_groups[g].canary[r];
        for (j = 0; j <= 10; j++) fprintf(stderr, "canary q%d %.2f\n", j * 10, quantile(all, m, j / 10.0));
        free(all);
    }
    info->canary_best = cmin;
    info->max_halves = 0;
    for (g = 0; g < g_ngroups; g++) {
        group_def *d = &g_groups[g];
        for (r = 0; r < rounds; r++) quiet_rounds += d->canary[r] <= quiet_limit, total++;
        for (j = 0; j < d->k; j++) {
            rstat *out = &d->out[j];
            const double *tj = d->t + j * rounds, *t0 = d->t;
            int m = 0, use_quiet;
            for (r = 0; r < rounds; r++) q[r] = tj[r] / t0[r];
            out->ratio_all = quantile(q, rounds, 0.5);
            for (r = 0; r < rounds; r++) q[r] = tj[r];
            out->ns_all = quantile(q, rounds, 0.5);
            for (r = 0; r < rounds; r++) m += d->canary[r] <= quiet_limit;
            out->quiet = m;
            use_quiet = m >= RATIO_MIN_QUIET;
            /* The figures: over the quiet rounds when there are enough. */
            m = 0;
            for (r = 0; r < rounds; r++)
                if (!use_quiet || d->canary[r] <= quiet_limit) q[m] = tj[r] / t0[r], h[m++] = tj[r];
            out->ratio = quantile(q, m, 0.5);
            out->q1 = quantile(q, m, 0.25);
            out->q3 = quantile(q, m, 0.75);
            out->ns = quantile(h, m, 0.5);
            if (j > 0 && m >= 20) { /* the median of the even rounds against the odd ones */
                double even, odd;
                int me = 0, mo = 0;
                for (r = 0; r < rounds; r++) {
                    if (use_quiet && d->canary[r] > quiet_limit) continue;
                    if (r % 2) q[mo++] = tj[r] / t0[r];
                    else h[me++] = tj[r] / t0[r];
                }
                even = quantile(h, me, 0.5);
                odd = quantile(q, mo, 0.5);
                out->halves = fabs(even - odd) / out->ratio;
                if (out->halves > info->max_halves) info->max_halves = out->halves;
                if (getenv("BENCH_CANARY") && out->halves > 0.05)
                    fprintf(stderr, "halves %s %.3f (ratio %.3f, %d rounds)\n", out->id, out->halves, out->ratio, m);
            }
        }
        free(d->t), free(d->canary);
    }
    info->quiet_share = total ? (double)quiet_rounds / total : 0;
    g_ngroups = 0;
    free(q), free(h);
}

/* ------------------------------------------------------------ the inputs */

/* The front end's accept test (include/collide2d.h C2D_ACCEPT_DEFINE_, which
 * real/collide/fast.h c2d_quick and the inline forms run), in double and in float: an approaching pair off the axes, inside
 * the window, whose d does not cancel. */
static int accepted(const ref_case *c)
{
    const double nx = c->pb[0] - c->pa[0], ny = c->pb[1] - c->pa[1];
    const double px = (c->vb[0] - c->va[0]) * nx, py = (c->vb[1] - c->va[1]) * ny;
    const double d = px + py, k = fabs(px) + fabs(py), nn = nx * nx + ny * ny;
    const float fnx = (float)c->pb[0] - (float)c->pa[0], fny = (float)c->pb[1] - (float)c->pa[1];
    const float fpx = ((float)c->vb[0] - (float)c->va[0]) * fnx, fpy = ((float)c->vb[1] - (float)c->va[1]) * fny;
    const float fd = fpx + fpy, fk = fabsf(fpx) + fabsf(fpy), fnn = fnx * fnx + fny * fny;
    const float fma_ = (float)c->ma, fmb = (float)c->mb;
    int ok = nx != 0 && ny != 0 && (k + nn) + (c->ma + c->mb) <= 0x1p200 &&
             fmin(fmin(k, nn), fmin(c->ma, c->mb)) >= 0x1p-200 && 4 * d + k <= 0;
    ok = ok && fnx != 0 && fny != 0 && (fk + fnn) + (fma_ + fmb) <= 0x1p20f &&
         fminf(fminf(fk, fnn), fminf(fma_, fmb)) >= 0x1p-20f && 4 * fd + fk <= 0;
    return ok;
}

static int cancels(const ref_case *c)
{
    double nx = c->pb[0] - c->pa[0], ny = c->pb[1] - c->pa[1];
    double px = (c->vb[0] - c->va[0]) * nx, py = (c->vb[1] - c->va[1]) * ny;
    return !(fabs(px) + fabs(py) <= 4 * fabs(px + py));
}

typedef enum gen_kind {
    G_RANDOM, G_IMPACTS, G_IMPACTS_OK, G_CANCEL, G_WALLS, G_EXTREME, G_EXTREME_F,
    G_AXIS_SWAP, G_AXIS_WALL, G_AXIS_PADDLE, G_AXIS_UNEQUAL, G_UNIT, G_BREAK, G_GAS
} gen_kind;

static int approaching(const ref_case *c)
{
    return (c->vb[0] - c->va[0]) * (c->pb[0] - c->pa[0]) + (c->vb[1] - c->va[1]) * (c->pb[1] - c->pa[1]) < 0;
}

/* A standard normal deviate (Box-Muller). */
static double gauss(c2d_rng *r)
{
    const double u = c2d_rng_range(r, 0x1p-53, 1), v = c2d_rng_range(r, 0, 6.283185307179586);
    return sqrt(-2 * log(u)) * cos(v);
}

/* Issue 22's mixes.  unit: centres 1 apart in a random direction,
 * velocities uniform in [-1, 1]^2, equal masses, e = 1; a separating pair
 * is turned round four times in five, so most approach and some separate. */
static void gen_unit(c2d_rng *r, ref_case *c)
{
    const double ang = c2d_rng_range(r, 0, 6.283185307179586);
    int i;
    c->pa[0] = c2d_rng_range(r, -10, 10), c->pa[1] = c2d_rng_range(r, -10, 10);
    c->pb[0] = c->pa[0] + cos(ang), c->pb[1] = c->pa[1] + sin(ang);
    for (i = 0; i < 2; i++) c->va[i] = c2d_rng_range(r, -1, 1), c->vb[i] = c2d_rng_range(r, -1, 1);
    if (!approaching(c) && c2d_rng_next(r) % 5 != 0)
        for (i = 0; i < 2; i++) c->va[i] = -c->va[i], c->vb[i] = -c->vb[i];
    c->ma = c->mb = 1, c->e = 1;
}

/* break: pool balls (0.17 kg, R 28.575 mm) in contact along a rack line (a
 * multiple of 30 degrees, +-1 degree) somewhere on a 9 ft table, the
 * struck ball at 0.5-8 m/s within 60 degrees of the line of centres, the
 * other at rest or (half the time) drifting at up to 0.3 m/s; approaching. */
static void gen_break(c2d_rng *r, ref_case *c)
{
    const double deg = 0.017453292519943295, R = 0.028575;
    do {
        const double line = (double)(c2d_rng_next(r) % 12) * 30 * deg + c2d_rng_range(r, -1, 1) * deg;
        const double dir = line + c2d_rng_range(r, -60, 60) * deg, speed = c2d_rng_range(r, 0.5, 8);
        c->pa[0] = c2d_rng_range(r, 0.1, 2.44), c->pa[1] = c2d_rng_range(r, 0.1, 1.17);
        c->pb[0] = c->pa[0] + 2 * R * cos(line), c->pb[1] = c->pa[1] + 2 * R * sin(line);
        c->va[0] = speed * cos(dir), c->va[1] = speed * sin(dir);
        c->vb[0] = c->vb[1] = 0;
        if (c2d_rng_next(r) & 1) c->vb[0] = c2d_rng_range(r, -0.3, 0.3), c->vb[1] = c2d_rng_range(r, -0.3, 0.3);
    } while (!approaching(c));
    c->ma = c->mb = 0.17, c->e = 1;
}

/* gas: unit disks at contact (centres 1 apart in a random direction, in a
 * box 100 wide), Maxwell-Boltzmann velocities (unit Gaussian components);
 * approaching, as every pair a gas resolves. */
static void gen_gas(c2d_rng *r, ref_case *c)
{
    do {
        const double ang = c2d_rng_range(r, 0, 6.283185307179586);
        int i;
        c->pa[0] = c2d_rng_range(r, 0, 100), c->pa[1] = c2d_rng_range(r, 0, 100);
        c->pb[0] = c->pa[0] + cos(ang), c->pb[1] = c->pa[1] + sin(ang);
        for (i = 0; i < 2; i++) c->va[i] = gauss(r), c->vb[i] = gauss(r);
    } while (!approaching(c));
    c->ma = c->mb = 1, c->e = 1;
}

/* b becomes an immovable wall at rest: a's velocity taken relative to it
 * (the approach is kept). */
static void static_wall(ref_case *c)
{
    c->va[0] -= c->vb[0], c->va[1] -= c->vb[1];
    c->vb[0] = c->vb[1] = 0;
    c->mb = INFINITY;
}

/* An axis-aligned impact: the centres share a coordinate; approaching. */
static void gen_axis(c2d_rng *r, ref_case *c)
{
    const int on_y = (int)(c2d_rng_next(r) & 1);
    const double dist = c2d_rng_range(r, 0.5, 2.0) * ((c2d_rng_next(r) & 1) ? 1 : -1);
    gen_plain(r, c);
    c->pb[0] = c->pa[0] + (on_y ? 0 : dist);
    c->pb[1] = c->pa[1] + (on_y ? dist : 0);
    if ((c->vb[0] - c->va[0]) * (c->pb[0] - c->pa[0]) + (c->vb[1] - c->va[1]) * (c->pb[1] - c->pa[1]) >= 0) {
        int i;
        for (i = 0; i < 2; i++) c->va[i] = -c->va[i], c->vb[i] = -c->vb[i];
    }
    if (c->vb[on_y] == c->va[on_y]) c->va[on_y] += dist; /* never exactly grazing */
}

static void gen_one(c2d_rng *r, gen_kind g, ref_case *c)
{
    switch (g) {
    case G_RANDOM: gen_plain(r, c); break;
    case G_IMPACTS: gen_impact(r, c); break;
    case G_IMPACTS_OK: do gen_impact(r, c); while (!accepted(c)); break;
    case G_CANCEL: do gen_plain(r, c); while (!cancels(c)); break;
    case G_WALLS: gen_impact(r, c), static_wall(c); break;
    case G_EXTREME: gen_extreme(r, c, 53, -1022, 1023); return; /* its own normal and restitution */
    case G_EXTREME_F: gen_extreme(r, c, 24, -126, 127); return;
    case G_AXIS_SWAP: gen_axis(r, c), c->mb = c->ma; break;
    case G_AXIS_WALL: gen_axis(r, c), static_wall(c); break;
    case G_AXIS_PADDLE: gen_axis(r, c), c->mb = INFINITY; break; /* a moving immovable body */
    case G_AXIS_UNEQUAL:
        do gen_axis(r, c); while (c->ma == c->mb);
        break;
    case G_UNIT: gen_unit(r, c); break;
    case G_BREAK: gen_break(r, c); break;
    case G_GAS: gen_gas(r, c); break;
    }
    c->has_normal = 0;
}

static ref_case *gen_cases(gen_kind g, int n, unsigned long long seed)
{
    ref_case *c = malloc((size_t)n * sizeof *c);
    c2d_rng r;
    int i;
    r.s = seed;
    for (i = 0; i < n; i++) gen_one(&r, g, &c[i]);
    return c;
}

static rset *make_set(gen_kind g, int n, unsigned long long seed, double e)
{
    ref_case *c = gen_cases(g, n, seed), *cf = NULL;
    rset *s;
    if (g == G_EXTREME) cf = gen_cases(G_EXTREME_F, n, seed + 7); /* float-range extremes for the float calls */
    s = rset_make(c, cf, NULL, NULL, n, e);
    free(c), free(cf);
    return s;
}

/* Ordinary time-of-impact pairs: radii 0.1..1, centres 2 to 20 radius sums
 * apart (at most 20 units), relative velocity aimed at the other disk within
 * 1.25 times the angle that still hits, so most hit and some miss. */
static void gen_toi_ordinary(c2d_rng *r, ref_case *c, double *rad)
{
    const double R = c2d_rng_range(r, 0.1, 1) + c2d_rng_range(r, 0.1, 1);
    const double dist = fmin(R * c2d_rng_range(r, 2, 20), 20), ang = c2d_rng_range(r, 0, 6.283185307179586);
    const double aim = ang + 1.25 * asin(R / dist) * c2d_rng_range(r, -1, 1), speed = c2d_rng_range(r, 0.5, 10);
    c->pa[0] = c2d_rng_range(r, -10, 10), c->pa[1] = c2d_rng_range(r, -10, 10);
    c->pb[0] = c->pa[0] + dist * cos(ang), c->pb[1] = c->pa[1] + dist * sin(ang);
    c->va[0] = c2d_rng_range(r, -1, 1), c->va[1] = c2d_rng_range(r, -1, 1);
    c->vb[0] = c->va[0] - speed * cos(aim), c->vb[1] = c->va[1] - speed * sin(aim);
    c->ma = c->mb = 1, c->n[0] = c->n[1] = 0, c->has_normal = 0, c->e = 1;
    *rad = R;
}

/* Extreme time-of-impact pairs (tests/unit/test_time_of_impact.c): half
 * scaled anywhere in the range, half with every component at its own
 * exponent (gen_toi_ratios). */
static void gen_toi_extreme(c2d_rng *r, ref_case *c, double *rad, int prec, int emin, int emax)
{
    int i;
    if (c2d_rng_next(r) & 1) {
        const int sp = (int)(c2d_rng_next(r) % (uint64_t)(2 * emax)) - emax;
        const int sv = (int)(c2d_rng_next(r) % (uint64_t)(2 * emax)) - emax;
        gen_toi_ordinary(r, c, rad);
        for (i = 0; i < 2; i++) {
            c->pa[i] = ldexp(c->pa[i], sp), c->pb[i] = ldexp(c->pb[i], sp);
            c->va[i] = ldexp(c->va[i], sv), c->vb[i] = ldexp(c->vb[i], sv);
        }
        *rad = ldexp(*rad, sp);
    } else {
        gen_toi_ratios(r, c, rad, prec, emin, emax);
    }
    c->ma = c->mb = 1, c->n[0] = c->n[1] = 0, c->has_normal = 0, c->e = 1;
    if (prec < 53) {
        for (i = 0; i < 2; i++)
            c->pa[i] = (float)c->pa[i], c->pb[i] = (float)c->pb[i], c->va[i] = (float)c->va[i], c->vb[i] = (float)c->vb[i];
        *rad = (float)*rad;
    }
}

void gen_toi_case(c2d_rng *r, ref_case *c, double *rad, int extreme, int is_float)
{
    if (!extreme) gen_toi_ordinary(r, c, rad);
    else if (is_float) gen_toi_extreme(r, c, rad, 24, -126, 127);
    else gen_toi_extreme(r, c, rad, 53, -1022, 1023);
}

static rset *make_toi_set(int extreme, int n, unsigned long long seed, double *hits)
{
    ref_case *c = calloc((size_t)n, sizeof *c), *cf = calloc((size_t)n, sizeof *cf);
    double *rad = calloc((size_t)n, sizeof *rad), *radf = calloc((size_t)n, sizeof *radf);
    c2d_rng r, rf;
    rset *s;
    int i, h = 0;
    r.s = seed, rf.s = seed + 3;
    for (i = 0; i < n; i++) {
        gen_toi_case(&r, &c[i], &rad[i], extreme, 0);
        if (extreme) gen_toi_case(&rf, &cf[i], &radf[i], 1, 1); /* float-range extremes */
        else cf[i] = c[i], radf[i] = rad[i];
    }
    s = rset_make(c, cf, rad, radf, n, 1.0);
    for (i = 0; i < n; i++) {
        double t;
        h += c2d_time_of_impact(&s->a0[i], &s->b0[i], s->rad[i], &t) == C2D_OK;
    }
    if (hits) *hits = (double)h / n;
    free(c), free(cf), free(rad), free(radf);
    return s;
}

/* ------------------------------------------------------------ measuring */

void ratios_measure(ratios *o, int rounds, int n, int callgrind)
{
    static const gen_kind ba_gen[BS_SETS] = {G_RANDOM, G_IMPACTS, G_EXTREME, G_CANCEL, G_WALLS,
                                             G_AXIS_SWAP, G_AXIS_WALL, G_AXIS_PADDLE, G_AXIS_UNEQUAL};
    static const char *const ba_name[BS_SETS] = {"random", "impacts", "extreme", "cancelling", "walls",
                                                 "axis_swap", "axis_wall", "axis_paddle", "axis_unequal"};
    const int slow = n >= 256 ? n / 4 : n; /* pairs in the sets whose calls take microseconds */
    static const char *const goal_set[GS_COUNT] = {"impacts", "random"};
    rset *gs[GS_COUNT], *bs[BS_SETS], *ok, *ax[AX_COUNT], *toi[2], *rough, *i22[3];
    pass goal_pass[GV_COUNT][GS_COUNT][GP_COUNT];
    char gid[64];
    int v, s, j;
    g_callgrind = callgrind;
    g_ngroups = 0;
    memset(o, 0, sizeof *o);
    o->rounds = rounds;
    o->n = n;
    o->have_old = BENCH_HAVE_OLD();
    o->as_written = C2D_INLINE_AS_WRITTEN;
    /* The benchmark's speed sets, seeds as bench.c's timing_cases. */
    gs[GS_RANDOM] = make_set(G_RANDOM, n, 1000, 1.0);
    gs[GS_IMPACTS] = make_set(G_IMPACTS, n, 1001, 1.0);
    {
        pass noop = {"noop", p_noop, gs[GS_IMPACTS], W_BODY};
        group("ratio", &noop, 1, &o->noop);
    }
    for (s = 0; s < GS_COUNT; s++) {
        const pass grp[GV_COUNT][GP_COUNT] = {
            {{"seed", p_seed, gs[s], W_BODY}, {"lib", p_collide, gs[s], W_BODY},
             {"inline", p_collide_inl, gs[s], W_BODY}, {"seed_inline", p_seed_inl, gs[s], W_BODY}},
            {{"seed", p_seedf, gs[s], W_BODYF}, {"lib", p_collidef, gs[s], W_BODYF},
             {"inline", p_collidef_inl, gs[s], W_BODYF}, {"seed_inline", p_seedf_inl, gs[s], W_BODYF}},
            {{"seed", p_seed_normal, gs[s], W_BODY}, {"lib", p_normal, gs[s], W_BODY},
             {"inline", p_normal_inl, gs[s], W_BODY}, {"seed_inline", p_seed_normal_inl, gs[s], W_BODY}},
            {{"seed", p_seed_normalf, gs[s], W_BODYF}, {"lib", p_normalf, gs[s], W_BODYF},
             {"inline", p_normalf_inl, gs[s], W_BODYF}, {"seed_inline", p_seed_normalf_inl, gs[s], W_BODYF}},
        };
        static const char *const vname[GV_COUNT] = {"collide", "collidef", "normal", "normalf"};
        memcpy(goal_pass[0][s], grp[0], sizeof grp[0]), memcpy(goal_pass[1][s], grp[1], sizeof grp[1]);
        memcpy(goal_pass[2][s], grp[2], sizeof grp[2]), memcpy(goal_pass[3][s], grp[3], sizeof grp[3]);
        for (v = 0; v < GV_COUNT; v++) {
            snprintf(gid, sizeof gid, "goal/%s/%s", vname[v], goal_set[s]);
            group(gid, grp[v], GP_COUNT, o->goal[v][s]);
        }
    }
    {   /* The seed given the normal as a c2d_vec2 by value (approaches.h) */
        const pass p[2] = {{"scalars", p_seed_normal, gs[GS_IMPACTS], W_BODY},
                           {"byvalue", p_seed_normal_v, gs[GS_IMPACTS], W_BODY}};
        group("note/seed_normal", p, 2, o->seed_byvalue);
    }
    /* Time of impact against the textbook quadratic, ordinary pairs. */
    toi[0] = make_toi_set(0, n, 2000, &o->toi_hits);
    {
        const pass d[2] = {{"textbook", p_toi_text, toi[0], W_BODY}, {"lib", p_toi, toi[0], W_BODY}};
        const pass f[2] = {{"textbook", p_toif_text, toi[0], W_BODYF}, {"lib", p_toif, toi[0], W_BODYF}};
        group("toi/double", d, 2, o->toi[0]);
        group("toi/float", f, 2, o->toi[1]);
    }
    /* Batch against the scalar call, every pair an accepted impact. */
    ok = make_set(G_IMPACTS_OK, n, 3000, 1.0);
    {
        const pass d[2] = {{"scalar", p_collide, ok, W_BODY}, {"batch", p_batch, ok, W_SOA}};
        const pass f[2] = {{"scalar", p_collidef, ok, W_BODYF}, {"batch", p_batchf, ok, W_SOAF}};
        group("batch/double", d, 2, o->batch[0]);
        group("batch/float", f, 2, o->batch[1]);
    }
    /* Issue 22: the seed on unit-distance pairs; the bare formula on break
     * and gas pairs; the batch on the gas and the random mix. */
    i22[0] = make_set(G_UNIT, n, 7000, 1.0);
    i22[1] = make_set(G_BREAK, n, 7001, 1.0);
    i22[2] = make_set(G_GAS, n, 7002, 1.0);
    {
        const pass d[3] = {{"seed", p_seed, i22[0], W_BODY}, {"lib", p_collide, i22[0], W_BODY},
                           {"inline", p_collide_inl, i22[0], W_BODY}};
        const pass f[3] = {{"seed", p_seedf, i22[0], W_BODYF}, {"lib", p_collidef, i22[0], W_BODYF},
                           {"inline", p_collidef_inl, i22[0], W_BODYF}};
        group("i22/unit/double", d, 3, o->i22_unit[0]);
        group("i22/unit/float", f, 3, o->i22_unit[1]);
    }
    for (s = 0; s < 2; s++) {
        rset *m = i22[1 + s];
        const pass d[I22_MIX] = {{"bare_inline", p_bare_inl, m, W_BODY}, {"bare", p_bare, m, W_BODY},
                                 {"lib", p_collide, m, W_BODY}, {"inline", p_collide_inl, m, W_BODY},
                                 {"normal", p_normal, m, W_BODY}};
        const pass f[I22_MIX] = {{"bare_inline", p_baref_inl, m, W_BODYF}, {"bare", p_baref, m, W_BODYF},
                                 {"lib", p_collidef, m, W_BODYF}, {"inline", p_collidef_inl, m, W_BODYF},
                                 {"normal", p_normalf, m, W_BODYF}};
        snprintf(gid, sizeof gid, "i22/%s/double", s ? "gas" : "break");
        group(gid, d, I22_MIX, o->i22_mix[s][0]);
        snprintf(gid, sizeof gid, "i22/%s/float", s ? "gas" : "break");
        group(gid, f, I22_MIX, o->i22_mix[s][1]);
    }
    for (s = 0; s < 2; s++) {
        rset *m = s ? gs[GS_RANDOM] : i22[2];
        const pass d[3] = {{"scalar", p_collide, m, W_BODY}, {"batch", p_batch, m, W_SOA},
                           {"bare_loop", p_bare_soa, m, W_SOA}};
        const pass f[3] = {{"scalar", p_collidef, m, W_BODYF}, {"batch", p_batchf, m, W_SOAF},
                           {"bare_loop", p_bare_soaf, m, W_SOAF}};
        snprintf(gid, sizeof gid, "i22/batch_%s/double", s ? "random" : "gas");
        group(gid, d, 3, o->i22_batch[s][0]);
        snprintf(gid, sizeof gid, "i22/batch_%s/float", s ? "random" : "gas");
        group(gid, f, 3, o->i22_batch[s][1]);
    }
    /* The axis-aligned branch against ordinary pairs. */
    ax[AX_ORDINARY] = gs[GS_IMPACTS];
    ax[AX_WALL_OBLIQUE] = make_set(G_WALLS, n, 4001, 1.0);
    ax[AX_SWAP] = make_set(G_AXIS_SWAP, n, 4002, 1.0);
    ax[AX_WALL1] = make_set(G_AXIS_WALL, n, 4003, 1.0);
    ax[AX_WALL08] = make_set(G_AXIS_WALL, n, 4003, 0.8);
    ax[AX_PADDLE] = make_set(G_AXIS_PADDLE, slow, 4005, 0.8);
    ax[AX_UNEQUAL] = make_set(G_AXIS_UNEQUAL, slow, 4004, 1.0);
    {
        static const char *const id[AX_COUNT] = {"ordinary", "wall_oblique", "swap", "wall_e1", "wall_e08", "paddle",
                                                 "unequal"};
        pass p[AX_COUNT];
        for (j = 0; j < AX_COUNT; j++) p[j].id = id[j], p[j].run = p_collide, p[j].s = ax[j], p[j].w = W_BODY;
        group("axis", p, AX_COUNT, o->axis);
    }
    /* Rough disks: the library (double, float), Walton as a textbook would
     * write him, and the frictionless call on the same pairs. */
    {
        ref_rough_case *rc = malloc((size_t)n * sizeof *rc);
        c2d_rng r;
        r.s = 5000;
        for (j = 0; j < n; j++) {
            gen_rough(&r, &rc[j]);
            rc[j].has_normal = 0;
        }
        rough = rset_rough(rc, n);
        free(rc);
    }
    {
        const pass p[RG_COUNT] = {{"walton", p_walton, rough, W_DISK}, {"rough", p_rough, rough, W_DISK},
                                  {"roughf", p_roughf, rough, W_DISK}, {"collide", p_collide, rough, W_BODY}};
        group("rough", p, RG_COUNT, o->rough);
    }
    /* The library before and after. */
    for (s = 0; s < BS_SETS; s++)
        bs[s] = s == BS_RANDOM    ? gs[GS_RANDOM]
                : s == BS_IMPACTS ? gs[GS_IMPACTS]
                                  : make_set(ba_gen[s], s == BS_EXTREME || s >= BS_AXIS_PADDLE ? slow : n,
                                             6000 + (unsigned)s, s == BS_AXIS_WALL || s == BS_AXIS_PADDLE ? 0.8 : 1.0);
    toi[1] = make_toi_set(1, slow, 2001, NULL);
    if (o->have_old) {
        for (s = 0; s < BS_SETS; s++) {
            const pass grp[BA_FN][2] = {
                {{"old", p_collide_old, bs[s], W_BODY}, {"new", p_collide, bs[s], W_BODY}},
                {{"old", p_normal_old, bs[s], W_BODY}, {"new", p_normal, bs[s], W_BODY}},
                {{"old", p_collidef_old, bs[s], W_BODYF}, {"new", p_collidef, bs[s], W_BODYF}},
                {{"old", p_normalf_old, bs[s], W_BODYF}, {"new", p_normalf, bs[s], W_BODYF}},
                {{"old", p_batch_old, bs[s], W_SOA}, {"new", p_batch, bs[s], W_SOA}},
                {{"old", p_batchf_old, bs[s], W_SOAF}, {"new", p_batchf, bs[s], W_SOAF}},
            };
            static const char *const fname[BA_FN] = {"collide", "normal", "collidef", "normalf", "batch", "batchf"};
            for (v = 0; v < (s >= BS_AXIS_SWAP ? BA_BATCH : BA_FN); v++) { /* axis-aligned: scalar calls */
                snprintf(gid, sizeof gid, "ba/%s/%s", fname[v], ba_name[s]);
                group(gid, grp[v], 2, o->ba[v][s]);
            }
        }
        for (s = 0; s < 2; s++) {
            const pass d[2] = {{"old", p_toi_old, toi[s], W_BODY}, {"new", p_toi, toi[s], W_BODY}};
            const pass f[2] = {{"old", p_toif_old, toi[s], W_BODYF}, {"new", p_toif, toi[s], W_BODYF}};
            snprintf(gid, sizeof gid, "ba/toi/%s", s ? "extreme" : "ordinary");
            group(gid, d, 2, o->ba_toi[0][s]);
            snprintf(gid, sizeof gid, "ba/toif/%s", s ? "extreme" : "ordinary");
            group(gid, f, 2, o->ba_toi[1][s]);
        }
    }
    {
        rset *cs = make_set(G_IMPACTS, n, 999, 1.0);
        const pass canary = {"canary", p_seed, cs, W_BODY};
        run_info info;
        info.canary_best = bench_canary_best;
        if (!callgrind) {
            run_groups(rounds, &canary, 0, &info);
            o->canary_ns = info.canary_best, o->quiet_share = info.quiet_share, o->max_halves = info.max_halves;
            bench_canary_best = info.canary_best;
            /* The goals' groups again, each group's rounds back to back: what
             * a benchmark of one function on fixed pairs would report. */
            for (s = 0; s < GS_COUNT; s++)
                for (v = 0; v < GV_COUNT; v++) {
                    snprintf(gid, sizeof gid, "b2b/%d/%d", v, s);
                    group(gid, goal_pass[v][s], GP_COUNT, o->goal_b2b[v][s]);
                }
            run_groups(rounds / 2 > 3 ? rounds / 2 : 3, &canary, 1, &info);
            o->quiet_share_b2b = info.quiet_share;
        }
        rset_free(cs);
    }
    for (s = 0; s < BS_SETS; s++)
        if (s != BS_RANDOM && s != BS_IMPACTS) rset_free(bs[s]);
    for (j = 1; j < AX_COUNT; j++) rset_free(ax[j]);
    rset_free(gs[0]), rset_free(gs[1]), rset_free(ok), rset_free(toi[0]), rset_free(toi[1]), rset_free(rough);
    rset_free(i22[0]), rset_free(i22[1]), rset_free(i22[2]);
}

/* ------------------------------------------------------------ checks */

/* For the smoke run: the old library (when linked) gives the new one's
 * bits on ordinary pairs off the axes (the speed work's front end changed
 * no result; only axis-aligned impacts were changed, to correctly
 * rounded), and the textbook time of impact agrees with the library on
 * ordinary pairs.
 * Returns the number of disagreements. */
int ratios_selfcheck(int n, int *compared)
{
    ref_case *c = gen_cases(G_RANDOM, n, 77);
    int i, bad = 0, cmp = 0;
    c2d_rng r;
    for (i = 0; i < n && BENCH_HAVE_OLD(); i++) {
        c2d_body a, b, a2, b2;
        c2d_bodyf af, bf, af2, bf2;
        c2d_status s1, s2;
        case_to_bodies(&c[i], &a, &b), a2 = a, b2 = b;
        case_to_bodiesf(&c[i], &af, &bf), af2 = af, bf2 = bf;
        if (a.pos.x == b.pos.x || a.pos.y == b.pos.y) continue;
        s1 = c2d_collide(&a, &b, c[i].e), s2 = old_c2d_collide(&a2, &b2, c[i].e);
        bad += s1 != s2 || memcmp(&a, &a2, sizeof a) != 0 || memcmp(&b, &b2, sizeof b) != 0;
        s1 = c2d_collidef(&af, &bf, (float)c[i].e), s2 = old_c2d_collidef(&af2, &bf2, (float)c[i].e);
        bad += s1 != s2 || memcmp(&af, &af2, sizeof af) != 0 || memcmp(&bf, &bf2, sizeof bf) != 0;
        cmp += 2;
    }
    r.s = 78;
    for (i = 0; i < n; i++) {
        ref_case t;
        c2d_body a, b;
        double rad, t1 = -1, t2 = -1;
        c2d_status s1, s2;
        gen_toi_ordinary(&r, &t, &rad);
        case_to_bodies(&t, &a, &b);
        s1 = c2d_time_of_impact(&a, &b, rad, &t1);
        s2 = bench_toi_textbook(&a, &b, rad, &t2);
        bad += s1 != s2 || (s1 == C2D_OK && !(fabs(t1 - t2) <= 1e-9 * (1 + t1)));
        cmp++;
    }
    free(c);
    /* Issue 22's baseline is the right formula: on unit, break and gas
     * pairs the bare impulse gives the library's statuses and velocities to
     * 1e-12 of the pair's speed. */
    {
        static const gen_kind mixes[3] = {G_UNIT, G_BREAK, G_GAS};
        int m;
        for (m = 0; m < 3; m++) {
            ref_case *mc = gen_cases(mixes[m], n, 79 + (unsigned)m);
            for (i = 0; i < n; i++) {
                c2d_body a, b, a2, b2;
                c2d_status s1, s2;
                double scale;
                case_to_bodies(&mc[i], &a, &b), a2 = a, b2 = b;
                scale = fabs(a.vel.x) + fabs(a.vel.y) + fabs(b.vel.x) + fabs(b.vel.y);
                s1 = c2d_collide(&a, &b, 1.0), s2 = bench_bare(&a2, &b2, 1.0);
                bad += s1 != s2 || !(fabs(a.vel.x - a2.vel.x) + fabs(a.vel.y - a2.vel.y) + fabs(b.vel.x - b2.vel.x) +
                                         fabs(b.vel.y - b2.vel.y) <= 1e-12 * scale);
                cmp++;
            }
            free(mc);
        }
    }
    *compared = cmp;
    return bad;
}
