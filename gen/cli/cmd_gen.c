/* fresnel gen: a scene manifest in, one C header out. */
#include <stdio.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "4_emit/emit.h"
#include "2_derive/targets.h"
#include "3_encode/encode.h"
#include "scene/scene.h"

#define WHERE "fresnel gen"

static void gen_usage(FILE *out)
{
    const char *names[SCENE_MAX_MODELS + 1];
    int i;
    const char *sep = "";
    fprintf(out, "usage: fresnel gen SCENE -o OUT.h [");
    for (i = 0; i < emit_backend_count; i++)
        if (emit_backends[i].option) {
            fprintf(out, "%s%s", sep, emit_backends[i].usage);
            sep = " | ";
        }
    fprintf(out, "] [--data DIR]\n\n"
                 "Reads the scene manifest SCENE and writes, with one back end, the constants and\n"
                 "tables of exactly its materials, models and number types.\n");
    for (i = 0; i < emit_backend_count; i++)
        fprintf(out, "%s\n", emit_backends[i].help);
    fprintf(out, "The output is written to a temporary file beside OUT.h and renamed over it\n"
                 "(an existing file keeps its mode; a symlink's target is replaced): on any\n"
                 "error OUT.h (and OUT_TABLES.h) is left as it was. -o - writes to stdout; a device\n"
                 "or FIFO is written in place. Identical input gives byte-identical output.\n\n"
                 "Manifest format: `key = value` lines, # comments, each key once (the reference:\n"
                 "gen/scene/scene.h). At least one material, from either or both of:\n"
                 "  materials = au cu al      ids from `fresnel materials` (the data pack)\n"
                 "  material tin = TiN.yml    your own n,k file as material 'tin', in any format\n"
                 "                            `fresnel import` reads, relative to SCENE; one\n"
                 "                            line per material\n"
                 "and:\n"
                 "  models = schlick f82 lut32 required; one or more of:");
    model_names(MODEL_SCENE, names, SCENE_MAX_MODELS + 1);
    for (i = 0; names[i]; i++)
        fprintf(out, " %s", names[i]);
    fprintf(out, " %s (N = %d..%d)\n"
                 "  space = srgb              display-p3 dci-p3 adobe-rgb rec2020 acescg\n"
                 "                            (any case; also rec709 bt709 p3 bt2020)\n"
                 "  sigma = 25                Gaussian window, nm (0 = point sampling)\n"
                 "  n1 = 1                    index of the incident medium\n"
                 "  types = f32               number types:",
            model_lut_patterns, SCENE_LUT_MIN, SCENE_LUT_MAX);
    for (i = 0; i < number_types_available; i++)
        fprintf(out, " %s", number_type_catalog[i].name);
    fprintf(out, "\n  lut_spacing = grazing     or uniform, or grazing-pl (types = q15: fresnel_lut_pl_u16_q15_fast)\n"
                 "  gamut = map               where a colour leaves the space:");
    for (i = 0; gamut_policy_names[i]; i++)
        fprintf(out, " %s", gamut_policy_names[i]);
    fprintf(out, "\n"
                 "                            (map: the nearest in-gamut colour; clip: per channel;\n"
                 "                            keep: values above 1 stay, for HDR pipelines)\n"
                 "  f_avg = no                yes: each material's hemispherical average too\n"
                 "  targets = openpbr blender other renderers' parameters (`fresnel params --for`)\n"
                 "                            in a comment per material; any of:");
    {
        const char *targets[32];
        int n = target_names(targets, 32);
        for (i = 0; i < n; i++)
            fprintf(out, " %s", targets[i]);
    }
    fprintf(out, "\n"
                 "  film = 1.38               with thin-film: the film's index on every material (n1..4)\n"
                 "  film ID = 2.1             material ID's own film\n"
                 "  film_thickness = 100 400  nm, optional (default 0 %g: set at run time)\n"
                 "  name = metals             the scene's part of every identifier (default: from\n"
                 "                            SCENE's file name)\n"
                 "The GLSL and HLSL output does not depend on types.\n",
            FRESNEL_FILM_D_MAX);
}

int cmd_gen(int argc, char **argv)
{
    const char *manifest = NULL, *out_path = NULL, *dir_option = NULL, *tex_path = NULL;
    const emit_backend *backend = emit_backend_find(NULL), *chosen;
    const char *options[8 + 8];
    int i, n = 0;
    options[n++] = "-o";
    for (i = 0; i < emit_backend_count && n < 8; i++)
        if (emit_backends[i].option)
            options[n++] = emit_backends[i].option;
    options[n++] = "--tables";
    options[n++] = "--data";
    options[n++] = "--help";
    options[n] = NULL;

    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            gen_usage(stdout);
            return 0;
        } else if ((chosen = emit_backend_find(argv[i])) != NULL) {
            if (backend->option && backend != chosen)
                return cli_error(WHERE, "%s and %s: one back end per run (see fresnel gen --help)", backend->option,
                                 chosen->option);
            backend = chosen;
        } else if (!strcmp(argv[i], "-o") || !strcmp(argv[i], "--data") || !strcmp(argv[i], "--tables")) {
            const char *opt = argv[i], *val = cli_option_value(WHERE, argc, argv, &i);
            if (!val)
                return CLI_BAD_INPUT;
            if (!strcmp(opt, "-o"))
                out_path = val;
            else if (!strcmp(opt, "--tables"))
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
    if (!manifest && out_path && backend->print_port && !tex_path) {
        /* the port alone (make wgsl) */
        cli_outfile o;
        int rc = cli_out_open(&o, out_path);
        if (rc)
            return rc;
        if (backend->print_port(o.f)) {
            cli_out_abort(&o);
            return CLI_FAILURE;
        }
        return cli_out_commit(&o);
    }
    if (!manifest || !out_path)
        return cli_error(WHERE, "usage: fresnel gen SCENE -o OUT.h (see fresnel gen --help)");
    if (tex_path && !backend->tables)
        return cli_error(WHERE, "--tables needs --glsl, --wgsl or --wgsl-f16 (see fresnel gen --help)");
    /* Neither may be a file the run reads (the manifest, a material's file,
     * the data pack): cli_out_open refuses those. */
    if (tex_path && (!strcmp(tex_path, out_path) || cli_out_is_input(tex_path, out_path)))
        return cli_error(WHERE, "--tables and -o name the same file '%s'", tex_path);
    return emit_scene(manifest, out_path, tex_path, dir_option, backend);
}
