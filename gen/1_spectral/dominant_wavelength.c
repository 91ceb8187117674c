/* Spectral step 5 of 7: the wavelength that stands for each primary [MS18 section 5]: the
 * ray from the space's white point through the primary's chromaticity, met
 * with the spectral locus of the CIE 1931 observer.
 *
 * MS18 pick the 1 nm locus sample closest to the line; here the ray is
 * intersected with the polyline through the 1 nm samples and the crossing is
 * interpolated inside its segment, which gives sub-nanometre wavelengths and
 * cannot pick a sample on the opposite side of the white point (the line
 * through white and primary also crosses the locus behind the white). */
#include <math.h>

#include "1_spectral/spectral.h"

static void locus_xy(const colorimetry *cm, int j, double xy[2])
{
    double sum = cm->xbar[j] + cm->ybar[j] + cm->zbar[j];
    xy[0] = cm->xbar[j] / sum;
    xy[1] = cm->ybar[j] / sum;
}

static double cross(const double a[2], const double b[2]) { return a[0] * b[1] - a[1] * b[0]; }

/* Wavelength where white + t*dir (t > 0) first meets the locus, or NaN when
 * it passes through the gap closed by the purple line. */
static double ray_meets_locus(const colorimetry *cm, const double white[2], const double dir[2])
{
    double best_t = HUGE_VAL, best_nm = NAN, a[2], b[2];
    int j;
    locus_xy(cm, 0, a);
    for (j = 0; j + 1 < CMF_N; j++, a[0] = b[0], a[1] = b[1]) {
        double edge[2], to_a[2], denom, t, u;
        locus_xy(cm, j + 1, b);
        edge[0] = b[0] - a[0];
        edge[1] = b[1] - a[1];
        denom = cross(dir, edge);
        if (denom == 0.0)
            continue; /* parallel: a crossing would be at a neighbouring vertex too */
        to_a[0] = a[0] - white[0];
        to_a[1] = a[1] - white[1];
        t = cross(to_a, edge) / denom;
        u = cross(to_a, dir) / denom;
        /* Past ~700 nm the CMF ratios are constant to rounding and the locus
         * jitters in place, so a ray can cross it more than once there; the
         * crossing nearest the white point is the one the eye would name. */
        if (t > 0.0 && u >= 0.0 && u <= 1.0 && t < best_t) {
            best_t = t;
            best_nm = SPEC_LO_NM + j + u;
        }
    }
    return best_nm;
}

void dominant_wavelengths(const colorimetry *cm, const colour_space *cs, double nm[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++) {
        double dir[2];
        dir[0] = cs->primary[ch][0] - cs->white[0];
        dir[1] = cs->primary[ch][1] - cs->white[1];
        nm[ch] = ray_meets_locus(cm, cs->white, dir);
    }
}
