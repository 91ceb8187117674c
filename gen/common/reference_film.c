/* The thin film's optics in double precision (reference_film.h). */
#include "common/reference_film.h"

#include <math.h>

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
static void khr_sensitivity(double opd, const double phi[3], double rgb[3])
{
    static const double amp[3] = {5.4856e-13, 4.4201e-13, 5.2481e-13};
    static const double centre[3] = {1.6810e+06, 1.7953e+06, 2.2084e+06};
    static const double var[3] = {4.3278e+09, 9.3046e+09, 6.6121e+09};
    static const double to_709[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                        {-0.9692660, 1.8760108, 0.0415560},
                                        {0.0556434, -0.2040259, 1.0572252}};
    const double two_pi = 6.283185307179586;
    double phase = two_pi * opd * 1e-9, xyz[3];
    int ch;
    for (ch = 0; ch < 3; ch++)
        xyz[ch] = amp[ch] * sqrt(two_pi * var[ch]) * cos(centre[ch] * phase + phi[ch]) * exp(-phase * phase * var[ch]);
    xyz[0] += 9.7470e-14 * sqrt(two_pi * 4.5282e+09) * cos(2.2399e+06 * phase + phi[0]) * exp(-4.5282e+09 * phase * phase);
    for (ch = 0; ch < 3; ch++)
        xyz[ch] /= 1.0685e-7;
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
