/* Fixed-point conformance on a target: every model of tests/ports/cross/q15_models.h
 * over the material set and the cos codes of next_code, the
 * results folded into one FNV-1a hash per model, and the run-time
 * preparation from Q16.16 of every material. The same program built for the
 * host prints the hashes the target must reproduce bit for bit
 * (tests/ports/test_cross.sh); the host's results are the ones
 * tests/runtime/q15/test_q15_bounds.c holds to the double reference. No float, no
 * libc: port.h only. */
#include "q15_models.h"
#include "port.h"

#ifndef CONFORM_STRIDE
#define CONFORM_STRIDE 1
#endif
#ifndef CONFORM_OFFSET
#define CONFORM_OFFSET 0
#endif
/* Every code within CONFORM_EDGE of 0 and of one is always run. */
#define CONFORM_EDGE 64

/* The cos code after c: every code within CONFORM_EDGE of 0 and one, and
 * between them those equal to CONFORM_OFFSET modulo CONFORM_STRIDE (every
 * code for stride 1). */
static int32_t next_code(int32_t c)
{
    uint32_t n = (uint32_t)c + 1u;
    if (n > CONFORM_EDGE && n < 32768u - CONFORM_EDGE) {
        n += (CONFORM_OFFSET + CONFORM_STRIDE - n % CONFORM_STRIDE) % CONFORM_STRIDE;
        if (n > 32768u - CONFORM_EDGE)
            n = 32768u - CONFORM_EDGE;
    }
    return (int32_t)n;
}

static uint32_t fnv(uint32_t h, uint32_t v)
{
    h = (h ^ (v & 0xffu)) * 16777619u;
    return (h ^ (v >> 8)) * 16777619u;
}

static uint32_t fnv_qf(uint32_t h, fresnel_qf q) { return fnv(fnv(fnv(h, q.m), q.m >> 16), (uint32_t)q.e); }

static void report(const char *name, uint32_t h)
{
    port_puts(name);
    port_puts(" ");
    port_put_hex(h);
    port_puts("\n");
}

int main(void)
{
    int i, k;
    uint32_t h;
    port_puts("conformance: ");
    port_put_dec((uint32_t)conform_material_count);
    port_puts(" materials, stride ");
    port_put_dec(CONFORM_STRIDE);
    port_puts(" from ");
    port_put_dec(CONFORM_OFFSET);
    port_puts("\n");
    for (i = 0; i < FIXED_MODEL_COUNT; i++) {
        h = 2166136261u;
        for (k = 0; k < (fixed_models[i].per_material ? conform_material_count : 1); k++) {
            int32_t c;
            for (c = 0; c <= 32768; c = next_code(c))
                h = fnv(h, fixed_models[i].fn(&conform_materials[k], c));
        }
        report(fixed_models[i].name, h);
    }
    /* the batches: the same codes in runs of 1 to BATCH_MAX - 3 (every
     * tail of a four-lane body), folded in the same order */
    batch_tables_init();
    for (i = 0; i < BATCH_MODEL_COUNT; i++) {
        int count = batch_models[i].per_material == 0 ? 1
                    : batch_models[i].per_material == 1 ? conform_material_count : conform_material_count - 2;
        h = 2166136261u;
        for (k = 0; k < count; k++) {
            fresnel_q15 c[BATCH_MAX], out[BATCH_MAX];
            int32_t code = 0;
            int len = 1, j;
            while (code <= 32768) {
                int n = 0;
                while (n < len && code <= 32768) {
                    c[n++] = (fresnel_q15)code;
                    code = next_code(code);
                }
                batch_models[i].fn(&conform_materials[k], c, out, n);
                for (j = 0; j < n; j++)
                    h = fnv(h, out[j]);
                len = len == BATCH_MAX - 3 ? 1 : len + 1; /* no remainder: the Cortex-M0 has no divide */
            }
        }
        report(batch_models[i].name, h);
    }
    /* run-time preparation from Q16.16, and a conductor evaluated from it */
    h = 2166136261u;
    for (k = 0; k < conform_material_count; k++) {
        const conform_material *m = &conform_materials[k];
        fresnel_ior_prep_q15 ior;
        fresnel_nk_prep_q15 nk;
        fresnel_lsk_prep_q15 lsk;
        fresnel_q15 r, g;
        int32_t c;
        ior = fresnel_ior_prepare_q15(m->eta, m->kappa);
        nk = fresnel_nk_prepare_q15(m->eta, m->kappa);
        lsk = fresnel_lsk_prepare_q15(m->eta, m->kappa, 65536, 7 << 16);
        { fresnel_rg_q15 rg_ = fresnel_gulbrandsen_rg_q15(m->eta, m->kappa); r = rg_.r; g = rg_.g; }
        h = fnv(fnv(fnv(h, (uint32_t)ior.a0), (uint32_t)ior.a0 >> 16), (uint32_t)ior.shift);
        h = fnv(fnv(h, (uint32_t)ior.a0_lo), (uint32_t)ior.a0_lo >> 16);
        h = fnv_qf(fnv_qf(fnv_qf(fnv_qf(h, ior.b), ior.n4), ior.t1_inv), ior.inv_eta2);
        h = fnv_qf(fnv_qf(h, nk.n), nk.nk2);
        h = fnv(fnv(fnv(h, lsk.f0), lsk.f0 >> 16), (uint32_t)lsk.alpha);
        h = fnv(fnv(fnv_qf(h, lsk.a), r), g);
        h = fnv(h, fresnel_f0_from_ior_q15(m->eta, m->kappa));
        for (c = 97 * CONFORM_OFFSET; c <= 32768; c += 97 * CONFORM_STRIDE)
            h = fnv(h, fresnel_conductor_q15(&ior, c));
    }
    report("prepare-q16", h);
    h = 2166136261u;
    for (k = 7 * CONFORM_OFFSET; k < 1 << 20; k += 7 * CONFORM_STRIDE) {
        uint32_t x = (uint32_t)k * 4099u + 1u;
        h = fnv(fnv(h, fresnel_isqrt_u32(x)), fresnel_isqrt_u32(x << 12));
        h = fnv(h, (uint32_t)fresnel_recip_q16((fresnel_q16)(x | 4u)));
    }
    report("isqrt-recip", h);
    port_puts("done\n");
    return 0;
}
