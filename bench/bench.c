/* collide2d speed-for-accuracy benchmark.  See bench/bench.mk.
 *   bench [--results FILE] [--plot-data FILE] [--ir FILE] [--flags TEXT]
 *         [--plain N] [--extreme N] [--rounds N] [--large N]
 *   bench --smoke        quick self-check for `make test`
 *   bench --callgrind    driver for valgrind --tool=callgrind (client requests) */
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "box2d_contender.h"

int bench_smoke(void);

#define PAIRS_IN_CACHE 4096
#define CALLGRIND_PAIRS 1024
#define MAXK 32

typedef struct options {
    const char *results, *plot_data, *ir, *flags;
    int n_plain, n_extreme, rounds;
    size_t n_large;
} options;

typedef struct results {
    acc_stats acc[MAXK][2];     /* plain, extreme */
    int has_acc[MAXK][2];
    acc_stats eq[MAXK];         /* equal masses, e = 1 */
    int has_eq[MAXK];
    acc_stats general[MAXK];    /* equal-mass-only formulas on general masses */
    double ns[2][MAXK + 1];     /* random plain, impacts; last slot: empty call */
    double ir[2][MAXK + 1];     /* instructions per collision (-1: unknown) */
    double slow_share[2];
    roof_result roof[2];        /* double, float */
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

/* Reads "<label>/<id> <total Ir>" lines (made from callgrind dumps). */
static void read_ir(const char *path, results *res)
{
    char line[256], name[200];
    double total[2][MAXK + 1];
    int s, j;
    FILE *f = path ? fopen(path, "r") : NULL;
    for (s = 0; s < 2; s++)
        for (j = 0; j <= MAXK; j++) total[s][j] = res->ir[s][j] = -1;
    if (f == NULL) return;
    while (fgets(line, sizeof line, f)) {
        double v;
        if (sscanf(line, "%199s %lf", name, &v) != 2) continue;
        s = strncmp(name, "plain/", 6) == 0 ? 0 : strncmp(name, "impacts/", 8) == 0 ? 1 : -1;
        if (s < 0) continue;
        for (j = 0; j <= bench_ncontenders; j++) {
            const char *id = j < bench_ncontenders ? bench_contenders[j].id : "noop";
            if (strcmp(strchr(name, '/') + 1, id) == 0) total[s][j] = v;
        }
    }
    fclose(f);
    for (s = 0; s < 2; s++) {
        double base = total[s][bench_ncontenders];
        for (j = 0; j <= bench_ncontenders; j++) {
            int batch = j < bench_ncontenders && (bench_contenders[j].kind == KIND_BATCH ||
                                                  bench_contenders[j].kind == KIND_BATCHF);
            if (total[s][j] < 0 || base < 0) continue;
            /* Scalar rows: beyond the empty call's loop; a batch is one call. */
            res->ir[s][j] = (total[s][j] - (batch || j == bench_ncontenders ? 0 : base)) / CALLGRIND_PAIRS;
        }
    }
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
    for (s = 0; s < 2; s++) {
        ref_case *c = timing_cases(s, 1000 + (unsigned long long)s);
        timing_data *t = timing_make(c, PAIRS_IN_CACHE);
        res->slow_share[s] = timing_slow_share(c, PAIRS_IN_CACHE);
        timing_run(t, o->rounds, res->ns[s]);
        timing_free(t);
        free(c);
    }
    roof_run(0, o->n_large, 5, &res->roof[0]);
    roof_run(1, o->n_large, 5, &res->roof[1]);
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
               "uses FMA, results are bit-identical).\n\n");
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

static void speed_table(FILE *f, const results *res, const options *o)
{
    char b[8][32];
    const int base = 0; /* c2d_collide */
    int j;
    fprintf(f, "### Speed (same %d in-cache pairs for every contender, e = 1)\n\n", PAIRS_IN_CACHE);
    fprintf(f, "Median ns per collision over %d interleaved rounds (inputs restored untimed before each "
               "pass). *Random*: the plain generator (%.0f%% of pairs cancel in d and need the "
               "double-double tier). *Impacts*: disks thrown at each other with a uniform impact "
               "parameter (%.0f%% need it). Instructions: callgrind, %d pairs, minus the empty call's loop "
               "(%.1f / %.1f instr per pair) for scalar rows.\n\n",
            o->rounds, 100 * res->slow_share[0], 100 * res->slow_share[1], CALLGRIND_PAIRS,
            res->ir[0][bench_ncontenders], res->ir[1][bench_ncontenders]);
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

static const char *verdict(int ok) { return ok ? "**met**" : "**not met**"; }

static void goals(FILE *f, const results *res)
{
    const int lib = find("c2d_collide"), seed = find("seed_equal"), seedm = find("seed_masses");
    const int trig = find("trig"), batch = find("c2d_collide_batch"), batchf = find("c2d_collide_batchf");
    const int libf = find("c2d_collidef");
    const double r0 = res->ns[0][lib] / res->ns[0][seed], r1 = res->ns[1][lib] / res->ns[1][seed];
    const double b0 = res->ns[0][lib] / res->ns[0][batch], bf = res->ns[0][libf] / res->ns[0][batchf];
    const double roofd = res->roof[0].batch_pps / res->roof[0].roof_pps;
    const double rooff = res->roof[1].batch_pps / res->roof[1].roof_pps;
    const double lmax = fmax(res->acc[lib][0].max_ulp, res->acc[lib][1].max_ulp);
    const acc_stats *sx = &res->acc[seedm][1], *tx = &res->acc[trig][1];
    fprintf(f, "### Goals\n\n| goal | measured | verdict |\n|---|---|---|\n");
    fprintf(f, "| c2d_collide no slower than the seed transcription (ratio <= 1.0) | %.2f random, %.2f "
               "impacts (vs the any-mass transcription: %.2f / %.2f) | %s |\n", r0, r1,
            res->ns[0][lib] / res->ns[0][seedm], res->ns[1][lib] / res->ns[1][seedm], verdict(r0 <= 1 && r1 <= 1));
    fprintf(f, "| batch >= 4x the scalar call's throughput | random: double %.2fx, float %.2fx; impacts: double "
               "%.2fx, float %.2fx | %s |\n", b0, bf, res->ns[1][lib] / res->ns[1][batch],
            res->ns[1][libf] / res->ns[1][batchf], verdict(b0 >= 4 && bf >= 4));
    fprintf(f, "| large batches >= 50%% of the bandwidth roof | double %.0f%%, float %.0f%% | %s |\n",
            100 * roofd, 100 * rooff, verdict(roofd >= 0.5 && rooff >= 0.5));
    char b[4][32];
    fprintf(f, "| c2d_collide worst error a few ulp (header bound: 16); seed and trig worse and failing at the extremes | "
               "library %.3g ulp plain / %.3g extreme, wrong statuses + NaN + Inf: %d; seed (any mass) %s / "
               "%s ulp, on extremes %d NaN, %d Inf, %d wrong statuses; trig %s / %s ulp, on extremes %d NaN, "
               "%d Inf, %d wrong | %s |\n\n", res->acc[lib][0].max_ulp, res->acc[lib][1].max_ulp,
            res->acc[lib][0].wrong_status + res->acc[lib][1].wrong_status + res->acc[lib][0].nan +
                res->acc[lib][1].nan + res->acc[lib][0].inf + res->acc[lib][1].inf,
            fmt(res->acc[seedm][0].max_ulp, b[0]), fmt(sx->max_ulp, b[1]), sx->nan, sx->inf, sx->wrong_status,
            fmt(res->acc[trig][0].max_ulp, b[2]), fmt(tx->max_ulp, b[3]), tx->nan, tx->inf, tx->wrong_status,
            verdict(lmax <= 16 && sx->max_ulp > lmax && tx->max_ulp > lmax));
    fprintf(f,
            "Why the speed goals are missed (callgrind, `gcc -S`, `-fopt-info-vec`): the scalar call's arithmetic "
            "is cheaper than the transcription's (one division against a square root and two divisions), but it "
            "also checks every input and intermediate against overflow, underflow and cancellation, which is what "
            "keeps the extreme rows at 0 wrong statuses, NaN and Inf; those checks are most of the instruction-count "
            "difference in the table below. Pairs whose d cancels (kappa > 4) take the double-double tier. The batch "
            "kernel is vectorised (float at -O2 on baseline x86-64, double from x86-64-v2 on, where SSE4.2 adds the "
            "64-bit compares its flag masks need; clang vectorises both), but SSE2 holds two doubles and the pairs "
            "the kernel declines fall back to the scalar call, which caps the gain well below 4x; large batches are "
            "then compute-bound, not bandwidth-bound.\n\n");
}

static void report(FILE *f, const results *res, const options *o)
{
    fprintf(f, "## collide2d speed-for-accuracy benchmark (`make bench`)\n\n");
    machine(f, o);
    goals(f, res);
    speed_table(f, res, o);
    roof_table(f, res, o);
    accuracy_table(f, res, o);
    equal_table(f, res);
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
    o->results = o->plot_data = o->ir = o->flags = NULL;
    o->n_plain = 20000, o->n_extreme = 20000, o->rounds = 101, o->n_large = (size_t)1 << 21;
    for (i = 1; i < argc; i++) {
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (v == NULL) return 0;
        if (strcmp(argv[i], "--results") == 0) o->results = v;
        else if (strcmp(argv[i], "--plot-data") == 0) o->plot_data = v;
        else if (strcmp(argv[i], "--ir") == 0) o->ir = v;
        else if (strcmp(argv[i], "--flags") == 0) o->flags = v;
        else if (strcmp(argv[i], "--plain") == 0) o->n_plain = atoi(v);
        else if (strcmp(argv[i], "--extreme") == 0) o->n_extreme = atoi(v);
        else if (strcmp(argv[i], "--rounds") == 0) o->rounds = atoi(v);
        else if (strcmp(argv[i], "--large") == 0) o->n_large = (size_t)atol(v);
        else return 0;
        i++;
    }
    return o->n_plain > 0 && o->n_extreme > 0 && o->rounds > 0 && o->n_large >= 8;
}

int main(int argc, char **argv)
{
    options o;
    static results res;
    case_set sets[SET_COUNT];
    int code;
    if (argc == 2 && strcmp(argv[1], "--callgrind") == 0) return run_callgrind_driver();
    if (argc == 2 && strcmp(argv[1], "--smoke") == 0) {
        bench_box2d_init();
        code = bench_smoke();
        bench_box2d_fini();
        return code;
    }
    if (!parse(argc, argv, &o)) {
        fprintf(stderr, "usage: %s [--smoke | --callgrind | [--results FILE] [--plot-data FILE] [--ir FILE] "
                        "[--flags TEXT] [--plain N] [--extreme N] [--rounds N] [--large N]]\n", argv[0]);
        return 2;
    }
    bench_box2d_init();
    sets_make(sets, o.n_plain, o.n_extreme, 2024);
    measure_accuracy(sets, &res);
    sets_free(sets);
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
