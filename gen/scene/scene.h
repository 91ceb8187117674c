/* Scene manifests: which materials, models and number types one generated C
 * header contains (host only).
 *
 * FORMAT (the reference for users)
 *   UTF-8 or ASCII text, one `key = value` per line. Blank lines and lines
 *   whose first non-blank character is `#` are ignored; a `#` after a value
 *   starts a comment running to the end of the line (no value contains `#`).
 *   Whitespace around keys and values is trimmed; CRLF line ends and a UTF-8
 *   byte-order mark at the start of the file are accepted. Each key may appear
 *   at most once.
 *
 *   materials    Whitespace-separated material ids of the data pack, each
 *                matching [a-z0-9_]+ and at most 31 characters. Whether they
 *                exist in the data pack is the caller's check (report it at
 *                scene.material_line[i]).
 *   material ID = FILE
 *                a material from the user's own n,k file, named ID in the
 *                generated code; FILE (no '#' in it) is relative to the
 *                manifest's directory unless absolute, in any format
 *                `fresnel import` reads (1_spectral/import.c). One line per
 *                material; repeatable.
 *                At least one material in all, at most 64, each id once.
 *   models       required. Whitespace-separated, no duplicates, each the
 *                name of a MODEL_SCENE row of the model catalog
 *                (catalog/models.h: `fresnel gen --help` lists them) or a
 *                lookup table `lutN` / `lutN-residual` / `lutN-cubic` with N an
 *                integer in SCENE_LUT_MIN..SCENE_LUT_MAX written without
 *                leading zeros (lut16, lut32-residual, lut16-cubic). At most
 *                SCENE_MAX_MODELS entries; read into scene_entry values.
 *                lutN-cubic needs lut_spacing grazing (the runtime's cubic
 *                reads nodes uniform in sqrt(c)).
 *   space        optional, default srgb; one of colour_space_ids[] in
 *                spectral.h (srgb, display-p3, dci-p3, adobe-rgb, rec2020,
 *                acescg).
 *   sigma        optional, default 25; Gaussian window width in nm, a finite
 *                number in [0, 200] (0 = point sampling).
 *   n1           optional, default 1; real index of the incident medium, a
 *                finite number in [1, 4].
 *   types        optional, default f32; whitespace-separated names of the
 *                number type catalog (catalog/number_types.h: f32, q15 or
 *                its second name fixed, and f16 where the generator's
 *                compiler has _Float16), no duplicates.
 *   lut_spacing  optional, default grazing; one of lut_spacing_names[]:
 *                grazing (LUT nodes uniform in sqrt(cos theta), denser
 *                towards cos theta = 0), uniform (nodes uniform in cos theta) or
 *                grazing-pl (uniform in a 64-piece linear stand-in for
 *                sqrt(cos theta), read by fresnel_lut_pl_u16_q15_fast
 *                without a square root: types = q15 only, lutN with N <= 64).
 *   gamut        optional, default map; what the constants and tables hold
 *                where a material's colour leaves the space's gamut
 *                (2_derive/derive.h, OUT-OF-GAMUT POLICY): map (the nearest
 *                in-gamut colour in CIEDE2000), clip (per channel) or keep
 *                (values above 1 kept, for HDR and wide-gamut pipelines).
 *   f_avg        optional, default no; yes emits each material's
 *                hemispherical average F_avg = 2 int F(mu) mu dmu of the
 *                ground truth under the gamut policy, per channel, beside
 *                the models' constants (a scene that reads it only).
 *   film         the thin-film model's film (required with models = ...
 *                thin-film, refused without it): the real index of a
 *                transparent, non-dispersive film on every material, a finite
 *                number in [n1, 4] (a film less dense than the incident
 *                medium, total reflection inside it, is outside the model's
 *                domain: include/fresnel_film.h, DOMAIN). The film's results
 *                are held to [0, 1] per channel (the clip policy) whatever
 *                the gamut key: its truth varies with the thickness, which
 *                only the run time knows.
 *   film ID = N  the film on material ID only, overriding `film`; one line
 *                per material, ID a material of the scene; repeatable. With
 *                thin-film every material has a film by one key or the other.
 *   film_thickness
 *                optional, with thin-film only: LO HI, the thicknesses in nm
 *                the film takes, 0 <= LO <= HI <= 5000 (LO = HI: one
 *                thickness). The runtime takes the thickness at run time in
 *                any case (fresnel_film_rgb(table, c, d_nm), clamped to
 *                [0, FRESNEL_FILM_D_MAX]); the range is what the header's
 *                comment states, what `fresnel report` measures over and what
 *                the viewer's slider spans. Default: 0 5000, the whole range
 *                the runtime takes (thickness left to run time).
 *   targets      optional; whitespace-separated renderers, each once, from
 *                the targets of `fresnel params --for` (catalog/targets.h:
 *                openpbr materialx blender unreal gltf filament
 *                gulbrandsen). Each material's section of the header then
 *                opens with a comment giving the parameters each of them
 *                takes, fitted through its own Fresnel formula to the ground
 *                truth under the gamut policy, with the fit's CIEDE2000 and
 *                the naive conversion's: values to type into those
 *                renderers, which compile into nothing.
 *   name         optional; the scene's part of every C identifier in the
 *                header (fresnel_<name>_<material>_<constant>, include guard
 *                FRESNEL_SCENE_<NAME>_H): 1 to SCENE_PREFIX_SIZE - 1 of
 *                A-Z a-z 0-9 _, no '_' at either end and no "__" (C++
 *                reserves identifiers containing it). Without it the name
 *                comes from the manifest's file name (scene_name_from_path):
 *                a final ".scene" dropped, letters lower-cased, every run of
 *                other characters but a-z 0-9 one '_', none at either end,
 *                "scene" if nothing is left (2metals.scene -> 2metals,
 *                x.v1 -> x_v1). Two manifests whose file names map to the
 *                same name need the key to tell their headers apart.
 *
 *   Example:
 *       # metals for the demo scene
 *       materials = gold silver copper
 *       models    = schlick f82 lut32-residual
 *       space     = display-p3   # the panel's gamut
 *       sigma     = 20
 *
 * ERRORS
 *   Reported on stderr as "path:line: what was expected" (cli_error) and
 *   returned as CLI_BAD_INPUT: a line without `=`, an empty key or value, an
 *   unknown key, a key given twice (the message names both lines), a malformed
 *   or out-of-range number, an unknown space/model/type/spacing, a bad or
 *   repeated list entry, too many entries. A missing required key is reported
 *   at the file's last line (line 1 for an empty file), where it would be
 *   added. An unreadable file gives "path: cannot read: <reason>". */
#ifndef FRESNEL_SCENE_H
#define FRESNEL_SCENE_H

#include "1_spectral/spectral.h"
#include "catalog/choices.h"
#include "catalog/models.h"
#include "catalog/number_types.h"
#include "catalog/targets.h"

#define SCENE_MAX_MATERIALS 64
#define SCENE_ID_SIZE 32 /* material id, NUL included: matches material_info.id */
#define SCENE_MAX_MODELS 64
#define SCENE_NAME_SIZE 24 /* model, type, space or spacing name, NUL included */
#define SCENE_MAX_TARGETS 16
#define SCENE_LUT_MIN 4
#define SCENE_LUT_MAX MODEL_LUT_NODES_MAX
#define SCENE_PREFIX_SIZE 41 /* scene name, NUL included */
#define SCENE_PATH_SIZE 1024 /* a material file's path as resolved, NUL included */

/* The vocabulary is the catalog's (gen/catalog/: models, number types,
 * targets, LUT spacings, gamut policies) and colour_space_ids in
 * spectral.h; the parser needs nothing else. */
extern const char *const scene_f_avg_names[]; /* "no", "yes" */

/* One model of a manifest, read once by the parser (the catalog reads the
 * name: model_scene_id); nothing after the parser looks at the name but
 * to print it. */
typedef struct scene_entry {
    char name[SCENE_NAME_SIZE];  /* as written: "lut16-residual" */
    char ident[SCENE_NAME_SIZE]; /* the same as a C identifier part: "lut16_residual" */
    model_row_id row;            /* its catalog row (model_of: its registry row); a LUT's: its form's at the scene's spacing */
    int lut_n;                   /* a LUT's nodes per channel; 0 for the other models */
} scene_entry;
/* Read a model name (a manifest's or a command's) at spacing: 0, or -1 for a
 * name no scene model answers to (no message). */
int scene_entry_parse(const char *name, lut_spacing spacing, scene_entry *out);

typedef struct scene {
    /* Line of the file where each key was set; 0 where the default applies. */
    int materials_line, models_line, space_line, sigma_line, n1_line, types_line,
        lut_spacing_line, name_line, gamut_line, f_avg_line, targets_line, film_line, film_thickness_line;
    char name[SCENE_PREFIX_SIZE]; /* the name key; "" when not given */

    int material_count; /* in the order the file names them */
    char materials[SCENE_MAX_MATERIALS][SCENE_ID_SIZE];
    char material_file[SCENE_MAX_MATERIALS][SCENE_PATH_SIZE]; /* "" for the data pack's */
    nk_format material_format[SCENE_MAX_MATERIALS];           /* a user's file's format (a manifest's: auto) */
    int material_line[SCENE_MAX_MATERIALS];
    int model_count;
    scene_entry models[SCENE_MAX_MODELS];
    int type_count;
    number_type_id types[NUMBER_TYPES]; /* in the file's order */
    char space[SCENE_NAME_SIZE]; /* a colour_space_ids entry */
    lut_spacing spacing;
    gamut_policy gamut;
    int f_avg; /* 1: emit each material's F_avg */
    int target_count; /* other renderers (catalog/targets.h), in the file's order */
    target_id targets[SCENE_MAX_TARGETS];
    double sigma; /* nm */
    double n1;
    /* The thin-film model's film: the film key (0 when not given), the
     * `film ID = N` lines in the file's order, the thickness range (nm). */
    double film_n;
    int film_count;
    char film_material[SCENE_MAX_MATERIALS][SCENE_ID_SIZE];
    double film_material_n[SCENE_MAX_MATERIALS];
    int film_material_line[SCENE_MAX_MATERIALS];
    double film_d_lo, film_d_hi;
} scene;

/* Read and validate a manifest. Returns 0, or CLI_BAD_INPUT after printing
 * one message; *out is filled on success and unspecified on error. Lists
 * keep the file's order. */
int scene_load(const char *path, scene *out);

/* A scene with every key at its default and nothing in it: what a command
 * line that names one material and some models fills in (--material or
 * --nk, --models, --space, ...), and the report's tables of other
 * materials. */
void scene_defaults(scene *out);
/* Append the model named name (scene_entry_parse, at out->spacing): 0, or
 * CLI_BAD_INPUT after a message (where) for a name no scene model answers
 * to or a full list. */
int scene_add_model(scene *out, const char *name, const char *where);

/* 1 if name is a valid value of the name key, else 0. */
int scene_name_ok(const char *name);
/* The scene name derived from a manifest's path, as FORMAT describes. */
void scene_name_from_path(const char *path, char out[SCENE_PREFIX_SIZE]);

/* The index of material i's film (its own line, else the film key); 0
 * where the scene has no film. */
double scene_film_n(const scene *sc, int i);

/* 1 if the loaded scene names this model (as written) / number type, else 0. */
int scene_has_model(const scene *sc, const char *model);
int scene_has_type(const scene *sc, number_type_id type);
/* What the scene's models read: the union of their catalog rows' MP_* bits
 * (q15 0) or MQ_* bits (q15 1). */
unsigned scene_reads(const scene *sc, int q15);

#endif
