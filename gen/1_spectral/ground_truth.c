/* Spectral step 7 of 7: the RGB reflectance every fitted constant is judged against
 * [Hof20 "Computing RGB parameter values": spectral Fresnel x illuminant x
 * CMFs -> XYZ -> adapted RGB]. Exact Fresnel at each 1 nm CMF sample, lit by
 * D65, normalised by the illuminant's Y so a perfect reflector has Y = 1;
 * colour_space's per-channel scale then makes it (1,1,1) to the last place.
 *
 * The integration is ground_truth_of; ground_truth gives it the bare
 * interface's reflectance, film_truth.c a thin film's. */
#include "common/reference.h"
#include "1_spectral/spectral.h"

/* Every tenth 0.1 nm node is a whole nanometre, where the CMFs are tabulated. */
#define NODES_PER_NM 10

void ground_truth_of(spectral_reflectance *reflectance, const void *ctx, const colorimetry *cm,
                     const colour_space *cs, double rgb[3])
{
    double xyz[3], x = 0.0, y = 0.0, z = 0.0, norm = 0.0;
    int j, ch;
    for (j = 0; j < CMF_N; j++) {
        double r = reflectance(ctx, j * NODES_PER_NM, SPEC_LO_NM + j);
        /* (r * d65) * cmf: with r = 1 these are the very products
         * illuminant_white sums, so the perfect reflector is bit-exact. */
        x += r * cm->d65[j] * cm->xbar[j];
        y += r * cm->d65[j] * cm->ybar[j];
        z += r * cm->d65[j] * cm->zbar[j];
        norm += cm->d65[j] * cm->ybar[j];
    }
    xyz[0] = x / norm;
    xyz[1] = y / norm;
    xyz[2] = z / norm;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = cs->xyz_to_rgb[ch][0] * xyz[0] + cs->xyz_to_rgb[ch][1] * xyz[1] +
                  cs->xyz_to_rgb[ch][2] * xyz[2];
}

typedef struct interface_at {
    const spectrum *s;
    double n1, c;
} interface_at;

static double interface_reflectance(const void *ctx, int node, double nm)
{
    const interface_at *a = ctx;
    (void)nm;
    return ref_conductor(a->s->n[node] / a->n1, a->s->k[node] / a->n1, a->c);
}

void ground_truth(const spectrum *s, const colorimetry *cm, const colour_space *cs, double n1,
                  double c, double rgb[3])
{
    interface_at a;
    a.s = s;
    a.n1 = n1;
    a.c = c;
    ground_truth_of(interface_reflectance, &a, cm, cs, rgb);
}
