/* fresnel bench: time per RGB evaluation of each model and number type for
 * one material (`make bench`); with --runs 0 it is the fixed workload the
 * report hands to callgrind for instruction counts. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/commands.h"
#include "bench/bench.h"
#include "bench/bench_targets.h"
#include "common/cli.h"
#include "cli/material_options.h"
#include "report/report.h"

#define WHERE "fresnel bench"

/* --targets: one row per line. */
static int bench_targets_print(void)
{
    bench_target_row rows[BENCH_TARGET_ROWS];
    int n = bench_target_errors(rows, BENCH_TARGET_ROWS), i;
    printf("name,max_abs_err,matched_c0,matched_c1e-4\n");
    for (i = 0; i < n; i++) {
        printf("%s,%.3g,", rows[i].name, rows[i].max_abs_err);
        if (rows[i].matched_c0 == -1.0) /* not a conductor row */
            printf("-,-\n");
        else if (isnan(rows[i].matched_c0)) /* printf's NaN may carry a sign */
            printf("nan,%.9g\n", rows[i].matched_c1e4);
        else
            printf("%.9g,%.9g\n", rows[i].matched_c0, rows[i].matched_c1e4);
    }
    return 0;
}

int cmd_bench(int argc, char **argv)
{
    const char *scene_path = "data/scenes/report.scene", *material = "au", *only_model = NULL,
               *dir_option = NULL, *nk_file = NULL;
    const number_type *only_type = NULL;
    char nk_id[32];
    material_source source;
    int count = 1 << 20, runs = 5, i, m, t, status = 0, targets = 0, scene_options = 0;
    static const char *const options[] = {"--scene", "--material", "--nk", "--model", "--type", "--data", "--count",
                                          "--runs", "--targets", "--help", NULL};
    const char *v;
    static scene sc; /* large; the one run of the command */
    encoded_scene es;
    for (i = 1; i < argc; i++) {
        const char *o = argv[i];
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            printf("usage: fresnel bench [--scene FILE] [--material ID | --nk FILE] [--model NAME] [--type f32|q15|f16]\n"
                   "                     [--count N] [--runs R] [--data DIR]\n"
                   "       fresnel bench --targets\n\n"
                   "Prints CSV model,type,ns_per_rgb_eval: the median of R timed batches (default 5) of N\n"
                   "evaluations (default 2^20) over fixed pseudo-random cosines, for each model of the\n"
                   "scene (default data/scenes/report.scene) and material ID (default au). --runs 0\n"
                   "runs one untimed batch (the callgrind workload of `make report`). --nk FILE takes the\n"
                   "material from a user's n,k file (formats: fresnel import --help).\n\n"
                   "--targets: the accuracy of the rows of the library's speed targets, CSV\n"
                   "  name,max_abs_err,matched_c0,matched_c1e-4\n"
                   "max_abs_err against the double reference on the grid gen/bench/bench_targets.h\n"
                   "describes; matched_*: the result at eta = 1, kappa = 0 (exact: 0; '-': not a\n"
                   "conductor row). mitsuba-style and pbrt-style are this project's binary32\n"
                   "transcriptions of Mitsuba 3's fresnel_conductor and pbrt-v4's FrComplex\n"
                   "(gen/bench/peers.h). Their speed, against the library's, is `make bench`\n"
                   "(speed/speed.c: each flag set built on its own, peers as calls and inlined).\n%s\n",
                   bench_compiler());
            return 0;
        }
        if (!strcmp(o, "--targets")) {
            targets = 1;
            continue;
        }
        if (!cli_in_list(o, options))
            return cli_bad_argument(WHERE, o, options);
        if (!(v = cli_option_value(WHERE, argc, argv, &i)))
            return CLI_BAD_INPUT;
        scene_options++;
        if (!strcmp(o, "--scene"))
            scene_path = v;
        else if (!strcmp(o, "--material"))
            material = v;
        else if (!strcmp(o, "--nk"))
            nk_file = v;
        else if (!strcmp(o, "--model"))
            only_model = v;
        else if (!strcmp(o, "--type")) {
            if (type_option(WHERE, v, &only_type))
                return CLI_BAD_INPUT;
        } else if (!strcmp(o, "--data"))
            dir_option = v;
        else if (!strcmp(o, "--count")) {
            if (cli_parse_int(v, 1, 1 << 26, &count))
                return cli_error(WHERE, "--count expects an integer 1..2^26, got '%s'", v);
        } else {
            if (cli_parse_int(v, 0, 101, &runs))
                return cli_error(WHERE, "--runs expects an integer 0..101, got '%s'", v);
        }
    }
    if (targets) {
        if (scene_options)
            return cli_error(WHERE, "--targets takes no other option (see fresnel bench --help)");
        return bench_targets_print();
    }
    if ((status = scene_load(scene_path, &sc)))
        return status;
    source.id = material;
    source.path = nk_file;
    source.format = NK_FORMAT_AUTO;
    source.film_n = 0.0;
    if (nk_file) {
        material_id_from_path(nk_file, nk_id);
        source.id = nk_id;
    }
    /* the film on this material: the scene's own for it, else the scene's default */
    for (m = 0; m < sc.material_count && strcmp(sc.materials[m], source.id); m++)
        ;
    for (i = 0; i < sc.model_count; i++)
        if (model_of(sc.models[i].row)->offered & MODEL_FILM)
            source.film_n = m < sc.material_count && !nk_file ? scene_film_n(&sc, m) : sc.film_n;
    if (sc.spacing == LUT_GRAZING_PL)
        return cli_error(scene_path, "lut_spacing grazing-pl tables are Q15-only; `make cross-count` "
                                     "times fresnel_lut_pl_u16_q15_fast");
    if (only_model && !scene_has_model(&sc, only_model)) {
        const char *names[SCENE_MAX_MODELS + 1];
        for (m = 0; m < sc.model_count; m++)
            names[m] = sc.models[m].name;
        names[m] = NULL;
        return cli_unknown(WHERE, "model (of the scene)", only_model, names);
    }
    /* the scene's models on the one material */
    if (strlen(source.id) >= sizeof sc.materials[0] || (nk_file && strlen(nk_file) >= sizeof sc.material_file[0]))
        return cli_error(WHERE, "expected a material id of at most %d bytes and a path of at most %d",
                         (int)sizeof sc.materials[0] - 1, (int)sizeof sc.material_file[0] - 1);
    strcpy(sc.materials[0], source.id);
    strcpy(sc.material_file[0], nk_file ? nk_file : "");
    sc.material_count = 1;
    sc.film_count = 0;
    sc.film_n = source.film_n;
    if ((status = encode_scene(&sc, NULL, WHERE, dir_option, &es)))
        return status;
    if (runs > 0)
        printf("model,type,ns_per_rgb_eval\n");
    for (m = 0; m < sc.model_count; m++) {
        model_rgb q;
        if (only_model && strcmp(only_model, sc.models[m].name))
            continue;
        q = scene_model_rgb(encoded_scene_model(&es, 0, m));
        for (t = 0; t < number_types_available; t++) {
            double ns;
            if (only_type && only_type != &number_types[t])
                continue;
            ns = report_time(&number_types[t], &q, count, runs);
            if (runs > 0)
                printf("%s,%s,%.3f\n", sc.models[m].name, number_types[t].name, ns);
        }
    }
    encoded_scene_free(&es);
    return status;
}
