/* The exact Fresnel equations: conductors (complex index) and dielectrics.
 *
 * The textbook form [LS05, Hof20] computes 2a^2 = sqrt(A^2 + 4 eta^2 kappa^2) + A
 * with A = eta^2 - kappa^2 - sin^2 theta, and 2b^2 the same with -A. When
 * kappa >> eta, A is large and negative and a^2 is the difference of two
 * nearly equal numbers (gold in the red: eta 0.15, kappa 3.5 loses about
 * half its digits in binary32). Here a = u and b = v are the real and
 * imaginary parts of sqrt((eta + i kappa)^2 - sin^2), and the smaller of the
 * two is taken from u v = eta kappa instead. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT
#include <math.h>

/* u + iv = sqrt((eta + i kappa)^2 - sin^2 theta) on the decaying branch, and
 * m = u^2 + v^2. */
struct fr__root {
    float u, v, m;
};

static inline struct fr__root fr__transmitted(float eta, float kappa, float c)
{
    struct fr__root w;
    float ek = eta * kappa;
    float a = fr__eta2_minus_sin2(eta, c, kappa * kappa);
    w.m = sqrtf(a * a + 4.0f * ek * ek);
    if (a >= 0.0f) {
        w.u = sqrtf(0.5f * (w.m + a));
        w.v = w.u > 0.0f ? ek / w.u : 0.0f;
    } else {
        w.v = sqrtf(0.5f * (w.m - a)); /* > 0: m - a >= -2a > 0 */
        w.u = ek / w.v;
    }
    return w;
}

float fresnel_conductor(float eta, float kappa, float c)
{
    struct fr__root w;
    float p, q, num_s, den_s, num_p, den_p, rs, rp;
    eta = fr__eta(eta);
    kappa = fr__kappa(kappa);
    c = fr__unit(c);
    /* Matched index: no interface, nothing reflected, at every c including
     * c = 0 where the limit depends on the direction of approach (and where
     * c^2 underflows for c < 1e-19, so it must not be computed from c). */
    if (eta == 1.0f && kappa == 0.0f)
        return 0.0f;
    w = fr__transmitted(eta, kappa, c);
    /* (eta + i kappa)^2 c = p + i q */
    p = c * ((eta - kappa) * (eta + kappa));
    q = 2.0f * eta * kappa * c;
    num_s = (c - w.u) * (c - w.u) + w.v * w.v;
    den_s = (c + w.u) * (c + w.u) + w.v * w.v;
    num_p = (p - w.u) * (p - w.u) + (q - w.v) * (q - w.v);
    den_p = (p + w.u) * (p + w.u) + (q + w.v) * (q + w.v);
    /* Denominators are >= m > 0 away from matched index. */
    rs = den_s > 0.0f ? num_s / den_s : 0.0f;
    rp = den_p > 0.0f ? num_p / den_p : 0.0f;
    return fr__unit(0.5f * (rs + rp));
}

fresnel_rgb fresnel_conductor_rgb(fresnel_rgb eta, fresnel_rgb kappa, float c)
{
    FR__RGB(fresnel_conductor(eta.r, kappa.r, c), fresnel_conductor(eta.g, kappa.g, c),
            fresnel_conductor(eta.b, kappa.b, c));
}

float fr__conductor_transmittance(float eta, float kappa, float c)
{
    /* |a+b|^2 - |a-b|^2 = 4 Re(a conj b) gives 1 - Rs = 4cu / den_s and
     * 1 - Rp = 4 (p u + q v) / den_p, and with u v = eta kappa,
     * p u + q v = c u (m + sin^2): sums of non-negative terms only. */
    struct fr__root w;
    float p, q, den_s, den_p, ts, tp, s2;
    eta = fr__eta(eta);
    kappa = fr__kappa(kappa);
    c = fr__unit(c);
    if (eta == 1.0f && kappa == 0.0f)
        return 1.0f; /* matched index, as in fresnel_conductor */
    w = fr__transmitted(eta, kappa, c);
    p = c * ((eta - kappa) * (eta + kappa));
    q = 2.0f * eta * kappa * c;
    s2 = (1.0f - c) * (1.0f + c);
    den_s = (c + w.u) * (c + w.u) + w.v * w.v;
    den_p = (p + w.u) * (p + w.u) + (q + w.v) * (q + w.v);
    ts = den_s > 0.0f ? 4.0f * c * w.u / den_s : 1.0f;
    tp = den_p > 0.0f ? 4.0f * c * w.u * (w.m + s2) / den_p : 1.0f;
    return fr__unit(0.5f * (ts + tp));
}

float fresnel_dielectric(float eta, float c)
{
    float a, w, e2c, rs, rp;
    eta = fr__eta(eta);
    c = fr__unit(c);
    if (eta == 1.0f)
        return 0.0f; /* matched index, as in fresnel_conductor */
    a = fr__eta2_minus_sin2(eta, c, 0.0f);
    if (a < 0.0f)
        return 1.0f; /* total internal reflection */
    w = sqrtf(a);
    e2c = eta * eta * c;
    /* c + w > 0: w = 0 needs a = 0, which with eta != 1 needs c > 0. */
    rs = (c - w) / (c + w);
    rp = (e2c - w) / (e2c + w);
    return fr__unit(0.5f * (rs * rs + rp * rp));
}

#else
typedef int fr__exact_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
