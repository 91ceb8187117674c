/* The fixed-point functions as one table of evaluators on prepared
 * material data, for the cross-target programs (conform.c, bench.c). */
#ifndef FRESNEL_CROSS_FIXED_MODELS_H
#define FRESNEL_CROSS_FIXED_MODELS_H

#include "conform.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"

typedef fresnel_q15 (*fixed_eval)(const conform_material *m, int32_t c);

static fresnel_q15 e_schlick(const conform_material *m, int32_t c) { return fresnel_schlick_q15(m->f0, c); }
static fresnel_q15 e_schlick_gen(const conform_material *m, int32_t c)
{
    return fresnel_schlick_gen_q15(m->f0, m->f90, m->p, c);
}
static fresnel_q15 e_schlick_gen_half(const conform_material *m, int32_t c)
{
    return fresnel_schlick_gen_q15(m->f0, m->f82, 32768, c); /* p = 0.5, F90 = F82 */
}
static fresnel_q15 e_schlick_gen_37(const conform_material *m, int32_t c)
{
    return fresnel_schlick_gen_q15(m->f0, 16384, 242483, c); /* p = 3.7, F90 = 0.5 */
}
static fresnel_q15 e_lsk(const conform_material *m, int32_t c) { return fresnel_lsk_q15(&m->lsk, c); }
static fresnel_q15 e_lsk_comp(const conform_material *m, int32_t c) { return fresnel_lsk_comp_q15(&m->lsk, c); }
static fresnel_q15 e_f82(const conform_material *m, int32_t c) { return fresnel_f82_q15(m->f0, m->f82, c); }
static fresnel_q15 e_gulbrandsen(const conform_material *m, int32_t c) { return fresnel_gulbrandsen_q15(m->r, m->g, c); }
static fresnel_q15 e_cook_torrance(const conform_material *m, int32_t c)
{
    return fresnel_cook_torrance_q15(m->f0, &m->ior, c);
}
static fresnel_q15 e_conductor(const conform_material *m, int32_t c) { return fresnel_conductor_q15(&m->ior, c); }
static fresnel_q15 e_dielectric(const conform_material *m, int32_t c) { return fresnel_dielectric_q15(&m->dior, c); }
static fresnel_q15 e_approx(const conform_material *m, int32_t c) { return fresnel_approx_conductor_q15(&m->nk, c); }
static fresnel_q15 e_internal(const conform_material *m, int32_t c)
{
    return fresnel_schlick_internal_q15(m->f0, &m->dior, c);
}
static fresnel_q15 e_f0_in_medium(const conform_material *m, int32_t c)
{
    return fresnel_f0_in_medium_q15(c, m->eta); /* every F0 code, the material's eta as the medium */
}
static fresnel_q15 e_lut_u16(const conform_material *m, int32_t c)
{
    (void)m;
    return fresnel_lut_u16_q15(conform_lut_u16[0], CONFORM_LUT_N, c);
}
static fresnel_q15 e_lut_linear_u16(const conform_material *m, int32_t c)
{
    (void)m;
    return fresnel_lut_linear_u16_q15(conform_lut_u16[1], CONFORM_LUT_N, c);
}
static fresnel_q15 e_lut_u8(const conform_material *m, int32_t c)
{
    (void)m;
    return fresnel_lut_u8_q15(conform_lut_u8[0], CONFORM_LUT_N, c);
}
static fresnel_q15 e_lut_residual_s16(const conform_material *m, int32_t c)
{
    (void)m;
    return fresnel_lut_residual_s16_q15(conform_lut_f0, conform_lut_s16[0], CONFORM_LUT_N, conform_lut_frac16, c);
}
static fresnel_q15 e_lut_linear_residual_s8(const conform_material *m, int32_t c)
{
    (void)m;
    return fresnel_lut_linear_residual_s8_q15(conform_lut_f0, conform_lut_s8[1], CONFORM_LUT_N, conform_lut_frac8, c);
}
static fresnel_q15 e_lut_cubic_u16(const conform_material *m, int32_t c)
{
    (void)m;
    return fresnel_lut_cubic_u16_q15(conform_lut_u16[0], CONFORM_LUT_N, c);
}
/* The averages take no cosine: the code's low two bits pick the form and
 * the next six the number of nodes read (2 to 64; masks, as the M0 has no
 * division). */
static fresnel_q15 e_lut_avg_u16(const conform_material *m, int32_t c)
{
    int form = (int)(c & 3), n = 2 + (int)((c >> 2) & 63);
    (void)m;
    if (n > CONFORM_LUT_N)
        n = CONFORM_LUT_N;
    return form == 1 ? fresnel_lut_cubic_avg_u16_q15(conform_lut_u16[0], n)
                     : (form == 2 ? fresnel_lut_linear_avg_u16_q15(conform_lut_u16[1], n)
                                  : fresnel_lut_avg_u16_q15(conform_lut_u16[0], n));
}
/* The fast paths (fresnel_fixed.h, "fast paths"): their preconditions hold
 * here (c, F0, F82 in [0, one]; a 64-node table). */
static fresnel_q15 e_schlick_fast(const conform_material *m, int32_t c) { return fresnel_schlick_q15_fast(m->f0, c); }
static fresnel_q15 e_f82_fast(const conform_material *m, int32_t c) { return fresnel_f82_q15_fast(m->f0, m->f82_a, c); }
static fresnel_q15 e_lut_u16_fast(const conform_material *m, int32_t c)
{
    (void)m;
    return fresnel_lut_u16_q15_fast(conform_lut_u16[0], CONFORM_LUT_N, c);
}
static fresnel_q15 e_lut_u16_pl_fast(const conform_material *m, int32_t c)
{
    (void)m;
    return fresnel_lut_pl_u16_q15_fast(conform_lut_u16[0], CONFORM_LUT_N, c);
}
/* every test material, also outside the fast path's documented domain: the
 * targets must give the host's results bit for bit all the same */
static fresnel_q15 e_conductor_fast(const conform_material *m, int32_t c)
{
    return fresnel_conductor_q15_fast(&m->cfast, c);
}
/* The thin film (fresnel_film_q15_rgb, one RGB evaluation): conform_film
 * at a thickness scattered over 0-4096 nm by the code (a multiplication,
 * not a remainder: the M0 has no division), the channels folded into one
 * value for the hash. */
static fresnel_q15 e_film(const conform_material *m, int32_t c)
{
    fresnel_rgb_q15 r = fresnel_film_q15_rgb(&conform_film, c, (fresnel_q16)(((uint32_t)c * 2654435761u) >> 4));
    (void)m;
    return (fresnel_q15)(r.r ^ (uint32_t)r.g << 5 ^ (uint32_t)r.b << 10);
}
typedef struct fixed_model {
    const char *name;
    fixed_eval fn;
    int per_material; /* 0: the LUTs, one table whatever the material */
} fixed_model;

static const fixed_model fixed_models[] = {
    {"schlick", e_schlick, 1},
    {"schlick-gen p=5", e_schlick_gen, 1},
    {"schlick-gen p=0.5", e_schlick_gen_half, 1},
    {"schlick-gen p=3.7", e_schlick_gen_37, 1},
    {"lsk", e_lsk, 1},
    {"lsk-comp", e_lsk_comp, 1},
    {"f82", e_f82, 1},
    {"gulbrandsen", e_gulbrandsen, 1},
    {"cook-torrance", e_cook_torrance, 1},
    {"exact-conductor", e_conductor, 1},
    {"exact-dielectric", e_dielectric, 1},
    {"approx-conductor", e_approx, 1},
    {"schlick-internal", e_internal, 1},
    {"f0-in-medium", e_f0_in_medium, 1},
    {"lut u16", e_lut_u16, 0},
    {"lut-linear u16", e_lut_linear_u16, 0},
    {"lut u8", e_lut_u8, 0},
    {"lut-residual s16", e_lut_residual_s16, 0},
    {"lut-linear-residual s8", e_lut_linear_residual_s8, 0},
    {"lut-cubic u16", e_lut_cubic_u16, 0},
    {"lut averages u16", e_lut_avg_u16, 0},
    {"schlick fast", e_schlick_fast, 1},
    {"f82 fast", e_f82_fast, 1},
    {"lut u16 fast", e_lut_u16_fast, 0},
    {"lut u16 pl fast", e_lut_u16_pl_fast, 0},
    {"exact-conductor fast", e_conductor_fast, 1},
    {"thin-film", e_film, 0},
};
#define FIXED_MODEL_COUNT ((int)(sizeof fixed_models / sizeof fixed_models[0]))

/* The batches (fresnel_q15.h, BATCHES): one material's cosines in, one
 * result each out; the _rgb forms take the material and the next two for
 * their channels and fold each result's channels into one value (as the
 * film's row does), the LUTs' a three-channel table made from the gold
 * curve (batch_lut_rgb, filled by batch_tables_init). */
typedef void (*batch_eval)(const conform_material *m, const fresnel_q15 *c, fresnel_q15 *out, int n);
static uint16_t batch_lut_rgb[3 * CONFORM_LUT_N];
static void batch_tables_init(void)
{
    int i;
    for (i = 0; i < CONFORM_LUT_N; i++) {
        batch_lut_rgb[i] = conform_lut_u16[0][i];
        batch_lut_rgb[CONFORM_LUT_N + i] = (uint16_t)(conform_lut_u16[0][i] - (conform_lut_u16[0][i] >> 3));
        batch_lut_rgb[2 * CONFORM_LUT_N + i] = (uint16_t)(conform_lut_u16[0][i] >> 1);
    }
}
static fresnel_rgb_q15 rgb_of(const conform_material *m, int which)
{
    fresnel_rgb_q15 v;
    const int32_t *f = which ? &m->f82 : &m->f0;
    v.r = (fresnel_q15)f[0];
    v.g = (fresnel_q15)(which ? m[1].f82 : m[1].f0);
    v.b = (fresnel_q15)(which ? m[2].f82 : m[2].f0);
    return v;
}
static fresnel_q15 fold_rgb(fresnel_rgb_q15 r) { return (fresnel_q15)(r.r ^ (uint32_t)r.g << 5 ^ (uint32_t)r.b << 10); }
#define BATCH_MAX 64
static fresnel_rgb_q15 batch_rgb_out[BATCH_MAX];
static void b_schlick(const conform_material *m, const fresnel_q15 *c, fresnel_q15 *o, int n) { fresnel_schlick_q15_batch(m->f0, c, o, n); }
static void b_schlick_gen(const conform_material *m, const fresnel_q15 *c, fresnel_q15 *o, int n)
{
    fresnel_schlick_gen_q15_batch(m->f0, m->f90, m->p, c, o, n);
}
static void b_f82(const conform_material *m, const fresnel_q15 *c, fresnel_q15 *o, int n) { fresnel_f82_q15_batch(m->f0, m->f82, c, o, n); }
static void b_lut_u16(const conform_material *m, const fresnel_q15 *c, fresnel_q15 *o, int n)
{
    (void)m;
    fresnel_lut_u16_q15_batch(conform_lut_u16[0], CONFORM_LUT_N, c, o, n);
}
static void b_lut_linear_u16(const conform_material *m, const fresnel_q15 *c, fresnel_q15 *o, int n)
{
    (void)m;
    fresnel_lut_linear_u16_q15_batch(conform_lut_u16[1], CONFORM_LUT_N, c, o, n);
}
static void b_lut_cubic_u16(const conform_material *m, const fresnel_q15 *c, fresnel_q15 *o, int n)
{
    (void)m;
    fresnel_lut_cubic_u16_q15_batch(conform_lut_u16[0], CONFORM_LUT_N, c, o, n);
}
#define BATCH_RGB(name, call)                                                                                          \
    static void name(const conform_material *m, const fresnel_q15 *c, fresnel_q15 *o, int n)                          \
    {                                                                                                                  \
        int i_;                                                                                                        \
        (void)m;                                                                                                       \
        call;                                                                                                          \
        for (i_ = 0; i_ < n; i_++)                                                                                     \
            o[i_] = fold_rgb(batch_rgb_out[i_]);                                                                       \
    }
BATCH_RGB(b_schlick_rgb, fresnel_schlick_q15_rgb_batch(rgb_of(m, 0), c, batch_rgb_out, n))
BATCH_RGB(b_f82_rgb, fresnel_f82_q15_rgb_batch(rgb_of(m, 0), rgb_of(m, 1), c, batch_rgb_out, n))
BATCH_RGB(b_lut_u16_rgb, fresnel_lut_u16_q15_rgb_batch(batch_lut_rgb, CONFORM_LUT_N, c, batch_rgb_out, n))
BATCH_RGB(b_lut_cubic_u16_rgb, fresnel_lut_cubic_u16_q15_rgb_batch(batch_lut_rgb, CONFORM_LUT_N, c, batch_rgb_out, n))

typedef struct batch_model {
    const char *name;
    batch_eval fn;
    int per_material; /* 0: the LUTs; the rgb forms read materials k, k+1, k+2 */
} batch_model;

static const batch_model batch_models[] = {
    {"schlick batch", b_schlick, 1},
    {"schlick-gen batch", b_schlick_gen, 1},
    {"f82 batch", b_f82, 1},
    {"lut u16 batch", b_lut_u16, 0},
    {"lut-linear u16 batch", b_lut_linear_u16, 0},
    {"lut-cubic u16 batch", b_lut_cubic_u16, 0},
    {"schlick rgb batch", b_schlick_rgb, 2},
    {"f82 rgb batch", b_f82_rgb, 2},
    {"lut u16 rgb batch", b_lut_u16_rgb, 0},
    {"lut-cubic u16 rgb batch", b_lut_cubic_u16_rgb, 0},
};
#define BATCH_MODEL_COUNT ((int)(sizeof batch_models / sizeof batch_models[0]))

#endif
