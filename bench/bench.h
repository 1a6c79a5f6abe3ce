/* Shared by the benchmark's parts: the contenders, the input sets with their
 * exact answers, accuracy statistics and timings. */
#ifndef C2D_BENCH_H
#define C2D_BENCH_H

#include <stddef.h>

#include "collide2d.h"
#include "cases.h"
#include "harness.h"
#include "referee.h"

/* How a contender is called and which precision its answers have. */
typedef enum bench_kind {
    KIND_DOUBLE,  /* fn on c2d_body, normal from the positions */
    KIND_NORMAL,  /* c2d_collide_normal with n = fl(pb - pa) */
    KIND_FLOAT,   /* c2d_collidef */
    KIND_FIXED,   /* c2d_collidex, Q16.16 */
    KIND_BATCH,   /* c2d_collide_batch */
    KIND_BATCHF,  /* c2d_collide_batchf */
    KIND_BOX2D    /* fn on c2d_body, float inside */
} bench_kind;

typedef c2d_status (*bench_fn)(c2d_body *a, c2d_body *b, double restitution);

typedef struct contender {
    const char *name;   /* row label */
    const char *id;     /* short name for callgrind dumps and the plot */
    bench_kind kind;
    bench_fn fn;        /* KIND_DOUBLE and KIND_BOX2D */
    int equal_only;     /* only meaningful for equal masses and e = 1 */
    int extreme;        /* evaluated on extreme inputs */
} contender;

extern const contender bench_contenders[];
extern const int bench_ncontenders;

/* Cases with their exact answers (for SEPARATING answers v[] holds the
 * unchanged input velocities). */
typedef struct case_set {
    const char *name;
    int n;
    ref_case *c;
    ref_answer *r;
    int prec, emin;      /* the format's ulp for "own" errors (0: Q16.16 steps) */
} case_set;

typedef enum set_id {
    SET_PLAIN, SET_PLAIN_NORMAL, SET_PLAIN_FLOAT, SET_PLAIN_FIXED, SET_PLAIN_EQUAL,
    SET_EXTREME, SET_EXTREME_NORMAL, SET_EXTREME_FLOAT, SET_EXTREME_EQUAL, SET_COUNT
} set_id;

/* Make all sets; n_plain / n_extreme cases each (equal-mass sets likewise). */
void sets_make(case_set *sets, int n_plain, int n_extreme, unsigned long long seed);
void sets_free(case_set *sets);
/* The plain / extreme set a contender is evaluated on; NULL if none. */
const case_set *sets_for(const case_set *sets, const contender *k, int extreme);

/* Run one contender on one case: status and the four output velocities
 * (inputs when nothing was written). */
c2d_status contender_run(const contender *k, const ref_case *c, double got[4]);

/* For a batch contender: every lane of its call on the case has the scalar
 * call's status and bits, and the returned count is right (header promise).
 * 1 for any other contender. */
int contender_batch_agrees(const contender *k, const ref_case *c);

typedef struct acc_stats {
    int n, evaluated, wrong_status, nan, inf, batch_mismatch;
    double max_ulp, med_ulp;      /* in the contender's own ulp (Q16.16: steps) */
    double max_rel, med_rel;      /* relative to the velocity scale */
    double max_momentum, max_energy; /* relative; energy over e = 1 cases */
} acc_stats;

void evaluate(const contender *k, const case_set *s, acc_stats *out);

/* Generators shared by the accuracy and timing parts. */
void gen_impact(c2d_rng *r, ref_case *c); /* uniform impact parameter */

/* ---------------------------------------------------------------- timing */
typedef struct timing_data timing_data;
timing_data *timing_make(const ref_case *cases, int n);
void timing_free(timing_data *t);

/* Median ns per collision for every contender over `rounds` interleaved
 * rounds; ns[i] for bench_contenders[i] (negative: not timed). */
void timing_run(timing_data *t, int rounds, double *ns);

/* Large-batch throughput (pairs/s) of the batch kernel and of a streaming
 * kernel that touches the same bytes; `count` pairs. */
typedef struct roof_result { double batch_pps, roof_pps, bytes_per_pair; } roof_result;
void roof_run(int is_float, size_t count, int reps, roof_result *out);

/* Run each contender over the first n pairs between callgrind client
 * requests (zero, then dump named "<label>/<id>"). */
void callgrind_run(timing_data *t, int n, const char *label);

/* Kappa > 2 share: pairs beyond the library's fast path. */
double timing_slow_share(const ref_case *cases, int n);

#endif
