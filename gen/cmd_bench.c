/* fresnel bench: time per RGB evaluation of each model and number type for
 * one material (`make bench`); with --runs 0 it is the fixed workload the
 * report hands to callgrind for instruction counts. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "cli.h"
#include "report.h"

#define WHERE "fresnel bench"

int cmd_bench(int argc, char **argv)
{
    const char *scene_path = "data/scenes/report.scene", *material = "au", *only_model = NULL, *only_type = NULL,
               *dir_option = NULL;
    int count = 1 << 20, runs = 5, i, m, t, status = 0;
    scene sc;
    gen_context *g = NULL;
    spectrum *s = NULL;
    material_params p;
    for (i = 1; i < argc; i++) {
        const char *o = argv[i];
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            printf("usage: fresnel bench [--scene FILE] [--material ID] [--model NAME] [--type f32|q15|f16]\n"
                   "                     [--count N] [--runs R] [--data DIR]\n\n"
                   "Prints CSV model,type,ns_per_rgb_eval: the median of R timed batches (default 5) of N\n"
                   "evaluations (default 2^20) over fixed pseudo-random cosines, for each model of the\n"
                   "scene (default data/scenes/report.scene) and material ID (default au). --runs 0\n"
                   "runs one untimed batch (the callgrind workload of `make report`).\n%s\n",
                   bench_compiler());
            return 0;
        }
        if (i + 1 >= argc)
            return cli_error(WHERE, "option '%s' needs a value (see fresnel bench --help)", o);
        if (!strcmp(o, "--scene"))
            scene_path = argv[++i];
        else if (!strcmp(o, "--material"))
            material = argv[++i];
        else if (!strcmp(o, "--model"))
            only_model = argv[++i];
        else if (!strcmp(o, "--type"))
            only_type = argv[++i];
        else if (!strcmp(o, "--data"))
            dir_option = argv[++i];
        else if (!strcmp(o, "--count")) {
            if (cli_parse_int(argv[++i], 1, 1 << 26, &count))
                return cli_error(WHERE, "--count expects an integer 1..2^26, got '%s'", argv[i]);
        } else if (!strcmp(o, "--runs")) {
            if (cli_parse_int(argv[++i], 0, 101, &runs))
                return cli_error(WHERE, "--runs expects an integer 0..101, got '%s'", argv[i]);
        } else
            return cli_error(WHERE, "unknown option '%s' (see fresnel bench --help)", o);
    }
    if ((status = scene_load(scene_path, &sc)))
        return status;
    if (!(g = malloc(sizeof *g)) || !(s = malloc(sizeof *s))) {
        status = cli_error(WHERE, "out of memory");
        goto done;
    }
    if ((status = gen_context_load(data_dir(dir_option), sc.space, g)) ||
        (status = derive_parameters(g, material, sc.sigma, sc.n1, s, &p)))
        goto done;
    if (runs > 0)
        printf("model,type,ns_per_rgb_eval\n");
    for (m = 0; m < sc.model_count; m++) {
        scene_model sm;
        report_prepared *q;
        if (only_model && strcmp(only_model, sc.models[m]))
            continue;
        if ((status = scene_model_prepare(sc.models[m], strcmp(sc.lut_spacing, "uniform") ? LUT_GRAZING : LUT_UNIFORM,
                                          s, g, &p, &sm)))
            goto done;
        if (!(q = report_prepare(&sm, &p))) {
            scene_model_free(&sm);
            status = cli_error(WHERE, "out of memory");
            goto done;
        }
        for (t = 0; t < report_type_count; t++) {
            double ns;
            if (only_type && strcmp(only_type, report_types[t].name))
                continue;
            ns = report_time(&report_types[t], q, count, runs);
            if (runs > 0)
                printf("%s,%s,%.3f\n", sc.models[m], report_types[t].name, ns);
        }
        report_prepared_free(q);
        scene_model_free(&sm);
    }
done:
    free(g);
    free(s);
    return status;
}
