/* fresnel.glsl -- the Fresnel models of include/fresnel.h as shader
 * functions: the GLSL port, and the one source of the models for every
 * shading language (ports/hlsl/fresnel.hlsl and ports/msl/fresnel.metal are
 * HLSL's and Metal's spellings, then this file).
 *
 * GLSL: ONE SOURCE, THREE DIALECTS
 *   GLSL ES 1.00 (WebGL 1, GLES 2), GLSL ES 3.00 (WebGL 2, GLES 3) and
 *   desktop GLSL 3.30, and every later version of each (also desktop 1.10
 *   to 1.50: tests/shader_ports/glsl_port_osmesa.c compiles it in every version Mesa lists). Paste or include this file
 *   after the #version line and a default float precision, for example the
 *   two lines of prelude_es100.glsl, prelude_es300.glsl or prelude_330.glsl:
 *       #version 300 es
 *       precision mediump float;
 *       <this file>
 *   The only dialect differences (texture2D/texture, where a const array can
 *   live) are handled below with __VERSION__; everything else is written in
 *   the common subset: float literals everywhere (ES has no implicit int to
 *   float conversion), no bit operations, no loops, no recursion.
 *
 * OTHER LANGUAGES: SPELLINGS, NOT COPIES
 *   The functions use only what GLSL shares with HLSL (the C preprocessor,
 *   overloading, swizzles, float(n) and int(x) conversions, clamp, min, max,
 *   floor, sqrt, pow) and these names for what the languages spell
 *   differently:
 *       FRESNEL_MP, FRESNEL_MP3     the mediump-safe functions' values: GLSL
 *                                   float, vec3 in the default precision;
 *                                   HLSL min16float, min16float3; MSL float
 *                                   or half, float3 or half3
 *       FRESNEL_HP, _HP2, _HP3      binary32 values: GLSL FRESNEL_HIGHP
 *                                   float, vec2, vec3; HLSL, MSL float, ...
 *       FRESNEL_VEC2, FRESNEL_VEC3  vectors of the default float and their
 *                                   constructors: vec2, vec3; float2, float3
 *       FRESNEL_SATURATE(x)         clamp(x, 0.0, 1.0); HLSL, MSL saturate(x)
 *   and `float` for a result in the default float (GLSL: the default
 *   precision; HLSL: float). A language's prelude defines them and then
 *   includes this file (ports/hlsl/fresnel.hlsl, ports/msl/fresnel.metal);
 *   without one they are GLSL's, below. WGSL has no preprocessor and no
 *   overloading: `fresnel gen --wgsl` runs this file through its own
 *   preprocessor with WGSL's spellings and rewrites the result
 *   (gen/4_emit/wgsl_translate.c), so each helper has one name per
 *   argument type (fresnel_i_unit, fresnel_i_unit_rgb) and a vector is
 *   clamped between vectors; with FRESNEL_MP as f16 (--wgsl-f16) the
 *   translator writes GLSL's implicit precision conversions out. A value converts between FRESNEL_MP3
 *   and FRESNEL_VEC3 only through a constructor (MSL converts no vector
 *   implicitly), and a conditional's two arms have one type. The texture forms of the tables (sampler2D) are GLSL's
 *   alone. Below, "mediump" means FRESNEL_MP and "highp" FRESNEL_HP.
 *
 * NAMES
 *   The C names: fresnel_schlick, fresnel_schlick_rgb (vec3), ...; vec3
 *   (HLSL float3) stands for fresnel_rgb, vec2 (float2) for fresnel_nk and
 *   fresnel_rg. Internal helpers are fresnel_i_*, as in the C runtime;
 *   macros FRESNEL_* (GLSL, like C++, reserves names with "__").
 *
 * CONVENTIONS (as in fresnel.h)
 *   c is cos(theta) in the incident medium, clamped to [0, 1] BEFORE 1 - c is
 *   formed: after normalisation on a GPU dot(n, v) is often 1.00001, and
 *   pow(1 - c, 5) of the negative base is NaN (LearnOpenGL#217, bevy#8926).
 *   Nothing here calls pow() with a base that can be negative.
 *   eta, kappa relative to the incident medium; reflectances and results in
 *   [0, 1]. Non-finite inputs: GLSL does not define NaN behaviour. On
 *   llvmpipe clamp() takes NaN c to 0 and +-Inf to the nearer end, so every
 *   function gives what the C runtime gives (tests/shader_ports/glsl_port_osmesa.c prints it);
 *   other GPUs may differ, so do not rely on NaN being cleaned up here.
 *
 * PRECISION: WHICH FUNCTIONS RUN IN MEDIUMP, WHICH NEED HIGHP
 *   Functions declared with FRESNEL_MP (no precision qualifier) run in the
 *   default float precision of the including shader (mediump on a mobile
 *   fragment shader); those declared with FRESNEL_HP compute in highp
 *   whatever the default is, and only their result is converted to it.
 *   mediump is IEEE binary16 on current mobile GPUs (and on Mesa's llvmpipe):
 *   11 significant bits, largest finite 65504, smallest normal 2^-14.
 *
 *   mediump-safe (errors and guards in each function's comment):
 *     fresnel_schlick, _schlick_gen, _f82, _lsk, _lsk_comp,
 *     _approx_conductor, _f0_from_ior, _f0_in_medium (and their _rgb)
 *   highp (FRESNEL_HP, that is FRESNEL_HIGHP float):
 *     fresnel_conductor, _dielectric, _schlick_internal: eta^2 + c^2 - 1
 *       cancels near the critical angle, and the conductor's
 *       A = eta^2 - kappa^2 - sin^2 squares again: A^2 reaches kappa^4, which
 *       overflows binary16 for kappa > 16 (a fitted gold red has kappa 19)
 *       and loses all digits of u v = eta kappa long before.
 *     fresnel_cook_torrance: uses the conductor's transmittance.
 *     fresnel_gulbrandsen, _nk, _rg: 1 - r for r near 1 (silver, aluminium:
 *       r 0.91-0.99) keeps 1-5 bits in binary16, and nmax = (1+sqrt r)^2/(1-r)
 *       reaches 4e4 at the clamp r = 0.9999 (binary16 rounds 0.9999 to 1, so
 *       1 - r = 0 and nmax = Inf).
 *     the LUT position (index and fraction): x (n - 1) for n up to 256 nodes
 *       would keep 2-3 bits of the fraction in binary16; table fetches use a
 *       highp sampler (a lowp/mediump sampler may return binary16 texels).
 *   ES 1.00 fragment shaders have highp only where GL_FRAGMENT_PRECISION_HIGH
 *   is defined; elsewhere FRESNEL_HIGHP falls back to mediump, and the highp
 *   functions then carry the errors measured under "mediump forced" in
 *   ports/glsl/README.md. Define FRESNEL_HIGHP yourself before this file to
 *   override (the tests define it as mediump to measure exactly that).
 *
 * EXACTNESS ON A GPU
 *   The C runtime forms eta^2 + c^2 - 1 from exact squares (Dekker, or fmaf)
 *   summed with TwoSum, so it keeps full precision at the critical angle.
 *   GLSL before 4.00 / ES 3.20 has neither fma() nor `precise`, and GPU
 *   compilers may contract a*b + c into an fma, or simplify (a + b) - a to b
 *   and move constants across additions in non-precise code (Mesa's NIR does
 *   all three), which silently breaks TwoSum and Veltkamp splitting. This port
 *   splits eta and c at the fixed point 2^-12 with floor() instead, so that
 *   every partial result of the cancelling part is a multiple of 2^-24 below
 *   1: exact in binary32 whatever the compiler contracts or reorders
 *   (fresnel_i_eta2_minus_sin2). It needs binary32 highp (mobile GPUs'
 *   highp is binary32) and floor(); nothing from a later GLSL version.
 *   The rest is the C runtime's arithmetic, operation for operation, except
 *   where GLSL has no equivalent: pow(1 - c, p) for exp(p log1p(-c)).
 *   Measured against the C runtime on llvmpipe: see README.md.
 *
 * fp16 UNDER- AND OVERFLOW GUARDS (mediump functions)
 *   Overflow: eta and kappa are clamped to [FRESNEL_ETA_MIN,
 *   FRESNEL_MP_IOR_MAX] = [2^-10, 100] in the mediump functions, which keeps
 *   every intermediate below 2.1e4 < 65504 (the C runtime clamps at 1e5;
 *   no measured material comes near 100). LSK's a is clamped to
 *   FRESNEL_MP_A_MAX = 1e4 instead of 1e6 (the host makes a = 2 eta <= 200).
 *   Underflow: the only quantities that fall below 2^-14 are powers of 1 - c
 *   near c = 1 and products with them; they are added to terms of order F0,
 *   so flushing them to zero changes a result by at most 2^-14 = 6.1e-5,
 *   an eighth of binary16's spacing at 1 (2^-11 = 4.9e-4). No mediump
 *   function divides by a quantity that can underflow to 0: the approximate
 *   conductor's s-term is formed scaled (see there). mix() is not used
 *   (mediump mix() misbehaves on some GPUs, WebGLSamples#4), nor HLSL's
 *   lerp(): interpolation is written a + t (b - a), as in C.
 */
#ifndef FRESNEL_SHADER
#define FRESNEL_SHADER 1

/* ------------------------------------------------------- GLSL spellings */

/* Unless a language's prelude has defined the spellings (see OTHER
 * LANGUAGES above), this is GLSL. */
#ifndef FRESNEL_HP
#define FRESNEL_GLSL 1

#ifndef FRESNEL_HIGHP
#if defined(GL_ES) && !defined(GL_FRAGMENT_PRECISION_HIGH)
#define FRESNEL_HIGHP mediump
#elif !defined(GL_ES) && __VERSION__ < 130
#define FRESNEL_HIGHP /* desktop GLSL 1.10, 1.20: no precision qualifiers */
#else
#define FRESNEL_HIGHP highp
#endif
#endif

/* FRESNEL_LUT_ARRAYS: 1 where tables can be const arrays indexed with a
 * variable (GLSL ES 3.00 and later, desktop GLSL 1.30 and later), 0 where
 * they cannot (GLSL ES 1.00: no array constructors, and fragment shaders need
 * only support constant indices; desktop 1.10: no array constructors; 1.20:
 * no integer min() and max(), which the cubic's index clamps need).
 * Generated scenes (`fresnel gen --glsl`) read their tables from const arrays
 * when it is 1 and from the packed RGBA8 texture (fresnel_lut_packed_rgb
 * below) when it is 0; define it as 0 before this file to use the texture in
 * any dialect. */
#ifndef FRESNEL_LUT_ARRAYS
#if (defined(GL_ES) && __VERSION__ >= 300) || (!defined(GL_ES) && __VERSION__ >= 130)
#define FRESNEL_LUT_ARRAYS 1
#else
#define FRESNEL_LUT_ARRAYS 0
#endif
#endif

#if __VERSION__ >= 130
#define FRESNEL_TEXTURE texture
#define FRESNEL_I_INDEXED_ARRAYS 1 /* any array indexed with a variable */
#else
#define FRESNEL_TEXTURE texture2D
#define FRESNEL_I_INDEXED_ARRAYS 0
#endif
/* FRESNEL_FILM: 1 where the thin film's highp arithmetic exists, every
 * dialect but a GLSL ES 1.00 fragment shader without
 * GL_FRAGMENT_PRECISION_HIGH (binary16 would put its phases turns off and
 * its table indices past mediump int's 2^10); generated scenes compile
 * their films only where it is 1. */
#ifndef FRESNEL_FILM
#if defined(GL_ES) && !defined(GL_FRAGMENT_PRECISION_HIGH)
#define FRESNEL_FILM 0
#else
#define FRESNEL_FILM 1
#endif
#endif
/* an index into the film's table (up to 1743: highp in GLSL ES 1.00) */
#define FRESNEL_INT FRESNEL_HIGHP int

#define FRESNEL_MP float
#define FRESNEL_MP3 vec3
#define FRESNEL_HP FRESNEL_HIGHP float
#define FRESNEL_HP2 FRESNEL_HIGHP vec2
#define FRESNEL_HP3 FRESNEL_HIGHP vec3
#define FRESNEL_VEC2 vec2
#define FRESNEL_VEC3 vec3
#define FRESNEL_SATURATE(x) clamp(x, 0.0, 1.0)
#endif /* GLSL spellings */

/* Domains, as in fresnel.h. FRESNEL_MP_* apply to the mediump functions. */
#define FRESNEL_ETA_MIN 0.0009765625
#define FRESNEL_ETA_MAX 1e5
#define FRESNEL_KAPPA_MAX 1e5
#define FRESNEL_KAPPA_TINY 1e-18
#define FRESNEL_P_MIN 1e-3
#define FRESNEL_P_MAX 1e3
#define FRESNEL_ALPHA_MAX 1e3
#define FRESNEL_A_MAX 1e6
#define FRESNEL_GULBRANDSEN_R_MAX 0.9999
#ifndef FRESNEL_MP_IOR_MAX
#define FRESNEL_MP_IOR_MAX 100.0
#endif
#ifndef FRESNEL_MP_A_MAX
#define FRESNEL_MP_A_MAX 1e4
#endif

/* MEDIUMP CONTRACT: the most a mediump-safe function's result differs from
 * the exact one (absolute, results in [0, 1]) when each of its operations is
 * done in binary16 or in binary32, in any mix a GPU chooses, with or without
 * binary16 subnormals flushed to zero and with or without fused
 * multiply-adds, its inputs binary16 values: the largest error a search
 * over random and adversarial mixes found on every binary16 cosine and the
 * binary16 material set, rounded up (tests/shader_ports/mixed_precision.cpp;
 * the table in ports/glsl/README.md). They hold for mediump (GLSL),
 * min16float (HLSL), half (MSL) and any GPU's way of computing those.
 * Inputs that need highp: on a GPU that flushes binary16 subnormals, a
 * cosine below 2^-14 is 0, which moves the approximate conductor by up to
 * 0.012 for eta below 0.05 (without such cosines its bound is 1.7e-3);
 * everything outside the binary16 domain (fresnel_f16.h: eta, kappa <= 16
 * for these bounds). */
#define FRESNEL_MP_BOUND_SCHLICK 2.4e-3
#define FRESNEL_MP_BOUND_SCHLICK_GEN 2.4e-3
#define FRESNEL_MP_BOUND_F82 3.3e-3
#define FRESNEL_MP_BOUND_LSK 2.9e-3
#define FRESNEL_MP_BOUND_LSK_COMP 2.9e-3
#define FRESNEL_MP_BOUND_APPROX_CONDUCTOR 1.3e-2
#define FRESNEL_MP_BOUND_F0_FROM_IOR 1.2e-3
#define FRESNEL_MP_BOUND_F0_IN_MEDIUM 2.0e-3

/* ------------------------------------------------------------- helpers */

FRESNEL_MP fresnel_i_unit(FRESNEL_MP x) { return FRESNEL_SATURATE(x); }
FRESNEL_MP3 fresnel_i_unit_rgb(FRESNEL_MP3 x) { return FRESNEL_SATURATE(x); }
FRESNEL_MP fresnel_i_pow5(FRESNEL_MP x)
{
    FRESNEL_MP x2 = x * x;
    return x2 * x2 * x;
}
FRESNEL_MP3 fresnel_i_pow5_rgb(FRESNEL_MP3 x)
{
    FRESNEL_MP3 x2 = x * x;
    return x2 * x2 * x;
}
/* (1 - c)^p for c in [0, 1], p > 0. The C runtime uses exp(p log1p(-c));
 * GLSL and HLSL have no log1p, and 1 - c is exact for c >= 0.5 (Sterbenz)
 * so the rounding p multiplies only exists where (1 - c)^p is large and its
 * relative error ~ p 6e-8 harmless. The base is >= 0 and 0 is answered
 * without pow() (pow(0, p) goes through log2(0) = -Inf). */
FRESNEL_MP fresnel_i_pow_one_minus(FRESNEL_MP c, FRESNEL_MP p)
{
    FRESNEL_MP x = 1.0 - c;
    return x > 0.0 ? pow(x, p) : FRESNEL_MP(0.0);
}
FRESNEL_HP fresnel_i_kappa(FRESNEL_HP k)
{
    return k >= FRESNEL_KAPPA_TINY ? min(k, FRESNEL_KAPPA_MAX) : 0.0;
}

/* eta^2 + c^2 - 1 = eta^2 - sin^2, correct to about one rounding of itself
 * even at the critical angle (eta < 1), where it is the difference of nearly
 * equal numbers. eta and c are split at 2^-12: the heads eh, ch are
 * multiples of 2^-12 below 1, so ch^2, (1 - eh)(1 + eh) and their difference
 * are multiples of 2^-24 below 1 in magnitude: exact in binary32 whatever the
 * compiler contracts or reorders (no TwoSum to be simplified away). The tails
 * add (eta - eh)(eta + eh) + (c - ch)(c + ch) < 2^-10 with relative error
 * 2^-23. For eta >= 1 both terms of (eta-1)(eta+1) + c^2 are >= 0: no
 * cancellation. */
FRESNEL_HP fresnel_i_eta2_minus_sin2(FRESNEL_HP eta, FRESNEL_HP c)
{
    FRESNEL_HP eh, ch;
    if (eta >= 1.0)
        return (eta - 1.0) * (eta + 1.0) + c * c;
    eh = floor(eta * 4096.0) * (1.0 / 4096.0);
    ch = floor(c * 4096.0) * (1.0 / 4096.0);
    return (ch * ch - (1.0 - eh) * (1.0 + eh)) + ((eta - eh) * (eta + eh) + (c - ch) * (c + ch));
}

/* ------------------------------------------------------------- Schlick */

/* F0 + (1 - F0)(1 - c)^5. mediump: (1-c)^5 underflows below 2^-14 for
 * c > 0.856, which changes F by < 6.1e-5 (see the file comment). */
FRESNEL_MP fresnel_schlick(FRESNEL_MP f0, FRESNEL_MP c)
{
    f0 = fresnel_i_unit(f0);
    return fresnel_i_unit(f0 + (1.0 - f0) * fresnel_i_pow5(1.0 - fresnel_i_unit(c)));
}
FRESNEL_MP3 fresnel_schlick_rgb(FRESNEL_MP3 f0, FRESNEL_MP c)
{
    f0 = fresnel_i_unit_rgb(f0);
    return fresnel_i_unit_rgb(f0 + (1.0 - f0) * fresnel_i_pow5(1.0 - fresnel_i_unit(c)));
}

/* F0 + (F90 - F0)(1 - c)^p, p clamped to [1e-3, 1e3]. mediump: as Schlick;
 * pow() itself is the GPU's (binary16 pow is exp2(p log2 x) with a few ulp). */
FRESNEL_MP fresnel_schlick_gen(FRESNEL_MP f0, FRESNEL_MP f90, FRESNEL_MP p, FRESNEL_MP c)
{
    FRESNEL_MP t;
    c = fresnel_i_unit(c);
    f0 = fresnel_i_unit(f0);
    f90 = fresnel_i_unit(f90);
    p = clamp(p, FRESNEL_P_MIN, FRESNEL_P_MAX);
    t = p == 5.0 ? fresnel_i_pow5(1.0 - c) : fresnel_i_pow_one_minus(c, p);
    return fresnel_i_unit(f0 + (f90 - f0) * t);
}
FRESNEL_MP3 fresnel_schlick_gen_rgb(FRESNEL_MP3 f0, FRESNEL_MP3 f90, FRESNEL_MP p, FRESNEL_MP c)
{
    FRESNEL_MP t;
    c = fresnel_i_unit(c);
    f0 = fresnel_i_unit_rgb(f0);
    f90 = fresnel_i_unit_rgb(f90);
    p = clamp(p, FRESNEL_P_MIN, FRESNEL_P_MAX);
    t = p == 5.0 ? fresnel_i_pow5(1.0 - c) : fresnel_i_pow_one_minus(c, p);
    return fresnel_i_unit_rgb(f0 + (f90 - f0) * t);
}

/* Schlick at the transmitted angle for eta < 1 (1 past the critical angle).
 * highp: eta^2 ct^2 = (eta-1)(eta+1) + c^2 cancels at the critical angle. */
float fresnel_schlick_internal(FRESNEL_MP f0, FRESNEL_HP eta, FRESNEL_HP c)
{
    FRESNEL_HP e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    FRESNEL_HP cc = FRESNEL_SATURATE(c);
    FRESNEL_HP ct2;
    if (e >= 1.0)
        return fresnel_schlick(f0, cc);
    ct2 = fresnel_i_eta2_minus_sin2(e, cc);
    if (!(ct2 > 0.0))
        return 1.0;
    return fresnel_schlick(f0, sqrt(ct2) / e);
}
FRESNEL_VEC3 fresnel_schlick_internal_rgb(FRESNEL_MP3 f0, FRESNEL_HP eta, FRESNEL_HP c)
{
    FRESNEL_HP e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    FRESNEL_HP cc = FRESNEL_SATURATE(c);
    FRESNEL_HP ct2;
    if (e >= 1.0)
        return FRESNEL_VEC3(fresnel_schlick_rgb(f0, cc));
    ct2 = fresnel_i_eta2_minus_sin2(e, cc);
    if (!(ct2 > 0.0))
        return FRESNEL_VEC3(1.0, 1.0, 1.0);
    return FRESNEL_VEC3(fresnel_schlick_rgb(f0, sqrt(ct2) / e));
}

/* Hoffman's F0 in a surrounding medium of index etaE, rebuilt from
 * 1 - s = 2/(etaE+1) and 1 - sqrt F0 = (1-F0)/(1+sqrt F0) as in C.
 * mediump: every intermediate is in [0, 2]; etaE clamped to [1e-3, 100]. */
FRESNEL_MP fresnel_f0_in_medium(FRESNEL_MP f0, FRESNEL_MP eta_e)
{
    FRESNEL_MP r, one_minus_s, one_minus_r, q;
    eta_e = clamp(eta_e, FRESNEL_ETA_MIN, FRESNEL_MP_IOR_MAX);
    f0 = fresnel_i_unit(f0);
    r = sqrt(f0);
    one_minus_s = 2.0 / (eta_e + 1.0);
    one_minus_r = (1.0 - f0) / (1.0 + r);
    q = (one_minus_s - one_minus_r) / (one_minus_r + r * one_minus_s);
    return fresnel_i_unit(q * q);
}

/* ((eta-1)^2 + kappa^2) / ((eta+1)^2 + kappa^2). mediump: eta, kappa <= 100
 * keep the denominator <= 20201; it is >= 1, so nothing underflows. */
FRESNEL_MP fresnel_f0_from_ior(FRESNEL_MP eta, FRESNEL_MP kappa)
{
    FRESNEL_MP k2;
    eta = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_MP_IOR_MAX);
    kappa = clamp(kappa, 0.0, FRESNEL_MP_IOR_MAX);
    k2 = kappa * kappa;
    return fresnel_i_unit(((eta - 1.0) * (eta - 1.0) + k2) / ((eta + 1.0) * (eta + 1.0) + k2));
}
FRESNEL_HP fresnel_i_f0_from_ior_hp(FRESNEL_HP eta, FRESNEL_HP kappa)
{
    FRESNEL_HP k2;
    eta = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    kappa = fresnel_i_kappa(kappa);
    k2 = kappa * kappa;
    return FRESNEL_SATURATE(((eta - 1.0) * (eta - 1.0) + k2) / ((eta + 1.0) * (eta + 1.0) + k2));
}

/* ----------------------------------------------------------------- LSK */

/* ((n-1)^2 + 4n (1-c)^5 + k^2) / ((n+1)^2 + k^2). mediump: guards as
 * fresnel_f0_from_ior; 4n(1-c)^5 <= 400. */
FRESNEL_MP fresnel_lsk(FRESNEL_MP n, FRESNEL_MP k, FRESNEL_MP c)
{
    FRESNEL_MP k2;
    n = clamp(n, FRESNEL_ETA_MIN, FRESNEL_MP_IOR_MAX);
    k = clamp(k, 0.0, FRESNEL_MP_IOR_MAX);
    c = fresnel_i_unit(c);
    k2 = k * k;
    return fresnel_i_unit(((n - 1.0) * (n - 1.0) + 4.0 * n * fresnel_i_pow5(1.0 - c) + k2) /
                          ((n + 1.0) * (n + 1.0) + k2));
}
FRESNEL_MP3 fresnel_lsk_rgb(FRESNEL_MP3 n, FRESNEL_MP3 k, FRESNEL_MP c)
{
    FRESNEL_MP3 k2;
    n = clamp(n, FRESNEL_MP3(FRESNEL_ETA_MIN), FRESNEL_MP3(FRESNEL_MP_IOR_MAX));
    k = clamp(k, FRESNEL_MP3(0.0), FRESNEL_MP3(FRESNEL_MP_IOR_MAX));
    c = fresnel_i_unit(c);
    k2 = k * k;
    return fresnel_i_unit_rgb(((n - 1.0) * (n - 1.0) + 4.0 * n * fresnel_i_pow5(1.0 - c) + k2) /
                          ((n + 1.0) * (n + 1.0) + k2));
}

/* fresnel_lsk - a c (1-c)^alpha, a in [0, 1e4] (mediump bound; C: 1e6),
 * alpha in [0, 1e3]; alpha = 0 means the term a c. mediump: a c (1-c)^alpha
 * is formed as a (c (1-c)^alpha), which stays below a; pow() underflowing to
 * 0 for large alpha drops a term < 2^-14 a c. */
FRESNEL_MP fresnel_lsk_comp(FRESNEL_MP n, FRESNEL_MP k, FRESNEL_MP a, FRESNEL_MP alpha, FRESNEL_MP c)
{
    FRESNEL_MP comp;
    c = fresnel_i_unit(c);
    a = clamp(a, 0.0, FRESNEL_MP_A_MAX);
    alpha = clamp(alpha, 0.0, FRESNEL_ALPHA_MAX);
    comp = alpha > 0.0 ? a * (c * fresnel_i_pow_one_minus(c, alpha)) : a * c;
    return fresnel_i_unit(fresnel_lsk(n, k, c) - comp);
}
FRESNEL_MP3 fresnel_lsk_comp_rgb(FRESNEL_MP3 n, FRESNEL_MP3 k, FRESNEL_MP3 a, FRESNEL_MP3 alpha, FRESNEL_MP c)
{
    return FRESNEL_MP3(fresnel_lsk_comp(n.r, k.r, a.r, alpha.r, c), fresnel_lsk_comp(n.g, k.g, a.g, alpha.g, c),
                       fresnel_lsk_comp(n.b, k.b, a.b, alpha.b, c));
}

/* ----------------------------------------------------------------- F82 */

/* F0 + (1-F0)(1-c)^5 - a c (1-c)^6, a = (7^7/6^6)(F0 - F82) + (49/6)(1 - F0),
 * clamped to [0, 1]. mediump: |a| <= 26; underflow as Schlick. The constants
 * are written out: in a mediump expression, 823543.0 / 46656.0 is folded after
 * 823543 has become binary16 Inf (measured on llvmpipe: F = 0 at c = 0).
 * 17.6513844 and 8.16666698 are the binary32 values of 7^7/6^6 and 49/6. */
#define FRESNEL_I_F82_A1 17.6513844
#define FRESNEL_I_F82_A2 8.16666698
FRESNEL_MP fresnel_f82(FRESNEL_MP f0, FRESNEL_MP f82, FRESNEL_MP c)
{
    FRESNEL_MP x, x5, a;
    f0 = fresnel_i_unit(f0);
    f82 = fresnel_i_unit(f82);
    c = fresnel_i_unit(c);
    x = 1.0 - c;
    x5 = fresnel_i_pow5(x);
    a = FRESNEL_I_F82_A1 * (f0 - f82) + FRESNEL_I_F82_A2 * (1.0 - f0);
    return fresnel_i_unit(f0 + (1.0 - f0) * x5 - a * c * x5 * x);
}
FRESNEL_MP3 fresnel_f82_rgb(FRESNEL_MP3 f0, FRESNEL_MP3 f82, FRESNEL_MP c)
{
    FRESNEL_MP x, x5;
    FRESNEL_MP3 a;
    f0 = fresnel_i_unit_rgb(f0);
    f82 = fresnel_i_unit_rgb(f82);
    c = fresnel_i_unit(c);
    x = 1.0 - c;
    x5 = fresnel_i_pow5(x);
    a = FRESNEL_I_F82_A1 * (f0 - f82) + FRESNEL_I_F82_A2 * (1.0 - f0);
    return fresnel_i_unit_rgb(f0 + (1.0 - f0) * x5 - a * c * x5 * x);
}

/* --------------------------------------------------- approximate conductor */

/* rs = ((n-c)^2 + k^2) / ((n+c)^2 + k^2),
 * rp = ((nc-1)^2 + (kc)^2) / ((n^2+k^2)c^2 + 2nc + 1),  F = (rs + rp)/2.
 * mediump: n, k <= 100 keep the rp denominator in [1, 20201]. rs is formed
 * from n - c, n + c and k divided by s = max(n + c, k), so that its
 * denominator is in [1, 2] and nothing that matters underflows: with the
 * squares themselves, (n - c)^2 falls below 2^-14 for |n - c| < 2^-7, and a
 * GPU that flushes binary16 subnormals to zero would make rs 0 instead of
 * about (n - c)^2 / (n + c)^2 (F off by 0.2 at n = 0.01, c = 0.002). s >= n
 * >= FRESNEL_ETA_MIN > 0. */
FRESNEL_MP fresnel_approx_conductor(FRESNEL_MP n, FRESNEL_MP k, FRESNEL_MP c)
{
    FRESNEL_MP kc, s, dm, dp, ks;
    n = clamp(n, FRESNEL_ETA_MIN, FRESNEL_MP_IOR_MAX);
    k = clamp(k, 0.0, FRESNEL_MP_IOR_MAX);
    c = fresnel_i_unit(c);
    kc = k * c;
    s = max(n + c, k);
    dm = (n - c) / s;
    dp = (n + c) / s;
    ks = k / s;
    return fresnel_i_unit(0.5 * ((dm * dm + ks * ks) / (dp * dp + ks * ks) +
                                 ((n * c - 1.0) * (n * c - 1.0) + kc * kc) /
                                     ((n * n + k * k) * c * c + 2.0 * n * c + 1.0)));
}
FRESNEL_MP3 fresnel_approx_conductor_rgb(FRESNEL_MP3 n, FRESNEL_MP3 k, FRESNEL_MP c)
{
    return FRESNEL_MP3(fresnel_approx_conductor(n.r, k.r, c), fresnel_approx_conductor(n.g, k.g, c),
                       fresnel_approx_conductor(n.b, k.b, c));
}
/* The same in highp with the C domain (eta, kappa up to 1e5), for Gulbrandsen. */
FRESNEL_HP fresnel_i_approx_conductor_hp(FRESNEL_HP n, FRESNEL_HP k, FRESNEL_HP c)
{
    FRESNEL_HP kc, rs, rp;
    n = clamp(n, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    k = fresnel_i_kappa(k);
    c = FRESNEL_SATURATE(c);
    kc = k * c;
    rs = ((n - c) * (n - c) + k * k) / ((n + c) * (n + c) + k * k);
    rp = ((n * c - 1.0) * (n * c - 1.0) + kc * kc) / ((n * n + k * k) * c * c + 2.0 * n * c + 1.0);
    return FRESNEL_SATURATE(0.5 * (rs + rp));
}

/* ---------------------------------------------------------- Gulbrandsen */

/* r, g -> (n, k), r clamped to [0, 0.9999]. highp (see the file comment).
 * k^2 in the factored form of src/f32/gulbrandsen.c. */
FRESNEL_HP2 fresnel_gulbrandsen_nk(FRESNEL_HP r, FRESNEL_HP g)
{
    FRESNEL_HP sr, nmin, nmax, n, k2;
    r = clamp(r, 0.0, FRESNEL_GULBRANDSEN_R_MAX);
    g = FRESNEL_SATURATE(g);
    sr = sqrt(r);
    nmin = (1.0 - r) / (1.0 + r);
    nmax = (1.0 + sr) * (1.0 + sr) / (1.0 - r);
    n = g * nmin + (1.0 - g) * nmax;
    k2 = g * (nmax - nmin) * (sr * (n + 1.0) + n - 1.0) / (1.0 + sr);
    return FRESNEL_VEC2(n, k2 > 0.0 ? sqrt(k2) : 0.0);
}

/* (n, k) -> (r, g); g clamped to [0, 1]. highp. */
FRESNEL_HP2 fresnel_gulbrandsen_rg(FRESNEL_HP n, FRESNEL_HP k)
{
    FRESNEL_HP r = fresnel_i_f0_from_ior_hp(n, k);
    FRESNEL_HP rc = min(r, FRESNEL_GULBRANDSEN_R_MAX);
    FRESNEL_HP sr = sqrt(rc);
    FRESNEL_HP nmin = (1.0 - rc) / (1.0 + rc);
    FRESNEL_HP nmax = (1.0 + sr) * (1.0 + sr) / (1.0 - rc);
    FRESNEL_HP span = nmax - nmin;
    n = clamp(n, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    return FRESNEL_VEC2(r, span > 0.0 ? FRESNEL_SATURATE((nmax - n) / span) : 0.0);
}

/* The approximate conductor at the (n, k) of (r, g). highp. */
float fresnel_gulbrandsen(FRESNEL_HP r, FRESNEL_HP g, FRESNEL_HP c)
{
    FRESNEL_HP2 nk = fresnel_gulbrandsen_nk(r, g);
    return fresnel_i_approx_conductor_hp(nk.x, nk.y, c);
}
FRESNEL_VEC3 fresnel_gulbrandsen_rgb(FRESNEL_HP3 r, FRESNEL_HP3 g, FRESNEL_HP c)
{
    return FRESNEL_VEC3(fresnel_gulbrandsen(r.r, g.r, c), fresnel_gulbrandsen(r.g, g.g, c),
                        fresnel_gulbrandsen(r.b, g.b, c));
}

/* ------------------------------------------------------------ exact */

/* u + iv = sqrt((eta + i kappa)^2 - sin^2) on the decaying branch, and
 * m = u^2 + v^2, returned as (u, v, m). The smaller of u, v comes from
 * u v = eta kappa, never from (m - |A|)/2. eta, kappa already clamped. */
FRESNEL_HP3 fresnel_i_transmitted(FRESNEL_HP eta, FRESNEL_HP kappa, FRESNEL_HP c)
{
    FRESNEL_HP ek = eta * kappa;
    FRESNEL_HP a = fresnel_i_eta2_minus_sin2(eta, c) - kappa * kappa;
    FRESNEL_HP m = sqrt(a * a + 4.0 * ek * ek);
    FRESNEL_HP u, v;
    if (a >= 0.0) {
        u = sqrt(0.5 * (m + a));
        v = u > 0.0 ? ek / u : 0.0;
    } else {
        v = sqrt(0.5 * (m - a));
        u = ek / v;
    }
    return FRESNEL_VEC3(u, v, m);
}

/* Exact unpolarised reflectance of eta + i kappa (fresnel.h). highp. */
float fresnel_conductor(FRESNEL_HP eta, FRESNEL_HP kappa, FRESNEL_HP c)
{
    FRESNEL_HP e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    FRESNEL_HP k = fresnel_i_kappa(kappa);
    FRESNEL_HP cc = FRESNEL_SATURATE(c);
    FRESNEL_HP3 w;
    FRESNEL_HP p, q, den_s, den_p, rs, rp;
    if (e == 1.0 && k == 0.0)
        return 0.0; /* matched index: nothing reflected, also at c = 0 */
    w = fresnel_i_transmitted(e, k, cc);
    p = cc * ((e - k) * (e + k)); /* (eta + i kappa)^2 c = p + i q */
    q = 2.0 * e * k * cc;
    den_s = (cc + w.x) * (cc + w.x) + w.y * w.y;
    den_p = (p + w.x) * (p + w.x) + (q + w.y) * (q + w.y);
    rs = den_s > 0.0 ? ((cc - w.x) * (cc - w.x) + w.y * w.y) / den_s : 0.0;
    rp = den_p > 0.0 ? ((p - w.x) * (p - w.x) + (q - w.y) * (q - w.y)) / den_p : 0.0;
    return FRESNEL_SATURATE(0.5 * (rs + rp));
}
FRESNEL_VEC3 fresnel_conductor_rgb(FRESNEL_HP3 eta, FRESNEL_HP3 kappa, FRESNEL_HP c)
{
    return FRESNEL_VEC3(fresnel_conductor(eta.r, kappa.r, c), fresnel_conductor(eta.g, kappa.g, c),
                        fresnel_conductor(eta.b, kappa.b, c));
}

/* 1 - fresnel_conductor, from sums of non-negative terms (src/f32/exact.c). */
FRESNEL_HP fresnel_i_conductor_transmittance(FRESNEL_HP e, FRESNEL_HP k, FRESNEL_HP cc)
{
    FRESNEL_HP3 w;
    FRESNEL_HP p, q, den_s, den_p, ts, tp;
    if (e == 1.0 && k == 0.0)
        return 1.0;
    w = fresnel_i_transmitted(e, k, cc);
    p = cc * ((e - k) * (e + k));
    q = 2.0 * e * k * cc;
    den_s = (cc + w.x) * (cc + w.x) + w.y * w.y;
    den_p = (p + w.x) * (p + w.x) + (q + w.y) * (q + w.y);
    ts = den_s > 0.0 ? 4.0 * cc * w.x / den_s : 1.0;
    tp = den_p > 0.0 ? 4.0 * cc * w.x * (w.z + (1.0 - cc) * (1.0 + cc)) / den_p : 1.0;
    return FRESNEL_SATURATE(0.5 * (ts + tp));
}

/* Exact dielectric, either side; 1 past the critical angle. highp. */
float fresnel_dielectric(FRESNEL_HP eta, FRESNEL_HP c)
{
    FRESNEL_HP e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    FRESNEL_HP cc = FRESNEL_SATURATE(c);
    FRESNEL_HP a, w, e2c, rs, rp;
    if (e == 1.0)
        return 0.0;
    a = fresnel_i_eta2_minus_sin2(e, cc);
    if (a < 0.0)
        return 1.0; /* total internal reflection */
    w = sqrt(a);
    e2c = e * e * cc;
    rs = (cc - w) / (cc + w);
    rp = (e2c - w) / (e2c + w);
    return FRESNEL_SATURATE(0.5 * (rs * rs + rp * rp));
}

/* -------------------------------------------------------- Cook-Torrance */

/* F0 + (1 - F0) (1 - T'(c)/T'(1)), T' the transmittance of one
 * representative eta + i kappa, T'(1) = 4 eta / ((eta+1)^2 + kappa^2).
 * F0 may be mediump; eta, kappa, c and the interpolant are highp. */
FRESNEL_HP fresnel_i_cook_torrance_t(FRESNEL_HP eta, FRESNEL_HP kappa, FRESNEL_HP c)
{
    FRESNEL_HP e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    FRESNEL_HP k = fresnel_i_kappa(kappa);
    FRESNEL_HP d = (e + 1.0) * (e + 1.0) + k * k;
    return FRESNEL_SATURATE(1.0 - fresnel_i_conductor_transmittance(e, k, FRESNEL_SATURATE(c)) * d / (4.0 * e));
}
float fresnel_cook_torrance(FRESNEL_MP f0, FRESNEL_HP eta, FRESNEL_HP kappa, FRESNEL_HP c)
{
    FRESNEL_HP t = fresnel_i_cook_torrance_t(eta, kappa, c);
    f0 = fresnel_i_unit(f0);
    return fresnel_i_unit(f0 + (1.0 - f0) * t);
}
FRESNEL_VEC3 fresnel_cook_torrance_rgb(FRESNEL_MP3 f0, FRESNEL_HP eta, FRESNEL_HP kappa, FRESNEL_HP c)
{
    FRESNEL_HP t = fresnel_i_cook_torrance_t(eta, kappa, c);
    f0 = fresnel_i_unit_rgb(f0);
    return FRESNEL_VEC3(fresnel_i_unit_rgb(f0 + (1.0 - f0) * t));
}

/* --------------------------------------------------------------- LUTs */

/* Tables of src/f32/lut.c: n nodes, uniform in sqrt(c), c_i = (i/(n-1))^2
 * (FRESNEL_LUT_*, fresnel_lut*), or in c (the LINEAR forms); RGB tables
 * hold n red nodes, then n green, then n blue; the RESIDUAL forms add the
 * table to Schlick(F0). Linear interpolation between the two nodes around c,
 * computed here (not by a texture unit, whose filter weights have 8 bits
 * on many GPUs), so results match the C runtime.
 *
 * FROM AN ARRAY (HLSL; GLSL ES 3.00, GLSL 1.30 and later; ES 1.00 does not
 * index fragment arrays with a variable): FRESNEL_LUT_ARRAY(table, n, c)
 * and friends below; table is a float array (const or uniform, in HLSL
 * static const, as `fresnel gen --hlsl` writes them, or a cbuffer) of n or
 * 3n nodes, n an int constant expression or variable. Each macro is one
 * expression.
 *
 * FROM A TEXTURE (GLSL): fresnel_lut*(table, strip, n, c), the R32F strip,
 * and fresnel_lut*_packed_rgb, the packed RGBA8 texture, further below.
 *
 * Precision: position, fetches and interpolation highp (see the file
 * comment); the result is converted to the default precision. */
FRESNEL_HP2 fresnel_i_lut_pos(FRESNEL_HP n, FRESNEL_HP x)
{
    FRESNEL_HP pos = x * (n - 1.0);
    FRESNEL_HP i = min(floor(pos), n - 2.0); /* x = 1 ends the last segment */
    return FRESNEL_VEC2(i, pos - i);
}
/* Node index (floor) and fraction of c in an n-node table. */
FRESNEL_HP2 fresnel_lut_pos(FRESNEL_HP n, FRESNEL_HP c)
{
    return fresnel_i_lut_pos(n, sqrt(FRESNEL_SATURATE(c)));
}
FRESNEL_HP2 fresnel_lut_linear_pos(FRESNEL_HP n, FRESNEL_HP c)
{
    return fresnel_i_lut_pos(n, FRESNEL_SATURATE(c));
}
FRESNEL_HP fresnel_lut_lerp(FRESNEL_HP a, FRESNEL_HP b, FRESNEL_HP t)
{
    return a + t * (b - a);
}

#define FRESNEL_I_LUT_AT(table, base, p) fresnel_lut_lerp((table)[(base) + int((p).x)], (table)[(base) + int((p).x) + 1], (p).y)
#define FRESNEL_I_LUT_AT_RGB(table, n, p) FRESNEL_VEC3(FRESNEL_I_LUT_AT(table, 0, p), FRESNEL_I_LUT_AT(table, (n), p), FRESNEL_I_LUT_AT(table, 2 * (n), p))
#define FRESNEL_LUT_ARRAY(table, n, c) FRESNEL_SATURATE(FRESNEL_I_LUT_AT(table, 0, fresnel_lut_pos(float(n), (c))))
#define FRESNEL_LUT_LINEAR_ARRAY(table, n, c) FRESNEL_SATURATE(FRESNEL_I_LUT_AT(table, 0, fresnel_lut_linear_pos(float(n), (c))))
#define FRESNEL_LUT_RESIDUAL_ARRAY(f0, table, n, c) FRESNEL_SATURATE(fresnel_schlick((f0), (c)) + FRESNEL_I_LUT_AT(table, 0, fresnel_lut_pos(float(n), (c))))
#define FRESNEL_LUT_LINEAR_RESIDUAL_ARRAY(f0, table, n, c) FRESNEL_SATURATE(fresnel_schlick((f0), (c)) + FRESNEL_I_LUT_AT(table, 0, fresnel_lut_linear_pos(float(n), (c))))
#define FRESNEL_LUT_ARRAY_RGB(table, n, c) FRESNEL_SATURATE(FRESNEL_I_LUT_AT_RGB(table, (n), fresnel_lut_pos(float(n), (c))))
#define FRESNEL_LUT_LINEAR_ARRAY_RGB(table, n, c) FRESNEL_SATURATE(FRESNEL_I_LUT_AT_RGB(table, (n), fresnel_lut_linear_pos(float(n), (c))))
#define FRESNEL_LUT_RESIDUAL_ARRAY_RGB(f0, table, n, c) FRESNEL_SATURATE(fresnel_schlick_rgb((f0), (c)) + FRESNEL_I_LUT_AT_RGB(table, (n), fresnel_lut_pos(float(n), (c))))
#define FRESNEL_LUT_LINEAR_RESIDUAL_ARRAY_RGB(f0, table, n, c) FRESNEL_SATURATE(fresnel_schlick_rgb((f0), (c)) + FRESNEL_I_LUT_AT_RGB(table, (n), fresnel_lut_linear_pos(float(n), (c))))

/* fresnel_lut_cubic (src/f32/lut.c): Catmull-Rom through the four nodes around
 * sqrt(c), the outer ones clamped to the table's ends; tables fitted for it
 * (lutN-cubic). Arrays, n an int (GLSL 1.20 has no integer min() and max()
 * for the index clamps), or the packed texture (fresnel_lut_cubic_packed_rgb,
 * every GLSL dialect). */
FRESNEL_HP fresnel_lut_cubic_blend(FRESNEL_HP p0, FRESNEL_HP p1, FRESNEL_HP p2, FRESNEL_HP p3, FRESNEL_HP t)
{
    FRESNEL_HP d = p2 - p1, m1 = 0.5 * (p2 - p0), m2 = 0.5 * (p3 - p1);
    return p1 + t * (m1 + t * ((3.0 * d - 2.0 * m1 - m2) + t * (m1 + m2 - 2.0 * d)));
}
#define FRESNEL_I_LUT_CUBIC_AT(table, base, n, p) fresnel_lut_cubic_blend((table)[(base) + max(int((p).x) - 1, 0)], (table)[(base) + int((p).x)], (table)[(base) + int((p).x) + 1], (table)[(base) + min(int((p).x) + 2, (n) - 1)], (p).y)
#define FRESNEL_LUT_CUBIC_ARRAY(table, n, c) FRESNEL_SATURATE(FRESNEL_I_LUT_CUBIC_AT(table, 0, (n), fresnel_lut_pos(float(n), (c))))
#define FRESNEL_LUT_CUBIC_ARRAY_RGB(table, n, c) FRESNEL_SATURATE(FRESNEL_VEC3(FRESNEL_I_LUT_CUBIC_AT(table, 0, (n), fresnel_lut_pos(float(n), (c))), FRESNEL_I_LUT_CUBIC_AT(table, (n), (n), fresnel_lut_pos(float(n), (c))), FRESNEL_I_LUT_CUBIC_AT(table, 2 * (n), (n), fresnel_lut_pos(float(n), (c)))))

/* ---------------------------------------------------------- thin film */

/* fresnel_film_rgb (include/fresnel_film.h): a transparent film of
 * thickness d_nm (clamped to [0, FRESNEL_FILM_D_MAX]) on a material, from
 * the material's table as `fresnel gen --glsl` or `--hlsl` writes it: a
 * float array of FRESNEL_FILM_FLOATS values in the order of the C struct
 * fresnel_film (freq[6], damp[6], weight[3][6][2], then 32 nodes of
 * FRESNEL_FILM_NODE values: a0[3], opd, decay, A, B, P, Q as six real
 * parts then six imaginary parts each). The binary32 runtime's algorithm:
 * the node pair around sqrt(c), linear interpolation, six poles
 *   F_j = zeta (A + B zeta) / (1 - P zeta + Q zeta^2),
 *   zeta = exp(2 pi i (x + i y)(nu + i gamma)),
 * and R = a0 + Re(sum_j w_j F_j) per channel, with the C runtime's
 * polynomials for cos and sin (the phase reduced to half a turn first) and
 * the GPU's exp where the C runtime has a polynomial too. highp throughout: phases reach a hundred turns, and the
 * denominators cancel near the fringes' peaks. Every GLSL dialect with
 * highp (FRESNEL_FILM), HLSL, MSL, WGSL. No loops: the six poles are
 * written out (one-line macros: GLSL ES 1.00 and 3.30 have no line
 * continuation). fresnel_film_rgb(t, c, d_nm) takes any table as an array
 * (GLSL ES 3.00, desktop 1.30 and later: ES 1.00 fragment shaders index
 * only uniform arrays with a variable); FRESNEL_FILM_RGB_READ is its body
 * over a table read any way, a texture in every dialect. */
#define FRESNEL_FILM_NODE 53
#define FRESNEL_FILM_FLOATS 1744
#define FRESNEL_FILM_TEXELS 436
#define FRESNEL_FILM_D_MAX 5000.0
#ifndef FRESNEL_INT
#define FRESNEL_INT int
#endif
#if !defined(FRESNEL_GLSL) || FRESNEL_FILM
FRESNEL_HP2 fresnel_i_film_pole(FRESNEL_HP2 xy, FRESNEL_HP2 pole, FRESNEL_HP2 a, FRESNEL_HP2 b, FRESNEL_HP2 p,
                                FRESNEL_HP2 q)
{
    /* cos and sin of the phase by src/f32/film.c's polynomials: the phase
     * less its nearest whole turn, h in [-1/2, 1/2], a quarter of it, then
     * the double angle twice. A GPU's own sin and cos may be far coarser
     * (WGSL allows an absolute error of 2^-11; SwiftShader's own would put
     * the film outside 1e-5, ports/wgsl/README.md). */
    FRESNEL_HP turns = xy.x * pole.x - xy.y * pole.y;
    FRESNEL_HP qa = 1.57079632679 * (turns - floor(turns + 0.5)), q2 = qa * qa, q4 = q2 * q2;
    FRESNEL_HP s4 = qa * ((0.999999997 - 0.166666502 * q2) + q4 * (0.00833201724 - 0.000195018938 * q2));
    FRESNEL_HP c4 = (0.999999968 - 0.499998427 * q2) + q4 * (0.0416544269 - 0.00135794706 * q2);
    FRESNEL_HP c2 = (c4 - s4) * (c4 + s4), s2 = 2.0 * s4 * c4;
    FRESNEL_HP2 z = exp(-6.28318530718 * max(xy.x * pole.y + xy.y * pole.x, 0.0)) *
                    FRESNEL_VEC2((c2 - s2) * (c2 + s2), 2.0 * s2 * c2);
    FRESNEL_HP2 z2 = FRESNEL_VEC2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y);
    FRESNEL_HP2 n0 = a + FRESNEL_VEC2(b.x * z.x - b.y * z.y, b.x * z.y + b.y * z.x);
    FRESNEL_HP2 n = FRESNEL_VEC2(z.x * n0.x - z.y * n0.y, z.x * n0.y + z.y * n0.x);
    FRESNEL_HP2 den = FRESNEL_VEC2(1.0 - (p.x * z.x - p.y * z.y) + (q.x * z2.x - q.y * z2.y),
                                   -(p.x * z.y + p.y * z.x) + (q.x * z2.y + q.y * z2.x));
    return FRESNEL_VEC2(n.x * den.x + n.y * den.y, n.y * den.x - n.x * den.y) / dot(den, den);
}
/* The table is read through a reader r: r(t, i) is value i of table t.
 * FRESNEL_FILM_ARRAY reads an array (a uniform or storage array, a const
 * array, a parameter); `fresnel gen --glsl` and `--wgsl` define a reader
 * per scene over a texture, a uniform block or a storage buffer, with t the
 * material's row. */
#define FRESNEL_FILM_ARRAY(t, i) (t)[i]
/* value i of the node at base b and of the next, interpolated at w */
#define FRESNEL_I_FILM_AT(r, t, b, i, w) fresnel_lut_lerp(r(t, (b) + (i)), r(t, (b) + FRESNEL_FILM_NODE + (i)), (w))
#define FRESNEL_I_FILM_C(r, t, b, i, w) FRESNEL_VEC2(FRESNEL_I_FILM_AT(r, t, b, i, w), FRESNEL_I_FILM_AT(r, t, b, (i) + 6, w))
#define FRESNEL_I_FILM_POLE(r, t, b, w, xy, j) fresnel_i_film_pole(xy, FRESNEL_VEC2(r(t, j), r(t, 6 + (j))), FRESNEL_I_FILM_C(r, t, b, 5 + (j), w), FRESNEL_I_FILM_C(r, t, b, 17 + (j), w), FRESNEL_I_FILM_C(r, t, b, 29 + (j), w), FRESNEL_I_FILM_C(r, t, b, 41 + (j), w))
/* channel ch: a0 + Re(w_j F_j) over the poles */
#define FRESNEL_I_FILM_W(r, t, ch, j, f) (r(t, 12 + 12 * (ch) + 2 * (j)) * (f).x - r(t, 13 + 12 * (ch) + 2 * (j)) * (f).y)
#define FRESNEL_I_FILM_CH(r, t, b, w, ch) (FRESNEL_I_FILM_AT(r, t, b, ch, w) + FRESNEL_I_FILM_W(r, t, ch, 0, fresnel_i_f0) + FRESNEL_I_FILM_W(r, t, ch, 1, fresnel_i_f1) + FRESNEL_I_FILM_W(r, t, ch, 2, fresnel_i_f2) + FRESNEL_I_FILM_W(r, t, ch, 3, fresnel_i_f3) + FRESNEL_I_FILM_W(r, t, ch, 4, fresnel_i_f4) + FRESNEL_I_FILM_W(r, t, ch, 5, fresnel_i_f5))
/* The body of a function of c and d_nm returning the film's RGB from table
 * t read by r (the table read in place, not passed: a 1744-float parameter
 * would be a copy per call). */
#define FRESNEL_FILM_RGB_READ(r, t, c, d_nm) FRESNEL_HP fresnel_i_pos = sqrt(FRESNEL_SATURATE(c)) * 31.0; FRESNEL_HP fresnel_i_k = min(floor(fresnel_i_pos), 30.0); FRESNEL_HP fresnel_i_w = fresnel_i_pos - fresnel_i_k; FRESNEL_INT fresnel_i_b = 48 + FRESNEL_FILM_NODE * int(fresnel_i_k); FRESNEL_HP2 fresnel_i_xy = clamp(d_nm, 0.0, FRESNEL_FILM_D_MAX) * FRESNEL_VEC2(FRESNEL_I_FILM_AT(r, t, fresnel_i_b, 3, fresnel_i_w), FRESNEL_I_FILM_AT(r, t, fresnel_i_b, 4, fresnel_i_w)); FRESNEL_HP2 fresnel_i_f0 = FRESNEL_I_FILM_POLE(r, t, fresnel_i_b, fresnel_i_w, fresnel_i_xy, 0); FRESNEL_HP2 fresnel_i_f1 = FRESNEL_I_FILM_POLE(r, t, fresnel_i_b, fresnel_i_w, fresnel_i_xy, 1); FRESNEL_HP2 fresnel_i_f2 = FRESNEL_I_FILM_POLE(r, t, fresnel_i_b, fresnel_i_w, fresnel_i_xy, 2); FRESNEL_HP2 fresnel_i_f3 = FRESNEL_I_FILM_POLE(r, t, fresnel_i_b, fresnel_i_w, fresnel_i_xy, 3); FRESNEL_HP2 fresnel_i_f4 = FRESNEL_I_FILM_POLE(r, t, fresnel_i_b, fresnel_i_w, fresnel_i_xy, 4); FRESNEL_HP2 fresnel_i_f5 = FRESNEL_I_FILM_POLE(r, t, fresnel_i_b, fresnel_i_w, fresnel_i_xy, 5); return FRESNEL_SATURATE(FRESNEL_VEC3(FRESNEL_I_FILM_CH(r, t, fresnel_i_b, fresnel_i_w, 0), FRESNEL_I_FILM_CH(r, t, fresnel_i_b, fresnel_i_w, 1), FRESNEL_I_FILM_CH(r, t, fresnel_i_b, fresnel_i_w, 2)));
/* The same over an array t. */
#define FRESNEL_FILM_RGB_BODY(t, c, d_nm) FRESNEL_FILM_RGB_READ(FRESNEL_FILM_ARRAY, t, c, d_nm)
/* The same as a function of any table (a uniform array, a cbuffer's). */
#if !defined(FRESNEL_GLSL) || FRESNEL_I_INDEXED_ARRAYS
FRESNEL_VEC3 fresnel_film_rgb(FRESNEL_HP t[FRESNEL_FILM_FLOATS], FRESNEL_HP c, FRESNEL_HP d_nm)
{
    FRESNEL_FILM_RGB_BODY(t, c, d_nm)
}
#endif
#ifdef FRESNEL_GLSL
/* THE RGBA32F TABLE TEXTURE (the film's texture route, `fresnel gen
 * --glsl`): row `row` holds one table, FRESNEL_FILM_TEXELS texels, value i
 * in component i % 4 of texel (i / 4, row). A float texture (GLES 2, WebGL
 * 1: OES_texture_float, format and internal format RGBA, type FLOAT), no
 * mipmaps, highp. The component by a one-hot dot product: exact for finite
 * values, and no dynamic vector index (which ANGLE rewrites into a
 * function of four branches per read). */
#if __VERSION__ >= 130
/* texelFetch: no filtering, no normalised coordinates */
FRESNEL_HP fresnel_film_texel(FRESNEL_HIGHP sampler2D s, int row, int i)
{
    int k = i / 4;
    return dot(texelFetch(s, ivec2(k, row), 0), vec4(equal(ivec4(i - 4 * k), ivec4(0, 1, 2, 3))));
}
#else
/* GLSL ES 1.00, desktop 1.10 and 1.20: texture2D at the texel's centre,
 * (i / 4 + 0.5) / FRESNEL_FILM_TEXELS across and v, the row's centre
 * ((row + 0.5) / rows), down; GL_NEAREST filters (any filter reads a
 * centre exactly, but GLES 2 filters no float texture without
 * OES_texture_float_linear) */
FRESNEL_HP fresnel_film_texel2d(FRESNEL_HIGHP sampler2D s, FRESNEL_HP v, FRESNEL_INT i)
{
    FRESNEL_INT k = i / 4;
    FRESNEL_HP u = (float(k) + 0.5) * (1.0 / float(FRESNEL_FILM_TEXELS));
    return dot(texture2D(s, FRESNEL_VEC2(u, v)), vec4(equal(ivec4(i - 4 * k), ivec4(0, 1, 2, 3))));
}
#endif
#endif
#endif

#ifdef FRESNEL_GLSL
/* ------------------------------------------------- LUTs in GLSL textures */

/* THE R32F STRIP: the table is a strip of texels in one row of a 2D texture
 * (node j of an RGB table at texel first + j, j = 0..3n-1), value in .r.
 * strip = (u of the first texel's centre, v of the row's centre, du = 1/width):
 *     strip = vec3((first + 0.5) / width, (row + 0.5) / height, 1.0 / width)
 * Any filter works (fetches hit texel centres); R32F keeps the table's
 * binary32 values (ES 2.0 needs OES_texture_float; ES 3.0 has R32F,
 * unfilterable, so NEAREST), R16F rounds them to binary16 (2.4e-4 near 1),
 * 8-bit formats to 1/510. Fetches use a highp sampler. */
FRESNEL_HP fresnel_i_lut_tex(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP2 pos, FRESNEL_HP first)
{
    FRESNEL_HP u = strip.x + (first + pos.x) * strip.z;
    return fresnel_lut_lerp(FRESNEL_TEXTURE(table, vec2(u, strip.y)).r,
                            FRESNEL_TEXTURE(table, vec2(u + strip.z, strip.y)).r, pos.y);
}

float fresnel_lut(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_i_lut_tex(table, strip, fresnel_lut_pos(n, c), 0.0));
}
float fresnel_lut_linear(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_i_lut_tex(table, strip, fresnel_lut_linear_pos(n, c), 0.0));
}
float fresnel_lut_residual(FRESNEL_MP f0, FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_schlick(f0, c) + fresnel_i_lut_tex(table, strip, fresnel_lut_pos(n, c), 0.0));
}
float fresnel_lut_linear_residual(FRESNEL_MP f0, FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n,
                                  FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_schlick(f0, c) +
                          fresnel_i_lut_tex(table, strip, fresnel_lut_linear_pos(n, c), 0.0));
}
FRESNEL_HP3 fresnel_i_lut_tex_rgb(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP2 pos, FRESNEL_HP n)
{
    return vec3(fresnel_i_lut_tex(table, strip, pos, 0.0), fresnel_i_lut_tex(table, strip, pos, n),
                fresnel_i_lut_tex(table, strip, pos, 2.0 * n));
}
vec3 fresnel_lut_rgb(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_i_lut_tex_rgb(table, strip, fresnel_lut_pos(n, c), n));
}
vec3 fresnel_lut_linear_rgb(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_i_lut_tex_rgb(table, strip, fresnel_lut_linear_pos(n, c), n));
}
vec3 fresnel_lut_residual_rgb(FRESNEL_MP3 f0, FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n,
                              FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_schlick_rgb(f0, c) +
                          fresnel_i_lut_tex_rgb(table, strip, fresnel_lut_pos(n, c), n));
}
vec3 fresnel_lut_linear_residual_rgb(FRESNEL_MP3 f0, FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip,
                                     FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_schlick_rgb(f0, c) +
                          fresnel_i_lut_tex_rgb(table, strip, fresnel_lut_linear_pos(n, c), n));
}

/* PACKED RGBA8 TEXTURE (every dialect; the form `fresnel gen --glsl` emits
 * for GLSL ES 1.00, where neither const arrays nor float textures are
 * guaranteed, and 16 uniform vectors are all a fragment shader is promised).
 * A table is one strip of texels in one row, addressed like the R32F strip
 * above (strip = (u of the first texel's centre, v of the row's centre,
 * du)); texel first + j of channel ch holds node j in .rg and node j + 1 in
 * .ba (the channel's last texel repeats its last node), so linear
 * interpolation needs one fetch per channel. A node v is the 16-bit code
 * q = round(v 2^15) + 2^14, high byte first: v in [-0.5, 1.5), step 2^-15,
 * quantisation error <= 2^-16; the decode below is exact in binary32 and
 * rounds once in binary16. Upload: GL_RGBA, GL_UNSIGNED_BYTE, NEAREST (any
 * filter works: fetches hit texel centres), CLAMP_TO_EDGE, no mipmaps. */
FRESNEL_HP2 fresnel_i_lut_u16x2(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP j)
{
    FRESNEL_HIGHP vec4 b = floor(FRESNEL_TEXTURE(table, vec2(strip.x + j * strip.z, strip.y)) * 255.0 + 0.5);
    /* (hi - 64) / 128 + lo / 2^15, with constants that are normal binary16 */
    return (b.yw * (1.0 / 256.0) + (b.xz - 64.0)) * (1.0 / 128.0);
}
FRESNEL_HP3 fresnel_i_lut_packed_rgb(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP2 pos, FRESNEL_HP n)
{
    FRESNEL_HP2 r = fresnel_i_lut_u16x2(table, strip, pos.x);
    FRESNEL_HP2 g = fresnel_i_lut_u16x2(table, strip, n + pos.x);
    FRESNEL_HP2 b = fresnel_i_lut_u16x2(table, strip, 2.0 * n + pos.x);
    return vec3(fresnel_lut_lerp(r.x, r.y, pos.y), fresnel_lut_lerp(g.x, g.y, pos.y), fresnel_lut_lerp(b.x, b.y, pos.y));
}
vec3 fresnel_lut_packed_rgb(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_i_lut_packed_rgb(table, strip, fresnel_lut_pos(n, c), n));
}
vec3 fresnel_lut_linear_packed_rgb(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_i_lut_packed_rgb(table, strip, fresnel_lut_linear_pos(n, c), n));
}
vec3 fresnel_lut_residual_packed_rgb(FRESNEL_MP3 f0, FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip,
                                     FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_schlick_rgb(f0, c) +
                          fresnel_i_lut_packed_rgb(table, strip, fresnel_lut_pos(n, c), n));
}
vec3 fresnel_lut_linear_residual_packed_rgb(FRESNEL_MP3 f0, FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip,
                                            FRESNEL_HP n, FRESNEL_HP c)
{
    return FRESNEL_SATURATE(fresnel_schlick_rgb(f0, c) +
                          fresnel_i_lut_packed_rgb(table, strip, fresnel_lut_linear_pos(n, c), n));
}

/* The cubic from the packed texture: texel i gives p1, p2; texel max(i-1, 0)
 * gives p0 in .rg; texel i + 1 gives p3 in .ba (node min(i + 2, n - 1),
 * since a channel's last texel repeats its last node). */
FRESNEL_HP fresnel_i_lut_cubic_packed(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP2 pos,
                                      FRESNEL_HP first)
{
    FRESNEL_HP2 a = fresnel_i_lut_u16x2(table, strip, first + max(pos.x - 1.0, 0.0));
    FRESNEL_HP2 m = fresnel_i_lut_u16x2(table, strip, first + pos.x);
    FRESNEL_HP2 z = fresnel_i_lut_u16x2(table, strip, first + pos.x + 1.0);
    return fresnel_lut_cubic_blend(a.x, m.x, m.y, z.y, pos.y);
}
vec3 fresnel_lut_cubic_packed_rgb(FRESNEL_HIGHP sampler2D table, FRESNEL_HP3 strip, FRESNEL_HP n, FRESNEL_HP c)
{
    FRESNEL_HP2 pos = fresnel_lut_pos(n, c);
    return FRESNEL_SATURATE(vec3(fresnel_i_lut_cubic_packed(table, strip, pos, 0.0),
                                 fresnel_i_lut_cubic_packed(table, strip, pos, n),
                                 fresnel_i_lut_cubic_packed(table, strip, pos, 2.0 * n)));
}
#endif /* FRESNEL_GLSL */

#endif /* FRESNEL_SHADER */
