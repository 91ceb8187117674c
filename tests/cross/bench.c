/* Instruction counts per evaluation on a target, read off an execution
 * trace (ports/count.sh): before each call, and after the last one, the
 * program calls port_mark, whose address the trace parser looks for; the
 * instructions between two marks are one call plus the loop around it,
 * which the first row (a function that returns its argument) measures and
 * the parser subtracts. 33 cosines, 0 to 1 in steps of 1/32, for copper at
 * 550 nm; the LUTs use their 64-node gold table. The program prints the
 * row names in order. */
#include "fixed_models.h"
#include "port.h"

#define BENCH_CODES 33

volatile uint32_t bench_sink;

static fresnel_q15 e_none(const conform_material *m, int32_t c)
{
    (void)m;
    return (fresnel_q15)c;
}

static void run(const char *name, fixed_eval fn, const conform_material *m)
{
    int k;
    port_puts(name);
    port_puts("\n");
    for (k = 0; k < BENCH_CODES; k++) {
        port_mark((uint32_t)k);
        bench_sink += fn(m, k * 1024);
    }
    port_mark(BENCH_CODES);
}

/* The run-time preparation, one call per "code" as well. */
static fresnel_q15 e_ior_prepare(const conform_material *m, int32_t c)
{
    fresnel_ior_prep_q15 out;
    (void)c;
    out = fresnel_ior_prepare_q15(m->eta, m->kappa);
    return (fresnel_q15)out.a0;
}
static fresnel_q15 e_gulbrandsen_nk(const conform_material *m, int32_t c)
{
    fresnel_nk_prep_q15 out;
    (void)c;
    out = fresnel_gulbrandsen_nk_q15(m->r, m->g);
    return (fresnel_q15)out.n.m;
}

int main(void)
{
    const conform_material *m = &conform_materials[conform_bench_material];
    int i;
    port_puts("BENCH\n");
    run("(loop)", e_none, m);
    for (i = 0; i < FIXED_MODEL_COUNT; i++)
        run(fixed_models[i].name, fixed_models[i].fn, m);
    run("fresnel_ior_prepare_q15", e_ior_prepare, m);
    run("fresnel_gulbrandsen_nk_q15", e_gulbrandsen_nk, m);
    port_puts("END\n");
    return 0;
}
