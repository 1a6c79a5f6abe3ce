/* SPDX-License-Identifier: MIT */
/* Generates tests/vectors/vectors.c from the case list below, with every
 * expected value and tolerance computed by the exact referee
 * (referee/referee.c; for the models referee/ref_rough.c and
 * referee/ref_toi_accel.c).  Run: make vectors.  `make test` regenerates the table
 * and requires it unchanged (check-vectors), so the committed table cannot
 * drift from the referee. */
#include "cases_toi_accel.h"
#include "ref_rough.h"
#include "ref_toi_accel.h"
#include "referee.h"
#include "vectors.h"

#include <float.h>
#include <math.h>
#include <mpfr.h>
#include <stdio.h>
#include <string.h>

enum { D = 1, F = 2, X = 4, ALL = 7 };

typedef struct gcase {
    const char *name;
    int kind, variants;
    double pa[2], pb[2], va[2], vb[2], ma, mb, n[2], e;
} gcase;

#define INF INFINITY
static const gcase cases[] = {
    /* name, kind, variants, pa, pb, va, vb, ma, mb, n, e (radius for TOI) */
    {"seed_45_degree_equal_masses", VEC_COLLIDE, ALL, {0, 0}, {1, 1}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 1},
    {"head_on_equal_masses_swap", VEC_COLLIDE, ALL, {0, 0}, {1, 0}, {1, 0}, {-1, 0}, 1, 1, {0, 0}, 1},
    {"head_on_plastic_common_velocity", VEC_COLLIDE, ALL, {0, 0}, {1, 0}, {2, 0}, {0, 0}, 1, 1, {0, 0}, 0},
    {"head_on_half_restitution_unequal", VEC_COLLIDE, ALL, {0, 0}, {0, 2}, {0, 3}, {0, -1}, 1, 3, {0, 0}, 0.5},
    {"oblique_unequal_masses", VEC_COLLIDE, ALL, {0, 0}, {3, 4}, {2, 1}, {-1, 0.5}, 2, 0.5, {0, 0}, 0.875},
    {"newton_cradle_pair_passes_velocity", VEC_COLLIDE, ALL, {0, 0}, {2, 0}, {1.5, 0}, {0, 0}, 0.25, 0.25, {0, 0}, 1},
    {"wall_bounce_with_restitution", VEC_COLLIDE_NORMAL, ALL, {0, 0}, {1, 0}, {3, 1}, {0, 0}, 1, INF, {1, 0}, 0.75},
    {"wall_oblique_normal", VEC_COLLIDE_NORMAL, ALL, {0, 0}, {0, 0}, {1, -2}, {0, 0}, 1, INF, {-3, -4}, 1},
    {"immovable_a_reflects_b", VEC_COLLIDE, ALL, {0, 0}, {0, 2}, {0, 0}, {0, -5}, INF, 1, {0, 0}, 1},
    {"normal_length_is_irrelevant", VEC_COLLIDE_NORMAL, ALL, {0, 0}, {0, 0}, {1, 0}, {0, 0}, 1, 1, {1024, 1024}, 1},
    {"separating_pair_untouched", VEC_COLLIDE, ALL, {0, 0}, {1, 0}, {-1, 0}, {1, 0}, 1, 1, {0, 0}, 1},
    {"tangential_motion_is_separating", VEC_COLLIDE, ALL, {0, 0}, {1, 0}, {0, 1}, {0, -1}, 1, 1, {0, 0}, 1},
    {"coincident_centres_degenerate", VEC_COLLIDE, ALL, {1, 1}, {1, 1}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 1},
    {"both_immovable_degenerate", VEC_COLLIDE, ALL, {0, 0}, {1, 0}, {1, 0}, {0, 0}, INF, INF, {0, 0}, 1},
    {"zero_normal_degenerate", VEC_COLLIDE_NORMAL, ALL, {0, 0}, {1, 0}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 1},
    {"nan_velocity_invalid", VEC_COLLIDE, D | F, {0, 0}, {1, 0}, {NAN, 0}, {0, 0}, 1, 1, {0, 0}, 1},
    {"infinite_position_invalid", VEC_COLLIDE, D | F, {-INF, 0}, {1, 0}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 1},
    {"nan_normal_invalid", VEC_COLLIDE_NORMAL, D | F, {0, 0}, {1, 0}, {1, 0}, {0, 0}, 1, 1, {NAN, 1}, 1},
    {"zero_mass_invalid", VEC_COLLIDE, ALL, {0, 0}, {1, 0}, {1, 0}, {0, 0}, 0, 1, {0, 0}, 1},
    {"negative_mass_invalid", VEC_COLLIDE, ALL, {0, 0}, {1, 0}, {1, 0}, {0, 0}, 1, -2, {0, 0}, 1},
    {"restitution_above_one_invalid", VEC_COLLIDE, ALL, {0, 0}, {1, 0}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 1.5},
    {"restitution_negative_invalid", VEC_COLLIDE, ALL, {0, 0}, {1, 0}, {1, 0}, {0, 0}, 1, 1, {0, 0}, -0.25},
    {"grazing_cancellation", VEC_COLLIDE, D, {0, 0}, {1, 1}, {1, -1 + 0x1p-40}, {0, 0}, 1, 1, {0, 0}, 1},
    {"grazing_cancellation_float", VEC_COLLIDE, F, {0, 0}, {1, 1}, {1, -1 + 0x1p-20}, {0, 0}, 1, 1, {0, 0}, 1},
    /* extremes, double */
    {"heavy_at_rest_gets_tiny_accurate_change", VEC_COLLIDE, D, {0, 0}, {1, 0}, {0, 0}, {-1, 0}, 1e300, 1, {0, 0}, 1},
    {"light_at_rest_hit_by_heavy", VEC_COLLIDE, D, {0, 0}, {1, 0}, {1, 0.5}, {0, 0}, 1e300, 1e-300, {0, 0}, 1},
    {"mass_ratio_beyond_double_range", VEC_COLLIDE, D, {0, 0}, {0, 1}, {0, 0}, {0, -DBL_MAX / 32}, DBL_MAX, 0x1p-1074, {0, 0}, 1},
    {"subnormal_normal", VEC_COLLIDE_NORMAL, D, {0, 0}, {0, 0}, {1, 2}, {-3, 0.5}, 2, 1, {0x1p-1074, 0x1p-1073}, 1},
    {"huge_normal", VEC_COLLIDE_NORMAL, D, {0, 0}, {0, 0}, {1, 2}, {-3, 0.5}, 2, 1, {DBL_MAX, DBL_MAX / 2}, 1},
    {"positions_far_apart_difference_overflows", VEC_COLLIDE, D, {-DBL_MAX, 0}, {DBL_MAX, 0}, {2, 1}, {-1, 3}, 1, 3, {0, 0}, 1},
    {"subnormal_position_difference", VEC_COLLIDE, D, {0, 0}, {0x1p-1074, 0}, {1, 1}, {0, 0}, 1, 1, {0, 0}, 1},
    {"subnormal_velocities", VEC_COLLIDE, D, {0, 0}, {1, 0}, {0x1p-1070, 0}, {-0x1p-1072, 0x1p-1074}, 1, 1, {0, 0}, 1},
    {"huge_velocities_no_overflow", VEC_COLLIDE, D, {0, 0}, {1, 1}, {1e306, 0}, {-1e306, 1e300}, 1, 1, {0, 0}, 0.5},
    {"result_overflows_range", VEC_COLLIDE, D, {0, 0}, {1, 0}, {0, 0}, {-DBL_MAX * 0.75, 0}, 1, 1e300, {0, 0}, 1},
    {"fast_tangential_heavy_slow_light", VEC_COLLIDE, D, {0, 0}, {0, 1}, {1e300, 0}, {0, -1e-300}, 1e10, 1, {0, 0}, 1},
    /* extremes, float */
    {"heavy_at_rest_float", VEC_COLLIDE, F, {0, 0}, {1, 0}, {0, 0}, {-1, 0}, 0x1p100, 1, {0, 0}, 1},
    {"mass_ratio_beyond_float_range", VEC_COLLIDE, F, {0, 0}, {0, 1}, {0, 0}, {0, -0x1p119}, FLT_MAX, 0x1p-149, {0, 0}, 1},
    {"subnormal_normal_float", VEC_COLLIDE_NORMAL, F, {0, 0}, {0, 0}, {1, 2}, {-3, 0.5}, 2, 1, {0x1p-149, 0x1p-148}, 1},
    {"result_overflows_range_float", VEC_COLLIDE, F, {0, 0}, {1, 0}, {0, 0}, {-0x1.8p127, 0}, 1, 0x1p100, {0, 0}, 1},
    /* time of impact: e = radius_sum, masses ignored */
    {"toi_head_on", VEC_TOI, ALL, {0, 0}, {10, 0}, {1, 0}, {-1, 0}, 1, 1, {0, 0}, 2},
    {"toi_oblique", VEC_TOI, ALL, {0, 0}, {5, 2}, {1, 0.5}, {-0.5, 0}, 1, 1, {0, 0}, 1},
    {"toi_miss", VEC_TOI, ALL, {0, 0}, {10, 5}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 2},
    {"toi_overlap_approaching_is_zero", VEC_TOI, ALL, {0, 0}, {1, 0}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 2},
    {"toi_overlap_receding_separating", VEC_TOI, ALL, {0, 0}, {1, 0}, {-1, 0}, {0, 0}, 1, 1, {0, 0}, 2},
    {"toi_receding", VEC_TOI, ALL, {0, 0}, {10, 0}, {-1, 0}, {0, 0}, 1, 1, {0, 0}, 2},
    {"toi_no_relative_motion", VEC_TOI, ALL, {0, 0}, {10, 0}, {1, 1}, {1, 1}, 1, 1, {0, 0}, 2},
    {"toi_far_apart_small_disks", VEC_TOI, D | F, {0, 0}, {1e6, 1}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 1.5},
    {"toi_far_apart_fixed", VEC_TOI, X, {0, 0}, {30000, 1}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 1.5},
    {"toi_negative_radius_invalid", VEC_TOI, ALL, {0, 0}, {10, 0}, {1, 0}, {0, 0}, 1, 1, {0, 0}, -1},
    {"toi_nan_position_invalid", VEC_TOI, D | F, {NAN, 0}, {10, 0}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 1},
    {"toi_huge_scale", VEC_TOI, D, {-1e300, 0}, {1e300, 0}, {1e300, 0}, {-1e300, 0}, 1, 1, {0, 0}, 1e299},
    {"toi_tiny_scale", VEC_TOI, D, {0, 0}, {0x1p-1060, 0x1p-1070}, {0x1p-1066, 0}, {0, 0}, 1, 1, {0, 0}, 0x1p-1064},
    {"toi_time_overflows_range", VEC_TOI, D, {-1e300, 0}, {1e300, 0}, {1e-300, 0}, {0, 0}, 1, 1, {0, 0}, 1},
};

static int representable_f(double x) { return isnan(x) || (double)(float)x == x || (isinf(x)); }
static int representable_x(double x) { return isfinite(x) && fabs(x) < 32768 && ldexp(x, 16) == floor(ldexp(x, 16)); }

static double round_q(const mpq_t q, int prec)
{
    mpfr_t f;
    double r;
    mpfr_init2(f, prec);
    mpfr_set_q(f, q, MPFR_RNDN);
    r = mpfr_get_d(f, MPFR_RNDN);
    mpfr_clear(f);
    return prec == 24 ? (double)(float)r : r;
}

static void print_num(FILE *o, double x, int variant)
{
    if (variant == X) {
        fprintf(o, "%ld", (long)x);
    } else if (isnan(x)) {
        fprintf(o, variant == F ? "(0.0f / 0.0f)" : "(0.0 / 0.0)");
    } else if (isinf(x)) {
        fprintf(o, variant == F ? "%s(1.0f / 0.0f)" : "%s(1.0 / 0.0)", x < 0 ? "-" : "");
    } else {
        fprintf(o, variant == F ? "%af" : "%a", x);
    }
}

static void print_arr(FILE *o, const double *x, int n, int variant)
{
    int i;
    fputc('{', o);
    for (i = 0; i < n; i++) {
        if (i) fputs(", ", o);
        print_num(o, x[i], variant);
    }
    fputc('}', o);
}

/* Q16.16 raw value of a real input; INFINITY mass -> C2D_FIXED_INFINITE_MASS. */
static double to_x(double v) { return isinf(v) ? (double)INT32_MAX : ldexp(v, 16); }

static int emit(FILE *o, const gcase *c, int variant)
{
    int prec = variant == F ? 24 : 53, emin = variant == F ? -126 : -1022;
    double limit = variant == F ? FLT_MAX : variant == X ? 32768.0 : DBL_MAX;
    ref_case rc;
    ref_answer ans;
    double out[4], tol[4];
    int status, i;
    double in[12] = {c->pa[0], c->pa[1], c->pb[0], c->pb[1], c->va[0], c->va[1], c->vb[0], c->vb[1], c->n[0], c->n[1], c->e, 0};
    /* A case runs in every variant it names, on exactly its inputs: one that
     * a variant cannot represent is a mistake in the table, not a case to
     * drop. */
    for (i = 0; i < 11; i++)
        if ((variant == F && !representable_f(in[i])) || (variant == X && !representable_x(in[i]))) {
            fprintf(stderr, "gen_vectors: %s: input %d (%a) is not exact in the %s variant\n", c->name, i, in[i],
                    variant == F ? "float" : "Q16.16");
            return -1;
        }
    if ((variant == F && (!representable_f(c->ma) || !representable_f(c->mb))) ||
        (variant == X && ((!isinf(c->ma) && !representable_x(c->ma)) || (!isinf(c->mb) && !representable_x(c->mb))))) {
        fprintf(stderr, "gen_vectors: %s: a mass is not exact in the %s variant\n", c->name,
                variant == F ? "float" : "Q16.16");
        return -1;
    }
    memcpy(rc.pa, c->pa, sizeof rc.pa);
    memcpy(rc.pb, c->pb, sizeof rc.pb);
    memcpy(rc.va, c->va, sizeof rc.va);
    memcpy(rc.vb, c->vb, sizeof rc.vb);
    memcpy(rc.n, c->n, sizeof rc.n);
    rc.ma = variant == F ? (double)(float)c->ma : c->ma;
    rc.mb = variant == F ? (double)(float)c->mb : c->mb;
    rc.has_normal = c->kind == VEC_COLLIDE_NORMAL;
    rc.e = c->e;
    out[0] = c->va[0];
    out[1] = c->va[1];
    out[2] = c->vb[0];
    out[3] = c->vb[1];
    memset(tol, 0, sizeof tol);
    if (c->kind == VEC_TOI) {
        double t = 0, unit = 0;
        status = (int)ref_time_of_impact(&rc, c->e, &t, &unit, prec, emin);
        if (status == C2D_OK) {
            double tl = variant == F ? FLT_MAX : DBL_MAX;
            if (variant == X) {
                /* 2 steps + the time to close 2^-16 + |d| 2^-27 of distance, in steps */
                double dist = hypot(c->pb[0] - c->pa[0], c->pb[1] - c->pa[1]);
                double close_time = (unit - ref_ulp(fabs(t), 53, -1022)) / ref_ulp(dist, 53, -1022) *
                                    (0x1p-16 + dist * 0x1p-27);
                tl = 32767.0;
                out[0] = nearbyint(ldexp(t, 16));
                tol[0] = 2 + ceil(ldexp(close_time, 16));
            } else {
                out[0] = variant == F ? (double)(float)t : t;
                tol[0] = 4 * unit;
            }
            if (t > tl) status = C2D_RANGE;
        }
        if (status != C2D_OK) out[0] = 0;
        out[1] = out[2] = out[3] = 0;
    } else {
        ref_answer_init(&ans);
        ref_collide(&rc, limit, &ans);
        status = (int)ans.status;
        if (status == C2D_OK && ans.range_allowed && !ans.range_required) {
            fprintf(stderr, "gen_vectors: %s is ambiguous (RANGE allowed but not required)\n", c->name);
            ref_answer_clear(&ans);
            return -1;
        }
        if (status == C2D_OK && ans.range_required) status = C2D_RANGE;
        if (status == C2D_OK) {
            double got[4];
            for (i = 0; i < 4; i++) got[i] = round_q(ans.v[i], prec);
            for (i = 0; i < 4; i++) {
                const double *v = i < 2 ? c->va : c->vb;
                double s = fmax(fmax(fabs(v[0]), fabs(v[1])), fmax(fabs(got[2 * (i / 2)]), fabs(got[2 * (i / 2) + 1])));
                if (variant == X) {
                    /* 3 steps + 2^-24 S, S the largest |velocity component| of either body */
                    double sx = fmax(fmax(fmax(fabs(c->va[0]), fabs(c->va[1])), fmax(fabs(c->vb[0]), fabs(c->vb[1]))),
                                     fmax(fmax(fabs(got[0]), fabs(got[1])), fmax(fabs(got[2]), fabs(got[3]))));
                    out[i] = nearbyint(ldexp(mpq_get_d(ans.v[i]), 16));
                    tol[i] = 3 + floor(ldexp(sx, 16) * 0x1p-24);
                } else {
                    out[i] = got[i];
                    tol[i] = 16 * ref_ulp(s, prec, emin);
                }
            }
        } else if (variant == X) {
            for (i = 0; i < 4; i++) out[i] = ldexp(out[i], 16);
        }
        ref_answer_clear(&ans);
    }
    if (variant == X && c->kind != VEC_TOI && status != C2D_OK) {
        /* untouched velocities, already converted above */
    }
    fprintf(o, "    {\"%s\", %d, ", c->name, c->kind);
    if (variant == X) {
        double pa[2] = {to_x(c->pa[0]), to_x(c->pa[1])}, pb[2] = {to_x(c->pb[0]), to_x(c->pb[1])};
        double va[2] = {to_x(c->va[0]), to_x(c->va[1])}, vb[2] = {to_x(c->vb[0]), to_x(c->vb[1])};
        double n[2] = {to_x(c->n[0]), to_x(c->n[1])};
        print_arr(o, pa, 2, X), fputs(", ", o), print_arr(o, pb, 2, X), fputs(", ", o);
        print_arr(o, va, 2, X), fputs(", ", o), print_arr(o, vb, 2, X), fputs(", ", o);
        print_num(o, to_x(c->ma), X), fputs(", ", o), print_num(o, to_x(c->mb), X), fputs(", ", o);
        print_arr(o, n, 2, X), fputs(", ", o), print_num(o, to_x(c->e), X);
    } else {
        print_arr(o, c->pa, 2, variant), fputs(", ", o), print_arr(o, c->pb, 2, variant), fputs(", ", o);
        print_arr(o, c->va, 2, variant), fputs(", ", o), print_arr(o, c->vb, 2, variant), fputs(", ", o);
        print_num(o, c->ma, variant), fputs(", ", o), print_num(o, c->mb, variant), fputs(", ", o);
        print_arr(o, c->n, 2, variant), fputs(", ", o), print_num(o, c->e, variant);
    }
    fprintf(o, ",\n     %d, ", status);
    print_arr(o, out, 4, variant), fputs(", ", o), print_arr(o, tol, 4, variant);
    fputs("},\n", o);
    return 1;
}

/* ------------------------------------------------------------ the models */

/* A rough disk: pos.x, pos.y, vel.x, vel.y, spin, mass, radius, inertia. */
typedef struct grcase {
    const char *name;
    int normal_given, variants;
    double a[8], b[8], n[2], s[3]; /* s: restitution, friction, tangential restitution */
} grcase;

/* Cue-ball sizes (radius 1, solid-ball inertia 2/5 m r^2 = 0.4); rolling:
 * spin r = -v along the line of travel (t^ of +x motion is +y). */
static const grcase rough_cases[] = {
    /* name, normal given, variants, a, b, n, {e, mu, beta} */
    {"rolling_ball_hits_resting_ball", 0, D | F, {0, 0, 2, 0, 0, 1, 1, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {0.9375, 0.0625, 0.5}},
    {"cut_shot_throws_object_ball", 0, D | F, {0, 0, 2, 0.5, -3, 1, 1, 0.375}, {1.5, 1.25, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {0.9375, 0.0625, 0.5}},
    {"sticking_contact_point_stops", 0, D | F, {0, 0, 1, 1, 0, 1, 1, 0.5}, {2, 0, -1, 0, 0, 2, 1, 1}, {0, 0}, {0.5, 1e6, 0}},
    {"sliding_coulomb_impulse", 0, D | F, {0, 0, 1, 4, 0, 1, 1, 0.5}, {2, 0, -1, 0, 3, 2, 1, 1}, {0, 0}, {0.75, 0.125, 0.5}},
    {"perfectly_rough_elastic", 0, D | F, {0, 0, 1, 0.5, 2, 1, 0.5, 0.125}, {1, 0, -0.5, 0, -1, 3, 0.5, 0.375}, {0, 0}, {1, INF, 1}},
    {"frictionless_equals_collide", 0, D | F, {0, 0, 1, 0.5, 2, 1, 0.5, 0.125}, {1, 1, -0.5, 0, -1, 3, 0.5, 0.375}, {0, 0}, {0.875, 0, 1}},
    {"smooth_beta_equals_collide", 0, D | F, {0, 0, 1, 0.5, 2, 1, 0.5, 0.125}, {1, 1, -0.5, 0, -1, 3, 0.5, 0.375}, {0, 0}, {0.875, 1, -1}},
    {"cushion_english_reverses_spin", 1, D | F, {0, 0, 3, 1, 5, 1, 1, 0.375}, {1, 0, 0, 0, 0, INF, 0, INF}, {1, 0}, {0.75, 0.25, 0.25}},
    {"cushion_oblique_normal", 1, D | F, {0, 0, 1, -2, -1, 1, 0.5, 0.125}, {0, 0, 0, 0, 0, INF, 0, INF}, {-3, -4}, {1, 0.5, 0}},
    {"infinite_inertia_keeps_spin", 0, D | F, {0, 0, 2, 1, 3, 1, 1, INF}, {2, 0, 0, 0, -1, 1, 1, 0.5}, {0, 0}, {1, 0.5, 0.5}},
    {"points_radius_zero_spins_unchanged", 0, D | F, {0, 0, 2, 1, 3, 1, 0, 0.5}, {1, 0, 0, 0, -1, 1, 0, 0.5}, {0, 0}, {1, 0.5, 0.5}},
    {"gap_between_disks", 0, D | F, {0, 0, 1, 1, 0, 1, 0.25, 0.03125}, {4, 0, -1, 0, 0, 1, 0.5, 0.125}, {0, 0}, {1, 1, 1}},
    {"separating_untouched", 0, D | F, {0, 0, -1, 0, 5, 1, 1, 0.375}, {2, 0, 1, 0, 0, 1, 1, 0.375}, {0, 0}, {1, 0.25, 0.5}},
    {"coincident_centres_degenerate", 0, D | F, {1, 1, 1, 0, 0, 1, 1, 0.375}, {1, 1, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1, 0.25, 0.5}},
    {"both_immovable_degenerate", 0, D | F, {0, 0, 1, 0, 0, INF, 1, INF}, {2, 0, 0, 0, 0, INF, 1, INF}, {0, 0}, {1, 0.25, 0.5}},
    {"zero_normal_degenerate", 1, D | F, {0, 0, 1, 0, 0, 1, 1, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1, 0.25, 0.5}},
    {"negative_radius_invalid", 0, D | F, {0, 0, 1, 0, 0, 1, -1, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1, 0.25, 0.5}},
    {"zero_inertia_invalid", 0, D | F, {0, 0, 1, 0, 0, 1, 1, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0}, {0, 0}, {1, 0.25, 0.5}},
    {"nan_spin_invalid", 0, D | F, {0, 0, 1, 0, NAN, 1, 1, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1, 0.25, 0.5}},
    {"infinite_radius_invalid", 0, D | F, {0, 0, 1, 0, 0, 1, INF, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1, 0.25, 0.5}},
    {"negative_friction_invalid", 0, D | F, {0, 0, 1, 0, 0, 1, 1, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1, -0.25, 0.5}},
    {"nan_friction_invalid", 0, D | F, {0, 0, 1, 0, 0, 1, 1, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1, NAN, 0.5}},
    {"beta_above_one_invalid", 0, D | F, {0, 0, 1, 0, 0, 1, 1, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1, 0.25, 1.5}},
    {"restitution_above_one_invalid", 0, D | F, {0, 0, 1, 0, 0, 1, 1, 0.375}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1.5, 0.25, 0.5}},
    /* rolling contact: the slip speed cancels to ~0 at a high speed */
    {"rolling_contact_fast", 0, D, {0, 0, 1e12, 0, 0, 1, 1, 0.375}, {2, 0, -1e12, 1e12, 1e12 - 0x1p-12, 1, 1, 0.375}, {0, 0}, {1, 0.5, 0.5}},
    {"rolling_contact_fast_float", 0, F, {0, 0, 1e6, 0, 0, 1, 1, 0.375}, {2, 0, -1e6, 1e6, 1e6 - 0.0625, 1, 1, 0.375}, {0, 0}, {1, 0.5, 0.5}},
    /* extremes, double */
    {"huge_speeds_and_spins", 0, D, {0, 0, 1e300, 1e299, -1e300, 1, 1, 0.5}, {1, 1, -1e300, 0, 1e300, 2, 1, 1}, {0, 0}, {0.5, 0.5, 0.5}},
    {"tiny_subnormal_speeds", 0, D, {0, 0, 0x1p-1060, 0, 0x1p-1062, 1, 1, 0.5}, {1, 0, -0x1p-1061, 0x1p-1070, 0, 1, 1, 0.5}, {0, 0}, {1, 1, 1}},
    {"mass_ratio_huge", 0, D, {0, 0, 1, 1, 1, 1e300, 1, 4e299}, {2, 0, -1, 0, 3, 1e-300, 1, 4e-301}, {0, 0}, {1, 0.5, 0.5}},
    {"radius_tiny_spin_huge", 0, D, {0, 0, 1, 1, 1e300, 1, 1e-300, 0x1p-1074}, {2, 0, 0, 0, 0, 1, 1, 0.375}, {0, 0}, {1, 0.5, 0.5}},
    {"result_overflows_range", 0, D, {0, 0, 0, 0, 0, 1, 1, 0.375}, {1, 0, -DBL_MAX * 0.75, 0, 0, 1e300, 1, 4e299}, {0, 0}, {1, 0, 1}},
    /* extremes, float */
    {"huge_speeds_and_spins_float", 0, F, {0, 0, 0x1p100, 0x1p97, -0x1p100, 1, 1, 0.5}, {1, 1, -0x1p100, 0, 0x1p100, 2, 1, 1}, {0, 0}, {0.5, 0.5, 0.5}},
    {"tiny_subnormal_speeds_float", 0, F, {0, 0, 0x1p-140, 0, 0x1p-142, 1, 1, 0.5}, {1, 0, -0x1p-141, 0x1p-149, 0, 1, 1, 0.5}, {0, 0}, {1, 1, 1}},
    {"result_overflows_range_float", 0, F, {0, 0, 0, 0, 0, 1, 1, 0.375}, {1, 0, -0x1.8p127, 0, 0, 0x1p100, 1, 0x1p98}, {0, 0}, {1, 0, 1}},
};

/* Time of impact under acceleration: positions, velocities, accelerations
 * of a and b, radius sum, horizon. */
typedef struct gacase {
    const char *name;
    int variants;
    double pa[2], va[2], aa[2], pb[2], vb[2], ab[2], r, h;
} gacase;

static const gacase accel_cases[] = {
    /* name, variants, pa, va, aa, pb, vb, ab, radius_sum, horizon */
    {"decelerating_ball_reaches_resting", D | F, {0, 0}, {4, 0}, {-1, 0}, {6, 0}, {0, 0}, {0, 0}, 2, INF},
    {"decelerating_ball_stops_short", D | F, {0, 0}, {2, 0}, {-1, 0}, {6, 0}, {0, 0}, {0, 0}, 2, INF},
    {"both_decelerating_oblique", D | F, {0, 0}, {3, 1}, {-0.5, -0.25}, {8, 3}, {-2, -1}, {0.5, 0.25}, 1, INF},
    {"zero_acceleration_is_linear", D | F, {0, 0}, {1, 0}, {0, 0}, {10, 0}, {-1, 0}, {0, 0}, 2, INF},
    {"same_acceleration_is_linear", D | F, {0, 0}, {1, 0.5}, {-3, 7}, {5, 2}, {-0.5, 0}, {-3, 7}, 1, INF},
    {"at_rest_accelerated_together", D | F, {0, 0}, {0, 0}, {1, 0}, {5, 0}, {0, 0}, {-1, 0}, 1, INF},
    {"horizon_ends_before_contact", D | F, {0, 0}, {0, 0}, {1, 0}, {5, 0}, {0, 0}, {-1, 0}, 1, 1.9375},
    {"horizon_ends_after_contact", D | F, {0, 0}, {0, 0}, {1, 0}, {5, 0}, {0, 0}, {-1, 0}, 1, 2.0625},
    {"touch_exactly_at_horizon", D | F, {0, 0}, {0, 0}, {1, 0}, {5, 0}, {0, 0}, {-1, 0}, 1, 2},
    {"zero_horizon_apart", D | F, {0, 0}, {1, 0}, {0, 0}, {5, 0}, {0, 0}, {0, 0}, 1, 0},
    {"overlap_approaching_is_zero", D | F, {0, 0}, {1, 0}, {-1, 0}, {1, 0}, {0, 0}, {0, 0}, 2, 0},
    {"overlap_receding_turns_back", D | F, {0, 0}, {-1, 0}, {1, 0}, {1, 0}, {0, 0}, {0, 0}, 2, INF},
    {"overlap_receding_leaves", D | F, {0, 0}, {-2, 0}, {1, 0}, {1, 0}, {0, 0}, {0, 0}, 2, INF},
    {"touching_separating_at_zero", D | F, {0, 0}, {-1, 0}, {0, 0}, {2, 0}, {0, 0}, {0, 0}, 2, INF},
    {"touching_pushed_together", D | F, {0, 0}, {0, 0}, {1, 0}, {2, 0}, {0, 0}, {0, 0}, 2, INF},
    {"touching_tangential_stays", D | F, {0, 0}, {0, 1}, {0, 0}, {2, 0}, {0, 1}, {0, 0}, 2, INF},
    {"exact_graze_is_no_contact", D | F, {0, 0}, {0, 0}, {0, 0}, {-4, 2}, {4, 0}, {-2, 0}, 2, INF},
    {"near_miss_curved_path", D | F, {0, 0}, {0, 0}, {0, 0}, {-4, 2.125}, {4, 0}, {-2, 0}, 2, INF},
    {"recedes_then_returns", D | F, {0, 0}, {0, 0}, {0, 0}, {3, 0.5}, {2, 0}, {-2, 0}, 1, INF},
    {"accelerates_into_contact_from_behind", D | F, {0, 0}, {0, 0}, {0.25, 0}, {20, 0.5}, {1, 0}, {0, 0}, 1, INF},
    {"no_relative_motion", D | F, {0, 0}, {1, 1}, {2, 2}, {10, 0}, {1, 1}, {2, 2}, 2, INF},
    {"far_apart_small_disks", D | F, {0, 0}, {0, 0}, {1, 0}, {1e6, 1}, {0, 0}, {0, 0}, 1.5, INF},
    {"nan_acceleration_invalid", D | F, {0, 0}, {1, 0}, {NAN, 0}, {10, 0}, {0, 0}, {0, 0}, 1, INF},
    {"infinite_acceleration_invalid", D | F, {0, 0}, {1, 0}, {0, 0}, {10, 0}, {0, 0}, {0, -INF}, 1, INF},
    {"nan_velocity_invalid", D | F, {0, 0}, {NAN, 0}, {0, 0}, {10, 0}, {0, 0}, {0, 0}, 1, INF},
    {"negative_radius_invalid", D | F, {0, 0}, {1, 0}, {0, 0}, {10, 0}, {0, 0}, {0, 0}, -1, INF},
    {"infinite_radius_invalid", D | F, {0, 0}, {1, 0}, {0, 0}, {10, 0}, {0, 0}, {0, 0}, INF, INF},
    {"negative_horizon_invalid", D | F, {0, 0}, {1, 0}, {0, 0}, {10, 0}, {0, 0}, {0, 0}, 1, -1},
    {"nan_horizon_invalid", D | F, {0, 0}, {1, 0}, {0, 0}, {10, 0}, {0, 0}, {0, 0}, 1, NAN},
    /* extremes, double */
    {"huge_scale", D, {-1e300, 0}, {1e300, 0}, {-2.5e299, 0}, {1e300, 0}, {-1e300, 0}, {2.5e299, 0}, 1e299, INF},
    {"tiny_scale", D, {0, 0}, {0x1p-1066, 0}, {0x1p-1072, 0}, {0x1p-1060, 0x1p-1070}, {0, 0}, {0, 0}, 0x1p-1064, INF},
    {"time_beyond_range", D, {-1e300, 0}, {1e-300, 0}, {1, 0}, {1e300, 0}, {0, 0}, {1, 0}, 1, INF},
    {"acceleration_tiny_against_speed", D, {0, 0}, {1, 0}, {-0x1p-60, 0x1p-60}, {1e3, 0.5}, {0, 0}, {0, 0}, 1, INF},
    /* extremes, float */
    {"huge_scale_float", F, {-0x1p100, 0}, {0x1p100, 0}, {-0x1p98, 0}, {0x1p100, 0}, {-0x1p100, 0}, {0x1p98, 0}, 0x1p96, INF},
    {"tiny_scale_float", F, {0, 0}, {0x1p-140, 0}, {0x1p-146, 0}, {0x1p-134, 0x1p-144}, {0, 0}, {0, 0}, 0x1p-138, INF},
    {"time_beyond_range_float", F, {-0x1p100, 0}, {0x1p-100, 0}, {1, 0}, {0x1p100, 0}, {0, 0}, {1, 0}, 1, INF},
};

/* A tolerance rounded upward into the variant's format. */
static double tol_up(double x, int variant)
{
    if (variant == F) {
        float f = (float)x;
        return (double)f < x ? (double)nextafterf(f, INFINITY) : (double)f;
    }
    return x;
}

/* A model case must be exact in every format it is generated for: a case
 * that is not is an error, not silently left out. */
static int representable_all(const char *name, const double *x, int n, int variant)
{
    int i;
    for (i = 0; i < n; i++)
        if (variant == F && !representable_f(x[i])) {
            fprintf(stderr, "gen_vectors: %s: input %a is not a float\n", name, x[i]);
            return 0;
        }
    return 1;
}

static double mpfr_in(const mpfr_t x, int variant)
{
    return variant == F ? (double)mpfr_get_flt(x, MPFR_RNDN) : mpfr_get_d(x, MPFR_RNDN);
}

/* ulp, in the variant's format without an upper limit, of a body's scale:
 * the largest of |vx|, |vy|, |spin radius| before and after. */
static double body_ulp(const ref_disk *d, mpfr_srcptr vx, mpfr_srcptr vy, mpfr_srcptr spin, int prec, int emin)
{
    mpfr_t s, x;
    long ex = 0;
    mpfr_inits2(4400, s, x, (mpfr_ptr)0); /* as referee/ref_rough.c: every product exact */
    mpfr_set_d(s, fmax(fabs(d->vel[0]), fabs(d->vel[1])), MPFR_RNDN);
    mpfr_set_d(x, d->spin, MPFR_RNDN), mpfr_mul_d(x, x, d->radius, MPFR_RNDN), mpfr_abs(x, x, MPFR_RNDN);
    mpfr_max(s, s, x, MPFR_RNDN);
    mpfr_abs(x, vx, MPFR_RNDN), mpfr_max(s, s, x, MPFR_RNDN);
    mpfr_abs(x, vy, MPFR_RNDN), mpfr_max(s, s, x, MPFR_RNDN);
    mpfr_mul_d(x, spin, d->radius, MPFR_RNDN), mpfr_abs(x, x, MPFR_RNDN), mpfr_max(s, s, x, MPFR_RNDN);
    if (mpfr_zero_p(s)) ex = emin;
    else (void)mpfr_get_d_2exp(&ex, s, MPFR_RNDZ); /* s = f 2^ex, f in [0.5, 1) */
    if (ex - 1 < emin) ex = emin + 1;
    mpfr_clears(s, x, (mpfr_ptr)0);
    return ldexp(1.0, (int)(ex - 1 - (prec - 1)));
}

static void disk_in(ref_disk *d, const double *x)
{
    d->pos[0] = x[0], d->pos[1] = x[1], d->vel[0] = x[2], d->vel[1] = x[3];
    d->spin = x[4], d->mass = x[5], d->radius = x[6], d->inertia = x[7];
}

/* The outputs rounded to the variant and their tolerances (vectors.h). */
static void rough_expected(const ref_rough_case *rc, const ref_rough_answer *ans, int variant, double out[6],
                           double tol[6])
{
    const int prec = variant == F ? 24 : 53, emin = variant == F ? -126 : -1022;
    const ref_disk *d[2] = {&rc->a, &rc->b};
    int i;
    for (i = 0; i < 2; i++) {
        const double u = 18 * body_ulp(d[i], ans->out[2 * i], ans->out[2 * i + 1], ans->out[4 + i], prec, emin);
        out[2 * i] = mpfr_in(ans->out[2 * i], variant);
        out[2 * i + 1] = mpfr_in(ans->out[2 * i + 1], variant);
        out[4 + i] = mpfr_in(ans->out[4 + i], variant);
        tol[2 * i] = tol_up(u + ref_ulp(fabs(out[2 * i]), prec, emin) / 2, variant);
        tol[2 * i + 1] = tol_up(u + ref_ulp(fabs(out[2 * i + 1]), prec, emin) / 2, variant);
        /* u / radius rounded up: one ulp above the nearest double */
        tol[4 + i] = d[i]->radius == 0 ? 0
                     : tol_up(nextafter(u / d[i]->radius, INFINITY) + ref_ulp(fabs(out[4 + i]), prec, emin) / 2,
                              variant);
    }
}

static int emit_rough(FILE *o, const grcase *c, int variant)
{
    const double limit = variant == F ? FLT_MAX : DBL_MAX;
    ref_rough_case rc;
    ref_rough_answer ans;
    double out[6] = {c->a[2], c->a[3], c->b[2], c->b[3], c->a[4], c->b[4]}, tol[6] = {0, 0, 0, 0, 0, 0};
    int status;
    if (!representable_all(c->name, c->a, 8, variant) || !representable_all(c->name, c->b, 8, variant) ||
        !representable_all(c->name, c->n, 2, variant) || !representable_all(c->name, c->s, 3, variant))
        return -1;
    disk_in(&rc.a, c->a), disk_in(&rc.b, c->b);
    rc.n[0] = c->n[0], rc.n[1] = c->n[1];
    rc.has_normal = c->normal_given;
    rc.e = c->s[0], rc.mu = c->s[1], rc.beta = c->s[2];
    ref_rough_init(&ans);
    ref_rough(&rc, limit, &ans);
    status = (int)ans.status;
    if (status == C2D_OK && ans.range_allowed && !ans.range_required) {
        fprintf(stderr, "gen_vectors: %s is ambiguous (RANGE allowed but not required)\n", c->name);
        ref_rough_clear(&ans);
        return -1;
    }
    if (status == C2D_OK && ans.range_required) status = C2D_RANGE;
    if (status == C2D_OK) rough_expected(&rc, &ans, variant, out, tol);
    ref_rough_clear(&ans);
    fprintf(o, "    {\"%s\", %d, ", c->name, c->normal_given);
    print_arr(o, c->a, 8, variant), fputs(", ", o), print_arr(o, c->b, 8, variant), fputs(", ", o);
    print_arr(o, c->n, 2, variant), fputs(", ", o), print_arr(o, c->s, 3, variant);
    fprintf(o, ",\n     %d, ", status);
    print_arr(o, out, 6, variant), fputs(", ", o), print_arr(o, tol, 6, variant);
    fputs("},\n", o);
    return 1;
}

/* Within the contract's tie band (referee/cases_toi_accel.h) but not an
 * exact tie (a distance exactly radius_sum at its minimum, or a radial speed
 * exactly 0 at its extremum, which the contract decides as a tie): no
 * certain answer, so not a vector. */
static int in_tie_band(const ref_toia_out *r, const gacase *c, int variant)
{
    const double ef = variant == F ? TOIA_EPS_F_FLOAT : TOIA_EPS_F_DOUBLE;
    const double eg = variant == F ? TOIA_EPS_G_FLOAT : TOIA_EPS_G_DOUBLE;
    const int accelerations_differ = c->aa[0] != c->ab[0] || c->aa[1] != c->ab[1];
    if (r->tie_f == 0 || r->tie_g == 0) return 0;
    if (r->tie_f <= ef || r->tie_g <= eg) return 1;
    return accelerations_differ && (r->tie_fs <= TOIA_K_RES || r->tie_gs <= TOIA_K_RES);
}

static int emit_accel(FILE *o, const gacase *c, int variant)
{
    const int prec = variant == F ? 24 : 53, emin = variant == F ? -126 : -1022;
    const double scalars[2] = {c->r, c->h};
    ref_toia_in in;
    ref_toia_out r;
    double t = 0, tol = 0;
    int status, i;
    if (!representable_all(c->name, c->pa, 2, variant) || !representable_all(c->name, c->va, 2, variant) ||
        !representable_all(c->name, c->aa, 2, variant) || !representable_all(c->name, c->pb, 2, variant) ||
        !representable_all(c->name, c->vb, 2, variant) || !representable_all(c->name, c->ab, 2, variant) ||
        !representable_all(c->name, scalars, 2, variant))
        return -1;
    for (i = 0; i < 2; i++) {
        in.pa[i] = c->pa[i], in.va[i] = c->va[i], in.aa[i] = c->aa[i];
        in.pb[i] = c->pb[i], in.vb[i] = c->vb[i], in.ab[i] = c->ab[i];
    }
    in.r = c->r, in.h = c->h;
    ref_toia_init(&r);
    ref_toia(&in, prec, emin, &r);
    status = (int)r.status;
    if (in_tie_band(&r, c, variant)) {
        fprintf(stderr, "gen_vectors: %s lies in the tie band (tie_f %g tie_g %g tie_fs %g tie_gs %g)\n", c->name,
                r.tie_f, r.tie_g, r.tie_fs, r.tie_gs);
        ref_toia_clear(&r);
        return -1;
    }
    if (status == C2D_OK) {
        t = mpfr_in(r.t, variant);
        tol = tol_up(r.unit + ref_ulp(t, prec, emin) / 2, variant);
    }
    ref_toia_clear(&r);
    fprintf(o, "    {\"%s\", ", c->name);
    print_arr(o, c->pa, 2, variant), fputs(", ", o), print_arr(o, c->va, 2, variant), fputs(", ", o);
    print_arr(o, c->aa, 2, variant), fputs(", ", o), print_arr(o, c->pb, 2, variant), fputs(", ", o);
    print_arr(o, c->vb, 2, variant), fputs(", ", o), print_arr(o, c->ab, 2, variant), fputs(", ", o);
    print_num(o, c->r, variant), fputs(", ", o), print_num(o, c->h, variant);
    fprintf(o, ",\n     %d, ", status);
    print_num(o, t, variant), fputs(", ", o), print_num(o, tol, variant);
    fputs("},\n", o);
    return 1;
}

/* One model table of one variant: "const TYPE NAME[] = {...}; COUNT". */
static int emit_model_table(FILE *o, int variant, int rough, const char *suffix)
{
    const char *what = rough ? "rough" : "accel";
    size_t i, n_cases = rough ? sizeof rough_cases / sizeof rough_cases[0] : sizeof accel_cases / sizeof accel_cases[0];
    int n = 0, r;
    fprintf(o, "const c2d_%s_vector_%s c2d_%s_vectors_%s[] = {\n", what, suffix, what, suffix);
    for (i = 0; i < n_cases; i++) {
        if (rough && (rough_cases[i].variants & variant)) r = emit_rough(o, &rough_cases[i], variant);
        else if (!rough && (accel_cases[i].variants & variant)) r = emit_accel(o, &accel_cases[i], variant);
        else continue;
        if (r < 0) return -1;
        n += r;
    }
    fprintf(o, "};\nconst int c2d_%s_vector_count_%s = %d;\n", what, suffix, n);
    return n;
}

int main(int argc, char **argv)
{
    static const struct { int v; const char *type, *table, *count, *guard; } tab[] = {
        {D, "c2d_vector_d", "c2d_vectors_d", "c2d_vector_count_d", "C2D_NO_DOUBLE"},
        {F, "c2d_vector_f", "c2d_vectors_f", "c2d_vector_count_f", "C2D_NO_FLOAT"},
        {X, "c2d_vector_x", "c2d_vectors_x", "c2d_vector_count_x", "C2D_NO_FIXED"},
    };
    FILE *o = argc > 1 ? fopen(argv[1], "w") : stdout;
    size_t i, t;
    if (!o) return 2;
    fputs("/* SPDX-License-Identifier: MIT */\n"
          "/* Generated by tests/vectors/gen_vectors.c from the exact referee: do not edit. */\n"
          "#include \"vectors.h\"\n", o);
    for (t = 0; t < 3; t++) {
        int n = 0;
        fprintf(o, "\n#ifndef %s\nconst %s %s[] = {\n", tab[t].guard, tab[t].type, tab[t].table);
        for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            int r;
            if (!(cases[i].variants & tab[t].v)) continue;
            r = emit(o, &cases[i], tab[t].v);
            if (r < 0) return 1;
            n += r;
        }
        fprintf(o, "};\nconst int %s = %d;\n", tab[t].count, n);
        if (tab[t].v != X) {
            const char *suffix = tab[t].v == D ? "d" : "f";
            fputc('\n', o);
            if (emit_model_table(o, tab[t].v, 1, suffix) < 0) return 1;
            fputc('\n', o);
            if (emit_model_table(o, tab[t].v, 0, suffix) < 0) return 1;
        }
        fputs("#endif\n", o);
    }
    if (o != stdout) fclose(o);
    return 0;
}
