/* The dense grid every float error bound is measured on (fresnel.h CONVENTIONS). */
#ifndef FRESNEL_TEST_GRID_H
#define FRESNEL_TEST_GRID_H

#include <math.h>

#define GRID_ETA_N 49
#define GRID_KAPPA_N 43 /* 0, then 1e-3 .. 1000 */
#define GRID_N1_N 4
static const double grid_n1[GRID_N1_N] = {1.0, 1.33, 1.5, 2.42};

static double grid_eta(int i) { return 0.01 * pow(1e4, i / (double)(GRID_ETA_N - 1)); }
static double grid_kappa(int i)
{
    return i == 0 ? 0.0 : 1e-3 * pow(1e6, (i - 1) / (double)(GRID_KAPPA_N - 2));
}

/* Cosines: 0, 1, points within 1e-6 of each, and 1025 points in between
 * spaced uniformly in c and in the angle. Returns the count written. */
static int grid_cos(float *c, int max)
{
    static const float near[] = {0.0f, 1e-30f, 1e-12f, 1e-8f, 1e-7f, 3e-7f, 1e-6f};
    int n = 0, i;
    for (i = 0; i < (int)(sizeof near / sizeof near[0]) && n + 2 <= max; i++) {
        c[n++] = near[i];
        c[n++] = 1.0f - near[i];
    }
    c[n++] = 1.0f - 5.96e-8f; /* one ulp below 1 */
    for (i = 1; i < 512 && n + 2 <= max; i++) {
        c[n++] = (float)(i / 512.0);
        c[n++] = (float)cos(i / 512.0 * 1.5707963267948966);
    }
    return n;
}

#endif
