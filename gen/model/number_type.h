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

#include "model/registry.h"

typedef enum number_type_id { TYPE_F32, TYPE_Q15, TYPE_F16, NUMBER_TYPES } number_type_id;

typedef struct number_type {
    number_type_id id;
    const char *name;   /* manifests' types, --type, the report's columns */
    const char *alias;  /* a second name accepted for it (q15: fixed), or NULL */
    const char *header; /* the runtime header a generated header includes for it */
    const char *what;   /* for --help */
    /* 1 where this build has the type (binary16: the compiler's _Float16):
     * only then does `fresnel gen` write its constants or anything evaluate it */
    int available;
    double lsb; /* the smallest positive cosine it represents */
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

/* In number_type_id order; the available rows come first (binary16 is the
 * last), number_types_available of them. */
extern const number_type number_types[NUMBER_TYPES];
extern const int number_types_available;
/* The row named (or aliased) name, available or not; NULL if none. */
const number_type *number_type_find(const char *name);
/* The available rows' names, NULL-terminated (max includes the NULL), for
 * messages and --help. */
int number_type_names(const char **out, int max);

#endif
