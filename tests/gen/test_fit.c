/* RGB eta, kappa fit: recovers known curves to round-off, finds the best
 * compromise for curves the exact model cannot reach, stays finite for
 * out-of-range targets, and is deterministic. */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "2_derive/fit.h"
#include "harness.h"
#include "common/reference.h"

#define ANGLES 91
#define PI 3.14159265358979323846

static double cosines[ANGLES];

static void fill_cosines(void)
{
    int i;
    for (i = 0; i < ANGLES; i++)
        cosines[i] = cos(i * PI / 180.0);
    cosines[ANGLES - 1] = 0.0; /* cos(pi/2) rounds to 6e-17; grazing is exactly 0 */
}

static double rms_against(double eta, double kappa, const double *target)
{
    double s = 0.0;
    int i;
    for (i = 0; i < ANGLES; i++) {
        double d = ref_conductor(eta, kappa, cosines[i]) - target[i];
        s += d * d;
    }
    return sqrt(s / ANGLES);
}

static double seconds(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

static void test_recovery(void)
{
    static const struct {
        const char *name;
        double eta, kappa;
    } cases[] = {
        {"gold red", 0.17, 3.2},    {"aluminium", 1.0, 6.7},      {"glass", 1.5, 0.0},
        {"silver", 0.05, 4.0},      {"chromium", 3.2, 3.3},       {"copper green", 0.9, 2.6},
        {"iron", 2.9, 3.0},         {"water to air", 0.75, 0.0},  {"diamond", 2.42, 0.0},
        {"weak absorber", 1.6, 0.02}, {"gold in water", 0.13, 2.4}, {"titanium", 2.7, 3.8},
        {"water from glass", 0.887, 0.0}, {"glass from diamond", 0.62, 0.0},
        {"near-critical", 0.996, 0.0}, {"lossy, from glass", 0.8, 0.004},
    };
    size_t k;
    long evaluations = 0;
    int iterations = 0, starts = 0;
    double t0 = seconds(), elapsed;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double target[ANGLES], eta = -1.0, kappa = -1.0, eta_err, kappa_err;
        char name[96];
        fit_report rep;
        int i, rc;
        for (i = 0; i < ANGLES; i++)
            target[i] = ref_conductor(cases[k].eta, cases[k].kappa, cosines[i]);
        rc = fit_eta_kappa_report(cosines, target, ANGLES, &eta, &kappa, &rep);
        eta_err = fabs(eta - cases[k].eta) / cases[k].eta;
        kappa_err = cases[k].kappa > 0.0 ? fabs(kappa - cases[k].kappa) / cases[k].kappa : kappa;
        snprintf(name, sizeof name, "fit recovers %s (%g, %g): curve", cases[k].name,
                 cases[k].eta, cases[k].kappa);
        CHECK(name, rc == 0 && rms_against(eta, kappa, target) < 1e-9 && rep.rms < 1e-9,
              "rc %d, got (%.9g, %.9g), rms %.3g", rc, eta, kappa, rms_against(eta, kappa, target));
        snprintf(name, sizeof name, "fit recovers %s (%g, %g): parameters", cases[k].name,
                 cases[k].eta, cases[k].kappa);
        CHECK(name, eta_err < 1e-5 && kappa_err < 1e-5,
              "got (%.9g, %.9g), relative errors %.3g, %.3g", eta, kappa, eta_err, kappa_err);
        NOTE("fit %-14s (%g, %g): rel. errors eta %.1e kappa %.1e, rms %.1e; %d starts, %d "
             "iterations, %ld evaluations",
             cases[k].name, cases[k].eta, cases[k].kappa, eta_err, kappa_err, rep.rms, rep.starts,
             rep.iterations, rep.evaluations);
        evaluations += rep.evaluations;
        iterations += rep.iterations;
        starts += rep.starts;
    }
    elapsed = seconds() - t0;
    NOTE("fit recovery: %d fits, %d starts, %d iterations, %ld evaluations, %.1f ms CPU "
         "(%.2f ms per fit)",
         (int)k, starts, iterations, evaluations, 1e3 * elapsed, 1e3 * elapsed / (double)k);
}

/* Targets from other curves: no exact match exists, so the fit must at least
 * beat every point of a dense grid over the plausible range. */
static void test_compromise(void)
{
    static const struct {
        const char *name;
        double f0, bump; /* Schlick curve, plus bump * sin(pi c): not a Fresnel curve */
    } cases[] = {{"schlick 0.04", 0.04, 0.0},       {"schlick 0.5", 0.5, 0.0},
                 {"schlick 0.95", 0.95, 0.0},       {"schlick 0.9 + bump", 0.9, 0.03},
                 {"schlick 0.2 - bump", 0.2, -0.05}, {"schlick 0.7 + bump", 0.7, 0.1}};
    size_t k;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double target[ANGLES], eta, kappa, fitted, dense = INFINITY, dense_eta = 0, dense_kappa = 0;
        char name[96];
        int i, a, b, rc;
        for (i = 0; i < ANGLES; i++)
            target[i] = ref_schlick(cases[k].f0, cosines[i]) + cases[k].bump * sin(PI * cosines[i]);
        rc = fit_eta_kappa(cosines, target, ANGLES, &eta, &kappa);
        fitted = rms_against(eta, kappa, target);
        for (a = 0; a < 160; a++)
            for (b = 0; b <= 160; b++) {
                double e = 0.01 * pow(1000.0, a / 159.0);
                double kp = b == 0 ? 0.0 : 0.001 * pow(20000.0, (b - 1) / 159.0);
                double r = rms_against(e, kp, target);
                if (r < dense) {
                    dense = r;
                    dense_eta = e;
                    dense_kappa = kp;
                }
            }
        snprintf(name, sizeof name, "fit compromise %s beats a dense grid", cases[k].name);
        CHECK(name, rc == 0 && fitted <= dense,
              "fit (%.6g, %.6g) rms %.6g; grid (%.6g, %.6g) rms %.6g", eta, kappa, fitted,
              dense_eta, dense_kappa, dense);
        NOTE("fit %-20s -> (%.5g, %.5g) rms %.3e (dense grid best %.3e)", cases[k].name, eta,
             kappa, fitted, dense);
    }
}

static void test_out_of_range(void)
{
    double target[ANGLES], eta, kappa, floor_rms;
    fit_report rep;
    int i, rc;

    for (i = 0; i < ANGLES; i++)
        target[i] = 1.02;
    rc = fit_eta_kappa_report(cosines, target, ANGLES, &eta, &kappa, &rep);
    CHECK("fit all-1.02 target gives finite values in the box",
          rc == 0 && isfinite(eta) && isfinite(kappa) && eta >= FIT_ETA_MIN &&
              eta <= FIT_ETA_MAX && kappa >= 0.0 && kappa <= FIT_KAPPA_MAX && isfinite(rep.rms),
          "rc %d, got (%g, %g), rms %g", rc, eta, kappa, rep.rms);
    CHECK("fit all-1.02 target saturates (reflectance ~1)", rep.rms < 0.0201,
          "rms %g against the 0.02 floor", rep.rms);
    NOTE("fit all-1.02 -> (%g, %g) rms %.4g, %d iterations, %ld evaluations", eta, kappa, rep.rms,
         rep.iterations, rep.evaluations);

    /* A red channel as a colour matrix makes it: weights summing to 1, one
     * negative, over two spectral curves, so F0 exceeds 1 (here 1.05) while
     * grazing incidence stays at exactly 1. */
    for (i = 0; i < ANGLES; i++)
        target[i] = 1.25 * ref_conductor(0.17, 3.2, cosines[i]) -
                    0.25 * ref_conductor(1.0, 2.0, cosines[i]);
    rc = fit_eta_kappa_report(cosines, target, ANGLES, &eta, &kappa, &rep);
    for (i = 0, floor_rms = 0.0; i < ANGLES; i++)
        floor_rms += (target[i] - 1.0) * (target[i] - 1.0);
    floor_rms = sqrt(floor_rms / ANGLES); /* every sample is >= 1: reflectance 1 is best */
    CHECK("fit red channel with F0 1.05 gives finite values in the box",
          rc == 0 && isfinite(eta) && isfinite(kappa) && eta >= FIT_ETA_MIN &&
              eta <= FIT_ETA_MAX && kappa >= 0.0 && kappa <= FIT_KAPPA_MAX,
          "rc %d, got (%g, %g)", rc, eta, kappa);
    CHECK("fit red channel with F0 1.05 reaches the saturation floor",
          rep.rms <= floor_rms + 1e-6, "rms %.9g, floor %.9g", rep.rms, floor_rms);
    NOTE("fit red channel, F0 %.4f -> (%g, %g) rms %.4g", target[0], eta, kappa, rep.rms);

    for (i = 0; i < ANGLES; i++)
        target[i] = -0.01;
    rc = fit_eta_kappa(cosines, target, ANGLES, &eta, &kappa);
    CHECK("fit all-negative target gives finite values",
          rc == 0 && isfinite(eta) && isfinite(kappa) && eta >= FIT_ETA_MIN && kappa >= 0.0,
          "rc %d, got (%g, %g)", rc, eta, kappa);
    NOTE("fit all -0.01 -> (%g, %g)", eta, kappa);
}

static void test_edges(void)
{
    double target[ANGLES], eta = 7.0, kappa = 7.0, eta2, kappa2, one_c = 1.0, one_t = 0.04;
    int i, rc;
    for (i = 0; i < ANGLES; i++)
        target[i] = ref_conductor(1.2, 2.1, cosines[i]);
    rc = fit_eta_kappa(cosines, target, ANGLES, &eta, &kappa);
    fit_eta_kappa(cosines, target, ANGLES, &eta2, &kappa2);
    CHECK("fit is deterministic", rc == 0 && eta == eta2 && kappa == kappa2,
          "(%.17g, %.17g) then (%.17g, %.17g)", eta, kappa, eta2, kappa2);

    eta = kappa = 7.0;
    target[3] = NAN;
    rc = fit_eta_kappa(cosines, target, ANGLES, &eta, &kappa);
    CHECK("fit rejects a NaN target, outputs untouched", rc == -1 && eta == 7.0 && kappa == 7.0,
          "rc %d", rc);
    target[3] = 0.5;
    cosines[5] = INFINITY;
    rc = fit_eta_kappa(cosines, target, ANGLES, &eta, &kappa);
    cosines[5] = cos(5 * PI / 180.0);
    CHECK("fit rejects an infinite cosine", rc == -1, "rc %d", rc);
    CHECK("fit rejects n = 0 and NULL",
          fit_eta_kappa(cosines, target, 0, &eta, &kappa) == -1 &&
              fit_eta_kappa(NULL, target, ANGLES, &eta, &kappa) == -1 &&
              fit_eta_kappa(cosines, NULL, ANGLES, &eta, &kappa) == -1 &&
              fit_eta_kappa(cosines, target, ANGLES, NULL, &kappa) == -1 &&
              fit_eta_kappa(cosines, target, ANGLES, &eta, NULL) == -1,
          "one was accepted");

    /* One sample cannot identify two parameters, but any answer on the
     * curve through it will do. */
    rc = fit_eta_kappa(&one_c, &one_t, 1, &eta, &kappa);
    CHECK("fit with a single sample matches it",
          rc == 0 && isfinite(eta) && isfinite(kappa) &&
              fabs(ref_conductor(eta, kappa, 1.0) - 0.04) < 1e-9,
          "rc %d, got (%g, %g) -> %.12g", rc, eta, kappa, ref_conductor(eta, kappa, 1.0));
}

/* The generator's load: 3 channels x 20 materials at 91 angles. */
static void test_cost(void)
{
    double t0, elapsed, worst = 0.0;
    long evaluations = 0;
    int m, ch, i;
    t0 = seconds();
    for (m = 0; m < 20; m++)
        for (ch = 0; ch < 3; ch++) {
            double e = 0.05 + 0.16 * m + 0.3 * ch, kp = m % 5 == 4 ? 0.0 : 0.5 * m + 0.4 * ch;
            double target[ANGLES], eta, kappa, r;
            fit_report rep;
            for (i = 0; i < ANGLES; i++)
                target[i] = ref_conductor(e, kp, cosines[i]);
            fit_eta_kappa_report(cosines, target, ANGLES, &eta, &kappa, &rep);
            r = rms_against(eta, kappa, target);
            worst = r > worst ? r : worst;
            evaluations += rep.evaluations;
        }
    elapsed = seconds() - t0;
    CHECK("fit 60 channels all recovered", worst < 1e-9, "worst rms %.3g", worst);
    NOTE("fit 3 channels x 20 materials x 91 angles: %.1f ms CPU, %ld evaluations, worst rms %.1e",
         1e3 * elapsed, evaluations, worst);
}

int main(void)
{
    fill_cosines();
    test_recovery();
    test_compromise();
    test_out_of_range();
    test_edges();
    test_cost();
    return harness_exit();
}
