/* Black-box fit of one colour channel's eta, kappa to ground-truth
 * reflectance [Hof20, "Computing RGB Parameter Values From Spectral IOR
 * Data"]: no physically meaningful RGB eta, kappa exists, so the useful one
 * is whichever makes the exact Fresnel curve closest to the spectral truth.
 * Host only. */
#ifndef FRESNEL_FIT_H
#define FRESNEL_FIT_H

/* The search box. Targets the exact Fresnel curve cannot reach (a channel
 * above 1, as linear-sRGB gold red at normal incidence) drive the fit towards
 * reflectance 1, i.e. towards an edge of this box; the box keeps the result
 * finite and inside the runtime's domain (fresnel.h CONVENTIONS). */
#define FIT_ETA_MIN 1e-3
#define FIT_ETA_MAX 1e3
#define FIT_KAPPA_MAX 1e3

typedef struct fit_report {
    double rms;       /* RMS of ref_conductor(eta, kappa, c_i) - target_i at the result */
    int starts;       /* local searches run */
    int iterations;   /* damped Gauss-Newton iterations, summed over the starts */
    long evaluations; /* ref_conductor calls, the unit of cost */
} fit_report;

/* eta in [FIT_ETA_MIN, FIT_ETA_MAX] and kappa in [0, FIT_KAPPA_MAX]
 * minimising the RMS of ref_conductor(eta, kappa, cos_theta[i]) - target[i]
 * over the n samples (eta, kappa relative to the incident medium, as the
 * targets are). kappa is exactly 0 when absorption would change the RMS by
 * less than round-off. Deterministic: no random starts.
 * Cost: about 1e5 ref_conductor calls for 91 samples (a few ms at -O2),
 * growing linearly with n. Returns 0, or -1 (outputs untouched) when n < 1,
 * a pointer is NULL or an input is not finite. */
int fit_eta_kappa(const double *cos_theta, const double *target, int n, double *eta,
                  double *kappa);
/* The same, also describing the fit in *report (may be NULL). */
int fit_eta_kappa_report(const double *cos_theta, const double *target, int n, double *eta,
                         double *kappa, fit_report *report);
/* The same minimising sum (w[i] (R_i - target[i]))^2 (w NULL: all 1; else
 * every w[i] finite and > 0). report->rms stays the unweighted RMS. */
int fit_eta_kappa_weighted(const double *cos_theta, const double *target, const double *w, int n, double *eta,
                           double *kappa, fit_report *report);

#endif
