/* fresnel.hlsl -- the Fresnel models of include/fresnel.h as HLSL functions:
 * HLSL's spellings of the shader names, then the models themselves from
 * ports/glsl/fresnel.glsl, the one source of every shading-language port
 * (its file comment lists the names and holds the derivations, guards and
 * error analysis). Every function of the GLSL port but its texture forms,
 * with the same names (fresnel_schlick, fresnel_schlick_rgb, ...; float3 for
 * fresnel_rgb, float2 for fresnel_nk and fresnel_rg) and the same formulas.
 *
 * USE
 *   #include "fresnel.hlsl" (Shader Model 5 and later, DXC or
 *   glslangValidator's HLSL front end), which includes
 *   ../glsl/fresnel.glsl: keep the two files in that layout, or use the
 *   single file `make hlsl` writes to build/hlsl/fresnel.hlsl. Then the
 *   output of `fresnel gen SCENE --hlsl -o scene.hlsl`: static const float3
 *   constants and tables, and float3 fresnel_<scene>_<material>_<model>_rgb(float c).
 *   Tested on lavapipe through glslangValidator -D -e main -S comp and
 *   SPIR-V (tests/shader_ports/test_vulkan.sh; measured differences: ports/README.md).
 *
 * PRECISION
 *   The mediump-safe functions (fresnel_schlick, _schlick_gen, _f82, _lsk,
 *   _lsk_comp, _approx_conductor, _f0_from_ior, _f0_in_medium and their
 *   _rgb) compute in FRESNEL_MP, min16float by default: at least binary16 on
 *   hardware that has it (SPIR-V RelaxedPrecision through glslang; DXC
 *   -enable-16bit-types makes it a real half). Their guards keep every
 *   intermediate finite in binary16. The others (fresnel_conductor,
 *   _dielectric, _schlick_internal, _cook_torrance, _gulbrandsen*, the
 *   LUTs) need binary32 and compute in float, whatever FRESNEL_MP is.
 *   Define FRESNEL_MP as float before this file for float everywhere.
 */
#ifndef FRESNEL_HLSL
#define FRESNEL_HLSL 1

#ifndef FRESNEL_MP
#define FRESNEL_MP min16float
#endif
#define FRESNEL_MP_CAT(t, n) t##n
#define FRESNEL_MP_VEC(t, n) FRESNEL_MP_CAT(t, n)
#define FRESNEL_MP3 FRESNEL_MP_VEC(FRESNEL_MP, 3)
#define FRESNEL_HP float
#define FRESNEL_HP2 float2
#define FRESNEL_HP3 float3
#define FRESNEL_VEC2 float2
#define FRESNEL_VEC3 float3
#define FRESNEL_SATURATE(x) saturate(x)

#include "../glsl/fresnel.glsl"

#endif /* FRESNEL_HLSL */
