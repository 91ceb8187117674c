/* The model registry: every model the tool knows is one row of model_table
 * (registry.c): its data, a row of catalog/models.h, and its evaluators in
 * every number type, one line per type in model/eval_ref.c, eval_f32.c,
 * eval_q15.c and eval_f16.c. Scene parsing and evaluation, `eval`, `curve`,
 * `accuracy`, `report`, `extremes`, `bench` and the back ends read the
 * rows; no other file names a model to choose or list models
 * (tests/gen/test_gen_layout.sh checks it).
 *
 * Adding a model: gen/README.md lists every place it touches (its runtime
 * functions, its double reference, its shader function, its catalog row
 * and its line in each evaluator table). */
#ifndef FRESNEL_REGISTRY_H
#define FRESNEL_REGISTRY_H

#include <stdint.h>
#include <stdio.h>

#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_q15.h"
#include "3_encode/encode.h"
#include "catalog/models.h"
#include "catalog/parameters.h"

/* The derived parameters a scene model reads (MP_*) and the prepared Q15
 * constants (MQ_*): catalog/parameters.h. */


/* Everything any model needs. eta and kappa are relative to the incident
 * medium; the rest are derived from them by the reference (model_derive). */
typedef struct model_params {
    double eta, kappa;
    double f0, f82, f90, p;
    double a, alpha; /* LSK compensation */
    double r, g;     /* Gulbrandsen */
} model_params;

/* A model's parameters in the fixed-point runtime's formats (fresnel_q15.h). */
typedef struct model_q15 {
    int32_t f0, f82, f90, r, g; /* Q15 codes */
    fresnel_q16 p;
    fresnel_ior_prep_q15 ior;  /* eta, kappa for the exact models and Cook-Torrance */
    fresnel_ior_prep_q15 dior; /* eta, kappa 0 for exact-dielectric */
    fresnel_nk_prep_q15 nk;    /* eta, kappa for the approximate conductor */
    fresnel_nk_prep_q15 gnk;   /* Gulbrandsen's n, k from r, g (fresnel_gulbrandsen_nk_q15) */
    fresnel_lsk_prep_q15 lsk;
} model_q15;

/* One scene model of one material as the runtime sees it in every number
 * type: the encoder's values (3_encode/encode.h), which are what `fresnel
 * gen` writes; what the scene evaluators read. */
typedef struct model_rgb {
    const struct model *def;
    const encoded_material *mat;
    const encoded_lut *lut;   /* the LUT rows' table; NULL for the others */
    const encoded_film *film; /* the MODEL_FILM row's film; NULL for the others */
    double d_nm;              /* the MODEL_FILM row's film thickness, nm; the others ignore it */
} model_rgb;

/* A timed loop over n cosines (c for the float types, cq the same as Q15
 * codes) of one prepared model: the row's evaluator is called directly, so
 * no dispatch sits inside the loop (bench.h's bench_batch). */
typedef double (*model_batch)(const void *q, const float *c, const int32_t *cq, int n);

/* A row's evaluators in each number type (NULL where it has none):
 * as a function of eta, kappa, c (MODEL_EVAL rows: `scalar`) and as a
 * scene model of one material (`scene`: model_rgb), its timed loop
 * (`batch`), and in binary32 the runtime's closed-form hemispherical
 * average (fresnel_*_avg_rgb). */
typedef struct model_eval_ref { /* the double reference; scene: on the binary32-rounded constants, channel ch */
    double (*scalar)(const model_params *m, double c);
    double (*scene)(const model_rgb *q, int ch, double c);
} model_eval_ref;
typedef struct model_eval_f32 {
    float (*scalar)(const model_params *m, float c);
    fresnel_rgb (*scene)(const model_rgb *q, float c);
    model_batch batch;
    fresnel_rgb (*avg)(const model_rgb *q);
} model_eval_f32;
typedef struct model_eval_q15 { /* scalar: the result code at cos code c (0..32768) */
    int32_t (*scalar)(const model_q15 *m, int32_t c);
    fresnel_rgb_q15 (*scene)(const model_rgb *q, int32_t c);
    model_batch batch;
} model_eval_q15;
typedef struct model_eval_f16 { /* every parameter and c rounded to binary16; all NULL without _Float16 */
    double (*scalar)(const model_params *m, double c);
    double (*scene)(const model_rgb *q, int ch, double c);
    model_batch batch;
} model_eval_f16;
extern const model_eval_ref model_evals_ref[MODEL_ROWS];
extern const model_eval_f32 model_evals_f32[MODEL_ROWS];
extern const model_eval_q15 model_evals_q15[MODEL_ROWS];
extern const model_eval_f16 model_evals_f16[MODEL_ROWS];

/* A row: the catalog's data (catalog/models.h says what each field holds)
 * and its evaluators. */
typedef struct model {
    MODEL_FACTS
    const model_eval_ref *ref;
    const model_eval_f32 *f32;
    const model_eval_q15 *q15;
    const model_eval_f16 *f16;
} model;

/* Every row, in model_row_id order: the MODEL_CATALOG rows (model_count of
 * them), then the LUT rows. */
extern const model model_table[MODEL_ROWS];
extern const int model_count;
/* The row named name offered as `offered`; NULL if none. */
const model *model_find_offered(const char *name, unsigned offered);
/* The MODEL_EVAL row named name (fresnel eval); NULL if none. */
const model *model_find(const char *name);
/* The row of id (a scene entry's, model_scene_id's, model_lut_id's). */
const model *model_of(model_row_id id);
/* Whether the shader ports (ports/glsl/fresnel.glsl, which
 * ports/hlsl/fresnel.hlsl includes, so one expression per row serves both)
 * express scene row `row` with tables spaced `spacing`: NULL, or what they
 * lack, for the back end's error message. */
const char *model_shader_lacks(const model *row, lut_spacing spacing);
/* The LUT names' patterns for --help ("lutN lutN-residual lutN-cubic"). */
extern const char model_lut_patterns[];

/* The models `fresnel curve` draws without --models: without and with --film. */
extern const char model_curve_default[], model_curve_film[];
/* The column order of the report's table of the papers' approaches. */
extern const char *const model_approaches_order[];

/* Rows other code needs by role. */
extern const model *const model_schlick;          /* Schlick (the yardstick of run-time costs) */
extern const model *const model_exact;            /* exact, the dielectric form at kappa 0 */
extern const model *const model_f82;              /* the F82 model (extremes: F0, F82 pairs) */
extern const model *const model_gulbrandsen;      /* Gulbrandsen (extremes: r, g pairs) */
extern const model *const model_schlick_internal; /* Schlick from inside (accuracy: its own table) */

/* Parameters of a material of index eta + i kappa seen from a medium of index
 * n1: F0 = exact at c = 1, F82 = exact at c = 1/7, LSK a and alpha, Gulbrandsen
 * r and g, with f90 and p as given (generalized Schlick). */
void model_derive(double eta, double kappa, double n1, double f90, double p, model_params *out);

/* Round every parameter to binary32, so that a double evaluation sees exactly
 * the inputs the float one does and the difference is the runtime's error. */
void model_params_round_f32(model_params *m);

/* The same for the fixed-point runtime: F0, F82, F90, r, g to Q15 codes (r
 * at most FRESNEL_GULBRANDSEN_R_MAX_Q15, the runtime's clamp), p and alpha to
 * Q16.16, a to its 31-bit mantissa. eta and kappa are kept: the prepared
 * constants carry 31-bit mantissas, and eta^2 - kappa^2 - 1 two words, so
 * their rounding is part of the error the tests measure. */
void model_params_round_q15(model_params *m);
/* Prepared constants and codes from (rounded) parameters. */
void model_q15_from_params(const model_params *m, model_q15 *out);
/* And for binary16: every parameter rounded to binary16 (a no-op without _Float16). */
void model_params_round_f16(model_params *m);

#endif
