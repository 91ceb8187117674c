/* fresnel materials: what data/ holds, and how much of 360-830 nm each
 * table really measures (the rest is held end values; see resample.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "1_spectral/spectral.h"

#define WHERE "fresnel materials"
#define MAX_MATERIALS 1024

static void materials_usage(FILE *out)
{
    fprintf(out,
            "usage: fresnel materials [--data DIR] [--verbose]\n"
            "\n"
            "Lists the materials of DIR/materials.csv as CSV with the header\n"
            "id,name,dataset,kind,measured_lo_nm,measured_hi_nm: materials.csv's own columns\n"
            "in its order (data/README.md describes them), then two that give the\n"
            "part of 360-830 nm that the material's n,k table covers (outside it the\n"
            "generator holds the end value). Every table is loaded and checked, so a\n"
            "damaged file is reported as file:line with exit status 2.\n"
            "--data DIR   data directory (default $FRESNEL_DATA, else %s)\n"
            "--verbose    also warn, per table, where the measurement stops short of 360-830 nm\n",
            data_dir(NULL));
}

int cmd_materials(int argc, char **argv)
{
    const char *dir_option = NULL, *dir;
    material_info *list = NULL;
    spectrum *s = NULL;
    double *lo = NULL, *hi = NULL;
    static const char *const options[] = {"--data", "--verbose", "--help", NULL};
    int count, i, status = CLI_BAD_INPUT, verbose = 0;
    for (i = 1; i < argc; i++) {
        const char *opt = argv[i];
        if (!strcmp(opt, "--help") || !strcmp(opt, "-h")) {
            materials_usage(stdout);
            return 0;
        }
        if (!strcmp(opt, "--verbose")) {
            verbose = 1;
            continue;
        }
        if (strcmp(opt, "--data"))
            return cli_bad_argument(WHERE, opt, options);
        if (!(dir_option = cli_option_value(WHERE, argc, argv, &i)))
            return CLI_BAD_INPUT;
    }
    /* The listing's measured_lo_nm, measured_hi_nm columns say the same. */
    spectrum_coverage_warnings = verbose;
    dir = data_dir(dir_option);
    list = malloc(MAX_MATERIALS * sizeof *list);
    s = malloc(sizeof *s);
    lo = malloc(MAX_MATERIALS * sizeof *lo);
    hi = malloc(MAX_MATERIALS * sizeof *hi);
    if (!list || !s || !lo || !hi) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((count = material_list(dir, list, MAX_MATERIALS)) < 0)
        goto done;
    /* Load everything before printing, so a bad table leaves stdout empty. */
    for (i = 0; i < count; i++) {
        if (spectrum_load(dir, list[i].id, s))
            goto done;
        lo[i] = s->measured_lo;
        hi[i] = s->measured_hi;
    }
    printf("id,name,dataset,kind,measured_lo_nm,measured_hi_nm\n");
    for (i = 0; i < count; i++)
        printf("%s,%s,%s,%s,%g,%g\n", list[i].id, list[i].name, list[i].dataset, list[i].kind,
               lo[i], hi[i]);
    status = 0;
done:
    spectrum_coverage_warnings = 1;
    free(list);
    free(s);
    free(lo);
    free(hi);
    return status;
}
