/* One model of one type per build, for `make size` (ports/cross.sh): the
 * entry function calls the model selected by PROBE (fixed point),
 * PROBE_F32 (binary32, fresnel.h) or PROBE_F16 (binary16, fresnel_f16.h)
 * on volatile inputs, and --gc-sections keeps only what that call needs.
 * PROBE 0 calls nothing: the baseline subtracted from every row. */
#include <stdint.h>

#include "fresnel_config.h"

volatile int32_t probe_i = 1311, probe_c = 20000;
volatile uint32_t probe_out;
void probe(void);

#if defined(PROBE)
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#ifndef SCENE_N
#define SCENE_N 1
#endif
static const fresnel_ior_prep_q15 ior = {-1051966000, 12345, 3, {1073741824u, -28}, {1073741824u, -21}, {1073741824u, -29},
                                    {1073741824u, -33}};
static const fresnel_nk_prep_q15 nk = {{1073741824u, -30}, {1073741824u, -27}};
static const fresnel_lsk_prep_q15 lsk = {700000000u, {1073741824u, -29}, 7 << 16};
static const uint16_t t16[8] = {32768, 30000, 28000, 27000, 26500, 26200, 26100, 26000};
static const int8_t t8[8] = {0, 10, 20, 30, 20, 10, 5, 0};
/* gold at 550 nm (the constants tests/ports/cross/conform_gen.c writes) in each of
 * three channels, for the conductor's fast path and its library call; read
 * through volatile pointers, so that nothing of them is folded into the
 * code */
#define PROBE_AU_FAST {-1860561660, -17564, 2, 562919072, 0, 34358, 14, 0}
#define PROBE_AU_IOR {-1860561660, -287761152, 2, {1125838144, -29}, {1327946657, -25}, {1287789325, -28}, {1492115577, -28}}
static const fresnel_conductor_prep_q15_fast cfast[3] = {PROBE_AU_FAST, PROBE_AU_FAST, PROBE_AU_FAST};
static const fresnel_conductor_prep_q15_fast *volatile cfast_at = cfast;
static const fresnel_ior_prep_q15 ior3[3] = {PROBE_AU_IOR, PROBE_AU_IOR, PROBE_AU_IOR};
static const fresnel_ior_prep_q15 *volatile ior_at = ior3;
#ifndef PROBE_N
#define PROBE_N 64
#endif
void probe(void)
{
    int32_t c = probe_c, f = probe_i;
#if PROBE == 1
    probe_out = fresnel_schlick_q15(f, c);
#elif PROBE == 2
    probe_out = fresnel_schlick_gen_q15(f, 32768, f * 64, c);
#elif PROBE == 3
    probe_out = fresnel_lsk_q15(&lsk, c);
#elif PROBE == 4
    probe_out = fresnel_lsk_comp_q15(&lsk, c);
#elif PROBE == 5
    probe_out = fresnel_f82_q15(f, f + 100, c);
#elif PROBE == 6
    probe_out = fresnel_gulbrandsen_q15(f, f + 100, c);
#elif PROBE == 7
    probe_out = fresnel_approx_conductor_q15(&nk, c);
#elif PROBE == 8
    probe_out = fresnel_cook_torrance_q15(f, &ior, c);
#elif PROBE == 9
    probe_out = fresnel_conductor_q15(&ior, c);
#elif PROBE == 10
    probe_out = fresnel_dielectric_q15(&ior, c);
#elif PROBE == 11
    probe_out = fresnel_schlick_internal_q15(f, &ior, c);
#elif PROBE == 12
    probe_out = fresnel_lut_u16_q15(t16, 8, c);
#elif PROBE == 13
    probe_out = fresnel_lut_residual_s8_q15(f, t8, 8, 12, c);
#elif PROBE == 14
    {
        fresnel_ior_prep_q15 out;
        out = fresnel_ior_prepare_q15(f * 4, c * 4);
        probe_out = (uint32_t)out.a0;
    }
#elif PROBE == 16
    probe_out = fresnel_schlick_q15_fast(f, c);
#elif PROBE == 17
    probe_out = fresnel_f82_q15_fast(f, f + 100, c); /* f + 100 stands for a_q12 */
#elif PROBE == 18
    probe_out = fresnel_lut_u16_q15_fast(t16, 8, c);
#elif PROBE == 21
    probe_out = fresnel_lut_pl_u16_q15_fast(t16, 8, c);
#elif PROBE == 19
    {
        /* a Schlick-only fixed scene of SCENE_N materials (F0 per material) */
        static const fresnel_q15 scene_f0[SCENE_N] = {25937};
        probe_out = fresnel_schlick_q15_fast(scene_f0[(uint32_t)f % SCENE_N], c);
    }
#elif PROBE == 20
    {
        /* the same scene in RGB: an F0 triple per material, as fresnel gen emits it */
        static const fresnel_rgb_q15 scene_f0[SCENE_N] = {{31784, 25937, 11907}};
        fresnel_rgb_q15 r = fresnel_schlick_q15_rgb_fast(scene_f0[(uint32_t)f % SCENE_N], c);
        probe_out = (fresnel_q15)(r.r ^ r.g ^ r.b);
    }
#elif PROBE == 15
    probe_out = fresnel_schlick_q15_rgb((fresnel_rgb_q15){(fresnel_q15)f, (fresnel_q15)(f + 1), (fresnel_q15)(f + 2)}, c).g;
#elif PROBE == 22
    probe_out = fresnel_conductor_q15_fast(cfast_at, c);
#elif PROBE == 23
    {
        fresnel_rgb_q15 r = fresnel_conductor_q15_rgb_fast(cfast_at, c);
        probe_out = (fresnel_q15)(r.r ^ r.g ^ r.b);
    }
#elif PROBE == 24
    {
        fresnel_rgb_q15 r = fresnel_conductor_q15_rgb(ior_at, c);
        probe_out = (fresnel_q15)(r.r ^ r.g ^ r.b);
    }
#elif PROBE >= 30 && PROBE < 50
    {
        /* the batches: a scanline of PROBE_N cosines */
        static fresnel_q15 in[PROBE_N], out[PROBE_N];
        static fresnel_rgb_q15 out3[PROBE_N];
        const fresnel_rgb_q15 f3 = {(fresnel_q15)f, (fresnel_q15)(f + 1), (fresnel_q15)(f + 2)};
        in[0] = (fresnel_q15)c;
#if PROBE == 30
        fresnel_schlick_q15_batch(f, in, out, PROBE_N);
#elif PROBE == 31
        fresnel_f82_q15_batch(f, f + 100, in, out, PROBE_N);
#elif PROBE == 32
        fresnel_lut_u16_q15_batch(t16, 8, in, out, PROBE_N);
#elif PROBE == 33
        fresnel_lut_linear_u16_q15_batch(t16, 8, in, out, PROBE_N);
#elif PROBE == 34
        fresnel_lut_cubic_u16_q15_batch(t16, 8, in, out, PROBE_N);
#elif PROBE == 35
        fresnel_schlick_q15_rgb_batch(f3, in, out3, PROBE_N);
#elif PROBE == 36
        fresnel_f82_q15_rgb_batch(f3, f3, in, out3, PROBE_N);
#elif PROBE == 37
        fresnel_schlick_gen_q15_batch(f, 32768, f * 64, in, out, PROBE_N);
#endif
        probe_out = (uint32_t)out[1] ^ out3[1].g;
        (void)f3;
    }
#endif
    (void)c, (void)f, (void)ior, (void)nk, (void)lsk, (void)t16, (void)t8, (void)cfast_at, (void)ior_at;
}

#elif defined(PROBE_F32)
#include "fresnel.h"
volatile float probe_x = 0.5f, probe_y = 0.04f, probe_r;
static const float table[8] = {1.0f, 0.9f, 0.85f, 0.82f, 0.81f, 0.8f, 0.8f, 0.8f};
void probe(void)
{
    float c = probe_x, f = probe_y;
    float r;
#if PROBE_F32 == 1
    r = fresnel_schlick(f, c);
#elif PROBE_F32 == 2
    r = fresnel_schlick_gen(f, 1.0f, 3.7f, c);
#elif PROBE_F32 == 3
    r = fresnel_lsk(f * 10.0f, 3.0f, c);
#elif PROBE_F32 == 4
    r = fresnel_lsk_comp(f * 10.0f, 3.0f, 1.0f, 7.0f, c);
#elif PROBE_F32 == 5
    r = fresnel_f82(f, f + 0.1f, c);
#elif PROBE_F32 == 6
    r = fresnel_gulbrandsen(f, f + 0.1f, c);
#elif PROBE_F32 == 7
    r = fresnel_approx_conductor(f * 10.0f, 3.0f, c);
#elif PROBE_F32 == 8
    r = fresnel_cook_torrance(f, f * 10.0f, 3.0f, c);
#elif PROBE_F32 == 9
    r = fresnel_conductor(f * 10.0f, 3.0f, c);
#elif PROBE_F32 == 10
    r = fresnel_dielectric(f * 10.0f, c);
#elif PROBE_F32 == 11
    r = fresnel_schlick_internal(f, f * 10.0f, c);
#elif PROBE_F32 == 12
    r = fresnel_lut(table, 8, c);
#elif PROBE_F32 == 13
    r = fresnel_lut_residual(f, table, 8, c);
#else
    r = c; /* no arithmetic: the baseline pulls in no soft-float helper */
#endif
    (void)c, (void)f, (void)table;
    probe_r = r;
}

#elif defined(PROBE_F16)
#include "fresnel_f16.h"
#if FRESNEL_HAS_F16
volatile fresnel_f16 probe_x, probe_y;
static fresnel_f16 table[8];
void probe(void)
{
    fresnel_f16 c = probe_x, f = probe_y, r;
#if PROBE_F16 == 1
    r = fresnel_schlick_f16(f, c);
#elif PROBE_F16 == 2
    r = fresnel_schlick_gen_f16(f, c, f, c);
#elif PROBE_F16 == 3
    r = fresnel_lsk_f16(f, c, c);
#elif PROBE_F16 == 4
    r = fresnel_lsk_comp_f16(f, c, f, c, c);
#elif PROBE_F16 == 5
    r = fresnel_f82_f16(f, c, c);
#elif PROBE_F16 == 6
    r = fresnel_gulbrandsen_f16(f, f, c);
#elif PROBE_F16 == 7
    r = fresnel_approx_conductor_f16(f, c, c);
#elif PROBE_F16 == 8
    r = fresnel_cook_torrance_f16(f, f, c, c);
#elif PROBE_F16 == 9
    r = fresnel_conductor_f16(f, c, c);
#elif PROBE_F16 == 10
    r = fresnel_dielectric_f16(f, c);
#elif PROBE_F16 == 11
    r = fresnel_schlick_internal_f16(f, f, c);
#elif PROBE_F16 == 12
    r = fresnel_lut_f16(table, 8, c);
#elif PROBE_F16 == 13
    r = fresnel_lut_residual_f16(f, table, 8, c);
#else
    r = c;
#endif
    (void)c, (void)f, (void)table;
    probe_x = r;
}
#else
void probe(void) {}
#endif
#endif
