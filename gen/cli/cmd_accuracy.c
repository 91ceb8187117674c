/* fresnel accuracy: how far each model is from the exact Fresnel equations
 * for measured materials at single wavelengths, and how much binary32 adds.
 * This is the scalar question (one IOR per evaluation); colour error against
 * the spectral ground truth is the generator's and the report's business. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "model/registry.h"
#include "common/reference.h"
#include "1_spectral/spectral.h"

#define WHERE "fresnel accuracy"
#define MAX_ITEMS 64

static const char *const default_materials[] = {"ag", "au", "cu", "al", "cr", "fe", "bk7", "water", NULL};
static const double default_nm[] = {450.0, 550.0, 650.0};

/* Models compared with the exact equations in the main table: the exact
 * variants are the yardstick, and Schlick for internal reflection only
 * means something inside a dielectric (its own table). */
static int in_main_table(const model *m)
{
    return (m->offered & MODEL_EVAL) && !(m->offered & MODEL_EXACT) && m != model_schlick_internal;
}

/* Schlick with the transmitted angle against the exact dielectric, for light
 * inside the material meeting air (relative index 1/eta). */
static void internal_row(const char *id, double nm, double eta, int steps)
{
    model_params mp;
    const model *m = model_schlick_internal;
    double worst = 0.0;
    int a;
    model_derive(1.0, 0.0, eta, 1.0, 5.0, &mp);
    for (a = 0; a <= steps; a++) {
        double c = cos(a * 1.5707963267948966 / steps);
        double e = fabs(m->ref->scalar(&mp, c) - ref_dielectric(mp.eta, c));
        if (e > worst)
            worst = e;
    }
    printf("| %s | %.0f | %.4g | %.2e |\n", id, nm, eta, worst);
}

static void accuracy_usage(FILE *out)
{
    fprintf(out,
            "usage: fresnel accuracy [--materials \"ID ...\"] [--nm \"W ...\"] [--steps N] [--data DIR]\n"
            "\n"
            "For each material (default: ag au cu al cr fe bk7 water) at each wavelength\n"
            "(default 450 550 650 nm; eta, kappa linearly interpolated from data/<id>.csv),\n"
            "prints a Markdown table of every model's maximum absolute difference from\n"
            "the exact Fresnel equations (double precision, parameters derived from that\n"
            "eta, kappa as `fresnel eval` does), over N+1 angles uniform in 0..90 degrees\n"
            "(default N = 900). The last row is the largest binary32 rounding error of\n"
            "each model over the same points (runtime against its own double reference).\n");
}

static int split_words(char *s, char **word, int max)
{
    int n = 0;
    char *tok = strtok(s, " \t,");
    while (tok && n < max) {
        word[n++] = tok;
        tok = strtok(NULL, " \t,");
    }
    return tok ? -1 : n;
}

int cmd_accuracy(int argc, char **argv)
{
    const char *mats[MAX_ITEMS], *dir_option = NULL, *dir;
    double nms[MAX_ITEMS];
    char *mat_buf = NULL, *nm_buf = NULL, *word[MAX_ITEMS];
    int n_mats = 0, n_nm = 3, steps = 900, i, j, k, status = 0;
    double rounding[32] = {0};
    spectrum *s = NULL;
    static struct {
        const char *id;
        double nm, eta;
    } internal[MAX_ITEMS * MAX_ITEMS];
    int n_internal = 0;
    static const char *const options[] = {"--materials", "--nm", "--steps", "--data", "--help", NULL};

    for (i = 0; default_materials[i]; i++)
        mats[n_mats++] = default_materials[i];
    for (i = 0; i < 3; i++)
        nms[i] = default_nm[i];
    for (i = 1; i < argc; i++) {
        const char *opt = argv[i];
        if (!strcmp(opt, "--help") || !strcmp(opt, "-h")) {
            accuracy_usage(stdout);
            goto done;
        }
        if (!cli_in_list(opt, options)) {
            status = cli_bad_argument(WHERE, opt, options);
            goto done;
        }
        if (!cli_option_value(WHERE, argc, argv, &i)) {
            status = CLI_BAD_INPUT;
            goto done;
        }
        i--; /* the branches below take the value as argv[++i] */
        if (!strcmp(opt, "--materials") || !strcmp(opt, "--nm")) {
            char **buf = opt[2] == 'm' ? &mat_buf : &nm_buf;
            int n;
            free(*buf);
            if (!(*buf = malloc(strlen(argv[i + 1]) + 1))) {
                status = cli_oom(WHERE);
                goto done;
            }
            strcpy(*buf, argv[++i]);
            if ((n = split_words(*buf, word, MAX_ITEMS)) <= 0) {
                status = cli_error(WHERE, "%s expects 1 to %d values", opt, MAX_ITEMS);
                goto done;
            }
            for (j = 0; j < n; j++)
                if (buf == &mat_buf)
                    mats[j] = word[j];
                else if (cli_parse_double(word[j], &nms[j]) || nms[j] < SPEC_LO_NM || nms[j] > SPEC_HI_NM) {
                    status = cli_error(WHERE, "--nm: expected wavelengths in 360..830, got '%s'", word[j]);
                    goto done;
                }
            if (buf == &mat_buf)
                n_mats = n;
            else
                n_nm = n;
        } else if (!strcmp(opt, "--steps")) {
            if (cli_parse_int(argv[++i], 1, 100000, &steps)) {
                status = cli_error(WHERE, "--steps expects an integer 1..100000, got '%s'", argv[i]);
                goto done;
            }
        } else if (!strcmp(opt, "--data")) {
            dir_option = argv[++i];
        }
    }
    dir = data_dir(dir_option);
    if (!(s = malloc(sizeof *s))) {
        status = cli_oom(WHERE);
        goto done;
    }

    printf("Maximum |model - exact Fresnel| over theta = 0..90 deg (%d steps), double precision.\n"
           "Parameters derived from the material's eta, kappa at one wavelength (fresnel eval).\n\n"
           "| material | nm | eta | kappa |",
           steps);
    for (k = 0; k < model_count; k++)
        if (in_main_table(&model_table[k]))
            printf(" %s |", model_table[k].name);
    printf("\n|---|---:|---:|---:|");
    for (k = 0; k < model_count; k++)
        if (in_main_table(&model_table[k]))
            printf("---:|");
    printf("\n");

    for (i = 0; i < n_mats; i++) {
        if ((status = spectrum_load(dir, mats[i], s)))
            goto done;
        for (j = 0; j < n_nm; j++) {
            double pos = (nms[j] - SPEC_LO_NM) / SPEC_STEP_NM;
            int lo = (int)floor(pos);
            double u = pos - lo, eta, kappa;
            model_params mp, mp32;
            if (lo >= SPEC_N - 1) {
                lo = SPEC_N - 2;
                u = 1.0;
            }
            eta = (1.0 - u) * s->n[lo] + u * s->n[lo + 1];
            kappa = (1.0 - u) * s->k[lo] + u * s->k[lo + 1];
            model_derive(eta, kappa, 1.0, 1.0, 5.0, &mp);
            mp32 = mp;
            model_params_round_f32(&mp32);
            if (kappa < 1e-3 && n_internal < MAX_ITEMS * MAX_ITEMS) {
                internal[n_internal].id = mats[i];
                internal[n_internal].nm = nms[j];
                internal[n_internal++].eta = eta;
            }
            printf("| %s | %.0f | %.4g | %.4g |", mats[i], nms[j], eta, kappa);
            for (k = 0; k < model_count; k++) {
                const model *m = &model_table[k];
                double worst = 0.0;
                int a;
                if (!in_main_table(m))
                    continue;
                for (a = 0; a <= steps; a++) {
                    double c = cos(a * (1.5707963267948966) / steps);
                    float cf = (float)c;
                    double e = fabs(m->ref->scalar(&mp, c) - ref_conductor(mp.eta, mp.kappa, c));
                    double r = fabs((double)m->f32->scalar(&mp32, cf) - m->ref->scalar(&mp32, (double)cf));
                    if (e > worst)
                        worst = e;
                    if (r > rounding[k])
                        rounding[k] = r;
                }
                printf(" %.2e |", worst);
            }
            printf("\n");
        }
    }
    printf("| binary32 rounding | | | |");
    for (k = 0; k < model_count; k++)
        if (in_main_table(&model_table[k]))
            printf(" %.1e |", rounding[k]);
    printf("\n\nInternal reflection, from inside each dielectric (kappa < 1e-3) into air:\n"
           "maximum |schlick-internal - exact dielectric| over the same angles.\n\n"
           "| material | nm | eta | schlick-internal |\n|---|---:|---:|---:|\n");
    for (i = 0; i < n_internal; i++)
        internal_row(internal[i].id, internal[i].nm, internal[i].eta, steps);
done:
    free(s);
    free(mat_buf);
    free(nm_buf);
    return status;
}
