/* `fresnel gen --glsl`: a scene's constants, tables and one evaluation
 * function per material and model as GLSL for ports/glsl/fresnel.glsl
 * (emit_glsl.c), and the packed RGBA8 LUT texture that GLSL ES 1.00 reads
 * instead of const arrays. */
#ifndef FRESNEL_EMIT_GLSL_H
#define FRESNEL_EMIT_GLSL_H

#include <stdio.h>

#include "4_emit/emit.h"
#include "scene/scene.h"

/* Whether the GLSL back end can express the scene: 0, or CLI_BAD_INPUT after
 * printing "manifest:line: what was expected". name is the scene's
 * identifier part (fresnel_<name>_...). */
int emit_glsl_check(const scene *sc, const char *manifest, const char *name);

/* The GLSL to f and, if tex is not NULL, the LUT texture as a C header to
 * tex. 0, or CLI_BAD_INPUT after a message (the caller discards both). */
int emit_glsl(FILE *f, FILE *tex, const emit_input *in);

/* A LUT node's 16-bit texel code: round(v 2^15) + 2^14 for v rounded to
 * binary32 first (what the C tables hold); -1 outside [-0.5, 1.5). */
long emit_glsl_node_code(double v);

#endif
