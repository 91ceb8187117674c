/* The thin-film constants per number type (film_encode.h). */
#include "3_encode/film_encode.h"

#include <complex.h>
#include <math.h>

#define J FRESNEL_FILM_POLES
#define NODES FRESNEL_FILM_NODES

void film_encode_f32(const film_model *m, fresnel_film *out)
{
    int j, k, ch, pol;
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
        for (j = 0; j < J; j++)
            for (pol = 0; pol < 2; pol++) {
                n->kappa_re[pol * J + j] = (float)creal(m->kappa[k][j][pol]);
                n->kappa_im[pol * J + j] = (float)cimag(m->kappa[k][j][pol]);
                n->q_re[pol * J + j] = (float)creal(m->q[k][j][pol]);
                n->q_im[pol * J + j] = (float)cimag(m->q[k][j][pol]);
            }
    }
}

void film_decode_f32(const fresnel_film *in, film_model *m)
{
    int j, k, ch, pol;
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
        for (j = 0; j < J; j++)
            for (pol = 0; pol < 2; pol++) {
                m->kappa[k][j][pol] = ref_complex(n->kappa_re[pol * J + j], n->kappa_im[pol * J + j]);
                m->q[k][j][pol] = ref_complex(n->q_re[pol * J + j], n->q_im[pol * J + j]);
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

int film_encode_q15(const film_model *m, fresnel_film_q15 *out)
{
    int j, k, ch, pol, bad = 0;
    int32_t v = 0;
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
        for (j = 0; j < J; j++)
            for (pol = 0; pol < 2; pol++) {
                double complex kappa = m->kappa[k][j][pol], q = m->q[k][j][pol];
                int l = pol * J + j;
                bad |= !(cabs(kappa) < 1.0 && cabs(kappa) <= 256.0 * (1.0 - cabs(q)));
                bad |= q_code(creal(kappa), 32768.0, -32767.0, 32767.0, &v);
                n->kappa_re[l] = (int16_t)v;
                bad |= q_code(cimag(kappa), 32768.0, -32767.0, 32767.0, &v);
                n->kappa_im[l] = (int16_t)v;
                bad |= q_code(creal(q), 32768.0, -32767.0, 32767.0, &v);
                n->q_re[l] = (int16_t)v;
                bad |= q_code(cimag(q), 32768.0, -32767.0, 32767.0, &v);
                n->q_im[l] = (int16_t)v;
            }
    }
    return bad ? -1 : 0;
}

void film_decode_q15(const fresnel_film_q15 *in, film_model *m)
{
    int j, k, ch, pol;
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
        for (j = 0; j < J; j++)
            for (pol = 0; pol < 2; pol++) {
                int l = pol * J + j;
                m->kappa[k][j][pol] = ref_complex(n->kappa_re[l] / 32768.0, n->kappa_im[l] / 32768.0);
                m->q[k][j][pol] = ref_complex(n->q_re[l] / 32768.0, n->q_im[l] / 32768.0);
            }
    }
}
