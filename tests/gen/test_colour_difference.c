/* CIELAB and CIEDE2000 (gen/1_spectral/colour_difference.c): the published test data of
 * Sharma, Wu, Dalal 2005, properties of the formula, and the Lab white of
 * every colour space of the data pack. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "1_spectral/colour_difference.h"
#include "harness.h"
#include "1_spectral/spectral.h"

/* Table 1 of G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000 color-difference
 * formula: implementation notes, supplementary test data, and mathematical
 * observations", Color Research and Application 30(1), 21-30, 2005:
 * L1 a1 b1, L2 a2 b2, Delta E00 (kL = kC = kH = 1), as published to 4
 * decimals. Pairs 7-16 exercise the hue-angle edge cases (neutral colours,
 * arctangent quadrants, hue differences either side of 180 degrees). */
static const double sharma[34][7] = {
    {50.0000, 2.6772, -79.7751, 50.0000, 0.0000, -82.7485, 2.0425},
    {50.0000, 3.1571, -77.2803, 50.0000, 0.0000, -82.7485, 2.8615},
    {50.0000, 2.8361, -74.0200, 50.0000, 0.0000, -82.7485, 3.4412},
    {50.0000, -1.3802, -84.2814, 50.0000, 0.0000, -82.7485, 1.0000},
    {50.0000, -1.1848, -84.8006, 50.0000, 0.0000, -82.7485, 1.0000},
    {50.0000, -0.9009, -85.5211, 50.0000, 0.0000, -82.7485, 1.0000},
    {50.0000, 0.0000, 0.0000, 50.0000, -1.0000, 2.0000, 2.3669},
    {50.0000, -1.0000, 2.0000, 50.0000, 0.0000, 0.0000, 2.3669},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0009, 7.1792},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0010, 7.1792},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0011, 7.2195},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0012, 7.2195},
    {50.0000, -0.0010, 2.4900, 50.0000, 0.0009, -2.4900, 4.8045},
    {50.0000, -0.0010, 2.4900, 50.0000, 0.0010, -2.4900, 4.8045},
    {50.0000, -0.0010, 2.4900, 50.0000, 0.0011, -2.4900, 4.7461},
    {50.0000, 2.5000, 0.0000, 50.0000, 0.0000, -2.5000, 4.3065},
    {50.0000, 2.5000, 0.0000, 73.0000, 25.0000, -18.0000, 27.1492},
    {50.0000, 2.5000, 0.0000, 61.0000, -5.0000, 29.0000, 22.8977},
    {50.0000, 2.5000, 0.0000, 56.0000, -27.0000, -3.0000, 31.9030},
    {50.0000, 2.5000, 0.0000, 58.0000, 24.0000, 15.0000, 19.4535},
    {50.0000, 2.5000, 0.0000, 50.0000, 3.1736, 0.5854, 1.0000},
    {50.0000, 2.5000, 0.0000, 50.0000, 3.2972, 0.0000, 1.0000},
    {50.0000, 2.5000, 0.0000, 50.0000, 1.8634, 0.5757, 1.0000},
    {50.0000, 2.5000, 0.0000, 50.0000, 3.2592, 0.3350, 1.0000},
    {60.2574, -34.0099, 36.2677, 60.4626, -34.1751, 39.4387, 1.2644},
    {63.0109, -31.0961, -5.8663, 62.8187, -29.7946, -4.0864, 1.2630},
    {61.2901, 3.7196, -5.3901, 61.4292, 2.2480, -4.9620, 1.8731},
    {35.0831, -44.1164, 3.7933, 35.0232, -40.0716, 1.5901, 1.8645},
    {22.7233, 20.0904, -46.6940, 23.0331, 14.9730, -42.5619, 2.0373},
    {36.4612, 47.8580, 18.3852, 36.2715, 50.5065, 21.2231, 1.4146},
    {90.8027, -2.0831, 1.4410, 91.1528, -1.6435, 0.0447, 1.4441},
    {90.9257, -0.5406, -0.9208, 88.6381, -0.8985, -0.7239, 1.5381},
    {6.7747, -0.2908, -2.4247, 5.8714, -0.0985, -2.2286, 0.6377},
    {2.0776, 0.0795, -1.1350, 0.9033, -0.0636, -0.5514, 0.9082},
};

static void test_sharma(void)
{
    double worst = 0.0, worst_asym = 0.0;
    int i, bad = -1;
    for (i = 0; i < 34; i++) {
        double e = ciede2000(sharma[i], sharma[i] + 3), r = ciede2000(sharma[i] + 3, sharma[i]);
        double err = fabs(e - sharma[i][6]);
        if (!(err <= worst)) {
            worst = err;
            if (!(err <= 1e-4) && bad < 0)
                bad = i;
        }
        if (fabs(e - r) > worst_asym)
            worst_asym = fabs(e - r);
    }
    NOTE("Sharma et al. 2005 pairs: max |dE00 - published| %.2e, max asymmetry %.2e", worst,
         worst_asym);
    CHECK("ciede2000: 34 published pairs of Sharma et al. 2005 within 1e-4", bad < 0,
          "pair %d: got %.6f, published %.4f", bad + 1,
          bad < 0 ? 0.0 : ciede2000(sharma[bad], sharma[bad] + 3), bad < 0 ? 0.0 : sharma[bad][6]);
    CHECK("ciede2000: symmetric on the published pairs", worst_asym <= 1e-12, "asymmetry %.3g",
          worst_asym);
}

/* A fixed stream of Lab colours covering every hue, neutral ones, signed
 * zeros and hue pairs near 180 degrees apart, for the properties below. */
static unsigned long lcg_state = 12345u;
static double uniform(double lo, double hi)
{
    lcg_state = (lcg_state * 1103515245u + 12345u) & 0x7fffffffu;
    return lo + (hi - lo) * (double)lcg_state / 2147483648.0;
}

static void test_properties(void)
{
    int i, asym_fail = 0, zero_fail = 0, range_fail = 0;
    double worst_asym = 0.0;
    static const double neg_zero[3] = {50.0, -0.0, -0.0}, pos_zero[3] = {50.0, 0.0, 0.0};
    for (i = 0; i < 20000; i++) {
        double p[3], q[3], e, r;
        p[0] = uniform(0.0, 100.0);
        p[1] = uniform(-120.0, 120.0);
        p[2] = uniform(-120.0, 120.0);
        switch (i % 4) {
        case 0: /* opposite hue, slightly rotated: the arc-crossing branches */
            q[0] = p[0] + uniform(-5.0, 5.0);
            q[1] = -p[1] + uniform(-0.01, 0.01);
            q[2] = -p[2] + uniform(-0.01, 0.01);
            break;
        case 1: /* neutral partner */
            q[0] = uniform(0.0, 100.0);
            q[1] = q[2] = 0.0;
            break;
        default:
            q[0] = uniform(0.0, 100.0);
            q[1] = uniform(-120.0, 120.0);
            q[2] = uniform(-120.0, 120.0);
        }
        e = ciede2000(p, q);
        r = ciede2000(q, p);
        if (fabs(e - r) > worst_asym)
            worst_asym = fabs(e - r);
        if (fabs(e - r) > 1e-12 * (1.0 + e))
            asym_fail++;
        if (!(e >= 0.0 && isfinite(e)))
            range_fail++;
        if (ciede2000(p, p) != 0.0)
            zero_fail++;
    }
    CHECK("ciede2000: symmetric on 20000 pairs incl. opposite hues and neutral partners",
          asym_fail == 0, "%d pairs, worst %.3g", asym_fail, worst_asym);
    CHECK("ciede2000: finite and >= 0 on 20000 pairs", range_fail == 0, "%d pairs", range_fail);
    CHECK("ciede2000: exactly 0 for identical colours", zero_fail == 0, "%d colours", zero_fail);
    CHECK("ciede2000: signed zeros of a neutral colour make no difference",
          ciede2000(neg_zero, pos_zero) == 0.0, "%.3g", ciede2000(neg_zero, pos_zero));
}

static colorimetry cm; /* large: not on the stack */

static void test_spaces(void)
{
    const char *dir = data_dir(NULL);
    colour_space cs, srgb;
    int i, loaded = colorimetry_load(dir, &cm) == 0;
    CHECK("colorimetry loads", loaded, "from %s", dir);
    if (!loaded || colour_space_load(dir, "srgb", &cm, &srgb))
        return;
    for (i = 0; colour_space_ids[i]; i++) {
        static const double one[3] = {1.0, 1.0, 1.0}, black[3] = {0.0, 0.0, 0.0},
                            grey[3] = {0.18, 0.18, 0.18};
        char name[128];
        double lab[3], lab_black[3], lab_grey[3], grey_l = 116.0 * cbrt(0.18) - 16.0;
        lab_space ls;
        if (colour_space_load(dir, colour_space_ids[i], &cm, &cs)) {
            CHECK("colour space loads", 0, "%s", colour_space_ids[i]);
            continue;
        }
        snprintf(name, sizeof name, "%s: lab_space_init", cs.id);
        CHECK(name, lab_space_init(&ls, &cs) == 0, "singular xyz_to_rgb");
        lab_from_linear_rgb(&cs, one, lab);
        snprintf(name, sizeof name, "%s: RGB (1,1,1) is L* 100, a* b* 0", cs.id);
        CHECK(name, fabs(lab[0] - 100.0) <= 1e-12 && fabs(lab[1]) <= 1e-12 && fabs(lab[2]) <= 1e-12,
              "Lab %.15g %.3g %.3g", lab[0], lab[1], lab[2]);
        snprintf(name, sizeof name, "%s: white has Y 1 (the D65 SPD normalised as ground_truth does)",
                 cs.id);
        CHECK(name, fabs(ls.white[1] - 1.0) <= 1e-12, "Y %.15g", ls.white[1]);
        lab_from_linear_rgb(&cs, black, lab_black);
        lab_from_linear_rgb(&cs, grey, lab_grey);
        snprintf(name, sizeof name, "%s: black is L* 0, grey 0.18 is neutral with L* %.4f", cs.id,
                 grey_l);
        CHECK(name,
              fabs(lab_black[0]) <= 1e-12 && fabs(lab_grey[0] - grey_l) <= 1e-9 &&
                  fabs(lab_grey[1]) <= 1e-9 && fabs(lab_grey[2]) <= 1e-9,
              "black L* %.3g, grey %.10g %.3g %.3g", lab_black[0], lab_grey[0], lab_grey[1],
              lab_grey[2]);
        {
            /* The same XYZ carried by sRGB or by this space is the same Lab:
             * the inverse undoes each space's adaptation. */
            static const double colours[3][3] = {
                {0.9, 0.6, 0.3}, {0.05, 0.4, 0.8}, {1.04, 0.79, 0.34}};
            double worst = 0.0;
            int k, j;
            lab_space s;
            lab_space_init(&s, &srgb);
            for (k = 0; k < 3; k++) {
                double xyz[3], rgb[3], l1[3], l2[3];
                lab_space_xyz(&s, colours[k], xyz);
                for (j = 0; j < 3; j++)
                    rgb[j] = cs.xyz_to_rgb[j][0] * xyz[0] + cs.xyz_to_rgb[j][1] * xyz[1] +
                             cs.xyz_to_rgb[j][2] * xyz[2];
                lab_space_lab(&s, colours[k], l1);
                lab_space_lab(&ls, rgb, l2);
                if (ciede2000(l1, l2) > worst)
                    worst = ciede2000(l1, l2);
            }
            snprintf(name, sizeof name, "%s: Lab independent of the space carrying the XYZ", cs.id);
            CHECK(name, worst <= 1e-9, "dE00 %.3g", worst);
        }
    }

    {
        /* sRGB primaries against their textbook Lab (D65 white 0.95047, 1,
         * 1.08883; Lindbloom's calculator). Ours uses the white of the D65
         * SPD (x 0.31273, y 0.32902), hence the tolerance. */
        static const double prim[3][3] = {{53.2408, 80.0925, 67.2032},
                                          {87.7347, -86.1827, 83.1793},
                                          {32.2970, 79.1875, -107.8602}};
        double worst = 0.0;
        int k, j;
        for (k = 0; k < 3; k++) {
            double rgb[3] = {0.0, 0.0, 0.0}, lab[3];
            rgb[k] = 1.0;
            lab_from_linear_rgb(&srgb, rgb, lab);
            for (j = 0; j < 3; j++)
                if (fabs(lab[j] - prim[k][j]) > worst)
                    worst = fabs(lab[j] - prim[k][j]);
        }
        CHECK("srgb: primaries' Lab within 0.1 of the textbook values", worst <= 0.1,
              "max deviation %.4f", worst);
        NOTE("srgb primaries: max deviation from textbook Lab %.4f", worst);
    }

    {
        /* Out-of-gamut RGB (gold's red above 1, a small negative channel) is
         * converted as is, and a small change is a small, finite difference. */
        static const double gold[3] = {1.04, 0.79, 0.34}, gold2[3] = {1.03, 0.79, 0.34},
                            neg[3] = {-0.02, 0.5, 0.6}, neg2[3] = {-0.01, 0.5, 0.6};
        double lab[3], e1 = delta_e2000_rgb(&srgb, gold, gold2),
                       e2 = delta_e2000_rgb(&srgb, neg, neg2);
        lab_from_linear_rgb(&srgb, gold, lab);
        CHECK("out of gamut: gold red 1.04 gives a finite Lab (L* > 90, a* > 0)",
              isfinite(lab[0]) && isfinite(lab[1]) && isfinite(lab[2]) && lab[0] > 90.0 &&
                  lab[1] > 0.0,
              "Lab %.4f %.4f %.4f", lab[0], lab[1], lab[2]);
        CHECK("out of gamut: 0.01 change above 1 and below 0 is a finite dE00 in (0, 2)",
              e1 > 0.0 && e1 < 2.0 && e2 > 0.0 && e2 < 2.0, "%.4f %.4f", e1, e2);
        CHECK("delta_e2000_rgb: 0 for identical colours", delta_e2000_rgb(&srgb, gold, gold) == 0.0,
              "%.3g", delta_e2000_rgb(&srgb, gold, gold));
    }
}

int main(void)
{
    test_sharma();
    test_properties();
    test_spaces();
    return harness_exit();
}
