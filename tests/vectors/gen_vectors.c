/* Generates tests/vectors/vectors.c from the case list below, with every
 * expected value and tolerance computed by the exact referee
 * (referee/referee.c).  Run: make vectors.  `make test` regenerates the table
 * and requires it unchanged (check-vectors), so the committed table cannot
 * drift from the referee. */
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
    {"heavy_at_rest_float", VEC_COLLIDE, F, {0, 0}, {1, 0}, {0, 0}, {-1, 0}, 1e30, 1, {0, 0}, 1},
    {"mass_ratio_beyond_float_range", VEC_COLLIDE, F, {0, 0}, {0, 1}, {0, 0}, {0, -1e36}, FLT_MAX, 0x1p-149, {0, 0}, 1},
    {"subnormal_normal_float", VEC_COLLIDE_NORMAL, F, {0, 0}, {0, 0}, {1, 2}, {-3, 0.5}, 2, 1, {0x1p-149, 0x1p-148}, 1},
    {"result_overflows_range_float", VEC_COLLIDE, F, {0, 0}, {1, 0}, {0, 0}, {-FLT_MAX * 0.75, 0}, 1, 1e30, {0, 0}, 1},
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
    for (i = 0; i < 11; i++) {
        if (variant == F && !representable_f(in[i])) return 0;
        if (variant == X && !representable_x(in[i])) return 0;
    }
    if (variant == X && ((!isinf(c->ma) && !representable_x(c->ma)) || (!isinf(c->mb) && !representable_x(c->mb))))
        return 0;
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
    fputs("/* Generated by tests/vectors/gen_vectors.c from the exact referee: do not edit. */\n"
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
        fprintf(o, "};\nconst int %s = %d;\n#endif\n", tab[t].count, n);
    }
    if (o != stdout) fclose(o);
    return 0;
}
