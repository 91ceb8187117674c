/* Measurements of the thin-film runtime for tests/cross/film_count.sh
 * (host side):
 *   film_bench table   the Q1.15 table of a 2.5 film on gold (sRGB) as C,
 *                      for the Cortex-M0 build (tests/cross/film_m0.c)
 *   film_bench speed   ns per RGB evaluation of fresnel_film_rgb and
 *                      fresnel_schlick_rgb, interleaved rounds in one
 *                      process, median and quartiles of the ratio */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "2_derive/derive.h"
#include "2_derive/film_fit.h"
#include "3_encode/film_encode.h"

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e9 + t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

#define ROUNDS 41
#define CALLS 20000

int main(int argc, char **argv)
{
    gen_context *g = malloc(sizeof *g);
    film_model *m = malloc(sizeof *m);
    spectrum *s = malloc(sizeof *s);
    fresnel_film *f32 = malloc(sizeof *f32);
    fresnel_film_q15 *q15 = malloc(sizeof *q15);
    film_stack f;
    if (argc != 2 || !g || !m || !s || !f32 || !q15 || gen_context_load(data_dir(NULL), "srgb", g) ||
        spectrum_load(data_dir(NULL), "au", s) || film_fit_poles(&g->cm, &g->cs, m, NULL)) {
        fprintf(stderr, "usage: film_bench table|speed (data/ must load)\n");
        return 2;
    }
    f.n1 = 1.0;
    f.film = NULL;
    f.film_n = 2.5;
    f.substrate = s;
    if (film_fit_material(&f, &g->cm, &g->cs, m) || film_encode_q15(m, q15))
        return 1;
    film_encode_f32(m, f32);
    if (!strcmp(argv[1], "table")) {
        const unsigned char *b = (const unsigned char *)q15;
        size_t i;
        printf("#include \"fresnel_film.h\"\n/* gold under a 2.5 film, sRGB (tests/cross/film_bench.c) */\n");
        printf("static const union {\n    unsigned char b[%u];\n    fresnel_film_q15 f;\n} film_table = {{", (unsigned)sizeof *q15);
        for (i = 0; i < sizeof *q15; i++)
            printf("%s%u,", i % 24 ? "" : "\n    ", b[i]);
        printf("\n}};\ntypedef char film_table_layout[sizeof(fresnel_film_q15) == %u ? 1 : -1];\n", (unsigned)sizeof *q15);
        printf("const fresnel_film_q15 *const film_gold = &film_table.f;\n");
        return 0;
    }
    if (!strcmp(argv[1], "speed")) {
        double film[ROUNDS], schlick[ROUNDS], ratio[ROUNDS];
        fresnel_rgb f0 = {0.9f, 0.6f, 0.3f};
        volatile float sink = 0.0f;
        int r, i;
        for (r = 0; r < ROUNDS; r++) {
            double t0, t1, t2;
            float acc = 0.0f;
            t0 = now_ns();
            for (i = 0; i < CALLS; i++) {
                fresnel_rgb o = fresnel_film_rgb(f32, (float)(i & 1023) * (1.0f / 1023.0f), (float)(i % 1000));
                acc += o.r + o.g + o.b;
            }
            t1 = now_ns();
            for (i = 0; i < CALLS; i++) {
                fresnel_rgb o = fresnel_schlick_rgb(f0, (float)(i & 1023) * (1.0f / 1023.0f));
                acc += o.r + o.g + o.b;
            }
            t2 = now_ns();
            sink += acc;
            film[r] = (t1 - t0) / CALLS;
            schlick[r] = (t2 - t1) / CALLS;
            ratio[r] = film[r] / schlick[r];
        }
        qsort(film, ROUNDS, sizeof film[0], cmp);
        qsort(schlick, ROUNDS, sizeof schlick[0], cmp);
        qsort(ratio, ROUNDS, sizeof ratio[0], cmp);
        printf("fresnel_film_rgb %.1f ns (fastest round %.1f), fresnel_schlick_rgb %.1f ns (fastest %.1f) per RGB "
               "evaluation; ratio median %.1f (quartiles %.1f-%.1f) over %d interleaved rounds\n",
               film[ROUNDS / 2], film[0], schlick[ROUNDS / 2], schlick[0], ratio[ROUNDS / 2], ratio[ROUNDS / 4],
               ratio[3 * ROUNDS / 4], ROUNDS);
        return 0;
    }
    fprintf(stderr, "usage: film_bench table|speed\n");
    return 2;
}
