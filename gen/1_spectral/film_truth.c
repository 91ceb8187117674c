/* Spectral truth of a thin film on a substrate: the Airy reflectance of
 * common/reference_film.h at every whole nanometre of the 0.1 nm grid,
 * integrated to RGB by ground_truth_of (the colorimetry of every other
 * ground truth in the project).
 *
 * Resolution: the film's spectrum oscillates with period
 * lambda^2 / (2 nf d cos(theta_f)) in wavelength; at 380 nm, nf = 2.5,
 * d = 1000 nm that is 29 nm, 29 samples of the 1 nm sum per period. At
 * FILM_TRUTH_D_MAX_NM (5000 nm) it is 5.8 samples there, the least the sum
 * resolves; thicker films are taken as that thickness. */
#include <math.h>
#include <stdlib.h>

#include "common/reference.h"
#include "common/reference_film.h"
#include "1_spectral/spectral.h"

struct film_optics_table {
    ref_film_optics o[CMF_N];
};

/* Every tenth 0.1 nm node is a whole nanometre: CMF sample j. */
void film_stack_index(const film_stack *f, int j, double n_film[2], double n_sub[2])
{
    int node = j * 10;
    n_film[0] = f->film ? f->film->n[node] : f->film_n;
    n_film[1] = f->film ? f->film->k[node] : 0.0;
    n_sub[0] = f->substrate->n[node];
    n_sub[1] = f->substrate->k[node];
}

film_optics_table *film_truth_prepare(const film_stack *f, double c)
{
    film_optics_table *t = malloc(sizeof *t);
    int j;
    if (!t)
        return NULL;
    c = ref_clamp(c, 0.0, 1.0);
    for (j = 0; j < CMF_N; j++) {
        double nf[2], ns[2];
        film_stack_index(f, j, nf, ns);
        ref_film_optics_at(f->n1, ref_complex(nf[0], nf[1]), ref_complex(ns[0], ns[1]), c, &t->o[j]);
    }
    return t;
}

typedef struct film_at {
    const film_optics_table *t;
    double d;
} film_at;

static double film_reflectance(const void *ctx, int node, double nm)
{
    const film_at *a = ctx;
    return ref_film_airy(&a->t->o[node / 10], a->d, nm);
}

void film_truth_at(const film_optics_table *t, const colorimetry *cm, const colour_space *cs, double d_nm,
                   double rgb[3])
{
    film_at a;
    a.t = t;
    a.d = ref_clamp(d_nm, 0.0, FILM_TRUTH_D_MAX_NM);
    ground_truth_of(film_reflectance, &a, cm, cs, rgb);
}

void film_truth(const film_stack *f, const colorimetry *cm, const colour_space *cs, double c,
                double d_nm, double rgb[3])
{
    film_optics_table *t = film_truth_prepare(f, c);
    if (!t) {
        rgb[0] = rgb[1] = rgb[2] = NAN;
        return;
    }
    film_truth_at(t, cm, cs, d_nm, rgb);
    free(t);
}
