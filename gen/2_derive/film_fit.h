/* The generator's side of the thin-film model (fresnel_film.h): the poles
 * that stand for the colorimetry, and a material's table of interface terms
 * (common/reference_film.h describes both). Host only. */
#ifndef FRESNEL_FILM_FIT_H
#define FRESNEL_FILM_FIT_H

#include "common/reference_film.h"
#include "1_spectral/spectral.h"

#include <stddef.h>

/* The poles and their weights for the colour space: a least-squares fit of
 * the CIE observer's X, Y, Z sensitivities under D65 (the ground truth's
 * colorimetry), as functions of the optical path x in [0, FILM_FIT_X_MAX]
 * nm, by FRESNEL_FILM_POLES damped complex exponentials; the space's
 * matrix then gives each RGB channel's weights. Deterministic (fixed start,
 * damped Gauss-Newton). *max_error (may be NULL) receives the largest
 * |S - fit| over the samples, relative to S(0) = 1. 0, or -1 when the fit
 * failed. About a second. */
#define FILM_FIT_X_MAX 20000.0
int film_fit_poles(const colorimetry *cm, const colour_space *cs, film_model *m, double *max_error);

/* The thickness range whose truth the interface terms are fitted to. */
#define FILM_FIT_D_MAX 1200.0

/* The stacks the model represents (fresnel_film.h, THE DOMAIN), each
 * condition a fact of the optics the table is interpolated from:
 *   - a film at least as dense as the incident medium (n_f >= n1): no
 *     total reflection inside the film;
 *   - a substrate whose cosine of refraction stays clear of zero over
 *     every angle and wavelength: the branch point of
 *     xi_3 = sqrt(N3^2 - n1^2 (1 - c^2)) at c^2 = 1 - N3^2 / n1^2 at least
 *     FILM_DOMAIN_BRANCH from the segment c^2 in [0, 1]. On it the
 *     substrate reflects totally (a glass substrate under a denser
 *     ambient); near it (a substrate of about the ambient's index) the
 *     interface terms turn at a square-root edge between the table's
 *     nodes and the table's constants grow until rounding dominates.
 * 0 when f is in the domain; else -1 and why (a sentence naming the
 * condition, the index and the wavelength) in why[size]. */
#define FILM_DOMAIN_BRANCH 0.2 /* where the runtime's errors stay near a film's in air (fresnel_film.h) */
int film_stack_domain(const film_stack *f, char *why, size_t size);

/* The material's table, m's poles already set: a non-dispersive film
 * (f->film NULL, f->film_n >= 1e-3) of any real index in any real ambient
 * (f->n1 > 0) on any substrate. 0, or -1 (m's table untouched) for a
 * dispersive film, a bad index or no memory. About half a second. */
int film_fit_material(const film_stack *f, const colorimetry *cm, const colour_space *cs, film_model *m);

#endif
