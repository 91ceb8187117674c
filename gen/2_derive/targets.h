/* Other renderers as targets: the parameters each renderer's metal takes,
 * fitted to the spectral ground truth through that renderer's own Fresnel
 * formula (`fresnel params --for TARGET`, the `targets` scene key, the
 * report's table of renderers).
 *
 * targets.c holds the table: each target's name, the parameters its UI or
 * file format takes (names, the range the fit keeps to, what the source says
 * of it), where the values go, and its formula from common/reference.h with
 * the source it is transcribed from. target_fit.c fits the parameters: the
 * naive conversion (F0 at normal incidence, the edge value at cos = 1/7,
 * "82 degrees"), and the parameters minimising the mean CIEDE2000 over
 * theta = 0, 1, ..., 90 degrees inside the target's ranges, started from the
 * naive ones, so that their mean is never above the naive conversion's. The
 * max is not minimised and can end well above the naive max (chromium for
 * MaterialX in linear sRGB: `fresnel params --material cr --for materialx`).
 * Host only. */
#ifndef FRESNEL_TARGETS_H
#define FRESNEL_TARGETS_H

#include "2_derive/derive.h"
#include "catalog/targets.h"
#include "common/reference_film.h"

#define TARGET_MAX_PARAMS 6 /* parameter rows of one target, with a film's index and thickness */
#define TARGET_MAX_X 14     /* numbers: 3 per colour row, 1 per scalar row */
#define TARGET_ANGLES GEN_FIT_ANGLES /* theta = 0, 1, ..., 90 degrees */

typedef struct target_param {
    const char *name; /* as the renderer spells it */
    int scalar;       /* 1: one number (printed repeated in r, g, b), 0: a colour */
    double lo, hi;    /* the range the fit keeps each number in */
} target_param;

/* The anchors of the naive conversion, per channel: the curve at normal
 * incidence and at cos theta = 1/7, and the fitted eta (Gulbrandsen's g). */
typedef struct target_anchor {
    double f0[3], f82[3], eta[3];
} target_anchor;

/* A renderer's thin-film inputs over its metal, in its names and units
 * (thickness NULL: it has none). The metal's own parameters stay the bare
 * metal's: the renderer lays the film over them. */
typedef struct target_film {
    const char *weight;        /* the film's weight, set to 1; NULL: none */
    const char *thickness;     /* the thickness input */
    const char *thickness_min; /* a lower bound set to the same thickness (glTF's range); NULL: none */
    double per_nm;             /* the thickness input's units per nanometre */
    const char *ior;           /* the film's index */
    const char *where;         /* the inputs' place and source, in a few words */
    /* The renderer's film over its metal at cosine c: x is the metal's
     * packed parameters, then the film's index, then its thickness in nm;
     * k the scene's sensitivities for a renderer that integrates against
     * them (Blender). Every target with a film input has one. */
    void (*eval)(const double *x, double c, const film_cmfs *k, double rgb[3]);
    const char *formula;       /* that formula and its source, in a few words */
} target_film;

typedef struct target {
    const char *name;    /* `--for` and the scene key */
    const char *title;   /* the renderer and the part of it */
    const char *formula; /* which Fresnel curve, in a few words */
    const char *source;  /* where the formula and ranges are stated */
    const char *inputs;  /* where the values go: colour space, ranges, clamps */
    int param_count;
    target_param param[TARGET_MAX_PARAMS];
    int rec709;          /* the format takes linear Rec. 709 (srgb) only */
    const char *naive_rule; /* how naive() converts, in a few words */
    /* The curve at cosine c for packed parameters x (param order, 3 numbers
     * per colour row, 1 per scalar row). */
    void (*eval)(const double *x, double c, double rgb[3]);
    /* The naive parameters from the anchors, inside the ranges. */
    void (*naive)(const target_anchor *a, double *x);
    target_film film;
} target;

/* The film inputs of t for a film of index n and thickness d_nm as
 * name/value pairs (at most 4): their count, 0 if t has no film input. */
int target_film_rows(const target *t, double n, double d_nm, const char *names[4], double values[4]);

/* Indexed by target_id (catalog/targets.h). */
extern const target target_table[TARGETS];
extern const int target_count;
/* The target named name; NULL if none. */
const target *target_find(const char *name);
/* How many numbers x holds for t. */
int target_x_count(const target *t);
/* Whether some colour row of t admits values above 1 (a colour outside the
 * gamut, as gold's F0 in linear sRGB). */
int target_above_one(const target *t);

/* target_fit.c */
typedef struct target_fit {
    const target *t;
    double naive[TARGET_MAX_X], fitted[TARGET_MAX_X];
    double naive_mean, naive_max; /* CIEDE2000 over TARGET_ANGLES */
    double fit_mean, fit_max;
    long evaluations; /* curves evaluated by the search */
} target_fit;

/* cos theta of sample i: theta = i degrees, exactly 0 at 90. */
double target_cos(int i);
/* Mean and max CIEDE2000 of t's curve with parameters x against truth
 * (TARGET_ANGLES RGB triples, theta = 0..90 degrees). */
void target_curve_de(const target *t, const lab_space *ls, const double (*truth)[3], const double *x, double *mean,
                     double *max);
/* Naive and fitted parameters of t for the curve truth (the anchors
 * describing the same curve). Deterministic. */
void target_fit_curve(const target *t, const lab_space *ls, const double (*truth)[3], const target_anchor *a,
                      target_fit *out);
/* The same search started from start (x of t) rather than t's naive
 * conversion; out->naive is start. */
void target_fit_from(const target *t, const lab_space *ls, const double (*truth)[3], const double *start,
                     target_fit *out);
/* The scene's sensitivities as Blender's film integrates against them
 * (film_cmfs in common/reference_film.h): g's CIE 1931 functions through
 * g's XYZ-to-RGB matrix, resampled uniformly in 1 / lambda by linear
 * interpolation of the 1 nm table. */
void target_film_cmfs(const gen_context *g, film_cmfs *k);

/* The metal's parameters of t refitted under a film of index n through t's
 * own film formula (t->film.eval, not NULL) against the film's spectral
 * truth on the material (each channel held to [0, 1]), started from t's
 * naive conversion: for one thickness d_lo = d_hi nm, or for every
 * thickness of the range at once (the mean over TARGET_FILM_CURVES
 * thicknesses evenly spaced from d_lo to d_hi, and the max over them).
 * out->fitted and out->naive hold the metal's numbers, then n and d_hi.
 * 0, or -1 (no memory). */
#define TARGET_FILM_CURVES 7
int target_film_fit(const target *t, const spectrum *s, const gen_context *g, const material_params *p, double n,
                    double d_lo, double d_hi, target_fit *out);
/* One material's truth and anchors: under the gamut policy (under_policy 1:
 * what the generator's other parameters are derived from) or the unclipped
 * spectral ground truth (0). */
void target_material_curve(const spectrum *s, const gen_context *g, const material_params *p, int under_policy,
                           double (*truth)[3], target_anchor *a);

#endif
