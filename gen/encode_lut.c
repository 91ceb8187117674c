/* Step 7: reflectance curves sampled at the LUT nodes the runtime expects
 * (include/fresnel.h, src/lut.c). */
#include <math.h>

#include "generator.h"
#include "reference.h"

double lut_node_cos(lut_spacing spacing, int i, int n)
{
    double w = (double)i / (n - 1);
    return spacing == LUT_UNIFORM ? w : w * w; /* grazing: uniform in sqrt(c) */
}

void encode_lut(const spectrum *s, const gen_context *g, const material_params *p, lut_spacing spacing,
                int n, int residual, double *table)
{
    int i, ch;
    for (i = 0; i < n; i++) {
        double c = lut_node_cos(spacing, i, n), rgb[3];
        ground_truth_clamped(s, g, p->n1, c, rgb);
        for (ch = 0; ch < 3; ch++)
            table[ch * n + i] = residual ? rgb[ch] - ref_schlick(p->f0[ch], c) : rgb[ch];
    }
}
