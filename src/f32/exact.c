/* The exact Fresnel equations: conductors (complex index) and dielectrics.
 *
 * The textbook form [LS05, Hof20] computes 2a^2 = sqrt(A^2 + 4 eta^2 kappa^2) + A
 * with A = eta^2 - kappa^2 - sin^2 theta, and 2b^2 the same with -A. When
 * kappa >> eta, A is large and negative and a^2 is the difference of two
 * nearly equal numbers (gold in the red: eta 0.15, kappa 3.5 loses about
 * half its digits in binary32). Here a = u and b = v are the real and
 * imaginary parts of sqrt((eta + i kappa)^2 - sin^2), and the smaller of the
 * two is taken from u v = eta kappa instead. That division is folded into
 * the ratios and Rs + Rp is one division (fresnel_i_exact_f), and a
 * material may be prepared once for many cosines (fresnel_conductor_prepare). */
#include "internal.h"
#include "exact_batch.h"

#if FRESNEL_HAS_FLOAT
#include <math.h>

/* u + iv = sqrt((eta + i kappa)^2 - sin^2 theta) on the decaying branch, and
 * m = u^2 + v^2. */
struct fresnel_i_root {
    float u, v, m;
};

static inline struct fresnel_i_root fresnel_i_transmitted(float eta, float kappa, float c)
{
    struct fresnel_i_root w;
    float ek = eta * kappa;
    float a = fresnel_i_eta2_minus_sin2(eta, c, kappa * kappa);
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

/* The rest of the exact form once A = eta^2 - kappa^2 - sin^2 is known, in
 * the a^2 + b^2 / 2ac arrangement of the textbook (Moeller, Optics) with u
 * taken where it has its digits:
 *   m = |A + 2i eta kappa| = u^2 + v^2,  t = (m + |A|)/2,  B = sqrt(t),
 *   u = B if A >= 0, else eta kappa / B (u v = eta kappa: no cancellation),
 *   Rs = (m + c^2 - 2cu) / (m + c^2 + 2cu),
 *   Rp = Rs P,  P = (c^2 m + s^4 - 2cu s^2) / (c^2 m + s^4 + 2cu s^2),  s^2 = 1 - c^2,
 *   F = (Rs + Rp)/2 = Rs (1 + P)/2.
 * The division for u is folded into the ratios: with X = 1, Y = B (A >= 0)
 * or X = B, Y = eta kappa (A < 0), X u = Y, and numerator and denominator of
 * Rs and of P are multiplied by X. The differences in the numerators lose
 * digits only where Rs or P is small: an absolute error of a few ulp of the
 * denominator, as with sums of squares. m + c^2 >= 2cu always, and m and u
 * carry a rounding or two of their own, since A does (see
 * fresnel_i_eta2_minus_sin2 and fresnel_conductor_prepare).
 * With Q = X (c^2 m + s^4), Dp + Np = 2Q, so F = Ns Q / (Ds Dp): Np is never
 * formed, and F <= 1 by construction (0 <= Q <= Dp, Ns <= Ds, each rounding
 * monotone). For eta kappa >= 2^-30, Ds >= (eta kappa)^1.5,
 * Dp >= sqrt(eta kappa) min(eta kappa, 1/4) and Ds Dp <= ~(|n|^2 + 2)^3:
 * normal and finite in binary32 over the whole domain. Where the target
 * has a fused multiply-add (FRESNEL_I_FAST_FMA), A^2 + 4(eta kappa)^2,
 * s^2 = 1 - c^2, c^2 m + s^4 and Dp are each rounded once (fmaf), which
 * keeps every inequality above and saves four operations of the batches'
 * lanes. Smaller eta kappa
 * (FRESNEL_I_COND2) divides twice, kappa = 0 (FRESNEL_I_DIEL) has
 * m = t = |A| (A^2 could underflow), u = B or 0: one square root. */

static inline float fresnel_i_exact_f(float a, float c, float ch, float ek, float ek4, int kind)
{
    const int diel = kind == FRESNEL_I_DIEL;
#if FRESNEL_I_FAST_FMA
    float m = diel ? fabsf(a) : sqrtf(fmaf(a, a, ek4));
#else
    float m = diel ? fabsf(a) : sqrtf(a * a + ek4);
#endif
    float t = diel ? m : 0.5f * (m + fabsf(a));
    float b = sqrtf(t);
    float x = a >= 0.0f ? 1.0f : b;
    float y = a >= 0.0f ? b : ek;
#if FRESNEL_I_FAST_FMA
    float s2 = fmaf(-c, c, 1.0f);
#else
    float s2 = (1.0f - c) * (1.0f + c);
#endif
    float c2y = (c + c) * y;
    float xs = x * (m + ch);
#if FRESNEL_I_FAST_FMA
    float q = x * fmaf(ch, m, s2 * s2);
    float dp = fmaf(c2y, s2, q);
#else
    float q = x * (ch * m + s2 * s2);
    float dp = q + c2y * s2;
#endif
    float ns = xs - c2y, ds = xs + c2y;
    float f = kind == FRESNEL_I_COND2 ? (ns / ds) * (q / dp) : (ns * q) / (ds * dp);
    /* Rounding can take Ns, so F, a few ulp below 0 where Rs is 0 (eta
     * near 1): clamp (the upper clamp never acts). */
    return fresnel_i_unit(f);
}

/* Which form a material takes (eta, kappa clamped). */
static inline int fresnel_i_conductor_kind(float eta, float kappa)
{
    if (kappa == 0.0f)
        return eta == 1.0f ? FRESNEL_I_MATCHED : FRESNEL_I_DIEL;
    return eta * kappa >= 0x1p-30f ? FRESNEL_I_COND1 : FRESNEL_I_COND2;
}

float fresnel_conductor(float eta, float kappa, float c)
{
    float ek, a;
    int kind;
    eta = fresnel_i_eta(eta);
    kappa = fresnel_i_kappa(kappa);
    c = fresnel_i_unit(c);
    kind = fresnel_i_conductor_kind(eta, kappa);
    /* Matched index: no interface, nothing reflected, at every c including
     * c = 0 where the limit depends on the direction of approach (and where
     * c^2 underflows for c < 1e-19, so it must not be computed from c). */
    if (kind == FRESNEL_I_MATCHED)
        return 0.0f;
    ek = eta * kappa;
    a = fresnel_i_eta2_minus_sin2(eta, c, kappa * kappa);
    /* one body with the form as a run-time value (kappa = 0 gives ek = 0) */
    return fresnel_i_exact_f(a, c, c * c, ek, 4.0f * ek * ek, kind);
}

/* x + y = s + err exactly, s = fl(x + y) (Knuth's TwoSum). */
static inline float fresnel_i_two_sum_err(float x, float y, float s)
{
    float t = s - x;
    return (x - (s - t)) + (y - t);
}

fresnel_conductor_prep fresnel_conductor_prepare(float eta, float kappa)
{
    fresnel_conductor_prep p;
    float eh, el, kh, kl, s, d, lo;
    eta = fresnel_i_eta(eta);
    kappa = fresnel_i_kappa(kappa);
    p.kind = fresnel_i_conductor_kind(eta, kappa);
    /* eta^2 - kappa^2 - 1 = a0 + a0_lo to about 2^-48 of its size: exact
     * squares, two TwoSums, the low parts summed last. */
    fresnel_i_square_exact(eta, &eh, &el);
    fresnel_i_square_exact(kappa, &kh, &kl);
    s = eh - 1.0f;
    d = s - kh;
    lo = ((fresnel_i_two_sum_err(eh, -1.0f, s) + fresnel_i_two_sum_err(s, -kh, d)) + el) - kl;
    p.a0 = d + lo;
    p.a0_lo = lo - (p.a0 - d); /* Fast2Sum: |d| >= |lo| */
    p.ek = eta * kappa;
    p.ek4 = 4.0f * p.ek * p.ek;
    return p;
}

/* A = eta^2 - kappa^2 - sin^2 = (a0 + c^2) + (a0_lo + c^2 low part): a0 + c^2
 * is exact where it cancels (Sterbenz), so A keeps its digits at a critical
 * angle as in fresnel_i_eta2_minus_sin2. */
static inline float fresnel_i_prepared_a(const fresnel_conductor_prep *p, float c)
{
#if FRESNEL_I_FAST_FMA
    /* a0 + c^2 rounded once from the exact square: its one rounding is
     * relative to the sum, as Sterbenz's exact a0 + ch is where it cancels */
    return fmaf(c, c, p->a0) + p->a0_lo;
#else
    float ch, cl;
    fresnel_i_square_exact(c, &ch, &cl);
    return (p->a0 + ch) + (p->a0_lo + cl);
#endif
}

#define FRESNEL_I_PREPARED(p, c, kind) fresnel_i_exact_f(fresnel_i_prepared_a(p, c), c, (c) * (c), (p)->ek, (p)->ek4, kind)

float fresnel_conductor_prepared(const fresnel_conductor_prep *p, float c)
{
    c = fresnel_i_unit(c);
    switch (p->kind) {
    case FRESNEL_I_DIEL: return FRESNEL_I_PREPARED(p, c, FRESNEL_I_DIEL);
    case FRESNEL_I_COND1: return FRESNEL_I_PREPARED(p, c, FRESNEL_I_COND1);
    case FRESNEL_I_COND2: return FRESNEL_I_PREPARED(p, c, FRESNEL_I_COND2);
    default: return 0.0f; /* matched index */
    }
}

#if !FRESNEL_I_VW
/* Portable C: one loop per kind with no branch inside, in blocks of 8 with
 * a fixed trip count, the shape compilers' vectorisers accept when sqrtf
 * need not set errno (-fno-math-errno) and compares may be if-converted
 * (-fno-trapping-math). */
#define FRESNEL_I_BLOCK 8
#define FRESNEL_I_VBATCH(name, kind)                                                                   \
    static void name(const fresnel_conductor_prep *p, const float *c, float *out, int n)                \
    {                                                                                                  \
        const fresnel_conductor_prep q = *p;                                                           \
        int i;                                                                                         \
        for (i = 0; n - i >= FRESNEL_I_BLOCK; i += FRESNEL_I_BLOCK) {                                  \
            int j;                                                                                     \
            for (j = 0; j < FRESNEL_I_BLOCK; j++) {                                                    \
                float cj = fresnel_i_unit(c[i + j]);                                                   \
                out[i + j] = FRESNEL_I_PREPARED(&q, cj, kind);                                         \
            }                                                                                          \
        }                                                                                              \
        for (; i < n; i++) {                                                                           \
            float ci = fresnel_i_unit(c[i]);                                                           \
            out[i] = FRESNEL_I_PREPARED(&q, ci, kind);                                                 \
        }                                                                                              \
    }
#endif

FRESNEL_I_VBATCH(fresnel_i_batch_diel, FRESNEL_I_DIEL)
FRESNEL_I_VBATCH(fresnel_i_batch_cond1, FRESNEL_I_COND1)
FRESNEL_I_VBATCH(fresnel_i_batch_cond2, FRESNEL_I_COND2)

void fresnel_conductor_batch(const fresnel_conductor_prep *p, const float *FRESNEL_I_RESTRICT c, float *FRESNEL_I_RESTRICT out,
                             int n)
{
    int i;
#if FRESNEL_I_AVX_DISPATCH
    __builtin_cpu_init(); /* returns at once once the runtime's start-up code has run */
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && p->kind != FRESNEL_I_MATCHED) {
        fresnel_i_conductor_batch_avx(p, c, out, n);
        return;
    }
#endif
    switch (p->kind) {
    case FRESNEL_I_DIEL: fresnel_i_batch_diel(p, c, out, n); break;
    case FRESNEL_I_COND1: fresnel_i_batch_cond1(p, c, out, n); break;
    case FRESNEL_I_COND2: fresnel_i_batch_cond2(p, c, out, n); break;
    default:
        for (i = 0; i < n; i++)
            out[i] = 0.0f; /* matched index */
    }
}

#if FRESNEL_I_VW
/* The fused kernels write fresnel_rgb as 3n floats. */
typedef char fresnel_i_rgb_rows[(sizeof(fresnel_rgb) == 3 * sizeof(float) &&
                                 offsetof(fresnel_rgb, g) == sizeof(float) &&
                                 offsetof(fresnel_rgb, b) == 2 * sizeof(float)) ? 1 : -1];
FRESNEL_I_VBATCH_RGB(fresnel_i_rgb_batch_diel, FRESNEL_I_DIEL)
FRESNEL_I_VBATCH_RGB(fresnel_i_rgb_batch_cond1, FRESNEL_I_COND1)
FRESNEL_I_VBATCH_RGB(fresnel_i_rgb_batch_cond2, FRESNEL_I_COND2)
#endif

/* Three channels of one form (the usual case: a metal, a dielectric): one
 * pass, each cosine's terms shared by the channels and the rows written by
 * vector shuffles (exact_batch.h). Otherwise, and in portable C, each
 * channel's batch over a block of cosines, then the block interleaved into
 * out. */
#define FRESNEL_I_RGB_BLOCK 64
void fresnel_conductor_rgb_batch(const fresnel_conductor_prep p[3], const float *FRESNEL_I_RESTRICT c,
                                 fresnel_rgb *FRESNEL_I_RESTRICT out, int n)
{
    float r[FRESNEL_I_RGB_BLOCK], g[FRESNEL_I_RGB_BLOCK], b[FRESNEL_I_RGB_BLOCK];
    int i, j, k;
#if FRESNEL_I_VW
    const int kind = p[0].kind;
    if (kind != FRESNEL_I_MATCHED && p[1].kind == kind && p[2].kind == kind) {
        float *o = (float *)out; /* rows of three floats: fresnel_i_rgb_rows */
#if FRESNEL_I_AVX_DISPATCH
        __builtin_cpu_init();
        if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
            fresnel_i_conductor_rgb_batch_avx(p, c, o, n);
            return;
        }
#endif
        switch (kind) {
        case FRESNEL_I_DIEL: fresnel_i_rgb_batch_diel(p, c, o, n); return;
        case FRESNEL_I_COND1: fresnel_i_rgb_batch_cond1(p, c, o, n); return;
        default: fresnel_i_rgb_batch_cond2(p, c, o, n); return;
        }
    }
#endif
    for (i = 0; i < n; i += k) {
        k = n - i < FRESNEL_I_RGB_BLOCK ? n - i : FRESNEL_I_RGB_BLOCK;
        fresnel_conductor_batch(&p[0], c + i, r, k);
        fresnel_conductor_batch(&p[1], c + i, g, k);
        fresnel_conductor_batch(&p[2], c + i, b, k);
        for (j = 0; j < k; j++) {
            out[i + j].r = r[j];
            out[i + j].g = g[j];
            out[i + j].b = b[j];
        }
    }
}

fresnel_rgb fresnel_conductor_rgb(fresnel_rgb eta, fresnel_rgb kappa, float c)
{
    FRESNEL_I_RGB(fresnel_conductor(eta.r, kappa.r, c), fresnel_conductor(eta.g, kappa.g, c),
            fresnel_conductor(eta.b, kappa.b, c));
}

float fresnel_i_conductor_transmittance(float eta, float kappa, float c)
{
    /* |a+b|^2 - |a-b|^2 = 4 Re(a conj b) gives 1 - Rs = 4cu / den_s and
     * 1 - Rp = 4 (p u + q v) / den_p, and with u v = eta kappa,
     * p u + q v = c u (m + sin^2): sums of non-negative terms only. */
    struct fresnel_i_root w;
    float p, q, den_s, den_p, ts, tp, s2;
    eta = fresnel_i_eta(eta);
    kappa = fresnel_i_kappa(kappa);
    c = fresnel_i_unit(c);
    if (eta == 1.0f && kappa == 0.0f)
        return 1.0f; /* matched index, as in fresnel_conductor */
    w = fresnel_i_transmitted(eta, kappa, c);
    p = c * ((eta - kappa) * (eta + kappa));
    q = 2.0f * eta * kappa * c;
    s2 = (1.0f - c) * (1.0f + c);
    den_s = (c + w.u) * (c + w.u) + w.v * w.v;
    den_p = (p + w.u) * (p + w.u) + (q + w.v) * (q + w.v);
    ts = den_s > 0.0f ? 4.0f * c * w.u / den_s : 1.0f;
    tp = den_p > 0.0f ? 4.0f * c * w.u * (w.m + s2) / den_p : 1.0f;
    return fresnel_i_unit(0.5f * (ts + tp));
}

float fresnel_dielectric(float eta, float c)
{
    float a, w, e2c, rs, rp;
    eta = fresnel_i_eta(eta);
    c = fresnel_i_unit(c);
    if (eta == 1.0f)
        return 0.0f; /* matched index, as in fresnel_conductor */
    a = fresnel_i_eta2_minus_sin2(eta, c, 0.0f);
    if (a < 0.0f)
        return 1.0f; /* total internal reflection */
    w = sqrtf(a);
    e2c = eta * eta * c;
    /* c + w > 0: w = 0 needs a = 0, which with eta != 1 needs c > 0. */
    rs = (c - w) / (c + w);
    rp = (e2c - w) / (e2c + w);
    return fresnel_i_unit(0.5f * (rs * rs + rp * rp));
}

#else
typedef int fresnel_i_exact_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
