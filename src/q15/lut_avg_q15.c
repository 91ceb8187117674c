/* Hemispherical averages of uint16_t lookup tables (fresnel_q15.h): the
 * weighted node sums of src/f32/lut_avg.c (whose header comment derives
 * the weights), exact, in integers.
 *
 * With N = n - 1 every weight is c_i / D: an integer polynomial c_i in i
 * (interior nodes) or N (end nodes) over one integer D for the table
 * (include/fresnel_lut_avg_sum.h). So the average in Q15 codes is the
 * ratio of two integers, sum_i c_i table[i] / D, of at most 88 and 68
 * bits, summed exactly in multi-word integers and divided once: the result is the
 * interpolant's integral rounded to the nearest code (halves up), for
 * every n and every table. The cubic's negative terms are summed apart. */
#include "internal.h"

#if FRESNEL_HAS_Q15

#include "fresnel_lut_avg_sum.h"

#define FRESNEL_I_AVG_N_MAX 32768

static fresnel_q15 fresnel_i_qavg_u16(const uint16_t *table, int n, int form)
{
    fresnel_i_big plus, minus, d;
    uint32_t top = FRESNEL_I_ONE_Q15, r, v;
    int16_t small[4];
    int i;
    if (n <= 1)
        return n == 1 ? table[0] : 0;
    fresnel_i_big_set(&plus, 0);
    fresnel_i_big_set(&minus, 0);
    fresnel_i_avg_den(&d, form, (uint32_t)n);
    for (i = 0; i < n; i++) {
        const int16_t *c = fresnel_i_avg_coef(form, (uint32_t)n, (uint32_t)i, &v, small);
        fresnel_i_avg_add(&plus, &minus, c, v, table[i]);
    }
    for (i = 0; i < n; i++)
        top = table[i] > top ? table[i] : top;
    if (fresnel_i_big_ge(&minus, &plus))
        return 0;
    fresnel_i_big_sub(&plus, &minus);
    /* (plus - minus) / D is below 2^16, the largest code: rounded to the
     * nearest (halves up) from floor(2 (plus - minus) / D) */
    fresnel_i_big_set(&minus, 0);
    fresnel_i_big_add_mul(&minus, &plus, 2u, 0, FRESNEL_I_LIMBS);
    r = (fresnel_i_big_div(&minus, &d) + 1u) >> 1;
    return (fresnel_q15)(r < top ? r : top);
}

static int fresnel_i_qavg_n(int n) { return n <= 0 ? 0 : (n > FRESNEL_I_AVG_N_MAX ? FRESNEL_I_AVG_N_MAX : n); }

fresnel_q15 fresnel_lut_avg_u16_q15(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16(table, fresnel_i_qavg_n(n), 0);
}
fresnel_q15 fresnel_lut_cubic_avg_u16_q15(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16(table, fresnel_i_qavg_n(n), 1);
}
fresnel_q15 fresnel_lut_linear_avg_u16_q15(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16(table, fresnel_i_qavg_n(n), 2);
}

static fresnel_rgb_q15 fresnel_i_qavg_u16_rgb(const uint16_t *table, int n, int form)
{
    n = fresnel_i_qavg_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_qavg_u16(table, n, form), fresnel_i_qavg_u16(table + n, n, form),
                      fresnel_i_qavg_u16(table + 2 * n, n, form));
}

fresnel_rgb_q15 fresnel_lut_avg_u16_q15_rgb(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16_rgb(table, n, 0);
}
fresnel_rgb_q15 fresnel_lut_cubic_avg_u16_q15_rgb(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16_rgb(table, n, 1);
}
fresnel_rgb_q15 fresnel_lut_linear_avg_u16_q15_rgb(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16_rgb(table, n, 2);
}

#else
typedef int fresnel_i_lut_avg_q15_disabled;
#endif
