/* fresnel_film.h -- thin-film iridescence (soap, oil, anodised titanium,
 * heat-tinted steel, lens coatings): the API and its manual.
 *
 * WHAT IT IS
 *   The RGB reflectance of a transparent film of thickness d on a substrate
 *   (a metal or a dielectric), seen from an incident medium, with d a
 *   run-time input (animate it, texture it), in binary32, Q1.15 and
 *   binary16. Each material (incident medium n1, film index n_f, substrate
 *   n, k spectrum, colour space) is one const table made on the host
 *   (gen/2_derive/film_fit.c, gen/3_encode/film_encode.c); this header
 *   evaluates it. Allocation-free, reentrant; the Q1.15 function uses no
 *   float, no division instruction, no int64 and no libm.
 *
 * USE
 *     #include "fresnel_film.h"
 *     static const fresnel_film oil_on_steel = {...};      // made on the host
 *     fresnel_rgb r = fresnel_film_rgb(&oil_on_steel, n_dot_v, thickness_nm);
 *     fresnel_rgb_q15 q = fresnel_film_q15_rgb(&table_q15, c_q15, d_q16);
 *   The tables come from `fresnel gen` (a scene with `models = thin-film`
 *   and `film = N`, or `film ID = N` per material: gen/scene/scene.h), one
 *   per material and number type, named fresnel_<scene>_<material>_thin_film
 *   (_q15, _f16); `fresnel curve --material ID --film N:D` prints the film's
 *   truth and this model over angle, `fresnel report` measures it.
 *
 * THE TRUTH (gen/1_spectral/film_truth.c)
 *   At every whole nanometre of the 0.1 nm spectral grid, Airy's sum of
 *   the film's two interfaces, complex amplitudes with phases, s and p
 *   averaged [Born & Wolf 1.6; Heavens 1955]:
 *     r = (r12 + r23 e^(2i beta)) / (1 + r12 r23 e^(2i beta)),
 *     beta = 2 pi d n_f cos(theta_f) / lambda,
 *   integrated to RGB by the colorimetry of every ground truth of the
 *   project (CIE 1931, D65, the colour space's matrix). d = 0 and n_f = n1
 *   give the bare substrate's ground truth to 1e-12; an independent
 *   characteristic-matrix film agrees to 4e-15 per channel
 *   (tests/runtime/thin_film/test_film_truth.c).
 *
 * THE MODEL (gen/common/reference_film.h has the derivation)
 *   Per wavelength R = a0 + 2 Re sum_{m>=1} kappa q^(m-1) z^m,
 *   z = exp(2 pi i X / lambda), X = 2 d n_f cos(theta_f): a Fourier series
 *   in the optical path X whose every order is needed near grazing
 *   incidence (|q| -> 1). The colour-space sensitivities, as functions of
 *   X, are fitted by FRESNEL_FILM_POLES damped exponentials
 *   sum_j c_j exp(2 pi i X p_j) (complex wavenumbers p_j; max error 0.0105
 *   of S(0)), and the spectral integral of the series then closes on the
 *   poles in closed form, every order summed:
 *     R_ch = a0_ch(c) + sum_j Re(w_ch,j F_j),
 *     F_j  = zeta_j (A_j + B_j zeta_j) / (1 - P_j zeta_j + Q_j zeta_j^2),
 *     zeta_j = exp(2 pi i d (opd(c) + i decay(c)) (nu_j + i gamma_j)),
 *   (w = 2 c in the tables). a0 is the incoherent reflectance integrated
 *   exactly; A, B, P, Q (the s and p terms of a pole over one denominator)
 *   are the series' coefficients continued to p_j and refitted to the truth
 *   at FRESNEL_FILM_NODES cosines c_k = (k/31)^2; a0, opd, decay, A, B, P,
 *   Q are interpolated linearly in sqrt(c) (dense nodes at grazing
 *   incidence, where the fringes stay deep to the last degree).
 *   Dispersion of the substrate is in the table (gold, copper); the film's
 *   own index is constant in this model (a dispersive film: the truth only).
 *
 * DOMAIN AND RESULTS
 *   c: cosine in the incident medium, clamped to [0, 1] (NaN and -Inf 0,
 *   +Inf 1; Q15: any int32, as fresnel_q15.h). d: thickness in nm,
 *   clamped to [0, FRESNEL_FILM_D_MAX] (NaN and negative 0, +Inf the
 *   maximum; Q15: Q16.16 nm, any int32), the range the spectral truth
 *   resolves (at 5000 nm the fringes are 5.8 samples of the 1 nm sum apart
 *   at 380 nm, n_f 2.5). Results in [0, 1] per channel, never NaN (colours out of
 *   the display's gamut clip, as under the clip policy).
 *   THE DOMAIN: the stacks the model represents, each condition checked
 *   by `fresnel gen`, `fresnel curve --film` and `fresnel report`, which
 *   refuse a stack outside it with the condition, the index and the
 *   wavelength (gen/2_derive/film_fit.h, film_stack_domain):
 *     1. a film at least as dense as its ambient, n1 <= n_f <= 4. A less
 *        dense one reflects totally inside past its critical angle, where
 *        the linear interpolation in c crosses the square-root edge of
 *        cos(theta_f): CIEDE2000 up to 80 within about 10 degrees of it,
 *        mean 0.36, max 11 further away (gold under 1.2 in glass,
 *        tests/runtime/thin_film/test_film.c), and the Q1.15 layout cannot hold its table
 *        (its A, B leave [-1, 1]);
 *     2. a substrate whose cosine of refraction stays clear of zero: at
 *        every wavelength of 360-830 nm, 1 - N^2 / n1^2 (N = n + i k, the
 *        branch point of cos(theta_3) in c^2) at least 0.2 from the real
 *        segment [0, 1]. On the segment, a substrate less dense than the
 *        ambient (glass / film / air, an index of 0.5 in air) reflects
 *        totally past its critical angle and the table cannot follow
 *        (CIEDE2000 15 and more); near it, a substrate of about the
 *        ambient's index (BK7 under an ambient of 1.5: 0.014, under 1.4:
 *        0.16; water under water) turns at a square-root edge between
 *        nodes and the table's constants grow. The errors rise steeply
 *        toward the edge, so it stands where they stay near those of
 *        films in air: Q1.15 40 LSB at the edge of water and of BK7, 64
 *        with FILM_DOMAIN_BRANCH at 0.1 (FILM_SEARCH_STACK="edge water"
 *        build/tests/test_film_search; silicon's edge). In air every
 *        material of data/ is inside (ice the nearest, 0.70 at 830 nm;
 *        silver 2.75 at 368 nm, the nearest metal), and so is a glass
 *        under water (BK7 under 1.33: 0.29).
 *
 * ERROR
 *   Against the double evaluation of the same table (gen/common/
 *   reference_film.c): the largest error a search for the worst case
 *   found over the domain, rounded up with a margin of at least 10%
 *   (tests/runtime/thin_film/test_film_search.c: every Q1.15 and binary16 cosine at sixteen
 *   thicknesses, random (c, d) and local maximisation from the worst, on
 *   films from the ambient's index to 4 over twelve substrates in air,
 *   1.33, 1.4, 1.5 and at the domain's edge; `make search`, and `make
 *   test` on the worst stacks it keeps): FRESNEL_BOUND_FILM, _Q15 (LSB),
 *   _F16 (the searched maxima and where: tests/README.md, "Thin film").
 *   Against the spectral truth (Airy's sum at every nanometre, held to
 *   [0, 1] per channel), CIEDE2000 over the films of the report's scene
 *   (data/scenes/report.scene: 20 materials, films 1.2-2.5), theta 0-90 deg
 *   every degree, d 0-1000 nm every 5 nm; `make report`, data/report/report.md
 *   "Thin film", row all (tests/repo/test_doc_numbers.sh holds these to it):
 *                 mean    max
 *     binary32    0.053   1.074
 *     Q1.15       0.055   1.090
 *     binary16    0.093   1.408
 *   FILM_FULL=1 build/tests/test_film prints the same measure on a denser
 *   grid (films 1.2-2.5 every 0.1 on six substrates, 1.52 million samples).
 *   (the double model: as binary32). Thick films (1000-5000 nm, gold
 *   under 2.5, BK7 under 1.8) stay below 0.25. A film of no thickness,
 *   and one of the ambient's index at any thickness, give the bare
 *   substrate's truth within 0.1 (measured 0.056, tests/runtime/thin_film/test_film.c).
 *
 * COST per RGB evaluation
 *   binary32: 53 interpolated table values, 6 complex exponentials (short
 *   polynomials, no libm call), 6 complex divisions, 36 multiply-adds for
 *   the channels; the poles' loop runs 8 lanes, padded, without a branch,
 *   and compilers vectorise it (src/f32/film.c). Measured: 66.0 ns (gcc
 *   -O2, x86-64; data/report/report.md, "Thin film", the f32 row; every
 *   compiler and flag set: `make bench`, row film-f32).
 *   Q1.15: each pole interpolates 8 values and forms a complex exponential
 *   from tables and a complex division normalised by shifts (a 257-entry
 *   reciprocal table, no division instruction, no soft-float helper); the
 *   channels' sums take 72 multiplications (16-bit weights by 30-bit terms
 *   split in two halves: no 64-bit product). Measured: 3396 instructions
 *   on a Cortex-M0 (`make cross-count`, row thin-film, mean; every target:
 *   data/report/report.md, "Cortex-M0, Cortex-M4F, RV32IMC and AArch64").
 *   Bit-identical on the Cortex-M0, M4F and RV32IMC and the host (make
 *   cross-test).
 *   binary16: the binary32 operations, in half.
 *   Table per material: sizeof(fresnel_film) 6976 bytes, fresnel_film_q15
 *   3560, fresnel_film_f16 3488 (`fresnel report`, "Thin film").
 *   Accuracy and cost by pole count: tests/README.md, "Thin film: poles".
 */
#ifndef FRESNEL_FILM_H
#define FRESNEL_FILM_H

#include <stdint.h>

#include "fresnel.h"
#include "fresnel_q15.h"
#include "fresnel_f16.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FRESNEL_FILM_POLES 6  /* damped exponentials standing for the observer */
#define FRESNEL_FILM_NODES 32  /* table cosines c_k = (k / 31)^2 */
#define FRESNEL_FILM_D_MAX 5000.0f /* nm; thicker is clamped */
#define FRESNEL_FILM_D_MAX_Q16 (5000 * 65536)
#define FRESNEL_BOUND_FILM 1.5e-6f  /* binary32 */
#define FRESNEL_BOUND_FILM_Q15 50.0 /* Q1.15, LSB */
#define FRESNEL_BOUND_FILM_F16 0.011 /* binary16 */

/* One table cosine: a0 (RGB), opd and decay (the optical path per nm of
 * thickness, 2 n_f cos(theta_f) as a complex number: decay > 0 only in
 * total reflection inside the film) and each pole's A, B, P, Q. */
typedef struct fresnel_film_node {
    float a0[3];
    float opd, decay;
    /* per pole: A, B, P, Q, real and imaginary parts */
    float a_re[FRESNEL_FILM_POLES], a_im[FRESNEL_FILM_POLES], b_re[FRESNEL_FILM_POLES], b_im[FRESNEL_FILM_POLES];
    float p_re[FRESNEL_FILM_POLES], p_im[FRESNEL_FILM_POLES], q_re[FRESNEL_FILM_POLES], q_im[FRESNEL_FILM_POLES];
} fresnel_film_node;

/* A material: the poles nu_j (freq) + i gamma_j (damp), cycles per nm of
 * optical path; the channels' weights w = 2 c (real, imaginary); the
 * nodes. */
typedef struct fresnel_film {
    float freq[FRESNEL_FILM_POLES];
    float damp[FRESNEL_FILM_POLES];
    float weight[3][FRESNEL_FILM_POLES][2];
    fresnel_film_node node[FRESNEL_FILM_NODES];
} fresnel_film;

#if FRESNEL_HAS_FLOAT
/* The model above in binary32. Error <= FRESNEL_BOUND_FILM. */
fresnel_rgb fresnel_film_rgb(const fresnel_film *m, float c, float d_nm);
#endif

/* The same table in fixed point: a0 Q14, opd and decay Q12 (< 16), A, B,
 * Q Q15 (|A| + |B| < 1, |Q| < 1), P Q14 (|P| < 2); turn_* = 2^32 nu,
 * gamma; octave_* = 2^32 2 pi log2(e) nu, gamma (< 2^27); weights Q12.
 * film_encode_q15 refuses a model outside these ranges. */
typedef struct fresnel_film_node_q15 {
    int16_t a0[3];
    uint16_t opd, decay;
    int16_t a_re[FRESNEL_FILM_POLES], a_im[FRESNEL_FILM_POLES], b_re[FRESNEL_FILM_POLES], b_im[FRESNEL_FILM_POLES];
    int16_t p_re[FRESNEL_FILM_POLES], p_im[FRESNEL_FILM_POLES], q_re[FRESNEL_FILM_POLES], q_im[FRESNEL_FILM_POLES];
} fresnel_film_node_q15;
typedef struct fresnel_film_q15 {
    uint32_t turn_nu[FRESNEL_FILM_POLES], turn_gamma[FRESNEL_FILM_POLES];
    uint32_t octave_nu[FRESNEL_FILM_POLES], octave_gamma[FRESNEL_FILM_POLES];
    int16_t weight[3][FRESNEL_FILM_POLES][2];
    fresnel_film_node_q15 node[FRESNEL_FILM_NODES];
} fresnel_film_q15;
#if FRESNEL_HAS_Q15
/* c Q15, d Q16.16 nm. Error <= FRESNEL_BOUND_FILM_Q15 LSB. */
fresnel_rgb_q15 fresnel_film_q15_rgb(const fresnel_film_q15 *m, int32_t c, fresnel_q16 d_nm);
#endif

#if FRESNEL_HAS_F16
typedef struct fresnel_rgb_f16 {
    fresnel_f16 r, g, b;
} fresnel_rgb_f16;
typedef struct fresnel_film_node_f16 {
    fresnel_f16 a0[3];
    fresnel_f16 opd, decay;
    fresnel_f16 a_re[FRESNEL_FILM_POLES], a_im[FRESNEL_FILM_POLES], b_re[FRESNEL_FILM_POLES], b_im[FRESNEL_FILM_POLES];
    fresnel_f16 p_re[FRESNEL_FILM_POLES], p_im[FRESNEL_FILM_POLES], q_re[FRESNEL_FILM_POLES], q_im[FRESNEL_FILM_POLES];
} fresnel_film_node_f16;
typedef struct fresnel_film_f16 {
    fresnel_f16 freq[FRESNEL_FILM_POLES], damp[FRESNEL_FILM_POLES];
    fresnel_f16 weight[3][FRESNEL_FILM_POLES][2];
    fresnel_film_node_f16 node[FRESNEL_FILM_NODES];
} fresnel_film_f16;
/* The binary32 table rounded to half, evaluated with every operation in
 * half (fresnel_f16.h ARITHMETIC). Error <= FRESNEL_BOUND_FILM_F16. */
fresnel_rgb_f16 fresnel_film_f16_rgb(const fresnel_film_f16 *m, fresnel_f16 c, fresnel_f16 d_nm);
#endif

#ifdef __cplusplus
}
#endif
#endif
