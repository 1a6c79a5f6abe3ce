/* SPDX-License-Identifier: MIT */
/* collide2d speed-for-accuracy benchmark.  See bench/bench.mk.
 *   bench [--results FILE] [--plot-data FILE] [--ir FILE] [--flags TEXT]
 *         [--sizes FILE] [--plain N] [--extreme N] [--rounds N]
 *         [--ratio-rounds N] [--large N]
 *   bench --smoke        quick self-check for `make test`
 *   bench --ratios-only ROUNDS   the interleaved ratios alone, briefly (ratio.c)
 *   bench --callgrind    driver for valgrind --tool=callgrind (client requests) */
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "box2d_contender.h"
#include "old.h"

int bench_smoke(void);

#define PAIRS_IN_CACHE 4096
#define BENCH_OLD_REV_TEXT "commit " BENCH_OLD_REV
#define CALLGRIND_PAIRS 1024
/* calls per contender in the time of impact's callgrind passes */
#define TOIA_CALLGRIND_CALLS 1024
#define MAXK 32

typedef struct options {
    const char *results, *plot_data, *ir, *flags, *sizes;
    int n_plain, n_extreme, rounds, ratio_rounds;
    size_t n_large;
} options;

/* Code size per call site (bench/callsite.c, nm -S): [var, one][variant]. */
typedef struct site_sizes {
    int found;
    long call[2][GV_COUNT], inl[2][GV_COUNT];
} site_sizes;

typedef struct results {
    acc_stats acc[MAXK][2];     /* plain, extreme */
    int has_acc[MAXK][2];
    acc_stats eq[MAXK];         /* equal masses, e = 1 */
    int has_eq[MAXK];
    acc_stats general[MAXK];    /* equal-mass-only formulas on general masses */
    double ns[2][MAXK + 1];     /* random plain, impacts; last slot: empty call */
    double ir[2][MAXK + 1];     /* instructions per collision (-1: unknown) */
    double slow_share[2];
    int quiet_rounds[2], rounds_run[2]; /* the speed table's quiet rounds of those run (random, impacts) */
    roof_result roof[2];        /* double, float */
    ratios rat;                 /* the speed goals' interleaved ratios */
    rough_stats rough[RK_COUNT][2]; /* plain, extreme */
    toi_stats toi[TK_COUNT][2][2];  /* [contender][double, float][ordinary, extreme] */
    toia_stats toia[TA_COUNT];      /* time of impact under acceleration */
    toia_stats toia_touch[TA_COUNT]; /* the same on touching pool balls */
    site_sizes sizes;
} results;

/* ------------------------------------------------------------ inputs */

static ref_case *timing_cases(int impacts, unsigned long long seed)
{
    ref_case *c = malloc(PAIRS_IN_CACHE * sizeof *c);
    c2d_rng r;
    int i;
    r.s = seed;
    for (i = 0; i < PAIRS_IN_CACHE; i++) {
        if (impacts) gen_impact(&r, &c[i]);
        else gen_plain(&r, &c[i]);
        c[i].e = 1.0;
        c[i].has_normal = 0;
    }
    return c;
}

/* Every "<name> <total Ir>" line (made from callgrind dumps). */
#define MAXIR 1024
static struct ir_entry { char name[200]; double v; } ir_tab[MAXIR];
static int n_ir;

static double ir_get(const char *name)
{
    int i;
    for (i = 0; i < n_ir; i++)
        if (strcmp(ir_tab[i].name, name) == 0) return ir_tab[i].v;
    return -1;
}

/* Reads the dumps; the contenders' rows are "<label>/<id>". */
static void read_ir(const char *path, results *res)
{
    char line[256], name[200];
    int s, j;
    FILE *f = path ? fopen(path, "r") : NULL;
    for (s = 0; s < 2; s++)
        for (j = 0; j <= MAXK; j++) res->ir[s][j] = -1;
    if (f == NULL) return;
    while (fgets(line, sizeof line, f)) {
        double v;
        if (sscanf(line, "%199s %lf", name, &v) != 2 || n_ir == MAXIR) continue;
        snprintf(ir_tab[n_ir].name, sizeof ir_tab[n_ir].name, "%s", name);
        ir_tab[n_ir++].v = v;
    }
    fclose(f);
    for (s = 0; s < 2; s++) {
        char key[128];
        double base;
        snprintf(key, sizeof key, "%s/noop", s ? "impacts" : "plain");
        base = ir_get(key);
        for (j = 0; j <= bench_ncontenders; j++) {
            const char *id = j < bench_ncontenders ? bench_contenders[j].id : "noop";
            int batch = j < bench_ncontenders && (bench_contenders[j].kind == KIND_BATCH ||
                                                  bench_contenders[j].kind == KIND_BATCHF);
            double total;
            snprintf(key, sizeof key, "%s/%s", s ? "impacts" : "plain", id);
            total = ir_get(key);
            if (total < 0 || base < 0) continue;
            /* Scalar rows: beyond the empty call's loop; a batch is one call. */
            res->ir[s][j] = (total - (batch || j == bench_ncontenders ? 0 : base)) / CALLGRIND_PAIRS;
        }
    }
}

/* Instructions per call of a timed pass (callgrind), scalar passes less
 * the empty call's loop; -1 when unknown. */
static double ir_of(const ratios *r, const rstat *s, int scalar)
{
    double v = ir_get(s->id), base = ir_get(r->noop.id);
    if (v < 0 || (scalar && base < 0) || s->n <= 0) return -1;
    return (v - (scalar ? base : 0)) / s->n;
}

/* Instructions per call of a time-of-impact callgrind pass (toi_accel.c
 * toia_callgrind), less the loop's; -1 when unknown. */
static double toia_ir(const char *set, const char *who)
{
    char key[64];
    double v, base;
    snprintf(key, sizeof key, "toia/%s/%s", set, who);
    v = ir_get(key);
    snprintf(key, sizeof key, "toia/%s/noop", set);
    base = ir_get(key);
    return v < 0 || base < 0 ? -1 : (v - base) / TOIA_CALLGRIND_CALLS;
}

/* bench/callsite.o's function sizes (nm -S --defined-only). */
static void read_sizes(const char *path, site_sizes *z)
{
    static const char *const variant[GV_COUNT] = {"collide", "collidef", "normal", "normalf"};
    char line[256], name[200], type[8];
    unsigned long addr, size;
    FILE *f = path ? fopen(path, "r") : NULL;
    memset(z, 0, sizeof *z);
    if (f == NULL) return;
    while (fgets(line, sizeof line, f)) {
        int w, v;
        if (sscanf(line, "%lx %lx %7s %199s", &addr, &size, type, name) != 4) continue;
        for (w = 0; w < 2; w++)
            for (v = 0; v < GV_COUNT; v++) {
                char want[64];
                snprintf(want, sizeof want, "site_%s_call_%s", w ? "one" : "var", variant[v]);
                if (strcmp(name, want) == 0) z->call[w][v] = (long)size, z->found++;
                snprintf(want, sizeof want, "site_%s_inline_%s", w ? "one" : "var", variant[v]);
                if (strcmp(name, want) == 0) z->inl[w][v] = (long)size, z->found++;
            }
    }
    fclose(f);
}

/* ------------------------------------------------------------ measuring */

static void measure_accuracy(const case_set *sets, results *res)
{
    int j, x;
    for (j = 0; j < bench_ncontenders; j++) {
        const contender *k = &bench_contenders[j];
        for (x = 0; x < 2; x++) {
            const case_set *s = sets_for(sets, k, x);
            res->has_acc[j][x] = s != NULL;
            if (s) evaluate(k, s, &res->acc[j][x]);
        }
        res->has_eq[j] = k->kind == KIND_DOUBLE || k->kind == KIND_BATCH || k->kind == KIND_BOX2D;
        if (res->has_eq[j]) evaluate(k, &sets[SET_PLAIN_EQUAL], &res->eq[j]);
        if (k->equal_only) evaluate(k, &sets[SET_PLAIN], &res->general[j]);
    }
}

static void measure_speed(const options *o, results *res)
{
    int s;
    /* The ratios first: their long run finds the canary's best, against
     * which the speed table's rounds are judged quiet or busy. */
    ratios_measure(&res->rat, o->ratio_rounds, PAIRS_IN_CACHE, 0);
    for (s = 0; s < 2; s++) {
        ref_case *c = timing_cases(s, 1000 + (unsigned long long)s);
        timing_data *t = timing_make(c, PAIRS_IN_CACHE);
        res->slow_share[s] = timing_slow_share(c, PAIRS_IN_CACHE);
        timing_run(t, o->rounds, res->ns[s]);
        res->quiet_rounds[s] = timing_quiet_rounds, res->rounds_run[s] = timing_rounds_run;
        timing_free(t);
        free(c);
    }
    roof_run(0, o->n_large, 5, &res->roof[0]);
    roof_run(1, o->n_large, 5, &res->roof[1]);
}

static void measure_toi(const options *o, results *res)
{
    int k, p, x;
    for (k = 0; k < TK_COUNT; k++)
        for (p = 0; p < 2; p++)
            for (x = 0; x < 2; x++)
                if (k != TK_OLD || BENCH_HAVE_OLD())
                    toi_evaluate(k, p, x, (x ? o->n_extreme : o->n_plain) / 4, 8000 + 2 * (unsigned)p + (unsigned)x,
                                 &res->toi[k][p][x]);
}

/* Cases per family: the plain set's size spread over the 14 families. */
static void measure_toi_accel(const options *o, results *res)
{
    toia_measure(o->n_plain / 20 > 50 ? o->n_plain / 20 : 50, o->rounds / 4 > 11 ? o->rounds / 4 : 11, res->toia,
                 res->toia_touch);
}

static void measure_rough(const options *o, results *res)
{
    int k, x;
    for (k = 0; k < RK_COUNT; k++)
        for (x = 0; x < 2; x++)
            rough_evaluate(k, x, x ? o->n_extreme : o->n_plain, 7000 + (unsigned)x, &res->rough[k][x]);
}

static int run_callgrind_driver(void)
{
    int s;
    bench_box2d_init();
    for (s = 0; s < 2; s++) {
        ref_case *c = timing_cases(s, 1000 + (unsigned long long)s);
        timing_data *t = timing_make(c, PAIRS_IN_CACHE);
        callgrind_run(t, CALLGRIND_PAIRS, s == 0 ? "plain" : "impacts");
        timing_free(t);
        free(c);
    }
    {
        static ratios r;
        ratios_measure(&r, 1, PAIRS_IN_CACHE, 1);
    }
    toia_callgrind(TOIA_CALLGRIND_CALLS);
    bench_box2d_fini();
    return 0;
}

/* ------------------------------------------------------------ report */

static const char *fmt(double v, char *buf)
{
    if (isnan(v)) return "n/a";
    if (isinf(v)) return "inf";
    if (v == 0) return "0";
    if (v >= 0.01 && v < 1e5) snprintf(buf, 32, "%.3g", v);
    else snprintf(buf, 32, "%.2e", v);
    return buf;
}

static const char *unit_of(const contender *k)
{
    switch (k->kind) {
    case KIND_FLOAT:
    case KIND_BATCHF: return "float ulp";
    case KIND_FIXED: return "2^-16 step";
    case KIND_BOX2D: return "double ulp";
    default: return "double ulp";
    }
}

static void machine(FILE *f, const options *o)
{
    char line[512], model[256] = "unknown";
    FILE *ci = fopen("/proc/cpuinfo", "r");
    int cpus = 0;
    if (ci) {
        while (fgets(line, sizeof line, ci)) {
            if (strncmp(line, "model name", 10) == 0 && cpus++ == 0) {
                char *p = strchr(line, ':');
                if (p) snprintf(model, sizeof model, "%s", p + 2);
                model[strcspn(model, "\n")] = 0;
            }
        }
        fclose(ci);
    }
    fprintf(f, "Machine: %s, %d logical CPUs. Compiler: gcc %s. Library and bench built with `%s`",
            model, cpus, __VERSION__, o->flags ? o->flags : "(flags not given)");
    fprintf(f, " (the flags a user gets from `make`; with `-march=native` the library's TwoProduct "
               "uses FMA, results are bit-identical).");
    ci = fopen("/proc/loadavg", "r");
    if (ci) {
        double l1, l5, l15;
        if (fscanf(ci, "%lf %lf %lf", &l1, &l5, &l15) == 3)
            fprintf(f, " Load average when the report was written (1, 5, 15 min): %.2f, %.2f, %.2f; the timed "
                       "figures are medians of the quiet rounds, the instruction counts do not depend on the load.",
                    l1, l5, l15);
        fclose(ci);
    }
    fprintf(f, "\n\n");
}

static void accuracy_table(FILE *f, const results *res, const options *o)
{
    char b[10][32];
    int j;
    fprintf(f, "### Accuracy against the exact referee (GMP rationals)\n\n");
    fprintf(f, "%d plain cases (unit-scale scenes: masses 0.1-10, restitution 0, 1 or random) and %d "
               "extreme cases (magnitudes 2^k over the whole range incl. subnormals, mass ratios to "
               "1e600, INFINITY masses). Error: |result - exact| in ulp of each body's velocity scale, "
               "in the contender's own format, over the cases that are impacts (exact status OK and "
               "in range; a wrong status is counted, not folded into the error). Momentum: relative to the total |momentum|; energy: "
               "relative change, e = 1 cases only. Statuses, NaN and Inf: count of cases (plain / "
               "extreme).\n\n", o->n_plain, o->n_extreme);
    fprintf(f, "| contender | unit | plain max | plain median | momentum | energy | extreme max | "
               "extreme median | wrong status | NaN | Inf |\n");
    fprintf(f, "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (j = 0; j < bench_ncontenders; j++) {
        const contender *k = &bench_contenders[j];
        const acc_stats *p = &res->acc[j][0], *x = &res->acc[j][1];
        int hx = res->has_acc[j][1];
        fprintf(f, "| %s%s | %s | %s | %s | %s | %s | %s | %s | %d / %s | %d / %s | %d / %s |\n", k->name,
                k->equal_only ? " ‡" : (k->kind == KIND_FIXED ? " §" : ""), unit_of(k),
                fmt(p->max_ulp, b[0]), fmt(p->med_ulp, b[1]), fmt(p->max_momentum, b[2]),
                fmt(p->max_energy, b[3]), hx ? fmt(x->max_ulp, b[4]) : "n/a",
                hx ? fmt(x->med_ulp, b[5]) : "n/a", p->wrong_status,
                hx ? (snprintf(b[6], 32, "%d", x->wrong_status), b[6]) : "n/a", p->nan,
                hx ? (snprintf(b[7], 32, "%d", x->nan), b[7]) : "n/a", p->inf,
                hx ? (snprintf(b[8], 32, "%d", x->inf), b[8]) : "n/a");
    }
    fprintf(f, "\n‡ Equal masses and e = 1 only: evaluated on the same cases with mb = ma and e = 1 "
               "(plain and extreme). On the general plain cases (unequal masses, e < 1) they are "
               "simply the wrong formula:");
    for (j = 0; j < bench_ncontenders; j++)
        if (bench_contenders[j].equal_only)
            fprintf(f, " %s max %s ulp, %d wrong statuses;", bench_contenders[j].id,
                    fmt(res->general[j].max_ulp, b[0]), res->general[j].wrong_status);
    fprintf(f, " the seed summary formulas are wrong even for equal masses in any oblique impact (the "
               "erratum: tangential terms use ut_y for x).\n");
    fprintf(f, "§ Q16.16 on plain inputs only, each input rounded to the 2^-16 grid first (the referee "
               "uses the rounded inputs); extreme inputs are not representable. Float rows use float-"
               "rounded plain inputs and float-range extreme inputs. The batch rows use each case "
               "padded to a block of 16 so it runs through the block kernel; batch results differed from "
               "the scalar call in");
    for (j = 0; j < bench_ncontenders; j++) {
        const contender *k = &bench_contenders[j];
        if (k->kind == KIND_BATCH || k->kind == KIND_BATCHF)
            fprintf(f, " %d + %d (%s)", res->acc[j][0].batch_mismatch, res->acc[j][1].batch_mismatch, k->id);
    }
    fprintf(f, " cases. Box2D (float state, unit-scale tuning) is not run on extreme inputs. The seed "
               "transcriptions have no status: they always write, so every separating, degenerate or "
               "invalid case counts as a wrong status; the trigonometric version checks approach only.\n\n");
}

static void equal_table(FILE *f, const results *res)
{
    char b[4][32];
    int j;
    fprintf(f, "### Equal masses, e = 1 (the seed's own setting), plain\n\n");
    fprintf(f, "| contender | max ulp | median ulp | wrong status |\n|---|---:|---:|---:|\n");
    for (j = 0; j < bench_ncontenders; j++)
        if (res->has_eq[j])
            fprintf(f, "| %s | %s | %s | %d |\n", bench_contenders[j].name, fmt(res->eq[j].max_ulp, b[0]),
                    fmt(res->eq[j].med_ulp, b[1]), res->eq[j].wrong_status);
    fprintf(f, "\n");
}

static void speed_table(FILE *f, const results *res)
{
    char b[8][32];
    const int base = 0; /* c2d_collide */
    int j;
    fprintf(f, "### Speed (same %d in-cache pairs for every contender, e = 1)\n\n", PAIRS_IN_CACHE);
    fprintf(f, "Median ns per collision over the quiet ones (%d / %d; as in the goals) of %d / %d interleaved rounds "
               "(inputs restored untimed before each pass; every contender once per round, so each pass follows "
               "ten others on the same pairs). *Random*: the plain generator (%.0f%% of pairs cancel in d and need the "
               "double-double tier). *Impacts*: disks thrown at each other with a uniform impact "
               "parameter (%.0f%% need it). Instructions: callgrind, %d pairs, minus the empty call's loop "
               "(%.1f / %.1f instr per pair) for scalar rows.\n\n",
            res->quiet_rounds[0], res->quiet_rounds[1], res->rounds_run[0], res->rounds_run[1], 100 * res->slow_share[0],
            100 * res->slow_share[1],
            CALLGRIND_PAIRS, res->ir[0][bench_ncontenders], res->ir[1][bench_ncontenders]);
    fprintf(f, "| contender | ns random | ns impacts | vs c2d_collide (random / impacts) | instr random | "
               "instr impacts | max rel. error (plain) |\n|---|---:|---:|---:|---:|---:|---:|\n");
    for (j = 0; j < bench_ncontenders; j++)
        fprintf(f, "| %s | %s | %s | %s / %s | %s | %s | %s |\n", bench_contenders[j].name,
                fmt(res->ns[0][j], b[0]), fmt(res->ns[1][j], b[1]), fmt(res->ns[0][j] / res->ns[0][base], b[2]),
                fmt(res->ns[1][j] / res->ns[1][base], b[3]), res->ir[0][j] < 0 ? "n/a" : fmt(res->ir[0][j], b[4]),
                res->ir[1][j] < 0 ? "n/a" : fmt(res->ir[1][j], b[5]), fmt(res->acc[j][0].max_rel, b[6]));
    fprintf(f, "| (empty call, loop overhead) | %s | %s | | | | |\n\n", fmt(res->ns[0][bench_ncontenders], b[0]),
            fmt(res->ns[1][bench_ncontenders], b[1]));
}

static void roof_table(FILE *f, const results *res, const options *o)
{
    int p;
    fprintf(f, "### Large batches (%zu pairs, far beyond the caches)\n\n", o->n_large);
    fprintf(f, "Roof: a streaming kernel that reads the same ten input arrays and writes the same four "
               "velocity arrays and status array (the bytes the batch moves), no arithmetic.\n\n");
    fprintf(f, "| kernel | bytes/pair | Mpairs/s | roof Mpairs/s (GB/s) | ratio |\n|---|---:|---:|---:|---:|\n");
    for (p = 0; p < 2; p++) {
        const roof_result *r = &res->roof[p];
        fprintf(f, "| %s | %.0f | %.1f | %.1f (%.1f) | %.2f |\n", p ? "c2d_collide_batchf" : "c2d_collide_batch",
                r->bytes_per_pair, r->batch_pps * 1e-6, r->roof_pps * 1e-6, r->roof_pps * r->bytes_per_pair * 1e-9,
                r->batch_pps / r->roof_pps);
    }
    fprintf(f, "\n");
}

static int find(const char *id)
{
    int j;
    for (j = 0; j < bench_ncontenders; j++)
        if (strcmp(bench_contenders[j].id, id) == 0) return j;
    return 0;
}

static const char *const lib_name[GV_COUNT] = {"c2d_collide", "c2d_collidef", "c2d_collide_normal",
                                               "c2d_collide_normalf"};
static const char *const inl_name[GV_COUNT] = {"c2d_collide_inline", "c2d_collidef_inline",
                                               "c2d_collide_normal_inline", "c2d_collide_normalf_inline"};
static const char *const seed_name[GV_COUNT] = {"bench_seed_equal", "bench_seed_equalf", "bench_seed_equal_normal",
                                                "bench_seed_equal_normalf"};

/* "0.72 (0.70–0.74; all 0.81)": the median ratio, its quartiles, and the
 * median over all rounds (busy machine included). */
static const char *rq(const rstat *s, char *buf)
{
    snprintf(buf, 64, "%.2f (%.2f–%.2f; all %.2f)", s->ratio, s->q1, s->q3, s->ratio_all);
    return buf;
}

/* The same as a gain (the inverse ratio: how many times faster). */
static const char *gain(const rstat *s, char *buf)
{
    snprintf(buf, 64, "%.2fx (%.2f–%.2f; all %.2f)", 1 / s->ratio, 1 / s->q3, 1 / s->q1, 1 / s->ratio_all);
    return buf;
}

/* A verdict on the quiet-machine figure, noting when the all-rounds one
 * (busy machine included) would not meet the goal. */
static const char *verdict2(int ok, int ok_all)
{
    if (ok && ok_all) return "**met**";
    if (ok) return "**met** (not in busy rounds)";
    if (ok_all) return "**not met** (met in busy rounds)";
    return "**not met**";
}

static const char *instr(double v, char *buf)
{
    if (v < 0) return "n/a";
    snprintf(buf, 32, v < 100 ? "%.1f" : "%.0f", v);
    return buf;
}

/* The x86-64 level the batch's run-time dispatch finds on this CPU. */
static const char *cpu_level(void)
{
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
        __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512cd"))
        return "x86-64-v4 (AVX-512)";
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return "x86-64-v3 (AVX2, FMA)";
    if (__builtin_cpu_supports("sse4.2")) return "x86-64-v2 (SSE4.2)";
    return "baseline x86-64 (SSE2)";
#else
    return "not x86-64: no run-time dispatch";
#endif
}

static const char *verdict(int ok) { return ok ? "**met**" : "**not met**"; }

static const char *const ba_fn_name[BA_FN] = {"c2d_collide", "c2d_collide_normal", "c2d_collidef",
                                              "c2d_collide_normalf", "c2d_collide_batch", "c2d_collide_batchf"};
static const char *const ba_set_name[BS_SETS] = {
    "random", "impacts", "extreme", "cancelling", "walls (oblique, at rest)", "axis-aligned, equal masses, e = 1",
    "axis-aligned wall at rest, e = 0.8", "axis-aligned moving wall, e = 0.8", "axis-aligned, unequal masses"};

/* Before/after rows that exist (the axis-aligned sets: scalar calls only). */
static int ba_timed(int v, int s) { return v < BA_BATCH || s < BS_AXIS_SWAP; }

static void goals(FILE *f, const results *res)
{
    const ratios *r = &res->rat;
    const int lib = find("c2d_collide"), seedm = find("seed_masses"), trig = find("trig");
    const double roofd = res->roof[0].batch_pps / res->roof[0].roof_pps;
    const double rooff = res->roof[1].batch_pps / res->roof[1].roof_pps;
    const double lmax = fmax(res->acc[lib][0].max_ulp, res->acc[lib][1].max_ulp);
    const acc_stats *sx = &res->acc[seedm][1], *tx = &res->acc[trig][1];
    char b[8][64];
    int v, p, s, x;
    fprintf(f, "### Goals (speed, same bits)\n\n");
    fprintf(f, "Every speed figure is a ratio timed interleaved in this one process. Each comparison is a group of "
               "passes over the same in-cache pairs (%d per pass; %d for the sets whose calls take microseconds); "
               "in each of %d rounds every group runs once, its passes one after another (order rotated, inputs "
               "restored untimed), so some 60 other groups run between two passes of one group and no branch "
               "predictor can learn a pass's pairs by heart (on fresh data each frame it could not either). A ratio "
               "is the median over the rounds of the per-round ratio. This machine is shared (a VM with steal "
               "time): before each group a canary (the seed transcription on pairs of its own) is timed, and a "
               "round counts as *quiet* when the canary is within 10%% of its best (%.2f ns); %.0f%% of the "
               "group-rounds were. Figures are medians over the quiet rounds, with their quartiles, then (after "
               "\"all\") the median over every round, busy ones included: contention slows the library's "
               "wide out-of-order code more than the bare formulas. The medians of the odd and of the even rounds "
               "differ by at most %.1f%% over every ratio. Built the way `make` builds (flags above); e = 1 "
               "unless stated.\n\n", r->n, r->n >= 256 ? r->n / 4 : r->n, r->rounds, r->canary_ns,
            100 * r->quiet_share, 100 * r->max_halves);
    fprintf(f, "| goal | measured: quiet median (quartiles; all rounds) | verdict |\n|---|---|---|\n");
    for (p = GP_LIB; p <= GP_INLINE; p++)
        for (v = 0; v < GV_COUNT; v++) {
            const rstat *im = &r->goal[v][GS_IMPACTS][p], *rn = &r->goal[v][GS_RANDOM][p];
            fprintf(f, "| `%s` <= 0.8x the seed's method (`%s`%s) on impacts, <= 1.0x on the random mix | impacts "
                       "%s, random %s | %s |\n", p == GP_LIB ? lib_name[v] : inl_name[v], seed_name[v],
                    v >= GV_NORMAL ? ", same normal" : "", rq(im, b[0]), rq(rn, b[1]),
                    verdict2(im->ratio <= 0.8 && rn->ratio <= 1.0, im->ratio_all <= 0.8 && rn->ratio_all <= 1.0));
        }
    if (res->sizes.found == 4 * GV_COUNT) {
        fprintf(f, "| code size per inline call site (bytes of a function making one call, restitution a parameter; "
                   "see below) | ");
        for (v = 0; v < GV_COUNT; v++)
            fprintf(f, "%s`%s` %ld vs %ld for the call", v ? ", " : "", inl_name[v], res->sizes.inl[0][v],
                    res->sizes.call[0][v]);
        fprintf(f, " | reported |\n");
    } else {
        fprintf(f, "| code size per inline call site | not measured (run `make bench`) | — |\n");
    }
    for (p = 0; p < 2; p++)
        fprintf(f, "| `%s` <= 3x the textbook quadratic (`%s`) on ordinary pairs | %s | %s |\n",
                p ? "c2d_time_of_impactf" : "c2d_time_of_impact", p ? "bench_toi_textbookf" : "bench_toi_textbook",
                rq(&r->toi[p][1], b[0]), verdict2(r->toi[p][1].ratio <= 3, r->toi[p][1].ratio_all <= 3));
    for (p = 0; p < 2; p++)
        fprintf(f, "| `%s` >= %dx the scalar call's throughput on all-OK impacts (dispatch as built: %s) | %s | %s |\n",
                p ? "c2d_collide_batchf" : "c2d_collide_batch", p ? 3 : 2, cpu_level(), gain(&r->batch[p][1], b[0]),
                verdict2(1 / r->batch[p][1].ratio >= (p ? 3 : 2), 1 / r->batch[p][1].ratio_all >= (p ? 3 : 2)));
    fprintf(f, "| large batches >= 50%% of the memory-bandwidth roof | double %.0f%%, float %.0f%% | %s |\n", 100 * roofd,
            100 * rooff, verdict(roofd >= 0.5 && rooff >= 0.5));
    fprintf(f, "| cost of the axis-aligned branch (`c2d_collide`, ns per call; table below) | ordinary %.1f, oblique "
               "wall %.1f; axis-aligned: swap %.1f, wall at rest e = 1 %.1f, e = 0.8 %.1f, moving wall e = 0.8 %.0f, "
               "unequal masses %.0f | reported |\n", r->axis[AX_ORDINARY].ns, r->axis[AX_WALL_OBLIQUE].ns,
            r->axis[AX_SWAP].ns, r->axis[AX_WALL1].ns, r->axis[AX_WALL08].ns, r->axis[AX_PADDLE].ns,
            r->axis[AX_UNEQUAL].ns);
    if (r->have_old) {
        static const char *const short_fn[BA_FN] = {"collide", "normal", "collidef", "normalf", "batch", "batchf"};
        double worst_ec = 0;
        char list[2048] = "";
        int slower = 0, rows = 0;
        for (s = 0; s < BS_SETS; s++) { /* per set: the functions more than 10% slower */
            double lo = INFINITY, hi = 0;
            char names[256] = "";
            int k = 0;
            for (v = 0; v < BA_FN; v++) {
                const double q = r->ba[v][s][1].ratio;
                if (!ba_timed(v, s)) continue;
                rows++;
                if ((s == BS_EXTREME || s == BS_CANCEL) && q > worst_ec) worst_ec = q;
                if (!(q > 1.10)) continue;
                k++, slower++;
                lo = fmin(lo, q), hi = fmax(hi, q);
                snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s %.2f", k > 1 ? ", " : "",
                         short_fn[v], q);
            }
            if (k == 0) continue;
            if (k <= 2)
                snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s: %s", list[0] ? "; " : "",
                         ba_set_name[s], names);
            else
                snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s: %.3g–%.3g (%d functions)",
                         list[0] ? "; " : "", ba_set_name[s], lo, hi, k);
        }
        for (x = 0; x < 2; x++)
            for (p = 0; p < 2; p++) {
                const double q = r->ba_toi[p][x][1].ratio;
                rows++;
                if (x == 1 && q > worst_ec) worst_ec = q;
                if (!(q > 1.10)) continue;
                slower++;
                snprintf(list + strlen(list), sizeof list - strlen(list), "%stime of impact%s %s %.3g",
                         list[0] ? "; " : "", p ? "f" : "", x ? "extreme" : "ordinary", q);
            }
        fprintf(f, "| nothing slower elsewhere: the extreme and cancelling rows within 10%% of the library before "
                   "(%s), new/old <= 1.10 | worst extreme/cancelling row %.3g; of all %d rows, %d more than 10%% "
                   "slower: %s (before/after table) | %s |\n", BENCH_OLD_REV_TEXT, worst_ec, rows, slower,
                slower ? list : "none", verdict(worst_ec <= 1.10 && slower == 0));
    } else {
        fprintf(f, "| nothing slower elsewhere | the old library could not be built (no git history) | — |\n");
    }
    fprintf(f, "| c2d_collide worst error a few ulp (header bound: 16); seed and trig worse and failing at the extremes | "
               "library %.3g ulp plain / %.3g extreme, wrong statuses + NaN + Inf: %d; seed (any mass) %s / "
               "%s ulp, on extremes %d NaN, %d Inf, %d wrong statuses; trig %s / %s ulp, on extremes %d NaN, "
               "%d Inf, %d wrong | %s |\n\n", res->acc[lib][0].max_ulp, res->acc[lib][1].max_ulp,
            res->acc[lib][0].wrong_status + res->acc[lib][1].wrong_status + res->acc[lib][0].nan +
                res->acc[lib][1].nan + res->acc[lib][0].inf + res->acc[lib][1].inf,
            fmt(res->acc[seedm][0].max_ulp, b[0]), fmt(sx->max_ulp, b[1]), sx->nan, sx->inf, sx->wrong_status,
            fmt(res->acc[trig][0].max_ulp, b[2]), fmt(tx->max_ulp, b[3]), tx->nan, tx->inf, tx->wrong_status,
            verdict(lmax <= 16 && sx->max_ulp > lmax && tx->max_ulp > lmax));
}

/* Why the missed goals and the slower rows are what they are: the profiles
 * (callgrind counts from this run; the rest measured once at this commit
 * with cachegrind's branch simulation and scratch builds of lib/, named as
 * such). */
static void why(FILE *f, const results *res)
{
    const ratios *r = &res->rat;
    const rstat *ci = r->goal[GV_COLLIDE][GS_IMPACTS], *cr = r->goal[GV_COLLIDE][GS_RANDOM];
    const rstat *ni = r->goal[GV_NORMAL][GS_IMPACTS];
    char b[16][64];
    fprintf(f, "**Why** (callgrind counts from this run; the branch and store-forwarding findings measured at this "
               "commit with `valgrind --tool=cachegrind --branch-sim=yes` and scratch builds of lib/, not committed):\n\n");
    fprintf(f, "- `c2d_collide(f)` against the seed: on impacts it executes %s instructions against the seed's %s and "
               "takes the same time (%.2fx; back to back %.2fx), short of the 0.77x measured when the goals were "
               "set, on another machine. On the random mix the 22%% of pairs whose d cancels go out of line to the double-double "
               "tier, and with the separating pairs they make the front end's branches data-dependent: %.2fx on "
               "fresh pairs, %.2fx when the same pairs run back to back and the predictor has learnt them.\n",
            instr(ir_of(r, &ci[GP_LIB], 1), b[0]), instr(ir_of(r, &ci[GP_SEED], 1), b[1]), ci[GP_LIB].ratio,
            r->goal_b2b[GV_COLLIDE][GS_IMPACTS][GP_LIB].ratio, cr[GP_LIB].ratio,
            r->goal_b2b[GV_COLLIDE][GS_RANDOM][GP_LIB].ratio);
    fprintf(f, "- `c2d_collide_normal` (double) %.1f ns against `c2d_collide`'s %.1f on the same pairs: its front "
               "end takes the normal as two scalars. Passed as a `c2d_vec2` by value, gcc 12 split the function "
               "into a `.part.0` that received the normal through memory, stored as two 8-byte halves and loaded "
               "as one 16-byte vector (`movupd`): no store forwarding, 17 ns a call before this change. The seed "
               "given a `c2d_vec2` by value still pays it (%.2fx its scalar form, above). The float normal "
               "(8 bytes) forwards, so `c2d_collide_normalf` takes it by address and inlines its front end whole; "
               "it is slower than `c2d_collidef` by its position-finiteness check and the `a == b` test.\n",
            ni[GP_LIB].ns, ci[GP_LIB].ns, r->seed_byvalue[1].ratio);
    fprintf(f, "- The `C2D_INLINE` forms join the window's conditions with `&` and take the minimum without a "
               "branch (`minsd`/`maxsd`, one branch per call); before, gcc compiled the minimum as a branch that "
               "mispredicted on a quarter of ordinary pairs. Now %.2fx the seed on fresh impacts, %.2fx back to "
               "back; the remaining gap to 0.8x is the accept path's length (some 94 instructions against the "
               "seed's 57, whose time is set by its divider).\n",
            ci[GP_INLINE].ratio, r->goal_b2b[GV_COLLIDE][GS_IMPACTS][GP_INLINE].ratio);
    if (res->roof[1].batch_pps < 0.5 * res->roof[1].roof_pps || res->roof[0].batch_pps < 0.5 * res->roof[0].roof_pps)
        fprintf(f, "- Large batches: the roof's pairs are the plain generator's (22%% cancel, some separate); the "
                   "cancelling ones take the batch's second vector pass, the separating ones and the rest of the "
                   "scalar tiers' pairs the scalar call: compute-bound on that mix, not at the memory's pace.\n");
    if (r->have_old) {
        const rstat *ax = r->ba[BA_COLLIDE][BS_AXIS_UNEQUAL], *pd = r->ba[BA_COLLIDE][BS_AXIS_PADDLE];
        const rstat *bw = r->ba[BA_BATCHF][BS_WALLS], *tx = r->ba_toi[0][1], *ne = r->ba[BA_NORMAL][BS_EXTREME];
        fprintf(f, "- Slower than before, axis-aligned impacts (now correctly rounded): a moving wall at e < 1 and "
                   "unequal masses first run the filter of `lib/real/arith/round.h` (the result in double length with a "
                   "rigorous error bound, kept when clear of every rounding boundary; the exact quotient "
                   "`c2d_round_quotient`, which alone made them 7922 and 28845 instructions per call, only near a boundary, on ties and "
                   "outside the filter's exponent window): %s and %s instructions against %s before. Swaps and "
                   "walls at rest execute only 20-50 instructions more than before, on the out-of-line axis path "
                   "with full validation, yet take 1.4-2.3x the time. Callgrind's branch simulator charges them "
                   "about two mispredicted branches per call (which axis, which way round: random in these sets), "
                   "but branch-free forms measured no better on this machine: velocities indexed by the axis were "
                   "slower (store forwarding), and a branch-free zero test in the front end gained 0.8 ns on swaps "
                   "while adding 6-9 instructions to every ordinary call; left as they are.\n",
                instr(ir_of(r, &pd[1], 1), b[0]), instr(ir_of(r, &ax[1], 1), b[1]), instr(ir_of(r, &ax[0], 1), b[2]));
        fprintf(f, "- `c2d_collide_normal(f)` on extreme inputs (%.2fx): about one given normal in eight there has a "
                   "zero component, and those now take the exact axis-aligned path (some 40%% of the instructions, "
                   "%s against %s per call).\n", ne[1].ratio, instr(ir_of(r, &ne[1], 1), b[0]),
                instr(ir_of(r, &ne[0], 1), b[1]));
        fprintf(f, "- Batches of walls (float %.2fx the library before): the kernel resolves a wall pair (one mass "
                   "INFINITY) itself with the scalar front end's mass pair, picked by bit masks (%s instructions "
                   "per pair against %s before); two walls and NaN masses still leave it for the scalar call.\n",
                bw[1].ratio, instr(ir_of(r, &bw[1], 0), b[0]), instr(ir_of(r, &bw[0], 0), b[1]));
        fprintf(f, "- The time of impact on extreme pairs (%.0fx): about 40%% of them (the components at independent "
                   "exponents) reach `c2d_toi_exact`, whose extended products (`c2d_acc_product`, `c2d_compress`: "
                   "over 90%% of the instructions) take some 250,000 instructions each; %s per call on average "
                   "against %s before, when %d of %d such statuses were wrong (referee table below). The "
                   "exact statuses the audit of the statuses asked for, at a price a cheaper exact sign (fewer, "
                   "shorter expansions) could lower.\n",
                tx[1].ratio, instr(ir_of(r, &tx[1], 1), b[0]), instr(ir_of(r, &tx[0], 1), b[1]),
                res->toi[TK_OLD][0][1].wrong_status, res->toi[TK_OLD][0][1].n);
    }
    fprintf(f, "- Unit-distance pairs (`c2d_collide` %.2fx the seed, %s instructions against %s): centres 1 apart "
               "anywhere in [-2, 2]^2, so in about one pair in nine (460 of 4096) a component of d = b - a is small "
               "against the positions it is taken from and its rounding would break the error bound: those pairs "
               "take the double-length d (`c2d_quick_cancelling`, `c2d_cancelling_fused`: 270 instructions each, "
               "24%% of the set's instructions). The input checks (NULL, restitution, masses, finiteness) are 9%% "
               "and the axis test 8%%; the seed has none of them and is wrong by its own rounding on those pairs.\n",
            r->i22_unit[0][1].ratio, instr(ir_of(r, &r->i22_unit[0][1], 1), b[0]),
            instr(ir_of(r, &r->i22_unit[0][0], 1), b[1]));
    fprintf(f, "- Gas pairs in float (`c2d_collidef` %.2fx the bare formula, double %.2fx): the same %s instructions "
               "as in double (unit disks in a box 100 wide: 382 of 4096 pairs, 9.3%%, cancel in d and take the "
               "double-length tier, 21%% of the instructions), while the bare formula's division and square root "
               "are cheaper in float than in double: the instruction ratio is the same, the time ratio grows.\n",
            r->i22_mix[1][1][I22_LIB].ratio, r->i22_mix[1][0][I22_LIB].ratio,
            instr(ir_of(r, &r->i22_mix[1][1][I22_LIB], 1), b[0]));
    fprintf(f, "- The batch on the gas (%s the scalar loop in double, %s on the random mix): the 9.3%% of gas "
               "pairs whose d cancels (22%% of the random mix) used to leave the vector kernel for the whole scalar "
               "call (253 instructions each, 29%% of the batch's instructions; 1.35x before); the kernel now queues "
               "them and a second branch-free vector pass resolves them 16 at a time with the scalar tier's own "
               "arithmetic (`lib/real/collide/batch.h`), so only lanes that tier passes on take the scalar call.\n",
            gain(&r->i22_batch[0][0][1], b[0]), gain(&r->i22_batch[1][0][1], b[1]));
    {
        const double bil = toia_ir("billiards", "lib"), fer = toia_ir("billiards", "ferrari");
        const double tch = toia_ir("touching", "lib"), pt = toia_ir("touching", "plain");
        fprintf(f, "- The time of impact under acceleration on the billiards family (%s instructions against "
                   "Ferrari's %s): Ferrari's closed form takes the quartic's rounded coefficients and is wrong on "
                   "%ld of %ld statuses (table below); the library splits each input vector into exact parts "
                   "(`c2d_toia_load_vec`, 15%%), scans the quartic with certified hulls and bounds "
                   "(`c2d_toia_fast`, 45%%, of which the hull test 12%%), and polishes the root with a bracketed "
                   "Newton step (9%%). On touching pool balls (%s instructions): the distance is R to rounding at "
                   "t = 0, so every filter sees a tie and the exact scan runs (`c2d_toia_scan` 80%%: the split "
                   "search, the exact value at the distance's minimum, the extended-precision root); the plain "
                   "time of impact on the same pairs (%s) takes the discriminant's exact expansion when the gap's "
                   "exact sign is positive (`c2d_toi_touching`, 93%%: `c2d_toi_mvalue` 34%%, `c2d_grow` 33%%). A "
                   "cheaper exact sign for a gap of a few ulps (a double-length discriminant with a proven error "
                   "bound before the expansions) is the next step for both.\n",
                instr(bil, b[0]), instr(fer, b[1]), res->toia[TA_FERRARI].wrong, res->toia[TA_FERRARI].n,
                instr(tch, b[2]), instr(pt, b[3]));
    }
    fprintf(f, "- Rough disks: `c2d_rough_tangential` is nearly 90%% of `c2d_collide_rough`'s %s instructions "
               "(Walton plainly: %s): the slip speed in double length with an extended exponent runs on every call, "
               "with no plain-arithmetic path in front of it for the contacts that do not need it.\n\n",
            instr(ir_of(r, &r->rough[RG_ROUGH], 1), b[0]), instr(ir_of(r, &r->rough[RG_WALTON], 1), b[1]));
}

/* The goals' detail: every comparison with its ns and instruction counts. */
static void goal_tables(FILE *f, const results *res)
{
    const ratios *r = &res->rat;
    char b[12][64];
    int v, s, p, x;
    fprintf(f, "### Against the seed's method (detail)\n\n");
    fprintf(f, "*Impacts*: disks thrown at each other (uniform impact parameter); *random*: the plain generator "
               "(22%% of pairs cancel in d). Seed: the bare transcription as an out-of-line call (`bench/approaches.c`); "
               "seed inlined: the same text expanded into the loop, as a user's own ten lines would be. Inline: the "
               "`C2D_INLINE` front end (`C2D_INLINE_AS_WRITTEN` = %d in the bench's flags). Instructions: callgrind, "
               "per call, less the empty call's loop (%s per call).\n\n", r->as_written,
            instr(r->noop.n > 0 && ir_get(r->noop.id) >= 0 ? ir_get(r->noop.id) / r->noop.n : -1, b[0]));
    fprintf(f, "| function | set | ns seed | ns library | library / seed | ns inline | inline / seed | inline / seed "
               "inlined | back to back: library / seed, inline / seed | instr seed / library / inline |\n"
               "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (v = 0; v < GV_COUNT; v++)
        for (s = 0; s < GS_COUNT; s++) {
            const rstat *g = r->goal[v][s], *k = r->goal_b2b[v][s];
            fprintf(f, "| `%s` | %s | %.2f | %.2f | %s | %.2f | %s | %.2f | %.2f, %.2f | %s / %s / %s |\n", lib_name[v],
                    s == GS_IMPACTS ? "impacts" : "random", g[GP_SEED].ns, g[GP_LIB].ns, rq(&g[GP_LIB], b[0]),
                    g[GP_INLINE].ns, rq(&g[GP_INLINE], b[1]), g[GP_INLINE].ratio / g[GP_SEED_INLINE].ratio,
                    k[GP_LIB].ratio, k[GP_INLINE].ratio, instr(ir_of(r, &g[GP_SEED], 1), b[2]),
                    instr(ir_of(r, &g[GP_LIB], 1), b[3]), instr(ir_of(r, &g[GP_INLINE], 1), b[4]));
        }
    fprintf(f, "\n*Back to back*: the same groups timed again, each group's %d rounds in a row (%.0f%% quiet), as a "
               "benchmark of one function on fixed pairs would: the branch predictor then learns the 4096 pairs' "
               "outcomes, which hides what data-dependent branches cost on fresh data. *The seed given a c2d_vec2 by "
               "value* (`bench_seed_equal_normal_v`) takes %.2f ns against %.2f with the normal as two scalars "
               "(%.2fx): gcc 12 spills the struct's two doubles and reloads them as one 16-byte vector, which cannot "
               "be store-forwarded.\n\n", r->rounds / 2 > 3 ? r->rounds / 2 : 3, 100 * r->quiet_share_b2b,
            r->seed_byvalue[1].ns, r->seed_byvalue[0].ns, r->seed_byvalue[1].ratio);
    if (res->sizes.found == 4 * GV_COUNT) {
        fprintf(f, "**Code size per call site** (`bench/callsite.c` compiled with the library's flags, `nm -S`): bytes "
                   "of a function that makes one call; the inline front end's constants (a few 8-byte literals in "
                   ".rodata, shared by every site of a file) not counted.\n\n");
        fprintf(f, "| function | library call, e a parameter | inline, e a parameter | library call, e = 1 | inline, "
                   "e = 1 |\n|---|---:|---:|---:|---:|\n");
        for (v = 0; v < GV_COUNT; v++)
            fprintf(f, "| `%s` | %ld | %ld | %ld | %ld |\n", inl_name[v], res->sizes.call[0][v], res->sizes.inl[0][v],
                    res->sizes.call[1][v], res->sizes.inl[1][v]);
        fprintf(f, "\n");
    }
    fprintf(f, "**Time of impact** on ordinary pairs (radii 0.1–1, centres 2 to 20 radius sums apart, at most 20; "
               "aimed within 1.25 times the hitting angle: %.0f%% hit). Textbook: `bench_toi_textbook(f)`.\n\n",
            100 * r->toi_hits);
    fprintf(f, "| | ns textbook | ns library | library / textbook | instr textbook / library |\n|---|---:|---:|---:|---:|\n");
    for (p = 0; p < 2; p++)
        fprintf(f, "| %s | %.2f | %.2f | %s | %s / %s |\n", p ? "float" : "double", r->toi[p][0].ns, r->toi[p][1].ns,
                rq(&r->toi[p][1], b[0]), instr(ir_of(r, &r->toi[p][0], 1), b[1]), instr(ir_of(r, &r->toi[p][1], 1), b[2]));
    fprintf(f, "\n**Batch** on all-OK impacts (every pair one the front end accepts, in double and in float), "
               "against the scalar call in a loop; the CPU offers %s (under callgrind, which has no AVX-512, the "
               "AVX2 clone runs). Instructions per pair, the batch's whole call included.\n\n", cpu_level());
    fprintf(f, "| | ns scalar | ns batch (per pair) | batch gain | instr scalar / batch |\n|---|---:|---:|---:|---:|\n");
    for (p = 0; p < 2; p++)
        fprintf(f, "| %s | %.2f | %.2f | %s | %s / %s |\n", p ? "float" : "double", r->batch[p][0].ns,
                r->batch[p][1].ns, gain(&r->batch[p][1], b[0]), instr(ir_of(r, &r->batch[p][0], 1), b[1]),
                instr(ir_of(r, &r->batch[p][1], 0), b[2]));
    fprintf(f, "\n**The axis-aligned branch** (`c2d_collide`, correctly rounded when the centres share a coordinate), "
               "against ordinary impacts, timed interleaved:\n\n");
    {
        static const char *const what[AX_COUNT] = {
            "ordinary impacts (oblique, unequal masses)", "oblique walls (b immovable, at rest)",
            "axis-aligned, equal masses (exact swap)", "axis-aligned wall at rest (exact negation)",
            "axis-aligned wall at rest (-e u, one rounding)",
            "axis-aligned moving wall (a paddle: exact quotient)", "axis-aligned, unequal masses (exact quotient)"};
        static const char *const e_of[AX_COUNT] = {"1", "1", "1", "1", "0.8", "0.8", "1"};
        fprintf(f, "| pairs | e | ns | vs ordinary | instr |\n|---|---:|---:|---:|---:|\n");
        for (x = 0; x < AX_COUNT; x++)
            fprintf(f, "| %s | %s | %.2f | %s | %s |\n", what[x], e_of[x], r->axis[x].ns, rq(&r->axis[x], b[0]),
                    instr(ir_of(r, &r->axis[x], 1), b[1]));
    }
    fprintf(f, "\n");
}

static void before_after(FILE *f, const results *res)
{
    const ratios *r = &res->rat;
    char b[6][64];
    int v, s, p, x;
    if (!r->have_old) return;
    fprintf(f, "### Before and after (the library as of %s)\n\n", BENCH_OLD_REV_TEXT);
    fprintf(f, "The old library is built inside the bench from `git archive %s lib include` with the same flags, its "
               "symbols renamed `old_*` (objcopy), and timed interleaved against today's on the same pairs. "
               "*Extreme*: the whole range (gen_extreme: subnormals, near-overflow, mass ratios to 1e600, INFINITY "
               "masses, invalid inputs; float calls on float-range ones); *cancelling*: plain pairs whose d cancels "
               "(kappa > 4); *walls*: impacts against an immovable b; time of impact *extreme*: scaled over the range "
               "and components at independent exponents. Ratio new/old below 1 is faster. Instructions per call "
               "(callgrind; batch rows per pair).\n\n", BENCH_OLD_REV_TEXT);
    fprintf(f, "| function | pairs | ns old | ns new | new / old | instr old | instr new |\n"
               "|---|---|---:|---:|---:|---:|---:|\n");
    for (v = 0; v < BA_FN; v++)
        for (s = 0; s < BS_SETS; s++) {
            const rstat *q = r->ba[v][s];
            const int scalar = v < BA_BATCH;
            if (!ba_timed(v, s)) continue;
            fprintf(f, "| `%s` | %s | %.2f | %.2f | %s%s | %s | %s |\n", ba_fn_name[v], ba_set_name[s], q[0].ns, q[1].ns,
                    rq(&q[1], b[0]), q[1].ratio > 1.10 ? " **slower**" : "", instr(ir_of(r, &q[0], scalar), b[1]),
                    instr(ir_of(r, &q[1], scalar), b[2]));
        }
    for (p = 0; p < 2; p++)
        for (x = 0; x < 2; x++) {
            const rstat *q = r->ba_toi[p][x];
            fprintf(f, "| `%s` | %s | %.2f | %.2f | %s%s | %s | %s |\n", p ? "c2d_time_of_impactf" : "c2d_time_of_impact",
                    x ? "extreme" : "ordinary", q[0].ns, q[1].ns, rq(&q[1], b[0]), q[1].ratio > 1.10 ? " **slower**" : "",
                    instr(ir_of(r, &q[0], 1), b[1]), instr(ir_of(r, &q[1], 1), b[2]));
        }
    fprintf(f, "\n");
}

static void toi_table(FILE *f, const results *res, const options *o)
{
    static const char *const name[TK_COUNT] = {"library", "library before (" BENCH_OLD_REV ")", "textbook quadratic"};
    char b[6][64];
    int k, p;
    fprintf(f, "### Time of impact against the exact referee\n\n");
    fprintf(f, "What the time of impact's price buys: %d ordinary pairs (the speed goal's) and %d extreme ones "
               "(scaled over the range, and components at independent exponents: magnitudes that differ by more "
               "than the exponent range), against the exact referee (statuses in rationals, t in 256-bit MPFR). "
               "Error: |t - exact| in the header's units (ulp of t plus the time one rounding of the centre "
               "distance is worth at contact; bound 4), over the hits both report. Wrong status: a hit reported "
               "as a miss or the reverse, or any other status but the referee's (RANGE where t overflows).\n\n",
            o->n_plain / 4, o->n_extreme / 4);
    fprintf(f, "| contender | format | ordinary: max / median units | wrong status | NaN/Inf t | extreme: max / "
               "median units | wrong status | NaN/Inf t |\n|---|---|---:|---:|---:|---:|---:|---:|\n");
    for (k = 0; k < TK_COUNT; k++)
        for (p = 0; p < 2; p++) {
            const toi_stats *a = &res->toi[k][p][0], *x = &res->toi[k][p][1];
            if (a->n == 0) continue;
            fprintf(f, "| %s | %s | %s / %s | %d | %d | %s / %s | %d | %d |\n", name[k], p ? "float" : "double",
                    fmt(a->max_units, b[0]), fmt(a->med_units, b[1]), a->wrong_status, a->nan_inf,
                    fmt(x->max_units, b[2]), fmt(x->med_units, b[3]), x->wrong_status, x->nan_inf);
        }
    fprintf(f, "\nHits among the pairs (referee): ordinary %d / %d, extreme %d / %d (double).\n\n",
            res->toi[TK_LIB][0][0].hits, res->toi[TK_LIB][0][0].n, res->toi[TK_LIB][0][1].hits, res->toi[TK_LIB][0][1].n);
}

static void rough_table(FILE *f, const results *res, const options *o)
{
    static const char *const name[RK_COUNT] = {"c2d_collide_rough (double)", "c2d_collide_roughf (float)",
                                               "Walton transcribed plainly (double, `bench_walton`)"};
    static const int timing[RK_COUNT] = {RG_ROUGH, RG_ROUGHF, RG_WALTON};
    const ratios *r = &res->rat;
    char b[12][64];
    int k;
    fprintf(f, "### Rough disks: friction and spin (Walton's model)\n\n");
    fprintf(f, "%d plain contacts (radii 0.1–1 touching, speeds and spin x radius to 10, inertia 0.1–1 m r^2 or "
               "INFINITY, 10%% walls, any e, mu in {0.05, 0.2, 1, 1e6, INFINITY}, beta in [-1, 1]; the unit test's "
               "generator) and %d extreme ones (the normal part from gen_extreme, spins, radii and inertias anywhere "
               "in the range), against the 4400-bit MPFR referee (`referee/ref_rough.c`). Error: worst component in "
               "ulp of the body's scale (largest |vx|, |vy|, |spin radius| before and after; header bound 18). Energy: "
               "the largest relative gain of kinetic energy with rotation over the plain impacts between bodies of "
               "finite mass and inertia (it must never grow; the referee's energies are rounded to double, so "
               "~1e-16 is rounding). Speed: %d in-cache plain "
               "contacts, interleaved, normal = b.pos - a.pos.\n\n", o->n_plain, o->n_extreme, r->n);
    fprintf(f, "| contender | unit | plain max | plain median | extreme max | extreme median | wrong status | NaN | Inf "
               "| energy gain | ns | vs transcription | instr |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (k = 0; k < RK_COUNT; k++) {
        const rough_stats *p = &res->rough[k][0], *x = &res->rough[k][1];
        const rstat *t = &r->rough[timing[k]];
        fprintf(f, "| %s | %s | %s | %s | %s | %s | %d / %d | %d / %d | %d / %d | %s | %.2f | %s | %s |\n", name[k],
                k == RK_LIBF ? "float ulp" : "double ulp", fmt(p->max_ulp, b[0]), fmt(p->med_ulp, b[1]),
                fmt(x->max_ulp, b[2]), fmt(x->med_ulp, b[3]), p->wrong_status, x->wrong_status, p->nan, x->nan, p->inf,
                x->inf, fmt(p->max_energy_gain, b[4]), t->ns, rq(t, b[5]), instr(ir_of(r, t, 1), b[6]));
    }
    fprintf(f, "| c2d_collide on the same pairs (no friction, for scale) | | | | | | | | | | %.2f | %s | %s |\n\n",
            r->rough[RG_COLLIDE].ns, rq(&r->rough[RG_COLLIDE], b[0]), instr(ir_of(r, &r->rough[RG_COLLIDE], 1), b[1]));
    fprintf(f, "Wrong status, NaN and Inf: counts of cases (plain / extreme). The transcription checks only the "
               "approach (gn < 0); it has no status for invalid, degenerate or overflowing inputs, so those count as "
               "wrong.\n\n");
}

/* The contenders' names in the callgrind dumps (toia_callgrind); the
 * Sturm solver is not counted. */
static const char *const kToiaWho[TA_COUNT] = {"lib", "libf", "ferrari", "sturm"};

static void toi_accel_table(FILE *f, const results *res)
{
    static const char *const name[TA_COUNT] = {"c2d_time_of_impact_accel (double)", "c2d_time_of_impact_accelf (float)",
                                               "Ferrari closed form (double, `bench_toia_ferrari`)",
                                               "Sturm sequence + bisection (double, `bench_toia_sturm`)"};
    const toia_stats *lib = &res->toia[TA_LIB];
    char b[4][64];
    int k;
    fprintf(f, "### Time of impact under constant acceleration against the exact referee\n\n");
    fprintf(f, "%ld cases over the unit test's 14 families (`referee/cases_toi_accel.c`: billiard balls on cloth, "
               "random accelerations, zero acceleration, one at rest, scaled and extreme magnitudes, grazes, inner "
               "touches, touches at t = 0, the horizon at a root, leave and re-enter, sub-ulp contacts, turns while "
               "overlapping, huge and zero horizons), each decided by the exact referee (Sturm sequences over the "
               "rationals, t in MPFR; `referee/ref_toi_accel.c`); the float row on the same families generated in "
               "float. Wrong status: differs from the referee outside the contract's tie band (%ld cases of the "
               "double set lie in it; disagreements there are listed apart). Error: |t - exact| in the header's "
               "units (ulp(t) + ulp(|d|)/approach speed; bound 1) over the hits outside the band. Speed: median ns "
               "per call over interleaved rounds, on the billiards family and on all families mixed.\n\n",
            lib->n, lib->band);
    fprintf(f, "| contender | wrong status | in-band disagreements | NaN/Inf t | worst units | > %g units | ns billiards "
               "| ns all families | instr billiards |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
            TOIA_BEYOND_UNITS);
    for (k = 0; k < TA_COUNT; k++) {
        const toia_stats *s = &res->toia[k];
        fprintf(f, "| %s | %ld / %ld | %ld | %ld | %s | %ld | %.1f | %.1f | %s |\n", name[k], s->wrong, s->n,
                s->band_wrong, s->nan_inf, fmt(s->worst, b[0]), s->beyond, s->ns[TA_BILLIARDS], s->ns[TA_ALL],
                instr(toia_ir("billiards", kToiaWho[k]), b[1]));
    }
    fprintf(f, "\n*Touching pool balls* (%ld cases, `toia_gen_touching`: centres 2R apart to rounding, one pushed "
               "within 2 rad of the line of centres at 0.01-8 m/s, the other at rest or moving, cloth decelerations; "
               "issue 22's goal of at most 2,500 instructions a call), the same referee:\n\n"
               "| contender | wrong status | in-band disagreements | worst units | ns | instr |\n"
               "|---|---:|---:|---:|---:|---:|\n", res->toia_touch[TA_LIB].n);
    for (k = 0; k < TA_COUNT; k++) {
        const toia_stats *s = &res->toia_touch[k];
        fprintf(f, "| %s | %ld / %ld | %ld | %s | %.1f | %s |\n", name[k], s->wrong, s->n, s->band_wrong,
                fmt(s->worst, b[0]), res->toia[k].ns[TA_TOUCHING], instr(toia_ir("touching", kToiaWho[k]), b[1]));
    }
    fprintf(f, "\nThe textbook solvers' errors and statuses come from forming the quartic's coefficients in double "
               "(cancellation in |d|^2 - R^2 near contact, and in c2 when the motion is nearly collinear) and from "
               "their epsilons; the library decides the status with certified error bounds and falls back to exact "
               "arithmetic near a tie.\n\n");
}

/* Issue 22's time-of-impact goals, in instructions (callgrind): under
 * acceleration at most 3x Ferrari's on the billiards family and at most
 * 2,500 on touching pool balls; the plain one on those touching balls at
 * most 3x its own on ordinary pairs (the timed set above). */
static void toi_goals(FILE *f, const results *res)
{
    const ratios *r = &res->rat;
    char b[4][64];
    int p;
    for (p = 0; p < 2; p++) {
        const char *lib = p ? "libf" : "lib";
        const double bil = toia_ir("billiards", lib), fer = toia_ir("billiards", "ferrari");
        const double tch = toia_ir("touching", lib), ord = ir_of(r, &r->toi[p][1], 1);
        const double pt = toia_ir("touching", p ? "plainf" : "plain");
        fprintf(f, "| `%s` <= 3x Ferrari's instructions on the billiards family | %s against %s (%.2fx) | %s |\n",
                p ? "c2d_time_of_impact_accelf" : "c2d_time_of_impact_accel", instr(bil, b[0]), instr(fer, b[1]),
                bil > 0 && fer > 0 ? bil / fer : 0.0, verdict(bil > 0 && fer > 0 && bil <= 3 * fer));
        fprintf(f, "| `%s` <= 2,500 instructions on touching pool balls | %s | %s |\n",
                p ? "c2d_time_of_impact_accelf" : "c2d_time_of_impact_accel", instr(tch, b[0]),
                verdict(tch > 0 && tch <= 2500));
        fprintf(f, "| `%s` on touching pool balls <= 3x its instructions on ordinary pairs | %s against %s (%.2fx) | "
                   "%s |\n", p ? "c2d_time_of_impactf" : "c2d_time_of_impact", instr(pt, b[0]), instr(ord, b[1]),
                pt > 0 && ord > 0 ? pt / ord : 0.0, verdict(pt > 0 && ord > 0 && pt <= 3 * ord));
    }
}

/* Issue 22's goals on its own mixes (bench/ratio.c gen_unit, gen_break,
 * gen_gas): the seed on unit-distance pairs, the bare impulse formula
 * (approaches.h BENCH_BARE) inlined on break and gas pairs, the batch on
 * the gas and the random mix against the scalar loop and a plain loop of
 * the bare formula over the same arrays, and c2d_collide_normal's time and
 * instructions against c2d_collide's on the same pairs. */
static void issue22(FILE *f, const results *res)
{
    static const char *const mix[2] = {"break", "gas"}, *const bset[2] = {"gas", "random"};
    static const char *const fn[2][2] = {{"c2d_collide", "c2d_collide_inline"}, {"c2d_collidef", "c2d_collidef_inline"}};
    const ratios *r = &res->rat;
    char b[8][64];
    int p, m, k;
    fprintf(f, "### Issue 22: unit-distance, break and gas pairs\n\n");
    fprintf(f, "Pairs (%d each, e = 1, equal masses): *unit*, centres 1 apart in random directions, velocities "
               "uniform in [-1, 1]^2, four in five separating pairs turned round; *break*, pool balls in contact "
               "along a rack line (multiples of 30 degrees +-1), the struck one at 0.5-8 m/s within 60 degrees of "
               "the line; *gas*, unit disks at contact with Maxwell velocities, approaching. *Bare*: the impulse "
               "formula j = -(1 + e) g / (1/ma + 1/mb) along n = d/|d| with no checks (`BENCH_BARE`), inlined into "
               "the loop or called. Ratios as above (median of per-round ratios, quiet rounds; quartiles; all "
               "rounds); instructions from callgrind, per call less the empty loop's.\n\n", r->n);
    fprintf(f, "| goal | measured | verdict |\n|---|---|---|\n");
    for (p = 0; p < 2; p++)
        for (k = 1; k < 3; k++) {
            const rstat *q = &r->i22_unit[p][k];
            fprintf(f, "| `%s` <= 0.8x the seed's method on unit-distance pairs (%s) | %s; instructions %s against "
                       "%s | %s |\n", fn[p][k - 1], p ? "float" : "double", rq(q, b[0]), instr(ir_of(r, q, 1), b[1]),
                    instr(ir_of(r, &r->i22_unit[p][0], 1), b[2]), verdict2(q->ratio <= 0.8, q->ratio_all <= 0.8));
        }
    for (m = 0; m < 2; m++)
        for (p = 0; p < 2; p++)
            for (k = I22_LIB; k <= I22_INLINE; k++) {
                const rstat *g = r->i22_mix[m][p], *q = &g[k];
                fprintf(f, "| `%s` <= 1.2x the bare formula inlined on %s pairs (%s) | %s; bare called %.2f; "
                           "instructions %s against %s inlined, %s called | %s |\n", fn[p][k - I22_LIB], mix[m],
                        p ? "float" : "double", rq(q, b[0]), g[I22_BARE].ratio, instr(ir_of(r, q, 1), b[1]),
                        instr(ir_of(r, &g[I22_BARE_INLINE], 1), b[2]), instr(ir_of(r, &g[I22_BARE], 1), b[3]),
                        verdict2(q->ratio <= 1.2, q->ratio_all <= 1.2));
            }
    for (m = 0; m < 2; m++)
        for (p = 0; p < 2; p++) {
            const rstat *g = r->i22_mix[m][p];
            const double il = ir_of(r, &g[I22_LIB], 1), in = ir_of(r, &g[I22_NORMAL], 1);
            fprintf(f, "| `%s` against `%s` on %s pairs (the same normal, d): time, instructions | %.2fx the time, "
                       "%s against %s instructions (%.2fx) | reported |\n",
                    p ? "c2d_collide_normalf" : "c2d_collide_normal", fn[p][0], mix[m],
                    g[I22_NORMAL].ratio / g[I22_LIB].ratio, instr(in, b[0]), instr(il, b[1]),
                    il > 0 && in > 0 ? in / il : 0.0);
        }
    for (m = 0; m < 2; m++)
        for (p = 0; p < 2; p++) {
            const rstat *g = r->i22_batch[m][p];
            const double vs_bare = g[2].ratio / g[1].ratio;
            fprintf(f, "| `%s` >= 2x the scalar loop and >= 1x the bare formula's loop over the same arrays (%s) | "
                       "%s the scalar loop; %.2fx the bare loop (%.2f against %.2f ns per pair) | %s |\n",
                    p ? "c2d_collide_batchf" : "c2d_collide_batch", bset[m], gain(&g[1], b[0]), vs_bare, g[1].ns,
                    g[2].ns, verdict(1 / g[1].ratio >= 2 && vs_bare >= 1));
        }
    toi_goals(f, res);
    /* Not measured by this program: the demo's build/opponent_bench under
     * callgrind (docs/GAME.md, which has the method and the history);
     * update both together. */
    fprintf(f, "| the pool opponent: the same candidates in <= 1/4 of the issue's 208 M instructions a turn "
               "(`build/opponent_bench --plain`, callgrind, seeds 1-8; not run by `make bench`) | 46.3 M (0.22x; "
               "121 M before), the same shots (digest 7069196ad8fa2fe8); on the games the same seeds play since the "
               "demo's own elementary functions, 51.7 M (0.25x; 120 turns, 112 candidates a turn, digest "
               "2d4a975dd0f8c1c9); with position play 71.3 M, 51.5%% of 200 games against the plain opponent "
               "(docs/GAME.md) | **met** |\n");
    fprintf(f, "\n");
}

static void report(FILE *f, const results *res, const options *o)
{
    fprintf(f, "## collide2d speed-for-accuracy benchmark (`make bench`)\n\n");
    machine(f, o);
    goals(f, res);
    issue22(f, res);
    why(f, res);
    goal_tables(f, res);
    before_after(f, res);
    speed_table(f, res);
    roof_table(f, res, o);
    accuracy_table(f, res, o);
    equal_table(f, res);
    toi_table(f, res, o);
    rough_table(f, res, o);
    toi_accel_table(f, res);
    fprintf(f, "![error vs time per collision](pareto.png)\n");
}

/* Columns: id, ns (impacts), worst and median relative error on plain
 * inputs, worst on extreme inputs (100: NaN/Inf/garbage, NaN: not run), and
 * a factor that moves a label down when an earlier point sits close by. */
static void plot_data(const char *path, const results *res)
{
    FILE *f = fopen(path, "w");
    double y[MAXK];
    int j, i;
    if (f == NULL) return;
    for (j = 0; j < bench_ncontenders; j++) {
        const acc_stats *a = &res->acc[j][0], *x = &res->acc[j][1];
        const bench_kind kind = bench_contenders[j].kind;
        /* Own ulp times the format's epsilon: a float result near a float
         * subnormal cannot be judged in double ulps. */
        const double rel = x->max_ulp * (kind == KIND_FLOAT || kind == KIND_BATCHF ? 0x1p-23 : 0x1p-52);
        double ext = !res->has_acc[j][1] ? NAN : (rel <= 1 && x->nan + x->inf == 0 ? rel : 100);
        int near = 0;
        /* Log axes: an exact result is drawn at 1e-17 (below half an ulp). */
        y[j] = fmax(a->max_rel, 1e-17);
        for (i = 0; i < j; i++)
            near += fabs(log10(res->ns[1][i] / res->ns[1][j])) < 0.2 && fabs(log10(y[i] / y[j])) < 1;
        fprintf(f, "\"%s\" %.6g %.6g %.6g %.6g %.3g\n", bench_contenders[j].id, res->ns[1][j], y[j],
                fmax(a->med_rel, 1e-17), isnan(ext) ? NAN : fmax(ext, 1e-17), pow(10, -0.7 * near));
    }
    fclose(f);
}

/* ------------------------------------------------------------ main */

static int parse(int argc, char **argv, options *o)
{
    int i;
    o->results = o->plot_data = o->ir = o->flags = o->sizes = NULL;
    o->n_plain = 20000, o->n_extreme = 20000, o->rounds = 201, o->ratio_rounds = 501, o->n_large = (size_t)1 << 21;
    for (i = 1; i < argc; i++) {
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (v == NULL) return 0;
        if (strcmp(argv[i], "--results") == 0) o->results = v;
        else if (strcmp(argv[i], "--plot-data") == 0) o->plot_data = v;
        else if (strcmp(argv[i], "--ir") == 0) o->ir = v;
        else if (strcmp(argv[i], "--flags") == 0) o->flags = v;
        else if (strcmp(argv[i], "--sizes") == 0) o->sizes = v;
        else if (strcmp(argv[i], "--ratio-rounds") == 0) o->ratio_rounds = atoi(v);
        else if (strcmp(argv[i], "--plain") == 0) o->n_plain = atoi(v);
        else if (strcmp(argv[i], "--extreme") == 0) o->n_extreme = atoi(v);
        else if (strcmp(argv[i], "--rounds") == 0) o->rounds = atoi(v);
        else if (strcmp(argv[i], "--large") == 0) o->n_large = (size_t)atol(v);
        else return 0;
        i++;
    }
    return o->n_plain > 0 && o->n_extreme > 0 && o->rounds > 0 && o->ratio_rounds > 0 && o->n_large >= 8;
}

int main(int argc, char **argv)
{
    options o;
    static results res;
    case_set sets[SET_COUNT];
    int code;
    if (argc == 2 && strcmp(argv[1], "--callgrind") == 0) return run_callgrind_driver();
    if (argc == 3 && strcmp(argv[1], "--ratios-only") == 0) { /* quick look at the ratios, no report */
        static ratios r;
        int v, g;
        ratios_measure(&r, atoi(argv[2]), PAIRS_IN_CACHE, 0);
        for (v = 0; v < GV_COUNT; v++)
            for (g = 0; g < GS_COUNT; g++)
                printf("%-20s %-8s seed %6.2f lib %6.2f (%.2f [%.2f-%.2f] all %.2f) inline %6.2f (%.2f all %.2f) "
                       "seed_inl %6.2f b2b %.2f %.2f\n", lib_name[v], g ? "random" : "impacts", r.goal[v][g][0].ns,
                       r.goal[v][g][1].ns, r.goal[v][g][1].ratio, r.goal[v][g][1].q1, r.goal[v][g][1].q3,
                       r.goal[v][g][1].ratio_all, r.goal[v][g][2].ns, r.goal[v][g][2].ratio, r.goal[v][g][2].ratio_all,
                       r.goal[v][g][3].ns, r.goal_b2b[v][g][1].ratio, r.goal_b2b[v][g][2].ratio);
        for (v = 0; v < 2; v++)
            printf("toi %d: text %.2f lib %.2f ratio %.2f; batch %d: scalar %.2f batch %.2f gain %.2f\n", v,
                   r.toi[v][0].ns, r.toi[v][1].ns, r.toi[v][1].ratio, v, r.batch[v][0].ns, r.batch[v][1].ns,
                   1 / r.batch[v][1].ratio);
        printf("max halves %.3f canary %.2f quiet share %.2f (b2b %.2f)\n", r.max_halves, r.canary_ns, r.quiet_share,
               r.quiet_share_b2b);
        for (v = 0; v < AX_COUNT; v++) printf("axis %d: %.2f ns (%.2f)\n", v, r.axis[v].ns, r.axis[v].ratio);
        for (v = 0; v < 2; v++)
            printf("i22 unit %s: seed %.2f ns, lib %.2f, inline %.2f\n", v ? "float" : "double",
                   r.i22_unit[v][0].ns, r.i22_unit[v][1].ratio, r.i22_unit[v][2].ratio);
        for (g = 0; g < 2; g++)
            for (v = 0; v < 2; v++)
                printf("i22 %s %s: bare inline %.2f ns, bare %.2f, lib %.2f, inline %.2f, normal %.2f\n",
                       g ? "gas" : "break", v ? "float" : "double", r.i22_mix[g][v][0].ns, r.i22_mix[g][v][1].ratio,
                       r.i22_mix[g][v][2].ratio, r.i22_mix[g][v][3].ratio, r.i22_mix[g][v][4].ratio);
        for (g = 0; g < 2; g++)
            for (v = 0; v < 2; v++)
                printf("i22 batch %s %s: scalar %.2f ns, batch %.2f, bare loop %.2f\n", g ? "random" : "gas",
                       v ? "float" : "double", r.i22_batch[g][v][0].ns, r.i22_batch[g][v][1].ns, r.i22_batch[g][v][2].ns);
        return 0;
    }
    if (argc == 2 && strcmp(argv[1], "--smoke") == 0) {
        bench_box2d_init();
        code = bench_smoke();
        bench_box2d_fini();
        return code;
    }
    if (!parse(argc, argv, &o)) {
        fprintf(stderr, "usage: %s [--smoke | --callgrind | [--results FILE] [--plot-data FILE] [--ir FILE] "
                        "[--flags TEXT] [--sizes FILE] [--plain N] [--extreme N] [--rounds N] [--ratio-rounds N] "
                        "[--large N]]\n", argv[0]);
        return 2;
    }
    bench_box2d_init();
    sets_make(sets, o.n_plain, o.n_extreme, 2024);
    measure_accuracy(sets, &res);
    sets_free(sets);
    measure_rough(&o, &res);
    measure_toi(&o, &res);
    measure_toi_accel(&o, &res);
    read_sizes(o.sizes, &res.sizes);
    measure_speed(&o, &res);
    read_ir(o.ir, &res);
    bench_box2d_fini();
    report(stdout, &res, &o);
    if (o.results) {
        FILE *f = fopen(o.results, "w");
        if (f == NULL) {
            fprintf(stderr, "bench: cannot write %s\n", o.results);
            return 2;
        }
        report(f, &res, &o);
        fclose(f);
    }
    if (o.plot_data) plot_data(o.plot_data, &res);
    return 0;
}
