/* Stage 4 driven end to end for one scene: manifest -> every material
 * through stages 1-3 -> the C or GLSL header, written safely (emit.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "4_emit/emit.h"
#include "4_emit/emit_glsl.h"
#include "3_encode/encode.h"
#include "scene/scene.h"

#define WHERE "fresnel gen"

int emit_scene(const char *manifest, const char *out_path, const char *tex_path, const char *dir_option, int glsl)
{
    scene *sc = NULL;
    gen_context *g = NULL;
    material_params *params = NULL;
    spectrum **spectra = NULL;
    char name[SCENE_PREFIX_SIZE], where[1100];
    int i, status = 0;
    cli_outfile out, tex;
    emit_input in;

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
    g->gamut = scene_gamut(sc);
    /* Every unknown material is reported, not only the first. */
    for (i = 0; i < sc->material_count; i++) {
        material_info info;
        snprintf(where, sizeof where, "%s:%d", manifest, sc->material_line[i]);
        if (!sc->material_file[i][0] && material_lookup(g->dir, sc->materials[i], &info, where))
            status = CLI_BAD_INPUT;
    }
    if (status)
        goto done;
    for (i = 0; i < sc->material_count; i++) {
        if (!(spectra[i] = malloc(sizeof *spectra[i]))) {
            status = cli_oom(WHERE);
            goto done;
        }
        material_source m = scene_material(sc, i);
        if ((status = derive_parameters(g, &m, sc->sigma, sc->n1, spectra[i], &params[i])))
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
