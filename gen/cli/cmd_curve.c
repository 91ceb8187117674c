/* fresnel curve: the spectral ground truth of one material over angle, and
 * every model evaluated with its derived parameters. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "common/reference.h"
#include "cli/material_options.h"
#include "scene/scene.h"
#include "model/encoded_scene.h"

#define WHERE "fresnel curve"


int cmd_curve(int argc, char **argv)
{
    material_options o;
    scene *sc = NULL;
    encoded_scene es;
    const gen_context *g;
    const spectrum *s;
    const material_params *p;
    char *names = NULL, *tok;
    const char *model_list = model_curve_default;
    static const char *const options[] = {"--material", "--nk",      "--name",   "--format",      "--space",
                                          "--gamut",    "--sigma",    "--n1",      "--data",   "--samples",     "--models",
                                          "--lut-spacing", "--type", "--film", "--help", NULL};
    const number_type *type = &number_types[TYPE_F32];
    const char *val;
    int samples = 91, n_models = 0, i, r, status = 0, models_given = 0;
    memset(&es, 0, sizeof es);
    double film_d = 0.0;
    film_stack film;
    lut_spacing spacing = LUT_GRAZING;
    material_options_init(&o);
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            int t;
            printf("usage: fresnel curve (--material ID | --nk FILE) [--space NAME] [--gamut map|clip|keep]\n"
                   "                     [--sigma S] [--samples N] [--models \"NAME ...\"]\n"
                   "                     [--lut-spacing grazing|uniform] [--type T] [--n1 X] [--data DIR]\n"
                   "                     [--film N:D]\n\n"
                   "Prints CSV: theta_deg,cos,gt_r,gt_g,gt_b (the spectral ground truth under the\n"
                   "--gamut policy, which every model is derived from), unclipped_r,_g,_b (the\n"
                   "spectral ground truth itself, outside [0,1] where the colour leaves the space's\n"
                   "gamut), then <model>_r,_g,_b for each model, evaluated by the runtime of\n"
                   "number type T (default f32) on the constants and tables `fresnel gen` writes\n"
                   "for it (a Q1.15 result as code / 32768). N rows (default 91), theta uniform\n"
                   "from 0 to 90 degrees.\n"
                   "With --film N:D, a film of index N (n1..4) and thickness D nm (0..5000) lies\n"
                   "on the material: gt and unclipped are the film's spectral truth (gt clipped\n"
                   "per channel, the thin-film model's policy), and the default model is thin-film,\n"
                   "at thickness D; any other model named is the bare material's.\n"
                   "Default models: %s\n\n%s"
                   "  --samples N     rows, 2..100000\n"
                   "  --film N:D      a thin film: index N, thickness D nm\n"
                   "  --type T        one of",
                   model_curve_default, material_options_help);
            for (t = 0; t < number_types_available; t++)
                printf(" %s", number_types[t].name);
            printf("\n");
            return 0;
        }
        if (!cli_in_list(argv[i], options))
            return cli_bad_argument(WHERE, argv[i], options);
        if (!(val = cli_option_value(WHERE, argc, argv, &i)))
            return CLI_BAD_INPUT;
        r = material_option(WHERE, argv[i - 1], val, &o);
        if (r == CLI_BAD_INPUT)
            return r;
        if (r == 0) {
            if (!strcmp(argv[i - 1], "--samples")) {
                if (cli_parse_int(val, 2, 100000, &samples))
                    return cli_error(WHERE, "--samples expects an integer 2..100000, got '%s'", val);
            } else if (!strcmp(argv[i - 1], "--models")) {
                model_list = val;
                models_given = 1;
            } else if (!strcmp(argv[i - 1], "--film")) {
                if (film_option(WHERE, val, &o.film_n, &film_d))
                    return CLI_BAD_INPUT;
            } else if (!strcmp(argv[i - 1], "--type")) {
                if (type_option(WHERE, val, &type))
                    return CLI_BAD_INPUT;
            } else {
                static const char *const spacings[] = {"grazing", "uniform", NULL};
                int k = catalog_choice(spacings, val);
                if (k < 0)
                    return cli_unknown(WHERE, "--lut-spacing", val, spacings);
                spacing = (lut_spacing)catalog_choice(lut_spacing_names, val);
            }
        }
    }
    if (!(sc = malloc(sizeof *sc)) || !(names = malloc(strlen(model_list) + 1))) {
        status = cli_oom(WHERE);
        goto done;
    }
    if (o.film_n > 0.0 && o.film_n < o.n1) {
        status = cli_error(WHERE,
                           "--film %g is less dense than --n1 %g: total reflection inside the film is outside the "
                           "thin-film model's domain (include/fresnel_film.h)",
                           o.film_n, o.n1);
        goto done;
    }
    if (o.film_n > 0.0 && !models_given)
        model_list = model_curve_film;
    if ((status = material_options_scene(WHERE, &o, sc)))
        goto done;
    sc->spacing = spacing;
    strcpy(names, model_list);
    for (tok = strtok(names, " \t,"); tok; tok = strtok(NULL, " \t,"))
        if ((status = scene_add_model(sc, tok, WHERE)))
            goto done;
    n_models = sc->model_count;
    if ((status = encode_scene(sc, NULL, WHERE, o.data, &es)))
        goto done;
    g = es.g;
    s = es.spectra[0];
    p = &es.params[0];
    film.n1 = o.n1;
    film.film = NULL;
    film.film_n = o.film_n;
    film.substrate = s;
    printf("theta_deg,cos,gt_r,gt_g,gt_b,unclipped_r,unclipped_g,unclipped_b");
    for (i = 0; i < n_models; i++)
        printf(",%s_r,%s_g,%s_b", sc->models[i].name, sc->models[i].name, sc->models[i].name);
    printf("\n");
    for (r = 0; r < samples; r++) {
        double theta = 90.0 * r / (samples - 1), c = r == samples - 1 ? 0.0 : cos(theta * (3.14159265358979323846 / 180.0));
        double gt[3], raw[3];
        int m;
        if (o.film_n > 0.0) {
            film_truth(&film, &g->cm, &g->cs, c, film_d, raw);
            for (m = 0; m < 3; m++)
                gt[m] = ref_clamp(raw[m], 0.0, 1.0);
        } else {
            ground_truth_gamut(s, g, p, c, gt);
            ground_truth(s, &g->cm, &g->cs, p->n1, c, raw);
        }
        printf("%.6g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", theta, c, gt[0], gt[1], gt[2], raw[0], raw[1], raw[2]);
        for (m = 0; m < n_models; m++) {
            model_rgb q = scene_model_rgb(encoded_scene_model(&es, 0, m));
            double v[3];
            q.d_nm = film_d;
            type->eval(&q, c, v);
            printf(",%.9g,%.9g,%.9g", v[0], v[1], v[2]);
        }
        printf("\n");
    }
done:
    encoded_scene_free(&es);
    free(names);
    free(sc);
    return status;
}
