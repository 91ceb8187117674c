/* `fresnel gen --glsl`: a scene's constants, tables and one evaluation
 * function per material and model as GLSL for ports/glsl/fresnel.glsl
 * (emit_glsl.c), and the packed RGBA8 LUT texture that GLSL ES 1.00 reads
 * instead of const arrays; `fresnel gen --hlsl`: the same as HLSL for
 * ports/hlsl/fresnel.hlsl and ports/msl/fresnel.metal (emit_braced.c). */
#ifndef FRESNEL_EMIT_GLSL_H
#define FRESNEL_EMIT_GLSL_H

#include <stdio.h>

#include "4_emit/emit.h"
#include "scene/scene.h"

/* Whether a shader back end (flag "--glsl" or "--hlsl", for messages) can
 * express the scene: its models (model_shader_lacks, gen/model/registry.c)
 * and identifiers. 0, or CLI_BAD_INPUT after printing "manifest:line: what
 * was expected". name is the scene's identifier part (fresnel_<name>_...). */
int emit_shader_check(const scene *sc, const char *manifest, const char *name, const char *flag);

/* Shared by the GLSL, HLSL and MSL back ends (emit_glsl.c, emit_braced.c), whose
 * ports are one source (ports/glsl/fresnel.glsl, which the HLSL port
 * includes), so the function and macro names are the same:
 *   emit_shader_float       a binary32 literal without suffix (emit_shader_const:
 *                           a constant's declaration)
 *   emit_shader_model_expr  an analytic model's return expression for the
 *                           material prefix (the registry row's)
 *   emit_shader_lut_array_call  FRESNEL_LUT_..._ARRAY_RGB(table, n, c) for
 *                           the table <prefix>_<table> */
void emit_shader_float(FILE *f, double v);
/* "/ * why * /", then decl prefix_name = ctor(v[0], ...) (ctor NULL: v[0]). */
void emit_shader_const(FILE *f, const char *decl, const char *ctor, const char *prefix, const char *name,
                       const double *v, int n, const char *why);
/* The opening comment's shared lines (scene, licence, colour space, window,
 * truth, models, materials), and the scene name upper-cased in guard. */
void emit_shader_opening(FILE *f, const emit_input *in, char guard[96]);
void emit_shader_model_expr(FILE *f, const char *prefix, const struct model *row);
void emit_shader_lut_array_call(FILE *f, const char *prefix, const char *table, int n, lut_form form,
                                lut_spacing spacing);

/* The thin film's table of material i (model e) as a float array of
 * FRESNEL_FILM_FLOATS values, the C struct's order: decl and the
 * initialiser's opening and closing ("const FRESNEL_HIGHP float", "float[1744](", ")"
 * for GLSL; "static const float", "{", "}" for HLSL); and the model
 * function's parameters after c (", FRESNEL_HIGHP float d_nm" for the film
 * in GLSL, "" for the other models). */
void emit_shader_film_table(FILE *f, const emit_input *in, int i, const char *prefix, const scene_entry *e,
                            const char *decl, const char *open, const char *close);
const char *emit_shader_more_params(const scene_entry *e, const char *float_type);

/* `fresnel gen --hlsl`: the scene as HLSL for ports/hlsl/fresnel.hlsl
 * (emit_braced.c). 0, or CLI_BAD_INPUT after a message. */
int emit_hlsl(FILE *f, const emit_input *in);
/* The same for ports/msl/fresnel.metal (constant float3, ...). */
int emit_msl(FILE *f, const emit_input *in);

/* `fresnel gen --wgsl`: the port translated from ports/glsl/fresnel.glsl
 * (wgsl_translate.c), then the scene, as one WGSL module (emit_wgsl.c). 0,
 * or CLI_BAD_INPUT after a message. */
int emit_wgsl(FILE *f, FILE *tables, const emit_input *in);
/* The same with `enable f16;` and the mediump-safe functions in f16
 * (`fresnel gen --wgsl-f16`). */
int emit_wgsl_f16(FILE *f, FILE *tables, const emit_input *in);
/* The translated port alone (make wgsl), in binary32 or with f16. 0, or -1
 * after a message. */
int emit_wgsl_port(FILE *f);
int emit_wgsl_f16_port(FILE *f);

/* The GLSL to f and, if tables is not NULL, the tables a program uploads
 * (the LUT texture, the film's tables) as a C header to tables. 0, or
 * CLI_BAD_INPUT after a message (the caller discards both). */
int emit_glsl(FILE *f, FILE *tables, const emit_input *in);
/* The film's tables alone as that C header (--wgsl --tables); flag names
 * the back end. 0, or CLI_BAD_INPUT (a scene without a film). */
int emit_shader_film_tables(FILE *f, const emit_input *in, const char *flag);
/* FRESNEL_FILM_RGB_READ(FRESNEL_<guard>_FILM_READ, row, c, d_nm): the film
 * function's body over the scene's film route, for material row. */
void emit_shader_film_read(FILE *f, const char *guard, int row);

/* A LUT node's 16-bit texel code: round(v 2^15) + 2^14 for v rounded to
 * binary32 first (what the C tables hold); -1 outside [-0.5, 1.5). */
long emit_glsl_node_code(double v);

#endif
