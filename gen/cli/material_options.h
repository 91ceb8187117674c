/* Options shared by the commands that look at one material in one colour
 * space: --material ID or --nk FILE [--name ID] [--format NAME], --space
 * NAME, --gamut NAME, --sigma S, --n1 X, --data DIR. */
#ifndef FRESNEL_MATERIAL_OPTIONS_H
#define FRESNEL_MATERIAL_OPTIONS_H

#include "2_derive/derive.h"
#include "model/number_type.h"
#include "scene/scene.h"

typedef struct material_options {
    const char *material;
    const char *nk, *name; /* --nk FILE, --name ID */
    nk_format format;      /* --format NAME */
    char id[32];           /* --name, or the id material_id_from_path gives --nk's file */
    const char *space;
    const char *data;
    double sigma, n1;
    gamut_policy gamut; /* --gamut NAME */
    double film_n;      /* a thin film on the material (curve's --film); 0: none */
} material_options;

void material_options_init(material_options *o);
/* If opt is one of the shared options, consume val: returns 1, or
 * CLI_BAD_INPUT after a message for a bad value; returns 0 for any other
 * option. */
int material_option(const char *where, const char *opt, const char *val, material_options *o);
extern const char material_options_help[];
/* --film N:D, a film of index N in [1, 4] and thickness D in [0,
 * FRESNEL_FILM_D_MAX] nm: 0, or CLI_BAD_INPUT after a message. */
int film_option(const char *where, const char *val, double *n, double *d_nm);
/* --gamut's value: 0, or CLI_BAD_INPUT after a message. */
int gamut_option(const char *where, const char *val, gamut_policy *out);
/* --type's value, a number type this build evaluates (number_type_find):
 * 0, or CLI_BAD_INPUT after a message. */
int type_option(const char *where, const char *val, const number_type **out);
/* The shared options' names, NULL-terminated (with --help). */
extern const char *const material_option_names[];

/* The options as a scene of one material and no models (encode_scene
 * takes it through the stages; the caller adds its models with
 * scene_add_model): 0, or CLI_BAD_INPUT after a message for options that
 * name no material or two. */
int material_options_scene(const char *where, material_options *o, scene *sc);

#endif
