/* Fitting the thin-film model (film_fit.h, common/reference_film.h).
 *
 * POLES. S_k(x) = sum_l w_k(l) exp(2 pi i x / l), the Fourier transform of
 * sensitivity k over wavenumber, is fitted for x >= 0 by
 * sum_j c_kj exp(2 pi i x p_j), Im p_j > 0 [a sum of Lorentzian lines in
 * wavenumber; Prony's problem]: variable projection (the c_kj by linear
 * least squares for given poles) and Levenberg-Marquardt on
 * (Re p_j, log Im p_j). For x > 0 the integral of w times a function of
 * wavenumber analytic above the real axis then closes on the poles:
 *   sum_l w(l) a(1/l) exp(2 pi i m X / l) ~ sum_j c_j a(p_j) exp(2 pi i m X p_j),
 * and with a(nu) the Airy terms' Fourier coefficients kappa q^(m-1) the sum
 * over every order m is kappa(p_j) zeta / (1 - q(p_j) zeta).
 *
 * CONTINUATION. kappa and q are known on the real axis (at the 1 nm
 * samples); each is fitted by a quadratic in u = (nu - Re p_j) / Im p_j
 * over |u| <= 2 and taken at u = i.
 *
 * REFIT. Then both are refitted at each node to the spectral truth at
 * thicknesses 0..FILM_FIT_D_MAX nm, each channel's residual weighted by
 * (max(R, 0) + 0.01)^(-2/3) (CIELAB's lightness slope, so that dark
 * anti-reflection minima count as much as they show), d = 0 ten times: for
 * given q the model is linear in the kappas (least squares, a small ridge
 * towards the continued values), and q takes damped Gauss-Newton steps
 * with the kappas held, a ridge (Q_RIDGE) keeping it near its continued
 * value. */
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "2_derive/film_fit.h"

#define J FRESNEL_FILM_POLES
#define NODES FRESNEL_FILM_NODES
static const double two_pi = 6.283185307179586476925;

/* ---------------------------------------------------------------- poles */

#define POLE_SAMPLES 2001 /* x = 0, 10, ..., FILM_FIT_X_MAX */
#define P (2 * J)

typedef struct pole_problem {
    double complex s[3][POLE_SAMPLES];
    double x[POLE_SAMPLES];
} pole_problem;

/* Solve the Hermitian positive definite system a c = b (n x n, nrhs
 * right-hand sides stored one after another) by Cholesky; 0 or -1. */
static int solve_hermitian(int n, double complex *a, double complex *b, int nrhs)
{
    int i, j, k, r;
    for (k = 0; k < n; k++) {
        double d = creal(a[k * n + k]);
        for (j = 0; j < k; j++)
            d -= creal(a[k * n + j] * conj(a[k * n + j]));
        if (!(d > 0.0))
            return -1;
        d = sqrt(d);
        a[k * n + k] = d;
        for (i = k + 1; i < n; i++) {
            double complex s = a[i * n + k];
            for (j = 0; j < k; j++)
                s -= a[i * n + j] * conj(a[k * n + j]);
            a[i * n + k] = s / d;
        }
    }
    for (r = 0; r < nrhs; r++) {
        double complex *x = b + r * n;
        for (i = 0; i < n; i++) {
            double complex s = x[i];
            for (j = 0; j < i; j++)
                s -= a[i * n + j] * x[j];
            x[i] = s / creal(a[i * n + i]);
        }
        for (i = n - 1; i >= 0; i--) {
            double complex s = x[i];
            for (j = i + 1; j < n; j++)
                s -= conj(a[j * n + i]) * x[j];
            x[i] = s / creal(a[i * n + i]);
        }
    }
    return 0;
}

/* Solve the real symmetric system a x = b (n x n) by Gaussian elimination
 * with partial pivoting; 0 or -1. */
static int solve_real(int n, double *a, double *b)
{
    int i, j, k;
    for (k = 0; k < n; k++) {
        int piv = k;
        for (i = k + 1; i < n; i++)
            if (fabs(a[i * n + k]) > fabs(a[piv * n + k]))
                piv = i;
        if (!(fabs(a[piv * n + k]) > 0.0))
            return -1;
        if (piv != k) {
            double t;
            for (j = 0; j < n; j++) {
                t = a[k * n + j];
                a[k * n + j] = a[piv * n + j];
                a[piv * n + j] = t;
            }
            t = b[k];
            b[k] = b[piv];
            b[piv] = t;
        }
        for (i = k + 1; i < n; i++) {
            double f = a[i * n + k] / a[k * n + k];
            for (j = k; j < n; j++)
                a[i * n + j] -= f * a[k * n + j];
            b[i] -= f * b[k];
        }
    }
    for (k = n - 1; k >= 0; k--) {
        double s = b[k];
        for (j = k + 1; j < n; j++)
            s -= a[k * n + j] * b[j];
        b[k] = s / a[k * n + k];
    }
    return 0;
}

/* The residuals (real and imaginary parts, 3 x samples x 2) of the best
 * coefficients for poles theta = (nu_j, log gamma_j); coef may be NULL.
 * Returns the sum of squares, or HUGE_VAL when the basis is degenerate. */
static double pole_residual(const pole_problem *pp, const double *theta, double complex coef[3][J], double *res,
                            double complex *basis)
{
    double complex a[J * J], rhs[3 * J];
    double ss = 0.0;
    int i, j, l, k;
    for (j = 0; j < J; j++) {
        double complex p = theta[2 * j] + I * exp(theta[2 * j + 1]);
        for (i = 0; i < POLE_SAMPLES; i++)
            basis[i * J + j] = cexp(I * two_pi * pp->x[i] * p);
    }
    for (j = 0; j < J; j++)
        for (l = 0; l < J; l++) {
            double complex s = 0.0;
            for (i = 0; i < POLE_SAMPLES; i++)
                s += conj(basis[i * J + j]) * basis[i * J + l];
            a[j * J + l] = s;
        }
    for (k = 0; k < 3; k++)
        for (j = 0; j < J; j++) {
            double complex s = 0.0;
            for (i = 0; i < POLE_SAMPLES; i++)
                s += conj(basis[i * J + j]) * pp->s[k][i];
            rhs[k * J + j] = s;
        }
    if (solve_hermitian(J, a, rhs, 3))
        return HUGE_VAL;
    for (k = 0; k < 3; k++)
        for (i = 0; i < POLE_SAMPLES; i++) {
            double complex e = -pp->s[k][i];
            for (j = 0; j < J; j++)
                e += rhs[k * J + j] * basis[i * J + j];
            if (res) {
                res[(k * POLE_SAMPLES + i) * 2] = creal(e);
                res[(k * POLE_SAMPLES + i) * 2 + 1] = cimag(e);
            }
            ss += creal(e * conj(e));
        }
    if (coef)
        for (k = 0; k < 3; k++)
            for (j = 0; j < J; j++)
                coef[k][j] = rhs[k * J + j];
    return ss;
}

int film_fit_poles(const colorimetry *cm, const colour_space *cs, film_model *m, double *max_error)
{
    enum { R = 3 * POLE_SAMPLES * 2 };
    pole_problem *pp = malloc(sizeof *pp);
    double *r = malloc(sizeof *r * R), *r2 = malloc(sizeof *r2 * R), *jac = malloc(sizeof *jac * R * P);
    double complex *basis = malloc(sizeof *basis * POLE_SAMPLES * J), coef[3][J];
    double theta[P], norm = 0.0, lambda = 1e-3, ss, worst = 0.0;
    int i, j, k, it, a, b, status = -1;
    if (!pp || !r || !r2 || !jac || !basis)
        goto done;
    for (j = 0; j < CMF_N; j++)
        norm += cm->d65[j] * cm->ybar[j];
    for (i = 0; i < POLE_SAMPLES; i++) {
        pp->x[i] = i * (FILM_FIT_X_MAX / (POLE_SAMPLES - 1));
        for (k = 0; k < 3; k++)
            pp->s[k][i] = 0.0;
        for (j = 0; j < CMF_N; j++) {
            double complex e = cexp(I * two_pi * pp->x[i] / (SPEC_LO_NM + j));
            pp->s[0][i] += cm->d65[j] * cm->xbar[j] / norm * e;
            pp->s[1][i] += cm->d65[j] * cm->ybar[j] / norm * e;
            pp->s[2][i] += cm->d65[j] * cm->zbar[j] / norm * e;
        }
    }
    /* Start: poles evenly spread in wavenumber over 420-700 nm, 1e-4 wide. */
    for (j = 0; j < J; j++) {
        theta[2 * j] = 1.0 / 700.0 + (1.0 / 420.0 - 1.0 / 700.0) * j / (J - 1.0);
        theta[2 * j + 1] = log(1e-4);
    }
    ss = pole_residual(pp, theta, NULL, r, basis);
    for (it = 0; it < 200 && ss < HUGE_VAL; it++) {
        double jtj[P * P], g[P], sys[P * P], step[P], trial[P], ss2 = HUGE_VAL;
        for (a = 0; a < P; a++) {
            double h = a % 2 ? 1e-6 : 1e-9, save = theta[a];
            theta[a] = save + h;
            pole_residual(pp, theta, NULL, r2, basis);
            theta[a] = save;
            for (i = 0; i < R; i++)
                jac[i * P + a] = (r2[i] - r[i]) / h;
        }
        for (a = 0; a < P; a++) {
            g[a] = 0.0;
            for (i = 0; i < R; i++)
                g[a] += jac[i * P + a] * r[i];
            for (b = 0; b <= a; b++) {
                double s = 0.0;
                for (i = 0; i < R; i++)
                    s += jac[i * P + a] * jac[i * P + b];
                jtj[a * P + b] = jtj[b * P + a] = s;
            }
        }
        for (;;) {
            memcpy(sys, jtj, sizeof sys);
            for (a = 0; a < P; a++) {
                sys[a * P + a] *= 1.0 + lambda;
                step[a] = -g[a];
            }
            if (solve_real(P, sys, step) == 0) {
                for (a = 0; a < P; a++)
                    trial[a] = theta[a] + step[a];
                ss2 = pole_residual(pp, trial, NULL, r2, basis);
            }
            if (ss2 < ss) {
                double gain = ss - ss2;
                memcpy(theta, trial, sizeof theta);
                memcpy(r, r2, sizeof *r * R);
                ss = ss2;
                lambda *= 0.3;
                if (gain < 1e-12 * ss)
                    it = 200;
                break;
            }
            lambda *= 10.0;
            if (lambda > 1e12) {
                it = 200;
                break;
            }
        }
    }
    if (!(pole_residual(pp, theta, coef, r, basis) < HUGE_VAL))
        goto done;
    for (i = 0; i < R / 2; i++)
        worst = fmax(worst, hypot(r[2 * i], r[2 * i + 1]));
    for (j = 0; j < J; j++) {
        m->nu[j] = theta[2 * j];
        m->gamma[j] = exp(theta[2 * j + 1]);
        /* (the binary32 runtime relies on 0 < nu, gamma < 1: src/f32/film.c) */
        if (!(m->nu[j] > 1.0 / SPEC_HI_NM && m->nu[j] < 1.0 / SPEC_LO_NM && m->gamma[j] > 0.0 && m->gamma[j] < 1.0))
            goto done;
        for (k = 0; k < 3; k++)
            m->weight[k][j] = cs->xyz_to_rgb[k][0] * coef[0][j] + cs->xyz_to_rgb[k][1] * coef[1][j] +
                              cs->xyz_to_rgb[k][2] * coef[2][j];
    }
    if (max_error)
        *max_error = worst;
    status = 0;
done:
    free(pp);
    free(r);
    free(r2);
    free(jac);
    free(basis);
    return status;
}

/* ------------------------------------------------------------- a material */

/* The Fourier coefficients of one wavelength, both polarisations. In total
 * reflection inside the film (|r12| = 1, zeta real) the form is the
 * expansion's first terms: a0 = |r12|^2, kappa = conj(r12) b, q as always;
 * the refit absorbs the rest. */
typedef struct film_terms {
    double a0;
    double complex kappa[2], q[2];
} film_terms;

/* q is kept inside |q| <= 1 - 2^-10: at a film's exact critical angle
 * |q| = 1 and 1 - q zeta = 0 at d = 0. */
static double complex q_inside(double complex q)
{
    const double q_max = 1.0 - 1.0 / 1024.0;
    double a = cabs(q);
    return a > q_max ? q * (q_max / a) : q;
}

static void terms_at(const ref_film_optics *o, int tir, film_terms *t)
{
    int pol;
    t->a0 = 0.0;
    for (pol = 0; pol < 2; pol++) {
        double a0;
        double complex kappa, q;
        ref_film_series(o->r12[pol], o->r23[pol], &a0, &kappa, &q);
        if (tir) {
            double complex b = (1.0 - o->r12[pol] * o->r12[pol]) * o->r23[pol];
            a0 = creal(o->r12[pol] * conj(o->r12[pol]));
            kappa = conj(o->r12[pol]) * b;
        }
        t->a0 += 0.5 * a0;
        t->kappa[pol] = 0.5 * kappa;
        t->q[pol] = q;
    }
}

typedef struct a0_at {
    const film_terms *t;
} a0_at;

static double incoherent(const void *ctx, int node, double nm)
{
    const a0_at *a = ctx;
    (void)nm;
    return a->t[node / 10].a0;
}

/* Quadratic least squares of v(u) over |u| <= 2, u = (1/lambda - nu) / gamma
 * at the CMF samples, evaluated at u = i. */
static double complex continued(const film_terms *t, int pol, int which, double nu, double gamma)
{
    double a[9] = {0}, br[3] = {0}, bi[3] = {0};
    int l, x, y;
    for (l = 0; l < CMF_N; l++) {
        double u = (1.0 / (SPEC_LO_NM + l) - nu) / gamma, ph[3];
        double complex v = which ? t[l].q[pol] : t[l].kappa[pol];
        if (fabs(u) > 2.0)
            continue;
        ph[0] = 1.0;
        ph[1] = u;
        ph[2] = u * u;
        for (x = 0; x < 3; x++) {
            br[x] += ph[x] * creal(v);
            bi[x] += ph[x] * cimag(v);
            for (y = 0; y < 3; y++)
                a[x * 3 + y] += ph[x] * ph[y];
        }
    }
    {
        double a2[9];
        memcpy(a2, a, sizeof a2);
        if (solve_real(3, a, br) || solve_real(3, a2, bi))
            return which ? t[0].q[pol] : t[0].kappa[pol];
    }
    /* v(i) = b0 + i b1 - b2 */
    return (br[0] - br[2]) + I * br[1] + I * (bi[0] - bi[2]) - bi[1];
}

#define FIT_D_STEP 10.0
#define FIT_D_N 121 /* 0, FIT_D_STEP, ..., FILM_FIT_D_MAX */
#define U (4 * J) /* unknowns: Re, Im of kappa (or q) per pole and polarisation */

/* One node's fit: the truth at the thicknesses, the poles' zeta there. */
typedef struct node_fit {
    const film_model *m;
    int node;
    double truth[FIT_D_N][3];
    double complex zeta[FIT_D_N][J];
    double complex kappa0[J][2], q0[J][2]; /* the continued values: the ridge's centre */
} node_fit;

static double weight_of(double r, int i)
{
    return pow(fmax(r, 0.0) + 0.01, -2.0 / 3.0) * (i == 0 ? 10.0 : 1.0);
}

/* The kappas that minimise the weighted residual for the given q (linear
 * least squares with a ridge towards the continued kappas); the weighted
 * sum of squares at them, or HUGE_VAL. */
static double solve_kappa(const node_fit *nf, double complex q[J][2], double complex kappa[J][2])
{
    const film_model *m = nf->m;
    double a[U * U], rhs[U], row[U], trace = 0.0, ridge, ss = 0.0;
    int i, j, pol, ch, x, y;
    memset(a, 0, sizeof a);
    memset(rhs, 0, sizeof rhs);
    for (i = 0; i < FIT_D_N; i++)
        for (ch = 0; ch < 3; ch++) {
            double w = weight_of(nf->truth[i][ch], i), y_ = (nf->truth[i][ch] - m->a0[nf->node][ch]) * w;
            for (j = 0; j < J; j++)
                for (pol = 0; pol < 2; pol++) {
                    double complex cp = 2.0 * m->weight[ch][j] * nf->zeta[i][j] / (1.0 - q[j][pol] * nf->zeta[i][j]);
                    row[4 * j + 2 * pol] = creal(cp) * w;
                    row[4 * j + 2 * pol + 1] = -cimag(cp) * w;
                }
            for (x = 0; x < U; x++) {
                rhs[x] += row[x] * y_;
                for (y = 0; y < U; y++)
                    a[x * U + y] += row[x] * row[y];
            }
        }
    for (x = 0; x < U; x++)
        trace += a[x * U + x];
    ridge = 1e-6 * trace / U;
    for (j = 0; j < J; j++)
        for (pol = 0; pol < 2; pol++) {
            x = 4 * j + 2 * pol;
            a[x * U + x] += ridge;
            a[(x + 1) * U + x + 1] += ridge;
            rhs[x] += ridge * creal(nf->kappa0[j][pol]);
            rhs[x + 1] += ridge * cimag(nf->kappa0[j][pol]);
        }
    if (solve_real(U, a, rhs))
        return HUGE_VAL;
    for (j = 0; j < J; j++)
        for (pol = 0; pol < 2; pol++)
            kappa[j][pol] = rhs[4 * j + 2 * pol] + I * rhs[4 * j + 2 * pol + 1];
    for (i = 0; i < FIT_D_N; i++)
        for (ch = 0; ch < 3; ch++) {
            double r = m->a0[nf->node][ch] - nf->truth[i][ch];
            for (j = 0; j < J; j++)
                for (pol = 0; pol < 2; pol++)
                    r += 2.0 * creal(m->weight[ch][j] * kappa[j][pol] * nf->zeta[i][j] /
                                     (1.0 - q[j][pol] * nf->zeta[i][j]));
            r *= weight_of(nf->truth[i][ch], i);
            ss += r * r;
        }
    return ss;
}

/* The ridge that keeps q near its continued value, relative to the mean
 * diagonal of the Gauss-Newton matrix. The nodes are fitted one by one and
 * interpolated linearly in c: a q that wanders from node to node to gain
 * at the nodes loses more between them (a ridge 100 times smaller tripled
 * the worst CIEDE2000 of the goal matrix while lowering it at the nodes). */
#define Q_RIDGE 1e-1
static double q_penalty(const node_fit *nf, double complex q[J][2], double mu)
{
    double s = 0.0;
    int j, pol;
    for (j = 0; j < J; j++)
        for (pol = 0; pol < 2; pol++)
            s += mu * creal((q[j][pol] - nf->q0[j][pol]) * conj(q[j][pol] - nf->q0[j][pol]));
    return s;
}

/* Then q, by damped Gauss-Newton steps with the kappas held (Kaufman's
 * simplification of variable projection), the kappas solved again after
 * each step; a step is kept only where it lowers the sum of squares plus
 * the ridge, and q stays inside q_inside's disc. */
static void refine_q(const node_fit *nf, double complex q[J][2], double complex kappa[J][2])
{
    const film_model *m = nf->m;
    double ss = solve_kappa(nf, q, kappa), lambda = 1e-2, mu = -1.0;
    int it, i, j, pol, ch, x, y;
    for (it = 0; it < 12 && ss < HUGE_VAL; it++) {
        double a[U * U], g[U], row[U];
        double complex q2[J][2], kappa2[J][2];
        double ss2;
        memset(a, 0, sizeof a);
        memset(g, 0, sizeof g);
        for (i = 0; i < FIT_D_N; i++)
            for (ch = 0; ch < 3; ch++) {
                double w = weight_of(nf->truth[i][ch], i), r = m->a0[nf->node][ch] - nf->truth[i][ch];
                for (j = 0; j < J; j++)
                    for (pol = 0; pol < 2; pol++) {
                        double complex z = nf->zeta[i][j], den = 1.0 - q[j][pol] * z;
                        double complex ck = 2.0 * m->weight[ch][j] * kappa[j][pol];
                        double complex dq = ck * z * z / (den * den); /* d model / d q */
                        r += creal(ck * z / den);
                        row[4 * j + 2 * pol] = creal(dq) * w;
                        row[4 * j + 2 * pol + 1] = -cimag(dq) * w;
                    }
                r *= w;
                for (x = 0; x < U; x++) {
                    g[x] += row[x] * r;
                    for (y = 0; y < U; y++)
                        a[x * U + y] += row[x] * row[y];
                }
            }
        if (mu < 0.0) {
            double trace = 0.0;
            for (x = 0; x < U; x++)
                trace += a[x * U + x];
            mu = Q_RIDGE * trace / U;
            ss += q_penalty(nf, q, mu);
        }
        for (j = 0; j < J; j++)
            for (pol = 0; pol < 2; pol++) {
                x = 4 * j + 2 * pol;
                a[x * U + x] += mu;
                a[(x + 1) * U + x + 1] += mu;
                g[x] += mu * creal(q[j][pol] - nf->q0[j][pol]);
                g[x + 1] += mu * cimag(q[j][pol] - nf->q0[j][pol]);
            }
        for (;;) {
            double sys[U * U], step[U];
            memcpy(sys, a, sizeof sys);
            for (x = 0; x < U; x++) {
                sys[x * U + x] += lambda * (a[x * U + x] + 1e-12);
                step[x] = -g[x];
            }
            ss2 = HUGE_VAL;
            if (solve_real(U, sys, step) == 0) {
                for (j = 0; j < J; j++)
                    for (pol = 0; pol < 2; pol++)
                        q2[j][pol] = q_inside(q[j][pol] + step[4 * j + 2 * pol] + I * step[4 * j + 2 * pol + 1]);
                ss2 = solve_kappa(nf, q2, kappa2) + q_penalty(nf, q2, mu);
            }
            if (ss2 < ss) {
                memcpy(q, q2, sizeof q2);
                memcpy(kappa, kappa2, sizeof kappa2);
                lambda *= 0.3;
                it = ss - ss2 < 1e-9 * ss ? 12 : it;
                ss = ss2;
                break;
            }
            lambda *= 10.0;
            if (lambda > 1e8) {
                it = 12;
                break;
            }
        }
    }
}

/* Distance of the complex z from the real segment [0, 1]. */
static double segment_distance(double complex z)
{
    double re = creal(z), im = fabs(cimag(z));
    if (re < 0.0)
        return hypot(re, im);
    if (re > 1.0)
        return hypot(re - 1.0, im);
    return im;
}

int film_stack_domain(const film_stack *f, char *why, size_t size)
{
    double worst = HUGE_VAL, worst_nm = 0.0, worst_n = 0.0, worst_k = 0.0;
    int j;
    if (f->film_n < f->n1) {
        snprintf(why, size,
                 "a film of index %g is less dense than the incident medium's %g: total reflection inside the film "
                 "is outside the thin-film model's domain",
                 f->film_n, f->n1);
        return -1;
    }
    for (j = 0; j < SPEC_N; j += 10) {
        double n = f->substrate->n[j], k = f->substrate->k[j];
        double complex n3 = ref_complex(n, k), branch = 1.0 - n3 * n3 / (f->n1 * f->n1);
        double dist = segment_distance(branch);
        if (dist < worst) {
            worst = dist;
            worst_nm = SPEC_LO_NM + j * SPEC_STEP_NM;
            worst_n = n;
            worst_k = k;
        }
    }
    if (!(worst >= FILM_DOMAIN_BRANCH)) {
        if (worst_k < 1e-3 && worst_n < f->n1)
            snprintf(why, size,
                     "the substrate (n %.4g, k %.3g at %.0f nm) is less dense than the incident medium's %g: it "
                     "reflects totally beyond its critical angle, outside the thin-film model's domain",
                     worst_n, worst_k, worst_nm, f->n1);
        else
            snprintf(why, size,
                     "the substrate (n %.4g, k %.3g at %.0f nm) is too close to the incident medium's index %g: "
                     "1 - N^2 / n1^2 comes within %.3g of [0, 1], where its cosine of refraction vanishes (the "
                     "domain asks %g), outside the thin-film model's domain",
                     worst_n, worst_k, worst_nm, f->n1, worst, FILM_DOMAIN_BRANCH);
        return -1;
    }
    return 0;
}

int film_fit_material(const film_stack *f, const colorimetry *cm, const colour_space *cs, film_model *m)
{
    film_model *out = malloc(sizeof *out);
    film_terms *t = malloc(sizeof *t * CMF_N);
    node_fit *nf = malloc(sizeof *nf);
    int k, l, j, pol, ch, status = -1;
    if (!out || !t || !nf || f->film || !(f->film_n >= 1e-3 && f->film_n < 1e6) || !(f->n1 > 0.0 && f->n1 < 1e6))
        goto done;
    *out = *m;
    for (k = 0; k < NODES; k++) {
        double x = (double)k / (NODES - 1), c = x * x, sigma = f->n1 * f->n1 * ((1.0 - c) * (1.0 + c));
        int tir = f->film_n * f->film_n < sigma;
        film_optics_table *truth = film_truth_prepare(f, c);
        double complex kappa[J][2], q[J][2], xi_f = 0.0;
        a0_at a;
        double rgb[3];
        if (!truth)
            goto done;
        for (l = 0; l < CMF_N; l++) {
            ref_film_optics o;
            double n_film[2], n_sub[2];
            film_stack_index(f, l, n_film, n_sub);
            ref_film_optics_at(f->n1, ref_complex(n_film[0], n_film[1]), ref_complex(n_sub[0], n_sub[1]), c, &o);
            terms_at(&o, tir, &t[l]);
            xi_f = o.xi_f;
        }
        a.t = t;
        ground_truth_of(incoherent, &a, cm, cs, rgb);
        for (ch = 0; ch < 3; ch++)
            out->a0[k][ch] = rgb[ch];
        out->opd[k] = 2.0 * creal(xi_f);
        out->decay[k] = 2.0 * cimag(xi_f);
        for (j = 0; j < J; j++)
            for (pol = 0; pol < 2; pol++) {
                nf->kappa0[j][pol] = continued(t, pol, 0, out->nu[j], out->gamma[j]);
                nf->q0[j][pol] = q_inside(continued(t, pol, 1, out->nu[j], out->gamma[j]));
            }
        nf->m = out;
        nf->node = k;
        for (l = 0; l < FIT_D_N; l++) {
            film_truth_at(truth, cm, cs, l * FIT_D_STEP, nf->truth[l]);
            for (j = 0; j < J; j++)
                nf->zeta[l][j] = cexp(I * two_pi * (l * FIT_D_STEP) * (out->opd[k] + I * out->decay[k]) *
                                      (out->nu[j] + I * out->gamma[j]));
        }
        memcpy(q, nf->q0, sizeof q);
        refine_q(nf, q, kappa);
        for (j = 0; j < J; j++)
            film_pole_terms(kappa[j], q[j], out->term[k][j]);
        free(truth);
    }
    *m = *out;
    status = 0;
done:
    free(out);
    free(t);
    free(nf);
    return status;
}
