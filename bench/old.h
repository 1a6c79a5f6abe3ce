/* SPDX-License-Identifier: MIT */
/* The library as it was before the speed work (commit BENCH_OLD_REV
 * below), built into the benchmark from `git archive` with its global
 * symbols renamed old_* (objcopy --redefine-syms), so the old and the new
 * calls can be timed interleaved in one process.  The types are the
 * current header's: the structs are the same.  Without the old sources (no
 * git history) bench/old_missing.c stands in and old_c2d_version() is 0. */
#ifndef C2D_BENCH_OLD_H
#define C2D_BENCH_OLD_H

#include "collide2d.h"

/* The commit the old library is taken from (read by bench/bench.mk too):
 * the start of the speed work, before the front end. */
#define BENCH_OLD_REV "ec2e2a8"

long old_c2d_version(void);
c2d_status old_c2d_collide(c2d_body *a, c2d_body *b, double restitution);
c2d_status old_c2d_collide_normal(c2d_body *a, c2d_body *b, c2d_vec2 normal, double restitution);
c2d_status old_c2d_time_of_impact(const c2d_body *a, const c2d_body *b, double radius_sum, double *t);
size_t old_c2d_collide_batch(const c2d_pairs *p, size_t count, double restitution, c2d_status *status);
c2d_status old_c2d_collidef(c2d_bodyf *a, c2d_bodyf *b, float restitution);
c2d_status old_c2d_collide_normalf(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f normal, float restitution);
c2d_status old_c2d_time_of_impactf(const c2d_bodyf *a, const c2d_bodyf *b, float radius_sum, float *t);
size_t old_c2d_collide_batchf(const c2d_pairsf *p, size_t count, float restitution, c2d_status *status);

/* 1 when the old library is linked in (not the stand-in). */
#define BENCH_HAVE_OLD() (old_c2d_version() != 0)

#endif
