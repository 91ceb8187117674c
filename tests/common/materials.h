/* The material set of the fixed-point and binary16 bound tests
 * (fresnel_fixed.h ERROR BOUNDS): eta, kappa relative to the incident
 * medium. Until the generator's default scene exists: measured data at the
 * three wavelengths the RGB fits centre on, from both sides of the
 * dielectrics (total internal reflection), metals under water, and corners
 * of the domain that the data do not reach. */
#ifndef FRESNEL_TEST_FIXED_MATERIALS_H
#define FRESNEL_TEST_FIXED_MATERIALS_H

#include <stdio.h>
#include <string.h>

#include "1_spectral/spectral.h"

#define TM_MAX 96

typedef struct test_material {
    char name[32];
    double eta, kappa; /* relative */
} test_material;

static int tm_add(test_material *t, int n, const char *name, double eta, double kappa)
{
    if (n >= TM_MAX)
        return n;
    snprintf(t[n].name, sizeof t[n].name, "%s", name);
    t[n].eta = eta;
    t[n].kappa = kappa;
    return n + 1;
}

/* Returns the count, or -1 when data/ cannot be read. */
static int test_materials(test_material *t)
{
    static const char *const metals[] = {"au", "cu", "ag", "al", "cr", "fe", "pt", "ti", "ni", "zn"};
    static const char *const dielectrics[] = {"bk7", "water"};
    static const double wl[3] = {450.0, 550.0, 650.0};
    static spectrum s;
    char name[32];
    int n = 0, i, j;
    for (i = 0; i < 12; i++) {
        const char *id = i < 10 ? metals[i] : dielectrics[i - 10];
        if (spectrum_load(data_dir(NULL), id, &s))
            return -1;
        for (j = 0; j < 3; j++) {
            int k = (int)((wl[j] - SPEC_LO_NM) / SPEC_STEP_NM + 0.5);
            snprintf(name, sizeof name, "%s %.0f", id, wl[j]);
            n = tm_add(t, n, name, s.n[k], s.k[k]);
            if (i >= 10) { /* from inside: eta' = 1/eta, total internal reflection */
                snprintf(name, sizeof name, "%s %.0f inside", id, wl[j]);
                n = tm_add(t, n, name, 1.0 / s.n[k], 0.0);
            } else if (j == 1) { /* under water */
                snprintf(name, sizeof name, "%s 550 in water", id);
                n = tm_add(t, n, name, s.n[k] / 1.333, s.k[k] / 1.333);
            }
        }
    }
    n = tm_add(t, n, "matched", 1.0, 0.0);
    n = tm_add(t, n, "eta 1.0001", 1.0001, 0.0);
    n = tm_add(t, n, "eta 0.9999", 0.9999, 0.0);
    n = tm_add(t, n, "eta 1 kappa 1e-3", 1.0, 1e-3);
    n = tm_add(t, n, "eta 0.05 kappa 0", 0.05, 0.0);
    n = tm_add(t, n, "eta 0.2 kappa 10", 0.2, 10.0);
    n = tm_add(t, n, "eta 5 kappa 0.5", 5.0, 0.5);
    n = tm_add(t, n, "eta 12 kappa 12", 12.0, 12.0);
    n = tm_add(t, n, "eta 40 kappa 0", 40.0, 0.0);
    n = tm_add(t, n, "eta 2 kappa 50", 2.0, 50.0);
    n = tm_add(t, n, "eta 0.17 kappa 1000", 0.17, 1000.0); /* r -> 1, g -> 1 */
    n = tm_add(t, n, "eta 0.01 kappa 0", 0.01, 0.0);      /* critical angle at c = 0.99995 */
    n = tm_add(t, n, "eta 0.0703 kappa 0", 0.0703, 0.0);  /* ... within a binary16 step of c = 1 */
    n = tm_add(t, n, "eta 0.01 kappa 5", 0.01, 5.0);
    /* near-dielectric conductors at their critical angle, and a rounded a0
     * at the layout's limit */
    n = tm_add(t, n, "eta 0.0156 kappa 2.2e-5", 0.0156, 2.2e-5);
    n = tm_add(t, n, "eta 0.999999225 kappa 1.9e-5", 0.999999225, 1.9e-5);
    n = tm_add(t, n, "eta 0.0112 kappa 0.0038", 0.0112, 0.0038);
    n = tm_add(t, n, "eta 2 kappa 1e-6", 2.0, 1e-6);
    return n;
}

#endif
