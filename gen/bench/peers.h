/* Other renderers' exact conductor Fresnel, this project's own binary32
 * transcriptions of their published formulas (no code of theirs), as static
 * inline functions: `make bench` (tests/speed/) times each inlined in an array
 * loop, as a renderer runs its header code, and out of line through
 * gen/bench/bench_compare.c. Never part of the runtime.
 *
 * The versions they follow:
 *   - Mitsuba 3, fresnel_conductor in include/mitsuba/render/fresnel.h (its
 *     comment: "modified from Optics by K. D. Moeller"); MaterialX's
 *     mx_fresnel_conductor is the same form;
 *   - pbrt-v4, FrComplex(Float, pstd::complex<Float>) in
 *     src/pbrt/util/scattering.h (Pharr, Jakob, Humphreys, Physically Based
 *     Rendering, 4th ed., section 9.5).
 * Both take c clamped to [0, 1] here (pbrt-v4 clamps; Mitsuba 3 assumes it),
 * so they see the inputs the library's functions see. */
#ifndef FRESNEL_BENCH_PEERS_H
#define FRESNEL_BENCH_PEERS_H

#include <math.h>

static inline float peer_clamp01(float c) { return c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f; }
static inline float peer_sqrt0(float x) { return sqrtf(x > 0.0f ? x : 0.0f); }

/* Mitsuba 3's real form, binary32 throughout:
 *   A = eta^2 - kappa^2 - sin^2,  a^2 + b^2 = sqrt(A^2 + 4 eta^2 kappa^2),
 *   a = sqrt((a^2 + b^2 + A)/2)   (square roots of max(0, x)),
 *   Rs = (a^2+b^2 + c^2 - 2ac) / (a^2+b^2 + c^2 + 2ac),
 *   Rp = Rs (c^2 (a^2+b^2) + sin^4 - 2ac sin^2) / (c^2 (a^2+b^2) + sin^4 + 2ac sin^2),
 * sin^2 = 1 - c^2 rounded, F = (Rs + Rp)/2. */
static inline float peer_mitsuba_conductor(float eta, float kappa, float c)
{
    float c2, s2, s4, a0, ab, a, t1, t2, t3, t4, rs, rp;
    c = peer_clamp01(c);
    c2 = c * c;
    s2 = 1.0f - c2;
    s4 = s2 * s2;
    a0 = eta * eta - kappa * kappa - s2;
    ab = peer_sqrt0(a0 * a0 + 4.0f * kappa * kappa * eta * eta); /* a^2 + b^2 */
    a = peer_sqrt0(0.5f * (ab + a0));
    t1 = ab + c2;
    t2 = 2.0f * c * a;
    rs = (t1 - t2) / (t1 + t2);
    t3 = ab * c2 + s4;
    t4 = t2 * s2;
    rp = rs * (t3 - t4) / (t3 + t4);
    return 0.5f * (rs + rp);
}

/* pbrt-v4's complex form on the relative index n = eta + i kappa:
 *   sin^2 t = (1 - c^2) / n^2,  cos t = sqrt(1 - sin^2 t)   (principal root),
 *   r_par = (n c - cos t) / (n c + cos t),  r_perp = (c - n cos t) / (c + n cos t),
 *   F = (|r_par|^2 + |r_perp|^2) / 2,
 * with textbook complex division ((a c + b d) + i (b c - a d)) / (c^2 + d^2)
 * (one reciprocal) and square root t1 = sqrt((|z| + |Re z|)/2),
 * t2 = Im z / (2 t1) (swapped, with signs, for Re z < 0). */
typedef struct peer_cx {
    float re, im;
} peer_cx;

static inline peer_cx peer_cx_make(float re, float im)
{
    peer_cx z;
    z.re = re;
    z.im = im;
    return z;
}
static inline peer_cx peer_cx_add(peer_cx a, peer_cx b) { return peer_cx_make(a.re + b.re, a.im + b.im); }
static inline peer_cx peer_cx_sub(peer_cx a, peer_cx b) { return peer_cx_make(a.re - b.re, a.im - b.im); }
static inline peer_cx peer_cx_mul(peer_cx a, peer_cx b)
{
    return peer_cx_make(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re);
}
static inline peer_cx peer_cx_scale(peer_cx a, float s) { return peer_cx_make(a.re * s, a.im * s); }
static inline float peer_cx_norm(peer_cx a) { return a.re * a.re + a.im * a.im; }
static inline peer_cx peer_cx_div(peer_cx a, peer_cx b)
{
    float s = 1.0f / peer_cx_norm(b);
    return peer_cx_make(s * (a.re * b.re + a.im * b.im), s * (a.im * b.re - a.re * b.im));
}
static inline peer_cx peer_cx_sqrt(peer_cx z)
{
    float n = sqrtf(peer_cx_norm(z)), t1, t2;
    if (n == 0.0f)
        return peer_cx_make(0.0f, 0.0f);
    t1 = sqrtf(0.5f * (n + fabsf(z.re)));
    t2 = 0.5f * z.im / t1;
    if (z.re >= 0.0f)
        return peer_cx_make(t1, t2);
    return peer_cx_make(fabsf(t2), copysignf(t1, z.im));
}

static inline float peer_pbrt_conductor(float eta, float kappa, float c)
{
    peer_cx n = peer_cx_make(eta, kappa), sin2t, cost, nc, ncost, r_par, r_perp;
    float s2;
    c = peer_clamp01(c);
    s2 = 1.0f - c * c;
    sin2t = peer_cx_div(peer_cx_make(s2, 0.0f), peer_cx_mul(n, n));
    cost = peer_cx_sqrt(peer_cx_sub(peer_cx_make(1.0f, 0.0f), sin2t));
    nc = peer_cx_scale(n, c);
    r_par = peer_cx_div(peer_cx_sub(nc, cost), peer_cx_add(nc, cost));
    ncost = peer_cx_mul(n, cost);
    r_perp = peer_cx_div(peer_cx_sub(peer_cx_make(c, 0.0f), ncost), peer_cx_add(peer_cx_make(c, 0.0f), ncost));
    return 0.5f * (peer_cx_norm(r_par) + peer_cx_norm(r_perp));
}

#endif
