/* The thin film's spectral truth (gen/1_spectral/film_truth.c): its
 * identities with today's ground truth, an independent evaluation by the
 * characteristic-matrix method, total internal reflection inside the film,
 * the film's critical angle, grazing light, extreme and hostile
 * thicknesses. */
#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "2_derive/derive.h"
#include "2_derive/targets.h"
#include "bench/peers.h"
#include "common/reference.h"
#include "common/reference_film.h"
#include "1_spectral/spectral.h"

static const char *const substrates[] = {"au", "cu", "al", "ti", "fe", "bk7"};
#define N_SUB 6

static double max_diff3(const double a[3], const double b[3])
{
    double m = 0.0;
    int ch;
    for (ch = 0; ch < 3; ch++)
        if (!(fabs(a[ch] - b[ch]) <= m))
            m = fabs(a[ch] - b[ch]);
    return m;
}

/* ---- an independent film: the characteristic matrix of the layer
 * [Born & Wolf 1.6.2; Macleod, Thin-Film Optical Filters, ch. 2], written
 * for this project's exp(-i w t), N = n + i k (Macleod's exp(i w t),
 * N = n - i k form conjugated, which leaves |r|^2 as it is):
 *   [B; C] = [[cos d, -i sin d / y_f], [-i y_f sin d, cos d]] [1; y_3],
 *   r = (y_1 B - C) / (y_1 B + C),
 * d = 2 pi t N_f cos(theta_f) / lambda, tilted admittances y = N cos(theta)
 * (s) and N / cos(theta) (p), each cos(theta) from Snell's law as
 * sqrt(1 - (n1 sin(theta_1) / N)^2) on the decaying branch. No Fresnel
 * coefficient and no Airy sum appear. Valid away from xi = 0 (the p
 * admittance is infinite there): the checks below keep c > 0 and avoid
 * the film's critical angle. */
static double complex cos_in(double complex n, double n1, double c)
{
    double complex sin_t = n1 * sqrt((1.0 - c) * (1.0 + c)) / n;
    double complex w = csqrt(1.0 - sin_t * sin_t);
    /* decaying branch: Im(n cos) >= 0 */
    if (cimag(n * w) < 0.0 || (cimag(n * w) == 0.0 && creal(n * w) < 0.0))
        w = -w;
    return w;
}

static double matrix_reflectance(double n1, double complex nf, double complex n3, double c, double t,
                                 double lambda)
{
    double complex cf = cos_in(nf, n1, c), c3 = cos_in(n3, n1, c);
    double complex delta = 2.0 * 3.14159265358979323846 * t * nf * cf / lambda;
    double sum = 0.0;
    int pol;
    for (pol = 0; pol < 2; pol++) {
        double complex y1 = pol ? n1 / c : n1 * c;
        double complex yf = pol ? nf / cf : nf * cf;
        double complex y3 = pol ? n3 / c3 : n3 * c3;
        double complex b = ccos(delta) - I * csin(delta) / yf * y3;
        double complex cc = -I * yf * csin(delta) + ccos(delta) * y3;
        double complex r = (y1 * b - cc) / (y1 * b + cc);
        sum += creal(r * conj(r));
    }
    return 0.5 * sum;
}

static void matrix_truth(const film_stack *f, const gen_context *g, double c, double t, double rgb[3])
{
    double x = 0.0, y = 0.0, z = 0.0, norm = 0.0;
    int j, ch;
    for (j = 0; j < CMF_N; j++) {
        double nf[2], ns[2], r;
        film_stack_index(f, j, nf, ns);
        r = matrix_reflectance(f->n1, nf[0] + I * nf[1], ns[0] + I * ns[1], c, t, 360.0 + j);
        x += r * g->cm.d65[j] * g->cm.xbar[j];
        y += r * g->cm.d65[j] * g->cm.ybar[j];
        z += r * g->cm.d65[j] * g->cm.zbar[j];
        norm += g->cm.d65[j] * g->cm.ybar[j];
    }
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = (g->cs.xyz_to_rgb[ch][0] * x + g->cs.xyz_to_rgb[ch][1] * y + g->cs.xyz_to_rgb[ch][2] * z) / norm;
}

static void test_identities(const gen_context *g, spectrum *const *s)
{
    static const double n1s[] = {1.0, 1.333, 1.52};
    static const double nfs[] = {1.2, 1.5, 2.5};
    static const double cosines[] = {0.0, 0.017452, 0.1, 0.5, 0.8660254, 1.0};
    static const double thick[] = {1.0, 100.0, 777.7, 5000.0};
    double worst_d0 = 0.0, worst_match = 0.0;
    int i, a, b, k, n;
    for (i = 0; i < N_SUB; i++)
        for (a = 0; a < 3; a++)
            for (k = 0; k < 6; k++) {
                double gt[3], rgb[3];
                film_stack f;
                ground_truth(s[i], &g->cm, &g->cs, n1s[a], cosines[k], gt);
                f.n1 = n1s[a];
                f.film = NULL;
                f.substrate = s[i];
                for (b = 0; b < 3; b++) {
                    f.film_n = nfs[b];
                    film_truth(&f, &g->cm, &g->cs, cosines[k], 0.0, rgb);
                    if (!(max_diff3(rgb, gt) <= worst_d0))
                        worst_d0 = max_diff3(rgb, gt);
                }
                f.film_n = n1s[a];
                for (n = 0; n < 4; n++) {
                    film_truth(&f, &g->cm, &g->cs, cosines[k], thick[n], rgb);
                    if (!(max_diff3(rgb, gt) <= worst_match))
                        worst_match = max_diff3(rgb, gt);
                }
            }
    CHECK("film truth: d = 0 is ground_truth (6 substrates, 3 ambients, 3 films, 6 cosines)", worst_d0 <= 1e-12,
          "worst %.3g", worst_d0);
    CHECK("film truth: a film of the ambient's index is ground_truth at every d", worst_match <= 1e-12,
          "worst %.3g", worst_match);
}

static void test_independent(const gen_context *g, spectrum *const *s, const spectrum *dispersive)
{
    static const double nfs[] = {1.2, 1.38, 1.8, 2.5};
    static const double cosines[] = {0.017452, 0.2, 0.6, 1.0};
    static const double thick[] = {0.0, 35.0, 310.0, 1000.0, 4000.0};
    double worst = 0.0;
    int i, b, k, n, count = 0;
    for (i = 0; i <= N_SUB; i++)
        for (b = 0; b < 4; b++)
            for (k = 0; k < 4; k++)
                for (n = 0; n < 5; n++) {
                    film_stack f;
                    double a[3], m[3];
                    f.n1 = b == 1 ? 1.333 : 1.0;
                    f.film = i == N_SUB ? dispersive : NULL; /* a dispersive film on gold */
                    f.film_n = nfs[b];
                    f.substrate = i == N_SUB ? s[0] : s[i];
                    film_truth(&f, &g->cm, &g->cs, cosines[k], thick[n], a);
                    matrix_truth(&f, g, cosines[k], thick[n], m);
                    if (!(max_diff3(a, m) <= worst))
                        worst = max_diff3(a, m);
                    count++;
                }
    CHECK("film truth = characteristic-matrix film within 1e-6 per channel (Airy vs matrix, 560 stacks)",
          worst <= 1e-6, "worst %.3g over %d", worst, count);
    NOTE("film truth vs characteristic matrix: largest difference %.3g over %d stacks", worst, count);
}

/* A film less dense than the incident medium: past its critical angle the
 * wave in the film is evanescent. Thick, nothing tunnels to the substrate
 * and the film reflects everything; thin, the substrate is reached
 * (frustrated total reflection). Gold under a low-index gap in glass is the
 * Otto configuration: the tunnelling light meets gold's surface plasmon. */
static void test_total_reflection(const gen_context *g, spectrum *const *s)
{
    film_stack f;
    double rgb[3], m[3], one[3] = {1.0, 1.0, 1.0}, worst_thick = 0.0, worst_matrix = 0.0;
    double c_crit, c, sigma, nf;
    int i, k;
    f.n1 = 1.52;
    f.film = NULL;
    f.film_n = 1.2;
    c_crit = sqrt(1.0 - (1.2 / 1.52) * (1.2 / 1.52));
    for (i = 0; i < N_SUB; i++) {
        f.substrate = s[i];
        for (k = 0; k < 8; k++) {
            c = c_crit * k / 9.0;
            film_truth(&f, &g->cm, &g->cs, c, 5000.0, rgb);
            if (!(max_diff3(rgb, one) <= worst_thick))
                worst_thick = max_diff3(rgb, one);
            film_truth(&f, &g->cm, &g->cs, c, 150.0, rgb);
            matrix_truth(&f, g, c > 0.0 ? c : 1e-9, 150.0, m);
            if (c > 0.0 && !(max_diff3(rgb, m) <= worst_matrix))
                worst_matrix = max_diff3(rgb, m);
        }
    }
    CHECK("film truth, total reflection in the film: a 5 um film reflects 1 past the critical angle",
          worst_thick <= 1e-9, "worst |R - 1| %.3g", worst_thick);
    CHECK("film truth, frustrated total reflection (150 nm) = characteristic matrix within 1e-6",
          worst_matrix <= 1e-6, "worst %.3g", worst_matrix);
    /* Otto: gold behind 30 nm of the film, just past the critical angle,
     * takes light that the thick film reflects: red below 1. */
    f.substrate = s[0];
    film_truth(&f, &g->cm, &g->cs, c_crit * 0.9, 30.0, rgb);
    CHECK("film truth, frustrated total reflection: light tunnels through 30 nm of film to gold",
          rgb[0] < 1.0 - 1e-3, "red %.6f", rgb[0]);

    /* The film's critical angle itself (xi_f = 0 exactly): a film index
     * whose square is sigma in binary64, so the 0/0 limit is taken; the
     * truth there is continuous with its neighbours. */
    /* A stack where xi_f is exactly 0: n1 = 2, dyadic cosines c (so that
     * sigma = 4 (1 - c)(1 + c) is exact) and nf the root of sigma, until
     * nf^2 rounds to sigma itself. */
    f.n1 = 2.0;
    sigma = 0.0;
    nf = 0.0;
    for (k = 0; k < 512; k++) {
        c = 0.5 + k / 1024.0;
        sigma = 4.0 * ((1.0 - c) * (1.0 + c));
        nf = sqrt(sigma);
        if (nf * nf == sigma)
            break;
    }
    f.film_n = nf;
    {
        ref_film_optics o;
        double near[3], lo = 0.0, d_max = 0.0;
        ref_film_optics_at(f.n1, ref_complex(nf, 0.0), ref_complex(s[0]->n[2000], s[0]->k[2000]), c, &o);
        for (k = 0; k < 3; k++) {
            double d = k == 0 ? 0.0 : (k == 1 ? 40.0 : 900.0);
            film_truth(&f, &g->cm, &g->cs, c, d, rgb);
            film_truth(&f, &g->cm, &g->cs, c + 1e-9, d, near);
            lo = max_diff3(rgb, near);
            if (!(lo <= d_max))
                d_max = lo;
        }
        CHECK("film truth at the film's critical angle (xi_f = 0 exactly): finite and continuous (1e-6)",
              sigma == nf * nf && o.xi_f == 0.0 && d_max <= 1e-6, "xi_f %g, jump %.3g", cabs(o.xi_f), d_max);
    }
}

static void test_grazing_and_extremes(const gen_context *g, spectrum *const *s)
{
    static const double thick[] = {0.0, 1e-9, 0.5, 1000.0, 5000.0};
    film_stack f;
    double rgb[3], ref[3], one[3] = {1.0, 1.0, 1.0}, worst_grazing = 0.0, worst_tiny = 0.0;
    double gt[3], worst_clamp = 0.0;
    int i, n;
    f.n1 = 1.0;
    f.film = NULL;
    f.film_n = 1.8;
    for (i = 0; i < N_SUB; i++) {
        f.substrate = s[i];
        for (n = 0; n < 5; n++) {
            film_truth(&f, &g->cm, &g->cs, 0.0, thick[n], rgb);
            if (!(max_diff3(rgb, one) <= worst_grazing))
                worst_grazing = max_diff3(rgb, one);
        }
        ground_truth(s[i], &g->cm, &g->cs, 1.0, 0.7, gt);
        film_truth(&f, &g->cm, &g->cs, 0.7, 1e-9, rgb);
        if (!(max_diff3(rgb, gt) <= worst_tiny))
            worst_tiny = max_diff3(rgb, gt);
        /* hostile thicknesses: the documented clamps */
        film_truth(&f, &g->cm, &g->cs, 0.7, 0.0, gt);
        film_truth(&f, &g->cm, &g->cs, 0.7, -5.0, rgb);
        worst_clamp = fmax(worst_clamp, max_diff3(rgb, gt));
        film_truth(&f, &g->cm, &g->cs, 0.7, NAN, rgb);
        worst_clamp = fmax(worst_clamp, max_diff3(rgb, gt));
        film_truth(&f, &g->cm, &g->cs, 0.7, FILM_TRUTH_D_MAX_NM, ref);
        film_truth(&f, &g->cm, &g->cs, 0.7, 1e300, rgb);
        worst_clamp = fmax(worst_clamp, max_diff3(rgb, ref));
        film_truth(&f, &g->cm, &g->cs, 0.7, INFINITY, rgb);
        worst_clamp = fmax(worst_clamp, max_diff3(rgb, ref));
        film_truth(&f, &g->cm, &g->cs, NAN, 300.0, rgb);
        film_truth(&f, &g->cm, &g->cs, 0.0, 300.0, ref);
        worst_clamp = fmax(worst_clamp, max_diff3(rgb, ref));
    }
    CHECK("film truth at grazing incidence (c = 0) is (1,1,1) at every thickness", worst_grazing <= 1e-12,
          "worst %.3g", worst_grazing);
    CHECK("film truth: a 1e-9 nm film is the bare substrate within 1e-9", worst_tiny <= 1e-9, "worst %.3g",
          worst_tiny);
    CHECK("film truth clamps: d < 0 and NaN as 0, d > FILM_TRUTH_D_MAX_NM and Inf as the maximum, c NaN as 0",
          worst_clamp == 0.0, "worst %.3g", worst_clamp);
}

/* The KHR_materials_iridescence peer (ref_film_khr_iridescence): finite and
 * never negative over films, bases, thicknesses and angles; for a thick
 * film (100 um: an optical path of at least 2 x 1.2 x 0.55 x 1e5 nm, where
 * the Gaussian sensitivities are below exp(-3000)) its orders m > 0 vanish and it is the incoherent sum of its two Schlick
 * interfaces, R12 + T^2 R23 / (1 - R12 R23); below the critical angle of a
 * film less dense than the outside, total reflection gives 1. */
static void test_khr_peer(void)
{
    static const double films[] = {1.2, 1.38, 1.8, 2.5}, cosines[] = {0.0, 0.05, 0.3, 0.7, 1.0};
    static const double bases[][3] = {{0.04, 0.04, 0.04}, {1.0, 0.71, 0.36}, {0.95, 0.64, 0.54}, {0.0, 0.5, 1.0}};
    int bad = 0, f, b, k, ch, d;
    double worst_incoherent = 0.0, rgb[3];
    for (f = 0; f < 4; f++)
        for (b = 0; b < 4; b++)
            for (k = 0; k < 5; k++) {
                double c = cosines[k], r0 = (films[f] - 1.0) / (films[f] + 1.0), m = 1.0 - c;
                double r12 = r0 * r0 + (1.0 - r0 * r0) * m * m * m * m * m;
                double cos2 = sqrt(1.0 - (1.0 - c * c) / (films[f] * films[f])), m2 = 1.0 - cos2;
                for (d = 0; d <= 1000; d += 7) {
                    ref_film_khr_iridescence(1.0, films[f], d, c, bases[b], rgb);
                    for (ch = 0; ch < 3; ch++)
                        bad += !(isfinite(rgb[ch]) && rgb[ch] >= 0.0);
                }
                ref_film_khr_iridescence(1.0, films[f], 1e5, c, bases[b], rgb);
                for (ch = 0; ch < 3; ch++) {
                    double f0 = bases[b][ch] > 0.9999 ? 0.9999 : bases[b][ch], s = sqrt(f0);
                    double n3 = (1.0 + s) / (1.0 - s), r1 = (n3 - films[f]) / (n3 + films[f]);
                    double r23 = r1 * r1 + (1.0 - r1 * r1) * m2 * m2 * m2 * m2 * m2, r123 = r12 * r23;
                    double want;
                    r123 = r123 < 1e-5 ? 1e-5 : (r123 > 0.9999 ? 0.9999 : r123);
                    want = r12 + (1.0 - r12) * (1.0 - r12) * r23 / (1.0 - r123);
                    worst_incoherent = fmax(worst_incoherent, fabs(rgb[ch] - want));
                }
            }
    CHECK("KHR_materials_iridescence peer: finite and >= 0 (4 films, 4 bases, 5 cosines, 0-1000 nm)", bad == 0,
          "%d channels not", bad);
    NOTE("KHR_materials_iridescence peer, 100 um film: max |peer - incoherent Schlick sum| %.3g", worst_incoherent);
    CHECK("KHR_materials_iridescence peer: a 100 um film is the incoherent sum of its interfaces within 1e-12",
          worst_incoherent <= 1e-12, "%.3g", worst_incoherent);
    /* the binary32 transcription make bench times (gen/bench/peers.h): the
     * same function, to binary32's rounding of phases up to 1000 nm x 2 x
     * 2.5 optical path (arguments of cos to about 70 rad) */
    {
        double worst32 = 0.0;
        for (f = 0; f < 4; f++)
            for (b = 0; b < 4; b++)
                for (k = 0; k < 5; k++)
                    for (d = 0; d <= 1000; d += 7) {
                        float f0f[3] = {(float)bases[b][0], (float)bases[b][1], (float)bases[b][2]}, r32[3];
                        double f0d[3] = {f0f[0], f0f[1], f0f[2]};
                        ref_film_khr_iridescence(1.0, (float)films[f], d, (float)cosines[k], f0d, rgb);
                        peer_khr_iridescence_rgb((float)films[f], (float)d, (float)cosines[k], f0f, r32);
                        for (ch = 0; ch < 3; ch++)
                            worst32 = fmax(worst32, fabs(r32[ch] - rgb[ch]));
                    }
        NOTE("KHR_materials_iridescence peer: max |binary32 - double| %.3g", worst32);
        CHECK("KHR_materials_iridescence peer: the binary32 transcription (make bench) within 1e-5 of the double one",
              worst32 <= 1e-5, "%.3g", worst32);
    }
    ref_film_khr_iridescence(1.5, 1.2, 300.0, 0.3, bases[1], rgb);
    CHECK("KHR_materials_iridescence peer: total reflection in a film less dense than the outside gives 1",
          rgb[0] == 1.0 && rgb[1] == 1.0 && rgb[2] == 1.0, "%g %g %g", rgb[0], rgb[1], rgb[2]);
}

/* The polarised peer (ref_film_belcour_polarised): finite and never
 * negative; with no film (d = 0) the base's exact reflectance
 * (ref_conductor); a film of the base's own index on a dielectric base is
 * invisible whatever its thickness (the film's surface alone,
 * ref_dielectric); for a 100 um film its orders m > 0 vanish and each
 * polarisation is the incoherent sum R12 + T^2 R23 / (1 - R12 R23) of the
 * exact reflectances (ref_conductor_sp, relative index eta/n_film at the
 * angle in the film), the two averaged; and the binary32 transcription
 * make bench times. */
static void test_belcour_peer(void)
{
    static const double films[] = {1.2, 1.38, 1.8, 2.5}, cosines[] = {0.0, 0.05, 0.3, 0.7, 1.0};
    static const double eta[][3] = {{0.18, 0.42, 1.37}, {0.27, 1.12, 1.22}, {1.5, 1.5, 1.5}, {2.9, 2.7, 2.5}};
    static const double kappa[][3] = {{3.4, 2.4, 1.8}, {3.6, 2.6, 2.5}, {0.0, 0.0, 0.0}, {3.1, 2.9, 2.7}};
    int bad = 0, f, b, k, ch, d;
    double worst_bare = 0.0, worst_same = 0.0, worst_incoherent = 0.0, worst32 = 0.0, rgb[3];
    for (f = 0; f < 4; f++)
        for (b = 0; b < 4; b++)
            for (k = 0; k < 5; k++) {
                double c = cosines[k], cos2 = sqrt(1.0 - (1.0 - c * c) / (films[f] * films[f]));
                double r12s, r12p;
                ref_conductor_sp(films[f], 0.0, c, &r12s, &r12p);
                for (d = 0; d <= 1000; d += 7) {
                    float etaf[3], kappaf[3], r32[3];
                    double etad[3], kappad[3];
                    ref_film_belcour_polarised(1.0, films[f], d, c, eta[b], kappa[b], rgb);
                    for (ch = 0; ch < 3; ch++) {
                        bad += !(isfinite(rgb[ch]) && rgb[ch] >= 0.0);
                        etaf[ch] = (float)eta[b][ch], kappaf[ch] = (float)kappa[b][ch];
                        etad[ch] = etaf[ch], kappad[ch] = kappaf[ch];
                    }
                    ref_film_belcour_polarised(1.0, (float)films[f], d, (float)c, etad, kappad, rgb);
                    peer_belcour_polarised_rgb((float)films[f], (float)d, (float)c, etaf, kappaf, r32);
                    for (ch = 0; ch < 3; ch++)
                        worst32 = fmax(worst32, fabs(r32[ch] - rgb[ch]));
                }
                ref_film_belcour_polarised(1.0, films[f], 0.0, c, eta[b], kappa[b], rgb);
                for (ch = 0; ch < 3; ch++)
                    worst_bare = fmax(worst_bare, fabs(rgb[ch] - ref_conductor(eta[b][ch], kappa[b][ch], c)));
                ref_film_belcour_polarised(1.0, films[f], 1e5, c, eta[b], kappa[b], rgb);
                for (ch = 0; ch < 3; ch++) {
                    double r23s, r23p, want = 0.0, r123;
                    ref_conductor_sp(eta[b][ch] / films[f], kappa[b][ch] / films[f], cos2, &r23s, &r23p);
                    r123 = fmin(r12s * r23s, 0.9999);
                    want += 0.5 * (r12s + (1.0 - r12s) * (1.0 - r12s) * r23s / (1.0 - r123));
                    r123 = fmin(r12p * r23p, 0.9999);
                    want += 0.5 * (r12p + (1.0 - r12p) * (1.0 - r12p) * r23p / (1.0 - r123));
                    worst_incoherent = fmax(worst_incoherent, fabs(rgb[ch] - want));
                }
                {
                    double same[3] = {films[f], films[f], films[f]}, zero[3] = {0.0, 0.0, 0.0};
                    for (d = 0; d <= 1000; d += 50) {
                        ref_film_belcour_polarised(1.0, films[f], d, c, same, zero, rgb);
                        for (ch = 0; ch < 3; ch++)
                            worst_same = fmax(worst_same, fabs(rgb[ch] - ref_dielectric(films[f], c)));
                    }
                }
            }
    CHECK("polarised film peer: finite and >= 0 (4 films, 4 bases, 5 cosines, 0-1000 nm)", bad == 0,
          "%d channels not", bad);
    NOTE("polarised film peer: d = 0 vs the base's exact reflectance %.3g; a film of the base's index %.3g; "
         "100 um vs the incoherent sums %.3g; binary32 vs double %.3g",
         worst_bare, worst_same, worst_incoherent, worst32);
    CHECK("polarised film peer: with no film, the base's exact reflectance within 1e-12", worst_bare <= 1e-12, "%.3g",
          worst_bare);
    CHECK("polarised film peer: a film of the base's own index is its surface alone within 1e-12",
          worst_same <= 1e-12, "%.3g", worst_same);
    CHECK("polarised film peer: a 100 um film is the incoherent sum of its exact interfaces within 1e-12",
          worst_incoherent <= 1e-12, "%.3g", worst_incoherent);
    CHECK("polarised film peer: the binary32 transcription (make bench) within 1e-5 of the double one",
          worst32 <= 1e-5, "%.3g", worst32);
    ref_film_belcour_polarised(1.5, 1.2, 300.0, 0.3, eta[0], kappa[0], rgb);
    CHECK("polarised film peer: total reflection in a film less dense than the outside gives 1",
          rgb[0] == 1.0 && rgb[1] == 1.0 && rgb[2] == 1.0, "%g %g %g", rgb[0], rgb[1], rgb[2]);
}

/* The renderers' own films (params --for TARGET --film): Blender's
 * (ref_film_blender) and MaterialX's, which OpenPBR's reference graph uses
 * (ref_film_materialx). Each finite and in [0, 1]; at no thickness the
 * renderer's bare metal (ref_blender_f82_tint below Cycles' 0.1 nm cutoff,
 * ref_materialx_schlick at d = 0); a film of the outside's index over
 * Blender's metal the bare metal (its index read from F0 gives back F0, and
 * the F82 curve seen from index 1 is the metal's own); over MaterialX's,
 * half the bare curve read as XYZ and taken to CIE RGB, as its R23 = f / 2
 * makes it. Blender's sensitivities (film_cmfs) against the Fourier sum
 * taken directly over the CIE table at 1 nm. */
static void test_renderer_films(const gen_context *g)
{
    static const double films[] = {1.0, 1.2, 1.38, 1.8, 2.5}, cosines[] = {0.0, 0.05, 0.3, 0.7, 1.0};
    static const double bases[][3] = {{0.04, 0.04, 0.04}, {1.0, 0.71, 0.36}, {0.95, 0.64, 0.54}, {0.0, 0.5, 1.0}};
    static const double tints[][3] = {{1.0, 1.0, 1.0}, {0.9, 1.0, 0.8}, {0.0, 0.5, 1.0}, {1.0, 0.3, 0.6}};
    static const double to_rgb[3][3] = {{2.3706743, -0.9000405, -0.4706338},
                                        {-0.5138850, 1.4253036, 0.0885814},
                                        {0.0052982, -0.0146949, 1.0093968}};
    film_cmfs *k = malloc(sizeof *k);
    int bad = 0, f, b, i, ch, d;
    double worst_bare = 0.0, worst_index1 = 0.0, worst_mx_bare = 0.0, worst_mx_index1 = 0.0, worst_s = 0.0;
    double rgb[3], one[3] = {1.0, 1.0, 1.0};
    if (!k) {
        CHECK("renderer films: memory", 0, "malloc failed");
        return;
    }
    target_film_cmfs(g, k);
    for (f = 0; f < 5; f++)
        for (b = 0; b < 4; b++)
            for (i = 0; i < 5; i++) {
                double c = cosines[i], bare[3], mx_bare[3];
                for (ch = 0; ch < 3; ch++) {
                    bare[ch] = ref_blender_f82_tint(bases[b][ch], tints[b][ch], c);
                    mx_bare[ch] = ref_materialx_schlick(bases[b][ch], tints[b][ch], 1.0, 5.0, c);
                }
                for (d = 0; d <= 1000; d += 13) {
                    ref_film_blender(films[f], d, c, bases[b], tints[b], k, rgb);
                    for (ch = 0; ch < 3; ch++)
                        bad += !(rgb[ch] >= 0.0 && rgb[ch] <= 1.0);
                    ref_film_materialx(films[f], d, c, bases[b], tints[b], one, 5.0, 2, rgb);
                    for (ch = 0; ch < 3; ch++)
                        bad += !(rgb[ch] >= 0.0 && rgb[ch] <= 1.0);
                }
                ref_film_blender(films[f], 0.1, c, bases[b], tints[b], k, rgb);
                for (ch = 0; ch < 3; ch++)
                    worst_bare = fmax(worst_bare, fabs(rgb[ch] - bare[ch]));
                ref_film_materialx(films[f], 0.0, c, bases[b], tints[b], one, 5.0, 2, rgb);
                for (ch = 0; ch < 3; ch++)
                    worst_mx_bare = fmax(worst_mx_bare, fabs(rgb[ch] - mx_bare[ch]));
                if (films[f] == 1.0 && c > 0.0) {
                    double want[3];
                    for (d = 50; d <= 1000; d += 50) {
                        if (bases[b][0] < 0.999 && bases[b][1] < 0.999 && bases[b][2] < 0.999) {
                            ref_film_blender(1.0, d, c, bases[b], tints[b], k, rgb);
                            for (ch = 0; ch < 3; ch++)
                                worst_index1 = fmax(worst_index1, fabs(rgb[ch] - bare[ch]));
                        }
                        ref_film_materialx(1.0, d, c, bases[b], tints[b], one, 5.0, 2, rgb);
                        for (ch = 0; ch < 3; ch++) {
                            want[ch] = 0.5 * (to_rgb[ch][0] * mx_bare[0] + to_rgb[ch][1] * mx_bare[1] +
                                              to_rgb[ch][2] * mx_bare[2]);
                            want[ch] = want[ch] < 0.0 ? 0.0 : (want[ch] > 1.0 ? 1.0 : want[ch]);
                            worst_mx_index1 = fmax(worst_mx_index1, fabs(rgb[ch] - want[ch]));
                        }
                    }
                }
            }
    /* S_ch(X) = sum_j w_j exp(2 pi i X nu_j) against the same transform
     * summed over wavelength: sum_lambda rgb_ch(lambda) exp(2 pi i X /
     * lambda) / sum_lambda rgb_ch(lambda), the CIE table at 1 nm */
    for (d = 0; d <= 15000; d += 1500)
        for (ch = 0; ch < 3; ch++) {
            double complex fs = 0.0, direct = 0.0;
            double area = 0.0;
            int j;
            for (j = 0; j < FILM_CMF_SAMPLES; j++)
                fs += k->w[j][ch] * cexp(2.0 * 3.141592653589793 * I * d * (k->nu0 + j * k->dnu));
            for (j = 0; j < CMF_N; j++) {
                double lambda = SPEC_LO_NM + j, w = g->cs.xyz_to_rgb[ch][0] * g->cm.xbar[j] +
                                                    g->cs.xyz_to_rgb[ch][1] * g->cm.ybar[j] +
                                                    g->cs.xyz_to_rgb[ch][2] * g->cm.zbar[j];
                direct += w * cexp(2.0 * 3.141592653589793 * I * d / lambda);
                area += w;
            }
            worst_s = fmax(worst_s, cabs(fs - direct / area));
        }
    free(k);
    CHECK("renderer films (Blender's, MaterialX's): in [0, 1] (5 films, 4 metals, 5 cosines, 0-1000 nm)", bad == 0,
          "%d channels not", bad);
    NOTE("renderer films: Blender's at 0.1 nm vs its bare metal %.3g, under a film of index 1 %.3g; MaterialX's at "
         "d = 0 %.3g, index 1 vs half the bare curve in CIE RGB %.3g; Blender's sensitivities vs the 1 nm sum %.3g",
         worst_bare, worst_index1, worst_mx_bare, worst_mx_index1, worst_s);
    CHECK("Blender's film: at Cycles' 0.1 nm cutoff, the bare F82-tint metal exactly", worst_bare == 0.0, "%.3g",
          worst_bare);
    CHECK("Blender's film: a film of the outside's index is the bare metal within 1e-12", worst_index1 <= 1e-12,
          "%.3g", worst_index1);
    CHECK("MaterialX's film: with no film, the bare generalized Schlick curve exactly", worst_mx_bare == 0.0, "%.3g",
          worst_mx_bare);
    /* R12 rounds to about 1e-16 there, and its square root enters the
     * series' orders m > 0 */
    CHECK("MaterialX's film: a film of the outside's index is half the bare curve taken from XYZ to CIE RGB, "
          "within 1e-7", worst_mx_index1 <= 1e-7, "%.3g", worst_mx_index1);
    CHECK("Blender's sensitivities: the frequency-sampled sum within 2e-3 of the 1 nm wavelength sum (0-15 um)",
          worst_s <= 2e-3, "%.3g", worst_s);
}

int main(void)
{
    gen_context *g = malloc(sizeof *g);
    spectrum *s[N_SUB], *dispersive = malloc(sizeof *dispersive);
    int i, ok = g && dispersive;
    for (i = 0; i < N_SUB; i++) {
        s[i] = malloc(sizeof *s[i]);
        ok = ok && s[i];
    }
    if (!ok || gen_context_load(data_dir(NULL), "srgb", g) || spectrum_load(data_dir(NULL), "sf11", dispersive)) {
        CHECK("film truth: data loads", 0, "colorimetry or materials missing");
        return harness_exit();
    }
    for (i = 0; i < N_SUB; i++)
        if (spectrum_load(data_dir(NULL), substrates[i], s[i])) {
            CHECK("film truth: substrates load", 0, "%s", substrates[i]);
            return harness_exit();
        }
    test_identities(g, s);
    test_independent(g, s, dispersive);
    test_total_reflection(g, s);
    test_grazing_and_extremes(g, s);
    test_khr_peer();
    test_belcour_peer();
    test_renderer_films(g);
    for (i = 0; i < N_SUB; i++)
        free(s[i]);
    free(dispersive);
    free(g);
    return harness_exit();
}
