/* fresnel wavelengths: the dominant wavelengths of a colour space's
 * primaries [MS18 section 5], the centres of the RGB eta/kappa windows. */
#include <stdio.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "1_spectral/spectral.h"

#define WHERE "fresnel wavelengths"

static void wavelengths_usage(FILE *out)
{
    int i;
    fprintf(out,
            "usage: fresnel wavelengths --space NAME [--data DIR]\n"
            "\n"
            "Prints, as CSV with the header red_nm,green_nm,blue_nm, the dominant\n"
            "wavelength of each primary of colour space NAME: where the ray from the\n"
            "space's white point through the primary's xy meets the CIE 1931 2-degree\n"
            "spectral locus (1 nm samples, interpolated between them).\n"
            "--data DIR   data directory (default $FRESNEL_DATA, else %s)\n"
            "\nspaces:",
            data_dir(NULL));
    for (i = 0; colour_space_ids[i]; i++)
        fprintf(out, " %s", colour_space_ids[i]);
    fprintf(out, "\n");
}

int cmd_wavelengths(int argc, char **argv)
{
    static const char *const options[] = {"--space", "--data", "--help", NULL};
    const char *space = NULL, *dir_option = NULL, *dir, *val;
    colorimetry cm;
    colour_space cs;
    double nm[3];
    int i;
    for (i = 1; i < argc; i++) {
        const char *opt = argv[i];
        if (!strcmp(opt, "--help") || !strcmp(opt, "-h")) {
            wavelengths_usage(stdout);
            return 0;
        }
        if (!cli_in_list(opt, options))
            return cli_bad_argument(WHERE, opt, options);
        if (!(val = cli_option_value(WHERE, argc, argv, &i)))
            return CLI_BAD_INPUT;
        if (!strcmp(opt, "--space"))
            space = val;
        else
            dir_option = val;
    }
    if (!space)
        return cli_error(WHERE, "--space is required (see fresnel wavelengths --help)");
    if (!colour_space_find(space))
        return cli_unknown(WHERE, "colour space", space, colour_space_ids);
    dir = data_dir(dir_option);
    if (colorimetry_load(dir, &cm) || colour_space_load(dir, space, &cm, &cs))
        return CLI_BAD_INPUT;
    dominant_wavelengths(&cm, &cs, nm);
    printf("red_nm,green_nm,blue_nm\n%.2f,%.2f,%.2f\n", nm[0], nm[1], nm[2]);
    return 0;
}
