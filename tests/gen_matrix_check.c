/* A header written by `fresnel gen` for a scene with types f32 and q15,
 * read back (tests/header_check.h: every value fits its C type and the
 * runtime's documented range), then every Q1.15 LUT table evaluated through
 * the fixed-point runtime against its binary32 twin through the binary32
 * runtime, at every cosine code below 2048 and every 4th above (RGB).
 * Driven by tests/test_gen_matrix.sh over materials x models x n1 x spacing.
 *
 * The bound, in LSB of Q15, is what the runtime documents plus what turning
 * the double table into codes adds:
 *   linear     FRESNEL_BOUND_LUT_Q15 + 0.5 (nodes rounded to codes)
 *   residual   FRESNEL_BOUND_LUT_Q15 + 0.5 (F0 rounded to a code, weighted
 *              by 1 - (1-c)^5 <= 1) + 2^(14 - frac) (nodes rounded to 2^-frac)
 *   cubic      FRESNEL_BOUND_LUT_CUBIC_Q15 + 0.625 (rounded nodes times the
 *              Catmull-Rom weights' largest absolute sum, 1.25)
 * plus the binary32 runtime's rounding (fresnel.h: 3e-7 linear, 5e-7 cubic,
 * 3e-7 more for the residual's Schlick) times 32768. grazing-pl tables have
 * no binary32 twin (the spacing is Q15-only): they are held to
 * FRESNEL_BOUND_LUT_PL_Q15_FAST_TIR against the same interpolation in double
 * at the runtime's own position.
 *
 * usage: test_gen_matrix HEADER SPACING LABEL   (SPACING grazing, uniform
 * or grazing-pl) */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#include "header_check.h"

static hc_header hh;

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long len;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)len + 1);
    if (buf && fread(buf, 1, (size_t)len, f) != (size_t)len) {
        free(buf);
        buf = NULL;
    }
    if (buf)
        buf[len] = '\0';
    fclose(f);
    return buf;
}

/* The interpolation fresnel_lut_pl_u16_q15_fast documents its bound
 * against: in double, at the runtime's own 15-bit P. */
static double pl_ref(const uint16_t *t, int n, int32_t c)
{
    uint32_t x = (uint32_t)c - ((uint32_t)c >> 15), j = x >> 9;
    uint32_t p = fresnel_lut_pl_knots_q15[j] +
                 (((uint32_t)(fresnel_lut_pl_knots_q15[j + 1] - fresnel_lut_pl_knots_q15[j]) * (x & 511u)) >> 9);
    double pos = p / 32768.0 * (n - 1), w;
    int i = (int)pos;
    if (i > n - 2)
        i = n - 2;
    w = pos - i;
    return (t[i] + (t[i + 1] - (double)t[i]) * w) / 32768.0;
}

/* The form from the table's name: what follows its last "_lutN". */
static int lut_form_of(const char *base)
{
    const char *p = base, *q;
    while ((q = strstr(p, "_lut")) != NULL)
        p = q + 4;
    return strstr(p, "_residual") ? 1 : (strstr(p, "_cubic") ? 2 : 0);
}

typedef struct worst {
    double excess, err, bound;
    char where[200];
    long tables;
} worst;

static void note(worst *w, double err, double bound, const char *table, int32_t c)
{
    if (err - bound > w->excess || !w->where[0]) {
        w->excess = err - bound;
        w->err = err;
        w->bound = bound;
        snprintf(w->where, sizeof w->where, "%.150s c=%ld", table, (long)c);
    }
}

int main(int argc, char **argv)
{
    char *text;
    const char *spacing, *label;
    int i, uniform, pl, fails = 0;
    worst w[4]; /* linear, residual, cubic, pl */
    static const char *const form_name[4] = {"linear", "residual", "cubic", "grazing-pl"};
    if (argc != 4) {
        fprintf(stderr, "usage: test_gen_matrix HEADER SPACING LABEL\n");
        return 2;
    }
    spacing = argv[2];
    label = argv[3];
    uniform = !strcmp(spacing, "uniform");
    pl = !strcmp(spacing, "grazing-pl");
    memset(w, 0, sizeof w);
    w[0].excess = w[1].excess = w[2].excess = w[3].excess = -1e9;
    if (!(text = read_all(argv[1]))) {
        printf("FAIL gen matrix %s: cannot read %s\n", label, argv[1]);
        return 1;
    }
    if (hc_parse(text, &hh))
        printf("FAIL gen matrix %s: header values in their types and ranges: %s\n", label, hh.err), fails++;
    else
        printf("PASS gen matrix %s: %d declarations, every value in its C type and documented range\n", label,
               hh.n);
    for (i = 0; i < hh.n; i++) {
        const hc_decl *q = &hh.d[i], *twin, *f0q = NULL, *f0f = NULL, *frac = NULL;
        char base[HC_NAME], name[HC_NAME + 8];
        size_t len = strlen(q->name);
        int n, form, ch;
        int32_t c;
        static uint16_t u16[3 * 256];
        static int16_t s16[3 * 256];
        static float f32[3 * 256];
        fresnel_rgb_q15 f0_q15 = {0, 0, 0};
        fresnel_rgb f0_f32 = {0.0f, 0.0f, 0.0f};
        if ((strcmp(q->type, "uint16_t") && strcmp(q->type, "int16_t")) || len < 5 ||
            strcmp(q->name + len - 4, "_q15"))
            continue;
        memcpy(base, q->name, len - 4);
        base[len - 4] = '\0';
        form = pl ? 3 : lut_form_of(base);
        n = q->count / 3;
        if (q->count % 3 || n < 2 || n > 256) {
            printf("FAIL gen matrix %s: %s has %d values\n", label, q->name, q->count), fails++;
            continue;
        }
        twin = hc_find(&hh, base);
        if (!pl && (!twin || twin->count != q->count || strcmp(twin->type, "float"))) {
            printf("FAIL gen matrix %s: %s has no binary32 twin %s of %d floats\n", label, q->name, base, q->count);
            fails++;
            continue;
        }
        for (ch = 0; ch < 3 * n; ch++) {
            u16[ch] = (uint16_t)q->v[ch];
            s16[ch] = (int16_t)q->v[ch];
            if (twin)
                f32[ch] = (float)twin->v[ch];
        }
        if (form == 1) {
            snprintf(name, sizeof name, "%s_frac", base);
            frac = hc_find(&hh, name);
            {
                const char *lut = base, *q2;
                while ((q2 = strstr(lut + 1, "_lut")) != NULL)
                    lut = q2;
                snprintf(name, sizeof name, "%.*s_f0_q15", (int)(lut - base), base);
                f0q = hc_find(&hh, name);
                snprintf(name, sizeof name, "%.*s_f0", (int)(lut - base), base);
            }
            f0f = hc_find(&hh, name);
            if (!frac || !f0q || !f0f) {
                printf("FAIL gen matrix %s: %s without its frac, Q15 F0 or binary32 F0\n", label, q->name), fails++;
                continue;
            }
            f0_q15.r = (fresnel_q15)f0q->v[0], f0_q15.g = (fresnel_q15)f0q->v[1], f0_q15.b = (fresnel_q15)f0q->v[2];
            f0_f32.r = (float)f0f->v[0], f0_f32.g = (float)f0f->v[1], f0_f32.b = (float)f0f->v[2];
        }
        w[form].tables++;
        for (c = 0; c <= 32768; c += c < 2048 ? 1 : 4) {
            float cf = (float)c / 32768.0f;
            fresnel_rgb_q15 o;
            fresnel_rgb r;
            double bound, got[3], ref[3];
            if (form == 3) {
                for (ch = 0; ch < 3; ch++) {
                    got[ch] = fresnel_lut_pl_u16_q15_fast(u16 + ch * n, n, c);
                    ref[ch] = pl_ref(u16 + ch * n, n, c);
                }
                bound = FRESNEL_BOUND_LUT_PL_Q15_FAST_TIR;
            } else {
                if (form == 0) {
                    o = uniform ? fresnel_lut_linear_u16_q15_rgb(u16, n, c) : fresnel_lut_u16_q15_rgb(u16, n, c);
                    r = uniform ? fresnel_lut_linear_rgb(f32, n, cf) : fresnel_lut_rgb(f32, n, cf);
                    bound = FRESNEL_BOUND_LUT_Q15 + 0.5 + 32768.0 * 3e-7;
                } else if (form == 1) {
                    int fr = (int)frac->v[0];
                    o = uniform ? fresnel_lut_linear_residual_s16_q15_rgb(f0_q15, s16, n, fr, c)
                                : fresnel_lut_residual_s16_q15_rgb(f0_q15, s16, n, fr, c);
                    r = uniform ? fresnel_lut_linear_residual_rgb(f0_f32, f32, n, cf)
                                : fresnel_lut_residual_rgb(f0_f32, f32, n, cf);
                    bound = FRESNEL_BOUND_LUT_Q15 + 0.5 + ldexp(1.0, 14 - fr) + 32768.0 * 6e-7;
                } else {
                    o = fresnel_lut_cubic_u16_q15_rgb(u16, n, c);
                    r = fresnel_lut_cubic_rgb(f32, n, cf);
                    bound = FRESNEL_BOUND_LUT_CUBIC_Q15 + 0.625 + 32768.0 * 5e-7;
                }
                got[0] = o.r, got[1] = o.g, got[2] = o.b;
                ref[0] = r.r, ref[1] = r.g, ref[2] = r.b;
            }
            for (ch = 0; ch < 3; ch++) {
                double err = fabs(got[ch] - ref[ch] * 32768.0);
                if (got[ch] < 0 || got[ch] > 32768)
                    err = 1e9;
                note(&w[form], err, bound, q->name, c);
            }
        }
    }
    for (i = 0; i < 4; i++) {
        if (!w[i].tables)
            continue;
        if (w[i].excess > 0.0)
            fails++;
        printf("%s gen matrix %s: %ld %s Q15 tables %s, worst %.4f LSB (bound %.4f) at %s\n",
               w[i].excess > 0.0 ? "FAIL" : "PASS", label, w[i].tables, form_name[i],
               i == 3 ? "against double at the runtime's position" : "against their binary32 twins", w[i].err,
               w[i].bound, w[i].where);
    }
    hc_free(&hh);
    free(text);
    return fails != 0;
}
