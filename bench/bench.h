/* SPDX-License-Identifier: MIT */
/* Shared by the benchmark's parts: the contenders, the input sets with their
 * exact answers, accuracy statistics and timings. */
#ifndef C2D_BENCH_H
#define C2D_BENCH_H

#include <stddef.h>

#include "collide2d.h"
#include "cases.h"
#include "harness.h"
#include "referee.h"
#include "cases_rough.h"

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
 * rounds, more when too few are quiet (the quiet ones, by a canary timed
 * first in each, when there are at least RATIO_MIN_QUIET; their number in
 * timing_quiet_rounds, of timing_rounds_run); ns[i] for
 * bench_contenders[i] (negative: not timed). */
void timing_run(timing_data *t, int rounds, double *ns);
extern int timing_quiet_rounds, timing_rounds_run;
/* The best canary time seen in this run (ratio.c and timing.c): a round is
 * quiet when its canary is within 10% of it. */
extern double bench_canary_best;

/* Large-batch throughput (pairs/s) of the batch kernel and of a streaming
 * kernel that touches the same bytes; `count` pairs. */
typedef struct roof_result { double batch_pps, roof_pps, bytes_per_pair; } roof_result;
void roof_run(int is_float, size_t count, int reps, roof_result *out);

/* Run each contender over the first n pairs between callgrind client
 * requests (zero, then dump named "<label>/<id>"). */
void callgrind_run(timing_data *t, int n, const char *label);

/* Kappa > 2 share: pairs beyond the library's fast path. */
double timing_slow_share(const ref_case *cases, int n);

/* ------------------------------------------------- interleaved ratios
 * (ratio.c).  A group of passes over the same in-cache pairs is timed pass
 * after pass in every round; each pass's ratio to the group's first pass is
 * the median over the rounds of the per-round ratio. */
typedef struct rstat {
    char id[48];        /* "<group>/<pass>": its callgrind dump */
    int n;              /* calls per pass */
    /* Over the rounds on a quiet machine (the canary within 10% of its
     * best) when there are at least RATIO_MIN_QUIET of them, else over all: */
    double ns;          /* median ns per call */
    double ratio;       /* median per-round ratio to the group's first pass */
    double q1, q3;      /* quartiles of that ratio */
    int quiet;          /* quiet rounds (the figures above use them when >= RATIO_MIN_QUIET) */
    double ratio_all, ns_all; /* the medians over all rounds */
    double halves;      /* |median of even rounds - of odd rounds| / ratio */
} rstat;

enum { GV_COLLIDE, GV_COLLIDEF, GV_NORMAL, GV_NORMALF, GV_COUNT };  /* goal variants */
enum { GS_IMPACTS, GS_RANDOM, GS_COUNT };                          /* goal input sets */
enum { GP_SEED, GP_LIB, GP_INLINE, GP_SEED_INLINE, GP_COUNT };     /* passes of a goal group */
enum { BA_COLLIDE, BA_NORMAL, BA_COLLIDEF, BA_NORMALF, BA_BATCH, BA_BATCHF, BA_FN };
enum { BS_RANDOM, BS_IMPACTS, BS_EXTREME, BS_CANCEL, BS_WALLS, BS_AXIS_SWAP, BS_AXIS_WALL, BS_AXIS_PADDLE,
       BS_AXIS_UNEQUAL, BS_SETS };
enum { AX_ORDINARY, AX_WALL_OBLIQUE, AX_SWAP, AX_WALL1, AX_WALL08, AX_PADDLE, AX_UNEQUAL, AX_COUNT };
enum { RG_WALTON, RG_ROUGH, RG_ROUGHF, RG_COLLIDE, RG_COUNT };
enum { I22_BARE_INLINE, I22_BARE, I22_LIB, I22_INLINE, I22_NORMAL, I22_MIX }; /* passes on break and gas pairs */

typedef struct ratios {
    int rounds, n, have_old, as_written;
    rstat noop;                               /* the empty call's loop */
    rstat goal[GV_COUNT][GS_COUNT][GP_COUNT]; /* ratios to the seed transcription */
    rstat goal_b2b[GV_COUNT][GS_COUNT][GP_COUNT]; /* the same, each group's rounds back to back */
    double quiet_share_b2b;
    rstat seed_byvalue[2];                    /* the seed, normal as scalars / as a c2d_vec2 by value */
    rstat toi[2][2];                          /* [double, float][textbook, library] */
    double toi_hits;                          /* share of hits among the ordinary pairs */
    rstat batch[2][2];                        /* [double, float][scalar, batch] */
    rstat axis[AX_COUNT];                     /* c2d_collide, ratios to ordinary impacts */
    rstat ba[BA_FN][BS_SETS][2];              /* [old, new] */
    rstat ba_toi[2][2][2];                    /* [double, float][ordinary, extreme][old, new] */
    rstat rough[RG_COUNT];                    /* ratios to the Walton transcription */
    rstat i22_unit[2][3];                     /* unit-distance pairs [double, float][seed, lib, inline] */
    rstat i22_mix[2][2][I22_MIX];             /* [break, gas][double, float], ratios to the bare formula inlined */
    rstat i22_batch[2][2][3];                 /* [gas, random][double, float][scalar, batch, bare loop] */
    double max_halves;                        /* largest even/odd-round difference of a median */
    double canary_ns, quiet_share;            /* the canary's best; share of quiet group-rounds */
} ratios;

#define RATIO_MIN_QUIET 30

/* n pairs per set; callgrind: one pass each under client requests. */
void ratios_measure(ratios *r, int rounds, int n, int callgrind);
/* Smoke: old == new bits off the axes, textbook toi == library; returns
 * the number of disagreements, *compared the number of comparisons. */
int ratios_selfcheck(int n, int *compared);
/* A time-of-impact case: ordinary (a few radii to 20 apart, aimed roughly
 * at each other) or extreme (over the range, or magnitude ratios). */
void gen_toi_case(c2d_rng *r, ref_case *c, double *rad, int extreme, int is_float);

/* ---------------------------------------------- time of impact (toi.c) */
enum { TK_LIB, TK_OLD, TK_TEXT, TK_COUNT };
typedef struct toi_stats {
    int n, hits, evaluated, wrong_status, nan_inf;
    double max_units, med_units; /* error in the header's units, over the hits both report */
} toi_stats;
/* Contender `which` on n ordinary (extreme 0) or extreme pairs against the
 * exact referee. */
void toi_evaluate(int which, int is_float, int extreme, int n, unsigned long long seed, toi_stats *out);

/* ------------------------------------------------------- rough disks
 * (rough.c) */

enum { RK_LIB, RK_LIBF, RK_WALTON, RK_COUNT };
typedef struct rough_stats {
    int n, evaluated, wrong_status, nan, inf;
    double max_ulp, med_ulp;   /* in the contender's own ulp of each body's scale */
    double max_energy_gain;    /* relative, over all impacts (energy must never grow) */
} rough_stats;

/* Contender `which` on n plain (extreme 0) or extreme cases against the
 * MPFR referee (referee/ref_rough.c). */
void rough_evaluate(int which, int extreme, int n, unsigned long long seed, rough_stats *out);

/* Results go here so no timed loop can be optimised away (timing.c). */
extern volatile double bench_sink;
/* A monotonic clock in ns (timing.c). */
double bench_now_ns(void);

/* ------------------------- time of impact under acceleration (toi_accel.c)
 * The library (double, float) and the textbook quartic solvers
 * (bench/quartic.c) on the unit test's families (referee/cases_toi_accel.c)
 * against the exact referee (referee/ref_toi_accel.c). */
enum { TA_LIB, TA_LIBF, TA_FERRARI, TA_STURM, TA_COUNT };
/* timed sets: the billiards family, every family, touching pool balls
 * (cases_toi_accel.h toia_gen_touching, not one of the families) */
enum { TA_BILLIARDS, TA_ALL, TA_TOUCHING, TA_SETS };
typedef struct toia_stats {
    long n, band, wrong, band_wrong, beyond, evaluated, nan_inf;
    double worst;        /* units (ulp(t) + ulp(|d|)/s) outside the band */
    double ns[TA_SETS];  /* median ns per call over interleaved rounds */
} toia_stats;
#define TOIA_BEYOND_UNITS 4.0
/* n cases per family; rounds of interleaved timing.  out: the families;
 * touch: the touching set (n cases), decided by the same referee. */
void toia_measure(int n_per_family, int rounds, toia_stats out[TA_COUNT], toia_stats touch[TA_COUNT]);
/* Under callgrind: one pass of n calls per contender on the billiards
 * family and on the touching set, each between client requests named
 * "toia/<set>/<contender>" (contenders lib, libf, ferrari; on the touching
 * set also plain and plainf, c2d_time_of_impact(f) on the same positions
 * and velocities; noop, the loop alone). */
void toia_callgrind(int n);

#endif
