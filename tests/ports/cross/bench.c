/* Instruction counts per evaluation on a target, read off an execution
 * trace (ports/count.sh): before each call, and after the last one, the
 * program calls port_mark, whose address the trace parser looks for; the
 * instructions between two marks are one call plus the loop around it,
 * which the first row (a function that returns its argument) measures and
 * the parser subtracts. Each row runs over the materials and cosine sets of
 * conform.h (conform_bench_materials x conform_bench_cos: copper,
 * aluminium and BK7 at 550 nm; 17 cosines uniform in c, uniform in the
 * angle and near grazing incidence); the LUTs use their 64-node gold table
 * whatever the material. The program prints the number of calls per row
 * after BENCH, then the row names in order. */
#include "q15_models.h"
#include "port.h"


volatile uint32_t bench_sink;

static fresnel_q15 e_none(const conform_material *m, int32_t c)
{
    (void)m;
    return (fresnel_q15)c;
}

static void run(const char *name, fixed_eval fn)
{
    int i, j, k;
    uint32_t calls = 0;
    port_puts(name);
    port_puts("\n");
    for (i = 0; i < CONFORM_BENCH_MATERIALS; i++)
        for (j = 0; j < CONFORM_BENCH_SETS; j++)
            for (k = 0; k < CONFORM_BENCH_CODES; k++) {
                port_mark(calls++);
                bench_sink += fn(&conform_materials[conform_bench_materials[i]], conform_bench_cos[j][k]);
            }
    port_mark(calls);
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

/* The batches: each call shades a scanline of BATCH_MAX cosines (the three
 * sets' codes in turn) of the row's material; the row's name carries
 * BATCH_MAX after a tab, so ports/count.sh reports it per cosine. */
static fresnel_q15 scanline[BATCH_MAX], scanline_out[BATCH_MAX];
static void run_batch(const batch_model *b)
{
    int i, j, k;
    uint32_t calls = 0;
    port_puts(b->name);
    port_puts("\t");
    port_put_dec(BATCH_MAX);
    port_puts("\n");
    for (i = 0; i < CONFORM_BENCH_MATERIALS; i++)
        for (j = 0; j < CONFORM_BENCH_SETS; j++)
            for (k = 0; k < CONFORM_BENCH_CODES; k++) {
                port_mark(calls++);
                b->fn(&conform_materials[conform_bench_materials[i]], scanline, scanline_out, BATCH_MAX);
                bench_sink += scanline_out[k];
            }
    port_mark(calls);
}

int main(void)
{
    int i;
    port_puts("BENCH ");
    port_put_dec(CONFORM_BENCH_MATERIALS * CONFORM_BENCH_SETS * CONFORM_BENCH_CODES);
    port_puts("\n");
    run("(loop)", e_none);
    for (i = 0; i < FIXED_MODEL_COUNT; i++)
        run(fixed_models[i].name, fixed_models[i].fn);
    batch_tables_init();
    {
        int set = 0, code = 0; /* i's remainders by the set and code counts, kept without a divide */
        for (i = 0; i < BATCH_MAX; i++) {
            scanline[i] = (fresnel_q15)conform_bench_cos[set][code];
            set = set + 1 == CONFORM_BENCH_SETS ? 0 : set + 1;
            code = code + 1 == CONFORM_BENCH_CODES ? 0 : code + 1;
        }
    }
    for (i = 0; i < BATCH_MODEL_COUNT; i++)
        run_batch(&batch_models[i]);
    run("fresnel_ior_prepare_q15", e_ior_prepare);
    run("fresnel_gulbrandsen_nk_q15", e_gulbrandsen_nk);
    port_puts("END\n");
    return 0;
}
