/* fresnel_film.h -- thin-film iridescence: the API and its manual.
 * (Skeleton: the manual is completed with the measured figures.) */
#ifndef FRESNEL_FILM_H
#define FRESNEL_FILM_H

#include <stdint.h>

#include "fresnel.h"
#include "fresnel_fixed.h"
#include "fresnel_f16.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FRESNEL_FILM_POLES 6
#define FRESNEL_FILM_NODES 32
#define FRESNEL_FILM_D_MAX 5000.0f

typedef struct fresnel_film_node {
    float a0[3];
    float opd, decay;
    float kappa[FRESNEL_FILM_POLES][2][2];
    float q[FRESNEL_FILM_POLES][2][2];
} fresnel_film_node;

typedef struct fresnel_film {
    float freq[FRESNEL_FILM_POLES];
    float damp[FRESNEL_FILM_POLES];
    float weight[3][FRESNEL_FILM_POLES][2];
    fresnel_film_node node[FRESNEL_FILM_NODES];
} fresnel_film;

#if FRESNEL_HAS_FLOAT
fresnel_rgb fresnel_film_rgb(const fresnel_film *m, float c, float d_nm);
#endif

#ifdef __cplusplus
}
#endif
#endif
