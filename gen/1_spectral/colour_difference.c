/* Linear RGB -> XYZ -> CIELAB -> CIEDE2000; see colour_difference.h. */
#include <math.h>
#include <string.h>

#include "1_spectral/colour_difference.h"

static const double pi = 3.14159265358979323846;

static double deg(double rad) { return rad * (180.0 / pi); }
static double rad(double deg) { return deg * (pi / 180.0); }

/* Inverse by cofactors. The threshold only rejects matrices with no inverse
 * worth the name; the colour-space matrices are far from it. */
static int invert3(const double a[3][3], double out[3][3])
{
    double c[3][3], det, scale = 0.0;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1];
            if (fabs(a[i][j]) > scale)
                scale = fabs(a[i][j]);
        }
    det = a[0][0] * c[0][0] + a[0][1] * c[0][1] + a[0][2] * c[0][2];
    if (!(fabs(det) > 1e-12 * scale * scale * scale))
        return -1;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            out[i][j] = c[j][i] / det;
    return 0;
}

int lab_space_init(lab_space *ls, const colour_space *cs)
{
    static const double one[3] = {1.0, 1.0, 1.0};
    if (invert3(cs->xyz_to_rgb, ls->rgb_to_xyz))
        return -1;
    /* The white goes through the same arithmetic as every colour, so RGB
     * (1,1,1) gives X/Xn = Y/Yn = Z/Zn = 1 exactly and L* is exactly 100. */
    lab_space_xyz(ls, one, ls->white);
    return 0;
}

void lab_space_xyz(const lab_space *ls, const double rgb[3], double xyz[3])
{
    double t[3];
    int i;
    for (i = 0; i < 3; i++)
        t[i] = ls->rgb_to_xyz[i][0] * rgb[0] + ls->rgb_to_xyz[i][1] * rgb[1] +
               ls->rgb_to_xyz[i][2] * rgb[2];
    memcpy(xyz, t, sizeof t);
}

/* CIE 15:2004 eq. 8.3: the cube root above (6/29)^3, its tangent line below,
 * which joins it with the same value and slope. */
static double lab_f(double t)
{
    const double d = 6.0 / 29.0;
    if (t > d * d * d)
        return cbrt(t);
    return t / (3.0 * d * d) + 4.0 / 29.0;
}

void lab_from_xyz(const double xyz[3], const double white[3], double lab[3])
{
    double fx = lab_f(xyz[0] / white[0]), fy = lab_f(xyz[1] / white[1]),
           fz = lab_f(xyz[2] / white[2]);
    lab[0] = 116.0 * fy - 16.0;
    lab[1] = 500.0 * (fx - fy);
    lab[2] = 200.0 * (fy - fz);
}

void lab_space_lab(const lab_space *ls, const double rgb[3], double lab[3])
{
    double xyz[3];
    lab_space_xyz(ls, rgb, xyz);
    lab_from_xyz(xyz, ls->white, lab);
}

void lab_from_linear_rgb(const colour_space *cs, const double rgb[3], double lab[3])
{
    lab_space ls;
    if (lab_space_init(&ls, cs)) {
        lab[0] = lab[1] = lab[2] = NAN;
        return;
    }
    lab_space_lab(&ls, rgb, lab);
}

double delta_e2000_rgb(const colour_space *cs, const double a[3], const double b[3])
{
    lab_space ls;
    double la[3], lb[3];
    if (lab_space_init(&ls, cs))
        return NAN;
    lab_space_lab(&ls, a, la);
    lab_space_lab(&ls, b, lb);
    return ciede2000(la, lb);
}

/* Hue angle in degrees in [0, 360), 0 for a neutral colour (Sharma et al.
 * eq. 4: atan2(0, 0) would otherwise depend on the signs of the zeros). */
static double hue(double a, double b)
{
    double h;
    if (a == 0.0 && b == 0.0)
        return 0.0;
    h = deg(atan2(b, a));
    if (h < 0.0)
        h += 360.0;
    /* A tiny negative angle plus 360 rounds to 360 itself. */
    if (h >= 360.0)
        h -= 360.0;
    return h;
}

/* Equation numbers are those of Sharma, Wu, Dalal 2005, section 2. */
double ciede2000(const double lab1[3], const double lab2[3])
{
    const double pow25_7 = 6103515625.0; /* 25^7 */
    double c1 = hypot(lab1[1], lab1[2]), c2 = hypot(lab2[1], lab2[2]);
    double c_mean = 0.5 * (c1 + c2), c_mean7 = pow(c_mean, 7.0);
    double g = 0.5 * (1.0 - sqrt(c_mean7 / (c_mean7 + pow25_7)));           /* (4) */
    double a1 = (1.0 + g) * lab1[1], a2 = (1.0 + g) * lab2[1];             /* (5) */
    double cp1 = hypot(a1, lab1[2]), cp2 = hypot(a2, lab2[2]);             /* (6) */
    double hp1 = hue(a1, lab1[2]), hp2 = hue(a2, lab2[2]);                 /* (7) */
    double dl = lab2[0] - lab1[0];                                         /* (8) */
    double dc = cp2 - cp1;                                                 /* (9) */
    double dh = 0.0, dhh, l_mean, cp_mean, h_mean, t, d_theta, cp_mean7, rc, l50, sl, sc, sh, rt;
    double kl_term, kc_term, kh_term;
    int neutral = cp1 * cp2 == 0.0;

    /* (10): the hue difference taken the short way round the circle, and 0
     * when either colour has no hue. */
    if (!neutral) {
        dh = hp2 - hp1;
        if (dh > 180.0)
            dh -= 360.0;
        else if (dh < -180.0)
            dh += 360.0;
    }
    dhh = 2.0 * sqrt(cp1 * cp2) * sin(rad(dh) / 2.0); /* (11) */

    l_mean = 0.5 * (lab1[0] + lab2[0]); /* (12) */
    cp_mean = 0.5 * (cp1 + cp2);        /* (13) */
    /* (14): the mean hue is the midpoint of the short arc; with a neutral
     * colour the sum is the other colour's hue (the neutral one's is 0). */
    if (neutral)
        h_mean = hp1 + hp2;
    else if (fabs(hp1 - hp2) <= 180.0)
        h_mean = 0.5 * (hp1 + hp2);
    else if (hp1 + hp2 < 360.0)
        h_mean = 0.5 * (hp1 + hp2 + 360.0);
    else
        h_mean = 0.5 * (hp1 + hp2 - 360.0);

    t = 1.0 - 0.17 * cos(rad(h_mean - 30.0)) + 0.24 * cos(rad(2.0 * h_mean)) +
        0.32 * cos(rad(3.0 * h_mean + 6.0)) - 0.20 * cos(rad(4.0 * h_mean - 63.0)); /* (15) */
    d_theta = 30.0 * exp(-((h_mean - 275.0) / 25.0) * ((h_mean - 275.0) / 25.0));   /* (16) */
    cp_mean7 = pow(cp_mean, 7.0);
    rc = 2.0 * sqrt(cp_mean7 / (cp_mean7 + pow25_7)); /* (17) */
    l50 = (l_mean - 50.0) * (l_mean - 50.0);
    sl = 1.0 + 0.015 * l50 / sqrt(20.0 + l50); /* (18) */
    sc = 1.0 + 0.045 * cp_mean;                /* (19) */
    sh = 1.0 + 0.015 * cp_mean * t;            /* (20) */
    rt = -sin(rad(2.0 * d_theta)) * rc;        /* (21) */

    kl_term = dl / sl;
    kc_term = dc / sc;
    kh_term = dhh / sh;
    return sqrt(kl_term * kl_term + kc_term * kc_term + kh_term * kh_term +
                rt * kc_term * kh_term); /* (22) */
}
