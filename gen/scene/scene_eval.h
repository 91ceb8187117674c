/* Evaluate a scene model (scene.h vocabulary) for one material with the
 * binary32 runtime and the generator's derived parameters: what a program
 * compiled against the emitted header computes. Shared by `fresnel curve`,
 * the report and the tests. */
#ifndef FRESNEL_SCENE_EVAL_H
#define FRESNEL_SCENE_EVAL_H

#include "3_encode/encode.h"
#include "model/registry.h"

/* A model with its LUT, if it has one (encode_lut, rounded to float). */
typedef struct scene_model {
    char name[24];
    const model *def; /* its registry row */
    int lut_n; /* 0 for analytic models */
    lut_form form;
    lut_spacing spacing;
    float *table;    /* 3 * lut_n values, malloc'd; scene_model_free */
    double *table_d; /* the same before rounding to binary32 */
} scene_model;

/* Prepare model `name` for material p (s = its spectrum, for LUT nodes);
 * 0, or CLI_BAD_INPUT for an unknown name. */
int scene_model_prepare(const char *name, lut_spacing spacing, const spectrum *s, const gen_context *g,
                        const material_params *p, scene_model *m);
void scene_model_free(scene_model *m);
void scene_model_eval(const scene_model *m, const material_params *p, float c, float rgb[3]);
/* The same model in double precision (gen/model/reference.c) with the parameters
 * rounded to binary32 as the runtime sees them: the difference from
 * scene_model_eval is the runtime's rounding, not the model's error. */
void scene_model_eval_ref(const scene_model *m, const material_params *p, double c, double rgb[3]);

#endif
