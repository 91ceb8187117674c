/* Stage 4 driven end to end for one scene: manifest -> every material
 * through stages 1-3 -> the C header or the GLSL or HLSL source, written
 * safely (emit.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "4_emit/emit.h"
#include "4_emit/emit_glsl.h"
#include "3_encode/encode.h"
#include "scene/scene.h"

#define WHERE "fresnel gen"

void emit_loaded_free(emit_loaded *l)
{
    int i;
    if (l->spectra)
        for (i = 0; l->sc && i < l->sc->material_count; i++)
            free(l->spectra[i]);
    free(l->spectra);
    free(l->enc);
    free(l->films);
    free(l->params);
    free(l->g);
    free(l->sc);
    memset(l, 0, sizeof *l);
}

int emit_load(const char *manifest, const char *dir_option, int glsl, emit_loaded *l)
{
    char where[1100];
    int i, status = 0;
    memset(l, 0, sizeof *l);
    if (!(l->sc = malloc(sizeof *l->sc)) || !(l->g = malloc(sizeof *l->g))) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((status = scene_load(manifest, l->sc)))
        goto done;
    if (l->sc->name[0])
        snprintf(l->name, sizeof l->name, "%s", l->sc->name);
    else
        scene_name_from_path(manifest, l->name);
    if (glsl && (status = emit_shader_check(l->sc, manifest, l->name, glsl == EMIT_HLSL ? "--hlsl" : "--glsl")))
        goto done;
    l->params = calloc((size_t)l->sc->material_count, sizeof *l->params);
    l->spectra = calloc((size_t)l->sc->material_count, sizeof *l->spectra);
    l->enc = calloc((size_t)l->sc->material_count, sizeof *l->enc);
    if (!l->params || !l->spectra || !l->enc) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((status = gen_context_load(data_dir(dir_option), l->sc->space, l->g)))
        goto done;
    l->g->gamut = l->sc->gamut;
    /* Every unknown material is reported, not only the first. */
    for (i = 0; i < l->sc->material_count; i++) {
        material_info info;
        snprintf(where, sizeof where, "%s:%d", manifest, l->sc->material_line[i]);
        if (!l->sc->material_file[i][0] && material_lookup(l->g->dir, l->sc->materials[i], &info, where))
            status = CLI_BAD_INPUT;
    }
    if (status)
        goto done;
    for (i = 0; i < l->sc->material_count; i++) {
        material_source m;
        if (!(l->spectra[i] = malloc(sizeof *l->spectra[i]))) {
            status = cli_oom(WHERE);
            goto done;
        }
        m = scene_material(l->sc, i);
        if ((status = derive_parameters(l->g, &m, l->sc->sigma, l->sc->n1, l->spectra[i], &l->params[i])))
            goto done;
        encode_material(&l->params[i], &l->enc[i]);
    }
    if (l->params[0].film_n > 0.0) { /* the scene has the thin-film model: every material has a film */
        if (!(l->films = malloc((size_t)l->sc->material_count * sizeof *l->films))) {
            status = cli_oom(WHERE);
            goto done;
        }
        for (i = 0; i < l->sc->material_count; i++)
            if (encode_film(l->spectra[i], l->g, &l->params[i], &l->films[i])) {
                snprintf(where, sizeof where, "%s:%d", manifest, l->sc->material_line[i]);
                status = l->films[i].why[0]
                             ? cli_error(where, "%s under a %g film in n1 %g: %s", l->sc->materials[i],
                                         l->params[i].film_n, l->params[i].n1, l->films[i].why)
                             : cli_error(where, "%s: fitting the thin-film model of a %g film failed",
                                         l->sc->materials[i], l->params[i].film_n);
                goto done;
            }
    }
    l->in.sc = l->sc;
    l->in.name = l->name;
    l->in.manifest_name = strrchr(manifest, '/') ? strrchr(manifest, '/') + 1 : manifest;
    l->in.manifest_path = manifest;
    l->in.g = l->g;
    l->in.params = l->params;
    l->in.spectra = l->spectra;
    l->in.enc = l->enc;
    l->in.films = l->films;
    l->in.glsl = glsl;
done:
    if (status)
        emit_loaded_free(l);
    return status;
}

int emit_scene(const char *manifest, const char *out_path, const char *tex_path, const char *dir_option, int glsl)
{
    emit_loaded l;
    int status;
    cli_outfile out, tex, *both[2];
    both[0] = &out;
    both[1] = &tex;
    if ((status = emit_load(manifest, dir_option, glsl, &l)))
        return status;
    if ((status = cli_out_open(&out, out_path)))
        goto done;
    if (tex_path && (status = cli_out_open(&tex, tex_path))) {
        cli_out_abort(&out);
        goto done;
    }
    status = glsl == EMIT_HLSL ? emit_hlsl(out.f, &l.in)
           : glsl         ? emit_glsl(out.f, tex_path ? tex.f : NULL, &l.in)
                          : emit_header(out.f, &l.in);
    /* The header and its texture are one output: both or neither. */
    if (status)
        cli_out_abort_all(both, tex_path ? 2 : 1);
    else
        status = cli_out_commit_all(both, tex_path ? 2 : 1);
done:
    emit_loaded_free(&l);
    return status;
}
