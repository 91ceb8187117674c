/* Options shared by `fresnel curve` and `fresnel params` (see material_options.h). */
#include "cli/material_options.h"

#include <string.h>

#include "cli/cli.h"

const char material_options_help[] =
    "  --material ID   material id (fresnel materials lists them), required\n"
    "  --space NAME    srgb (default), display-p3, dci-p3, adobe-rgb, rec2020, acescg\n"
    "                  (any case; aliases sRGB, rec709, bt709, p3, bt2020, ACEScg)\n"
    "  --sigma S       Gaussian window in nm for Metzgar's eta', kappa' (default 25; 0 = point sampling)\n"
    "  --n1 X          real index of the incident medium (default 1)\n"
    "  --data DIR      data directory (default $FRESNEL_DATA, else the build's data/)\n";

const char *const material_option_names[] = {"--material", "--space", "--sigma", "--n1", "--data", "--help", NULL};

void material_options_init(material_options *o)
{
    o->material = NULL;
    o->space = "srgb";
    o->data = NULL;
    o->sigma = 25.0;
    o->n1 = 1.0;
}

int material_option(const char *where, const char *opt, const char *val, material_options *o)
{
    if (!strcmp(opt, "--material"))
        o->material = val;
    else if (!strcmp(opt, "--space"))
        o->space = val;
    else if (!strcmp(opt, "--data"))
        o->data = val;
    else if (!strcmp(opt, "--sigma")) {
        if (cli_parse_double(val, &o->sigma) || o->sigma < 0.0 || o->sigma > 200.0)
            return cli_error(where, "--sigma expects a number of nm in [0, 200], got '%s'", val);
    } else if (!strcmp(opt, "--n1")) {
        if (cli_parse_double(val, &o->n1) || o->n1 < 1.0 || o->n1 > 4.0)
            return cli_error(where, "--n1 expects a number in [1, 4], got '%s'", val);
    } else
        return 0;
    return 1;
}

int material_options_derive(const char *where, const material_options *o, gen_context *g, spectrum *s,
                            material_params *p)
{
    if (!o->material)
        return cli_error(where, "--material is required (fresnel materials lists the ids)");
    if (gen_context_load(data_dir(o->data), o->space, g))
        return CLI_BAD_INPUT;
    return derive_parameters(g, o->material, o->sigma, o->n1, s, p);
}
