/* Stage 4: printing an encoded scene (model/encoded_scene.h) as a C header
 * (binary32: emit_header.c, Q15: emit_q15.c, binary16: emit_f16.c), GLSL
 * (emit_glsl.c) or HLSL (emit_hlsl.c). The back ends print what the encoded
 * scene holds; none fits or encodes a value. */
#ifndef FRESNEL_EMIT_H
#define FRESNEL_EMIT_H

#include <stdio.h>

#include "3_encode/encode.h"
#include "model/encoded_scene.h"
#include "scene/scene.h"

typedef struct emit_input {
    const encoded_scene *es;   /* what every back end prints */
    const scene *sc;
    const char *name;          /* C identifier part: fresnel_<name>_<material>_<param> */
    const char *manifest_name; /* for the leading comment */
    const char *manifest_path; /* for errors: path:line */
    const gen_context *g;
    const material_params *params; /* one per scene material, in order */
    spectrum *const *spectra;      /* the same */
    const encoded_material *enc;   /* the same, encoded: every constant the back ends write */
    const encoded_film *films;     /* the same: each material's film; NULL for a scene without thin-film */
    const target_fit *fits;        /* [material * sc->target_count + target]: the targets key's fits */
    const target_fit *film_fits;   /* the same under the film (encoded_scene.h); t NULL where none */
} emit_input;

/* The back ends of `fresnel gen` (emit_backends.c): the C header, GLSL for
 * ports/glsl/fresnel.glsl, HLSL for ports/hlsl/fresnel.hlsl. */
typedef struct emit_backend {
    const char *option; /* the gen option that chooses it; NULL: the C header, the default */
    const char *usage;  /* its part of `fresnel gen`'s usage line */
    const char *help;   /* its paragraph of `fresnel gen --help` */
    int shader;         /* 1: a shader port's source, which emit_shader_check admits a scene to */
    int tables;         /* 1: it also writes the tables a program uploads (--tables) */
    /* Print the scene to f (and its tables to tables, if not NULL): 0, or
     * CLI_BAD_INPUT after a message (the caller discards the output). */
    int (*print)(FILE *f, FILE *tables, const emit_input *in);
    /* Without a manifest: print the port alone (a back end whose port is
     * generated rather than a file of the tree); NULL: a manifest needed. */
    int (*print_port)(FILE *f);
} emit_backend;
extern const emit_backend emit_backends[];
extern const int emit_backend_count;
/* The back end chosen by option (NULL: the default); NULL if none. */
const emit_backend *emit_backend_find(const char *option);

int emit_header(FILE *f, const emit_input *in); /* 0 or CLI_BAD_INPUT */
/* A manifest loaded and encoded (encode_scene, emit_scene.c): what the
 * back ends read. emit_load returns 0 or a CLI_* status after a message
 * (then nothing is held); a shader back end also checks that it can
 * express the scene. emit_loaded_free releases it. */
typedef struct emit_loaded {
    scene *sc;
    encoded_scene es;
    char name[SCENE_PREFIX_SIZE];
    emit_input in;
} emit_loaded;
int emit_load(const char *manifest, const char *dir_option, const emit_backend *backend, emit_loaded *l);
void emit_loaded_free(emit_loaded *l);
/* `fresnel gen`: load and encode the manifest's scene, print it with the
 * back end (and, if tex_path, its LUT texture), each written to a
 * temporary beside its target and renamed over it only on success
 * (dir_option NULL: the default data directory). 0 or a CLI_* status after
 * a message. */
int emit_scene(const char *manifest, const char *out_path, const char *tex_path, const char *dir_option,
               const emit_backend *backend);
void emit_licence_comment(FILE *f, const emit_input *in); /* the data's terms, material by material */
/* The opening comment's list of materials and where each came from: a data
 * pack file, or a user's file by name, format, size and SHA-256. */
void emit_material_list(FILE *f, const emit_input *in);
/* The opening comment's ground-truth line, with the scene's gamut policy. */
void emit_truth_comment(FILE *f, const scene *sc);
/* One material's floating-point constants for the scene's models, through
 * the back end's syntax for an RGB triple and a scalar: the binary32 ones
 * (the encoder's), or those of one number type seen as doubles. */
typedef void (*emit_rgb_fn)(FILE *f, const char *prefix, const char *name, const double v[3], const char *why);
typedef void (*emit_float_fn)(FILE *f, const char *prefix, const char *name, double v, const char *why);
void emit_material_params(FILE *f, const scene *sc, const encoded_material *e, const char *prefix, emit_rgb_fn rgb,
                          emit_float_fn flt);
#define EMIT_FLOATS_MEMBER(field, count, group, constant, row, why, q15, q15_why) double field PARAM_ARRAY_##count;
typedef struct emit_floats {
    DERIVED_PARAMETERS(EMIT_FLOATS_MEMBER) /* catalog/parameters.h */
} emit_floats;
void emit_float_params(FILE *f, const scene *sc, const emit_floats *v, const char *prefix, emit_rgb_fn rgb,
                       emit_float_fn flt);
/* A C float literal that reads back to the same binary32 value (9
 * significant digits, a '.' or an exponent, the 'f' suffix). */
void emit_c_float(FILE *f, double v);
/* Model m's table for material i in every number type (n 0 for a model
 * without one). */
const encoded_lut *emit_lut(const emit_input *in, int material, int model);

/* Material i's heading comment and, for a scene with the targets key, the
 * comment holding other renderers' parameters (emit_targets.c). */
void emit_material_heading(FILE *f, const emit_input *in, int material);

/* The C header's back end of each number type: one material's constants and
 * tables; prefix is fresnel_<scene>_<material>. 0, or CLI_BAD_INPUT after a
 * message. emit_header.c: binary32; emit_q15.c: Q1.15; emit_f16.c:
 * binary16. */
typedef int (*emit_type_fn)(FILE *f, const emit_input *in, int material, const char *prefix);
int emit_f32_material(FILE *f, const emit_input *in, int material, const char *prefix);
int emit_q15_material(FILE *f, const emit_input *in, int material, const char *prefix);
int emit_f16_material(FILE *f, const emit_input *in, int material, const char *prefix);
/* The Q1.15 prepared structs' initializers (fresnel_q15.h LAYOUT;
 * positional, in declaration order), as the Q1.15 back end writes them
 * (emit_q15.c). */
void emit_q15_qf(FILE *f, fresnel_qf q);
void emit_q15_ior(FILE *f, fresnel_ior_prep_q15 q);
void emit_q15_nk(FILE *f, fresnel_nk_prep_q15 q);
void emit_q15_lsk(FILE *f, fresnel_lsk_prep_q15 q);
void emit_q15_conductor_fast(FILE *f, fresnel_conductor_prep_q15_fast q);
/* Material i's thin-film table in number type `type` (emit_film.c), where
 * the scene has the thin-film model: 0. */
int emit_film(FILE *f, const emit_input *in, int material, const char *prefix, number_type_id type);
/* The initializer of one film table in number type `type` ("{...};" and a
 * newline), as emit_film writes it; encode_film says whether the type holds
 * it (encoded_film: q15_ok, f32_finite, f16_finite). */
void emit_film_initializer(FILE *f, const encoded_film *film, number_type_id type);

#endif
