/* A LUT model's table for one material, as the encoded scene holds it, for
 * the C, Q15, GLSL and HLSL back ends (emit.h). */
#include "4_emit/emit.h"

const encoded_lut *emit_lut(const emit_input *in, int material, int model)
{
    return &encoded_scene_model(in->es, material, model)->lut;
}
