/* `make bench`: the library's host speed against other renderers' exact
 * conductor Fresnel and against floor loops, in one process, in the file
 * format gen/bench/speed_targets.h describes (`make report` reads it).
 *
 * The Makefile builds this program, the runtime's sources and the peers
 * with the flag set of the run (OPT) plus the runtime's math flags, in a
 * directory of their own per compiler and flag set, so that every row is
 * compiled as the run says. Every row is timed in every round, rounds in
 * rotating order, so that a change in machine load falls on all rows alike;
 * ratios are taken within a round, then the median and quartiles over the
 * rounds. Outputs go to arrays; the checksum is taken outside the timed
 * region.
 *
 *   speed [--rounds R]     R interleaved rounds (default 41, 1..1001) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench/speed_targets.h"
#include "kernels.h"

#ifndef SPEED_OPT
#define SPEED_OPT "unknown"
#endif
#ifndef SPEED_CFLAGS
#define SPEED_CFLAGS "unknown"
#endif

#define N 2048                /* cosines per kernel call: inputs and outputs stay in L1 */
#define SAMPLE_NS 100000.0    /* every row's sample lasts about this long */
#define MAX_ROUNDS 1001

static float cos_f[N], out_f[N];
static fresnel_rgb out_rgb[N];
static int32_t cos_q[N], out_q[N];
static volatile uint32_t sink;

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e9 + t.tv_nsec;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* min, q1, median, q3, max of v[0..n) (sorted in place). */
static void quartiles(double *v, int n, double *q)
{
    qsort(v, (size_t)n, sizeof *v, by_value);
    q[0] = v[0];
    q[1] = v[n / 4];
    q[2] = v[n / 2];
    q[3] = v[(3 * n) / 4];
    q[4] = v[n - 1];
}

/* One sample: reps calls of kernel k over the whole array, ns per cosine. */
static double sample(const speed_ctx *x, int k, int reps)
{
    const speed_kernel_def *d = &speed_kernels[k];
    double t0 = now_ns(), t;
    int r;
    for (r = 0; r < reps; r++)
        d->fn(x, cos_f, cos_q, out_f, out_q, out_rgb, N);
    t = (now_ns() - t0) / ((double)reps * N);
    return t;
}

/* The outputs of the last call: in range, folded into the sink. */
static int check_outputs(int k)
{
    uint32_t sum = 0;
    int i;
    for (i = 0; i < N; i++) {
        if (speed_kernels[k].rgb) {
            const float v[3] = {out_rgb[i].r, out_rgb[i].g, out_rgb[i].b};
            int j;
            for (j = 0; j < 3; j++) {
                uint32_t bits;
                if (!(v[j] >= 0.0f && v[j] <= 1.0f))
                    return -1;
                memcpy(&bits, &v[j], sizeof bits);
                sum += bits;
            }
        } else if (speed_kernels[k].q15) {
            if (out_q[i] < 0 || out_q[i] > 32768)
                return -1;
            sum += (uint32_t)out_q[i];
        } else {
            uint32_t bits;
            if (!(out_f[i] >= 0.0f && out_f[i] <= 1.0f))
                return -1;
            memcpy(&bits, &out_f[i], sizeof bits);
            sum += bits;
        }
    }
    sink ^= sum;
    return 0;
}

static void cpu_model(char *dst, size_t size)
{
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[256];
    snprintf(dst, size, "unknown (no /proc/cpuinfo)");
    if (!f)
        return;
    while (fgets(line, sizeof line, f))
        if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
            const char *v = strchr(line, ':') + 1;
            while (*v == ' ')
                v++;
            snprintf(dst, size, "%.*s", (int)strcspn(v, "\n"), v);
            break;
        }
    fclose(f);
}

static const char *vector_isa(void)
{
#if defined(__AVX512F__)
    return "AVX-512F (512-bit)";
#elif defined(__AVX2__) && defined(__FMA__)
    return "AVX2 + FMA (256-bit)";
#elif defined(__AVX2__)
    return "AVX2 (256-bit)";
#elif defined(__AVX__)
    return "AVX (256-bit)";
#elif defined(__SSE2__)
    return "SSE2 (128-bit)";
#elif defined(__ARM_NEON)
    return "NEON (128-bit)";
#else
    return "none known";
#endif
}

static int kernel_index(const char *name)
{
    int k;
    for (k = 0; k < speed_kernel_count; k++)
        if (!strcmp(speed_kernels[k].name, name))
            return k;
    return -1;
}

int main(int argc, char **argv)
{
    static double t[64][MAX_ROUNDS], v[MAX_ROUNDS];
    int kreps[64];
    speed_ctx x;
    unsigned s = 2463534242u;
    int rounds = 41, reps, i, k, r, base, flagset = speed_flagset(SPEED_OPT);
    double t1 = 1e30;
    char cpu[128];
    for (i = 1; i < argc; i++) {
        char *end;
        long n;
        if (!strcmp(argv[i], "--rounds") && i + 1 < argc && (n = strtol(argv[i + 1], &end, 10), *end == '\0') &&
            n >= 1 && n <= MAX_ROUNDS) {
            rounds = (int)n;
            i++;
        } else {
            fprintf(stderr, "speed: usage: speed [--rounds R]   (R in 1..%d)\n", MAX_ROUNDS);
            return 2;
        }
    }
    if (speed_kernel_count > 64)
        return 1;
    for (i = 0; i < N; i++) { /* fixed pseudo-random cosines in [0, 1] (xorshift32) */
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        cos_f[i] = (float)(s >> 8) / 16777216.0f;
        cos_q[i] = (int32_t)(cos_f[i] * 32768.0f + 0.5f);
    }
    speed_ctx_init(&x, 0.24f, 3.63f); /* copper at 650 nm */
    base = kernel_index("schlick-f32");
    for (k = 0; k < speed_kernel_count; k++) { /* warm up, and check every kernel's outputs once */
        sample(&x, k, 2);
        if (check_outputs(k)) {
            fprintf(stderr, "speed: row %s wrote a result outside [0, 1]\n", speed_kernels[k].name);
            return 1;
        }
    }
    /* Each row's calls per sample make its sample last about SAMPLE_NS, so
     * that a loaded machine's preemptions fall alike on cheap and dear rows. */
    for (k = 0; k < speed_kernel_count; k++) {
        for (i = 0, t1 = 1e30; i < 5; i++) {
            double d = sample(&x, k, 1) * N;
            t1 = d < t1 ? d : t1;
        }
        reps = (int)(SAMPLE_NS / (t1 > 1.0 ? t1 : 1.0));
        kreps[k] = reps < 1 ? 1 : reps;
    }
    for (r = 0; r < rounds; r++)
        for (i = 0; i < speed_kernel_count; i++) {
            k = (i + r) % speed_kernel_count;
            t[k][r] = sample(&x, k, kreps[k]);
            check_outputs(k);
        }
    cpu_model(cpu, sizeof cpu);
    printf("# fresnel speed (make bench): one channel of copper at 650 nm (eta 0.24, kappa 3.63)\n"
           "# opt: %s\n# cflags: %s\n# compiler: %s%s\n# cpu: %s\n# vector: %s (the widest vector extension this "
           "build lets the compiler use)\n",
           SPEED_OPT, SPEED_CFLAGS,
#if defined(__clang__)
           "", __VERSION__,
#elif defined(__GNUC__)
           "gcc ", __VERSION__,
#else
           "", "unknown",
#endif
           cpu, vector_isa());
    /* The runtime's own batch SIMD width joins the header here when
     * fresnel.h exposes it as a macro. */
    printf("# workload: %d cosines in [0, 1] (L1-resident), kernel calls per sample sized to about %.0f us "
           "(schlick-f32: %d calls), %d interleaved rounds in rotating order\n"
           "# peers: mitsuba-* and pbrt-* are this project's binary32 transcriptions (gen/bench/peers.h) of "
           "Mitsuba 3's fresnel_conductor (include/mitsuba/render/fresnel.h) and pbrt-v4's FrComplex "
           "(src/pbrt/util/scattering.h), no code of theirs\n"
           "# film peers: the same 1.5 film on gold as film-f32, this project's binary32 transcriptions "
           "(gen/bench/peers.h): khr-iridescence-inline, KHR_materials_iridescence as the glTF Sample Viewer "
           "evaluates it (given gold's F0); polarised-film-inline, the same family with the exact polarised Fresnel "
           "equations (Belcour and Barla's form, given gold's Gaussian-window eta, kappa)\n"
           "# rows *-rgb: three channels of one material per cosine (copper), ns per cosine\n"
           "# forms: call = an out-of-line function per cosine; inline = a header's static function inlined into "
           "the array loop; batch = the library's array function; floor = copy loop, minimal inline Schlick, and "
           "the square roots and divisions of the exact forms alone (sqrt2-div1: the batch's two roots and one "
           "division per cosine; sqrt2-div2: Mitsuba's two and two)\n"
           "#\n# row NAME FORM  ns per evaluation: min q1 median q3 max  time / schlick-f32 in the same round: "
           "median q1 q3\n",
           N, SAMPLE_NS / 1000.0, kreps[base], rounds);
    for (k = 0; k < speed_kernel_count; k++) {
        double q[5], x5[5];
        memcpy(v, t[k], (size_t)rounds * sizeof *v);
        quartiles(v, rounds, q);
        for (r = 0; r < rounds; r++)
            v[r] = t[k][r] / t[base][r];
        quartiles(v, rounds, x5);
        printf("row %-20s %-6s %7.3f %7.3f %7.3f %7.3f %7.3f   %6.3f %6.3f %6.3f\n", speed_kernels[k].name,
               speed_kernels[k].form, q[0], q[1], q[2], q[3], q[4], x5[2], x5[1], x5[3]);
    }
    printf("#\n# target ID  ratio NUM / DEN in the same round: median q1 q3  goal at this flag set  mark\n");
    for (i = 0; i < speed_target_count; i++) {
        const speed_target *g = &speed_targets[i];
        int a = kernel_index(g->num), b = kernel_index(g->den);
        double q[5];
        if (a < 0 || b < 0) {
            printf("# target %s: rows %s, %s not timed in this build\n", g->id, g->num, g->den);
            continue;
        }
        for (r = 0; r < rounds; r++)
            v[r] = t[a][r] / t[b][r];
        quartiles(v, rounds, q);
        printf("target %-32s %6.3f %6.3f %6.3f  ", g->id, q[2], q[1], q[3]);
        if (flagset < 0)
            printf("goal -O2 <= %g, -O3 -march=native <= %g  (this flag set has none)\n", g->goal[0], g->goal[1]);
        else
            printf("goal <= %g  %s\n", g->goal[flagset], q[2] <= g->goal[flagset] ? "pass" : "MISS");
    }
    return 0;
}
