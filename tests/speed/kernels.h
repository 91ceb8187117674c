/* The timed kernels of `make bench` (tests/speed/speed.c): each evaluates one
 * channel of one material on n cosines and writes n results to an array, as
 * a renderer's loop over pixels or samples does. No kernel sums or reduces:
 * speed.c checks the outputs outside the timed region. */
#ifndef FRESNEL_SPEED_KERNELS_H
#define FRESNEL_SPEED_KERNELS_H

#include <stdint.h>

#include "fresnel.h"

typedef struct speed_ctx {
    float eta, kappa, f0;
    int32_t f0q;
    fresnel_conductor_prep prep;
    float eta3[3], kappa3[3]; /* the three channels of the RGB rows */
    fresnel_conductor_prep prep3[3];
    fresnel_rgb f0_3; /* their F0, for Schlick's RGB row */
    fresnel_rgb film_f0; /* the film row's gold at normal incidence, bare: the KHR peer's F0 */
    float film_eta[3], film_kappa[3]; /* gold's Gaussian-window eta, kappa: the polarised peer's */
    float lut16[16], lut32[32], lin16[16];
    uint16_t q16[16], q32[32], qlin16[16];
} speed_ctx;

/* c: binary32 cosines, cq: the same as Q1.15 codes; out (binary32), outq
 * (Q1.15) or outrgb (three channels per cosine) receives the results. */
typedef void (*speed_kernel)(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,
                             fresnel_rgb *outrgb, int n);

typedef struct speed_kernel_def {
    const char *name, *form; /* form: floor, call, inline or batch */
    speed_kernel fn;
    int q15;                 /* writes outq instead of out */
    int rgb;                 /* writes outrgb: three channels per cosine */
} speed_kernel_def;
extern const speed_kernel_def speed_kernels[];
extern const int speed_kernel_count;

void speed_ctx_init(speed_ctx *x, float eta, float kappa);

#endif
