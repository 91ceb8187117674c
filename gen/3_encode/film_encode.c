/* The thin-film constants per number type (film_encode.h). */
#include "3_encode/film_encode.h"

#include <complex.h>
#include <math.h>
#include <stddef.h>

#define J FRESNEL_FILM_POLES
#define NODES FRESNEL_FILM_NODES

void film_encode_f32(const film_model *m, fresnel_film *out)
{
    int j, k, ch;
    for (j = 0; j < J; j++) {
        out->freq[j] = (float)m->nu[j];
        out->damp[j] = (float)m->gamma[j];
        for (ch = 0; ch < 3; ch++) {
            out->weight[ch][j][0] = (float)(2.0 * creal(m->weight[ch][j]));
            out->weight[ch][j][1] = (float)(2.0 * cimag(m->weight[ch][j]));
        }
    }
    for (k = 0; k < NODES; k++) {
        fresnel_film_node *n = &out->node[k];
        for (ch = 0; ch < 3; ch++)
            n->a0[ch] = (float)m->a0[k][ch];
        n->opd = (float)m->opd[k];
        n->decay = (float)m->decay[k];
        for (j = 0; j < J; j++) {
            const double complex *v = m->term[k][j];
            n->a_re[j] = (float)creal(v[0]);
            n->a_im[j] = (float)cimag(v[0]);
            n->b_re[j] = (float)creal(v[1]);
            n->b_im[j] = (float)cimag(v[1]);
            n->p_re[j] = (float)creal(v[2]);
            n->p_im[j] = (float)cimag(v[2]);
            n->q_re[j] = (float)creal(v[3]);
            n->q_im[j] = (float)cimag(v[3]);
        }
    }
}

void film_decode_f32(const fresnel_film *in, film_model *m)
{
    int j, k, ch;
    for (j = 0; j < J; j++) {
        m->nu[j] = in->freq[j];
        m->gamma[j] = in->damp[j];
        for (ch = 0; ch < 3; ch++)
            m->weight[ch][j] = 0.5 * ref_complex(in->weight[ch][j][0], in->weight[ch][j][1]);
    }
    for (k = 0; k < NODES; k++) {
        const fresnel_film_node *n = &in->node[k];
        for (ch = 0; ch < 3; ch++)
            m->a0[k][ch] = n->a0[ch];
        m->opd[k] = n->opd;
        m->decay[k] = n->decay;
        for (j = 0; j < J; j++) {
            m->term[k][j][0] = ref_complex(n->a_re[j], n->a_im[j]);
            m->term[k][j][1] = ref_complex(n->b_re[j], n->b_im[j]);
            m->term[k][j][2] = ref_complex(n->p_re[j], n->p_im[j]);
            m->term[k][j][3] = ref_complex(n->q_re[j], n->q_im[j]);
        }
    }
}

/* 2 pi log2(e): octaves of decay per unit of 2 pi x gamma */
static const double octaves_per_neper_turn = 6.283185307179586476925 * 1.442695040888963407360;

static int q_code(double v, double scale, double lo, double hi, int32_t *out)
{
    double r = floor(v * scale + 0.5);
    if (!(r >= lo && r <= hi)) {
        *out = 0;
        return -1;
    }
    *out = (int32_t)r;
    return 0;
}

/* Q15 for A, B, Q; Q14 for P (|P| < 2) */
static const double term_scale[4] = {32768.0, 32768.0, 16384.0, 32768.0};

int film_encode_q15(const film_model *m, fresnel_film_q15 *out)
{
    int j, k, ch, bad = 0;
    int32_t v = 0, v32 = 0;
    for (j = 0; j < J; j++) {
        out->turn_nu[j] = (uint32_t)floor(m->nu[j] * 4294967296.0 + 0.5);
        out->turn_gamma[j] = (uint32_t)floor(m->gamma[j] * 4294967296.0 + 0.5);
        out->octave_nu[j] = (uint32_t)floor(octaves_per_neper_turn * m->nu[j] * 4294967296.0 + 0.5);
        out->octave_gamma[j] = (uint32_t)floor(octaves_per_neper_turn * m->gamma[j] * 4294967296.0 + 0.5);
        bad |= out->octave_nu[j] >= (1u << 27) || out->octave_gamma[j] >= (1u << 27);
        for (ch = 0; ch < 3; ch++) {
            bad |= q_code(2.0 * creal(m->weight[ch][j]), 4096.0, -32768.0, 32767.0, &v);
            out->weight[ch][j][0] = (int16_t)v;
            bad |= q_code(2.0 * cimag(m->weight[ch][j]), 4096.0, -32768.0, 32767.0, &v);
            out->weight[ch][j][1] = (int16_t)v;
        }
    }
    for (k = 0; k < NODES; k++) {
        fresnel_film_node_q15 *n = &out->node[k];
        for (ch = 0; ch < 3; ch++) {
            bad |= q_code(m->a0[k][ch], 16384.0, -32768.0, 32767.0, &v);
            n->a0[ch] = (int16_t)v;
        }
        bad |= q_code(m->opd[k], 4096.0, 0.0, 65535.0, &v);
        n->opd = (uint16_t)v;
        bad |= q_code(m->decay[k], 4096.0, 0.0, 65535.0, &v);
        n->decay = (uint16_t)v;
        for (j = 0; j < J; j++) {
            const double complex *t = m->term[k][j];
            int16_t *dst[8];
            int x;
            dst[0] = &n->a_re[j], dst[1] = &n->a_im[j], dst[2] = &n->b_re[j], dst[3] = &n->b_im[j];
            dst[4] = &n->p_re[j], dst[5] = &n->p_im[j], dst[6] = &n->q_re[j], dst[7] = &n->q_im[j];
            for (x = 0; x < 8; x++) {
                double v = x % 2 ? cimag(t[x / 2]) : creal(t[x / 2]);
                bad |= q_code(v, term_scale[x / 2], -32767.0, 32767.0, &v32);
                *dst[x] = (int16_t)v32;
            }
            /* the runtime's ranges: |A + B zeta| < 1 and |den| in [2^-10, 4) */
            bad |= !(cabs(t[0]) + cabs(t[1]) < 1.0);
            bad |= !(cabs(t[2]) < 2.0 && cabs(t[3]) < 1.0);
        }
    }
    return bad ? -1 : 0;
}

void film_decode_q15(const fresnel_film_q15 *in, film_model *m)
{
    int j, k, ch;
    for (j = 0; j < J; j++) {
        m->nu[j] = in->turn_nu[j] / 4294967296.0;
        m->gamma[j] = in->turn_gamma[j] / 4294967296.0;
        for (ch = 0; ch < 3; ch++)
            m->weight[ch][j] = 0.5 * ref_complex(in->weight[ch][j][0] / 4096.0, in->weight[ch][j][1] / 4096.0);
    }
    for (k = 0; k < NODES; k++) {
        const fresnel_film_node_q15 *n = &in->node[k];
        for (ch = 0; ch < 3; ch++)
            m->a0[k][ch] = n->a0[ch] / 16384.0;
        m->opd[k] = n->opd / 4096.0;
        m->decay[k] = n->decay / 4096.0;
        for (j = 0; j < J; j++) {
            m->term[k][j][0] = ref_complex(n->a_re[j] / term_scale[0], n->a_im[j] / term_scale[0]);
            m->term[k][j][1] = ref_complex(n->b_re[j] / term_scale[1], n->b_im[j] / term_scale[1]);
            m->term[k][j][2] = ref_complex(n->p_re[j] / term_scale[2], n->p_im[j] / term_scale[2]);
            m->term[k][j][3] = ref_complex(n->q_re[j] / term_scale[3], n->q_im[j] / term_scale[3]);
        }
    }
}

#if FRESNEL_HAS_F16
/* The binary32 constants rounded to half, field by field (the layouts are
 * the same). */
void film_encode_f16(const film_model *m, fresnel_film_f16 *out)
{
    fresnel_film f;
    const float *src;
    fresnel_f16 *dst = (fresnel_f16 *)out;
    size_t i, n = sizeof f / sizeof(float);
    typedef char same_layout[sizeof(fresnel_film_f16) * 2 == sizeof(fresnel_film) ? 1 : -1];
    (void)sizeof(same_layout);
    film_encode_f32(m, &f);
    src = (const float *)&f;
    for (i = 0; i < n; i++)
        dst[i] = (fresnel_f16)src[i];
}

void film_decode_f16(const fresnel_film_f16 *in, film_model *m)
{
    fresnel_film f;
    float *dst = (float *)&f;
    const fresnel_f16 *src = (const fresnel_f16 *)in;
    size_t i, n = sizeof f / sizeof(float);
    for (i = 0; i < n; i++)
        dst[i] = (float)src[i];
    film_decode_f32(&f, m);
}
#endif
