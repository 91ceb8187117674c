/* Spectral truth of a thin film on a substrate: the Airy reflectance of
 * model/reference_film.h at every whole nanometre of the 0.1 nm grid,
 * integrated to RGB by ground_truth_of (the colorimetry of every other
 * ground truth in the project).
 *
 * Resolution: the film's spectrum oscillates with period
 * lambda^2 / (2 nf d cos(theta_f)) in wavelength; at 380 nm, nf = 2.5,
 * d = 1000 nm that is 29 nm, 29 samples of the 1 nm sum per period. At
 * FILM_TRUTH_D_MAX_NM (5000 nm) it is 5.8 samples there, the least the sum
 * resolves; thicker films are taken as that thickness. */
#include <math.h>

#include "model/reference.h"
#include "model/reference_film.h"
#include "1_spectral/spectral.h"

typedef struct film_at {
    const film_stack *f;
    double c, d;
} film_at;

static double film_reflectance(const void *ctx, int node, double nm)
{
    const film_at *a = ctx;
    const film_stack *f = a->f;
    ref_film_optics o;
    double complex nf = f->film ? ref_complex(f->film->n[node], f->film->k[node])
                                : ref_complex(f->film_n, 0.0);
    ref_film_optics_at(f->n1, nf, ref_complex(f->substrate->n[node], f->substrate->k[node]), a->c, &o);
    return ref_film_airy(&o, a->d, nm);
}

void film_truth(const film_stack *f, const colorimetry *cm, const colour_space *cs, double c,
                double d_nm, double rgb[3])
{
    film_at a;
    a.f = f;
    a.c = ref_clamp(c, 0.0, 1.0);
    a.d = ref_clamp(d_nm, 0.0, FILM_TRUTH_D_MAX_NM);
    ground_truth_of(film_reflectance, &a, cm, cs, rgb);
}
