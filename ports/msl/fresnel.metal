/* fresnel.metal -- the Fresnel models of include/fresnel.h as Metal Shading
 * Language functions: MSL's spellings of the shader names, then the models
 * themselves from ports/glsl/fresnel.glsl, the one source of every
 * shading-language port (its file comment lists the names and holds the
 * derivations, guards and error analysis). Every function of the GLSL port
 * but its texture forms, with the same names (fresnel_schlick,
 * fresnel_schlick_rgb, ...; float3 for fresnel_rgb, float2 for fresnel_nk
 * and fresnel_rg) and the same formulas.
 *
 * USE
 *   #include "fresnel.metal" in a .metal file (MSL 2.0 and later), which
 *   includes ../glsl/fresnel.glsl: keep the two files in that layout, or use
 *   the single file `make msl` writes to build/msl/fresnel.metal. Then the
 *   output of `fresnel gen SCENE --msl -o scene.metal`: constant float3
 *   constants and tables, and float3 fresnel_<scene>_<material>_<model>_rgb(float c).
 *
 * PRECISION
 *   Metal has no relaxed precision: a function computes in the types it is
 *   written in. By default every function computes in float (binary32), the
 *   binary32 bounds apply. `#define FRESNEL_MSL_HALF 1` before this file makes
 *   the mediump-safe functions (fresnel_schlick, _schlick_gen, _f82, _lsk,
 *   _lsk_comp, _approx_conductor, _f0_from_ior, _f0_in_medium and their
 *   _rgb) compute in half (FRESNEL_MP): MSL then does each operation
 *   between two halves in half and each operation with a float literal in
 *   float, a mix whose error is measured on the host (ports/msl/README.md).
 *   They take and return half and half3, and each _rgb function and
 *   fresnel_cook_torrance_rgb also float3 (MSL converts no vector
 *   implicitly; the overloads below convert, then compute in half), so a
 *   scene of `fresnel gen --msl` compiles either way. The others
 *   (fresnel_conductor, _dielectric, _schlick_internal, _cook_torrance,
 *   _gulbrandsen*, the LUTs, the film) need binary32 and compute in float
 *   whatever FRESNEL_MP is.
 *
 * CHECKED WITHOUT APPLE'S COMPILER
 *   Apple's Metal compiler runs on macOS only. tests/shader_ports/test_msl.sh
 *   compiles this file and generated scenes as C++ with g++ and clang
 *   through a project-owned header that maps the part of metal_stdlib the
 *   port uses (tests/shader_ports/msl/metal_stdlib: half rounded to binary16
 *   after every operation) and compares every function with the C runtime.
 */
#ifndef FRESNEL_METAL
#define FRESNEL_METAL 1

#include <metal_stdlib>

#ifdef FRESNEL_MSL_HALF
#define FRESNEL_MP half
#else
#define FRESNEL_MP float
#endif
#define FRESNEL_MP_CAT(t, n) t##n
#define FRESNEL_MP_VEC(t, n) FRESNEL_MP_CAT(t, n)
#define FRESNEL_MP3 FRESNEL_MP_VEC(FRESNEL_MP, 3)
#define FRESNEL_HP float
#define FRESNEL_HP2 metal::float2
#define FRESNEL_HP3 metal::float3
#define FRESNEL_VEC2 metal::float2
#define FRESNEL_VEC3 metal::float3
#define FRESNEL_SATURATE(x) metal::saturate(x)

using namespace metal;

#include "../glsl/fresnel.glsl"

#ifdef FRESNEL_MSL_HALF
/* float3 in, float3 out, computed in half: conversions only. */
float3 fresnel_schlick_rgb(float3 f0, float c) { return float3(fresnel_schlick_rgb(half3(f0), c)); }
float3 fresnel_schlick_gen_rgb(float3 f0, float3 f90, float p, float c)
{
    return float3(fresnel_schlick_gen_rgb(half3(f0), half3(f90), p, c));
}
float3 fresnel_schlick_internal_rgb(float3 f0, float eta, float c)
{
    return fresnel_schlick_internal_rgb(half3(f0), eta, c);
}
float3 fresnel_lsk_rgb(float3 n, float3 k, float c) { return float3(fresnel_lsk_rgb(half3(n), half3(k), c)); }
float3 fresnel_lsk_comp_rgb(float3 n, float3 k, float3 a, float3 alpha, float c)
{
    return float3(fresnel_lsk_comp_rgb(half3(n), half3(k), half3(a), half3(alpha), c));
}
float3 fresnel_f82_rgb(float3 f0, float3 f82, float c) { return float3(fresnel_f82_rgb(half3(f0), half3(f82), c)); }
float3 fresnel_approx_conductor_rgb(float3 n, float3 k, float c)
{
    return float3(fresnel_approx_conductor_rgb(half3(n), half3(k), c));
}
float3 fresnel_cook_torrance_rgb(float3 f0, float eta, float kappa, float c)
{
    return fresnel_cook_torrance_rgb(half3(f0), eta, kappa, c);
}
#endif

#endif /* FRESNEL_METAL */
