/* The Q1.15 batches (fresnel_q15.h, BATCHES) against the scalar calls,
 * bit for bit: every cos code 0..65535 (above one: read as one), a spread
 * of materials, the input cut into runs of 1 to 67 cosines so that every
 * tail length and alignment of a vector body is met, and a guard after
 * each run that must stay unwritten. The arrays are malloc'd to their exact
 * size, so the sanitized build catches a read past n. On the host this is
 * the long-multiply body; ports/cross.sh's conformance runs the halves
 * (Cortex-M0), the long multiply (M4F) and Helium (M55) against it. */
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "fresnel_q15.h"

#define CODES 65536
#define GUARD 0xBEEF

typedef void (*batch1)(const void *m, const fresnel_q15 *c, fresnel_q15 *out, int n);
typedef fresnel_q15 (*scalar1)(const void *m, int32_t c);
typedef void (*batch3)(const void *m, const fresnel_q15 *c, fresnel_rgb_q15 *out, int n);
typedef fresnel_rgb_q15 (*scalar3)(const void *m, int32_t c);

typedef struct material {
    int32_t f0, f82, f90;
    fresnel_q16 p;
    fresnel_rgb_q15 f0_rgb, f82_rgb, f90_rgb;
    const uint16_t *table;
    int nodes;
} material;

#define M(m) ((const material *)(m))
static void b_schlick(const void *m, const fresnel_q15 *c, fresnel_q15 *o, int n) { fresnel_schlick_q15_batch(M(m)->f0, c, o, n); }
static fresnel_q15 s_schlick(const void *m, int32_t c) { return fresnel_schlick_q15(M(m)->f0, c); }
static void b_gen(const void *m, const fresnel_q15 *c, fresnel_q15 *o, int n)
{
    fresnel_schlick_gen_q15_batch(M(m)->f0, M(m)->f90, M(m)->p, c, o, n);
}
static fresnel_q15 s_gen(const void *m, int32_t c) { return fresnel_schlick_gen_q15(M(m)->f0, M(m)->f90, M(m)->p, c); }
static void b_f82(const void *m, const fresnel_q15 *c, fresnel_q15 *o, int n) { fresnel_f82_q15_batch(M(m)->f0, M(m)->f82, c, o, n); }
static fresnel_q15 s_f82(const void *m, int32_t c) { return fresnel_f82_q15(M(m)->f0, M(m)->f82, c); }
static void b_lut(const void *m, const fresnel_q15 *c, fresnel_q15 *o, int n) { fresnel_lut_u16_q15_batch(M(m)->table, M(m)->nodes, c, o, n); }
static fresnel_q15 s_lut(const void *m, int32_t c) { return fresnel_lut_u16_q15(M(m)->table, M(m)->nodes, c); }
static void b_linear(const void *m, const fresnel_q15 *c, fresnel_q15 *o, int n)
{
    fresnel_lut_linear_u16_q15_batch(M(m)->table, M(m)->nodes, c, o, n);
}
static fresnel_q15 s_linear(const void *m, int32_t c) { return fresnel_lut_linear_u16_q15(M(m)->table, M(m)->nodes, c); }
static void b_cubic(const void *m, const fresnel_q15 *c, fresnel_q15 *o, int n)
{
    fresnel_lut_cubic_u16_q15_batch(M(m)->table, M(m)->nodes, c, o, n);
}
static fresnel_q15 s_cubic(const void *m, int32_t c) { return fresnel_lut_cubic_u16_q15(M(m)->table, M(m)->nodes, c); }

static void b3_schlick(const void *m, const fresnel_q15 *c, fresnel_rgb_q15 *o, int n) { fresnel_schlick_q15_rgb_batch(M(m)->f0_rgb, c, o, n); }
static fresnel_rgb_q15 s3_schlick(const void *m, int32_t c) { return fresnel_schlick_q15_rgb(M(m)->f0_rgb, c); }
static void b3_gen(const void *m, const fresnel_q15 *c, fresnel_rgb_q15 *o, int n)
{
    fresnel_schlick_gen_q15_rgb_batch(M(m)->f0_rgb, M(m)->f90_rgb, M(m)->p, c, o, n);
}
static fresnel_rgb_q15 s3_gen(const void *m, int32_t c) { return fresnel_schlick_gen_q15_rgb(M(m)->f0_rgb, M(m)->f90_rgb, M(m)->p, c); }
static void b3_f82(const void *m, const fresnel_q15 *c, fresnel_rgb_q15 *o, int n)
{
    fresnel_f82_q15_rgb_batch(M(m)->f0_rgb, M(m)->f82_rgb, c, o, n);
}
static fresnel_rgb_q15 s3_f82(const void *m, int32_t c) { return fresnel_f82_q15_rgb(M(m)->f0_rgb, M(m)->f82_rgb, c); }
static void b3_lut(const void *m, const fresnel_q15 *c, fresnel_rgb_q15 *o, int n)
{
    fresnel_lut_u16_q15_rgb_batch(M(m)->table, M(m)->nodes, c, o, n);
}
static fresnel_rgb_q15 s3_lut(const void *m, int32_t c) { return fresnel_lut_u16_q15_rgb(M(m)->table, M(m)->nodes, c); }
static void b3_linear(const void *m, const fresnel_q15 *c, fresnel_rgb_q15 *o, int n)
{
    fresnel_lut_linear_u16_q15_rgb_batch(M(m)->table, M(m)->nodes, c, o, n);
}
static fresnel_rgb_q15 s3_linear(const void *m, int32_t c) { return fresnel_lut_linear_u16_q15_rgb(M(m)->table, M(m)->nodes, c); }
static void b3_cubic(const void *m, const fresnel_q15 *c, fresnel_rgb_q15 *o, int n)
{
    fresnel_lut_cubic_u16_q15_rgb_batch(M(m)->table, M(m)->nodes, c, o, n);
}
static fresnel_rgb_q15 s3_cubic(const void *m, int32_t c) { return fresnel_lut_cubic_u16_q15_rgb(M(m)->table, M(m)->nodes, c); }

/* Runs of 1..67 cosines over every code; the first mismatch, a write past
 * a run, or 0. */
static long check1(batch1 b, scalar1 s, const void *m, const fresnel_q15 *codes)
{
    int start = 0, len = 1;
    while (start < CODES) {
        int n = start + len <= CODES ? len : CODES - start, i;
        fresnel_q15 *c = malloc((size_t)n * sizeof *c), *out = malloc(((size_t)n + 1) * sizeof *out);
        long bad = 0;
        if (!c || !out) {
            free(c);
            free(out);
            return -1;
        }
        memcpy(c, codes + start, (size_t)n * sizeof *c);
        out[n] = GUARD;
        b(m, c, out, n);
        for (i = 0; i < n && !bad; i++)
            if (out[i] != s(m, c[i]))
                bad = 1 + start + i;
        if (!bad && out[n] != GUARD)
            bad = 1 + start + n;
        free(c);
        free(out);
        if (bad)
            return bad;
        start += n;
        len = len % 67 + 1;
    }
    return 0;
}

static long check3(batch3 b, scalar3 s, const void *m, const fresnel_q15 *codes)
{
    int start = 0, len = 1;
    while (start < CODES) {
        int n = start + len <= CODES ? len : CODES - start, i;
        fresnel_q15 *c = malloc((size_t)n * sizeof *c);
        fresnel_rgb_q15 *out = malloc(((size_t)n + 1) * sizeof *out);
        long bad = 0;
        if (!c || !out) {
            free(c);
            free(out);
            return -1;
        }
        memcpy(c, codes + start, (size_t)n * sizeof *c);
        out[n].r = out[n].g = out[n].b = GUARD;
        b(m, c, out, n);
        for (i = 0; i < n && !bad; i++) {
            fresnel_rgb_q15 want = s(m, c[i]);
            if (out[i].r != want.r || out[i].g != want.g || out[i].b != want.b)
                bad = 1 + start + i;
        }
        if (!bad && (out[n].r != GUARD || out[n].g != GUARD || out[n].b != GUARD))
            bad = 1 + start + n;
        free(c);
        free(out);
        if (bad)
            return bad;
        start += n;
        len = len % 67 + 1;
    }
    return 0;
}

int main(void)
{
    static const struct {
        const char *name;
        batch1 b;
        scalar1 s;
        batch3 b3;
        scalar3 s3;
    } rows[] = {
        {"schlick", b_schlick, s_schlick, b3_schlick, s3_schlick},
        {"schlick-gen", b_gen, s_gen, b3_gen, s3_gen},
        {"f82", b_f82, s_f82, b3_f82, s3_f82},
        {"lut u16", b_lut, s_lut, b3_lut, s3_lut},
        {"lut-linear u16", b_linear, s_linear, b3_linear, s3_linear},
        {"lut-cubic u16", b_cubic, s_cubic, b3_cubic, s3_cubic},
    };
    /* F0, F82 and F90 codes from 0 to past one; p = 5 (the Schlick path),
     * 0.5, 3.7 and the clamps' ends */
    static const int32_t f0s[] = {0, 1, 1310, 9000, 23000, 32767, 32768, 40000};
    static const int32_t f82s[] = {0, 32768, 20000, 31000, 5, 32768, 12345, 32768};
    static const fresnel_q16 ps[] = {5 << 16, 32768, 242483, 5 << 16, 1, 5 << 16, 64 << 16, 5 << 16};
    /* node counts: the clamps (0, 1, 2), and 20000, where the sqrt LUT
     * batch takes the exact root for every cosine (k - 1 >= 2^14) */
    static const int nodes[] = {16, 64, 2, 1, 0, 17, 1024, 20000};
    fresnel_q15 *codes = malloc(CODES * sizeof *codes);
    uint16_t *table = malloc(3 * 20000 * sizeof *table);
    int r, k, i;
    if (!codes || !table) {
        CHECK("batch: memory", 0, "malloc failed");
        return harness_exit();
    }
    for (i = 0; i < CODES; i++)
        codes[i] = (fresnel_q15)i;
    /* a reflectance-like curve per channel, some nodes above one (headroom) */
    for (i = 0; i < 3 * 20000; i++)
        table[i] = (uint16_t)((i * 2654435761u >> 7) % 36000u);
    for (r = 0; r < (int)(sizeof rows / sizeof rows[0]); r++) {
        long bad1 = 0, bad3 = 0;
        int where = -1;
        for (k = 0; k < 8 && !bad1 && !bad3; k++) {
            material m;
            m.f0 = f0s[k];
            m.f82 = f82s[k];
            m.f90 = f82s[(k + 3) % 8];
            m.p = ps[k];
            m.f0_rgb.r = (fresnel_q15)(f0s[k] > 32768 ? 32768 : f0s[k]);
            m.f0_rgb.g = (fresnel_q15)f0s[(k + 1) % 8];
            m.f0_rgb.b = (fresnel_q15)f0s[(k + 5) % 8];
            m.f82_rgb.r = (fresnel_q15)f82s[k];
            m.f82_rgb.g = (fresnel_q15)f82s[(k + 2) % 8];
            m.f82_rgb.b = (fresnel_q15)f82s[(k + 4) % 8];
            m.f90_rgb = m.f82_rgb;
            m.table = table;
            m.nodes = nodes[k];
            bad1 = check1(rows[r].b, rows[r].s, &m, codes);
            bad3 = check3(rows[r].b3, rows[r].s3, &m, codes);
            where = k;
        }
        {
            char name[128];
            snprintf(name, sizeof name, "%s batch and rgb batch: bit-identical to the scalar calls, every code 0-65535, "
                                        "8 materials, runs of 1-67", rows[r].name);
            CHECK(name, bad1 == 0 && bad3 == 0, "material %d: batch %s at code %ld, rgb batch %s at code %ld", where,
                  bad1 < 0 ? "out of memory" : "differs", bad1 - 1, bad3 < 0 ? "out of memory" : "differs", bad3 - 1);
        }
    }
    /* n <= 0 writes nothing */
    {
        fresnel_q15 out[2] = {GUARD, GUARD};
        fresnel_rgb_q15 out3[1];
        out3[0].r = out3[0].g = out3[0].b = GUARD;
        fresnel_schlick_q15_batch(100, codes, out, 0);
        fresnel_f82_q15_batch(100, 200, codes, out, -3);
        fresnel_lut_u16_q15_batch(table, 16, codes, out, -1);
        fresnel_schlick_q15_rgb_batch(out3[0], codes, out3, 0);
        CHECK("batches: n <= 0 writes nothing", out[0] == GUARD && out[1] == GUARD && out3[0].r == GUARD, "%u %u",
              out[0], out[1]);
    }
    free(codes);
    free(table);
    return harness_exit();
}
