/* Stage 3 of the generator: LUT node positions and values for the runtime's
 * table models (include/fresnel.h, src/f32/lut.c), fitted to the ground truth,
 * and every constant and table of a scene in each number type the runtime
 * reads (encode_constants.c). */
#ifndef FRESNEL_ENCODE_H
#define FRESNEL_ENCODE_H

#include <stdint.h>

#include "2_derive/derive.h"
#include "catalog/models.h"
#include "3_encode/film_encode.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_film.h"
#include "fresnel_q15.h"

/* cos theta of node i of n. */
double lut_node_cos(lut_spacing spacing, int i, int n);
/* The position in [0, 1] along the nodes of cos theta = c (node i at i/(n-1)). */
double lut_position(lut_spacing spacing, double c);
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
 * and prepared structs of fresnel_q15.h, through q15_params.h) and,
 * where the compiler has _Float16, binary16. `fresnel gen` writes these
 * values and nothing else; `fresnel report`, `curve`, `bench`, the viewer
 * and the tests evaluate these values (model_rgb in model/registry.h), so
 * every figure they print is a figure of the emitted header. */


/* The members of a parameter (catalog/parameters.h) in each type. */
#define ENCODED_F32_3(field) fresnel_rgb field;
#define ENCODED_F32_1(field) float field;
#define ENCODED_Q15_Q15_NONE(field)
#define ENCODED_Q15_Q15_CODE(field) fresnel_rgb_q15 q_##field;
#define ENCODED_Q15_Q15_CODE_ONE(field) fresnel_rgb_q15 q_##field;
#define ENCODED_Q15_Q15_CODE_HELD(field) fresnel_rgb_q15 q_##field;
#define ENCODED_F32_MEMBER(field, count, group, constant, row, why, q15, q15_why) ENCODED_F32_##count(field)
#define ENCODED_Q15_MEMBER(field, count, group, constant, row, why, q15, q15_why) ENCODED_Q15_##q15(field)
#define ENCODED_F16_MEMBER(field, count, group, constant, row, why, q15, q15_why) fresnel_f16 h_##field PARAM_ARRAY_##count;

typedef struct encoded_material {
    /* binary32: every parameter */
    DERIVED_PARAMETERS(ENCODED_F32_MEMBER)
    /* Q1.15: the parameters held as codes, round(v 32768) clamped to [0,
     * 65535] (every scene's range check refuses a value that leaves its
     * type) */
    DERIVED_PARAMETERS(ENCODED_Q15_MEMBER)
    /* q_f0 is held to one (32768): every Q1.15 function reads F0 above one
     * as one, and the fast paths (fresnel_q15_fast.h) take f0 only up to
     * one; 1 where gamut = keep put a channel above. */
    int q_f0_held;
    int32_t q_f82_a[3];                           /* fresnel_f82_q15_fast's a_q12 from q_f0, q_f82 */
    fresnel_lsk_prep_q15 q_lsk[3], q_lsk_comp[3]; /* on the fitted eta, kappa; q_lsk: a = alpha = 0 */
    fresnel_ior_prep_q15 q_ior[ETA_SOURCES][3], q_ct;
    fresnel_nk_prep_q15 q_nk[3];                  /* the fitted eta, kappa */
    fresnel_conductor_prep_q15_fast q_ior_fast[3];     /* the fitted eta, kappa, where q_ior_fast_out is -1 */
    int q_ior_fast_out; /* the first channel outside fresnel_conductor_q15_fast's domain, or -1 */
#if FRESNEL_HAS_F16
    /* binary16, per channel (the binary16 runtime is scalar): every parameter */
    DERIVED_PARAMETERS(ENCODED_F16_MEMBER)
#endif
} encoded_material;
void encode_material(const material_params *p, encoded_material *out);
/* Whether every Q1.15 constant of the material that models reading reads
 * (MP_*) and q15_reads (MQ_*) hold has its value in its C type and the
 * range fresnel_q15.h's LAYOUT documents (encode_check.c): 0, or -1 with
 * the first that does not in why. */
int encode_q15_fits(const material_params *p, const encoded_material *e, unsigned reads, unsigned q15_reads,
                    char *why, size_t size);
/* The eta, kappa a model reads (its row's model_eta), in binary32 and
 * binary16. */
fresnel_rgb encoded_eta(const encoded_material *e, model_eta source, int kappa);
#if FRESNEL_HAS_F16
const fresnel_f16 *encoded_eta_f16(const encoded_material *e, model_eta source, int kappa);
#endif

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
    int f32_finite, f16_finite; /* 1 where every value of the binary32, binary16 table is finite */
    char why[256]; /* why encode_film refused the stack, or empty */
#if FRESNEL_HAS_F16
    fresnel_film_f16 f16;
#endif
} encoded_film;
/* 0; -1 when p has no film (film_n 0), the stack is outside the model's
 * domain (film_stack_domain: out->why says which condition fails) or the
 * fit fails (out of memory). s: the material's spectrum. poles: the
 * colour space's poles (film_fit_poles, the same for every material of a
 * scene), or NULL to fit them here. */
int encode_film(const spectrum *s, const gen_context *g, const material_params *p, const film_model *poles,
                encoded_film *out);

#endif
