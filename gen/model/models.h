/* The table of models that `fresnel eval`, the accuracy report and the tests
 * share: each model's binary32 runtime function and its double reference,
 * and how its parameters derive from a complex IOR. */
#ifndef FRESNEL_MODELS_H
#define FRESNEL_MODELS_H

#include <stdint.h>

#include "fresnel_fixed.h"

/* Everything any model needs. eta and kappa are relative to the incident
 * medium; the rest are derived from them by the reference (model_derive). */
typedef struct model_params {
    double eta, kappa;
    double f0, f82, f90, p;
    double a, alpha; /* LSK compensation */
    double r, g;     /* Gulbrandsen */
} model_params;

/* A model's parameters in the fixed-point runtime's formats (fresnel_fixed.h). */
typedef struct model_fixed {
    int32_t f0, f82, f90, r, g; /* Q15 codes */
    fresnel_q16 p;
    fresnel_ior_prep_q15 ior; /* eta, kappa for the exact models and Cook-Torrance */
    fresnel_ior_prep_q15 dior; /* eta, kappa 0 for exact-dielectric */
    fresnel_nk_prep_q15 nk;   /* eta, kappa for the approximate conductor */
    fresnel_nk_prep_q15 gnk;  /* Gulbrandsen's n, k from r, g (fresnel_gulbrandsen_nk_q15) */
    fresnel_lsk_prep_q15 lsk;
} model_fixed;

typedef struct model {
    const char *name;
    const char *params; /* which parameters it reads, for --help */
    double (*f64)(const model_params *m, double c);
    float (*f32)(const model_params *m, float c);
    float bound; /* documented binary32 error bound, FRESNEL_BOUND_* */
    /* Q15 runtime: the result code at cos code c (0..32768), and its
     * documented bound in LSB, FRESNEL_BOUND_*_Q15 */
    int32_t (*q15)(const model_fixed *m, int32_t c);
    double q15_bound;
    /* binary16 runtime with every parameter and c rounded to binary16 (NULL
     * where the compiler has no _Float16), and FRESNEL_BOUND_*_F16 */
    double (*f16)(const model_params *m, double c);
    double f16_bound;
} model;

extern const model model_table[];
extern const int model_count;
const model *model_find(const char *name);

/* Parameters of a material of index eta + i kappa seen from a medium of index
 * n1: F0 = exact at c = 1, F82 = exact at c = 1/7, LSK a and alpha, Gulbrandsen
 * r and g, with f90 and p as given (generalized Schlick). */
void model_derive(double eta, double kappa, double n1, double f90, double p, model_params *out);

/* Round every parameter to binary32, so that a double evaluation sees exactly
 * the inputs the float one does and the difference is the runtime's error. */
void model_params_round_f32(model_params *m);

/* The same for the fixed-point runtime: F0, F82, F90, r, g to Q15 codes (r
 * at most FRESNEL_GULBRANDSEN_R_MAX_Q15, the runtime's clamp), p and alpha to
 * Q16.16, a to its 31-bit mantissa. eta and kappa are kept: the prepared
 * constants carry 31-bit mantissas, and eta^2 - kappa^2 - 1 two words, so
 * their rounding is part of the error the tests measure. */
void model_params_round_fixed(model_params *m);
/* Prepared constants and codes from (rounded) parameters. */
void model_fixed_from_params(const model_params *m, model_fixed *out);
/* And for binary16: every parameter rounded to binary16 (a no-op without _Float16). */
void model_params_round_f16(model_params *m);

#endif
