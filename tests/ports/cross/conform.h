/* Data of the cross-target conformance and instruction-count programs:
 * the material set of tests/runtime/q15/test_q15_bounds.c, prepared on the host
 * exactly as that test prepares it (model_q15_from_params), written out as
 * C by tests/ports/cross/conform_gen.c. */
#ifndef FRESNEL_CONFORM_H
#define FRESNEL_CONFORM_H

#include <stdint.h>

#include "fresnel_film.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"

typedef struct conform_material {
    int32_t f0, f82, f90, r, g; /* Q15 codes */
    fresnel_q16 p;
    fresnel_ior_prep_q15 ior, dior;
    fresnel_nk_prep_q15 nk, gnk;
    fresnel_lsk_prep_q15 lsk;
    fresnel_q16 eta, kappa; /* Q16.16, for the run-time *_prepare functions */
    int32_t f82_a;          /* fresnel_f82_q15_fast's a_q12 */
    fresnel_conductor_prep_q15_fast cfast; /* fresnel_conductor_q15_fast's constants */
} conform_material;

extern const conform_material conform_materials[];
extern const int conform_material_count;
extern const int conform_bench_material; /* index of copper at 550 nm */
/* The instruction and cycle counts' materials (copper, aluminium -- a high
 * kappa -- and BK7 -- kappa ~ 0 -- at 550 nm) and cosine sets (Q15 codes:
 * uniform in c, uniform in the angle, near grazing incidence). */
#define CONFORM_BENCH_MATERIALS 3
#define CONFORM_BENCH_SETS 3
#define CONFORM_BENCH_CODES 17
extern const int conform_bench_materials[CONFORM_BENCH_MATERIALS];
extern const char *const conform_bench_material_names[CONFORM_BENCH_MATERIALS];
extern const int32_t conform_bench_cos[CONFORM_BENCH_SETS][CONFORM_BENCH_CODES];
extern const char *const conform_bench_set_names[CONFORM_BENCH_SETS];
/* copper at 550 nm for the binary32 and binary16 benchmarks: eta, kappa,
 * F0, F82, LSK a, alpha, Gulbrandsen r, g */
extern const float conform_bench_float[8];

/* One curve (gold at 550 nm, 64 nodes, nodes uniform in sqrt(c) and in c)
 * in every LUT encoding. */
#define CONFORM_LUT_N 64
extern const uint16_t conform_lut_u16[2][CONFORM_LUT_N];
extern const uint8_t conform_lut_u8[2][CONFORM_LUT_N];
extern const int16_t conform_lut_s16[2][CONFORM_LUT_N];
extern const int8_t conform_lut_s8[2][CONFORM_LUT_N];
extern const int conform_lut_frac16, conform_lut_frac8;
extern const int32_t conform_lut_f0;

/* A thin film's tables (fresnel_film.h): a 2.5 film on gold in air, sRGB. */
extern const fresnel_film_q15 conform_film;
#if FRESNEL_HAS_FLOAT
extern const fresnel_film conform_film_f32;
#endif

#endif
