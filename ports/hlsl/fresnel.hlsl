/* fresnel.hlsl -- the Fresnel models of include/fresnel.h as HLSL functions:
 * every function of ports/glsl/fresnel.glsl but its texture forms, with the
 * same formulas, the same precision-safe forms and the same names
 * (fresnel_schlick, fresnel_schlick_rgb, ...; float3 for fresnel_rgb,
 * float2 for fresnel_nk and fresnel_rg). The derivations, guards and error
 * analysis are in ports/glsl/fresnel.glsl's comments; below, "mediump" is
 * FRESNEL_MP and "highp" is float.
 *
 * USE
 *   #include "fresnel.hlsl" (Shader Model 5 and later, DXC or
 *   glslangValidator's HLSL front end), then the output of
 *   `fresnel gen SCENE --hlsl -o scene.hlsl`: static const float3 constants
 *   and tables, and float3 fresnel_<scene>_<material>_<model>_rgb(float c).
 *   Tested on lavapipe through glslangValidator -D -e main -S comp and
 *   SPIR-V (tests/test_vulkan.sh; measured differences: ports/README.md).
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
 *
 * CONVENTIONS (as in fresnel.h)
 *   c is cos(theta), clamped with saturate() before 1 - c is formed (a
 *   normalised dot product reaches 1.00001, and pow() of a negative base is
 *   NaN); eta, kappa relative to the incident medium; results in [0, 1].
 *   Interpolation of the mediump functions is written a + t (b - a), as in
 *   C; lerp() is used for the binary32 table interpolation.
 */
#ifndef FRESNEL_HLSL
#define FRESNEL_HLSL 1

#ifndef FRESNEL_MP
#define FRESNEL_MP min16float
#endif
#define FRESNEL_MP_CAT(t, n) t##n
#define FRESNEL_MP_VEC(t, n) FRESNEL_MP_CAT(t, n)
#define FRESNEL_MP3 FRESNEL_MP_VEC(FRESNEL_MP, 3)

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

/* ------------------------------------------------------------- helpers */

FRESNEL_MP fresnel_i_unit(FRESNEL_MP x) { return saturate(x); }
FRESNEL_MP3 fresnel_i_unit(FRESNEL_MP3 x) { return saturate(x); }
FRESNEL_MP fresnel_i_pow5(FRESNEL_MP x)
{
    FRESNEL_MP x2 = x * x;
    return x2 * x2 * x;
}
FRESNEL_MP3 fresnel_i_pow5(FRESNEL_MP3 x)
{
    FRESNEL_MP3 x2 = x * x;
    return x2 * x2 * x;
}
/* (1 - c)^p for c in [0, 1], p > 0. The C runtime uses exp(p log1p(-c));
 * HLSL has no log1p, and 1 - c is exact for c >= 0.5 (Sterbenz) so the
 * rounding p multiplies only exists where (1 - c)^p is large and its relative
 * error ~ p 6e-8 harmless. The base is >= 0 and 0 is answered without pow()
 * (pow(0, p) goes through log2(0) = -Inf). */
FRESNEL_MP fresnel_i_pow_one_minus(FRESNEL_MP c, FRESNEL_MP p)
{
    FRESNEL_MP x = 1.0 - c;
    return x > 0.0 ? pow(x, p) : 0.0;
}
float fresnel_i_kappa(float k)
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
float fresnel_i_eta2_minus_sin2(float eta, float c)
{
    float eh, ch;
    if (eta >= 1.0)
        return (eta - 1.0) * (eta + 1.0) + c * c;
    eh = floor(eta * 4096.0) * (1.0 / 4096.0);
    ch = floor(c * 4096.0) * (1.0 / 4096.0);
    return (ch * ch - (1.0 - eh) * (1.0 + eh)) + ((eta - eh) * (eta + eh) + (c - ch) * (c + ch));
}

/* ------------------------------------------------------------- Schlick */

/* F0 + (1 - F0)(1 - c)^5. mediump: (1-c)^5 underflows below 2^-14 for
 * c > 0.856, which changes F by < 6.1e-5 (ports/glsl/fresnel.glsl's file comment). */
FRESNEL_MP fresnel_schlick(FRESNEL_MP f0, FRESNEL_MP c)
{
    f0 = fresnel_i_unit(f0);
    return fresnel_i_unit(f0 + (1.0 - f0) * fresnel_i_pow5(1.0 - fresnel_i_unit(c)));
}
FRESNEL_MP3 fresnel_schlick_rgb(FRESNEL_MP3 f0, FRESNEL_MP c)
{
    f0 = fresnel_i_unit(f0);
    return fresnel_i_unit(f0 + (1.0 - f0) * fresnel_i_pow5(1.0 - fresnel_i_unit(c)));
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
    f0 = fresnel_i_unit(f0);
    f90 = fresnel_i_unit(f90);
    p = clamp(p, FRESNEL_P_MIN, FRESNEL_P_MAX);
    t = p == 5.0 ? fresnel_i_pow5(1.0 - c) : fresnel_i_pow_one_minus(c, p);
    return fresnel_i_unit(f0 + (f90 - f0) * t);
}

/* Schlick at the transmitted angle for eta < 1 (1 past the critical angle).
 * highp: eta^2 ct^2 = (eta-1)(eta+1) + c^2 cancels at the critical angle. */
float fresnel_schlick_internal(FRESNEL_MP f0, float eta, float c)
{
    float e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    float cc = saturate(c);
    float ct2;
    if (e >= 1.0)
        return fresnel_schlick(f0, cc);
    ct2 = fresnel_i_eta2_minus_sin2(e, cc);
    if (!(ct2 > 0.0))
        return 1.0;
    return fresnel_schlick(f0, sqrt(ct2) / e);
}
float3 fresnel_schlick_internal_rgb(FRESNEL_MP3 f0, float eta, float c)
{
    float e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    float cc = saturate(c);
    float ct2;
    if (e >= 1.0)
        return fresnel_schlick_rgb(f0, cc);
    ct2 = fresnel_i_eta2_minus_sin2(e, cc);
    if (!(ct2 > 0.0))
        return float3(1.0, 1.0, 1.0);
    return fresnel_schlick_rgb(f0, sqrt(ct2) / e);
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
float fresnel_i_f0_from_ior_hp(float eta, float kappa)
{
    float k2;
    eta = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    kappa = fresnel_i_kappa(kappa);
    k2 = kappa * kappa;
    return saturate(((eta - 1.0) * (eta - 1.0) + k2) / ((eta + 1.0) * (eta + 1.0) + k2));
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
    n = clamp(n, FRESNEL_ETA_MIN, FRESNEL_MP_IOR_MAX);
    k = clamp(k, 0.0, FRESNEL_MP_IOR_MAX);
    c = fresnel_i_unit(c);
    k2 = k * k;
    return fresnel_i_unit(((n - 1.0) * (n - 1.0) + 4.0 * n * fresnel_i_pow5(1.0 - c) + k2) /
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
    return float3(fresnel_lsk_comp(n.r, k.r, a.r, alpha.r, c), fresnel_lsk_comp(n.g, k.g, a.g, alpha.g, c),
                fresnel_lsk_comp(n.b, k.b, a.b, alpha.b, c));
}

/* ----------------------------------------------------------------- F82 */

/* F0 + (1-F0)(1-c)^5 - a c (1-c)^6, a = (7^7/6^6)(F0 - F82) + (49/6)(1 - F0),
 * clamped to [0, 1]. mediump: |a| <= 26; underflow as Schlick. The constants
 * are written out: in a mediump expression, 823543.0 / 46656.0 is folded after
 * 823543 has become binary16 Inf (measured with the GLSL port on llvmpipe:
 * F = 0 at c = 0).
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
    f0 = fresnel_i_unit(f0);
    f82 = fresnel_i_unit(f82);
    c = fresnel_i_unit(c);
    x = 1.0 - c;
    x5 = fresnel_i_pow5(x);
    a = FRESNEL_I_F82_A1 * (f0 - f82) + FRESNEL_I_F82_A2 * (1.0 - f0);
    return fresnel_i_unit(f0 + (1.0 - f0) * x5 - a * c * x5 * x);
}

/* --------------------------------------------------- approximate conductor */

/* rs = ((n-c)^2 + k^2) / ((n+c)^2 + k^2),
 * rp = ((nc-1)^2 + (kc)^2) / ((n^2+k^2)c^2 + 2nc + 1),  F = (rs + rp)/2.
 * mediump: n, k <= 100 keep both denominators <= 20201; the rp denominator
 * is >= 1; the rs denominator underflows only when n, k and c are all below
 * 2^-8, where rs = 1 is the limit. */
FRESNEL_MP fresnel_approx_conductor(FRESNEL_MP n, FRESNEL_MP k, FRESNEL_MP c)
{
    FRESNEL_MP kc, den_s;
    n = clamp(n, FRESNEL_ETA_MIN, FRESNEL_MP_IOR_MAX);
    k = clamp(k, 0.0, FRESNEL_MP_IOR_MAX);
    c = fresnel_i_unit(c);
    kc = k * c;
    den_s = (n + c) * (n + c) + k * k;
    return fresnel_i_unit(0.5 * ((den_s > 0.0 ? ((n - c) * (n - c) + k * k) / den_s : 1.0) +
                                 ((n * c - 1.0) * (n * c - 1.0) + kc * kc) /
                                     ((n * n + k * k) * c * c + 2.0 * n * c + 1.0)));
}
FRESNEL_MP3 fresnel_approx_conductor_rgb(FRESNEL_MP3 n, FRESNEL_MP3 k, FRESNEL_MP c)
{
    return float3(fresnel_approx_conductor(n.r, k.r, c), fresnel_approx_conductor(n.g, k.g, c),
                fresnel_approx_conductor(n.b, k.b, c));
}
/* The same in highp with the C domain (eta, kappa up to 1e5), for Gulbrandsen. */
float fresnel_i_approx_conductor_hp(float n, float k,
                                                  float c)
{
    float kc, rs, rp;
    n = clamp(n, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    k = fresnel_i_kappa(k);
    c = saturate(c);
    kc = k * c;
    rs = ((n - c) * (n - c) + k * k) / ((n + c) * (n + c) + k * k);
    rp = ((n * c - 1.0) * (n * c - 1.0) + kc * kc) / ((n * n + k * k) * c * c + 2.0 * n * c + 1.0);
    return saturate(0.5 * (rs + rp));
}

/* ---------------------------------------------------------- Gulbrandsen */

/* r, g -> (n, k), r clamped to [0, 0.9999]. highp (see ports/glsl/fresnel.glsl).
 * k^2 in the factored form of src/gulbrandsen.c. */
float2 fresnel_gulbrandsen_nk(float r, float g)
{
    float sr, nmin, nmax, n, k2;
    r = clamp(r, 0.0, FRESNEL_GULBRANDSEN_R_MAX);
    g = saturate(g);
    sr = sqrt(r);
    nmin = (1.0 - r) / (1.0 + r);
    nmax = (1.0 + sr) * (1.0 + sr) / (1.0 - r);
    n = g * nmin + (1.0 - g) * nmax;
    k2 = g * (nmax - nmin) * (sr * (n + 1.0) + n - 1.0) / (1.0 + sr);
    return float2(n, k2 > 0.0 ? sqrt(k2) : 0.0);
}

/* (n, k) -> (r, g); g clamped to [0, 1]. highp. */
float2 fresnel_gulbrandsen_rg(float n, float k)
{
    float r = fresnel_i_f0_from_ior_hp(n, k);
    float rc = min(r, FRESNEL_GULBRANDSEN_R_MAX);
    float sr = sqrt(rc);
    float nmin = (1.0 - rc) / (1.0 + rc);
    float nmax = (1.0 + sr) * (1.0 + sr) / (1.0 - rc);
    float span = nmax - nmin;
    n = clamp(n, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    return float2(r, span > 0.0 ? saturate((nmax - n) / span) : 0.0);
}

/* The approximate conductor at the (n, k) of (r, g). highp. */
float fresnel_gulbrandsen(float r, float g, float c)
{
    float2 nk = fresnel_gulbrandsen_nk(r, g);
    return fresnel_i_approx_conductor_hp(nk.x, nk.y, c);
}
float3 fresnel_gulbrandsen_rgb(float3 r, float3 g, float c)
{
    return float3(fresnel_gulbrandsen(r.r, g.r, c), fresnel_gulbrandsen(r.g, g.g, c),
                fresnel_gulbrandsen(r.b, g.b, c));
}

/* ------------------------------------------------------------ exact */

/* u + iv = sqrt((eta + i kappa)^2 - sin^2) on the decaying branch, and
 * m = u^2 + v^2, returned as (u, v, m). The smaller of u, v comes from
 * u v = eta kappa, never from (m - |A|)/2. eta, kappa already clamped. */
float3 fresnel_i_transmitted(float eta, float kappa,
                                         float c)
{
    float ek = eta * kappa;
    float a = fresnel_i_eta2_minus_sin2(eta, c) - kappa * kappa;
    float m = sqrt(a * a + 4.0 * ek * ek);
    float u, v;
    if (a >= 0.0) {
        u = sqrt(0.5 * (m + a));
        v = u > 0.0 ? ek / u : 0.0;
    } else {
        v = sqrt(0.5 * (m - a));
        u = ek / v;
    }
    return float3(u, v, m);
}

/* Exact unpolarised reflectance of eta + i kappa (fresnel.h). highp. */
float fresnel_conductor(float eta, float kappa, float c)
{
    float e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    float k = fresnel_i_kappa(kappa);
    float cc = saturate(c);
    float3 w;
    float p, q, den_s, den_p, rs, rp;
    if (e == 1.0 && k == 0.0)
        return 0.0; /* matched index: nothing reflected, also at c = 0 */
    w = fresnel_i_transmitted(e, k, cc);
    p = cc * ((e - k) * (e + k)); /* (eta + i kappa)^2 c = p + i q */
    q = 2.0 * e * k * cc;
    den_s = (cc + w.x) * (cc + w.x) + w.y * w.y;
    den_p = (p + w.x) * (p + w.x) + (q + w.y) * (q + w.y);
    rs = den_s > 0.0 ? ((cc - w.x) * (cc - w.x) + w.y * w.y) / den_s : 0.0;
    rp = den_p > 0.0 ? ((p - w.x) * (p - w.x) + (q - w.y) * (q - w.y)) / den_p : 0.0;
    return saturate(0.5 * (rs + rp));
}
float3 fresnel_conductor_rgb(float3 eta, float3 kappa, float c)
{
    return float3(fresnel_conductor(eta.r, kappa.r, c), fresnel_conductor(eta.g, kappa.g, c),
                fresnel_conductor(eta.b, kappa.b, c));
}

/* 1 - fresnel_conductor, from sums of non-negative terms (src/exact.c). */
float fresnel_i_conductor_transmittance(float e, float k,
                                                      float cc)
{
    float3 w;
    float p, q, den_s, den_p, ts, tp;
    if (e == 1.0 && k == 0.0)
        return 1.0;
    w = fresnel_i_transmitted(e, k, cc);
    p = cc * ((e - k) * (e + k));
    q = 2.0 * e * k * cc;
    den_s = (cc + w.x) * (cc + w.x) + w.y * w.y;
    den_p = (p + w.x) * (p + w.x) + (q + w.y) * (q + w.y);
    ts = den_s > 0.0 ? 4.0 * cc * w.x / den_s : 1.0;
    tp = den_p > 0.0 ? 4.0 * cc * w.x * (w.z + (1.0 - cc) * (1.0 + cc)) / den_p : 1.0;
    return saturate(0.5 * (ts + tp));
}

/* Exact dielectric, either side; 1 past the critical angle. highp. */
float fresnel_dielectric(float eta, float c)
{
    float e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    float cc = saturate(c);
    float a, w, e2c, rs, rp;
    if (e == 1.0)
        return 0.0;
    a = fresnel_i_eta2_minus_sin2(e, cc);
    if (a < 0.0)
        return 1.0; /* total internal reflection */
    w = sqrt(a);
    e2c = e * e * cc;
    rs = (cc - w) / (cc + w);
    rp = (e2c - w) / (e2c + w);
    return saturate(0.5 * (rs * rs + rp * rp));
}

/* -------------------------------------------------------- Cook-Torrance */

/* F0 + (1 - F0) (1 - T'(c)/T'(1)), T' the transmittance of one
 * representative eta + i kappa, T'(1) = 4 eta / ((eta+1)^2 + kappa^2).
 * F0 may be mediump; eta, kappa, c and the interpolant are highp. */
float fresnel_i_cook_torrance_t(float eta, float kappa,
                                              float c)
{
    float e = clamp(eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    float k = fresnel_i_kappa(kappa);
    float d = (e + 1.0) * (e + 1.0) + k * k;
    return clamp(1.0 - fresnel_i_conductor_transmittance(e, k, saturate(c)) * d / (4.0 * e), 0.0,
                 1.0);
}
float fresnel_cook_torrance(FRESNEL_MP f0, float eta, float kappa,
                            float c)
{
    float t = fresnel_i_cook_torrance_t(eta, kappa, c);
    f0 = fresnel_i_unit(f0);
    return fresnel_i_unit(f0 + (1.0 - f0) * t);
}
float3 fresnel_cook_torrance_rgb(FRESNEL_MP3 f0, float eta, float kappa,
                               float c)
{
    float t = fresnel_i_cook_torrance_t(eta, kappa, c);
    f0 = fresnel_i_unit(f0);
    return fresnel_i_unit(f0 + (1.0 - f0) * t);
}

/* --------------------------------------------------------------- LUTs */

/* Tables of src/lut.c: n nodes, uniform in sqrt(c), c_i = (i/(n-1))^2
 * (FRESNEL_LUT_*ARRAY*), or in c (FRESNEL_LUT_LINEAR_*); RGB tables hold n
 * red nodes, then n green, then n blue; the RESIDUAL forms add the table to
 * Schlick(F0). Tables are float arrays (static const, as `fresnel gen
 * --hlsl` writes them, or in a cbuffer), n an int; linear interpolation
 * with lerp() between the two nodes around c. Position, fetches and
 * interpolation in float: x (n - 1) in binary16 would keep 2-3 bits of the
 * fraction for n = 256. */
float2 fresnel_i_lut_pos(float n, float x)
{
    float pos = x * (n - 1.0);
    float i = min(floor(pos), n - 2.0); /* x = 1 ends the last segment */
    return float2(i, pos - i);
}
/* Node index (floor) and fraction of c in an n-node table. */
float2 fresnel_lut_pos(float n, float c)
{
    return fresnel_i_lut_pos(n, sqrt(saturate(c)));
}
float2 fresnel_lut_linear_pos(float n, float c)
{
    return fresnel_i_lut_pos(n, saturate(c));
}
float fresnel_lut_lerp(float a, float b, float t)
{
    return lerp(a, b, t);
}
/* table: a float array of n or 3n nodes; each macro is one expression. */
#define FRESNEL_I_LUT_AT(table, base, p) fresnel_lut_lerp((table)[(base) + (int)((p).x)], (table)[(base) + (int)((p).x) + 1], (p).y)
#define FRESNEL_I_LUT_AT_RGB(table, n, p) float3(FRESNEL_I_LUT_AT(table, 0, p), FRESNEL_I_LUT_AT(table, (n), p), FRESNEL_I_LUT_AT(table, 2 * (n), p))
#define FRESNEL_LUT_ARRAY(table, n, c) saturate(FRESNEL_I_LUT_AT(table, 0, fresnel_lut_pos((float)(n), (c))))
#define FRESNEL_LUT_LINEAR_ARRAY(table, n, c) saturate(FRESNEL_I_LUT_AT(table, 0, fresnel_lut_linear_pos((float)(n), (c))))
#define FRESNEL_LUT_RESIDUAL_ARRAY(f0, table, n, c) fresnel_i_unit(fresnel_schlick((f0), (c)) + FRESNEL_I_LUT_AT(table, 0, fresnel_lut_pos((float)(n), (c))))
#define FRESNEL_LUT_LINEAR_RESIDUAL_ARRAY(f0, table, n, c) fresnel_i_unit(fresnel_schlick((f0), (c)) + FRESNEL_I_LUT_AT(table, 0, fresnel_lut_linear_pos((float)(n), (c))))
#define FRESNEL_LUT_ARRAY_RGB(table, n, c) saturate(FRESNEL_I_LUT_AT_RGB(table, (n), fresnel_lut_pos((float)(n), (c))))
#define FRESNEL_LUT_LINEAR_ARRAY_RGB(table, n, c) saturate(FRESNEL_I_LUT_AT_RGB(table, (n), fresnel_lut_linear_pos((float)(n), (c))))
#define FRESNEL_LUT_RESIDUAL_ARRAY_RGB(f0, table, n, c) fresnel_i_unit(fresnel_schlick_rgb((f0), (c)) + FRESNEL_I_LUT_AT_RGB(table, (n), fresnel_lut_pos((float)(n), (c))))
#define FRESNEL_LUT_LINEAR_RESIDUAL_ARRAY_RGB(f0, table, n, c) fresnel_i_unit(fresnel_schlick_rgb((f0), (c)) + FRESNEL_I_LUT_AT_RGB(table, (n), fresnel_lut_linear_pos((float)(n), (c))))

/* fresnel_lut_cubic (src/lut.c): Catmull-Rom through the four nodes around
 * sqrt(c), the outer ones clamped to the table's ends; tables fitted for it
 * (lutN-cubic). */
float fresnel_lut_cubic_blend(float p0, float p1, float p2,
                                            float p3, float t)
{
    float d = p2 - p1, m1 = 0.5 * (p2 - p0), m2 = 0.5 * (p3 - p1);
    return p1 + t * (m1 + t * ((3.0 * d - 2.0 * m1 - m2) + t * (m1 + m2 - 2.0 * d)));
}
#define FRESNEL_I_LUT_CUBIC_AT(table, base, n, p) fresnel_lut_cubic_blend((table)[(base) + max((int)((p).x) - 1, 0)], (table)[(base) + (int)((p).x)], (table)[(base) + (int)((p).x) + 1], (table)[(base) + min((int)((p).x) + 2, (n) - 1)], (p).y)
#define FRESNEL_LUT_CUBIC_ARRAY(table, n, c) saturate(FRESNEL_I_LUT_CUBIC_AT(table, 0, (n), fresnel_lut_pos((float)(n), (c))))
#define FRESNEL_LUT_CUBIC_ARRAY_RGB(table, n, c) saturate(float3(FRESNEL_I_LUT_CUBIC_AT(table, 0, (n), fresnel_lut_pos((float)(n), (c))), FRESNEL_I_LUT_CUBIC_AT(table, (n), (n), fresnel_lut_pos((float)(n), (c))), FRESNEL_I_LUT_CUBIC_AT(table, 2 * (n), (n), fresnel_lut_pos((float)(n), (c)))))


#endif /* FRESNEL_HLSL */
