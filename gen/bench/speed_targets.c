/* The host speed targets and the `make bench` file (see speed_targets.h). */
#include "bench/speed_targets.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const speed_flagset_names[SPEED_FLAGSETS] = {"-O2", "-O3 -march=native"};

/* Where the film's time goes, against either peer. */
#define FILM_PEER_TIME                                                                                                 \
    "the film's time does not fall with fewer poles (tests/README.md, \"Thin film: poles\": 70.6 ns at three "      \
    "poles, 65.4 ns at six, gcc -O2): the eight-lane loop over the poles and the 53 table values interpolated per "   \
    "call are its floor, not the poles' count. On a 2-core host shared with other work the ratios moved "            \
    "across the goals from run to run (gcc -O2, three runs of make bench: 0.46-0.54 against KHR, 0.24-0.27 against " \
    "the polarised form, quartiles)"

/* Row names are those of tests/speed/kernels.c. */
const speed_target speed_targets[] = {
    {"batch-vs-mitsuba-inline", "conductor-batch", "mitsuba-inline",
     "fresnel_conductor_batch against Mitsuba 3's fresnel_conductor inlined in an array loop (x86-64 host)", {0.5, 0.8},
     "fused multiply-adds in the scalar and the vector code alike where the target has them (clang 14 does not "
     "define FP_FAST_FMAF, so its kernels had taken Dekker's split: clang -O3 -march=native on AVX-512 from 1.03x "
     "to 0.87x), and FMA for the exact c^2 in the run-time AVX2 kernel of -O2 builds (clang -O2 from 0.59x to "
     "0.49x) were kept; four vectors per step instead of two (no change) was not. Per cosine the batch needs two "
     "correctly rounded square roots and a division, Mitsuba's form two and two, and one unit, not pipelined, "
     "executes them: rows sqrt2-div1 and sqrt2-div2 (those operations alone, chained, at the run's width) are the "
     "floor of each, and the batch runs about 10% above its own. Where the compiler brings Mitsuba's loop near "
     "its floor (clang contracts it into FMAs: on an AMD Zen 4 with AVX-512, 0.57 ns against a floor of 0.54 ns "
     "per cosine), 0.8x asks the batch to come within 3% of its floor (0.44 ns)"},
    {"rgb-batch-vs-mitsuba-inline", "conductor-rgb-batch", "mitsuba-inline-rgb",
     "fresnel_conductor_rgb_batch (three channels of one material) against Mitsuba 3's fresnel_conductor inlined "
     "per channel in an array loop",
     {0.5, 0.8},
     "the one-channel kernel per channel with the cosine terms shared and two vectors of cosines per step (one "
     "per step: no change); the same floor as the one-channel batch, three times (rows sqrt2-div1 and "
     "sqrt2-div2), and the interleaving of the three channels into rows on top"},
    {"conductor-vs-mitsuba-call", "conductor-call", "mitsuba-call",
     "fresnel_conductor against Mitsuba 3's fresnel_conductor, both out-of-line calls", {1.0, 1.0},
     "A = eta^2 - kappa^2 - sin^2 from exact squares in binary64 where the target has it in hardware (from 1.85x at "
     "-O2), one body for every form, one division (the Np-free ratio) were kept; computing every form and "
     "selecting, SSE min/max clamps, binary64 throughout, and prepare plus prepared inlined were slower or no "
     "better. The rest is the input clamps and the choice of form (with both removed the call measured 1.01x at "
     "-O2), which buy the bound: 2.9e-7 against the textbook form's 3.6e-5. Fused multiply-adds where the target "
     "has them were kept (gcc -O3 -march=native from 1.20x to 1.14x, AMD Zen 4). A documented fast variant was "
     "measured there and not shipped: without the input clamps and the choice of form (one body; eta kappa = 0 "
     "or >= 2^-30 required) it took 1.07x (gcc -O2), 1.16x (clang -O2), 1.20x (gcc -O3 -march=native), 1.04x "
     "(clang -O3 -march=native); only with A formed in binary32 as Mitsuba forms it did it beat the call (0.91x "
     "gcc -O2, 1.02x clang -O2), at an error of 8.1e-5 over the Q15 fast path's domain and 0.023 beside a "
     "dielectric's critical angle, far above 1e-5. The accurate form's floor is its binary64 A, about 1.2 ns of "
     "the 9.2 ns call at gcc -O2, and the clamps"},
    {"lut16-cubic-vs-schlick", "lut16-cubic-f32", "schlick-f32",
     "fresnel_lut_cubic, 16 nodes, against fresnel_schlick (binary32 calls)", {1.5, 1.5},
     "the outer nodes by index arithmetic instead of branches (same results, no measurable change) was kept; a "
     "reordered polynomial (3%, other last bits) was not. The call is a chain: square root, position to integer "
     "and back, four loads, a three-step Horner polynomial and the clamp to the nodes' range, against Schlick's "
     "five products; linear interpolation through the same position (lut32-f32) costs about 1.4x. Nodes uniform "
     "in a root-free warp (the generator fits them; the report's LUT table) were not kept: the root is about 3% of "
     "the call (c (2 - c) in its place measured 2.91x against 3.00x, gcc -O2, AMD Zen 4), and at equal size the "
     "warps lose accuracy (16 nodes, worst max dE2000 0.45 for c (2 - c), 0.063 for (1 + c - (1 - c)^16)/2, "
     "against 0.0155): the time is the cubic's own, four loads, the index arithmetic and the clamp to its two "
     "nodes around the Catmull-Rom sum"},
    {"lut32-q15-vs-schlick-q15", "lut32-q15", "schlick-q15",
     "fresnel_lut_u16_q15, 32 nodes, against fresnel_schlick_q15", {3.0, 3.0}, NULL},
    {"lut16-cubic-q15-vs-schlick-q15", "lut16-cubic-q15", "schlick-q15",
     "fresnel_lut_cubic_u16_q15, 16 nodes, against fresnel_schlick_q15", {3.0, 3.0},
     "sqrt(c) from two chord tables instead of 30 digit steps (bit-identical) was kept (from about 24x); every "
     "helper inlined (6%, twice the Cortex-M0 code) and a branch-free four-tap sum (no gain) were not. Without any "
     "root (nodes uniform in c) the Q1.15 Catmull-Rom alone costs about 2x Q1.15 Schlick. Nodes uniform in the "
     "root-free warp c (2 - c) (one product for the root) measured 2.19x at -O2 and 2.07x at -O3 -march=native "
     "(gcc, AMD Zen 4), within the goal, but at equal size its worst max dE2000 is 0.45 against sqrt(c)'s 0.0155, "
     "and (1 + c - (1 - c)^16)/2 reaches 0.063, four times sqrt(c)'s and above the lut16 target's 0.05 (the "
     "report's LUT table), so sqrt(c) stays: its exact root is the half of the call above the goal"},
    {"lut16-linear-q15-vs-schlick-q15", "lut16-linear-q15", "schlick-q15",
     "fresnel_lut_linear_u16_q15, 16 nodes, against fresnel_schlick_q15", {3.0, 3.0}, NULL},
    {"film-vs-schlick-rgb", "film-f32", "schlick-rgb-f32",
     "fresnel_film_rgb (a thin film: six poles, 53 interpolated table values, RGB) against fresnel_schlick_rgb",
     {10.0, 10.0}, NULL},
    {"film-vs-polarised-film", "film-f32", "polarised-film-inline",
     "fresnel_film_rgb against the same film by the polarised form of its family (Belcour and Barla's exact "
     "Fresnel on per-channel eta, kappa; gen/bench/peers.h, inlined), a 1.5 film on gold",
     {0.25, 0.25}, FILM_PEER_TIME},
    {"film-vs-khr-iridescence", "film-f32", "khr-iridescence-inline",
     "fresnel_film_rgb against the same film by KHR_materials_iridescence's form (Schlick at both interfaces, as "
     "the glTF Sample Viewer evaluates it; gen/bench/peers.h, inlined)",
     {0.5, 0.5}, FILM_PEER_TIME},
};
const int speed_target_count = (int)(sizeof speed_targets / sizeof speed_targets[0]);

int speed_flagset(const char *opt)
{
    char words[96] = "";
    const char *p = opt;
    int k;
    while (*p) { /* single blanks between words */
        size_t n;
        while (*p == ' ' || *p == '\t')
            p++;
        n = strcspn(p, " \t");
        if (!n)
            break;
        if (strlen(words) + n + 2 > sizeof words)
            return -1;
        if (*words)
            strcat(words, " ");
        strncat(words, p, n);
        p += n;
    }
    for (k = 0; k < SPEED_FLAGSETS; k++)
        if (!strcmp(words, speed_flagset_names[k]))
            return k;
    return -1;
}

static void text_value(char *dst, size_t size, const char *v)
{
    size_t n = strcspn(v, "\r\n");
    if (n >= size)
        n = size - 1;
    memcpy(dst, v, n);
    dst[n] = '\0';
}

/* sscanf's %lf reads "inf" and "nan" too. */
static int all_finite(const double *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

int speed_file_read(FILE *in, const char *path, speed_file *f, char *where, int wherelen, const char **what)
{
    char line[512];
    int ln = 0, has_opt = 0;
    memset(f, 0, sizeof *f);
    while (fgets(line, sizeof line, in)) {
        char name[SPEED_NAME], form[16], tail;
        const char *bad = NULL;
        ln++;
        if (!strchr(line, '\n') && !feof(in))
            bad = "expected a line shorter than 512 bytes";
        else if (!strncmp(line, "# opt: ", 7)) {
            if (has_opt)
                bad = "expected one flag set per file (a second '# opt:' line; `make bench OPT=...` prints one)";
            text_value(f->opt, sizeof f->opt, line + 7);
            has_opt = 1;
        } else if (!strncmp(line, "# compiler: ", 12))
            text_value(f->compiler, sizeof f->compiler, line + 12);
        else if (!strncmp(line, "# cpu: ", 7))
            text_value(f->cpu, sizeof f->cpu, line + 7);
        else if (!strncmp(line, "# vector: ", 10))
            text_value(f->vector, sizeof f->vector, line + 10);
        else if (line[0] == '#' || line[strspn(line, " \t\r\n")] == '\0')
            continue;
        else if (!strncmp(line, "row ", 4)) {
            speed_row *r = &f->rows[f->n_rows];
            if (f->n_rows == SPEED_MAX_ROWS)
                bad = "at most 48 rows";
            else if (sscanf(line, "row %39s %15s %lf %lf %lf %lf %lf %lf %lf %lf %c", name, form, &r->ns[0], &r->ns[1],
                            &r->ns[2], &r->ns[3], &r->ns[4], &r->x[0], &r->x[1], &r->x[2], &tail) != 10 ||
                     !all_finite(r->ns, 5) || !all_finite(r->x, 3) ||
                     !(r->ns[0] > 0.0 && r->ns[0] <= r->ns[2] && r->ns[2] <= r->ns[4] && r->x[0] > 0.0))
                bad = "expected row NAME FORM then 8 finite numbers: ns min q1 median q3 max (0 < min <= median <= max), "
                      "ratio median q1 q3 (> 0)";
            else {
                strcpy(r->name, name);
                strcpy(r->form, form);
                f->n_rows++;
            }
        } else if (!strncmp(line, "target ", 7)) {
            speed_ratio *t = &f->targets[f->n_targets];
            if (f->n_targets == SPEED_MAX_ROWS)
                bad = "at most 48 targets";
            else if (sscanf(line, "target %39s %lf %lf %lf", name, &t->med, &t->q1, &t->q3) != 4 || !isfinite(t->med) ||
                     !isfinite(t->q1) || !isfinite(t->q3) || !(t->med > 0.0))
                bad = "expected target ID then its ratio, finite: median q1 q3 (median > 0)";
            else {
                strcpy(t->id, name);
                f->n_targets++;
            }
        } else
            bad = "expected '# ...', 'row ...' or 'target ...'";
        if (bad) {
            snprintf(where, (size_t)wherelen, "%s:%d", path, ln);
            *what = bad;
            return -1;
        }
    }
    if (ferror(in))
        return 1;
    if (!has_opt) {
        snprintf(where, (size_t)wherelen, "%s", path);
        *what = "expected an '# opt: FLAGS' line (the output of `make bench`)";
        return -1;
    }
    return 0;
}

const speed_ratio *speed_file_target(const speed_file *f, const char *id)
{
    int i;
    for (i = 0; i < f->n_targets; i++)
        if (!strcmp(f->targets[i].id, id))
            return &f->targets[i];
    return NULL;
}

const speed_row *speed_file_row(const speed_file *f, const char *name)
{
    int i;
    for (i = 0; i < f->n_rows; i++)
        if (!strcmp(f->rows[i].name, name))
            return &f->rows[i];
    return NULL;
}
