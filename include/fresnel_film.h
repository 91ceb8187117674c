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
#define FRESNEL_BOUND_FILM 1.5e-6f
#define FRESNEL_BOUND_FILM_Q15 24.0
#define FRESNEL_BOUND_FILM_F16 8e-3

typedef struct fresnel_film_node {
    float a0[3];
    float opd, decay;
    /* per pole: A, B, P, Q, real and imaginary parts */
    float a_re[FRESNEL_FILM_POLES], a_im[FRESNEL_FILM_POLES], b_re[FRESNEL_FILM_POLES], b_im[FRESNEL_FILM_POLES];
    float p_re[FRESNEL_FILM_POLES], p_im[FRESNEL_FILM_POLES], q_re[FRESNEL_FILM_POLES], q_im[FRESNEL_FILM_POLES];
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

#define FRESNEL_FILM_D_MAX_Q16 (5000 * 65536)
typedef struct fresnel_film_node_q15 {
    int16_t a0[3];
    uint16_t opd, decay;
    int16_t a_re[FRESNEL_FILM_POLES], a_im[FRESNEL_FILM_POLES], b_re[FRESNEL_FILM_POLES], b_im[FRESNEL_FILM_POLES];
    int16_t p_re[FRESNEL_FILM_POLES], p_im[FRESNEL_FILM_POLES], q_re[FRESNEL_FILM_POLES], q_im[FRESNEL_FILM_POLES];
} fresnel_film_node_q15;
typedef struct fresnel_film_q15 {
    uint32_t turn_nu[FRESNEL_FILM_POLES], turn_gamma[FRESNEL_FILM_POLES];
    uint32_t octave_nu[FRESNEL_FILM_POLES], octave_gamma[FRESNEL_FILM_POLES];
    int16_t weight[3][FRESNEL_FILM_POLES][2];
    fresnel_film_node_q15 node[FRESNEL_FILM_NODES];
} fresnel_film_q15;
#if FRESNEL_HAS_FIXED
fresnel_rgb_q15 fresnel_film_q15_rgb(const fresnel_film_q15 *m, int32_t c, fresnel_q16 d_nm);
#endif

#if FRESNEL_HAS_F16
typedef struct fresnel_rgb_f16 {
    fresnel_f16 r, g, b;
} fresnel_rgb_f16;
typedef struct fresnel_film_node_f16 {
    fresnel_f16 a0[3];
    fresnel_f16 opd, decay;
    fresnel_f16 a_re[FRESNEL_FILM_POLES], a_im[FRESNEL_FILM_POLES], b_re[FRESNEL_FILM_POLES], b_im[FRESNEL_FILM_POLES];
    fresnel_f16 p_re[FRESNEL_FILM_POLES], p_im[FRESNEL_FILM_POLES], q_re[FRESNEL_FILM_POLES], q_im[FRESNEL_FILM_POLES];
} fresnel_film_node_f16;
typedef struct fresnel_film_f16 {
    fresnel_f16 freq[FRESNEL_FILM_POLES], damp[FRESNEL_FILM_POLES];
    fresnel_f16 weight[3][FRESNEL_FILM_POLES][2];
    fresnel_film_node_f16 node[FRESNEL_FILM_NODES];
} fresnel_film_f16;
fresnel_rgb_f16 fresnel_film_f16_rgb(const fresnel_film_f16 *m, fresnel_f16 c, fresnel_f16 d_nm);
#endif

#ifdef __cplusplus
}
#endif
#endif
