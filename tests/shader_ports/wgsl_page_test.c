/* The WGSL port in a browser's WebGPU, two steps around the browser run
 * (tests/shader_ports/test_wgsl.sh):
 *
 *   wgsl_page_test page OUT.html MANIFEST IDENT SCENE.wgsl [f16]
 *       writes a page holding the output of `fresnel gen --wgsl` and a
 *       compute shader that evaluates every material and model of the scene
 *       on every cosine c = i/1024, i = -1..1025 (the thin film at
 *       thicknesses 0-1195 nm scattered over the cosines, port_checks.h),
 *       and for the default scene the port functions no scene model calls.
 *       The page reports compile errors (getCompilationInfo, with line
 *       numbers), then the results as the bits of each binary32 in hex
 *       (console.log lines "R OFFSET HEX..."), then "WGSL_DONE".
 *   wgsl_page_test check MANIFEST IDENT LOG BROWSER [f16]
 *       reads those lines back from the browser's log and compares each
 *       value with what the C runtime computes from the same manifest
 *       (gen/model/encoded_scene.c): max |WGSL - C| <= 1e-5 per model, every
 *       result in [0, 1]; NOTE table lines per model.
 * With f16 the module is `fresnel gen --wgsl-f16`'s: the page asks for the
 * shader-f16 feature, leaves out the port functions, and each model is
 * held to its bound with the mediump-safe functions in binary16
 * (port_half_bound, as MSL's half).
 * Run from the top of the tree. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "harness.h"
#include "port_checks.h"
#include "1_spectral/spectral.h"

#define WORKGROUP 64

/* Slots: model m, material i at (m nmat + i) NCOS 3; then port function k
 * at the end, one float per cosine. */
static int write_page(const char *path, const scene *sc, const char *ident, const char *wgsl, int funcs,
                      const scene_model *models, int f16)
{
    FILE *f = fopen(path, "w");
    int i, m, k, nmat = sc->material_count, film_m = -1;
    long nres = 3L * NCOS * nmat * sc->model_count, total = nres + (funcs ? (long)NFUNCS * NCOS : 0);
    if (!f)
        return -1;
    fputs("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>wgsl_page_test</title></head><body>\n"
          "<script type=\"text/wgsl\" id=\"wgsl\">\n",
          f);
    if (port_append_file(f, wgsl)) {
        fclose(f);
        return -1;
    }
    for (m = 0; m < sc->model_count; m++)
        if (model_of(sc->models[m].row)->offered & MODEL_FILM)
            film_m = m;
    fprintf(f, "\n@group(0) @binding(1) var<storage, read_write> fresnel_test_out: array<f32>;\n"
               "@compute @workgroup_size(%d)\n"
               "fn fresnel_test_main(@builtin(global_invocation_id) gid: vec3u) {\n"
               "    let i = i32(gid.x);\n    if (i >= %d) {\n        return;\n    }\n"
               "    let c = f32(i + (%d)) / 1024.0;\n    var r: vec3f;\n",
            WORKGROUP, NCOS, C_LO);
    for (m = 0; m < sc->model_count; m++)
        for (i = 0; i < nmat; i++) {
            int film = (model_of(sc->models[m].row)->offered & MODEL_FILM) != 0;
            long base = ((long)m * nmat + i) * NCOS * 3;
            fprintf(f, "    r = fresnel_%s_%s_%s_rgb(c%s);\n", ident, sc->materials[i], sc->models[m].ident,
                    film ? ", f32((i * 157) % 256) * 4.6875" : "");
            fprintf(f, "    fresnel_test_out[%ld + 3 * i] = r.x;\n    fresnel_test_out[%ld + 3 * i + 1] = r.y;\n"
                       "    fresnel_test_out[%ld + 3 * i + 2] = r.z;\n",
                    base, base, base);
        }
    for (k = 0; funcs && k < NFUNCS; k++)
        fprintf(f, "    fresnel_test_out[%ld + i] = f32(%s);\n", nres + (long)k * NCOS, port_funcs[k].expr);
    fputs("}\n</script>\n<script>\n", f);
    /* the film's tables, row i material i, as --tables writes them: the
     * storage buffer at binding 0 of `gen --wgsl` */
    fputs("const film = new Uint32Array([", f);
    for (i = 0; film_m >= 0 && i < nmat; i++) {
        const float *t = &models[(size_t)i * sc->model_count + film_m].film->f32.freq[0];
        for (k = 0; k < (int)(sizeof(fresnel_film) / sizeof(float)); k++) {
            unsigned int u;
            memcpy(&u, &t[k], sizeof u);
            fprintf(f, "%s0x%x", i || k ? (k % 8 ? "," : ",\n") : "", u);
        }
    }
    fputs("]);\n", f);
    fprintf(f, "const log = (s) => {\n"
               "  console.log(s);\n"
               "  if (typeof dump === 'function') dump(s + '\\n'); /* Firefox: to stdout */\n"
               "};\n"
               "(async () => {\n"
               "  try {\n"
               "    const adapter = await navigator.gpu.requestAdapter();\n"
               "    const f16 = %d;\n"
               "    if (f16 && !adapter.features.has('shader-f16')) throw 'the adapter has no shader-f16';\n"
               "    const device = await adapter.requestDevice(f16 ? {requiredFeatures: ['shader-f16']} : {});\n"
               "    const code = document.getElementById('wgsl').textContent;\n"
               "    const module = device.createShaderModule({code});\n"
               "    const info = await module.getCompilationInfo();\n"
               "    let bad = false;\n"
               "    for (const msg of info.messages) {\n"
               "      log('WGSL ' + msg.type + ' line ' + msg.lineNum + ':' + msg.linePos + ': ' + msg.message);\n"
               "      if (msg.type === 'error') bad = true;\n"
               "    }\n"
               "    if (bad) { log('WGSL_DONE compile error'); return; }\n"
               "    const pipeline = await device.createComputePipelineAsync({layout: 'auto',\n"
               "      compute: {module, entryPoint: 'fresnel_test_main'}});\n"
               "    const size = %ld * 4;\n"
               "    const buf = device.createBuffer({size, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC});\n"
               "    const rb = device.createBuffer({size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST});\n"
               "    const entries = [{binding: 1, resource: {buffer: buf}}];\n"
               "    if (film.length) {\n"
               "      const tb = device.createBuffer({size: film.byteLength, usage: GPUBufferUsage.STORAGE,\n"
               "        mappedAtCreation: true});\n"
               "      new Uint32Array(tb.getMappedRange()).set(film);\n      tb.unmap();\n"
               "      entries.push({binding: 0, resource: {buffer: tb}});\n"
               "    }\n"
               "    const bg = device.createBindGroup({layout: pipeline.getBindGroupLayout(0), entries});\n"
               "    const enc = device.createCommandEncoder();\n"
               "    const pass = enc.beginComputePass();\n"
               "    pass.setPipeline(pipeline);\n    pass.setBindGroup(0, bg);\n"
               "    pass.dispatchWorkgroups(%d);\n    pass.end();\n"
               "    enc.copyBufferToBuffer(buf, 0, rb, 0, size);\n"
               "    device.queue.submit([enc.finish()]);\n"
               "    await rb.mapAsync(GPUMapMode.READ);\n"
               "    const u = new Uint32Array(rb.getMappedRange());\n"
               "    for (let k = 0; k < u.length; k += 256)\n"
               "      log('R ' + k + ' ' + Array.from(u.subarray(k, k + 256), (x) => x.toString(16)).join(' '));\n"
               "    log('WGSL_DONE ok');\n"
               "  } catch (e) {\n"
               "    log('WGSL_FAIL ' + e);\n    log('WGSL_DONE error');\n"
               "  }\n"
               "})();\n</script>\n</body></html>\n",
            f16, total, (NCOS + WORKGROUP - 1) / WORKGROUP);
    return fclose(f);
}

static float from_bits(unsigned long b)
{
    unsigned int u = (unsigned int)b;
    float v;
    memcpy(&v, &u, sizeof v);
    return v;
}

int main(int argc, char **argv)
{
    static scene sc;
    static gen_context gc;
    static double worst[SCENE_MAX_MODELS], fworst[64];
    material_params *params;
    spectrum *spectra;
    scene_model *models;
    float *ref, *got;
    char *line = NULL, name[256];
    size_t cap = 0;
    long nres, total, filled = 0;
    int i, m, k, nmat, funcs, done = 0, bad = 0;
    FILE *log;
    const char *ident, *browser;
    int f16 = argc == 7 && !strcmp(argv[6], "f16");
    if ((argc == 6 || f16) && !strcmp(argv[1], "page")) {
        if (scene_load(argv[3], &sc) || gen_context_load(data_dir(NULL), sc.space, &gc)) {
            CHECK("wgsl: scene loads", 0, "%s", argv[3]);
            return harness_exit();
        }
        nmat = sc.material_count;
        params = calloc((size_t)nmat, sizeof *params);
        spectra = calloc((size_t)nmat, sizeof *spectra);
        models = calloc((size_t)nmat * (size_t)sc.model_count, sizeof *models);
        ref = malloc(3L * NCOS * nmat * sc.model_count * sizeof *ref);
        if (!params || !spectra || !models || !ref)
            return 1;
        if (port_scene_refs(&sc, &gc, params, spectra, models, ref)) {
            CHECK("wgsl: the scene's materials derive", 0, "%s", argv[3]);
            return harness_exit();
        }
        if (write_page(argv[2], &sc, argv[4], argv[5], !f16 && !strcmp(argv[4], "default"), models, f16)) {
            CHECK("wgsl: page written", 0, "%s", argv[2]);
            return harness_exit();
        }
        return 0;
    }
    if ((argc != 6 && !f16) || strcmp(argv[1], "check")) {
        fprintf(stderr, "usage: wgsl_page_test page OUT.html MANIFEST IDENT SCENE.wgsl [f16]\n"
                        "       wgsl_page_test check MANIFEST IDENT LOG BROWSER [f16]\n");
        return 2;
    }
    ident = argv[3];
    browser = argv[5];
    funcs = !f16 && !strcmp(ident, "default");
    if (scene_load(argv[2], &sc) || gen_context_load(data_dir(NULL), sc.space, &gc)) {
        CHECK("wgsl: scene loads", 0, "%s", argv[2]);
        return harness_exit();
    }
    nmat = sc.material_count;
    nres = 3L * NCOS * nmat * sc.model_count;
    total = nres + (funcs ? (long)NFUNCS * NCOS : 0);
    params = calloc((size_t)nmat, sizeof *params);
    spectra = calloc((size_t)nmat, sizeof *spectra);
    models = calloc((size_t)nmat * (size_t)sc.model_count, sizeof *models);
    ref = malloc((size_t)nres * sizeof *ref);
    got = calloc((size_t)total, sizeof *got);
    if (!params || !spectra || !models || !ref || !got)
        return 1;
    if (port_scene_refs(&sc, &gc, params, spectra, models, ref)) {
        CHECK("wgsl: the scene's materials derive", 0, "%s", argv[2]);
        return harness_exit();
    }
    if (!(log = fopen(argv[4], "r"))) {
        CHECK("wgsl: browser log", 0, "cannot read %s", argv[4]);
        return harness_exit();
    }
    while (getline(&line, &cap, log) > 0) {
        /* Chromium logs "R ..." quoted inside its own line, Firefox's
         * dump() the bare text */
        char *p = !strncmp(line, "R ", 2) ? line : strstr(line, "\"R "), *e;
        long off;
        if (p && p != line)
            p++;
        if (strstr(line, "\"WGSL ") || !strncmp(line, "WGSL ", 5) || strstr(line, "WGSL_FAIL"))
            fprintf(stdout, "wgsl: %s %s", browser, line);
        if (strstr(line, "WGSL_DONE ok"))
            done = 1;
        if (!p)
            continue;
        off = strtol(p + 2, &e, 10);
        for (p = e; off >= 0 && off < total; off++) {
            unsigned long b = strtoul(p, &e, 16);
            if (e == p)
                break;
            got[off] = from_bits(b);
            filled++;
            p = e;
        }
    }
    free(line);
    fclose(log);
    snprintf(name, sizeof name, "wgsl: %s, %s runs the module", ident, browser);
    CHECK(name, done && filled == total, "%ld of %ld results read%s", filled, total,
          done ? "" : ", no WGSL_DONE ok (see the log)");
    if (!done || filled != total)
        return harness_exit();
    for (m = 0; m < sc.model_count; m++)
        for (i = 0; i < nmat; i++)
            for (k = 0; k < 3 * NCOS; k++) {
                size_t at = ((size_t)m * nmat + i) * NCOS * 3 + (size_t)k;
                double v = got[at], d = fabs(v - ref[at]);
                bad += !(v >= 0.0 && v <= 1.0);
                if (!(d <= worst[m]))
                    worst[m] = d;
            }
    for (k = 0; funcs && k < NFUNCS; k++)
        for (i = 0; i < NCOS; i++) {
            double d = port_func_diff(k, got[nres + (long)k * NCOS + i], port_cosine(i));
            if (!(d <= fworst[k]))
                fworst[k] = d;
        }
    snprintf(name, sizeof name, "wgsl: %s, %s, every result in [0, 1]", ident, browser);
    CHECK(name, bad == 0, "%d results not in [0, 1]", bad);
    for (m = 0; m < sc.model_count; m++) {
        /* f16: the mediump-safe functions in binary16, the others in
         * binary32, as MSL's half (port_half_bound) */
        double bound = f16 ? port_half_bound(&sc, m) : HIGHP_BOUND;
        snprintf(name, sizeof name, "wgsl: %s %s, %d materials, %s%s", ident, sc.models[m].name, nmat, browser,
                 f16 ? " f16" : "");
        NOTE("%s: max |WGSL - C| %.2g (bound %.2g)", name, worst[m], bound);
        CHECK(name, worst[m] <= bound, "max difference %.3g (bound %.3g)", worst[m], bound);
    }
    for (k = 0; funcs && k < NFUNCS; k++) {
        snprintf(name, sizeof name, "wgsl: %s, %s", port_funcs[k].expr, browser);
        NOTE("%s: max |WGSL - C|%s %.2g (bound %.2g)", name, port_funcs[k].rel ? " / max(|C|, 1)" : "", fworst[k],
             HIGHP_BOUND);
        CHECK(name, fworst[k] <= HIGHP_BOUND, "max difference %.3g (bound %.3g)", fworst[k], HIGHP_BOUND);
    }
    for (m = 0; m < sc.model_count; m++) /* the table's header: test_wgsl.sh */
        NOTE("table | %s | %s | %s%s | %.2g | %.2g |", ident, sc.models[m].name, browser, f16 ? " f16" : "", worst[m],
             f16 ? port_half_bound(&sc, m) : HIGHP_BOUND);
    free(params);
    free(spectra);
    free(models);
    free(ref);
    free(got);
    return harness_exit();
}
