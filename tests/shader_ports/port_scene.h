/* The scene every test of a generated shader scene loads (OSMesa:
 * glsl_generated_osmesa.c; Vulkan: vulkan_test.c; MSL on the host:
 * msl_host_test.c), with room for its materials. */
#ifndef FRESNEL_TESTS_PORT_SCENE_H
#define FRESNEL_TESTS_PORT_SCENE_H

#include <stdio.h>
#include <stdlib.h>

#include "harness.h"
#include "2_derive/derive.h"
#include "model/encoded_scene.h"
#include "scene/scene.h"
#include "1_spectral/spectral.h"

/* The file at path appended to f: 0, or -1 if it cannot be read. */
static inline int port_append_file(FILE *f, const char *path)
{
    FILE *in = fopen(path, "r");
    char buf[8192];
    size_t n;
    if (!in)
        return -1;
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        fwrite(buf, 1, n, f);
    return fclose(in);
}

/* The scene of a port test (label names it in the CHECK line) and room for
 * its materials' parameters, spectra and prepared models
 * ([material][model]). 0, or -1 after a FAIL line. */
static inline int port_scene_load(const char *label, const char *manifest, scene *sc, gen_context *gc,
                                  material_params **params, spectrum **spectra, scene_model **models)
{
    char what[128];
    int nmat;
    snprintf(what, sizeof what, "%s: scene loads", label);
    if (scene_load(manifest, sc) || gen_context_load(data_dir(NULL), sc->space, gc)) {
        CHECK(what, 0, "%s", manifest);
        return -1;
    }
    nmat = sc->material_count;
    *params = calloc((size_t)nmat, sizeof **params);
    *spectra = calloc((size_t)nmat, sizeof **spectra);
    *models = calloc((size_t)nmat * (size_t)sc->model_count, sizeof **models);
    if (!*params || !*spectra || !*models) {
        CHECK(what, 0, "out of memory");
        return -1;
    }
    return 0;
}

#endif
