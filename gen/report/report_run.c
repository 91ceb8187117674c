/* The report's data: the run's cells and summaries that the tables and
 * plots read, the published figures they are compared with, and the files
 * the run writes. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bench/bench.h"
#include "report/report.h"

/* Hoffman's "Schlick" and "Fitted eta, kappa" columns [Hof20, course notes,
 * ACEScg with a D60 white], metals in his order with our ids. */
const report_hoffman_row report_hoffman[REPORT_HOFFMAN] = {
    {"ag", "Silver", 0.27, 0.02, 0.99},  {"cu", "Copper", 0.69, 0.03, 8.49},
    {"au", "Gold", 0.69, 0.05, 6.05},    {"commercial_bronze", "Bronze", 0.78, 0.02, 9.47},
    {"brass", "Brass", 1.04, 0.04, 5.49}, {"al", "Aluminum", 1.12, 0.01, 1.09},
    {"pd", "Palladium", 1.70, 0.02, 2.61}, {"ni", "Nickel", 1.82, 0.02, 3.80},
    {"ti", "Titanium", 1.87, 0.01, 3.34}, {"hg", "Mercury", 1.89, 0.02, 0.97},
    {"pt", "Platinum", 2.08, 0.02, 3.01}, {"fe", "Iron", 2.42, 0.01, 0.65},
    {"zn", "Zinc", 2.44, 0.08, 8.67},     {"cr", "Chromium", 2.90, 0.02, 0.36},
};

double report_time(const number_type *t, const model_rgb *q, int n, int runs)
{
    return bench_ns_per_eval(t->batch(q->def), q, n, runs);
}

int report_material_index(const report_run *r, const char *id)
{
    int i;
    for (i = 0; i < r->sc.material_count; i++)
        if (!strcmp(r->mats[i].p.info.id, id))
            return i;
    return -1;
}

report_cell *report_cell_at(report_run *r, int mat, int model, int type)
{
    return &r->cells[((size_t)mat * r->sc.model_count + model) * number_types_available + type];
}

int report_is_metal(const report_material *rm) { return !strcmp(rm->p.info.kind, "metal"); }

void report_metal_summary(report_run *r, int model, int type, double *mean, double *worst)
{
    int i, n = 0;
    *mean = 0.0;
    *worst = 0.0;
    for (i = 0; i < r->sc.material_count; i++) {
        report_cell *c = report_cell_at(r, i, model, type);
        if (!report_is_metal(&r->mats[i]))
            continue;
        *mean += c->de_mean;
        if (c->de_max > *worst)
            *worst = c->de_max;
        n++;
    }
    *mean = n ? *mean / n : NAN;
}

const double report_sigmas[REPORT_SIGMAS] = {0.0, 12.0, 25.0, 50.0};

FILE *report_out_open(report_run *r, const char *name, int *status)
{
    char path[CLI_PATH_MAX];
    if ((size_t)snprintf(path, sizeof path, "%s/%s", r->out_dir, name) >= sizeof path) {
        *status = cli_error(r->out_dir, "path too long");
        return NULL;
    }
    if (r->out_count == r->out_cap) {
        *status = cli_error(path, "expected at most %d output files", r->out_cap);
        return NULL;
    }
    if ((*status = cli_out_open(&r->out[r->out_count], path)))
        return NULL;
    return r->out[r->out_count++].f;
}
