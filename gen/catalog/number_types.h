/* Every number type of the runtime, as data: its names and the facts a
 * generated header states about it, one row each. model/number_type.c adds
 * each row's evaluators and bounds (number_type.h); the manifest parser
 * (scene/scene.c) reads the names here.
 *
 *   X(ID, .name = ..., ...)   ID: TYPE_<ID>, the row's index
 *
 * .name, .alias  manifests' `types`, --type, the report's columns; a second
 *                name accepted for it, or none
 * .header        the runtime header a generated header includes for it
 * .what          for --help
 * .available     1 where this build has the type (binary16: the compiler's
 *                _Float16): only then does anything write or evaluate it
 * .lsb           the smallest positive cosine it represents
 * .floating      1 for a floating-point type (its constants are written as
 *                floating literals), 0 for Q1.15 codes
 * .suffix        what its generated identifiers end with
 * .film_struct, .film_layout, .film_call   the thin film's table type, its
 *                number layout and the call that reads it, for the header's
 *                comment */
#ifndef FRESNEL_CATALOG_NUMBER_TYPES_H
#define FRESNEL_CATALOG_NUMBER_TYPES_H

#include "fresnel_f16.h"

#define NUMBER_TYPE_CATALOG(X)                                                                                         \
    X(F32, .name = "f32", .header = "fresnel.h", .what = "binary32 (fresnel.h)", .available = 1, .lsb = 0x1p-149,     \
      .floating = 1, .suffix = "", .film_struct = "fresnel_film", .film_layout = "binary32",                          \
      .film_call = "fresnel_film_rgb(&table, c, d_nm)")                                                                \
    X(Q15, .name = "q15", .alias = "fixed", .header = "fresnel_q15.h", .what = "Q1.15 fixed point (fresnel_q15.h)",  \
      .available = 1, .lsb = 0x1p-15, .floating = 0, .suffix = "_q15", .film_struct = "fresnel_film_q15",             \
      .film_layout = "Q1.15 (layout: fresnel_film.h)", .film_call = "fresnel_film_q15_rgb(&table, c_q15, d_nm_q16)")  \
    X(F16, .name = "f16", .header = "fresnel_f16.h",                                                                   \
      .what = "binary16 (fresnel_f16.h; where the compiler has _Float16)", .available = FRESNEL_HAS_F16,              \
      .lsb = 0x1p-24, .floating = 1, .suffix = "_f16", .film_struct = "fresnel_film_f16", .film_layout = "binary16", \
      .film_call = "fresnel_film_f16_rgb(&table, c, d_nm)")

#define NUMBER_TYPE_ID(id, ...) TYPE_##id,
typedef enum number_type_id { NUMBER_TYPE_CATALOG(NUMBER_TYPE_ID) NUMBER_TYPES } number_type_id;
#undef NUMBER_TYPE_ID

/* The fields of a row, shared by the catalog's table and the registry's
 * (model/number_type.h). */
#define NUMBER_TYPE_FACTS                                                                                              \
    number_type_id id;                                                                                                 \
    const char *name, *alias, *header, *what;                                                                          \
    int available;                                                                                                     \
    double lsb;                                                                                                        \
    int floating;                                                                                                      \
    const char *suffix, *film_struct, *film_layout, *film_call;

typedef struct number_type_facts {
    NUMBER_TYPE_FACTS
} number_type_facts;

/* In number_type_id order; the available rows come first (binary16 is the
 * last), number_types_available of them. */
extern const number_type_facts number_type_catalog[NUMBER_TYPES];
extern const int number_types_available;
/* The id of the type named (or aliased) name, available or not; -1 if none. */
int number_type_parse(const char *name);
/* The available types' names, NULL-terminated (max includes the NULL), for
 * messages and --help. */
int number_type_names(const char **out, int max);

#endif
