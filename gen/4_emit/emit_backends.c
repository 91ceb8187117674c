/* The back ends of `fresnel gen`, one row each (emit.h): the option that
 * chooses it, and the function that prints an encoded scene in it. A new
 * back end is its printer and one row here. */
#include <string.h>

#include "4_emit/emit.h"
#include "4_emit/emit_glsl.h"

static int print_c(FILE *f, FILE *tex, const emit_input *in)
{
    (void)tex;
    return emit_header(f, in);
}

static int print_hlsl(FILE *f, FILE *tex, const emit_input *in)
{
    (void)tex;
    return emit_hlsl(f, in);
}

static int print_msl(FILE *f, FILE *tex, const emit_input *in)
{
    (void)tex;
    return emit_msl(f, in);
}

static int print_wgsl(FILE *f, FILE *tables, const emit_input *in)
{
    return emit_wgsl(f, tables, in);
}

const emit_backend emit_backends[] = {
    {.option = NULL, .usage = "", .print = print_c,
     .help = "Without a back end's option: the C header for include/fresnel.h and the scene's\n"
             "number types (static const)."},
    {.option = "--glsl", .usage = "--glsl [--tables OUT_TABLES.h]", .shader = 1, .tables = 1, .print = emit_glsl,
     .help = "--glsl writes the same constants as GLSL instead (const vec3, float arrays)\n"
             "for use after ports/glsl/fresnel.glsl, with vec3 fresnel_<scene>_<material>_<model>_rgb(c)\n"
             "per material and model, in every dialect the port supports; lut_spacing\n"
             "grazing or uniform. --tables writes, as a C header, what a program uploads:\n"
             "the packed RGBA8 texture GLSL ES 1.00 reads the LUT models from (no const\n"
             "arrays there) and the thin film's tables (a texture, a uniform block or a\n"
             "storage buffer: ports/glsl/README.md)."},
    {.option = "--hlsl", .usage = "--hlsl", .shader = 1, .print = print_hlsl,
     .help = "--hlsl writes them as HLSL for ports/hlsl/fresnel.hlsl (static const float3,\n"
             "float arrays), with float3 fresnel_<scene>_<material>_<model>_rgb(float c)."},
    {.option = "--msl", .usage = "--msl", .shader = 1, .print = print_msl,
     .help = "--msl writes them as Metal Shading Language for ports/msl/fresnel.metal\n"
             "(constant float3, constant float arrays), with\n"
             "float3 fresnel_<scene>_<material>_<model>_rgb(float c)."},
    {.option = "--wgsl", .usage = "--wgsl [--tables OUT_TABLES.h]", .shader = 1, .tables = 1, .print = print_wgsl, .print_port = emit_wgsl_port,
     .help = "--wgsl writes one WebGPU (WGSL) module: the port's functions, translated from\n"
             "ports/glsl/fresnel.glsl, then the scene's const values and arrays, with\n"
             "fn fresnel_<scene>_<material>_<model>_rgb(c: f32) -> vec3f; the thin film\n"
             "reads a storage buffer, whose contents --tables writes. Without a SCENE:\n"
             "the translated port alone."},
    {.option = "--wgsl-f16", .usage = "--wgsl-f16 [--tables OUT_TABLES.h]", .shader = 1, .tables = 1,
     .print = emit_wgsl_f16, .print_port = emit_wgsl_f16_port,
     .help = "--wgsl-f16 writes the same module with `enable f16;` (a device with the\n"
             "shader-f16 feature) and the mediump-safe functions computing in f16, the\n"
             "others in f32 as in a mediump GLSL shader; the scene's functions take and\n"
             "return f32 as with --wgsl. Its bounds: ports/README.md."},
};
const int emit_backend_count = (int)(sizeof emit_backends / sizeof emit_backends[0]);

const emit_backend *emit_backend_find(const char *option)
{
    int i;
    for (i = 0; i < emit_backend_count; i++)
        if (option ? emit_backends[i].option && !strcmp(option, emit_backends[i].option) : !emit_backends[i].option)
            return &emit_backends[i];
    return NULL;
}
