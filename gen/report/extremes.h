/* The extreme and stiff cases, shared by `fresnel extremes` (which
 * prints what every model returns on them) and tests/runtime/every_type/test_extremes.c (which
 * asserts the properties). Host only. */
#ifndef FRESNEL_EXTREMES_H
#define FRESNEL_EXTREMES_H

#include <stdint.h>

#include "model/number_type.h"
#include "model/registry.h"

/* A material seen from an incident medium: eta + i kappa absolute, n1 real. */
typedef struct extreme_case {
    const char *name;
    double eta, kappa, n1;
    const char *note;
} extreme_case;
extern const extreme_case extreme_cases[];
extern const int extreme_case_count;

/* Cosines as a caller might pass them, in and outside [0, 1]. */
typedef struct extreme_cos {
    const char *label;
    float c;
    int lsb; /* 1: the type's smallest positive cosine instead of c */
} extreme_cos;
extern const extreme_cos extreme_cosines[];
extern const int extreme_cosine_count;

/* F0/F82 pairs at and beyond the ends of [0, 1] (out-of-gamut gold, F82 far
 * above or below F0). */
typedef struct extreme_reflectance {
    const char *name;
    float f0, f82;
} extreme_reflectance;
extern const extreme_reflectance extreme_reflectances[];
extern const int extreme_reflectance_count;
/* Gulbrandsen r (in .f0) and g (in .f82) at the ends of their domain. */
extern const extreme_reflectance extreme_gulbrandsen[];
extern const int extreme_gulbrandsen_count;

/* The cosines in [0, 1] every maximum error is taken over: each extreme of
 * extreme_cosines inside [0, 1], then points uniform in c and in the angle.
 * Writes at most max, returns the count. */
int extreme_cos_grid(float *c, int max);

/* Parameters of a case as `fresnel eval` makes them (model_derive, f90 = 1,
 * p = 5), rounded to binary32. */
void extreme_params(const extreme_case *e, model_params *m);

/* 1 if eta and kappa (relative, after the runtime's clamps) lie where the
 * FRESNEL_BOUND_* were measured: eta in [0.01, 100], kappa in [0, 1000]. */
int extreme_in_measured_domain(const model_params *m);

/* A number type of the runtime: f32 (fresnel.h), q15 (fresnel_q15.h),
 * f16 (fresnel_f16.h, where the compiler has _Float16). */
typedef struct extreme_typed {
    model_params p;  /* parameters as the reference sees them for this type */
    model_q15 q;   /* q15: the prepared constants */
    int in_domain;   /* the documented bound applies */
} extreme_typed;
typedef struct extreme_type {
    const number_type *type; /* its row: name, clamps, cosines, evaluators, bounds */
} extreme_type;
extern const extreme_type extreme_types[];
extern const int extreme_type_count;

/* The cosine a type is given for an entry of extreme_cosines. */
double extreme_cos_input(const extreme_type *ty, const extreme_cos *x);
/* A case's parameters as the reference sees them in type ty: derived
 * (f90 = 1, p = 5), rounded to the type, clamped where its runtime clamps. */
void extreme_prepare(const extreme_type *ty, const extreme_case *e, extreme_typed *t);
/* The type's result at cosine x (converted to the type: rounded, or to a
 * Q15 code) and the cosine the reference sees; 0 if x has no
 * representation in the type (NaN in Q15). */
int extreme_eval(const extreme_type *ty, const model *m, const extreme_typed *t, double x, double *got, double *ref_c);
/* Max |result - reference| over extreme_cos_grid; *bad when a result is not
 * a number in [0, 1]. */
double extreme_max_err(const model *m, const extreme_type *ty, const extreme_typed *t, int *bad);
/* fresnel_f82 (kind 0) or fresnel_gulbrandsen (kind 1) of type ti called
 * directly with (a, b) over 4097 cosines: max |result - reference|; *na when
 * the type cannot represent a or b (NaN in Q15). And the documented bound. */
double extreme_direct_max_err(int kind, int ti, float a, float b, int *bad, int *na);
double extreme_direct_bound(int kind, int ti);

/* F82 curve F0 + (1-F0)(1-c)^5 - a c (1-c)^6 without the final clamp, in
 * double: how far outside [0, 1] a pair pushes it before the runtime clamps. */
double extreme_f82_unclamped(double f0, double f82, double c);

/* Every table of `fresnel extremes`, as Markdown on stdout. */
void extremes_print(void);

#endif
