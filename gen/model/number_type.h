/* The number type registry: every number type of the runtime is one row of
 * number_types (number_type.c), holding its names, whether this build
 * evaluates it, its evaluators and its documented bounds, as the model
 * registry (registry.h) holds the models. Manifests (`types`), `fresnel
 * eval --type`, `curve --type`, `bench --type`, the report and `extremes`
 * read the rows; the header emitter writes each row's constants with the
 * back end indexed by its id (4_emit/emit_header.c: emit_types).
 *
 * Adding a number type: its runtime (include/, src/), its fields in the
 * encoder (3_encode/encode.h) and evaluators in the model rows
 * (registry.c), one row here and its emitter in 4_emit/. */
#ifndef FRESNEL_NUMBER_TYPE_H
#define FRESNEL_NUMBER_TYPE_H

#include "catalog/number_types.h"
#include "model/registry.h"

typedef struct number_type {
    NUMBER_TYPE_FACTS /* its catalog row (catalog/number_types.h says what each holds) */
    /* A scene model: the encoder's values (model_rgb) at cosine c, RGB. */
    void (*eval)(const model_rgb *q, double c, double rgb[3]);
    /* Its timed loop for row (bench.h's bench_batch over model_rgb). */
    model_batch (*batch)(const model *row);
    /* A function of eta, kappa, c (MODEL_EVAL row): 1 if the row has an
     * evaluator in this type; the parameters rounded to the type; the row
     * at c (converted to the type) on parameters so rounded; its documented
     * absolute bound. */
    int (*has)(const model *row);
    void (*round)(model_params *p);
    double (*eval_params)(const model *row, const model_params *p, double c);
    double (*bound)(const model *row);
} number_type;

/* In number_type_id order, the catalog's rows with their evaluators. */
extern const number_type number_types[NUMBER_TYPES];
/* The row named (or aliased) name, available or not; NULL if none. */
const number_type *number_type_find(const char *name);

#endif
