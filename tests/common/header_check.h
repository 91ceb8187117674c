/* Compile-free checks of a header written by `fresnel gen` (C, not GLSL):
 * every `static const TYPE NAME[...] ... = {...};` and `enum { NAME = V };`
 * is read back, and each value is checked against its C type and the range
 * include/fresnel_fixed.h and fresnel.h document for it:
 *   float, fresnel_rgb    binary32 literals with an 'f' suffix, finite
 *   fresnel_f16           the same, each a binary16 value (11 significant
 *                         bits, or a multiple of 2^-24 below 2^-14; |v| <= 65504)
 *   fresnel_rgb_q15       3 codes in [0, FRESNEL_ONE_Q15]
 *   uint16_t              LUT codes in [0, FRESNEL_ONE_Q15]
 *   int16_t               residual LUT nodes in [-32768, 32767]
 *   int32_t               F82's a_q12, |a| <= 73000 (fresnel_f82_q15_fast)
 *   fresnel_ior_prep_q15       a0, a0_lo, shift, then qf b, n4, t1_inv, inv_eta2:
 *                         shift in [0, 30], a0 + 2^(30 - shift) in int32,
 *                         |a0_lo| <= 2^29, each qf {0, 0} or m in [2^30, 2^31)
 *   fresnel_nk_prep_q15        qf n, nk2
 *   fresnel_lsk_prep_q15       f0 in [0, 2^30], qf a, alpha in [0, FRESNEL_ALPHA_MAX_Q16]
 *   fresnel_conductor_prep_q15_fast
 *                         a0, a0_lo, shift, b1, b2, bm, be, span
 *                         (fresnel_fixed_fast.h): shift in [0, 30], a0 +
 *                         2^(30 - shift) in int32, |a0_lo| <= 2^15, b1, b2
 *                         in [0, 2^31), bm 0 (be 255) or in [2^15, 2^16),
 *                         span 0 or 65535 (65535 only with shift 0)
 *   fresnel_film          the thin-film table (fresnel_film.h), its floats in
 *                         struct order, finite
 *   fresnel_film_q15      the same in Q1.15: turn_* in uint32_t, octave_* in
 *                         [0, 2^27), weights int16_t; per node a0 int16_t,
 *                         opd and decay uint16_t, A, B, P, Q int16_t
 *   fresnel_film_f16      the same in binary16, each a binary16 value
 *   enum NAME_frac        a residual table's fraction bits, [14, 30]
 * and each initialiser has exactly as many values as its type and length
 * need. Any other declared type is an error, so a new emitted type must be
 * added here. Used by tests/gen/gen_matrix_check.c and the fuzz target
 * tests/fuzz/fuzz_gen_header.c. Host only. */
#ifndef FRESNEL_HEADER_CHECK_H
#define FRESNEL_HEADER_CHECK_H

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel_film.h"

#define HC_MAX_DECLS 8192
/* fresnel_film (fresnel_film.h): freq, damp, weight[3][J][2], then per node
 * a0[3], opd, decay and eight arrays of J; the Q1.15 layout has four pole
 * arrays where the float ones have two. */
#define HC_FILM_NODE (5 + 8 * FRESNEL_FILM_POLES)
#define HC_FILM_FLOATS (2 * FRESNEL_FILM_POLES + 6 * FRESNEL_FILM_POLES + FRESNEL_FILM_NODES * HC_FILM_NODE)
#define HC_NAME 160

typedef struct hc_decl {
    char type[32], name[HC_NAME];
    int count;     /* values */
    double *v;     /* malloc'd; integers exactly, floats as read */
} hc_decl;

typedef struct hc_header {
    int n;
    hc_decl d[HC_MAX_DECLS];
    char err[512]; /* the first problem, "" if none */
} hc_header;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static inline void hc_fail(hc_header *h, const char *fmt, ...)
{
    va_list ap;
    if (h->err[0])
        return;
    va_start(ap, fmt);
    vsnprintf(h->err, sizeof h->err, fmt, ap);
    va_end(ap);
}

/* Fields per element of a type, or 0 if the type is unknown. */
static inline int hc_fields(const char *type, int *is_float)
{
    static const struct {
        const char *type;
        int fields, is_float;
    } t[] = {{"float", 1, 1},   {"fresnel_rgb", 3, 1},      {"fresnel_rgb_q15", 3, 0},
             {"uint16_t", 1, 0}, {"int16_t", 1, 0},          {"int32_t", 1, 0},
             {"fresnel_ior_prep_q15", 11, 0}, {"fresnel_nk_prep_q15", 4, 0}, {"fresnel_lsk_prep_q15", 4, 0},
             {"fresnel_conductor_prep_q15_fast", 8, 0}, {"fresnel_f16", 1, 1},
             {"fresnel_film", HC_FILM_FLOATS, 1}, {"fresnel_film_q15", HC_FILM_FLOATS + 12, 0},
             {"fresnel_film_f16", HC_FILM_FLOATS, 1}};
    size_t i;
    for (i = 0; i < sizeof t / sizeof t[0]; i++)
        if (!strcmp(t[i].type, type)) {
            *is_float = t[i].is_float;
            return t[i].fields;
        }
    return 0;
}

static inline int hc_in(double v, double lo, double hi) { return v >= lo && v <= hi && v == floor(v); }

static inline void hc_qf(hc_header *h, const hc_decl *d, const double *q)
{
    if (q[0] == 0.0 ? q[1] != 0.0 : !hc_in(q[0], 1073741824.0, 2147483647.0))
        hc_fail(h, "%s %s: qf mantissa %.17g not 0 or in [2^30, 2^31)", d->type, d->name, q[0]);
    if (!hc_in(q[1], -2147483648.0, 2147483647.0))
        hc_fail(h, "%s %s: qf exponent %.17g not an int32_t", d->type, d->name, q[1]);
}

/* Check one element of d (its fields at v). */
static inline void hc_element(hc_header *h, const hc_decl *d, const double *v)
{
    const char *t = d->type;
    int i;
    if (!strcmp(t, "fresnel_f16") || !strcmp(t, "fresnel_film_f16")) { /* the literals are a float's */
        int n = strcmp(t, "fresnel_f16") ? HC_FILM_FLOATS : 1;
        for (i = 0; i < n; i++) {
            int e;
            double x = (double)(float)v[i], m = frexp(x, &e);
            if (!(fabs(x) <= 65504.0) ||
                (fabs(x) >= 0x1p-14 ? ldexp(m, 11) != floor(ldexp(m, 11)) : ldexp(x, 24) != floor(ldexp(x, 24)))) {
                hc_fail(h, "%s %s: value %d, %.17g, is not a binary16 value", t, d->name, i, v[i]);
                break;
            }
        }
    } else if (!strcmp(t, "fresnel_film_q15")) {
        const int poles = 4 * FRESNEL_FILM_POLES, weights = poles + 6 * FRESNEL_FILM_POLES;
        for (i = 0; i < HC_FILM_FLOATS + 12; i++) {
            int at = (i - weights) % HC_FILM_NODE;
            double lo = -32768.0, hi = 32767.0;
            if (i < poles)
                lo = 0.0, hi = i < 2 * FRESNEL_FILM_POLES ? 4294967295.0 : 134217727.0;
            else if (i >= weights && (at == 3 || at == 4))
                lo = 0.0, hi = 65535.0;
            if (!hc_in(v[i], lo, hi)) {
                hc_fail(h, "%s %s: value %d, %.17g, not in [%.0f, %.0f]", t, d->name, i, v[i], lo, hi);
                break;
            }
        }
    } else if (!strcmp(t, "fresnel_rgb_q15")) {
        for (i = 0; i < 3; i++)
            if (!hc_in(v[i], 0.0, 32768.0))
                hc_fail(h, "%s %s: code %.17g not in [0, 32768]", t, d->name, v[i]);
    } else if (!strcmp(t, "uint16_t")) {
        if (!hc_in(v[0], 0.0, 32768.0))
            hc_fail(h, "%s %s: LUT code %.17g not in [0, 32768]", t, d->name, v[0]);
    } else if (!strcmp(t, "int16_t")) {
        if (!hc_in(v[0], -32768.0, 32767.0))
            hc_fail(h, "%s %s: %.17g does not fit int16_t", t, d->name, v[0]);
    } else if (!strcmp(t, "int32_t")) {
        if (!hc_in(v[0], -73000.0, 73000.0))
            hc_fail(h, "%s %s: a_q12 %.17g not in [-73000, 73000]", t, d->name, v[0]);
    } else if (!strcmp(t, "fresnel_ior_prep_q15")) {
        if (!hc_in(v[2], 0.0, 30.0))
            hc_fail(h, "%s %s: shift %.17g not in [0, 30]", t, d->name, v[2]);
        else if (!hc_in(v[0] + ldexp(1.0, 30 - (int)v[2]), -2147483648.0, 2147483647.0) ||
                 !hc_in(v[0], -2147483648.0, 2147483647.0))
            hc_fail(h, "%s %s: a0 %.17g + 2^(30 - shift) not an int32_t", t, d->name, v[0]);
        if (!hc_in(v[1], -536870912.0, 536870912.0))
            hc_fail(h, "%s %s: a0_lo %.17g not in [-2^29, 2^29]", t, d->name, v[1]);
        for (i = 3; i < 11; i += 2)
            hc_qf(h, d, v + i);
    } else if (!strcmp(t, "fresnel_conductor_prep_q15_fast")) {
        if (!hc_in(v[2], 0.0, 30.0))
            hc_fail(h, "%s %s: shift %.17g not in [0, 30]", t, d->name, v[2]);
        else if (!hc_in(v[0] + ldexp(1.0, 30 - (int)v[2]), -2147483648.0, 2147483647.0) ||
                 !hc_in(v[0], -2147483648.0, 2147483647.0))
            hc_fail(h, "%s %s: a0 %.17g + 2^(30 - shift) not an int32_t", t, d->name, v[0]);
        if (!hc_in(v[1], -32768.0, 32768.0))
            hc_fail(h, "%s %s: a0_lo %.17g not in [-2^15, 2^15]", t, d->name, v[1]);
        if (!hc_in(v[3], 0.0, 2147483647.0) || !hc_in(v[4], 0.0, 2147483647.0))
            hc_fail(h, "%s %s: b1 %.17g or b2 %.17g not in [0, 2^31)", t, d->name, v[3], v[4]);
        if (v[5] == 0.0 ? v[6] != 255.0 : !hc_in(v[5], 32768.0, 65535.0) || !hc_in(v[6], -64.0, 254.0))
            hc_fail(h, "%s %s: bm %.17g, be %.17g: expected 0, 255 or bm in [2^15, 2^16)", t, d->name, v[5], v[6]);
        if (v[7] != 0.0 && (v[7] != 65535.0 || v[2] != 0.0))
            hc_fail(h, "%s %s: span %.17g not 0, or 65535 with shift 0", t, d->name, v[7]);
    } else if (!strcmp(t, "fresnel_nk_prep_q15")) {
        hc_qf(h, d, v);
        hc_qf(h, d, v + 2);
    } else if (!strcmp(t, "fresnel_lsk_prep_q15")) {
        if (!hc_in(v[0], 0.0, 1073741824.0))
            hc_fail(h, "%s %s: f0 %.17g not in [0, 2^30]", t, d->name, v[0]);
        hc_qf(h, d, v + 1);
        if (!hc_in(v[3], 0.0, 1000.0 * 65536.0))
            hc_fail(h, "%s %s: alpha %.17g not in [0, 1000 2^16]", t, d->name, v[3]);
    }
}

/* One number token at *p: a float literal (must end in 'f', be finite and
 * within binary32) or an integer (decimal, optional '-'). */
static inline int hc_number(hc_header *h, const char **p, int is_float, const char *what, double *out)
{
    const char *s = *p;
    char *end;
    if (is_float) {
        double v = strtod(s, &end);
        if (end == s || *end != 'f' || !(fabs(v) <= FLT_MAX) || !strpbrk(s, ".e") || strpbrk(s, ".e") > end) {
            hc_fail(h, "%s: bad float literal near '%.20s'", what, s);
            return -1;
        }
        *p = end + 1;
        *out = v;
    } else {
        long long v = strtoll(s, &end, 10);
        if (end == s || isalpha((unsigned char)*end) || *end == '.') {
            hc_fail(h, "%s: bad integer literal near '%.20s'", what, s);
            return -1;
        }
        *p = end;
        *out = (double)v;
    }
    return 0;
}

static inline void hc_free(hc_header *h)
{
    int i;
    for (i = 0; i < h->n; i++)
        free(h->d[i].v);
    h->n = 0;
}

/* Parse and check text (NUL-terminated). 0 if every check holds, else -1
 * with h->err set. */
static inline int hc_parse(const char *text, hc_header *h)
{
    const char *p = text;
    h->n = 0;
    h->err[0] = '\0';
    while ((p = strstr(p, "\nstatic const ")) != NULL) {
        hc_decl *d;
        const char *q = p + 14, *eq, *semi;
        int len = -1, fields, is_float, i, elems;
        if (h->n == HC_MAX_DECLS) {
            hc_fail(h, "more than %d declarations", HC_MAX_DECLS);
            break;
        }
        d = &h->d[h->n];
        d->v = NULL;
        if (sscanf(q, "%31s %159[A-Za-z0-9_]", d->type, d->name) != 2) {
            hc_fail(h, "unreadable declaration near '%.40s'", q);
            break;
        }
        q = strstr(q, d->name) + strlen(d->name);
        if (*q == '[')
            len = atoi(q + 1);
        eq = strchr(q, '=');
        semi = eq ? strchr(eq, ';') : NULL;
        if (!eq || !semi) {
            hc_fail(h, "%s %s: no initialiser", d->type, d->name);
            break;
        }
        fields = hc_fields(d->type, &is_float);
        if (!fields) {
            hc_fail(h, "%s %s: type unknown to the checker", d->type, d->name);
            break;
        }
        elems = len < 0 ? 1 : len;
        d->count = 0;
        d->v = (double *)malloc(sizeof(double) * (size_t)(elems * fields + 1));
        h->n++;
        for (q = eq + 1; q < semi;) {
            if (isdigit((unsigned char)*q) || *q == '-' || *q == '.' || isalpha((unsigned char)*q)) {
                double v;
                if (d->count == elems * fields) {
                    hc_fail(h, "%s %s: more values than the type holds", d->type, d->name);
                    break;
                }
                if (hc_number(h, &q, is_float, d->name, &v))
                    break;
                d->v[d->count++] = v;
            } else {
                q++;
            }
        }
        if (d->count != elems * fields)
            hc_fail(h, "%s %s: %d values, expected %d", d->type, d->name, d->count, elems * fields);
        else
            for (i = 0; i < elems; i++)
                hc_element(h, d, d->v + i * fields);
        p = semi;
    }
    /* enum { NAME_frac = V }; */
    for (p = text; (p = strstr(p, "\nenum { ")) != NULL; p++) {
        char name[HC_NAME];
        long v;
        if (sscanf(p + 8, "%159[A-Za-z0-9_] = %ld };", name, &v) != 2 || h->n == HC_MAX_DECLS) {
            hc_fail(h, "unreadable enum near '%.40s'", p + 1);
            break;
        }
        if (strlen(name) < 5 || strcmp(name + strlen(name) - 5, "_frac") != 0 || v < 14 || v > 30)
            hc_fail(h, "enum %s: %ld is not a residual fraction in [14, 30]", name, v);
        h->d[h->n].v = (double *)malloc(sizeof(double));
        h->d[h->n].v[0] = (double)v;
        h->d[h->n].count = 1;
        strcpy(h->d[h->n].type, "enum");
        strcpy(h->d[h->n].name, name);
        h->n++;
    }
    return h->err[0] ? -1 : 0;
}

static inline const hc_decl *hc_find(const hc_header *h, const char *name)
{
    int i;
    for (i = 0; i < h->n; i++)
        if (!strcmp(h->d[i].name, name))
            return &h->d[i];
    return NULL;
}

#endif
