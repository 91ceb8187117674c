/* `fresnel gen --glsl` (see emit_glsl.h). One GLSL file serves every dialect
 * of ports/glsl/fresnel.glsl: LUT tables are const arrays where
 * FRESNEL_LUT_ARRAYS is 1 (GLSL ES 3.00+, desktop 1.30+) and strips of a
 * packed RGBA8 texture where it is 0 (GLSL ES 1.00: no array constructors,
 * constant-index-only arrays in fragment shaders, 16 uniform vectors
 * guaranteed, float textures optional). Output depends only on the manifest
 * and the data. */
#include "4_emit/emit_glsl.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"

#define WHERE "fresnel gen"
#define FILM_FLOATS ((int)(sizeof(fresnel_film) / sizeof(float))) /* FRESNEL_FILM_FLOATS of ports/glsl/fresnel.glsl */

/* A binary32 literal that reads back to the same float, without suffix
 * (GLSL ES 1.00 has none; HLSL reads it as float): 9 significant digits,
 * always a '.' or exponent. */
void emit_shader_float(FILE *f, double v)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%.9g", (double)(float)v);
    fputs(buf, f);
    if (!strpbrk(buf, ".e"))
        fputs(".0", f);
}

void emit_shader_const(FILE *f, const char *decl, const char *ctor, const char *prefix, const char *name,
                       const double *v, int n, const char *why)
{
    int i;
    fprintf(f, "/* %s */\n%s %s_%s = %s%s", why, decl, prefix, name, ctor ? ctor : "", ctor ? "(" : "");
    for (i = 0; i < n; i++) {
        if (i)
            fputs(", ", f);
        emit_shader_float(f, v[i]);
    }
    fputs(ctor ? ");\n" : ";\n", f);
}

/* Highp constants: the highp functions (conductor, Gulbrandsen, ...) then
 * get binary32 parameters even in a mediump-default shader. */
static void emit_rgb(FILE *f, const char *prefix, const char *name, const double v[3], const char *why)
{
    emit_shader_const(f, "const FRESNEL_HIGHP vec3", "vec3", prefix, name, v, 3, why);
}

static void emit_float(FILE *f, const char *prefix, const char *name, double v, const char *why)
{
    emit_shader_const(f, "const FRESNEL_HIGHP float", NULL, prefix, name, &v, 1, why);
}

/* GLSL reserves identifiers containing "__"; fresnel_<scene>_<material>_...
 * has one when a part starts or ends with '_' or contains "__". */
static int glsl_part_ok(const char *s)
{
    size_t n = strlen(s);
    return n > 0 && s[0] != '_' && s[n - 1] != '_' && !strstr(s, "__");
}

int emit_shader_check(const scene *sc, const char *manifest, const char *name, const char *flag)
{
    char where[1100];
    int i;
    for (i = 0; i < sc->model_count; i++) {
        const char *lacks = model_shader_lacks(model_of(sc->models[i].row), sc->spacing);
        if (!lacks)
            continue;
        if (sc->spacing == LUT_GRAZING_PL) {
            snprintf(where, sizeof where, "%s:%d", manifest, sc->lut_spacing_line ? sc->lut_spacing_line : 1);
            return cli_error(where, "expected lut_spacing grazing or uniform with %s: %s", flag, lacks);
        }
        snprintf(where, sizeof where, "%s:%d", manifest, sc->models_line);
        return cli_error(where, "expected models the shader ports have with %s, got '%s': %s", flag,
                         sc->models[i].name, lacks);
    }
    if (!glsl_part_ok(name))
        return cli_error(manifest,
                         "expected a file name giving a scene name without leading, trailing or double '_' "
                         "with %s (GLSL and HLSL reserve identifiers containing \"__\"), got '%s'", flag, name);
    snprintf(where, sizeof where, "%s:%d", manifest, sc->materials_line);
    for (i = 0; i < sc->material_count; i++)
        if (!glsl_part_ok(sc->materials[i]))
            return cli_error(where,
                             "expected material ids without leading, trailing or double '_' with %s "
                             "(GLSL and HLSL reserve identifiers containing \"__\"), got '%s'", flag,
                             sc->materials[i]);
    return 0;
}

long emit_glsl_node_code(double v)
{
    double q = floor((double)(float)v * 32768.0 + 0.5) + 16384.0;
    return q >= 0.0 && q <= 65535.0 ? (long)q : -1;
}

/* One LUT of one material and its place in the texture. */
typedef struct glsl_lut {
    int material, model, n;
    lut_form form;
    char name[32];
    const float *t; /* 3n nodes: the encoded scene's binary32 table */
    int x0, row; /* first texel and row in the texture */
} glsl_lut;

typedef struct glsl_layout {
    glsl_lut *luts;
    int count;
    int block, width, height; /* texels per strip slot, texture size */
} glsl_layout;

static int pow2_at_least(int v)
{
    int p = 1;
    while (p < v)
        p *= 2;
    return p;
}

static void layout_free(glsl_layout *l)
{
    free(l->luts);
    l->luts = NULL;
    l->count = 0;
}

/* Every LUT of the scene, material-major, one per strip slot; slots of
 * `block` texels (a power of two >= 3 n_max) in columns of `height` rows,
 * the number of columns the smallest power of two that keeps the texture no
 * taller than wide. Power-of-two sizes: no NPOT restrictions in ES 2.0. */
static int layout_build(const emit_input *in, glsl_layout *l)
{
    const scene *sc = in->sc;
    int i, m, nmax = 0, cols = 1, rows;
    memset(l, 0, sizeof *l);
    l->luts = calloc((size_t)sc->material_count * (size_t)sc->model_count + 1, sizeof *l->luts);
    if (!l->luts)
        return cli_error(WHERE, "out of memory");
    for (i = 0; i < sc->material_count; i++)
        for (m = 0; m < sc->model_count; m++) {
            glsl_lut *u = &l->luts[l->count];
            const scene_entry *e = &sc->models[m];
            if (!e->lut_n)
                continue;
            u->material = i;
            u->model = m;
            u->n = e->lut_n;
            u->form = model_of(e->row)->form;
            snprintf(u->name, sizeof u->name, "%s", e->ident);
            u->t = emit_lut(in, i, m)->f32;
            l->count++;
            if (u->n > nmax)
                nmax = u->n;
        }
    if (l->count == 0)
        return 0;
    l->block = pow2_at_least(3 * nmax);
    while ((rows = (l->count + cols - 1) / cols) > cols * l->block)
        cols *= 2;
    l->height = pow2_at_least(rows);
    l->width = cols * l->block;
    for (i = 0; i < l->count; i++) {
        l->luts[i].x0 = (i / l->height) * l->block;
        l->luts[i].row = i % l->height;
    }
    return 0;
}

static const glsl_lut *layout_find(const glsl_layout *l, int material, int model)
{
    int i;
    for (i = 0; i < l->count; i++)
        if (l->luts[i].material == material && l->luts[i].model == model)
            return &l->luts[i];
    return NULL;
}

static void emit_lut_data(FILE *f, const char *scene_prefix, const char *prefix, const glsl_lut *u,
                          const glsl_layout *l, lut_spacing spacing)
{
    int i;
    fprintf(f, "/* %s: %d nodes per channel (red, then green, then blue), uniform in %s,\n"
               " * fitted to the ground truth through %s interpolation. */\n",
            u->name, u->n, spacing == LUT_UNIFORM ? "cos theta" : "sqrt(cos theta), from grazing to normal",
            u->form == LUT_CUBIC ? "Catmull-Rom" : "linear");
    fprintf(f, "#if FRESNEL_LUT_ARRAYS\nconst FRESNEL_HIGHP float %s_%s[%d] = float[%d](", prefix, u->name, 3 * u->n,
            3 * u->n);
    for (i = 0; i < 3 * u->n; i++) {
        fputs(i % 6 == 0 ? "\n    " : " ", f);
        emit_shader_float(f, u->t[i]);
        if (i + 1 < 3 * u->n)
            fputc(',', f);
    }
    fprintf(f, "\n);\n#else\n/* strip in %s_lut_texture: texels %d..%d of row %d */\nconst FRESNEL_HIGHP vec3 %s_%s_strip = vec3(",
            scene_prefix, u->x0, u->x0 + 3 * u->n - 1, u->row, prefix, u->name);
    emit_shader_float(f, (u->x0 + 0.5) / l->width);
    fputs(", ", f);
    emit_shader_float(f, (u->row + 0.5) / l->height);
    fputs(", ", f);
    emit_shader_float(f, 1.0 / l->width);
    fputs(");\n#endif\n", f);
}

void emit_shader_lut_array_call(FILE *f, const char *prefix, const char *table, int n, lut_form form,
                                lut_spacing spacing)
{
    fprintf(f, "FRESNEL_LUT_%s%sARRAY_RGB(%s%s%s_%s, %d, c)", spacing == LUT_UNIFORM ? "LINEAR_" : "",
            form == LUT_CUBIC ? "CUBIC_" : (form == LUT_RESIDUAL ? "RESIDUAL_" : ""), form == LUT_RESIDUAL ? prefix : "",
            form == LUT_RESIDUAL ? "_f0, " : "", prefix, table, n);
}

void emit_shader_model_expr(FILE *f, const char *prefix, const struct model *row)
{
    const char *t;
    for (t = row->glsl; *t; t++)
        if (*t == '@')
            fprintf(f, "%s_", prefix);
        else
            fputc(*t, f);
}

typedef char film_table_floats[sizeof(fresnel_film) % sizeof(float) == 0 ? 1 : -1];

void emit_shader_film_table(FILE *f, const emit_input *in, int i, const char *prefix, const scene_entry *e,
                            const char *decl, const char *open, const char *close)
{
    const float *v = &in->films[i].f32.freq[0];
    int k;
    fprintf(f, "/* %s: a film of index %g on %s, the binary32 table of fresnel_film.h as %d floats in its\n"
               " * order (fresnel_film_rgb in ports/glsl/fresnel.glsl). */\n%s %s_%s[%d] = %s",
            e->name, in->films[i].n_film, in->params[i].info.id, FILM_FLOATS, decl, prefix, e->ident, FILM_FLOATS,
            open);
    for (k = 0; k < FILM_FLOATS; k++) {
        fputs(k % 6 == 0 ? "\n    " : " ", f);
        emit_shader_float(f, v[k]);
        if (k + 1 < FILM_FLOATS)
            fputc(',', f);
    }
    fprintf(f, "\n%s;\n", close);
}

const char *emit_shader_more_params(const scene_entry *e, const char *float_type)
{
    static char buf[64];
    if (!(model_of(e->row)->offered & MODEL_FILM))
        return "";
    snprintf(buf, sizeof buf, ", %s d_nm", float_type);
    return buf;
}

/* vec3 <prefix>_<model>_rgb(c): the model for this material, as
 * gen/model/encoded_scene.c evaluates it with the C runtime. */
static void emit_model_function(FILE *f, const char *scene_prefix, const char *prefix, const scene_entry *e,
                                const glsl_lut *u, lut_spacing spacing, const char *guard, int row)
{
    fprintf(f, "vec3 %s_%s_rgb(FRESNEL_HIGHP float c%s)\n{\n", prefix, e->ident,
            emit_shader_more_params(e, "FRESNEL_HIGHP float"));
    if (u) {
        const char *kind = u->form == LUT_CUBIC ? "cubic_" : (u->form == LUT_RESIDUAL ? "residual_" : "");
        const char *lin = spacing == LUT_UNIFORM ? "linear_" : "";
        char f0[192] = "";
        if (u->form == LUT_RESIDUAL)
            snprintf(f0, sizeof f0, "%s_f0, ", prefix);
        fputs("#if FRESNEL_LUT_ARRAYS\n    return ", f);
        emit_shader_lut_array_call(f, prefix, u->name, u->n, u->form, spacing);
        fputs(";\n#else\n", f);
        fprintf(f, "    return fresnel_lut_%s%spacked_rgb(%s%s_lut_texture, %s_%s_strip, %d.0, c);\n#endif\n}\n", lin,
                kind, f0, scene_prefix, prefix, u->name, u->n);
        return;
    }
    if (model_of(e->row)->offered & MODEL_FILM) { /* a body, over the scene's film route */
        fputs("    ", f);
        emit_shader_film_read(f, guard, row);
        fputs("\n}\n", f);
        return;
    }
    fputs("    return ", f);
    emit_shader_model_expr(f, prefix, model_of(e->row));
    fputs(";\n}\n", f);
}

static int scene_has_film(const scene *sc)
{
    int m;
    for (m = 0; m < sc->model_count; m++)
        if (model_of(sc->models[m].row)->offered & MODEL_FILM)
            return 1;
    return 0;
}

/* The packed RGBA8 LUT texture's bytes (fresnel_lut_packed_rgb): 0, or
 * CLI_BAD_INPUT after a message. */
static int emit_lut_texture(FILE *f, const emit_input *in, const glsl_layout *l, const char *guard)
{
    unsigned char *px = calloc((size_t)l->width * (size_t)l->height * 4, 1);
    size_t i, total = (size_t)l->width * (size_t)l->height * 4;
    int k, ch, j;
    if (!px)
        return cli_error(WHERE, "out of memory");
    for (k = 0; k < l->count; k++) {
        const glsl_lut *u = &l->luts[k];
        for (ch = 0; ch < 3; ch++)
            for (j = 0; j < u->n; j++) {
                long a = emit_glsl_node_code(u->t[ch * u->n + j]);
                long b = emit_glsl_node_code(u->t[ch * u->n + (j + 1 < u->n ? j + 1 : j)]);
                unsigned char *t = px + 4 * ((size_t)u->row * (size_t)l->width + (size_t)(u->x0 + ch * u->n + j));
                if (a < 0 || b < 0) {
                    free(px);
                    return cli_error(WHERE,
                                     "%s %s: a LUT node (%g) outside the packed texture's range [-0.5, 1.5)",
                                     in->params[u->material].info.id, in->sc->models[u->model].name,
                                     a < 0 ? u->t[ch * u->n + j] : u->t[ch * u->n + j + 1]);
                }
                t[0] = (unsigned char)(a >> 8);
                t[1] = (unsigned char)(a & 255);
                t[2] = (unsigned char)(b >> 8);
                t[3] = (unsigned char)(b & 255);
            }
    }
    fprintf(f, "/* The LUT texture, for the GLSL where FRESNEL_LUT_ARRAYS is 0 (GLSL ES 1.00, desktop\n"
               " * 1.10 and 1.20). Upload as the sampler uniform fresnel_%s_lut_texture:\n"
               " *   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, FRESNEL_%s_LUT_TEXTURE_WIDTH,\n"
               " *                FRESNEL_%s_LUT_TEXTURE_HEIGHT, 0, GL_RGBA, GL_UNSIGNED_BYTE, fresnel_%s_lut_texture);\n"
               " * with GL_NEAREST filters, GL_CLAMP_TO_EDGE and no mipmaps (rows bottom to top, as GL\n"
               " * reads them). Texel layout and node code: fresnel_lut_packed_rgb in\n"
               " * ports/glsl/fresnel.glsl. */\n",
            in->name, guard, guard, in->name);
    fprintf(f, "#define FRESNEL_%s_LUT_TEXTURE_WIDTH %d\n#define FRESNEL_%s_LUT_TEXTURE_HEIGHT %d\n", guard, l->width,
            guard, l->height);
    fprintf(f, "static const unsigned char fresnel_%s_lut_texture[%d * %d * 4] FRESNEL_GEN_UNUSED = {", in->name,
            l->height, l->width);
    for (i = 0; i < total; i++)
        fprintf(f, "%s%u%s", i % 16 == 0 ? "\n    " : " ", (unsigned)px[i], i + 1 < total ? "," : "");
    fprintf(f, "\n};\n\n");
    free(px);
    return 0;
}

/* The thin film's tables, one row of FILM_FLOATS binary32 values per
 * material, for every route of emit_film_routes. */
static void emit_film_tables(FILE *f, const emit_input *in, const char *guard)
{
    int i, k, rows = in->sc->material_count;
    fprintf(f, "/* The thin film's tables: row i (the scene's material i, named before it) is its\n"
               " * fresnel_film (include/fresnel_film.h) as %d binary32 values in the struct's order.\n"
               " * Feed them to the GPU by the route the shader chose (ports/glsl/README.md):\n"
               " *   texture (default): glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, FRESNEL_%s_FILM_TEXELS,\n"
               " *     FRESNEL_%s_FILM_ROWS, 0, GL_RGBA, GL_FLOAT, fresnel_%s_film_table), GL_NEAREST\n"
               " *     filters, no mipmaps, to the sampler uniform fresnel_%s_film_texture;\n"
               " *   FRESNEL_FILM_UNIFORM: these bytes as the uniform block fresnel_%s_film_block (std140);\n"
               " *   FRESNEL_FILM_STORAGE, WGSL: these bytes as the storage buffer fresnel_%s_film (std430). */\n",
            FILM_FLOATS, guard, guard, in->name, in->name, in->name, in->name);
    fprintf(f, "#define FRESNEL_%s_FILM_ROWS %d\n#define FRESNEL_%s_FILM_TEXELS %d\n", guard, rows, guard,
            FILM_FLOATS / 4);
    fprintf(f, "static const float fresnel_%s_film_table[%d * %d] FRESNEL_GEN_UNUSED = {", in->name, rows,
            FILM_FLOATS);
    for (i = 0; i < rows; i++) {
        const float *v = &in->films[i].f32.freq[0];
        fprintf(f, "\n    /* %s */", in->params[i].info.id);
        for (k = 0; k < FILM_FLOATS; k++) {
            fputs(k % 6 == 0 ? "\n    " : " ", f);
            emit_c_float(f, v[k]);
            if (k + 1 < FILM_FLOATS || i + 1 < rows)
                fputc(',', f);
        }
    }
    fprintf(f, "\n};\n\n");
}

static int write_tables(FILE *f, const emit_input *in, const glsl_layout *l, const char *flag)
{
    char guard[96];
    int i, status = 0, film = scene_has_film(in->sc);
    if (!film && (!l || l->count == 0))
        return cli_error(WHERE, "--tables: scene %s has %s, so no tables to write", in->manifest_name,
                         l ? "no LUT model and no thin film" : "no thin film");
    for (i = 0; in->name[i] && i < 95; i++)
        guard[i] = (char)toupper((unsigned char)in->name[i]);
    guard[i] = '\0';
    fprintf(f, "/* Tables of the Fresnel scene \"%s\" for its %s (fresnel gen %s %s --tables from %s),\n"
               " * as a C header a program uploads to the GPU. Do not edit: regenerate. */\n",
            in->name, flag, GEN_VERSION, flag, in->manifest_name);
    fprintf(f, "#ifndef FRESNEL_SCENE_%s_TABLES_H\n#define FRESNEL_SCENE_%s_TABLES_H\n\n", guard, guard);
    fprintf(f, "#ifndef FRESNEL_GEN_UNUSED\n#if defined(__GNUC__)\n#define FRESNEL_GEN_UNUSED __attribute__((unused))\n"
               "#else\n#define FRESNEL_GEN_UNUSED\n#endif\n#endif\n\n");
    if (l && l->count)
        status = emit_lut_texture(f, in, l, guard);
    if (film && !status)
        emit_film_tables(f, in, guard);
    fprintf(f, "#endif\n");
    return status;
}

int emit_shader_film_tables(FILE *f, const emit_input *in, const char *flag)
{
    return write_tables(f, in, NULL, flag);
}

/* The routes by which a scene's GLSL reads the film's tables (one row per
 * material), chosen by the includer's macros, each defining the reader
 * FRESNEL_<SCENE>_FILM_READ(row, i) for FRESNEL_FILM_RGB_READ. */
static void emit_film_routes(FILE *f, const emit_input *in, const char *guard)
{
    int rows = in->sc->material_count, bytes = rows * FILM_FLOATS * 4;
    const char *s = in->name;
    fprintf(f, "/* The thin film: its tables (one row of %d floats per material, written by --tables)\n"
               " * reach the shader by one of three routes, chosen before this file:\n"
               " *   the texture route (default but in Vulkan; every GLSL dialect, WebGL 1 and 2): the\n"
               " *     sampler uniform fresnel_%s_film_texture, RGBA32F (GLES 2, WebGL 1: RGBA, FLOAT by\n"
               " *     OES_texture_float), %d x %d texels, GL_NEAREST;\n"
               " *   #define FRESNEL_FILM_UNIFORM: the uniform block fresnel_%s_film_block (std140,\n"
               " *     %d bytes; GLES 3.0 guarantees 16384 per block);\n"
               " *   #define FRESNEL_FILM_STORAGE (the default in Vulkan): the read-only storage buffer\n"
               " *     fresnel_%s_film_buffer (std430; GLSL ES 3.10, desktop 4.30, Vulkan).\n"
               " * The storage buffer sits at binding FRESNEL_FILM_BINDING (default 0); in Vulkan both\n"
               " * blocks do, in set FRESNEL_FILM_SET (default 0). In GL, bind the uniform block with\n"
               " * glUniformBlockBinding (GLSL ES 3.00 has no binding qualifier). */\n",
            FILM_FLOATS, s, FILM_FLOATS / 4, rows, s, bytes, s);
    fprintf(f, "#if FRESNEL_FILM\n#ifndef FRESNEL_FILM_BINDING\n#define FRESNEL_FILM_BINDING 0\n#endif\n"
               "#if defined(VULKAN)\n#ifndef FRESNEL_FILM_SET\n#define FRESNEL_FILM_SET 0\n#endif\n"
               "#define FRESNEL_I_FILM_LAYOUT(packing) layout(packing, set = FRESNEL_FILM_SET, binding = "
               "FRESNEL_FILM_BINDING)\n"
               "#else\n#define FRESNEL_I_FILM_LAYOUT(packing) layout(packing, binding = FRESNEL_FILM_BINDING)\n"
               "#endif\n");
    fprintf(f, "#if defined(FRESNEL_FILM_STORAGE) || (defined(VULKAN) && !defined(FRESNEL_FILM_UNIFORM))\n"
               "FRESNEL_I_FILM_LAYOUT(std430) readonly buffer fresnel_%s_film_buffer\n{\n"
               "    FRESNEL_HIGHP float fresnel_%s_film[];\n};\n"
               "#define FRESNEL_%s_FILM_READ(row, i) fresnel_%s_film[(row) * %d + (i)]\n",
            s, s, guard, s, FILM_FLOATS);
    fputs("#elif defined(FRESNEL_FILM_UNIFORM)\n", f);
    if (bytes > 16384)
        fprintf(f, "#error \"scene %s: %d film tables are %d bytes, over the 16384 of a uniform block GLES 3.0 "
                   "guarantees: use the texture or storage route\"\n",
                s, rows, bytes);
    fprintf(f, "#if defined(VULKAN)\nFRESNEL_I_FILM_LAYOUT(std140)\n#else\nlayout(std140)\n#endif\n"
               "uniform fresnel_%s_film_block\n{\n"
               "    FRESNEL_HIGHP vec4 fresnel_%s_film[%d];\n};\n"
               "#define FRESNEL_%s_FILM_READ(row, i) fresnel_%s_film[(row) * %d + (i) / 4][(i) - 4 * ((i) / 4)]\n",
            s, s, rows * FILM_FLOATS / 4, guard, s, FILM_FLOATS / 4);
    fprintf(f, "#else\nuniform FRESNEL_HIGHP sampler2D fresnel_%s_film_texture;\n#if __VERSION__ >= 130\n"
               "#define FRESNEL_%s_FILM_READ(row, i) fresnel_film_texel(fresnel_%s_film_texture, row, i)\n#else\n"
               "#define FRESNEL_%s_FILM_READ(row, i) fresnel_film_texel2d(fresnel_%s_film_texture, (float(row) + 0.5) "
               "* (1.0 / %d.0), i)\n#endif\n#endif\n#endif\n",
            s, guard, s, guard, s, rows);
}

void emit_shader_film_read(FILE *f, const char *guard, int row)
{
    fprintf(f, "FRESNEL_FILM_RGB_READ(FRESNEL_%s_FILM_READ, %d, c, d_nm)", guard, row);
}

void emit_shader_opening(FILE *f, const emit_input *in, char guard[96])
{
    const scene *sc = in->sc;
    const gen_context *g = in->g;
    int i, m;
    for (i = 0; in->name[i] && i < 95; i++)
        guard[i] = (char)toupper((unsigned char)in->name[i]);
    guard[i] = '\0';
    fprintf(f, "/* Fresnel scene \"%s\", generated by fresnel gen %s from %s. Do not edit: regenerate.\n", in->name,
            GEN_VERSION, in->manifest_name);
    emit_licence_comment(f, in);
    fprintf(f, " * Colour space %s (white x %.4f y %.4f); dominant wavelengths R %.2f G %.2f B %.2f nm;\n", sc->space,
            g->cs.white[0], g->cs.white[1], g->nm[0], g->nm[1], g->nm[2]);
    fprintf(f, " * Gaussian window sigma %g nm; incident medium n1 %g (eta, kappa below are relative to it).\n",
            sc->sigma, sc->n1);
    emit_truth_comment(f, sc);
    fprintf(f, " * Models:");
    for (m = 0; m < sc->model_count; m++)
        fprintf(f, " %s", sc->models[m].name);
    fprintf(f, ".\n");
    emit_material_list(f, in);
}

int emit_glsl(FILE *f, FILE *tables, const emit_input *in)
{
    const scene *sc = in->sc;
    lut_spacing spacing = sc->spacing;
    glsl_layout l;
    char guard[96], scene_prefix[96];
    int i, m, status;
    snprintf(scene_prefix, sizeof scene_prefix, "fresnel_%s", in->name);
    if ((status = layout_build(in, &l)))
        return status;

    emit_shader_opening(f, in, guard);
    fprintf(f, " * GLSL for every dialect of ports/glsl/fresnel.glsl (GLSL ES 1.00, ES 3.00, desktop 3.30 and\n"
               " * later): paste after it. Each material and model has vec3 %s_<material>_<model>_rgb(c)\n"
               " * (lsk-comp -> lsk_comp), computing what the C runtime computes from the C header of the\n"
               " * same manifest.\n",
            scene_prefix);
    if (l.count)
        fprintf(f, " * LUT models: const float arrays where FRESNEL_LUT_ARRAYS is 1 (GLSL ES 3.00+, desktop 1.30+);\n"
                   " * where it is 0 (GLSL ES 1.00, desktop 1.10 and 1.20) a strip of the packed RGBA8 texture\n"
                   " * in the sampler uniform %s_lut_texture, %d x %d texels, 16 bits per node\n"
                   " * (quantisation <= 2^-16), whose\n"
                   " * bytes `fresnel gen %s --glsl -o OUT.glsl --tables OUT_TABLES.h` writes as a C array;\n"
                   " * in fragment shaders (ES 2.0 promises no vertex texture units).\n",
                scene_prefix, l.width, l.height, in->manifest_name);
    fprintf(f, " */\n#ifndef FRESNEL_SCENE_%s_GLSL\n#define FRESNEL_SCENE_%s_GLSL\n", guard, guard);
    fprintf(f, "#if !defined(FRESNEL_GLSL) || !defined(FRESNEL_LUT_ARRAYS)\n"
               "#error \"paste ports/glsl/fresnel.glsl (with FRESNEL_LUT_ARRAYS) before this file\"\n#endif\n");
    if (l.count)
        fprintf(f, "#if !FRESNEL_LUT_ARRAYS\nuniform FRESNEL_HIGHP sampler2D %s_lut_texture;\n#endif\n", scene_prefix);
    if (scene_has_film(sc))
        emit_film_routes(f, in, guard);

    for (i = 0; i < sc->material_count; i++) {
        const material_params *p = &in->params[i];
        char prefix[160];
        snprintf(prefix, sizeof prefix, "%s_%s", scene_prefix, p->info.id);
        emit_material_heading(f, in, i);
        emit_material_params(f, sc, &in->enc[i], prefix, emit_rgb, emit_float);
        for (m = 0; m < sc->model_count; m++) {
            const glsl_lut *u = layout_find(&l, i, m);
            if (u)
                emit_lut_data(f, scene_prefix, prefix, u, &l, spacing);
        }
        for (m = 0; m < sc->model_count; m++) {
            const scene_entry *e = &sc->models[m];
            if (model_of(e->row)->offered & MODEL_FILM) /* highp only */
                fputs("#if FRESNEL_FILM\n", f);
            emit_model_function(f, scene_prefix, prefix, e, layout_find(&l, i, m), spacing, guard, i);
            if (model_of(e->row)->offered & MODEL_FILM)
                fputs("#endif\n", f);
        }
    }
    fprintf(f, "\n#endif\n");
    status = tables ? write_tables(tables, in, &l, "--glsl") : 0;
    layout_free(&l);
    return status;
}
