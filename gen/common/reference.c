/* Double-precision reference of every model (see reference.h). */
#include "common/reference.h"

#include <complex.h>
#include <math.h>

#include "fresnel.h"

double ref_clamp(double x, double lo, double hi)
{
    return x > lo ? (x < hi ? x : hi) : lo;
}

static double unit(double x) { return ref_clamp(x, 0.0, 1.0); }
static double eta_dom(double x) { return ref_clamp(x, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX); }
static double kappa_dom(double x)
{
    return x >= FRESNEL_KAPPA_TINY ? (x < FRESNEL_KAPPA_MAX ? x : FRESNEL_KAPPA_MAX) : 0.0;
}

/* eta^2 + c^2 - 1 - kappa^2 with the squares exact (fma) and their sum's
 * rounding carried, as src/f32/internal.h does in binary32: near the critical
 * angle this is a difference of nearly equal numbers whose root is taken. */
static double eta2_minus_sin2(double eta, double c, double kappa2)
{
    double eh = eta * eta, el = fma(eta, eta, -eh);
    double ch = c * c, cl = fma(c, c, -ch);
    double s = eh + ch, t = s - eh;
    double err = (eh - (s - t)) + (ch - t);
    return (s - 1.0) + ((err + el + cl) - kappa2);
}

double ref_schlick(double f0, double c)
{
    f0 = unit(f0);
    return unit(f0 + (1.0 - f0) * pow(1.0 - unit(c), 5.0));
}

double ref_schlick_gen(double f0, double f90, double p, double c)
{
    f0 = unit(f0);
    f90 = unit(f90);
    p = ref_clamp(p, FRESNEL_P_MIN, FRESNEL_P_MAX);
    return unit(f0 + (f90 - f0) * pow(1.0 - unit(c), p));
}

double ref_schlick_internal(double f0, double eta, double c)
{
    double ct2;
    eta = eta_dom(eta);
    c = unit(c);
    if (eta >= 1.0)
        return ref_schlick(f0, c);
    ct2 = eta2_minus_sin2(eta, c, 0.0);
    if (!(ct2 > 0.0))
        return 1.0;
    return ref_schlick(f0, sqrt(ct2) / eta);
}

double ref_f0_in_medium(double f0, double eta_e)
{
    double s, r, q;
    eta_e = eta_dom(eta_e);
    s = (eta_e - 1.0) / (eta_e + 1.0);
    r = sqrt(unit(f0));
    q = (r - s) / (1.0 - r * s);
    return unit(q * q);
}

double ref_f0_from_ior(double eta, double kappa)
{
    double k2;
    eta = eta_dom(eta);
    kappa = kappa_dom(kappa);
    k2 = kappa * kappa;
    return unit(((eta - 1.0) * (eta - 1.0) + k2) / ((eta + 1.0) * (eta + 1.0) + k2));
}

double ref_lsk(double n, double k, double c)
{
    double k2;
    n = eta_dom(n);
    k = kappa_dom(k);
    c = unit(c);
    k2 = k * k;
    return unit(((n - 1.0) * (n - 1.0) + 4.0 * n * pow(1.0 - c, 5.0) + k2) /
                ((n + 1.0) * (n + 1.0) + k2));
}

double ref_lsk_comp(double n, double k, double a, double alpha, double c)
{
    c = unit(c);
    a = ref_clamp(a, 0.0, FRESNEL_A_MAX);
    alpha = ref_clamp(alpha, 0.0, FRESNEL_ALPHA_MAX);
    return unit(ref_lsk(n, k, c) - a * c * pow(1.0 - c, alpha));
}

void ref_lsk_fit(double n, double k, double *a, double *alpha)
{
    n = eta_dom(n);
    k = kappa_dom(k);
    ref_lsk_fit_target(n, k, ref_conductor(n, k, 0.15), a, alpha);
}

void ref_lsk_fit_target(double n, double k, double target_015, double *a, double *alpha)
{
    /* Two constraints [LS05]: slope -a = -2n at c = 0 (their approximation for
     * large k), and -a c (1-c)^alpha = target - rescaled at c = 0.15, near the
     * error's minimum for most metals. */
    const double cm = 0.15;
    double err, al;
    n = eta_dom(n);
    k = kappa_dom(k);
    err = target_015 - ref_lsk(n, k, cm);
    *a = 0.0;
    *alpha = 0.0;
    if (!(err < 0.0))
        return; /* rescaled curve not above the target there: nothing to compensate */
    al = log(-err / (cm * 2.0 * n)) / log(1.0 - cm);
    if (!(al > 0.0))
        return; /* the error exceeds what -2n c (1-c)^alpha can reach: no fit */
    *a = 2.0 * n;
    *alpha = ref_clamp(al, 0.0, FRESNEL_ALPHA_MAX);
}

double ref_f82(double f0, double f82, double c)
{
    double x, a;
    f0 = unit(f0);
    f82 = unit(f82);
    c = unit(c);
    x = 1.0 - c;
    a = ref_f82_a(f0, f82);
    return unit(f0 + (1.0 - f0) * pow(x, 5.0) - a * c * pow(x, 6.0));
}

double ref_f82_a(double f0, double f82) { return (823543.0 / 46656.0) * (f0 - f82) + (49.0 / 6.0) * (1.0 - f0); }

void ref_gulbrandsen_nk(double r, double g, double *n, double *k)
{
    double sr, nmin, nmax, k2;
    r = ref_clamp(r, 0.0, FRESNEL_GULBRANDSEN_R_MAX);
    g = unit(g);
    sr = sqrt(r);
    nmin = (1.0 - r) / (1.0 + r);
    nmax = (1.0 + sr) * (1.0 + sr) / (1.0 - r); /* = (1+sr)/(1-sr), see gulbrandsen.c */
    *n = g * nmin + (1.0 - g) * nmax;
    /* The paper's (r(n+1)^2 - (n-1)^2)/(1-r), factored: see gulbrandsen.c. */
    k2 = g * (nmax - nmin) * (*n * (1.0 + sr) - (1.0 - r) / (1.0 + sr)) / (1.0 + sr);
    *k = k2 > 0.0 ? sqrt(k2) : 0.0;
}

void ref_gulbrandsen_rg(double n, double k, double *r, double *g)
{
    *r = ref_f0_from_ior(n, k);
    *g = ref_gulbrandsen_g(*r, n);
}

double ref_gulbrandsen_g(double r, double n)
{
    double rc, sr, nmax1, span;
    n = eta_dom(n);
    rc = ref_clamp(r, 0.0, FRESNEL_GULBRANDSEN_R_MAX);
    sr = sqrt(rc);
    /* nmax - 1 and nmax - nmin without cancellation (gulbrandsen.c) */
    nmax1 = 2.0 * sr * (1.0 + sr) / (1.0 - rc);
    span = nmax1 * (1.0 + sr) / (1.0 + rc);
    return span > 0.0 ? unit((nmax1 - (n - 1.0)) / span) : 0.0;
}

double ref_gulbrandsen(double r, double g, double c)
{
    double n, k;
    ref_gulbrandsen_nk(r, g, &n, &k);
    return ref_approx_conductor(n, k, c);
}

double ref_approx_conductor(double n, double k, double c)
{
    double nk2, rs, rp;
    n = eta_dom(n);
    k = kappa_dom(k);
    c = unit(c);
    nk2 = n * n + k * k;
    rs = ((n - c) * (n - c) + k * k) / ((n + c) * (n + c) + k * k);
    rp = ((n * c - 1.0) * (n * c - 1.0) + k * c * k * c) / (nk2 * c * c + 2.0 * n * c + 1.0);
    return unit(0.5 * (rs + rp));
}

double ref_cook_torrance(double f0, double eta, double kappa, double c)
{
    double d, t;
    f0 = unit(f0);
    eta = eta_dom(eta);
    kappa = kappa_dom(kappa);
    d = (eta + 1.0) * (eta + 1.0) + kappa * kappa;
    /* max(0, F'(c) - F'(1)) / (1 - F'(1)) with F' = 1 - T' */
    t = unit(1.0 - ref_conductor_transmittance(eta, kappa, c) * d / (4.0 * eta));
    return unit(f0 + (1.0 - f0) * t);
}

/* u + iv = sqrt((eta + i kappa)^2 - sin^2), m = u^2 + v^2 (see src/f32/exact.c). */
static void transmitted(double eta, double kappa, double c, double *u, double *v, double *m)
{
    double ek = eta * kappa;
    double a = eta2_minus_sin2(eta, c, kappa * kappa);
    *m = hypot(a, 2.0 * ek);
    if (a >= 0.0) {
        *u = sqrt(0.5 * (*m + a));
        *v = *u > 0.0 ? ek / *u : 0.0;
    } else {
        *v = sqrt(0.5 * (*m - a));
        *u = ek / *v;
    }
}

void ref_conductor_sp(double eta, double kappa, double c, double *rs, double *rp)
{
    double u, v, m, p, q, den_s, den_p;
    eta = eta_dom(eta);
    kappa = kappa_dom(kappa);
    c = unit(c);
    if (eta == 1.0 && kappa == 0.0) { /* matched index: 0 at every c (fresnel.h) */
        *rs = *rp = 0.0;
        return;
    }
    transmitted(eta, kappa, c, &u, &v, &m);
    p = c * ((eta - kappa) * (eta + kappa));
    q = 2.0 * eta * kappa * c;
    den_s = (c + u) * (c + u) + v * v;
    den_p = (p + u) * (p + u) + (q + v) * (q + v);
    *rs = den_s > 0.0 ? ((c - u) * (c - u) + v * v) / den_s : 0.0;
    *rp = den_p > 0.0 ? ((p - u) * (p - u) + (q - v) * (q - v)) / den_p : 0.0;
}

double ref_conductor(double eta, double kappa, double c)
{
    double rs, rp;
    ref_conductor_sp(eta, kappa, c, &rs, &rp);
    return unit(0.5 * (rs + rp));
}

double ref_conductor_transmittance(double eta, double kappa, double c)
{
    double u, v, m, p, q, s2, den_s, den_p, ts, tp;
    eta = eta_dom(eta);
    kappa = kappa_dom(kappa);
    c = unit(c);
    if (eta == 1.0 && kappa == 0.0)
        return 1.0;
    transmitted(eta, kappa, c, &u, &v, &m);
    p = c * ((eta - kappa) * (eta + kappa));
    q = 2.0 * eta * kappa * c;
    s2 = (1.0 - c) * (1.0 + c);
    den_s = (c + u) * (c + u) + v * v;
    den_p = (p + u) * (p + u) + (q + v) * (q + v);
    ts = den_s > 0.0 ? 4.0 * c * u / den_s : 1.0;
    tp = den_p > 0.0 ? 4.0 * c * u * (m + s2) / den_p : 1.0;
    return unit(0.5 * (ts + tp));
}

/* C99 has no CMPLX; a complex double is laid out as double[2] (C99 6.2.5),
 * which sets the imaginary part's sign exactly, unlike x + I*y. */
static double complex make_complex(double re, double im)
{
    double complex z;
    ((double *)&z)[0] = re;
    ((double *)&z)[1] = im;
    return z;
}

void ref_conductor_complex_sp(double eta, double kappa, double c, double *rs, double *rp)
{
    double complex n, n2, w, a, b;
    double s2;
    eta = eta_dom(eta);
    kappa = kappa_dom(kappa);
    c = unit(c);
    if (eta == 1.0 && kappa == 0.0) {
        *rs = *rp = 0.0;
        return;
    }
    n = eta + I * kappa;
    n2 = n * n;
    s2 = (1.0 - c) * (1.0 + c);
    /* n cos(theta_t) = sqrt(n^2 - sin^2): the principal root has Im >= 0
     * because Im(n^2) = 2 eta kappa >= 0 (+0 when kappa = 0, so a negative
     * real argument gives +i sqrt: the evanescent wave decays). */
    w = csqrt(make_complex(creal(n2) - s2, cimag(n2)));
    a = c - w;
    b = c + w;
    *rs = cabs(b) > 0.0 ? creal(a * conj(a)) / creal(b * conj(b)) : 0.0;
    a = n2 * c - w;
    b = n2 * c + w;
    *rp = cabs(b) > 0.0 ? creal(a * conj(a)) / creal(b * conj(b)) : 0.0;
}

double ref_conductor_complex(double eta, double kappa, double c)
{
    double rs, rp;
    ref_conductor_complex_sp(eta, kappa, c, &rs, &rp);
    return unit(0.5 * (rs + rp));
}

double ref_dielectric(double eta, double c)
{
    double a, w, e2c, rs, rp;
    eta = eta_dom(eta);
    c = unit(c);
    if (eta == 1.0)
        return 0.0;
    a = eta2_minus_sin2(eta, c, 0.0);
    if (a < 0.0)
        return 1.0;
    w = sqrt(a);
    e2c = eta * eta * c;
    rs = c + w > 0.0 ? (c - w) / (c + w) : 0.0;
    rp = e2c + w > 0.0 ? (e2c - w) / (e2c + w) : 0.0;
    return unit(0.5 * (rs * rs + rp * rp));
}

double ref_lut(const double *v, int n, int cubic, double x)
{
    double pos = x * (n - 1), t;
    int i = (int)pos;
    if (i >= n - 1)
        i = n - 2;
    t = pos - i;
    if (!cubic)
        return v[i] + t * (v[i + 1] - v[i]);
    return v[i > 0 ? i - 1 : 0] * 0.5 * t * (-1.0 + t * (2.0 - t)) + v[i] * (1.0 + t * t * (1.5 * t - 2.5)) +
           v[i + 1] * 0.5 * t * (1.0 + t * (4.0 - 3.0 * t)) + v[i + 2 < n ? i + 2 : n - 1] * 0.5 * t * t * (t - 1.0);
}
