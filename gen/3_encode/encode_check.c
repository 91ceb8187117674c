/* Whether the Q1.15 constants of a material hold their values (encode.h:
 * encode_q15_fits): every value is checked against its C type and the range
 * the runtime documents (fresnel_q15.h, LAYOUT), because a wrapped or
 * clamped constant compiles into a silently wrong reflectance. */
#include <math.h>
#include <stdio.h>

#include "3_encode/encode.h"
#include "common/reference.h"

typedef struct q15_check {
    const char *id; /* the material */
    char *why;
    size_t size;
    int bad;
} q15_check;

/* v must be an integer in [lo, hi]; else the first such value is told. */
static void in_range(q15_check *k, double v, double lo, double hi, const char *type, const char *what,
                     const char *constant)
{
    if (k->bad || (v >= lo && v <= hi && v == floor(v)))
        return;
    snprintf(k->why, k->size, "%s %s: %s is %.17g, which does not fit %s [%.17g, %.17g]", k->id, constant, what, v,
             type, lo, hi);
    k->bad = 1;
}

/* The value a constant derives from must be finite (NaN or an infinity
 * would turn into an arbitrary code). */
static void finite(q15_check *k, double v, const char *what, const char *constant)
{
    if (!(v - v == 0.0))
        in_range(k, v, -1e300, 1e300, "a finite number", what, constant);
}

/* A qf as the LAYOUT defines it: {0, 0}, or m in [2^30, 2^31). */
static void qf(q15_check *k, fresnel_qf q, const char *what, const char *constant)
{
    if (q.m != 0 || q.e != 0)
        in_range(k, (double)q.m, 1073741824.0, 2147483647.0, "fresnel_qf.m [2^30, 2^31)", what, constant);
}

static void codes(q15_check *k, const double v[3], long hi, const char *what, const char *constant)
{
    int ch;
    for (ch = 0; ch < 3; ch++) {
        finite(k, v[ch], what, constant);
        in_range(k, v[ch] - v[ch] == 0.0 ? floor(v[ch] * 32768.0 + 0.5) : 0.0, 0.0, (double)hi,
                 hi == 32768 ? "Q1.15 [0, one]" : "Q1.15 [0, 2)", what, constant);
    }
}

static void ior(q15_check *k, double eta, double kappa, const fresnel_ior_prep_q15 *q, const char *constant)
{
    finite(k, eta, "eta", constant);
    finite(k, kappa, "kappa", constant);
    in_range(k, q->shift, 0.0, 30.0, "shift [0, 30]", "the ior's shift", constant);
    in_range(k, (double)q->a0 + ldexp(1.0, 30 - (q->shift < 0 || q->shift > 30 ? 0 : (int)q->shift)),
             -2147483647.0 - 1.0, 2147483647.0, "int32_t (a0 + 2^(30 - shift))", "the ior's a0", constant);
    in_range(k, q->a0_lo, -536870912.0, 536870912.0, "a0_lo [-2^29, 2^29]", "the ior's a0_lo", constant);
    qf(k, q->b, "the ior's b", constant);
    qf(k, q->n4, "the ior's n4", constant);
    qf(k, q->t1_inv, "the ior's t1_inv", constant);
    qf(k, q->inv_eta2, "the ior's inv_eta2", constant);
}

static void lsk(q15_check *k, const material_params *p, int comp, const fresnel_lsk_prep_q15 prep[3],
                const char *constant)
{
    int ch;
    for (ch = 0; ch < 3; ch++) {
        double f0 = floor(ref_f0_from_ior(p->eta_fit[ch], p->kappa_fit[ch]) * 1073741824.0 + 0.5);
        finite(k, p->eta_fit[ch], "eta", constant);
        finite(k, p->kappa_fit[ch], "kappa", constant);
        if (comp) {
            finite(k, p->lsk_a[ch], "the compensation weight a", constant);
            finite(k, p->lsk_alpha[ch], "the compensation exponent alpha", constant);
        }
        in_range(k, f0 == f0 ? f0 : -1.0, 0.0, 1073741824.0, "Q30 F0 [0, 2^30]", "LSK f0", constant);
        in_range(k, prep[ch].alpha, 0.0, FRESNEL_ALPHA_MAX_Q16, "Q16.16 alpha [0, 1000]", "LSK alpha", constant);
        qf(k, prep[ch].a, "LSK a", constant);
    }
}

/* The parameters held as codes (catalog/parameters.h), where read. */
#define CHECK_CODES_Q15_NONE(field, constant, what)
#define CHECK_CODES_Q15_CODE(field, constant, what) codes(&k, p->field, 65535, what, constant);
#define CHECK_CODES_Q15_CODE_ONE(field, constant, what) codes(&k, p->field, 32768, what, constant);
#define CHECK_CODES_Q15_CODE_HELD(field, constant, what) codes(&k, p->field, 65535, what, constant);
#define CHECK_CODES(field, count, group, constant, row, why, q15, q15_why)                                             \
    if (reads & (group)) {                                                                                             \
        CHECK_CODES_##q15(field, constant, q15_why)                                                                    \
    }

int encode_q15_fits(const material_params *p, const encoded_material *e, unsigned reads, unsigned q15_reads,
                    char *why, size_t size)
{
    q15_check k;
    int ch;
    k.id = p->info.id;
    k.why = why;
    k.size = size;
    k.bad = 0;
    DERIVED_PARAMETERS(CHECK_CODES)
    if (reads & MP_F82)
        for (ch = 0; ch < 3; ch++) {
            finite(&k, p->f0[ch], "F0", "f82_a_q12");
            finite(&k, p->f82[ch], "F82", "f82_a_q12");
            /* fresnel_f82_q15_fast documents |a_q12| <= 73000 */
            in_range(&k, (double)e->q_f82_a[ch], -73000.0, 73000.0, "a_q12 [-73000, 73000]", "F82's a", "f82_a_q12");
        }
    if (q15_reads & MQ_LSK)
        lsk(&k, p, 0, e->q_lsk, "lsk_q15");
    if (q15_reads & MQ_LSK_COMP)
        lsk(&k, p, 1, e->q_lsk_comp, "lsk_comp_q15");
    for (ch = 0; ch < 3; ch++) {
        if (q15_reads & MQ_IOR)
            ior(&k, p->eta_fit[ch], p->kappa_fit[ch], &e->q_ior[ETA_FIT][ch], "ior_q15");
        if (q15_reads & MQ_IOR_GAUSS)
            ior(&k, p->eta_gauss[ch], p->kappa_gauss[ch], &e->q_ior[ETA_GAUSS][ch], "ior_gaussian_q15");
        if (q15_reads & MQ_IOR_POINT)
            ior(&k, p->eta_point[ch], p->kappa_point[ch], &e->q_ior[ETA_POINT][ch], "ior_point_q15");
        if (q15_reads & MQ_NK) {
            finite(&k, p->eta_fit[ch], "eta", "nk_q15");
            finite(&k, p->kappa_fit[ch], "kappa", "nk_q15");
            qf(&k, e->q_nk[ch].n, "n", "nk_q15");
            qf(&k, e->q_nk[ch].nk2, "nk2", "nk_q15");
        }
    }
    if (q15_reads & MQ_CT)
        ior(&k, p->ct_eta, p->ct_kappa, &e->q_ct, "ct_ior_q15");
    return k.bad ? -1 : 0;
}
