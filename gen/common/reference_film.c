/* The thin film's optics in double precision (reference_film.h). */
#include "common/reference_film.h"

#include <math.h>

#include "common/reference.h"

double complex ref_complex(double re, double im)
{
    double complex z;
    ((double *)&z)[0] = re;
    ((double *)&z)[1] = im;
    return z;
}

/* sqrt(N^2 - sigma) on the decaying branch: Im(N^2) = 2 n k >= 0 (+0 for
 * k = 0), so the principal root has Re, Im >= 0. */
static double complex normal_component(double complex n, double sigma)
{
    double re = creal(n), im = cimag(n);
    return csqrt(ref_complex((re - im) * (re + im) - sigma, 2.0 * re * im));
}

/* Both denominators vanish only where xi_i = xi_j = 0 (two media both at
 * grazing propagation): no interface to reflect from. */
static double complex ratio(double complex num, double complex den)
{
    return den == 0.0 ? 0.0 : num / den;
}

static void interface(double complex ni, double complex xi_i, double complex nj,
                      double complex xi_j, double complex r[2])
{
    double complex ni2 = ni * ni, nj2 = nj * nj;
    r[0] = ratio(xi_i - xi_j, xi_i + xi_j);
    r[1] = ratio(nj2 * xi_i - ni2 * xi_j, nj2 * xi_i + ni2 * xi_j);
}

void ref_film_optics_at(double n1, double complex n_film, double complex n_sub, double c,
                        ref_film_optics *o)
{
    double sigma = n1 * n1 * ((1.0 - c) * (1.0 + c));
    double complex xi1 = n1 * c, xi3;
    o->xi_f = normal_component(n_film, sigma);
    xi3 = normal_component(n_sub, sigma);
    interface(n1, xi1, n_film, o->xi_f, o->r12);
    interface(n_film, o->xi_f, n_sub, xi3, o->r23);
    interface(n1, xi1, n_sub, xi3, o->r13);
    o->z1[0] = xi1;
    o->z3[0] = xi3;
    o->z1[1] = xi1 / (n1 * n1);
    o->z3[1] = xi3 / (n_sub * n_sub);
    o->n_film2 = n_film * n_film;
}

/* xi_f = 0: with r_ij = (Z_i - Z_j) / (Z_i + Z_j) for Z = xi (s) or
 * xi / N^2 (p), Z_f = e -> 0 and z = exp(2 i k e N_f^2) (p; k = 2 pi d /
 * lambda; s without N_f^2), numerator and denominator of the sum are both
 * 2 e (...) + O(e^2):
 *   r -> (Z1 - Z3 - i k' Z1 Z3) / (Z1 + Z3 - i k' Z1 Z3),  k' = k (s), k N_f^2 (p). */
static double complex critical_limit(const ref_film_optics *o, int pol, double k)
{
    double complex kk = pol ? k * o->n_film2 : k, t = I * kk * o->z1[pol] * o->z3[pol];
    return ratio(o->z1[pol] - o->z3[pol] - t, o->z1[pol] + o->z3[pol] - t);
}

double ref_film_airy(const ref_film_optics *o, double d_nm, double lambda_nm)
{
    const double two_pi = 6.283185307179586476925;
    double complex z = cexp(2.0 * I * (two_pi * d_nm / lambda_nm) * o->xi_f);
    double sum = 0.0;
    int pol;
    for (pol = 0; pol < 2; pol++) {
        double complex r = o->xi_f == 0.0
                               ? critical_limit(o, pol, two_pi * d_nm / lambda_nm)
                               : ratio(o->r12[pol] + o->r23[pol] * z, 1.0 + o->r12[pol] * o->r23[pol] * z);
        sum += creal(r) * creal(r) + cimag(r) * cimag(r);
    }
    return 0.5 * sum;
}

void ref_film_series(double complex r12, double complex r23, double *a0, double complex *kappa,
                     double complex *q)
{
    double complex b = (1.0 - r12 * r12) * r23;
    double q2, b2, tail;
    *q = -r12 * r23;
    q2 = creal(*q) * creal(*q) + cimag(*q) * cimag(*q);
    b2 = creal(b) * creal(b) + cimag(b) * cimag(b);
    tail = q2 < 1.0 ? b2 / (1.0 - q2) : 0.0;
    *a0 = creal(r12) * creal(r12) + cimag(r12) * cimag(r12) + tail;
    *kappa = b * conj(r12) + tail * *q;
}

void film_pole_terms(const double complex k[2], const double complex q[2], double complex abpq[4])
{
    abpq[0] = k[0] + k[1];
    abpq[1] = -(k[0] * q[1] + k[1] * q[0]);
    abpq[2] = q[0] + q[1];
    abpq[3] = q[0] * q[1];
}

void ref_film_model(const film_model *m, double c, double d_nm, int clamp, double rgb[3])
{
    const double two_pi = 6.283185307179586476925;
    const int last = FRESNEL_FILM_NODES - 1;
    double pos, t, opd, decay;
    int i, j, n, ch;
    c = c > 0.0 ? (c < 1.0 ? c : 1.0) : 0.0;
    d_nm = d_nm > 0.0 ? (d_nm < FRESNEL_FILM_D_MAX ? d_nm : FRESNEL_FILM_D_MAX) : 0.0;
    pos = sqrt(c) * last;
    i = (int)pos;
    if (i > last - 1)
        i = last - 1;
    t = pos - i;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = (1.0 - t) * m->a0[i][ch] + t * m->a0[i + 1][ch];
    opd = (1.0 - t) * m->opd[i] + t * m->opd[i + 1];
    decay = (1.0 - t) * m->decay[i] + t * m->decay[i + 1];
    for (j = 0; j < FRESNEL_FILM_POLES; j++) {
        double complex path = d_nm * (opd + I * decay), p = m->nu[j] + I * m->gamma[j];
        double complex zeta = cexp(I * two_pi * path * p), v[4], f;
        for (n = 0; n < 4; n++)
            v[n] = (1.0 - t) * m->term[i][j][n] + t * m->term[i + 1][j][n];
        f = zeta * (v[0] + v[1] * zeta) / (1.0 - v[2] * zeta + v[3] * zeta * zeta);
        for (ch = 0; ch < 3; ch++)
            rgb[ch] += 2.0 * creal(m->weight[ch][j] * f);
    }
    if (clamp)
        for (ch = 0; ch < 3; ch++)
            rgb[ch] = rgb[ch] > 0.0 ? (rgb[ch] < 1.0 ? rgb[ch] : 1.0) : 0.0;
}

/* KHR_materials_iridescence (reference_film.h). The sensitivity of order m
 * at optical path difference opd (nm) and phase shift phi: the Fourier
 * transform of three Gaussians fitted to the CIE 1931 x, y, z functions
 * (amplitude, centre frequency and variance per channel, and a second lobe
 * for x), normalised by the integral of y, then to linear Rec. 709. The
 * constants are Belcour and Barla's ("A Practical Extension to Microfacet
 * Theory for the Modeling of Varying Iridescence", ACM TOG 36(4), 2017,
 * supplemental material), as the extension's reference implementation
 * quotes them. */
static void belcour_sensitivity_xyz(double opd, const double phi[3], double xyz[3])
{
    static const double amp[3] = {5.4856e-13, 4.4201e-13, 5.2481e-13};
    static const double centre[3] = {1.6810e+06, 1.7953e+06, 2.2084e+06};
    static const double var[3] = {4.3278e+09, 9.3046e+09, 6.6121e+09};
    const double two_pi = 6.283185307179586;
    double phase = two_pi * opd * 1e-9;
    int ch;
    for (ch = 0; ch < 3; ch++)
        xyz[ch] = amp[ch] * sqrt(two_pi * var[ch]) * cos(centre[ch] * phase + phi[ch]) * exp(-phase * phase * var[ch]);
    xyz[0] += 9.7470e-14 * sqrt(two_pi * 4.5282e+09) * cos(2.2399e+06 * phase + phi[0]) * exp(-4.5282e+09 * phase * phase);
    for (ch = 0; ch < 3; ch++)
        xyz[ch] /= 1.0685e-7;
}

static void khr_sensitivity(double opd, const double phi[3], double rgb[3])
{
    static const double to_709[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                        {-0.9692660, 1.8760108, 0.0415560},
                                        {0.0556434, -0.2040259, 1.0572252}};
    double xyz[3];
    int ch;
    belcour_sensitivity_xyz(opd, phi, xyz);
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = to_709[ch][0] * xyz[0] + to_709[ch][1] * xyz[1] + to_709[ch][2] * xyz[2];
}

static double khr_schlick(double f0, double c)
{
    double m = 1.0 - c, m2 = m * m;
    return f0 + (1.0 - f0) * m2 * m2 * m;
}

void ref_film_khr_iridescence(double outside_ior, double film_ior, double d_nm, double c, const double base_f0[3],
                              double rgb[3])
{
    const double pi = 3.141592653589793;
    double t = d_nm / 0.03, fade = d_nm <= 0.0 ? 0.0 : (d_nm >= 0.03 ? 1.0 : t * t * (3.0 - 2.0 * t));
    double eta2 = outside_ior + (film_ior - outside_ior) * fade;
    double sin2_sq = (outside_ior / eta2) * (outside_ior / eta2) * (1.0 - c * c), cos2_sq = 1.0 - sin2_sq, cos2;
    double r0, r12, t121, phi21, opd, sens[3], phi[3], base_ior[3], r23[3], r123[3], amp[3], rs[3];
    int ch, m;
    if (cos2_sq < 0.0) { /* total reflection inside the film */
        rgb[0] = rgb[1] = rgb[2] = 1.0;
        return;
    }
    cos2 = sqrt(cos2_sq);
    r0 = (eta2 - outside_ior) / (eta2 + outside_ior);
    r12 = khr_schlick(r0 * r0, c);
    t121 = 1.0 - r12;
    phi21 = pi - (eta2 < outside_ior ? pi : 0.0);
    opd = 2.0 * eta2 * d_nm * cos2;
    for (ch = 0; ch < 3; ch++) {
        double f0 = base_f0[ch] < 0.0 ? 0.0 : (base_f0[ch] > 0.9999 ? 0.9999 : base_f0[ch]), s = sqrt(f0), r1;
        base_ior[ch] = (1.0 + s) / (1.0 - s);
        r1 = (base_ior[ch] - eta2) / (base_ior[ch] + eta2);
        r23[ch] = khr_schlick(r1 * r1, cos2);
        phi[ch] = phi21 + (base_ior[ch] < eta2 ? pi : 0.0);
        r123[ch] = r12 * r23[ch];
        r123[ch] = r123[ch] < 1e-5 ? 1e-5 : (r123[ch] > 0.9999 ? 0.9999 : r123[ch]);
        rs[ch] = t121 * t121 * r23[ch] / (1.0 - r123[ch]);
        rgb[ch] = r12 + rs[ch]; /* order 0 */
        amp[ch] = rs[ch] - t121;
    }
    for (m = 1; m <= 2; m++) {
        double phim[3];
        for (ch = 0; ch < 3; ch++) {
            amp[ch] *= sqrt(r123[ch]);
            phim[ch] = m * phi[ch];
        }
        khr_sensitivity(m * opd, phim, sens);
        for (ch = 0; ch < 3; ch++)
            rgb[ch] += amp[ch] * 2.0 * sens[ch];
    }
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = rgb[ch] > 0.0 ? rgb[ch] : 0.0;
}

/* Belcour and Barla's polarised form (reference_film.h). The amplitude
 * coefficients of both interfaces in one convention (r_p = (n_b cos_a -
 * n_a cos_b) / (n_b cos_a + n_a cos_b) for light from medium a into b, so
 * that r_ba = -r_ab for either polarisation), the phase of each reflection
 * its argument: the round trip in the film adds phi21 = arg(r21) =
 * arg(-r12) and phi23 = arg(r23) to the path's phase, and order m of the
 * Airy series is C_m 2 S(m OPD, m (phi21 + phi23)) with C_0 = R12 + Rs,
 * C_m = (Rs - T121) sqrt(R12 R23)^m, Rs = T121^2 R23 / (1 - R12 R23), as
 * in the Schlick form above but with the exact reflectances, per
 * polarisation, and the two averaged. */
void ref_film_belcour_polarised(double outside_ior, double film_ior, double d_nm, double c, const double eta[3],
                                const double kappa[3], double rgb[3])
{
    double t = d_nm / 0.03, fade = d_nm <= 0.0 ? 0.0 : (d_nm >= 0.03 ? 1.0 : t * t * (3.0 - 2.0 * t));
    double n1 = outside_ior, n2 = outside_ior + (film_ior - outside_ior) * fade;
    double cos2_sq = 1.0 - (n1 / n2) * (n1 / n2) * (1.0 - c * c), cos2, opd, r12[2];
    int ch, pol, m;
    if (cos2_sq < 0.0) { /* total reflection inside the film */
        rgb[0] = rgb[1] = rgb[2] = 1.0;
        return;
    }
    cos2 = sqrt(cos2_sq);
    opd = 2.0 * n2 * d_nm * cos2;
    /* 0/0 only at grazing incidence with no film (n2 = n1): no interface */
    r12[0] = n1 * c + n2 * cos2 > 0.0 ? (n1 * c - n2 * cos2) / (n1 * c + n2 * cos2) : 0.0;
    r12[1] = n2 * c + n1 * cos2 > 0.0 ? (n2 * c - n1 * cos2) / (n2 * c + n1 * cos2) : 0.0;
    for (ch = 0; ch < 3; ch++) {
        double complex n3 = ref_complex(eta[ch], kappa[ch]);
        double complex n3cos3 = csqrt(n3 * n3 - n2 * n2 * (1.0 - cos2_sq));
        double complex r23[2];
        double sum = 0.0;
        r23[0] = (n2 * cos2 - n3cos3) / (n2 * cos2 + n3cos3);
        r23[1] = (n3 * n3 * cos2 - n2 * n3cos3) / (n3 * n3 * cos2 + n2 * n3cos3);
        for (pol = 0; pol < 2; pol++) {
            double big_r12 = r12[pol] * r12[pol], t121 = 1.0 - big_r12, big_r23 = creal(r23[pol] * conj(r23[pol]));
            double phi = (r12[pol] > 0.0 ? 3.141592653589793 : 0.0) + carg(r23[pol]);
            double r123 = big_r12 * big_r23 < 0.9999 ? big_r12 * big_r23 : 0.9999;
            double rs = t121 * t121 * big_r23 / (1.0 - r123), amp = rs - t121, v = big_r12 + rs;
            for (m = 1; m <= 2; m++) {
                double phim[3], sens[3];
                amp *= sqrt(r123);
                phim[0] = phim[1] = phim[2] = m * phi;
                khr_sensitivity(m * opd, phim, sens);
                v += amp * 2.0 * sens[ch];
            }
            sum += 0.5 * v;
        }
        rgb[ch] = sum > 0.0 ? sum : 0.0;
    }
}

/* Blender's film over its F82-tint metal (reference_film.h), transcribed
 * from Cycles: intern/cycles/kernel/closure/bsdf_microfacet.h
 * (microfacet_fresnel, the F82_TINT branch: r = min(F0, 0.999),
 * g = F82 curve at 1/7, n = mix((1 + sqrt r) / (1 - sqrt r), (1 - r) / (1 + r), g),
 * k = sqrt((r (n + 1)^2 - (n - 1)^2) / (1 - r))) and
 * intern/cycles/kernel/closure/bsdf_util.h (fresnel_iridescence,
 * fresnel_dielectric_polarized, fresnel_conductor_polarized with its F82
 * branch, iridescence_airy_summation), THINFILM_THICKNESS_CUTOFF 0.1 nm in
 * intern/cycles/kernel/svm/types.h. The order-m term
 * C_m 2 (Re phasor^m Re S + Im phasor^m Im S) with Cycles' table S (an FFT,
 * e^(-i...)) is C_m 2 Re(phasor^m S(m X)) with S as film_cmfs writes it. */
static double blender_schlick(double f0, double c)
{
    double s = ref_clamp(1.0 - c, 0.0, 1.0), s2 = s * s;
    return f0 + (1.0 - f0) * s2 * s2 * s;
}

static double blender_f82(double c, double f0, double b)
{
    double s = ref_clamp(1.0 - c, 0.0, 1.0), s2 = s * s, s5 = s2 * s2 * s;
    return ref_clamp(f0 + (1.0 - f0) * s5 - b * c * s5 * s, 0.0, 1.0);
}

/* fresnel_f82_B: the dip's factor that puts the curve through f82 at 1/7. */
static double blender_f82_b(double f0, double f82)
{
    const double f = 6.0 / 7.0, f5 = f * f * f * f * f;
    return 7.0 / (f5 * f) * (f0 + (1.0 - f0) * f5 - f82);
}

/* S_ch(x) of the three channels in one pass (film_cmfs). */
static void blender_sensitivity(const film_cmfs *k, double x, double complex s[3])
{
    const double two_pi = 6.283185307179586;
    double complex step = cexp(ref_complex(0.0, two_pi * x * k->dnu)), z = cexp(ref_complex(0.0, two_pi * x * k->nu0));
    int j;
    s[0] = s[1] = s[2] = 0.0;
    for (j = 0; j < FILM_CMF_SAMPLES; j++) {
        s[0] += k->w[j][0] * z;
        s[1] += k->w[j][1] * z;
        s[2] += k->w[j][2] * z;
        z *= step;
    }
}

void ref_film_blender(double film_ior, double d_nm, double c, const double base[3], const double tint[3],
                      const film_cmfs *k, double rgb[3])
{
    double eta = film_ior, eta_cos_t_sq, cos_t, amp[2], r12[2], opd;
    double complex sens[3][3];
    int ch, pol, m;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_blender_f82_tint(base[ch], tint[ch], c);
    if (d_nm <= 0.1) /* THINFILM_THICKNESS_CUTOFF: the bare metal */
        return;
    if (d_nm < 1.0) {
        double t = d_nm; /* smoothstep(0, 1, d) */
        eta = 1.0 + (film_ior - 1.0) * t * t * (3.0 - 2.0 * t);
    }
    eta_cos_t_sq = eta * eta - (1.0 - c * c);
    if (eta_cos_t_sq <= 0.0) { /* total reflection at the top */
        rgb[0] = rgb[1] = rgb[2] = 1.0;
        return;
    }
    cos_t = -sqrt(eta_cos_t_sq) / eta;
    /* amplitudes as fresnel_dielectric_polarized writes them; 0/0 (grazing
     * light, a film of the outside's index: no interface) taken as 0 */
    amp[0] = c - eta * cos_t > 0.0 ? (c + eta * cos_t) / (c - eta * cos_t) : 0.0;
    amp[1] = eta * c - cos_t > 0.0 ? (cos_t + eta * c) / (eta * c - cos_t) : 0.0;
    r12[0] = amp[0] * amp[0];
    r12[1] = amp[1] * amp[1];
    if (r12[0] == 1.0 && r12[1] == 1.0) {
        rgb[0] = rgb[1] = rgb[2] = 1.0;
        return;
    }
    opd = -2.0 * eta * d_nm * cos_t;
    for (m = 1; m <= 3; m++)
        blender_sensitivity(k, m * opd, sens[m - 1]);
    for (ch = 0; ch < 3; ch++) {
        /* fresnel_f82tint_B: B = Schlick(F0, 1/7) 7 / (6/7)^6 (1 - tint) */
        double f0 = ref_clamp(base[ch], 0.0, 1.0), edge = blender_schlick(f0, 1.0 / 7.0);
        double b = edge * 7.0 / pow(6.0 / 7.0, 6.0) * (1.0 - ref_clamp(tint[ch], 0.0, 1.0));
        double g = blender_f82(1.0 / 7.0, f0, b), r = f0 < 0.999 ? f0 : 0.999, sr = sqrt(r);
        double n = (1.0 + sr) / (1.0 - sr) + ((1.0 - r) / (1.0 + r) - (1.0 + sr) / (1.0 - sr)) * g;
        double k2 = (r * (n + 1.0) * (n + 1.0) - (n - 1.0) * (n - 1.0)) / (1.0 - r), kk = k2 > 0.0 ? sqrt(k2) : 0.0;
        double cosi = -cos_t, t1 = n * n - kk * kk - eta * eta * (1.0 - cosi * cosi);
        double t2 = sqrt(t1 * t1 + 4.0 * n * n * kk * kk);
        double u2 = 0.5 * (t2 + t1) > 0.0 ? 0.5 * (t2 + t1) : 0.0, v2 = 0.5 * (t2 - t1) > 0.0 ? 0.5 * (t2 - t1) : 0.0;
        double u = sqrt(u2), v = sqrt(v2);
        double nn = n / eta, kf2 = (kk / eta) * (kk / eta);
        double f0_film = ((nn - 1.0) * (nn - 1.0) + kf2) / ((nn + 1.0) * (nn + 1.0) + kf2);
        double r23 = blender_f82(cosi, f0_film, blender_f82_b(f0_film, g));
        double complex phasor23[2];
        double re, im, mag, sum = 0.0;
        re = -u2 - v2 + (eta * cosi) * (eta * cosi);
        im = -2.0 * eta * cosi * v;
        mag = sqrt(re * re + im * im);
        phasor23[0] = mag == 0.0 ? 1.0 : ref_complex(re / mag, im / mag);
        re = ((n * n + kk * kk) * cosi) * ((n * n + kk * kk) * cosi) - eta * eta * (u2 + v2);
        im = 2.0 * eta * cosi * (2.0 * n * kk * u - (n * n - kk * kk) * v);
        mag = sqrt(re * re + im * im);
        phasor23[1] = mag == 0.0 ? 1.0 : ref_complex(re / mag, im / mag);
        for (pol = 0; pol < 2; pol++) {
            double complex phasor = phasor23[pol] * -(amp[pol] >= 0.0 ? 1.0 : -1.0), power = phasor;
            double t121 = 1.0 - r12[pol], r123 = r12[pol] * r23, rs, cm, v_pol;
            if (r123 >= 1.0) {
                sum += 0.5;
                continue;
            }
            rs = t121 * t121 * r23 / (1.0 - r123);
            v_pol = rs + r12[pol];
            cm = rs - t121;
            for (m = 1; m <= 3; m++) {
                cm *= sqrt(r123);
                v_pol += cm * 2.0 * creal(power * sens[m - 1][ch]);
                power *= phasor;
            }
            sum += 0.5 * v_pol;
        }
        rgb[ch] = ref_clamp(sum, 0.0, 1.0);
    }
}

/* MaterialX's film over its generalized Schlick metal (reference_film.h),
 * transcribed from mx_fresnel_airy, mx_fresnel_dielectric_polarized,
 * mx_fresnel_hoffman_schlick, mx_f0_to_ior (F0 clamped to [0.01, 0.99])
 * and mx_eval_sensitivity in libraries/pbrlib/genglsl/lib/
 * mx_microfacet_specular.glsl (MaterialX 1.39), the iteration count
 * hwAiryFresnelIterations = 2 of source/MaterialXGenShader/GenOptions.h. */
void ref_film_materialx(double film_ior, double d_nm, double c, const double color0[3], const double color82[3],
                        const double color90[3], double exponent, int iterations, double rgb[3])
{
    /* XYZ to CIE 1931 RGB under illuminant E, as the GLSL's XYZ_TO_RGB (its
     * mat3 is column-major: these are its rows) */
    static const double to_rgb[3][3] = {{2.3706743, -0.9000405, -0.4706338},
                                        {-0.5138850, 1.4253036, 0.0885814},
                                        {0.0052982, -0.0146949, 1.0093968}};
    const double pi = 3.141592653589793;
    double eta2 = film_ior > 1.0 ? film_ior : 1.0, eta3[3], r23[3], phi23[3], big[3] = {0.0, 0.0, 0.0};
    double c2 = c * c, s2 = 1.0 - c2, t0, t1, t2, t3, t4, r12[2], phi21[2], cos_t, opd;
    int ch, pol, m;
    if (d_nm <= 0.0) { /* no film: the bare curve */
        for (ch = 0; ch < 3; ch++)
            rgb[ch] = ref_materialx_schlick(color0[ch], color82[ch], color90[ch], exponent, c);
        return;
    }
    cos_t = sqrt(1.0 - s2 / (eta2 * eta2));
    /* mx_fresnel_dielectric_polarized(c, eta2): (Rp, Rs) */
    t0 = eta2 * eta2 - s2 > 0.0 ? eta2 * eta2 - s2 : 0.0;
    t1 = t0 + c2;
    t2 = 2.0 * sqrt(t0) * c;
    r12[1] = t1 + t2 > 0.0 ? (t1 - t2) / (t1 + t2) : 0.0;
    t3 = c2 * t0 + s2 * s2;
    t4 = t2 * s2;
    r12[0] = t3 + t4 > 0.0 ? r12[1] * (t3 - t4) / (t3 + t4) : 0.0;
    phi21[0] = c < cos(atan(eta2)) ? 0.0 : pi;
    phi21[1] = pi;
    opd = 2.0 * eta2 * cos_t * d_nm;
    for (ch = 0; ch < 3; ch++) {
        double s = sqrt(ref_clamp(color0[ch], 0.01, 0.99));
        eta3[ch] = (1.0 + s) / (1.0 - s);
        r23[ch] = 0.5 * ref_materialx_schlick(color0[ch], color82[ch], color90[ch], exponent, cos_t);
        phi23[ch] = eta3[ch] < eta2 ? pi : 0.0;
    }
    for (pol = 0; pol < 2; pol++) {
        double t121 = 1.0 - r12[pol], cm[3], r123[3];
        for (ch = 0; ch < 3; ch++) {
            double rs = t121 * t121 * r23[ch] / (1.0 - r12[pol] * r23[ch]);
            /* GLSL's max(sqrt(x), 0): sqrt of a negative product is undefined there; 0 here */
            r123[ch] = r12[pol] * r23[ch] > 0.0 ? sqrt(r12[pol] * r23[ch]) : 0.0;
            big[ch] += r12[pol] + rs;
            cm[ch] = rs - t121;
        }
        for (m = 1; m <= iterations; m++) {
            double shift[3], sens[3];
            for (ch = 0; ch < 3; ch++)
                shift[ch] = m * (phi23[ch] + phi21[pol]);
            belcour_sensitivity_xyz(m * opd, shift, sens);
            for (ch = 0; ch < 3; ch++) {
                cm[ch] *= r123[ch];
                big[ch] += cm[ch] * 2.0 * sens[ch];
            }
        }
    }
    for (ch = 0; ch < 3; ch++)
        big[ch] *= 0.5;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_clamp(to_rgb[ch][0] * big[0] + to_rgb[ch][1] * big[1] + to_rgb[ch][2] * big[2], 0.0, 1.0);
}
