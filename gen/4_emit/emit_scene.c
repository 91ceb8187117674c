/* `fresnel gen` end to end for one scene: manifest -> the encoded scene
 * (encode_scene: stages 1-3) -> the C header or the GLSL or HLSL source,
 * written safely (emit.h). */
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
    encoded_scene_free(&l->es);
    free(l->sc);
    memset(l, 0, sizeof *l);
}

int emit_load(const char *manifest, const char *dir_option, const emit_backend *backend, emit_loaded *l)
{
    int status = 0;
    memset(l, 0, sizeof *l);
    if (!(l->sc = malloc(sizeof *l->sc))) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((status = scene_load(manifest, l->sc)))
        goto done;
    if (l->sc->name[0])
        snprintf(l->name, sizeof l->name, "%s", l->sc->name);
    else
        scene_name_from_path(manifest, l->name);
    if (backend->shader && (status = emit_shader_check(l->sc, manifest, l->name, backend->option)))
        goto done;
    if ((status = encode_scene(l->sc, manifest, WHERE, dir_option, &l->es)))
        goto done;
    l->in.es = &l->es;
    l->in.sc = l->sc;
    l->in.name = l->name;
    l->in.manifest_name = strrchr(manifest, '/') ? strrchr(manifest, '/') + 1 : manifest;
    l->in.manifest_path = manifest;
    l->in.g = l->es.g;
    l->in.params = l->es.params;
    l->in.spectra = l->es.spectra;
    l->in.enc = l->es.enc;
    l->in.films = l->es.films;
    l->in.fits = l->es.fits;
    l->in.film_fits = l->es.film_fits;
done:
    if (status)
        emit_loaded_free(l);
    return status;
}

int emit_scene(const char *manifest, const char *out_path, const char *tex_path, const char *dir_option,
               const emit_backend *backend)
{
    emit_loaded l;
    int status;
    cli_outfile out, tex, *both[2];
    both[0] = &out;
    both[1] = &tex;
    if ((status = emit_load(manifest, dir_option, backend, &l)))
        return status;
    if ((status = cli_out_open(&out, out_path)))
        goto done;
    if (tex_path && (status = cli_out_open(&tex, tex_path))) {
        cli_out_abort(&out);
        goto done;
    }
    status = backend->print(out.f, tex_path ? tex.f : NULL, &l.in);
    /* The header and its texture are one output: both or neither. */
    if (status)
        cli_out_abort_all(both, tex_path ? 2 : 1);
    else
        status = cli_out_commit_all(both, tex_path ? 2 : 1);
done:
    emit_loaded_free(&l);
    return status;
}
