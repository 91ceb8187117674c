/* fresnel gen: a scene manifest in, one C header out. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "emit.h"
#include "generator.h"
#include "scene.h"

#define WHERE "fresnel gen"

static void gen_usage(FILE *out)
{
    int i;
    fprintf(out, "usage: fresnel gen SCENE -o OUT.h [--glsl] [--data DIR]\n\n"
                 "Reads the scene manifest SCENE and writes a C header with static const\n"
                 "constants and tables for exactly its materials, models and number types.\n"
                 "--glsl writes the same constants as GLSL instead (const vec3, float arrays)\n"
                 "for use after ports/glsl/fresnel.glsl.\n"
                 "The output is written to a temporary file beside OUT.h and renamed over it\n"
                 "(an existing file keeps its mode; a symlink's target is replaced): on any\n"
                 "error OUT.h is left as it was. -o - writes to stdout; a device or FIFO is\n"
                 "written in place. Identical input gives byte-identical output.\n\n"
                 "Manifest format: `key = value` lines, # comments (see gen/scene.h):\n"
                 "  materials = au cu al      required; ids from `fresnel materials`\n"
                 "  models = schlick f82 lut32 required; one or more of:");
    for (i = 0; scene_model_names[i]; i++)
        fprintf(out, " %s", scene_model_names[i]);
    fprintf(out, " lutN lutN-residual lutN-cubic (N = %d..%d)\n"
                 "  space = srgb              display-p3 dci-p3 adobe-rgb rec2020 acescg\n"
                 "                            (any case; also rec709 bt709 p3 bt2020)\n"
                 "  sigma = 25                Gaussian window, nm (0 = point sampling)\n"
                 "  n1 = 1                    index of the incident medium\n"
                 "  types = f32               number types:",
            SCENE_LUT_MIN, SCENE_LUT_MAX);
    for (i = 0; scene_type_names[i]; i++)
        fprintf(out, " %s", scene_type_names[i]);
    fprintf(out, "\n  lut_spacing = grazing     or uniform, or grazing-pl (types = q15: fresnel_lut_q15_u16_pl_fast)\n");
}

/* The scene's C name: the manifest's file name without directory and
 * extension, lower-cased, anything but [a-z0-9_] turned into '_'. */
static void scene_name(const char *path, char *out, size_t size)
{
    const char *base = strrchr(path, '/');
    size_t i = 0;
    base = base ? base + 1 : path;
    while (*base && *base != '.' && i + 1 < size) {
        int ch = tolower((unsigned char)*base++);
        out[i++] = (char)(isalnum(ch) ? ch : '_');
    }
    if (i == 0 || isdigit((unsigned char)out[0]))
        out[i++] = 's';
    out[i] = '\0';
}

int cmd_gen(int argc, char **argv)
{
    const char *manifest = NULL, *out_path = NULL, *dir_option = NULL;
    scene *sc = NULL;
    gen_context *g = NULL;
    material_params *params = NULL;
    spectrum **spectra = NULL;
    char name[64], where[1100];
    int i, status = 0, glsl = 0;
    cli_outfile out;
    emit_input in;
    static const char *const options[] = {"-o", "--glsl", "--data", "--help", NULL};

    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            gen_usage(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--glsl")) {
            glsl = 1;
        } else if (!strcmp(argv[i], "-o") || !strcmp(argv[i], "--data")) {
            const char *val = cli_option_value(WHERE, argc, argv, &i);
            if (!val)
                return CLI_BAD_INPUT;
            if (argv[i - 1][1] == 'o')
                out_path = val;
            else
                dir_option = val;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_bad_argument(WHERE, argv[i], options);
        } else if (manifest) {
            return cli_error(WHERE, "one scene manifest expected, got '%s' and '%s'", manifest, argv[i]);
        } else {
            manifest = argv[i];
        }
    }
    if (!manifest || !out_path)
        return cli_error(WHERE, "usage: fresnel gen SCENE -o OUT.h (see fresnel gen --help)");
    if (cli_out_is_input(out_path, manifest))
        return cli_error(WHERE, "'%s' is the scene manifest itself; refusing to overwrite it", out_path);
    if (!(sc = malloc(sizeof *sc)) || !(g = malloc(sizeof *g))) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((status = scene_load(manifest, sc)))
        goto done;
    params = calloc((size_t)sc->material_count, sizeof *params);
    spectra = calloc((size_t)sc->material_count, sizeof *spectra);
    if (!params || !spectra) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((status = gen_context_load(data_dir(dir_option), sc->space, g)))
        goto done;
    snprintf(where, sizeof where, "%s:%d", manifest, sc->materials_line);
    /* Every unknown material is reported, not only the first. */
    for (i = 0; i < sc->material_count; i++) {
        material_info info;
        if (material_lookup(g->dir, sc->materials[i], &info, where))
            status = CLI_BAD_INPUT;
    }
    if (status)
        goto done;
    for (i = 0; i < sc->material_count; i++) {
        if (!(spectra[i] = malloc(sizeof *spectra[i]))) {
            status = cli_oom(WHERE);
            goto done;
        }
        if ((status = derive_parameters(g, sc->materials[i], sc->sigma, sc->n1, spectra[i], &params[i])))
            goto done;
    }
    scene_name(manifest, name, sizeof name);
    in.sc = sc;
    in.name = name;
    in.manifest_name = strrchr(manifest, '/') ? strrchr(manifest, '/') + 1 : manifest;
    in.g = g;
    in.params = params;
    in.spectra = spectra;
    in.glsl = glsl;
    if ((status = cli_out_open(&out, out_path)))
        goto done;
    if ((status = emit_header(out.f, &in))) {
        cli_out_abort(&out);
        goto done;
    }
    status = cli_out_commit(&out);
done:
    if (spectra)
        for (i = 0; sc && i < sc->material_count; i++)
            free(spectra[i]);
    free(spectra);
    free(params);
    free(g);
    free(sc);
    return status;
}
