/* Every model the tool knows, as data: one row each, in designated
 * initialisers of model/registry.h's `model`, expanded by the registry
 * (model/registry.c: model_table, the LUT rows), which adds each row's
 * evaluators in every number type from one line per type
 * (model/eval_ref.c, eval_f32.c, eval_q15.c, eval_f16.c).
 *
 *   X(id, .name = ..., ...)
 *
 * id         the row's index, MODEL_ROW_<id>, in every evaluator table
 * .name      the one name: manifests, --model, report and curve columns
 * .offered   where it is offered (MODEL_*)
 * .params    which parameters it reads, for --help
 * .bound, .q15_bound, .f16_bound   its documented error bound in binary32
 *            (absolute), Q1.15 (LSB) and binary16 (absolute): the
 *            headers' FRESNEL_BOUND_*
 * .reads, .q15_reads   the derived parameters (MP_*) and prepared Q1.15
 *            constants (MQ_*) a scene model reads (catalog/parameters.h)
 * .eta       which eta, kappa its exact forms read
 * .form, .uniform   LUT rows: the runtime's form and its spacing (1 nodes
 *            uniform in c, 0 in sqrt(c))
 * .glsl      the shader return expression (ports/glsl/fresnel.glsl, the
 *            one source of the GLSL and HLSL ports); '@' stands for the
 *            material's identifier prefix (the thin film's is a statement
 *            macro); none for LUT rows, whose shader code the back ends
 *            build from the form, and none for a row the ports lack
 * .cross_row its row in `make cross-count`'s tables
 *            (tests/ports/cross/q15_models.h), the Q1.15 function a
 *            firmware calls for it; none where there is none */
#ifndef FRESNEL_CATALOG_MODELS_H
#define FRESNEL_CATALOG_MODELS_H

#include "catalog/parameters.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_film.h"
#include "fresnel_q15.h"

/* The most nodes a scene LUT has (scene/scene.h: SCENE_LUT_MAX). */
#define MODEL_LUT_NODES_MAX 256

/* Where a row is offered. */
#define MODEL_EVAL 1u  /* a function of eta, kappa, c: `fresnel eval`, `extremes`, the bound tests */
#define MODEL_SCENE 2u /* a scene model: manifests, `gen`, `curve`, `report`, `bench` */
#define MODEL_LUT 4u   /* a LUT form; its scene names are lutN, lutN-residual, lutN-cubic */
#define MODEL_EXACT 8u /* the Fresnel equations themselves (the reference `accuracy` measures against) */
#define MODEL_FILM 16u /* the thin film (fresnel_film.h): reads the material's film at a thickness;
                        * a scene with it names the film's index */
#define MODEL_EVAL_SCENE (MODEL_EVAL | MODEL_SCENE)

/* LUT_GRAZING: nodes uniform in sqrt(c); LUT_UNIFORM: in c; LUT_GRAZING_PL:
 * uniform in fresnel_q15_fast.h's 64-piece linear stand-in for sqrt(c), the
 * position of fresnel_lut_pl_u16_q15_fast. LUT_WARP2, LUT_WARP16: uniform in
 * the root-free warps c (2 - c) = 1 - (1 - c)^2 and (1 + c - (1 - c)^16)/2,
 * whose slope at c = 0 (2; 8.5) crowds the nodes toward grazing incidence
 * at the cost of a few multiplications instead of a square root; no runtime
 * function reads them: the report's LUT table measures them against sqrt(c)
 * at equal size. */
typedef enum lut_spacing { LUT_GRAZING, LUT_UNIFORM, LUT_GRAZING_PL, LUT_WARP2, LUT_WARP16 } lut_spacing;
/* The runtime's LUT forms: linear interpolation of the curve (fresnel_lut),
 * of its residual from Schlick(F0) (fresnel_lut_residual), Catmull-Rom of
 * the curve (fresnel_lut_cubic). */
typedef enum lut_form { LUT_PLAIN, LUT_RESIDUAL, LUT_CUBIC } lut_form;
/* Which eta, kappa of a material a model reads. */
typedef enum model_eta { ETA_FIT, ETA_GAUSS, ETA_POINT, ETA_SOURCES } model_eta;

#define MODEL_CATALOG(X)                                                                                               \
    X(schlick, .name = "schlick", .offered = MODEL_EVAL_SCENE, .params = "F0", .bound = FRESNEL_BOUND_SCHLICK,         \
      .q15_bound = FRESNEL_BOUND_SCHLICK_Q15, .f16_bound = FRESNEL_BOUND_SCHLICK_F16, .reads = MP_F0,                  \
      .glsl = "fresnel_schlick_rgb(@f0, c)", .cross_row = "schlick")                                                   \
    X(schlick_gen, .name = "schlick-gen", .offered = MODEL_EVAL, .params = "F0, --f90, --p",                           \
      .bound = FRESNEL_BOUND_SCHLICK_GEN, .q15_bound = FRESNEL_BOUND_SCHLICK_GEN_Q15,                                  \
      .f16_bound = FRESNEL_BOUND_SCHLICK_GEN_F16)                                                                      \
    X(lsk, .name = "lsk", .offered = MODEL_EVAL_SCENE, .params = "eta, kappa", .bound = FRESNEL_BOUND_LSK,             \
      .q15_bound = FRESNEL_BOUND_LSK_Q15, .f16_bound = FRESNEL_BOUND_LSK_F16, .reads = MP_ETA_FIT,                     \
      .q15_reads = MQ_LSK, .glsl = "fresnel_lsk_rgb(@eta, @kappa, c)", .cross_row = "lsk")                             \
    X(lsk_comp, .name = "lsk-comp", .offered = MODEL_EVAL_SCENE, .params = "eta, kappa, LSK a and alpha",              \
      .bound = FRESNEL_BOUND_LSK_COMP, .q15_bound = FRESNEL_BOUND_LSK_COMP_Q15,                                        \
      .f16_bound = FRESNEL_BOUND_LSK_COMP_F16, .reads = MP_ETA_FIT | MP_LSK, .q15_reads = MQ_LSK_COMP,                 \
      .glsl = "fresnel_lsk_comp_rgb(@eta, @kappa, @lsk_a, @lsk_alpha, c)", .cross_row = "lsk-comp")                    \
    X(f82, .name = "f82", .offered = MODEL_EVAL_SCENE, .params = "F0, F82", .bound = FRESNEL_BOUND_F82,                \
      .q15_bound = FRESNEL_BOUND_F82_Q15, .f16_bound = FRESNEL_BOUND_F82_F16, .reads = MP_F0 | MP_F82,                 \
      .glsl = "fresnel_f82_rgb(@f0, @f82, c)", .cross_row = "f82")                                                     \
    X(gulbrandsen, .name = "gulbrandsen", .offered = MODEL_EVAL_SCENE, .params = "r = F0, edge tint g",                \
      .bound = FRESNEL_BOUND_GULBRANDSEN, .q15_bound = FRESNEL_BOUND_GULBRANDSEN_Q15,                                  \
      .f16_bound = FRESNEL_BOUND_GULBRANDSEN_F16, .reads = MP_GULB,                                                    \
      .glsl = "fresnel_gulbrandsen_rgb(@gulbrandsen_r, @gulbrandsen_g, c)", .cross_row = "gulbrandsen")                \
    X(cook_torrance, .name = "cook-torrance", .offered = MODEL_EVAL_SCENE,                                             \
      .params = "F0 and the same eta, kappa as representative IOR", .bound = FRESNEL_BOUND_COOK_TORRANCE,              \
      .q15_bound = FRESNEL_BOUND_COOK_TORRANCE_Q15, .f16_bound = FRESNEL_BOUND_COOK_TORRANCE_F16,                      \
      .reads = MP_F0 | MP_CT, .q15_reads = MQ_CT, .glsl = "fresnel_cook_torrance_rgb(@f0, @ct_eta, @ct_kappa, c)",     \
      .cross_row = "cook-torrance")                                                                                    \
    X(exact, .name = "exact", .offered = MODEL_EVAL_SCENE | MODEL_EXACT,                                               \
      .params = "eta, kappa (dielectric form when kappa = 0)", .bound = FRESNEL_BOUND_CONDUCTOR,                       \
      .q15_bound = FRESNEL_BOUND_CONDUCTOR_Q15, .f16_bound = FRESNEL_BOUND_CONDUCTOR_F16, .reads = MP_ETA_FIT,         \
      .q15_reads = MQ_IOR, .glsl = "fresnel_conductor_rgb(@eta, @kappa, c)", .cross_row = "exact-conductor")           \
    /* Metzgar's Gaussian-window and point-sampled eta, kappa: scene models                                            \
     * only; as functions of eta, kappa they are the exact conductor. */                                               \
    X(exact_gaussian, .name = "exact-gaussian", .offered = MODEL_SCENE | MODEL_EXACT,                                  \
      .params = "eta', kappa' in a Gaussian window", .bound = FRESNEL_BOUND_CONDUCTOR,                                 \
      .q15_bound = FRESNEL_BOUND_CONDUCTOR_Q15, .f16_bound = FRESNEL_BOUND_CONDUCTOR_F16, .reads = MP_ETA_GAUSS,       \
      .q15_reads = MQ_IOR_GAUSS, .eta = ETA_GAUSS, .glsl = "fresnel_conductor_rgb(@eta_gaussian, @kappa_gaussian, c)", \
      .cross_row = "exact-conductor")                                                                                  \
    X(exact_point, .name = "exact-point", .offered = MODEL_SCENE | MODEL_EXACT, .params = "eta, kappa point-sampled",  \
      .bound = FRESNEL_BOUND_CONDUCTOR, .q15_bound = FRESNEL_BOUND_CONDUCTOR_Q15,                                      \
      .f16_bound = FRESNEL_BOUND_CONDUCTOR_F16, .reads = MP_ETA_POINT, .q15_reads = MQ_IOR_POINT, .eta = ETA_POINT,    \
      .glsl = "fresnel_conductor_rgb(@eta_point, @kappa_point, c)", .cross_row = "exact-conductor")                    \
    X(exact_conductor, .name = "exact-conductor", .offered = MODEL_EVAL | MODEL_EXACT,                                 \
      .params = "eta, kappa (conductor form always)", .bound = FRESNEL_BOUND_CONDUCTOR,                                \
      .q15_bound = FRESNEL_BOUND_CONDUCTOR_Q15, .f16_bound = FRESNEL_BOUND_CONDUCTOR_F16)                              \
    X(exact_dielectric, .name = "exact-dielectric", .offered = MODEL_EVAL | MODEL_EXACT,                               \
      .params = "eta (kappa ignored)", .bound = FRESNEL_BOUND_DIELECTRIC, .q15_bound = FRESNEL_BOUND_DIELECTRIC_Q15,   \
      .f16_bound = FRESNEL_BOUND_DIELECTRIC_F16)                                                                       \
    X(approx_conductor, .name = "approx-conductor", .offered = MODEL_EVAL_SCENE, .params = "eta, kappa",               \
      .bound = FRESNEL_BOUND_APPROX_CONDUCTOR, .q15_bound = FRESNEL_BOUND_APPROX_CONDUCTOR_Q15,                        \
      .f16_bound = FRESNEL_BOUND_APPROX_CONDUCTOR_F16, .reads = MP_ETA_FIT, .q15_reads = MQ_NK,                        \
      .glsl = "fresnel_approx_conductor_rgb(@eta, @kappa, c)", .cross_row = "approx-conductor")                        \
    X(schlick_internal, .name = "schlick-internal", .offered = MODEL_EVAL,                                             \
      .params = "F0, eta (eta < 1: from inside the denser medium)", .bound = FRESNEL_BOUND_SCHLICK_INTERNAL,           \
      .q15_bound = FRESNEL_BOUND_SCHLICK_INTERNAL_Q15, .f16_bound = FRESNEL_BOUND_SCHLICK_INTERNAL_F16)                \
    /* A scene model only: a function of the film's index and thickness too. */                                       \
    X(thin_film, .name = "thin-film", .offered = MODEL_SCENE | MODEL_FILM,                                             \
      .params = "a film: its index (the scene's film key), its thickness (run time)", .bound = FRESNEL_BOUND_FILM,     \
      .q15_bound = FRESNEL_BOUND_FILM_Q15, .f16_bound = FRESNEL_BOUND_FILM_F16,                                        \
      .glsl = "FRESNEL_FILM_RGB_BODY(@thin_film, c, d_nm)", .cross_row = "thin-film")

/* The LUT forms: a family of scene models named by pattern, lutN (plain),
 * lutN-residual (from Schlick's F0) and lutN-cubic; one row per form and
 * node spacing, as the runtime has one function for each. */
#define LUT_CATALOG(X)                                                                                                 \
    X(lut, .name = "lutN", .offered = MODEL_SCENE | MODEL_LUT, .form = LUT_PLAIN, .cross_row = "lut u16")              \
    X(lut_linear, .name = "lutN", .offered = MODEL_SCENE | MODEL_LUT, .form = LUT_PLAIN, .uniform = 1,                 \
      .cross_row = "lut-linear u16")                                                                                   \
    X(lut_residual, .name = "lutN-residual", .offered = MODEL_SCENE | MODEL_LUT, .reads = MP_F0,                       \
      .form = LUT_RESIDUAL, .cross_row = "lut-residual s16")                                                           \
    X(lut_linear_residual, .name = "lutN-residual", .offered = MODEL_SCENE | MODEL_LUT, .reads = MP_F0,                \
      .form = LUT_RESIDUAL, .uniform = 1)                                                                              \
    X(lut_cubic, .name = "lutN-cubic", .offered = MODEL_SCENE | MODEL_LUT, .form = LUT_CUBIC,                          \
      .cross_row = "lut-cubic u16")

/* Every row's index: in model_catalog below, the registry's rows and every
 * evaluator table. */
#define MODEL_ROW_ID(id, ...) MODEL_ROW_##id,
typedef enum model_row_id { MODEL_CATALOG(MODEL_ROW_ID) LUT_CATALOG(MODEL_ROW_ID) MODEL_ROWS } model_row_id;
#undef MODEL_ROW_ID
/* The first LUT row: the rows before it are MODEL_CATALOG's. */
#define MODEL_ROW_FIRST_LUT MODEL_ROW_lut

/* The fields of a row, shared by model_catalog and the registry's rows
 * (model/registry.h), which add the evaluators. */
#define MODEL_FACTS                                                                                                    \
    const char *name;                                                                                                  \
    unsigned offered;                                                                                                  \
    const char *params;                                                                                                \
    float bound;                                                                                                       \
    double q15_bound, f16_bound;                                                                                       \
    unsigned reads, q15_reads;                                                                                         \
    model_eta eta;                                                                                                     \
    lut_form form;                                                                                                     \
    int uniform;                                                                                                       \
    const char *glsl;                                                                                                  \
    const char *cross_row;

typedef struct model_facts {
    MODEL_FACTS
} model_facts;

/* Every row as data, in model_row_id order (catalog.c). */
extern const model_facts model_catalog[MODEL_ROWS];

/* A scene model's name read, the one place a name is: the row of a
 * MODEL_SCENE name, or for "lutN", "lutN-residual", "lutN-cubic" (N in
 * lo..hi, no leading zeros) the row of its form at `spacing` with N in
 * *lut_n (0 for the others). -1 for any other string. */
int model_scene_id(const char *name, lut_spacing spacing, int lo, int hi, int *lut_n);
/* The LUT row of form `form` at `spacing` (a manifest may set its spacing
 * after its models). */
model_row_id model_lut_id(lut_form form, lut_spacing spacing);
/* The names of the MODEL_CATALOG rows offered as `offered` (every bit),
 * NULL-terminated (max includes the NULL); returns the count. */
int model_names(unsigned offered, const char **out, int max);

#endif
