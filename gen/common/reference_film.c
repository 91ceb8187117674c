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
