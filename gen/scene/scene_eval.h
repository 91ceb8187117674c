/* Evaluate a scene model (scene.h vocabulary) for one material with the
 * runtime on the values the encoder gives it (3_encode/encode.h), which are
 * the values `fresnel gen` writes: what a program compiled against the
 * emitted header computes. Shared by `fresnel curve`, `bench`, the report,
 * the viewer and the tests. */
#ifndef FRESNEL_SCENE_EVAL_H
#define FRESNEL_SCENE_EVAL_H

#include "3_encode/encode.h"
#include "model/registry.h"
#include "scene/scene.h"

/* A model with the material's constants and its LUT, if it has one. */
typedef struct scene_model {
    char name[SCENE_NAME_SIZE];
    const model *def;     /* its registry row */
    encoded_material mat; /* the material's constants in every number type */
    encoded_lut lut;      /* LUT rows: the table in every number type; lut.n 0 for the others */
    encoded_film *film;   /* the thin-film row: the material's film (malloc'd); NULL for the others */
} scene_model;

/* Prepare model e, with tables spaced `spacing`, for material p (s = its
 * spectrum, for LUT nodes and films): 0, or CLI_OOM after a message;
 * CLI_BAD_INPUT after a message for the thin-film row on a material
 * without a film (p->film_n 0) or one the model cannot fit. */
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
