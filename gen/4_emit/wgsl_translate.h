/* The WGSL port, translated from the one shader source
 * (ports/glsl/fresnel.glsl, embedded in the tool) rather than written a
 * second time: a small C preprocessor runs the source with WGSL's spellings
 * of the shader names (FRESNEL_MP = float, ..., FRESNEL_SATURATE(x) =
 * saturate(x)), so the GLSL-only parts drop out, and the remaining GLSL
 * subset (function definitions, local declarations, if/else, return,
 * assignments, expressions with ?:) is rewritten in WGSL syntax. A scene's
 * functions (`fresnel gen --wgsl`) are GLSL text of the same form, run
 * through the same preprocessor state (the port's macros) and translator. */
#ifndef FRESNEL_WGSL_TRANSLATE_H
#define FRESNEL_WGSL_TRANSLATE_H

#include <stdio.h>

typedef struct wgsl_tr wgsl_tr;

/* A translator whose macro table holds WGSL's spellings: binary32, or with
 * f16 the mediump-safe functions (FRESNEL_MP) in f16, the module needing
 * `enable f16;`. NULL: no memory. */
wgsl_tr *wgsl_tr_new(int f16);

/* Declares a module-scope value printed outside the translator (a scene's
 * const, the film's storage buffer) for the conversions of the functions
 * that use it: its GLSL type (float, vec3), an array of it when array.
 * 0, or -1 after a message. */
int wgsl_tr_declare(wgsl_tr *t, const char *name, const char *glsl_type, int array);
void wgsl_tr_free(wgsl_tr *t);

/* Preprocess glsl (macros defined by earlier calls stay defined) and print
 * its function definitions as WGSL to f. 0, or -1 after printing
 * "wgsl: what was expected" to stderr (a construct outside the subset). */
int wgsl_tr_text(wgsl_tr *t, const char *glsl, FILE *f);

/* The GLSL port's source as the tool carries it (NUL-terminated). */
const char *wgsl_glsl_port(void);

#endif
