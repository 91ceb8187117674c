/* A program as a game or firmware writes it against the single-file runtimes
 * (ports/single.sh): WITH_F32, WITH_Q15 and WITH_F16 pick the types, which
 * come from ports/single/fresnel_single_<type>.h, or, with FRESNEL_LIBRARY, from include/
 * and libfresnel.a. tests/ports/test_single_file.sh builds it both ways, as C99
 * and (a unity build that includes the .c files) as C++17, and compares the
 * printed results bit for bit. single_file_impl.c is the one file that
 * defines FRESNEL_IMPLEMENTATION. */
#include <stdio.h>

#ifdef FRESNEL_LIBRARY
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_fixed_fast.h"
#else
#ifdef WITH_F32
#include "fresnel_single_f32.h"
#endif
#ifdef WITH_Q15
#include "fresnel_single_q15.h"
#endif
#ifdef WITH_F16
#include "fresnel_single_f16.h"
#endif
#endif

#ifdef WITH_F32
/* cosines from 0 to 1 and beyond both ends: 37 of them, so the batches take
 * their vector loops and their remainder */
static float cosine(int i) { return (float)(i - 2) / 32.0f; }

static void print_f32(void)
{
    const fresnel_rgb f0 = {0.95f, 0.64f, 0.54f}, f82 = {0.93f, 0.75f, 0.71f};
    const fresnel_rgb eta = {0.24f, 1.01f, 1.24f}, kappa = {3.63f, 2.58f, 2.39f};
    const float table[3 * 5] = {0.95f, 0.95f, 0.94f, 0.9f, 1.0f, 0.64f, 0.64f, 0.65f, 0.7f, 1.0f,
                                0.54f, 0.54f, 0.56f, 0.62f, 1.0f};
    fresnel_conductor_prep prep[3];
    float c[37], out[37];
    fresnel_rgb rgb[37];
    int i;
    prep[0] = fresnel_conductor_prepare(eta.r, kappa.r);
    prep[1] = fresnel_conductor_prepare(eta.g, kappa.g);
    prep[2] = fresnel_conductor_prepare(eta.b, kappa.b);
    for (i = 0; i < 37; i++)
        c[i] = cosine(i);
    fresnel_conductor_batch(&prep[0], c, out, 37);
    fresnel_conductor_rgb_batch(prep, c, rgb, 37);
    for (i = 0; i < 37; i++) {
        const fresnel_rgb f = fresnel_f82_rgb(f0, f82, c[i]);
        const fresnel_rgb l = fresnel_lut_cubic_rgb(table, 5, c[i]);
        printf("f32 %a %a %a %a %a %a %a %a %a %a %a %a %a %a %a\n", (double)c[i], (double)fresnel_schlick(0.04f, c[i]),
               (double)fresnel_schlick_gen(0.3f, 0.9f, 3.5f, c[i]), (double)f.g,
               (double)fresnel_lsk_comp(1.5f, 2.0f, 0.8f, 5.0f, c[i]), (double)fresnel_gulbrandsen(0.9f, 0.6f, c[i]),
               (double)fresnel_approx_conductor(0.2f, 3.0f, c[i]), (double)fresnel_cook_torrance(0.9f, 0.2f, 3.0f, c[i]),
               (double)fresnel_conductor(eta.r, kappa.r, c[i]), (double)fresnel_dielectric(1.0f / 1.33f, c[i]),
               (double)out[i], (double)rgb[i].r, (double)rgb[i].b, (double)l.b,
               (double)fresnel_schlick_internal(0.04f, 1.5f, c[i]));
    }
    printf("f32 avg %a %a\n", (double)fresnel_f82_avg(0.9f, 0.8f), (double)fresnel_lut_cubic_avg(table, 5));
}
#endif

#ifdef WITH_Q15
static void print_q15(void)
{
    static const uint16_t table[5] = {31130, 31130, 30800, 29500, 32768};
    const fresnel_ior_prep_q15 cu = fresnel_ior_prepare_q15(15729, 237896); /* 0.24, 3.63 in Q16.16 */
    const fresnel_nk_prep_q15 nk = fresnel_nk_prepare_q15(15729, 237896);
    int32_t c;
    for (c = -1024; c <= 32768 + 1024; c += 1024)
        printf("q15 %d %d %d %d %d %d %d %d %d\n", (int)c, (int)fresnel_schlick_q15(1311, c),
               (int)fresnel_f82_q15(31130, 30474, c), (int)fresnel_conductor_q15(&cu, c),
               (int)fresnel_approx_conductor_q15(&nk, c), (int)fresnel_lut_cubic_u16_q15(table, 5, c),
               (int)fresnel_gulbrandsen_q15(29491, 19661, c), (int)fresnel_schlick_q15_fast(1311, c < 0 ? 0 : c),
               (int)fresnel_lut_u16_q15_fast(table, 5, c));
    printf("q15 avg %d\n", (int)fresnel_lut_cubic_avg_u16_q15(table, 5));
}
#endif

#if defined(WITH_F16) && FRESNEL_HAS_F16
static void print_f16(void)
{
    int i;
    for (i = 0; i <= 16; i++) {
        const fresnel_f16 c = (fresnel_f16)((float)i / 16.0f);
        printf("f16 %a %a %a\n", (double)fresnel_schlick_f16((fresnel_f16)0.04f, c),
               (double)fresnel_conductor_f16((fresnel_f16)0.24f, (fresnel_f16)3.63f, c),
               (double)fresnel_f82_f16((fresnel_f16)0.9f, (fresnel_f16)0.8f, c));
    }
}
#endif

int main(void)
{
#ifdef WITH_F32
    print_f32();
#endif
#ifdef WITH_Q15
    print_q15();
#endif
#if defined(WITH_F16) && FRESNEL_HAS_F16
    print_f16();
#endif
    return 0;
}
