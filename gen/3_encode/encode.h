/* Stage 3 of the generator: LUT node positions and values for the runtime's
 * table models (include/fresnel.h, src/f32/lut.c), fitted to the ground truth,
 * and every constant and table of a scene in each number type the runtime
 * reads (encode_constants.c). */
#ifndef FRESNEL_ENCODE_H
#define FRESNEL_ENCODE_H

#include <stdint.h>

#include "2_derive/derive.h"
#include "3_encode/film_encode.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_film.h"
#include "fresnel_q15.h"

/* LUT_GRAZING: nodes uniform in sqrt(c); LUT_UNIFORM: in c; LUT_GRAZING_PL:
 * uniform in fresnel_fixed_fast.h's 64-piece linear stand-in for sqrt(c), the
 * position of fresnel_lut_pl_u16_q15_fast. LUT_WARP2, LUT_WARP16: uniform in
 * the root-free warps c (2 - c) = 1 - (1 - c)^2 and (1 + c - (1 - c)^16)/2,
 * whose slope at c = 0 (2; 8.5) crowds the nodes toward grazing incidence
 * at the cost of a few multiplications instead of a square root; no runtime
 * function reads them: the report's LUT table measures them against sqrt(c)
 * at equal size. */
typedef enum lut_spacing { LUT_GRAZING, LUT_UNIFORM, LUT_GRAZING_PL, LUT_WARP2, LUT_WARP16 } lut_spacing;
/* cos theta of node i of n. */
double lut_node_cos(lut_spacing spacing, int i, int n);
/* The position in [0, 1] along the nodes of cos theta = c (node i at i/(n-1)). */
double lut_position(lut_spacing spacing, double c);
/* The runtime's LUT forms: linear interpolation of the curve (fresnel_lut),
 * of its residual from Schlick(F0) (fresnel_lut_residual), Catmull-Rom of
 * the curve (fresnel_lut_cubic). */
typedef enum lut_form { LUT_PLAIN, LUT_RESIDUAL, LUT_CUBIC } lut_form;
/* table[ch * n + i]: node i of channel ch, least-squares fitted through the
 * form's interpolation to the ground truth under the gamut policy (minus
 * Schlick(F0) for LUT_RESIDUAL) at theta every 0.05 degrees and at the
 * nodes; curve nodes that would leave [0, 1] (under the keep policy
 * [0, the curve's maximum], at most ENCODE_LUT_KEEP_MAX) are held at the
 * bound and the others refitted.
 * 0, or -1 when out of memory. */
#define ENCODE_LUT_KEEP_MAX (65535.0 / 32768.0) /* the largest uint16_t Q15 node */
int encode_lut(const spectrum *s, const gen_context *g, const material_params *p, lut_spacing spacing, int n,
               lut_form form, double *table);

/* THE ENCODER. One material's constants and one LUT's nodes in every number
 * type: binary32 (the C, GLSL and HLSL headers' literals), Q1.15 (the codes
 * and prepared structs of fresnel_fixed.h, through fixed_params.h) and,
 * where the compiler has _Float16, binary16. `fresnel gen` writes these
 * values and nothing else; `fresnel report`, `curve`, `bench`, the viewer
 * and the tests evaluate these values (model_rgb in model/registry.h), so
 * every figure they print is a figure of the emitted header. */

/* Which eta, kappa of material_params a model reads. */
typedef enum model_eta { ETA_FIT, ETA_GAUSS, ETA_POINT, ETA_SOURCES } model_eta;

typedef struct encoded_material {
    /* binary32 */
    fresnel_rgb f0, f_avg, f82, eta[ETA_SOURCES], kappa[ETA_SOURCES], lsk_a, lsk_alpha, gulb_r, gulb_g;
    float ct_eta, ct_kappa;
    /* Q1.15: codes round(v 32768) clamped to [0, 65535] (the emitters refuse
     * a value that leaves its type before writing it) */
    fresnel_rgb_q15 q_f0, q_f_avg, q_f82, q_gulb_r, q_gulb_g;
    /* q_f0 is held to one (32768): every Q1.15 function reads F0 above one
     * as one, and the fast paths (fresnel_fixed_fast.h) take f0 only up to
     * one; 1 where gamut = keep put a channel above. */
    int q_f0_held;
    int32_t q_f82_a[3];                           /* fresnel_f82_q15_fast's a_q12 from q_f0, q_f82 */
    fresnel_lsk_prep_q15 q_lsk[3], q_lsk_comp[3]; /* on the fitted eta, kappa; q_lsk: a = alpha = 0 */
    fresnel_ior_prep_q15 q_ior[ETA_SOURCES][3], q_ct;
    fresnel_nk_prep_q15 q_nk[3];                  /* the fitted eta, kappa */
    fresnel_conductor_prep_q15_fast q_ior_fast[3];     /* the fitted eta, kappa, where q_ior_fast_out is -1 */
    int q_ior_fast_out; /* the first channel outside fresnel_conductor_q15_fast's domain, or -1 */
#if FRESNEL_HAS_F16
    /* binary16, per channel (the binary16 runtime is scalar) */
    fresnel_f16 h_f0[3], h_f_avg[3], h_f82[3], h_eta[ETA_SOURCES][3], h_kappa[ETA_SOURCES][3], h_lsk_a[3],
        h_lsk_alpha[3], h_gulb_r[3], h_gulb_g[3], h_ct_eta, h_ct_kappa;
#endif
} encoded_material;
void encode_material(const material_params *p, encoded_material *out);

typedef struct encoded_lut {
    int n; /* nodes per channel; 0: no table */
    lut_form form;
    lut_spacing spacing;
    double *nodes;    /* 3n: node i of channel ch at [ch n + i] (encode_lut) */
    float *f32;       /* the same in binary32 */
    uint16_t *q15;    /* curves: round(v 32768); NULL for a residual */
    int16_t *q15_res; /* residuals: round(v 2^frac); NULL for a curve */
    int frac;         /* the most fraction bits in [14, 30] that keep every residual node in int16_t */
#if FRESNEL_HAS_F16
    fresnel_f16 *f16;
#endif
    int bad; /* the first node that is not finite or that no Q1.15 code holds (at frac 14), or -1 */
} encoded_lut;
/* Fit (encode_lut) and encode a table: 0, or -1 when out of memory (then
 * nothing is held). encoded_lut_free releases it (and accepts a zeroed one). */
int encode_table(const spectrum *s, const gen_context *g, const material_params *p, lut_spacing spacing, int n,
                 lut_form form, encoded_lut *out);
void encoded_lut_free(encoded_lut *t);
/* The Q1.15 codes of curve nodes (round(v 32768) clamped to [0, 65535]),
 * for tables the report builds to compare encodings. */
void encode_curve_q15(const double *nodes, int count, uint16_t *codes);

/* A material's thin film (fresnel_film.h) in every number type: the
 * observer's poles and the material's table fitted (2_derive/film_fit.h)
 * for a film of index p->film_n on the material in p->n1, then encoded
 * (film_encode.h). model is the fit in double; model_f32 the double model of
 * the binary32 table (the reference of the binary32 runtime's bound). */
typedef struct encoded_film {
    double n_film;
    film_model model, model_f32;
    fresnel_film f32;
    fresnel_film_q15 q15;
    int q15_ok; /* 0 where the Q1.15 layout holds no table of it (film_encode_q15) */
    char why[256]; /* why encode_film refused the stack, or empty */
#if FRESNEL_HAS_F16
    fresnel_film_f16 f16;
#endif
} encoded_film;
/* 0; -1 when p has no film (film_n 0), the stack is outside the model's
 * domain (film_stack_domain: out->why says which condition fails) or the
 * fit fails (out of memory). s: the material's spectrum. */
int encode_film(const spectrum *s, const gen_context *g, const material_params *p, encoded_film *out);

#endif
