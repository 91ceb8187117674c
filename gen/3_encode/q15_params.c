/* Double -> fixed-point parameters (see q15_params.h and the LAYOUT section
 * of include/fresnel_q15.h). */
#include "3_encode/q15_params.h"

#include <math.h>

#include "fresnel.h"
#include "common/reference.h"

fresnel_qf q15_qf(double x)
{
    fresnel_qf q = {0, 0};
    int k;
    double f, m;
    if (!(x > 0.0))
        return q;
    f = frexp(x, &k); /* [0.5, 1) */
    m = floor(f * 2147483648.0 + 0.5);
    q.e = k - 31;
    if (m >= 2147483648.0) {
        m = 1073741824.0;
        q.e += 1;
    }
    q.m = (uint32_t)m;
    return q;
}

double q15_qf_value(fresnel_qf x) { return ldexp((double)x.m, x.e); }

int32_t q15_code(double x)
{
    return (int32_t)floor(ref_clamp(x, 0.0, 65535.0 / 32768.0) * 32768.0 + 0.5);
}

fresnel_q16 q16_code(double x)
{
    double v = floor(x * 65536.0 + 0.5);
    return v >= 2147483647.0 ? 2147483647 : (v <= -2147483648.0 ? (fresnel_q16)-2147483647 - 1 : (fresnel_q16)v);
}

static double eta_dom(double x) { return ref_clamp(x, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX); }
static double kappa_dom(double x)
{
    return x >= FRESNEL_KAPPA_TINY ? (x < FRESNEL_KAPPA_MAX ? x : FRESNEL_KAPPA_MAX) : 0.0;
}

void q15_ior(double eta, double kappa, fresnel_ior_prep_q15 *out)
{
    double eh, el, d, x, hi;
    int s;
    eta = eta_dom(eta);
    kappa = kappa_dom(kappa);
    /* D = eta^2 - kappa^2 - 1 with eta^2 exact in two doubles (fma): near
     * eta = 1, the dielectric critical-angle case, D has all its digits */
    eh = eta * eta;
    el = fma(eta, eta, -eh);
    d = ((eh - 1.0) + el) - kappa * kappa;
    /* the smallest shift whose ROUNDED a0 leaves room for c^2 in int32 */
    for (s = 0;; s++) {
        x = fabs(d) * ldexp(1.0, 30 - s);
        hi = floor(x + 0.5);
        if (s == 30 || hi + ldexp(1.0, 30 - s) <= 2147483647.0)
            break;
    }
    if (hi + ldexp(1.0, 30 - s) > 2147483647.0) { /* beyond the domain: saturate */
        hi = 2147483646.0;
        x = hi;
    }
    out->shift = s;
    out->a0 = d < 0.0 ? -(int32_t)hi : (int32_t)hi;
    /* x - hi is exact (both near each other), and at most 1/2 */
    out->a0_lo = (int32_t)floor((x - hi) * 1073741824.0 + 0.5) * (d < 0.0 ? -1 : 1);
    out->b = q15_qf(2.0 * eta * kappa);
    out->n4 = q15_qf((eta * eta + kappa * kappa) * (eta * eta + kappa * kappa));
    out->t1_inv = q15_qf(((eta + 1.0) * (eta + 1.0) + kappa * kappa) / (4.0 * eta));
    out->inv_eta2 = q15_qf(1.0 / (eta * eta));
}

void q15_conductor_fast(double eta, double kappa, fresnel_conductor_prep_q15_fast *out)
{
    double eh, el, d, x, hi = 0.0, b;
    int s, k, two;
    eta = eta_dom(eta);
    kappa = kappa_dom(kappa);
    eh = eta * eta;
    el = fma(eta, eta, -eh);
    d = ((eh - 1.0) + el) - kappa * kappa;
    b = 2.0 * eta * kappa;
    /* the smallest shift whose rounded a0 keeps a0 + [0, 2^(30-s)] in int32,
     * and b 2^(30-s) too */
    for (s = 0; s < 30; s++) {
        hi = floor(d * ldexp(1.0, 30 - s) + 0.5);
        if (hi >= -2147483647.0 && hi + ldexp(1.0, 30 - s) <= 2147483647.0 && b * ldexp(1.0, 30 - s) < 2147483647.0)
            break;
    }
    x = d * ldexp(1.0, 30 - s);
    hi = floor(x + 0.5);
    out->shift = s;
    out->a0 = (int32_t)hi;
    out->a0_lo = (int32_t)floor((x - hi) * 65536.0 + 0.5);
    out->b1 = (int32_t)floor(b * ldexp(1.0, 30 - s) + 0.5);
    x = floor(b * ldexp(1.0, 46 - s) + 0.5);
    /* the two-word A only where b is small too, and at s = 0, where a0 + c^2
     * drops no bit of c^2 (fresnel_q15_fast.h: shift > 0 only where
     * |A| >= 1 at every c, which one word holds) */
    two = s == 0 && out->b1 < 32768;
    out->b2 = two ? (int32_t)x : 0;
    out->span = two ? 65535u : 0u;
    if (b > 0.0) {
        double f = frexp(b, &k); /* [0.5, 1) */
        double m = floor(f * 65536.0 + 0.5);
        if (m >= 65536.0) {
            m = 32768.0;
            k++;
        }
        out->bm = (int32_t)m;
        out->be = 16 - k;
    } else {
        out->bm = 0;
        out->be = 255;
    }
}

int q15_conductor_fast_in_domain(double eta, double kappa)
{
    return eta >= FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST && eta <= FRESNEL_CONDUCTOR_ETA_MAX_Q15_FAST && kappa >= 0.0 &&
           (kappa >= 0.1 || eta >= FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST_DIELECTRIC) &&
           kappa <= FRESNEL_CONDUCTOR_KAPPA_MAX_Q15_FAST &&
           hypot(eta * eta - kappa * kappa - 1.0, 2.0 * eta * kappa) >= FRESNEL_CONDUCTOR_MATCH_MIN_Q15_FAST;
}

void q15_nk(double n, double k, fresnel_nk_prep_q15 *out)
{
    n = eta_dom(n);
    k = kappa_dom(k);
    out->n = q15_qf(n);
    out->nk2 = q15_qf(n * n + k * k);
}

void q15_lsk(double n, double k, double a, double alpha, fresnel_lsk_prep_q15 *out)
{
    out->f0 = (uint32_t)floor(ref_f0_from_ior(n, k) * 1073741824.0 + 0.5);
    out->a = q15_qf(ref_clamp(a, 0.0, FRESNEL_A_MAX));
    out->alpha = q16_code(ref_clamp(alpha, 0.0, FRESNEL_ALPHA_MAX));
}

int32_t q15_f82_a_q12(int32_t f0, int32_t f82)
{
    double F0 = (f0 < 0 ? 0 : (f0 > 32768 ? 32768 : f0)) / 32768.0;
    double F82 = (f82 < 0 ? 0 : (f82 > 32768 ? 32768 : f82)) / 32768.0;
    return (int32_t)lround(4096.0 * ref_f82_a(F0, F82));
}
