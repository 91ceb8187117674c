/* fresnel gen: a scene manifest in, one C header out. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "4_emit/emit.h"
#include "4_emit/emit_glsl.h"
#include "3_encode/encode.h"
#include "scene/scene.h"

#define WHERE "fresnel gen"

static void gen_usage(FILE *out)
{
    int i;
    fprintf(out, "usage: fresnel gen SCENE -o OUT.h [--glsl [--glsl-texture OUT_TEX.h]] [--data DIR]\n\n"
                 "Reads the scene manifest SCENE and writes a C header with static const\n"
                 "constants and tables for exactly its materials, models and number types.\n"
                 "--glsl writes the same constants as GLSL instead (const vec3, float arrays)\n"
                 "for use after ports/glsl/fresnel.glsl, with vec3 fresnel_<scene>_<material>_<model>_rgb(c)\n"
                 "per material and model, in every dialect the port supports; lut_spacing\n"
                 "grazing or uniform. --glsl-texture writes, as a C header, the packed RGBA8\n"
                 "texture GLSL ES 1.00 reads the LUT models from (no const arrays there).\n"
                 "The output is written to a temporary file beside OUT.h and renamed over it\n"
                 "(an existing file keeps its mode; a symlink's target is replaced): on any\n"
                 "error OUT.h (and OUT_TEX.h) is left as it was. -o - writes to stdout; a device\n"
                 "or FIFO is written in place. Identical input gives byte-identical output.\n\n"
                 "Manifest format: `key = value` lines, # comments (see gen/scene/scene.h):\n"
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
    fprintf(out, "\n  lut_spacing = grazing     or uniform, or grazing-pl (types = q15: fresnel_lut_pl_u16_q15_fast)\n");
}

int cmd_gen(int argc, char **argv)
{
    const char *manifest = NULL, *out_path = NULL, *dir_option = NULL, *tex_path = NULL;
    scene *sc = NULL;
    gen_context *g = NULL;
    material_params *params = NULL;
    spectrum **spectra = NULL;
    char name[SCENE_PREFIX_SIZE], where[1100];
    int i, status = 0, glsl = 0;
    cli_outfile out, tex;
    emit_input in;
    static const char *const options[] = {"-o", "--glsl", "--glsl-texture", "--data", "--help", NULL};

    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            gen_usage(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--glsl")) {
            glsl = 1;
        } else if (!strcmp(argv[i], "-o") || !strcmp(argv[i], "--data") || !strcmp(argv[i], "--glsl-texture")) {
            const char *val = cli_option_value(WHERE, argc, argv, &i);
            if (!val)
                return CLI_BAD_INPUT;
            if (argv[i - 1][1] == 'o')
                out_path = val;
            else if (argv[i - 1][2] == 'g')
                tex_path = val;
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
    if (tex_path && !glsl)
        return cli_error(WHERE, "--glsl-texture needs --glsl (see fresnel gen --help)");
    if (tex_path && !strcmp(tex_path, out_path))
        return cli_error(WHERE, "--glsl-texture and -o name the same file '%s'", out_path);
    if (cli_out_is_input(out_path, manifest))
        return cli_error(WHERE, "'%s' is the scene manifest itself; refusing to overwrite it", out_path);
    if (tex_path && (cli_out_is_input(tex_path, manifest) || cli_out_is_input(tex_path, out_path)))
        return cli_error(WHERE, "'%s' is the scene manifest or the -o file; refusing to overwrite it", tex_path);
    if (!(sc = malloc(sizeof *sc)) || !(g = malloc(sizeof *g))) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((status = scene_load(manifest, sc)))
        goto done;
    if (sc->name[0])
        snprintf(name, sizeof name, "%s", sc->name);
    else
        scene_name_from_path(manifest, name);
    if (glsl && (status = emit_glsl_check(sc, manifest, name)))
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
    in.sc = sc;
    in.name = name;
    in.manifest_name = strrchr(manifest, '/') ? strrchr(manifest, '/') + 1 : manifest;
    in.manifest_path = manifest;
    in.g = g;
    in.params = params;
    in.spectra = spectra;
    in.glsl = glsl;
    if ((status = cli_out_open(&out, out_path)))
        goto done;
    if (tex_path && (status = cli_out_open(&tex, tex_path))) {
        cli_out_abort(&out);
        goto done;
    }
    status = glsl ? emit_glsl(out.f, tex_path ? tex.f : NULL, &in) : emit_header(out.f, &in);
    if (status) {
        cli_out_abort(&out);
        if (tex_path)
            cli_out_abort(&tex);
        goto done;
    }
    if (tex_path && (status = cli_out_commit(&tex))) {
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
