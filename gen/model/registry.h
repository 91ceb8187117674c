/* The model registry: every model the tool knows is one row of model_table
 * (registry.c), holding its names, where it is offered, the parameters it
 * reads, and its evaluators in every number type. Scene parsing and
 * evaluation, `eval`, `curve`, `accuracy`, `report`, `extremes`, `bench` and
 * the three emitters read the rows; no other file names a model to choose
 * or list models (tests/gen/test_gen_layout.sh checks it).
 *
 * Adding a model: gen/README.md lists every place it touches (its runtime
 * functions, its double reference, its shader function, one row here). */
#ifndef FRESNEL_REGISTRY_H
#define FRESNEL_REGISTRY_H

#include <stdint.h>
#include <stdio.h>

#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_fixed.h"
#include "3_encode/encode.h"

/* Where a row is offered. */
#define MODEL_EVAL 1u  /* a function of eta, kappa, c: `fresnel eval`, `extremes`, the bound tests */
#define MODEL_SCENE 2u /* a scene model: manifests, `gen`, `curve`, `report`, `bench` */
#define MODEL_LUT 4u   /* a LUT form; its scene names are lutN, lutN-residual, lutN-cubic */
#define MODEL_EXACT 8u /* the Fresnel equations themselves (the reference `accuracy` measures against) */
#define MODEL_FILM 16u /* the thin film (fresnel_film.h): reads the material's film (encoded_film) at
                        * model_rgb's thickness; a scene with it names the film's index */

/* The derived parameters (material_params) a scene model reads, one bit per
 * group, in the order the C and GLSL emitters write them (emit_header.c). */
#define MP_F0 0x01u
#define MP_F82 0x02u
#define MP_ETA_FIT 0x04u
#define MP_LSK 0x08u
#define MP_ETA_GAUSS 0x10u
#define MP_ETA_POINT 0x20u
#define MP_GULB 0x40u
#define MP_CT 0x80u
/* Prepared Q15 constants (fresnel_fixed.h) a scene model reads, in the order
 * the Q15 emitter writes them (emit_fixed.c), after the MP_ groups. */
#define MQ_LSK 0x01u
#define MQ_LSK_COMP 0x02u
#define MQ_IOR 0x04u
#define MQ_IOR_GAUSS 0x08u
#define MQ_IOR_POINT 0x10u
#define MQ_NK 0x20u
#define MQ_CT 0x40u

/* The most nodes a scene LUT has (scene.h: SCENE_LUT_MAX). */
#define MODEL_LUT_NODES_MAX 256

/* Everything any model needs. eta and kappa are relative to the incident
 * medium; the rest are derived from them by the reference (model_derive). */
typedef struct model_params {
    double eta, kappa;
    double f0, f82, f90, p;
    double a, alpha; /* LSK compensation */
    double r, g;     /* Gulbrandsen */
} model_params;

/* A model's parameters in the fixed-point runtime's formats (fresnel_fixed.h). */
typedef struct model_fixed {
    int32_t f0, f82, f90, r, g; /* Q15 codes */
    fresnel_q16 p;
    fresnel_ior_prep_q15 ior;  /* eta, kappa for the exact models and Cook-Torrance */
    fresnel_ior_prep_q15 dior; /* eta, kappa 0 for exact-dielectric */
    fresnel_nk_prep_q15 nk;    /* eta, kappa for the approximate conductor */
    fresnel_nk_prep_q15 gnk;   /* Gulbrandsen's n, k from r, g (fresnel_gulbrandsen_nk_q15) */
    fresnel_lsk_prep_q15 lsk;
} model_fixed;

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

typedef struct model {
    const char *name;   /* the one name: manifests, --model, report and curve columns */
    unsigned offered;   /* MODEL_* */
    const char *params; /* which parameters it reads, for --help */

    /* As a function of eta, kappa, c (MODEL_EVAL) */
    double (*f64)(const model_params *m, double c);
    float (*f32)(const model_params *m, float c);
    float bound; /* documented binary32 error bound, FRESNEL_BOUND_* */
    /* Q15 runtime: the result code at cos code c (0..32768), and its
     * documented bound in LSB, FRESNEL_BOUND_*_Q15 */
    int32_t (*q15)(const model_fixed *m, int32_t c);
    double q15_bound;
    /* binary16 runtime with every parameter and c rounded to binary16 (NULL
     * where the compiler has no _Float16), and FRESNEL_BOUND_*_F16 */
    double (*f16)(const model_params *m, double c);
    double f16_bound;

    /* As a scene model (MODEL_SCENE) */
    unsigned reads;     /* MP_* */
    unsigned q15_reads; /* MQ_* */
    model_eta eta;      /* which eta, kappa its exact forms read (encode.h) */
    lut_form form;      /* MODEL_LUT rows */
    int uniform;        /* MODEL_LUT rows: 1 nodes uniform in c, 0 in sqrt(c) */
    /* Shader return expression (ports/glsl/fresnel.glsl, the one source of
     * the GLSL and HLSL ports); '@' stands for the material's
     * identifier prefix and '_' (the MODEL_FILM row's is a function body,
     * a statement macro). NULL for LUT rows, whose shader code the
     * emitters build from the form; NULL in a scene row: no shader form. */
    const char *glsl;
    fresnel_rgb (*rgb_f32)(const model_rgb *q, float c);
    fresnel_rgb_q15 (*rgb_q15)(const model_rgb *q, int32_t c);
    double (*ch_f16)(const model_rgb *q, int ch, double c); /* NULL without _Float16 */
    /* The double reference on the binary32-rounded parameters, channel ch */
    double (*ch_ref)(const model_rgb *q, int ch, double c);
    model_batch batch_f32, batch_q15, batch_f16; /* batch_f16 NULL without _Float16 */
    /* The runtime's closed-form hemispherical average (fresnel_*_avg_rgb,
     * binary32); NULL where the runtime has none. */
    fresnel_rgb (*avg_f32)(const model_rgb *q);
    /* Its row in `make cross-count`'s tables (tests/ports/cross/q15_models.h),
     * the Q15 function a firmware calls for it; NULL where there is none. */
    const char *cross_row;
} model;

extern const model model_table[];
extern const int model_count;
/* The row named name offered as `offered`; NULL if none. */
const model *model_find_offered(const char *name, unsigned offered);
/* The MODEL_EVAL row named name (fresnel eval); NULL if none. */
const model *model_find(const char *name);
/* A scene model's name read, the one place a name is: the row of a
 * MODEL_SCENE name, or for "lutN", "lutN-residual", "lutN-cubic" (N in
 * lo..hi, no leading zeros) the row of its form at `spacing` with N in
 * *lut_n (0 for the others). NULL for any other string. */
const model *model_scene_parse(const char *name, lut_spacing spacing, int lo, int hi, int *lut_n);
/* The LUT row of form `form` at `spacing` (a manifest may set its spacing
 * after its models). */
const model *model_lut_row(lut_form form, lut_spacing spacing);
/* Whether the shader ports (ports/glsl/fresnel.glsl, which
 * ports/hlsl/fresnel.hlsl includes, so one expression per row serves both)
 * express scene row `row` with tables spaced `spacing`: NULL, or what they
 * lack, for the back end's error message. */
const char *model_shader_lacks(const model *row, lut_spacing spacing);
/* The rows offered as `offered`, without LUT rows, NULL-terminated: their
 * names for messages and --help. max includes the NULL. */
int model_names(unsigned offered, const char **out, int max);
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
void model_params_round_fixed(model_params *m);
/* Prepared constants and codes from (rounded) parameters. */
void model_fixed_from_params(const model_params *m, model_fixed *out);
/* And for binary16: every parameter rounded to binary16 (a no-op without _Float16). */
void model_params_round_f16(model_params *m);

#endif
