/* The thin film from a single-file runtime in a file of the program that
 * does not define FRESNEL_IMPLEMENTATION (single_film_main.c does), with the
 * table from a generated scene header: scene_film.h, `fresnel gen` of a
 * scene named film with material cu, model thin-film and the one type
 * given by WITH_F32, WITH_Q15 or WITH_F16. With FRESNEL_LIBRARY the runtime
 * comes from include/ and libfresnel.a instead. tests/ports/test_single_file.sh
 * builds it both ways, as C99 and as C++17, and compares what it prints
 * bit for bit. */
#include <stdio.h>

#ifdef FRESNEL_LIBRARY
#include "fresnel_film.h"
#elif defined(WITH_F32)
#include "fresnel_single_f32.h"
#elif defined(WITH_Q15)
#include "fresnel_single_q15.h"
#elif defined(WITH_F16)
#include "fresnel_single_f16.h"
#endif
#include "scene_film.h"

void single_film_print(void);

/* cosines 0 to 1 in eighths, thicknesses 0 to 5000 nm */
static const float cosines[9] = {0.0f, 0.125f, 0.25f, 0.375f, 0.5f, 0.625f, 0.75f, 0.875f, 1.0f};
static const float thicknesses[6] = {0.0f, 75.0f, 310.0f, 640.0f, 1500.0f, 5000.0f};

void single_film_print(void)
{
    int i, j;
    for (i = 0; i < 9; i++) {
        for (j = 0; j < 6; j++) {
#ifdef WITH_F32
            const fresnel_film *m = &fresnel_film_cu_thin_film;
            fresnel_rgb r = fresnel_film_rgb(m, cosines[i], thicknesses[j]);
            printf("f32 %g %g: %a %a %a\n", cosines[i], thicknesses[j], r.r, r.g, r.b);
#endif
#ifdef WITH_Q15
            const fresnel_film_q15 *m = &fresnel_film_cu_thin_film_q15;
            fresnel_rgb_q15 r = fresnel_film_q15_rgb(m, (int32_t)(cosines[i] * FRESNEL_ONE_Q15),
                                                     (fresnel_q16)(thicknesses[j] * 65536.0f));
            printf("q15 %g %g: %u %u %u\n", cosines[i], thicknesses[j], r.r, r.g, r.b);
#endif
#if defined(WITH_F16) && FRESNEL_HAS_F16
            const fresnel_film_f16 *m = &fresnel_film_cu_thin_film_f16;
            fresnel_rgb_f16 r = fresnel_film_f16_rgb(m, (fresnel_f16)cosines[i], (fresnel_f16)thicknesses[j]);
            printf("f16 %g %g: %a %a %a\n", cosines[i], thicknesses[j], (double)r.r, (double)r.g, (double)r.b);
#elif defined(WITH_F16)
            /* no _Float16 here: the binary16 film builds to nothing */
            (void)cosines[i];
            (void)thicknesses[j];
#endif
        }
    }
}
