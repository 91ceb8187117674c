/* The project's targets for the library (targets.md, the developers' file
 * beside report.md), each with the value this run measured and a pass/miss
 * mark, plus the LUT ablation that shows which encoding choice bought what.
 * Accuracy comes from the run's own materials (the 14 metals of Hoffman's
 * table must be in the scene), host speed from the output of `make bench`
 * at each flag set (--speed FILE) with the errors of bench_targets.c,
 * Cortex-M0 counts and sizes from the output of `make cross-count` and
 * `make size` (--cross and --size FILE; make report passes them all). */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench_targets.h"
#include "bench/speed_targets.h"
#include "3_encode/q15_params.h"
#include "fresnel_q15.h"
#include "fresnel_q15_fast.h"
#include "report/report.h"

enum { MISS, PASS, UNMEASURED };

static void goal_row(FILE *f, const char *what, const char *goal, int status, const char *fmt, ...)
{
    va_list ap;
    fprintf(f, "| %s | %s | ", what, goal);
    va_start(ap, fmt);
    vfprintf(f, fmt, ap);
    va_end(ap);
    fprintf(f, " | %s |\n", status == PASS ? "**pass**" : (status == MISS ? "**MISS**" : "not measured"));
}

/* ---- LUTs in Q1.15 on Hoffman's metals */

typedef struct lut_variant {
    const char *what;
    int n;
    lut_spacing spacing;
    int fitted, cubic;
} lut_variant;

static const lut_variant lut_variants[] = {
    {"16 nodes uniform in c, values on the curve, linear", 16, LUT_UNIFORM, 0, 0},
    {"16 nodes uniform in sqrt(c), values on the curve, linear (the naive LUT)", 16, LUT_GRAZING, 0, 0},
    {"16 nodes uniform in c, fitted values, linear", 16, LUT_UNIFORM, 1, 0},
    {"16 nodes uniform in sqrt(c), fitted values, linear (lut16)", 16, LUT_GRAZING, 1, 0},
    {"16 nodes uniform in sqrt(c), values on the curve, Catmull-Rom", 16, LUT_GRAZING, 0, 1},
    {"16 nodes uniform in sqrt(c), fitted values, Catmull-Rom (lut16-cubic)", 16, LUT_GRAZING, 1, 1},
    {"32 nodes uniform in sqrt(c), values on the curve, linear", 32, LUT_GRAZING, 0, 0},
    {"32 nodes uniform in sqrt(c), fitted values, linear (lut32)", 32, LUT_GRAZING, 1, 0},
    {"32 nodes uniform in sqrt(c), fitted values, Catmull-Rom (lut32-cubic)", 32, LUT_GRAZING, 1, 1},
    {"16 nodes uniform in a piecewise-linear sqrt(c), fitted, linear (lut16, grazing-pl)", 16, LUT_GRAZING_PL, 1, 0},
    {"32 nodes uniform in a piecewise-linear sqrt(c), fitted, linear (lut32, grazing-pl)", 32, LUT_GRAZING_PL, 1, 0},
    {"16 nodes uniform in a piecewise-linear sqrt(c), fitted, Catmull-Rom (interpolated in double)", 16,
     LUT_GRAZING_PL, 1, 1},
    {"16 nodes uniform in c (2 - c), fitted, Catmull-Rom (no root; interpolated in double)", 16, LUT_WARP2, 1, 1},
    {"16 nodes uniform in (1 + c - (1 - c)^16)/2, fitted, Catmull-Rom (no root; interpolated in double)", 16,
     LUT_WARP16, 1, 1},
};
#define N_VARIANTS ((int)(sizeof lut_variants / sizeof lut_variants[0]))
#define V_LUT16_CUBIC 5
#define V_LUT32 7
#define V_LUT32_PL 10

typedef struct lut_result {
    int measured;
    double worst_mean, worst_max, gold_mean, gold_max;
    const char *worst_mean_at, *worst_max_at;
} lut_result;

/* Channel ch of Q1.15 table q (n nodes per channel) at cos code c, by the
 * generator's own position and Catmull-Rom in double, rounded to a code:
 * the warps no runtime function reads. */
static fresnel_q15 lut_double_cubic(const uint16_t *q, int n, lut_spacing spacing, int32_t c)
{
    double pos = lut_position(spacing, c / 32768.0) * (n - 1), t, p0, p1, p2, p3, d, m1, m2, v;
    int j = (int)pos;
    if (j >= n - 1)
        j = n - 2;
    t = pos - j;
    p0 = q[j > 0 ? j - 1 : 0];
    p1 = q[j];
    p2 = q[j + 1];
    p3 = q[j + 2 < n ? j + 2 : n - 1];
    d = p2 - p1;
    m1 = 0.5 * (p2 - p0);
    m2 = 0.5 * (p3 - p1);
    v = floor(p1 + t * (m1 + t * ((3.0 * d - 2.0 * m1 - m2) + t * (m1 + m2 - 2.0 * d))) + 0.5);
    return (fresnel_q15)(v < 0.0 ? 0.0 : (v > 65535.0 ? 65535.0 : v));
}

/* One metal through one variant in Q1.15: mean and max CIEDE2000. */
static int lut_metal(report_run *r, const report_material *rm, const lut_variant *v, double *mean, double *max)
{
    double table[3 * 32], rgb[REPORT_ANGLES][3], rms;
    uint16_t q[3 * 32];
    int i, ch, a;
    if (v->fitted) {
        if (encode_lut(rm->s, r->g, &rm->p, v->spacing, v->n, v->cubic ? LUT_CUBIC : LUT_PLAIN, table))
            return -1;
    } else
        for (i = 0; i < v->n; i++) {
            double gt[3];
            ground_truth_gamut(rm->s, r->g, &rm->p, lut_node_cos(v->spacing, i, v->n), gt);
            for (ch = 0; ch < 3; ch++)
                table[ch * v->n + i] = gt[ch];
        }
    encode_curve_q15(table, 3 * v->n, q);
    for (a = 0; a < REPORT_ANGLES; a++) {
        int32_t c = q15_code(report_cos(a));
        fresnel_rgb_q15 o;
        if (v->cubic && v->spacing != LUT_GRAZING) { /* no runtime function: in double */
            o.r = lut_double_cubic(q, v->n, v->spacing, c);
            o.g = lut_double_cubic(q + v->n, v->n, v->spacing, c);
            o.b = lut_double_cubic(q + 2 * v->n, v->n, v->spacing, c);
        } else if (v->spacing == LUT_GRAZING_PL) { /* the Cortex-M0 fast path, channel by channel */
            o.r = fresnel_lut_pl_u16_q15_fast(q, v->n, c);
            o.g = fresnel_lut_pl_u16_q15_fast(q + v->n, v->n, c);
            o.b = fresnel_lut_pl_u16_q15_fast(q + 2 * v->n, v->n, c);
        } else
            o = v->cubic ? fresnel_lut_cubic_u16_q15_rgb(q, v->n, c)
                         : (v->spacing == LUT_UNIFORM ? fresnel_lut_linear_u16_q15_rgb(q, v->n, c)
                                                      : fresnel_lut_u16_q15_rgb(q, v->n, c));
        rgb[a][0] = o.r / 32768.0;
        rgb[a][1] = o.g / 32768.0;
        rgb[a][2] = o.b / 32768.0;
    }
    report_curve_de(&r->ls, (const double(*)[3])rm->gt, (const double(*)[3])rgb, mean, &rms, max);
    return 0;
}

static void lut_measure(report_run *r, lut_result *out)
{
    int v, i;
    memset(out, 0, N_VARIANTS * sizeof *out);
    for (i = 0; i < REPORT_HOFFMAN; i++)
        if (report_material_index(r, report_hoffman[i].id) < 0)
            return; /* all 14 or nothing */
    for (v = 0; v < N_VARIANTS; v++) {
        lut_result *o = &out[v];
        o->measured = 1;
        for (i = 0; i < REPORT_HOFFMAN; i++) {
            const report_material *rm = &r->mats[report_material_index(r, report_hoffman[i].id)];
            double mean, max;
            if (lut_metal(r, rm, &lut_variants[v], &mean, &max)) {
                o->measured = 0;
                break;
            }
            if (mean >= o->worst_mean) {
                o->worst_mean = mean;
                o->worst_mean_at = report_hoffman[i].id;
            }
            if (max >= o->worst_max) {
                o->worst_max = max;
                o->worst_max_at = report_hoffman[i].id;
            }
            if (!strcmp(report_hoffman[i].id, "au")) {
                o->gold_mean = mean;
                o->gold_max = max;
            }
        }
    }
}

static void lut_target(FILE *f, const char *what, const lut_result *o, double mean, double max)
{
    char goal[64];
    snprintf(goal, sizeof goal, "<= %g mean, <= %g max dE2000, each metal", mean, max);
    if (!o->measured)
        goal_row(f, what, goal, UNMEASURED, "the scene lacks Hoffman's 14 metals");
    else
        goal_row(f, what, goal, o->worst_mean <= mean && o->worst_max <= max ? PASS : MISS,
               "worst mean %.4f (%s), worst max %.4f (%s)", o->worst_mean, o->worst_mean_at, o->worst_max,
               o->worst_max_at);
}

static void hoffman_target(report_run *r, FILE *f)
{
    int i, beaten = 0, counted = 0;
    char misses[256] = "";
    double lo = INFINITY, hi = 0.0;
    for (i = 0; i < REPORT_HOFFMAN; i++) {
        if (!r->hoffman_in_gamut[i])
            continue;
        counted++;
        if (r->hoffman_rms[i][1] <= report_hoffman[i].fitted + 0.005) /* his table has two decimals */
            beaten++;
        else
            snprintf(misses + strlen(misses), sizeof misses - strlen(misses), " %s %.3f vs %.2f;", report_hoffman[i].id,
                     r->hoffman_rms[i][1], report_hoffman[i].fitted);
        lo = fmin(lo, r->hoffman_rms[i][1]);
        hi = fmax(hi, r->hoffman_rms[i][1]);
    }
    goal_row(f, "Fitted RGB eta, kappa (exact Fresnel), RMS dE2000 in ACEScg",
           "<= Hoffman's \"Fitted\" column per metal with F0 in gamut (his two decimals: <= his + 0.005)", beaten == counted ? PASS : MISS,
           "%d of %d metals at or below his value (ours %.3f-%.3f, his 0.01-0.08)%s%s", beaten, counted, lo, hi,
           *misses ? "; above:" : "", misses);
}

static void write_ablation(FILE *f, const lut_result *o)
{
    int v;
    if (!o[0].measured)
        return;
    fprintf(f, "\nWhich LUT choice bought what (Q1.15 tables, 2 bytes per node and channel, through the Q1.15 "
               "runtime; CIEDE2000 over Hoffman's 14 metals, worst per-metal mean and max, and gold, whose red F0 "
               "is out of the sRGB gamut, against its curve under the gamut policy):\n\n"
               "| LUT | bytes per material | worst mean | worst max | gold mean / max |\n|---|---:|---:|---:|---:|\n");
    for (v = 0; v < N_VARIANTS; v++)
        fprintf(f, "| %s | %d | %.4f (%s) | %.4f (%s) | %.4f / %.4f |\n", lut_variants[v].what, 6 * lut_variants[v].n,
                o[v].worst_mean, o[v].worst_mean_at, o[v].worst_max, o[v].worst_max_at, o[v].gold_mean,
                o[v].gold_max);
}

/* ---- host speed: `make bench` at each flag set (--speed FILE), errors from
 * bench_targets.c */

/* The accuracy row (bench_targets.c) of a speed row (speed/speed.c): the
 * same function, timed as a call or inlined. */
static const char *const accuracy_of[][2] = {
    {"conductor-call", "conductor"},         {"conductor-batch", "conductor-batch"},
    {"mitsuba-call", "mitsuba-style"},       {"mitsuba-inline", "mitsuba-style"},
    {"lut16-cubic-f32", "lut16-cubic-f32"},  {"lut32-q15", "lut32-q15"},
    {"lut16-cubic-q15", "lut16-cubic-q15"},  {"lut16-linear-q15", "lut16-linear-q15"},
    {"schlick-q15", "schlick-q15"},
    {"schlick-f32", "schlick"},
};

static double row_error(const bench_target_row *rows, int n, const char *speed_name)
{
    size_t k;
    int i;
    for (k = 0; k < sizeof accuracy_of / sizeof accuracy_of[0]; k++)
        if (!strcmp(accuracy_of[k][0], speed_name))
            for (i = 0; i < n; i++)
                if (!strcmp(rows[i].name, accuracy_of[k][1]))
                    return rows[i].max_abs_err;
    return NAN;
}

/* The compiler of a --speed file as its header names it ("gcc 12.2.0",
 * "Debian Clang 14.0.6"), or "?" when the file has no compiler line. */
static const char *speed_compiler(const speed_file *sf) { return *sf->compiler ? sf->compiler : "?"; }

static void host_speed_targets(const report_run *r, FILE *f)
{
    bench_target_row rows[BENCH_TARGET_ROWS];
    int n, t, k, i;
    if (!r->speed_count) {
        goal_row(f, "Host speed against Mitsuba 3's and pbrt-v4's algorithms, LUTs against Schlick", "", UNMEASURED,
               "run through `make report` (--speed: the output of `make bench` at -O2 and -O3 -march=native)");
        return;
    }
    n = bench_target_errors(rows, BENCH_TARGET_ROWS);
    for (t = 0; t < speed_target_count; t++) {
        const speed_target *g = &speed_targets[t];
        char goal[96], text[4096] = "", what[256];
        int covered[SPEED_FLAGSETS] = {0}, measured = 0, missed = 0;
        double en = row_error(rows, n, g->num), ed = row_error(rows, n, g->den);
        snprintf(goal, sizeof goal, "<= %gx at %s, <= %gx at %s (one process, median over interleaved rounds)",
                 g->goal[0], speed_flagset_names[0], g->goal[1], speed_flagset_names[1]);
        /* every file at a flag set with a goal, in the order given (each compiler's) */
        for (i = 0; i < r->speed_count; i++) {
            const speed_file *sf = r->speed[i];
            const speed_ratio *q = speed_file_target(sf, g->id);
            const speed_row *a = speed_file_row(sf, g->num), *b = speed_file_row(sf, g->den);
            size_t len = strlen(text);
            if ((k = speed_flagset(sf->opt)) < 0)
                continue;
            if (!q || !a || !b) {
                snprintf(text + len, sizeof text - len, "%s%s %s: not measured", *text ? "; " : "",
                         speed_compiler(sf), speed_flagset_names[k]);
                continue;
            }
            covered[k] = 1;
            if (q->med <= g->goal[k])
                snprintf(text + len, sizeof text - len, "%s%s %s: %.2fx (quartiles %.2f-%.2f) pass", *text ? "; " : "",
                         speed_compiler(sf), speed_flagset_names[k], q->med, q->q1, q->q3);
            else {
                missed++;
                snprintf(text + len, sizeof text - len,
                         "%s%s %s: %.2fx (quartiles %.2f-%.2f) MISS: %s takes %.2fx the time of %s, goal %gx "
                         "(%.2f ns against %.2f ns per evaluation)",
                         *text ? "; " : "", speed_compiler(sf), speed_flagset_names[k], q->med, q->q1, q->q3, g->num,
                         q->med, g->den, g->goal[k], a->ns[2], b->ns[2]);
            }
        }
        for (k = 0; k < SPEED_FLAGSETS; k++) {
            size_t len = strlen(text);
            measured += covered[k];
            if (!covered[k])
                snprintf(text + len, sizeof text - len, "%s%s: not measured", *text ? "; " : "",
                         speed_flagset_names[k]);
        }
        for (i = 0; i < r->speed_count; i++) { /* other flag sets: their ratio, no goal */
            const speed_ratio *q = speed_flagset(r->speed[i]->opt) < 0 ? speed_file_target(r->speed[i], g->id) : NULL;
            size_t len = strlen(text);
            if (q)
                snprintf(text + len, sizeof text - len, "; %s %s: %.2fx (no goal at this flag set)",
                         speed_compiler(r->speed[i]), r->speed[i]->opt, q->med);
        }
        if (missed && g->tried) {
            size_t len = strlen(text);
            snprintf(text + len, sizeof text - len, "; tried: %s", g->tried);
        }
        if (!isnan(en) && !isnan(ed)) {
            size_t len = strlen(text);
            snprintf(text + len, sizeof text - len, "; largest error %s %.1e, %s %.1e (fresnel bench --targets)",
                     g->num, en, g->den, ed);
        }
        snprintf(what, sizeof what, "Host speed: %s (rows %s / %s of `make bench`)", g->what, g->num, g->den);
        goal_row(f, what, goal, missed ? MISS : (measured == SPEED_FLAGSETS ? PASS : UNMEASURED), "%s", text);
    }
}

/* ---- Cortex-M0 (make cross-count, make size output) */

/* Column col of row `name` in the section whose header starts with
 * `section` ("== m0 fixed point"): the row is the name, spaces, then the
 * instructions' mean, min and max (columns 0-2) and, on the Cortex-M0, the
 * cycles' with a 1-cycle (3-5) and a 32-cycle multiplier (6-8). NaN when
 * absent. */
static double section_column(const char *path, const char *section, const char *name, int col)
{
    FILE *in = fopen(path, "r");
    char line[512];
    int in_m0 = 0;
    double v = NAN;
    size_t len = strlen(name);
    if (!in)
        return NAN;
    while (fgets(line, sizeof line, in)) {
        if (!strncmp(line, "== ", 3))
            in_m0 = !strncmp(line, section, strlen(section));
        else if (in_m0 && !strncmp(line, name, len) && line[len] == ' ' &&
                 isdigit((unsigned char)line[len + strspn(line + len, " ")])) {
            /* the name itself, not a longer row it begins ("lut u16" of "lut u16 fast") */
            char *p = line + len, *end;
            double x = NAN;
            int k;
            for (k = 0; k <= col; k++, p = end) {
                x = strtod(p, &end);
                if (end == p) {
                    x = NAN;
                    break;
                }
            }
            v = isfinite(x) ? x : NAN; /* strtod reads "inf" too */
        }
    }
    fclose(in);
    return v;
}

static double m0_column(const char *path, const char *name, int col)
{
    return section_column(path, "== m0 fixed point", name, col);
}

double report_m0_count(const char *path, const char *name) { return m0_column(path, name, 0); }

/* The numbers after ".text " and ".rodata " on the line starting with
 * prefix; -1 when absent. */
static void size_line(const char *path, const char *prefix, long *text, long *rodata, long *more_text,
                      long *more_rodata)
{
    FILE *in = fopen(path, "r");
    char line[512];
    *text = *rodata = *more_text = *more_rodata = -1;
    if (!in)
        return;
    while (fgets(line, sizeof line, in))
        if (!strncmp(line, prefix, strlen(prefix))) {
            char *p = strstr(line, ".text "), *q;
            if (p)
                *text = strtol(p + 6, NULL, 10);
            if ((q = strstr(line, ".rodata ")))
                *rodata = strtol(q + 8, NULL, 10);
            if ((p = strstr(line, "per further material: .text ")))
                *more_text = strtol(p + 28, NULL, 10);
            if (p && (q = strstr(p, ".rodata ")))
                *more_rodata = strtol(q + 8, NULL, 10);
        }
    fclose(in);
}

/* The Q1.15 batches against the scalar calls, per cosine, on the cores
 * with a batch body of their own. */
static void batch_targets(const report_run *r, FILE *f)
{
    static const struct {
        const char *what, *scalar, *batch;
    } rows[] = {{"Schlick", "schlick", "schlick batch"},
                {"F82", "f82", "f82 batch"},
                {"LUT (u16, 64 nodes uniform in sqrt(c))", "lut u16", "lut u16 batch"},
                {"LUT (u16, 64 nodes uniform in c)", "lut-linear u16", "lut-linear u16 batch"}};
    static const struct {
        const char *section, *core;
        double goal;
    } cores[] = {{"== m4f fixed point", "Cortex-M4F (long multiply)", 0.5}, {"== m55 fixed point", "Cortex-M55 (Helium)", 0.25}};
    int c, k;
    if (!r->cross_path)
        return;
    for (c = 0; c < 2; c++)
        for (k = 0; k < 4; k++) {
            double one = section_column(r->cross_path, cores[c].section, rows[k].scalar, 0);
            double batch = section_column(r->cross_path, cores[c].section, rows[k].batch, 0);
            char what[200], goal[32];
            snprintf(what, sizeof what, "%s, %s batch: instructions per cosine against the scalar call's (qemu trace)",
                     cores[c].core, rows[k].what);
            snprintf(goal, sizeof goal, "<= %.2gx", cores[c].goal);
            if (isnan(one) || isnan(batch))
                goal_row(f, what, goal, UNMEASURED, "not in the cross-count output");
            else
                goal_row(f, what, goal, batch <= cores[c].goal * one ? PASS : MISS, "%.1f against %.0f (%.2fx)%s",
                         batch, one, batch / one,
                         k == 2 ? (c == 0 ? "; the root's last two corrections taken only where they can move the "
                                            "position (fresnel_q15.h, BATCHES)"
                                          : "; the scalar call's root, four lanes at a time")
                                : "");
        }
}

/* .text and .rodata of `make size`'s table row `model` (fixed point) on
 * the Cortex-M0, its first target column: 0, or -1 when absent. */
static int table_bytes(const char *path, const char *model, long *text, long *rodata)
{
    FILE *in = path ? fopen(path, "r") : NULL;
    char line[512], want[128];
    int found = -1;
    if (!in)
        return -1;
    snprintf(want, sizeof want, "| %s | fixed | ", model);
    while (fgets(line, sizeof line, in))
        if (!strncmp(line, want, strlen(want)) &&
            sscanf(line + strlen(want), "%ld / %ld", text, rodata) == 2)
            found = 0;
    fclose(in);
    return found;
}

static void m0_targets(const report_run *r, FILE *f)
{
    static const struct {
        const char *what, *row, *library_row;
        double goal;
        const char *why; /* for a miss: where the instructions go */
    } counts[] = {{"Schlick", "schlick fast", "schlick", 20, NULL},
                  {"LUT (u16, 64 nodes, grazing-pl spacing)", "lut u16 pl fast", NULL, 30, NULL},
                  {"LUT (u16, 64 nodes, nodes uniform in sqrt(c))", "lut u16 fast", "lut u16", 30,
                   "the square root of the position (chord tables in Q22) is most of the call; the same table "
                   "read through the root-free grazing-pl spacing (row above) meets the goal at the same accuracy "
                   "(the LUT table below), and the polynomial warps that drop the root lose it"},
                  {"F82", "f82 fast", "f82", 35, NULL},
                  {"exact conductor", "exact-conductor fast", "exact-conductor", 300, NULL}};
    long t, ro, mt, mr;
    int k;
    if (!r->cross_path) {
        goal_row(f, "Cortex-M0 instructions and sizes", "", UNMEASURED, "run through `make report` (--cross, --size)");
        return;
    }
    for (k = 0; k < 5; k++) {
        double fast = report_m0_count(r->cross_path, counts[k].row);
        double lib = counts[k].library_row ? report_m0_count(r->cross_path, counts[k].library_row) : NAN;
        char what[160], goal[32];
        snprintf(what, sizeof what, "Cortex-M0 fixed point, %s: instructions per evaluation (qemu trace)",
                 counts[k].what);
        snprintf(goal, sizeof goal, "<= %.0f", counts[k].goal);
        if (isnan(fast) && isnan(lib))
            goal_row(f, what, goal, UNMEASURED, "not in the cross-count output");
        else {
            double best = isnan(fast) ? lib : fast;
            const char *why = best > counts[k].goal && counts[k].why ? counts[k].why : NULL;
            if (isnan(fast))
                goal_row(f, what, goal, lib <= counts[k].goal ? PASS : MISS, "%.0f (library function; no fast path)%s%s",
                       lib, why ? "; " : "", why ? why : "");
            else if (isnan(lib))
                goal_row(f, what, goal, fast <= counts[k].goal ? PASS : MISS, "%.0f inline fast path (its only form)%s%s",
                       fast, why ? "; " : "", why ? why : "");
            else
                goal_row(f, what, goal, fast <= counts[k].goal ? PASS : MISS,
                       "%.0f inline fast path (library function %.0f)%s%s", fast, lib, why ? "; " : "", why ? why : "");
        }
    }
    { /* the exact conductor's fast path: its worst call, its cycles and its bound as well */
        const char *row = counts[4].row;
        double mx = m0_column(r->cross_path, row, 2);
        if (!isnan(mx))
            goal_row(f, "Cortex-M0 fixed point, exact conductor fast path: the slowest call, cycles, error",
                   "<= 300 instructions at <= 4 LSB", mx <= 300 && FRESNEL_BOUND_CONDUCTOR_Q15_FAST <= 4 ? PASS : MISS,
                   "%.0f instructions at most; cycles mean %.0f (max %.0f) with a 1-cycle multiplier, %.0f (max %.0f) "
                   "with a 32-cycle one; error <= %.1f LSB (FRESNEL_BOUND_CONDUCTOR_Q15_FAST, tests/runtime/q15/test_q15_fast.c)",
                   mx, m0_column(r->cross_path, row, 3), m0_column(r->cross_path, row, 5),
                   m0_column(r->cross_path, row, 6), m0_column(r->cross_path, row, 8),
                   FRESNEL_BOUND_CONDUCTOR_Q15_FAST);
    }
    size_line(r->size_path, "schlick-only fixed scene:", &t, &ro, &mt, &mr);
    if (t >= 0)
        goal_row(f, "Cortex-M0 -Os, a Schlick-only fixed scene, one channel per material", "<= 64 B .text, <= 8 B .rodata per material",
               t <= 64 && mr <= 8 ? PASS : MISS, ".text %ld B; .rodata %ld B per further material", t, mr);
    size_line(r->size_path, "schlick-only fixed scene, RGB", &t, &ro, &mt, &mr);
    if (t >= 0)
        goal_row(f, "Cortex-M0 -Os, the same scene in RGB (an F0 triple per material)", "<= 64 B .text, <= 8 B .rodata per material",
               t <= 64 && mr <= 8 ? PASS : MISS, ".text %ld B; .rodata %ld B per further material", t, mr);
    size_line(r->size_path, "whole fixed runtime", &t, &ro, &mt, &mr);
    if (t >= 0)
        goal_row(f, "Cortex-M0 -Os, the whole fixed-point runtime (every model's Q15 code)", "<= 2048 B .text",
               t <= 2048 ? PASS : MISS, ".text %ld B", t);
    {
        long ft, fr, et, er;
        if (!table_bytes(r->size_path, "exact-conductor-rgb-fast", &ft, &fr) &&
            !table_bytes(r->size_path, "exact-conductor-rgb", &et, &er))
            goal_row(f, "Cortex-M0 -Os, the exact conductor's RGB fast path (fresnel_conductor_q15_rgb_fast): code and "
                        "tables against the library's RGB call (fresnel_conductor_q15_rgb)",
                     "<= the library call's", ft + fr <= et + er ? PASS : MISS,
                     "%ld B (.text %ld, .rodata %ld) against %ld B (.text %ld, .rodata %ld)%s", ft + fr, ft, fr, et + er,
                     et, er,
                     ft + fr <= et + er ? ""
                                        : "; the fast path's chord tables (two square roots and a reciprocal with no "
                                          "division, a byte table of leading zeros for the Cortex-M0's missing CLZ) "
                                          "are most of it: its code, inlined once for the three channels, is half "
                                          "the library call's");
    }
}

/* ---- the thin film (report_film.c measures it): one row per type with a
 * goal, and the Cortex-M0's */

/* The goals per number type id: mean and max CIEDE2000; 0 where the goal
 * names none. */
static const double film_goal_mean[NUMBER_TYPES] = {0.5, 0.6, 1.0};
static const double film_goal_max[NUMBER_TYPES] = {2.0, 2.5, 0.0};
#define FILM_GOAL_M0_INSTRUCTIONS 2000.0

/* The film against the better of its two peers (KHR_materials_iridescence,
 * the polarised form with its best input set) on the goal substrates the
 * scene has: its binary32 mean CIEDE2000 at most FILM_GOAL_PEER_RATIO of
 * the peer's, each substrate. A miss names each substrate over the goal
 * with the film's mean in every type: where they agree, the arithmetic is
 * not what limits it. */
#define FILM_GOAL_PEER_RATIO 0.05
static void film_peer_target(const report_run *r, FILE *out)
{
    static const char *const goal_substrates[] = {"au", "cu", "al", "ti", "fe", "bk7"};
    const report_film *f = &r->film;
    const scene *sc = &r->sc;
    int best, g, i, t, n = 0, over = 0;
    double worst = 0.0;
    char worst_id[64] = "", misses[512] = "";
    size_t used = 0;
    if (!f->peer_measured)
        return;
    best = report_film_best_polarised(f, sc->material_count);
    for (g = 0; g < (int)(sizeof goal_substrates / sizeof goal_substrates[0]); g++)
        for (i = 0; i < sc->material_count; i++) {
            const report_film_cell *c0 = &f->cells[i * number_types_available];
            double ratio = c0->de_mean / fmin(f->peer_mean[i], f->pol_mean[best * sc->material_count + i]);
            if (strcmp(r->mats[i].p.info.id, goal_substrates[g]))
                continue;
            n++;
            if (ratio > worst) {
                worst = ratio;
                snprintf(worst_id, sizeof worst_id, "%s", r->mats[i].p.info.id);
            }
            if (ratio <= FILM_GOAL_PEER_RATIO || used >= sizeof misses)
                continue;
            over++;
            used += (size_t)snprintf(misses + used, sizeof misses - used, "%s %s %.3f (film mean", used ? ";" : "",
                                     r->mats[i].p.info.id, ratio);
            for (t = 0; t < number_types_available && used < sizeof misses; t++)
                used += (size_t)snprintf(misses + used, sizeof misses - used, "%s %s %.3f", t ? "," : "",
                                         number_types[t].name, c0[t].de_mean);
            if (used < sizeof misses)
                used += (size_t)snprintf(misses + used, sizeof misses - used, ")");
        }
    if (!n)
        return;
    fprintf(out, "| Thin film (%s) in %s beside its peers (KHR_materials_iridescence; the polarised form on its "
                 "best input): its mean over the better peer's, on the goal substrates of Au, Cu, Al, Ti, Fe, BK7 in "
                 "the scene (%d) | <= %g, each substrate | worst %.3f (%s)%s%s | %s |\n",
            f->entry.name, number_types[0].name, n, FILM_GOAL_PEER_RATIO, worst, worst_id, over ? "; over the goal:" : "",
            misses, over ? "**MISS**" : "**pass**");
}

static void film_targets(const report_run *r, FILE *out)
{
    const report_film *f = &r->film;
    const scene *sc = &r->sc;
    int i, t;
    double m0;
    if (!f->present)
        return;
    for (t = 0; t < number_types_available; t++) {
        int id = number_types[t].id, ok;
        double mean = 0.0, max = 0.0;
        char goal[64];
        for (i = 0; i < sc->material_count; i++) {
            mean += f->cells[i * number_types_available + t].de_mean / sc->material_count;
            max = fmax(max, f->cells[i * number_types_available + t].de_max);
        }
        if (film_goal_max[id] > 0.0)
            snprintf(goal, sizeof goal, "<= %g mean, <= %g max dE2000", film_goal_mean[id], film_goal_max[id]);
        else
            snprintf(goal, sizeof goal, "<= %g mean dE2000", film_goal_mean[id]);
        ok = mean <= film_goal_mean[id] && (film_goal_max[id] <= 0.0 || max <= film_goal_max[id]);
        fprintf(out, "| Thin film (%s) in %s against its spectral truth, the scene's materials | %s | mean %.3f, max %.3f | %s |\n",
                f->entry.name, number_types[t].name, goal, mean, max, ok ? "**pass**" : "**MISS**");
    }
    film_peer_target(r, out);
    m0 = r->cross_path && model_of(f->entry.row)->cross_row ? report_m0_count(r->cross_path, model_of(f->entry.row)->cross_row) : NAN;
    if (!isnan(m0))
        fprintf(out, "| Cortex-M0 fixed point, thin film: instructions per RGB evaluation of fresnel_film_q15_rgb (qemu trace) "
                     "| <= %g | %.0f | %s |\n",
                FILM_GOAL_M0_INSTRUCTIONS, m0, m0 <= FILM_GOAL_M0_INSTRUCTIONS ? "**pass**" : "**MISS**");
}

void report_targets(report_run *r, FILE *f)
{
    lut_result luts[N_VARIANTS];
    lut_measure(r, luts);
    fprintf(f, "# Targets\n\nThe project's goals for the library, for its developers, each with the value this run "
               "measured (`build/fresnel report --scene %s`; the measurements themselves: report.md). Accuracy: "
               "theta 0-90 deg in 1 deg steps, linear %s, against the spectral ground truth under the gamut policy, on the 14 "
               "metals of Hoffman's table.\n\n| target | goal | measured | |\n|---|---|---|---|\n",
            r->scene_path, r->sc.space);
    lut_target(f, "LUT, 16 nodes per channel in Q1.15 (96 bytes per material): lut16-cubic", &luts[V_LUT16_CUBIC],
               0.01, 0.05);
    lut_target(f, "LUT, 32 nodes per channel in Q1.15 (192 bytes): lut32", &luts[V_LUT32], 0.005, 0.03);
    lut_target(f, "LUT, 32 nodes per channel in Q1.15 for the Cortex-M0 fast path: lut32, lut_spacing grazing-pl",
               &luts[V_LUT32_PL], 0.005, 0.03);
    hoffman_target(r, f);
    if (luts[V_LUT16_CUBIC].measured)
        goal_row(f, "Gold (red F0 1.04 in linear sRGB, out of gamut): the LUT targets against its curve under the gamut policy",
               "lut16: <= 0.01 / 0.05; lut32: <= 0.005 / 0.03",
               luts[V_LUT16_CUBIC].gold_mean <= 0.01 && luts[V_LUT16_CUBIC].gold_max <= 0.05 &&
                       luts[V_LUT32].gold_mean <= 0.005 && luts[V_LUT32].gold_max <= 0.03
                   ? PASS
                   : MISS,
               "lut16-cubic %.4f / %.4f, lut32 %.4f / %.4f", luts[V_LUT16_CUBIC].gold_mean,
               luts[V_LUT16_CUBIC].gold_max, luts[V_LUT32].gold_mean, luts[V_LUT32].gold_max);
    host_speed_targets(r, f);
    m0_targets(r, f);
    batch_targets(r, f);
    film_targets(r, f);
    write_ablation(f, luts);
    fprintf(f, "\n");
}
