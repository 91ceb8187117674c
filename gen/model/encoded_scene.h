/* A scene taken once through the pipeline: every material loaded and
 * resampled (1_spectral), its parameters derived and its renderer targets
 * fitted (2_derive), its constants, LUT nodes and film table fitted,
 * encoded in every number type and range-checked (3_encode). encode_scene
 * is the one place those stages run for a scene; `fresnel gen` prints what
 * it holds, and `report`, `curve`, `bench`, `params`, the viewer and the
 * tests evaluate the same values through the runtime (model/registry.h:
 * model_rgb), so every figure they print is a figure of the header `gen`
 * writes for the same scene.
 *
 * A command line that names one material and some models is a scene too
 * (scene_one in scene.h); so is a table the report builds from a list of
 * materials. */
#ifndef FRESNEL_ENCODED_SCENE_H
#define FRESNEL_ENCODED_SCENE_H

#include "2_derive/targets.h"
#include "3_encode/encode.h"
#include "model/registry.h"
#include "scene/scene.h"

/* One model of one material: its constants and its LUT, if it has one. */
typedef struct scene_model {
    char name[SCENE_NAME_SIZE];
    const model *def;          /* its registry row */
    encoded_material mat;      /* the material's constants in every number type */
    encoded_lut lut;           /* LUT rows: the table in every number type; lut.n 0 for the others */
    const encoded_film *film;  /* the thin-film row: the material's film; NULL for the others */
    encoded_film *film_owned;  /* the film scene_model_prepare fitted (freed with it); NULL in a scene */
} scene_model;

typedef struct encoded_scene {
    const scene *sc;
    const char *manifest;      /* messages name manifest:line; NULL: a command line's scene */
    const char *where;         /* messages of a command line's scene start with it */
    gen_context *g;
    int material_count;        /* sc->material_count */
    material_params *params;   /* [material] */
    spectrum **spectra;        /* [material]: the resampled spectrum (for more ground truth) */
    encoded_material *enc;     /* [material] */
    encoded_film *films;       /* [material]; NULL for a scene without the thin-film model */
    scene_model *models;       /* [material * sc->model_count + model] */
    target_fit *fits;          /* [material * sc->target_count + target]: the targets key's renderers */
    target_fit *film_fits;     /* the same under the scene's film, through each renderer's own film formula
                                * (t NULL: no film, or no film input) */
} encoded_scene;

/* Every stage for every material of sc (which must outlive out), with the
 * data pack of dir_option (NULL: the default). Every unknown material is
 * reported, then the first material that fails to load or derive, then the
 * first film outside the model's domain, then the first value no header
 * could hold (a derived parameter that is not a finite binary32, a LUT node
 * that is not finite or that no Q1.15 table holds). 0, or a CLI_* status
 * after a message (then nothing is held). */
int encode_scene(const scene *sc, const char *manifest, const char *where, const char *dir_option,
                 encoded_scene *out);
/* Releases what encode_scene holds (a zeroed one too). */
void encoded_scene_free(encoded_scene *es);
/* Model m of material i. */
const scene_model *encoded_scene_model(const encoded_scene *es, int material, int model);

/* One model of one material derived elsewhere (p, its spectrum s), for
 * tests of one stage: its constants, table and film, as encode_scene
 * encodes them. 0, or CLI_OOM after a message; CLI_BAD_INPUT after a
 * message for the thin-film row on a material without a film (p->film_n
 * 0) or one the model cannot fit. */
int scene_model_prepare(const scene_entry *e, lut_spacing spacing, const spectrum *s, const gen_context *g,
                        const material_params *p, scene_model *m);
/* The same for a model named on a command line (scene_entry_parse):
 * CLI_BAD_INPUT after a message for a name no scene model answers to. */
int scene_model_prepare_name(const char *name, lut_spacing spacing, const spectrum *s, const gen_context *g,
                             const material_params *p, scene_model *m);
void scene_model_free(scene_model *m);
/* What the registry row's evaluators read: pointers into m (the film's
 * thickness d_nm 0: the caller sets it). */
model_rgb scene_model_rgb(const scene_model *m);
/* The binary32 runtime at c. */
void scene_model_eval(const scene_model *m, float c, float rgb[3]);
/* The same model in double precision (gen/common/reference.c) on the
 * binary32 constants and nodes: the difference from scene_model_eval is
 * the runtime's rounding, not the model's error. */
void scene_model_eval_ref(const scene_model *m, double c, double rgb[3]);

#endif
