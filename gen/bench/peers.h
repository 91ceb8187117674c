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
 * so they see the inputs the library's functions see.
 *
 * And the real-time thin film: KHR_materials_iridescence as the glTF 2.0
 * extension specifies it and the Khronos glTF Sample Viewer evaluates it,
 * in binary32 (peer_khr_iridescence_rgb; the double-precision reference and
 * its sources: ref_film_khr_iridescence, gen/common/reference_film.h), and
 * the same family with the exact polarised Fresnel equations on a base of
 * per-channel eta, kappa (peer_belcour_polarised_rgb;
 * ref_film_belcour_polarised). */
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

/* KHR_materials_iridescence in binary32, in air (outside index 1): the
 * film's index and thickness in nm, cos theta, the base's F0 per channel.
 * The same steps as ref_film_khr_iridescence: Schlick at both interfaces,
 * the base's index from its F0, orders 0-2 of the Airy series with the
 * Gaussian fits of the XYZ sensitivities, linear Rec. 709, negatives to 0. */
static inline void peer_khr_sensitivity(float opd, const float phi[3], float rgb[3])
{
    static const float amp[3] = {5.4856e-13f, 4.4201e-13f, 5.2481e-13f};
    static const float centre[3] = {1.6810e+06f, 1.7953e+06f, 2.2084e+06f};
    static const float var[3] = {4.3278e+09f, 9.3046e+09f, 6.6121e+09f};
    static const float to_709[3][3] = {
        {3.2404542f, -1.5371385f, -0.4985314f}, {-0.9692660f, 1.8760108f, 0.0415560f}, {0.0556434f, -0.2040259f, 1.0572252f}};
    const float two_pi = 6.28318531f;
    float phase = two_pi * opd * 1e-9f, xyz[3];
    int ch;
    for (ch = 0; ch < 3; ch++)
        xyz[ch] = amp[ch] * sqrtf(two_pi * var[ch]) * cosf(centre[ch] * phase + phi[ch]) * expf(-phase * phase * var[ch]);
    xyz[0] += 9.7470e-14f * sqrtf(two_pi * 4.5282e+09f) * cosf(2.2399e+06f * phase + phi[0]) *
              expf(-4.5282e+09f * phase * phase);
    for (ch = 0; ch < 3; ch++)
        xyz[ch] /= 1.0685e-7f;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = to_709[ch][0] * xyz[0] + to_709[ch][1] * xyz[1] + to_709[ch][2] * xyz[2];
}

static inline float peer_khr_schlick(float f0, float c)
{
    float m = 1.0f - c, m2 = m * m;
    return f0 + (1.0f - f0) * m2 * m2 * m;
}

static inline void peer_khr_iridescence_rgb(float film_ior, float d_nm, float c, const float base_f0[3], float rgb[3])
{
    const float pi = 3.14159265f;
    float t = d_nm / 0.03f, fade = d_nm <= 0.0f ? 0.0f : (d_nm >= 0.03f ? 1.0f : t * t * (3.0f - 2.0f * t));
    float eta2 = 1.0f + (film_ior - 1.0f) * fade, cos2_sq = 1.0f - (1.0f - c * c) / (eta2 * eta2), cos2;
    float r0, r12, t121, phi21, opd, sens[3], phi[3], r123[3], amp[3];
    int ch, m;
    if (cos2_sq < 0.0f) {
        rgb[0] = rgb[1] = rgb[2] = 1.0f;
        return;
    }
    cos2 = sqrtf(cos2_sq);
    r0 = (eta2 - 1.0f) / (eta2 + 1.0f);
    r12 = peer_khr_schlick(r0 * r0, c);
    t121 = 1.0f - r12;
    phi21 = eta2 < 1.0f ? 0.0f : pi;
    opd = 2.0f * eta2 * d_nm * cos2;
    for (ch = 0; ch < 3; ch++) {
        float f0 = base_f0[ch] < 0.0f ? 0.0f : (base_f0[ch] > 0.9999f ? 0.9999f : base_f0[ch]), s = sqrtf(f0);
        float base_ior = (1.0f + s) / (1.0f - s), r1 = (base_ior - eta2) / (base_ior + eta2);
        float r23 = peer_khr_schlick(r1 * r1, cos2), rs;
        phi[ch] = phi21 + (base_ior < eta2 ? pi : 0.0f);
        r123[ch] = r12 * r23;
        r123[ch] = r123[ch] < 1e-5f ? 1e-5f : (r123[ch] > 0.9999f ? 0.9999f : r123[ch]);
        rs = t121 * t121 * r23 / (1.0f - r123[ch]);
        rgb[ch] = r12 + rs;
        amp[ch] = rs - t121;
    }
    for (m = 1; m <= 2; m++) {
        float phim[3];
        for (ch = 0; ch < 3; ch++) {
            amp[ch] *= sqrtf(r123[ch]);
            phim[ch] = (float)m * phi[ch];
        }
        peer_khr_sensitivity((float)m * opd, phim, sens);
        for (ch = 0; ch < 3; ch++)
            rgb[ch] += amp[ch] * 2.0f * sens[ch];
    }
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = rgb[ch] > 0.0f ? rgb[ch] : 0.0f;
}

/* Belcour and Barla's polarised form in binary32, in air: the film's index
 * and thickness in nm, cos theta, the base's eta and kappa per channel. The
 * same function as ref_film_belcour_polarised, arranged as a renderer at its
 * best would run it: each order's Gaussian envelopes (the exponentials) and
 * carrier (cos and sin of centre x phase) computed once and shared by the
 * three channels and two polarisations, and each interface's phase taken as
 * the unit vector of its amplitude coefficient (cos and sin of phi21 + phi23
 * without atan2), so that cos(centre x phase + m phi) is two products; orders
 * 0-2 per polarisation and channel, averaged; negatives to 0. */
static inline void peer_belcour_polarised_rgb(float film_ior, float d_nm, float c, const float eta[3],
                                              const float kappa[3], float rgb[3])
{
    static const float amp[4] = {5.4856e-13f, 4.4201e-13f, 5.2481e-13f, 9.7470e-14f};
    static const float centre[4] = {1.6810e+06f, 1.7953e+06f, 2.2084e+06f, 2.2399e+06f};
    static const float var[4] = {4.3278e+09f, 9.3046e+09f, 6.6121e+09f, 4.5282e+09f};
    static const float to_709[3][3] = {
        {3.2404542f, -1.5371385f, -0.4985314f}, {-0.9692660f, 1.8760108f, 0.0415560f}, {0.0556434f, -0.2040259f, 1.0572252f}};
    const float two_pi = 6.28318531f;
    float t = d_nm / 0.03f, fade = d_nm <= 0.0f ? 0.0f : (d_nm >= 0.03f ? 1.0f : t * t * (3.0f - 2.0f * t));
    float n2 = 1.0f + (film_ior - 1.0f) * fade, sin2_sq = (1.0f - c * c) / (n2 * n2), cos2_sq = 1.0f - sin2_sq;
    float cos2, opd, r12[2], env[2][4], ca[2][4], sa[2][4];
    int ch, pol, m, k;
    if (cos2_sq < 0.0f) {
        rgb[0] = rgb[1] = rgb[2] = 1.0f;
        return;
    }
    cos2 = sqrtf(cos2_sq);
    opd = 2.0f * n2 * d_nm * cos2;
    r12[0] = c + n2 * cos2 > 0.0f ? (c - n2 * cos2) / (c + n2 * cos2) : 0.0f; /* 0/0: grazing, no film */
    r12[1] = n2 * c + cos2 > 0.0f ? (n2 * c - cos2) / (n2 * c + cos2) : 0.0f;
    for (m = 0; m < 2; m++) { /* orders 1 and 2: the envelopes and carriers of x (two lobes), y, z */
        float phase = two_pi * (float)(m + 1) * opd * 1e-9f;
        for (k = 0; k < 4; k++) {
            env[m][k] = amp[k] * sqrtf(two_pi * var[k]) / 1.0685e-7f * expf(-phase * phase * var[k]);
            ca[m][k] = cosf(centre[k] * phase);
            sa[m][k] = sinf(centre[k] * phase);
        }
    }
    for (ch = 0; ch < 3; ch++) {
        peer_cx n3 = peer_cx_make(eta[ch], kappa[ch]), n3sq = peer_cx_mul(n3, n3);
        peer_cx n3cos3 = peer_cx_sqrt(peer_cx_sub(n3sq, peer_cx_make(n2 * n2 * sin2_sq, 0.0f)));
        peer_cx a = peer_cx_make(n2 * cos2, 0.0f), r23[2];
        float sum = 0.0f;
        r23[0] = peer_cx_div(peer_cx_sub(a, n3cos3), peer_cx_add(a, n3cos3));
        r23[1] = peer_cx_div(peer_cx_sub(peer_cx_scale(n3sq, cos2), peer_cx_scale(n3cos3, n2)),
                             peer_cx_add(peer_cx_scale(n3sq, cos2), peer_cx_scale(n3cos3, n2)));
        for (pol = 0; pol < 2; pol++) {
            float big_r12 = r12[pol] * r12[pol], t121 = 1.0f - big_r12, big_r23 = peer_cx_norm(r23[pol]);
            float r123 = big_r12 * big_r23 < 0.9999f ? big_r12 * big_r23 : 0.9999f;
            float rs = t121 * t121 * big_r23 / (1.0f - r123), amp_m = rs - t121, v = big_r12 + rs;
            /* e^{i phi}, phi = arg(-r12) + arg(r23); phi = 0 where r23 = 0 */
            float norm = sqrtf(big_r23), sign = r12[pol] > 0.0f ? -1.0f : 1.0f;
            float cp = norm > 0.0f ? sign * r23[pol].re / norm : 1.0f, sp = norm > 0.0f ? sign * r23[pol].im / norm : 0.0f;
            float cpm = cp, spm = sp;
            for (m = 0; m < 2; m++) {
                float xyz[3], s_rgb;
                if (m == 1) { /* e^{2 i phi} */
                    cpm = cp * cp - sp * sp;
                    spm = 2.0f * cp * sp;
                }
                for (k = 0; k < 3; k++)
                    xyz[k] = env[m][k] * (ca[m][k] * cpm - sa[m][k] * spm);
                xyz[0] += env[m][3] * (ca[m][3] * cpm - sa[m][3] * spm);
                s_rgb = to_709[ch][0] * xyz[0] + to_709[ch][1] * xyz[1] + to_709[ch][2] * xyz[2];
                amp_m *= sqrtf(r123);
                v += amp_m * 2.0f * s_rgb;
            }
            sum += 0.5f * v;
        }
        rgb[ch] = sum > 0.0f ? sum : 0.0f;
    }
}

#endif
