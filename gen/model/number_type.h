/* The number type registry: every number type of the runtime is one row of
 * number_types (number_type.c): its catalog row (catalog/number_types.h:
 * names, header, smallest cosine, identifier suffix, film facts) with its
 * evaluators, its documented bounds and how its runtime clamps parameters
 * and takes a cosine, as the model registry (registry.h) holds the models.
 * `fresnel eval --type`, `curve --type`, `bench --type`, the report and
 * `extremes` read the rows; the header emitter writes each type's constants
 * with the back end indexed by its id (4_emit/emit_header.c: emit_types).
 *
 * Adding a number type: its runtime (include/, src/), its fields in the
 * encoder (3_encode/encode.h) and evaluators in the model rows
 * (registry.c), its catalog row, its line of evaluators here and its
 * emitter in 4_emit/. */
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
    /* Where this type's runtime functions clamp their parameters: p (rounded
     * by `round`) clamped the same way, so that a reference on p sees what
     * the runtime evaluates; 1 if eta and kappa were inside the type's
     * domain, 0 if they were clamped. */
    int (*clamp)(model_params *p);
    /* A cosine x as this type takes it: 1 and the cosine the runtime sees in
     * *seen (rounded to the type; a Q1.15 code, saturated), or 0 where x has
     * no representation (NaN in Q1.15). */
    int (*cosine)(double x, double *seen);
    /* A MODEL_EVAL row at a cosine from `cosine`, on p rounded and clamped
     * (q: its Q1.15 constants, model_q15_from_params). */
    double (*at)(const model *row, const model_params *p, const model_q15 *q, double seen);
    /* fresnel_f82 (gulbrandsen 0) or fresnel_gulbrandsen (1) of this type
     * called directly on a, b, c given in binary32: 1, the result in *got and
     * in a, b, c the values it evaluated; 0 where the type cannot take them
     * (NaN in Q1.15). direct_ref: the double reference on those values. */
    int (*direct)(int gulbrandsen, float *a, float *b, float *c, double *got);
    double (*direct_ref)(int gulbrandsen, float a, float b, float c);
} number_type;

/* In number_type_id order, the catalog's rows with their evaluators. */
extern const number_type number_types[NUMBER_TYPES];
/* The row named (or aliased) name, available or not; NULL if none. */
const number_type *number_type_find(const char *name);

#endif
