/* Double-precision optics of a thin film: the spectral truth's reflectance
 * at one wavelength (film_truth.c integrates it), the quantities the
 * generator fits the run-time constants from (2_derive/film_fit.c), and the
 * double evaluation of the run-time model (the yardstick of the runtime's
 * error bounds, as reference.c is for the other models). Host only.
 *
 * THE STACK: incident medium of real index n1 | film of complex index
 * Nf = nf + i kf, thickness d | substrate N3 = n3 + i k3 (semi-infinite).
 * c is the cosine of the angle of incidence in the incident medium.
 *
 * FORMULAS [Born & Wolf, Principles of Optics, 7th ed., sections 1.5-1.6;
 * Heavens, Optical Properties of Thin Solid Films, 1955, ch. 4], time
 * dependence exp(-i w t), absorbing indices with k >= 0:
 *   sigma = n1^2 (1 - c^2)                 (n sin(theta), the same in every layer)
 *   xi_j = N_j cos(theta_j) = sqrt(N_j^2 - sigma),  the root with Im >= 0 (the
 *          wave decays away from the interface; a real negative radicand is
 *          total internal reflection)
 *   r_ij,s = (xi_i - xi_j) / (xi_i + xi_j)
 *   r_ij,p = (N_j^2 xi_i - N_i^2 xi_j) / (N_j^2 xi_i + N_i^2 xi_j)
 *   beta   = 2 pi d xi_f / lambda              (the film's phase thickness)
 *   r      = (r12 + r23 e^(2 i beta)) / (1 + r12 r23 e^(2 i beta))   (Airy's sum
 *            of the multiply reflected waves)
 *   R      = (|r_s|^2 + |r_p|^2) / 2          (unpolarised light)
 * d = 0 gives r = r13 (the bare interface); Nf = n1 gives r12 = 0 and
 * |r| = |r23| (a lossless film adds only phase); an interface between two
 * media with xi_i = xi_j = 0 (grazing light in a film of the incident
 * medium's index) has r = 0. At a film's critical angle (xi_f = 0, a film
 * less dense than the incident medium) r12 and r23 are +-1 and the sum is
 * 0/0; its limit is taken there (reference_film.c).
 *
 * THE FOURIER FORM used by the run-time model (fresnel_film.h): for a real
 * phase (Im xi_f = 0), z = e^(2 i beta), q = -r12 r23 and
 * b = (1 - r12^2) r23, r = r12 + b z sum_{j>=0} (q z)^j, so
 *   R_pol = a0 + 2 Re sum_{m>=1} a_m z^m,
 *   a0  = |r12|^2 + |b|^2 / (1 - |q|^2)          (the incoherent sum)
 *   a_m = kappa q^(m-1),  kappa = b conj(r12) + |b|^2 q / (1 - |q|^2).
 * z^m = exp(2 pi i m X / lambda) with X = 2 d Re(xi_f), the optical path
 * difference of one round trip. */
#ifndef FRESNEL_REFERENCE_FILM_H
#define FRESNEL_REFERENCE_FILM_H

#include <complex.h>

#include "fresnel_film.h"

/* The interface amplitudes of one wavelength, [0] s and [1] p, and xi_f. */
typedef struct ref_film_optics {
    double complex r12[2], r23[2], r13[2];
    double complex xi_f;
    /* for the critical-angle limit: the s and p "impedances" of media 1
     * and 3 (xi and xi / N^2) and the film's N^2 */
    double complex z1[2], z3[2], n_film2;
} ref_film_optics;
void ref_film_optics_at(double n1, double complex n_film, double complex n_sub, double c,
                        ref_film_optics *o);

/* Airy reflectance R of the stack at wavelength lambda_nm, thickness d_nm. */
double ref_film_airy(const ref_film_optics *o, double d_nm, double lambda_nm);

/* The Fourier coefficients above for one polarisation (Im xi_f = 0 assumed
 * by the series, not by the function): a0 and a_1 = kappa, and q. */
void ref_film_series(double complex r12, double complex r23, double *a0, double complex *kappa,
                     double complex *q);

/* ---- the run-time model (fresnel_film.h) in double precision.
 * Poles p_j = nu_j + i gamma_j (cycles per nm of optical path) and weights
 * c_ch,j fit each channel's spectral sensitivity as
 *   S_ch(x) = sum_lambda w_ch(lambda) exp(2 pi i x / lambda)
 *           ~ sum_j c_ch,j exp(2 pi i x p_j),   x >= 0
 * (2_derive/film_fit.c). Then, for the Fourier form above,
 *   R_ch = a0_ch + 2 Re sum_j c_ch,j sum_pol kappa_j,pol zeta_j / (1 - q_j,pol zeta_j),
 *   zeta_j = exp(2 pi i d (opd + i decay) p_j),
 * the sum over every order m in closed form. a0_ch is the incoherent
 * reflectance integrated exactly; kappa, q are the Fourier coefficients
 * continued to the complex frequency p_j (then refitted), at
 * FRESNEL_FILM_NODES cosines c_k = (k / (nodes - 1))^2; opd + i decay = 2 xi_f,
 * the optical path per nm of thickness (decay > 0 only in total reflection
 * inside the film). The two polarisations of pole j share one denominator,
 *   sum_pol kappa zeta / (1 - q zeta) = zeta (A + B zeta) / (1 - P zeta + Q zeta^2),
 *   A = kappa_s + kappa_p, B = -(kappa_s q_p + kappa_p q_s), P = q_s + q_p, Q = q_s q_p,
 * (one reciprocal per pole instead of two), and a0, opd, decay, A, B, P, Q
 * are what is interpolated, linearly in sqrt(c): nodes dense at grazing
 * incidence, where the fringes stay deep up to the last degree while the
 * reflectance goes to 1. */
typedef struct film_model {
    double nu[FRESNEL_FILM_POLES], gamma[FRESNEL_FILM_POLES];
    double complex weight[3][FRESNEL_FILM_POLES];
    double a0[FRESNEL_FILM_NODES][3];
    double opd[FRESNEL_FILM_NODES], decay[FRESNEL_FILM_NODES];
    double complex term[FRESNEL_FILM_NODES][FRESNEL_FILM_POLES][4]; /* A, B, P, Q */
} film_model;
/* R at cosine c and thickness d nm, with the runtime's clamps (c to [0, 1],
 * d to [0, FRESNEL_FILM_D_MAX], NaN to 0) and the result clamped to [0, 1]
 * (clamp = 0: unclamped, for fitting). */
void ref_film_model(const film_model *m, double c, double d_nm, int clamp, double rgb[3]);
/* A, B, P, Q (above) from kappa and q of the s [0] and p [1] polarisations. */
void film_pole_terms(const double complex kappa[2], const double complex q[2], double complex abpq[4]);

/* The real-time standard for iridescence, as the KHR_materials_iridescence
 * extension of glTF 2.0 specifies it and the Khronos glTF Sample Viewer
 * evaluates it (evalIridescence; three.js and Babylon.js follow it):
 * Belcour and Barla's 2017 thin-film model with Schlick's approximation at
 * both interfaces, the base's index from its F0 (clamped to [0, 0.9999]) as
 * if it were a dielectric, the film's index faded to the outside's below
 * 0.03 nm, the Airy series to order m = 2 with each order's spectrum the
 * Fourier transform of Gaussian fits of the CIE XYZ sensitivities, and the
 * result in linear Rec. 709, negative channels set to 0 (no upper clamp).
 * Inputs as the peer takes them: the outside's index, the film's index and
 * thickness in nm, cos theta in the outside, and the base's F0 per channel.
 * Transcribed from the extension's specification and the paper's published
 * constants (gen/common/reference_film.c cites them). */
void ref_film_khr_iridescence(double outside_ior, double film_ior, double d_nm, double c, const double base_f0[3],
                              double rgb[3]);

/* The same family with the exact Fresnel equations, as Belcour and Barla's
 * paper derives it: the s and p polarisations each carried through the Airy
 * series (orders m <= 2, the sensitivities above) with the reflectance and
 * the phase shift of each interface from its complex amplitude coefficient
 * (the film's a dielectric's, the base's a conductor's with index
 * eta + i kappa), then averaged. Per-channel base indices, as a renderer with
 * RGB eta, kappa supplies them: channel ch is the ch-th Rec. 709 component
 * of the form evaluated with eta[ch], kappa[ch]. The film's index fades to
 * the outside's below 0.03 nm as above, R12 R23 is held below 0.9999 (the
 * series' denominator), and negative results are set to 0. At d = 0 it is
 * the base's exact unpolarised reflectance. */
void ref_film_belcour_polarised(double outside_ior, double film_ior, double d_nm, double c, const double eta[3],
                                const double kappa[3], double rgb[3]);

/* A colour space's sensitivities as Blender's Cycles feeds its thin film
 * (intern/cycles/scene/shader.cpp, compute_thin_film_table;
 * intern/cycles/doc/precompute/thin_film_table.py): the CIE 1931 functions
 * mapped to the space's RGB, each channel scaled to unit area, sampled
 * uniformly in frequency nu = 1 / lambda (per nm) with the Jacobian
 * d lambda = d nu / nu^2, so that the channel's spectrum of order m is
 *   S_ch(X) = sum_j w[j][ch] exp(2 pi i X nu_j),  nu_j = nu0 + j dnu,
 * the Fourier transform Cycles tabulates (512 entries over X = 0-60 um,
 * read with linear interpolation; here the sum itself). Built by
 * 2_derive/target_fit.c from the scene's CMFs and colour space. */
#define FILM_CMF_SAMPLES 1024
typedef struct film_cmfs {
    double nu0, dnu;
    double w[FILM_CMF_SAMPLES][3];
} film_cmfs;

/* Blender's Principled BSDF with Metallic = 1 under its thin film (Cycles,
 * Blender 4.2 and later): the F82-tint metal's F0 = base (Base Color) and
 * F82 = g (the curve at cos theta = 1/7, from Specular Tint) read as
 * Gulbrandsen's r and g to give the metal an index n + i k; Belcour and
 * Barla's series per polarisation with the exact phase of each interface
 * and orders m <= 3 against the sensitivities above, the base's reflectance
 * inside the film the F82 curve refitted to the index seen from the film;
 * result held to [0, 1]. No film at or below 0.1 nm (the bare metal); the
 * film's index faded to the outside's below 1 nm. In air (index 1).
 * reference_film.c transcribes it from the source files it names. */
void ref_film_blender(double film_ior, double d_nm, double c, const double base[3], const double tint[3],
                      const film_cmfs *k, double rgb[3]);

/* MaterialX's thin_film_bsdf over a generalized_schlick_bsdf (and so
 * OpenPBR's thin film over its metal, whose reference graph is that node
 * with color90 = 1 and exponent 5): mx_fresnel_airy of
 * libraries/pbrlib/genglsl/lib/mx_microfacet_specular.glsl. The base's
 * index from color0 as a dielectric's, its reflectance inside the film half
 * of Hoffman's curve at the film's angle, phase shifts of 0 or pi, orders
 * m <= iterations (the generator's default 2) against Belcour and Barla's
 * Gaussian fits of the XYZ sensitivities, each RGB channel's terms taken as
 * the same-numbered XYZ component, then CIE RGB (illuminant E) held to
 * [0, 1]. At d = 0 the bare generalized Schlick curve. In air. */
void ref_film_materialx(double film_ior, double d_nm, double c, const double color0[3], const double color82[3],
                        const double color90[3], double exponent, int iterations, double rgb[3]);

/* C99 has no CMPLX: a complex from its parts with the sign of a zero
 * imaginary part kept (it decides csqrt's branch on the negative axis). */
double complex ref_complex(double re, double im);

#endif
