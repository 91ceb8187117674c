/* Stage 3 of the generator: LUT node positions and values for the runtime's
 * table models (include/fresnel.h, src/lut.c), fitted to the ground truth. */
#ifndef FRESNEL_ENCODE_H
#define FRESNEL_ENCODE_H

#include "2_derive/derive.h"

/* LUT_GRAZING: nodes uniform in sqrt(c); LUT_UNIFORM: in c; LUT_GRAZING_PL:
 * uniform in fresnel_fixed_fast.h's 64-piece linear stand-in for sqrt(c), the
 * position of fresnel_lut_pl_u16_q15_fast. LUT_WARP2, LUT_WARP16: uniform in
 * the root-free warps c (2 - c) = 1 - (1 - c)^2 and (1 + c - (1 - c)^16)/2,
 * whose slope at c = 0 (2; 8.5) crowds the nodes toward grazing incidence
 * at the cost of a few multiplications instead of a square root; no runtime
 * function reads them: the report's LUT table measures them against sqrt(c)
 * at equal size. */
typedef enum lut_spacing { LUT_GRAZING, LUT_UNIFORM, LUT_GRAZING_PL, LUT_WARP2, LUT_WARP16 } lut_spacing;
/* cos theta of node i of n. */
double lut_node_cos(lut_spacing spacing, int i, int n);
/* The position in [0, 1] along the nodes of cos theta = c (node i at i/(n-1)). */
double lut_position(lut_spacing spacing, double c);
/* The runtime's LUT forms: linear interpolation of the curve (fresnel_lut),
 * of its residual from Schlick(F0) (fresnel_lut_residual), Catmull-Rom of
 * the curve (fresnel_lut_cubic). */
typedef enum lut_form { LUT_PLAIN, LUT_RESIDUAL, LUT_CUBIC } lut_form;
/* table[ch * n + i]: node i of channel ch, least-squares fitted through the
 * form's interpolation to the ground truth under the gamut policy (minus
 * Schlick(F0) for LUT_RESIDUAL) at theta every 0.05 degrees and at the
 * nodes; curve nodes that would leave [0, 1] (under the keep policy
 * [0, the curve's maximum], at most ENCODE_LUT_KEEP_MAX) are held at the
 * bound and the others refitted.
 * 0, or -1 when out of memory. */
#define ENCODE_LUT_KEEP_MAX (65535.0 / 32768.0) /* the largest uint16_t Q15 node */
int encode_lut(const spectrum *s, const gen_context *g, const material_params *p, lut_spacing spacing, int n,
               lut_form form, double *table);

#endif
