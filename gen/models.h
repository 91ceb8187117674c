/* The table of models that `fresnel eval`, the accuracy report and the tests
 * share: each model's binary32 runtime function and its double reference,
 * and how its parameters derive from a complex IOR. */
#ifndef FRESNEL_MODELS_H
#define FRESNEL_MODELS_H

/* Everything any model needs. eta and kappa are relative to the incident
 * medium; the rest are derived from them by the reference (model_derive). */
typedef struct model_params {
    double eta, kappa;
    double f0, f82, f90, p;
    double a, alpha; /* LSK compensation */
    double r, g;     /* Gulbrandsen */
} model_params;

typedef struct model {
    const char *name;
    const char *params; /* which parameters it reads, for --help */
    double (*f64)(const model_params *m, double c);
    float (*f32)(const model_params *m, float c);
    float bound; /* documented binary32 error bound, FRESNEL_BOUND_* */
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

#endif
