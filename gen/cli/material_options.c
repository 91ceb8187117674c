/* Options shared by `fresnel curve` and `fresnel params` (see material_options.h). */
#include "cli/material_options.h"

#include <stdio.h>
#include <string.h>

#include "common/cli.h"
#include "fresnel_film.h"
#include "scene/scene.h"

const char material_options_help[] =
    "  --material ID   material id (fresnel materials lists them); this or --nk is required\n"
    "  --nk FILE       the material from your own n,k file: refractiveindex.info YAML or CSV,\n"
    "                  SOPRA .nk, .spd (NAME.eta.spd + NAME.k.spd) or wavelength_nm,n,k CSV,\n"
    "                  told from its content (fresnel import --help gives each format's rules)\n"
    "  --name ID       the id --nk's material is shown under (default: from the file name)\n"
    "  --format NAME   read --nk as auto (default), csv, rii-yaml, rii-csv, sopra or spd\n"
    "  --space NAME    srgb (default), display-p3, dci-p3, adobe-rgb, rec2020, acescg\n"
    "                  (any case; aliases sRGB, rec709, bt709, p3, bt2020, ACEScg)\n"
    "  --gamut NAME    out-of-gamut colour: map (default; nearest in CIEDE2000, for a [0, 1] display),\n"
    "                  clip (per channel), keep (values above 1 stay, for HDR / wide-gamut pipelines)\n"
    "  --sigma S       Gaussian window in nm for Metzgar's eta', kappa' (default 25; 0 = point sampling)\n"
    "  --n1 X          real index of the incident medium (default 1)\n"
    "  --data DIR      data directory (default $FRESNEL_DATA, else the build's data/)\n";

const char *const material_option_names[] = {"--material", "--nk",   "--name", "--format", "--space",
                                              "--gamut",    "--sigma",    "--n1",   "--data", "--help",   NULL};

void material_options_init(material_options *o)
{
    o->material = NULL;
    o->nk = o->name = NULL;
    o->format = NK_FORMAT_AUTO;
    o->id[0] = '\0';
    o->space = "srgb";
    o->data = NULL;
    o->sigma = 25.0;
    o->n1 = 1.0;
    o->gamut = GAMUT_MAP;
    o->film_n = 0.0;
}

int type_option(const char *where, const char *val, const number_type **out)
{
    const char *names[NUMBER_TYPES + 1];
    number_type_names(names, NUMBER_TYPES + 1);
    if (!(*out = number_type_find(val)))
        return cli_unknown(where, "type", val, names);
    if (!(*out)->available)
        return cli_error(where, "--type %s: this build's compiler has no _Float16", val);
    return 0;
}

int film_option(const char *where, const char *val, double *n, double *d_nm)
{
    const char *colon = strchr(val, ':');
    char text[64];
    size_t len = colon ? (size_t)(colon - val) : sizeof text;
    if (len < sizeof text) {
        memcpy(text, val, len);
        text[len] = '\0';
        if (!cli_parse_double(text, n) && *n >= 1.0 && *n <= 4.0 && !cli_parse_double(colon + 1, d_nm) &&
            *d_nm >= 0.0 && *d_nm <= FRESNEL_FILM_D_MAX)
            return 0;
    }
    return cli_error(where, "--film expects N:D, a film index N in [1, 4] and a thickness D of nm in [0, %g], got '%s'",
                     FRESNEL_FILM_D_MAX, val);
}

int gamut_option(const char *where, const char *val, gamut_policy *out)
{
    int i = catalog_choice(gamut_policy_names, val);
    if (i < 0)
        return cli_unknown(where, "--gamut", val, gamut_policy_names);
    *out = (gamut_policy)i;
    return 0;
}

int material_option(const char *where, const char *opt, const char *val, material_options *o)
{
    if (!strcmp(opt, "--material"))
        o->material = val;
    else if (!strcmp(opt, "--nk"))
        o->nk = val;
    else if (!strcmp(opt, "--name")) {
        size_t len = strlen(val);
        if (len == 0 || len > 31 || strspn(val, "abcdefghijklmnopqrstuvwxyz0123456789_") != len)
            return cli_error(where, "--name expects 1-31 characters of a-z, 0-9 and '_', got '%s'", val);
        o->name = val;
    } else if (!strcmp(opt, "--format")) {
        int f;
        for (f = 0; nk_format_names[f] && strcmp(nk_format_names[f], val); f++)
            ;
        if (!nk_format_names[f])
            return cli_unknown(where, "format", val, nk_format_names);
        o->format = (nk_format)f;
    }
    else if (!strcmp(opt, "--space"))
        o->space = val;
    else if (!strcmp(opt, "--gamut")) {
        if (gamut_option(where, val, &o->gamut))
            return CLI_BAD_INPUT;
    }
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

int material_options_scene(const char *where, material_options *o, scene *sc)
{
    if (o->material && o->nk)
        return cli_error(where, "expected --material ID or --nk FILE, not both");
    if (!o->material && !o->nk)
        return cli_error(where, "--material ID or --nk FILE is required (fresnel materials lists the ids)");
    if ((o->name || o->format != NK_FORMAT_AUTO) && !o->nk)
        return cli_error(where, "--name and --format describe --nk FILE, which is not given");
    if (o->material && strpbrk(o->material, "./"))
        return cli_error(where, "--material takes a data-pack id, got '%s'; a file of your own is read with --nk FILE",
                         o->material);
    scene_defaults(sc);
    if (strlen(o->space) >= sizeof sc->space)
        return cli_error(where, "unknown colour space '%s'", o->space);
    strcpy(sc->space, o->space);
    sc->sigma = o->sigma;
    sc->n1 = o->n1;
    sc->gamut = o->gamut;
    sc->film_n = o->film_n;
    sc->material_count = 1;
    if (o->nk) {
        if (o->name)
            snprintf(o->id, sizeof o->id, "%s", o->name);
        else
            material_id_from_path(o->nk, o->id);
        if (strlen(o->nk) >= sizeof sc->material_file[0])
            return cli_error(where, "--nk: a path of at most %d bytes expected", (int)sizeof sc->material_file[0] - 1);
        strcpy(sc->material_file[0], o->nk);
        sc->material_format[0] = o->format;
        snprintf(sc->materials[0], sizeof sc->materials[0], "%s", o->id);
    } else if (strlen(o->material) >= sizeof sc->materials[0])
        return cli_error(where, "unknown material '%s' (fresnel materials lists the ids)", o->material);
    else
        strcpy(sc->materials[0], o->material);
    return 0;
}
