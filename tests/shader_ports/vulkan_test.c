/* The shader ports in a real Vulkan pipeline: Mesa's lavapipe through
 * ports/vulkan/vkrun.c (compute queue only, no window). For one scene, the
 * output of `fresnel gen --glsl` after ports/glsl/fresnel.glsl (GLSL 4.50,
 * ports/glsl/prelude_450.glsl) and of `fresnel gen --hlsl` after
 * #include "fresnel.hlsl" (ports/hlsl/, which includes the GLSL port's
 * functions) are compiled to SPIR-V by glslangValidator (GLSL front end,
 * and HLSL front end with -D -e main -Iports/hlsl), checked by
 * spirv-val, and run on every cosine c = i/1024, i = -1..1025 (both ends
 * just outside [0, 1]) for every material and model of the scene (the thin
 * film at thicknesses 0-1195 nm scattered over the cosines, its table in a
 * storage buffer: write_main); each
 * result is compared with what the C runtime computes from the same
 * manifest (gen/model/encoded_scene.c, the evaluation of the C header).
 *
 * Five variants, each one module per model (a specialisation constant picks
 * the material, so each pipeline compiles one function):
 *   glsl highp          default precision highp: max |GPU - C| <= 1e-5, the
 *                       bound of the OSMesa tests (tests/shader_ports/glsl_port_osmesa.c)
 *   glsl mediump        `precision mediump float;`: the mediump-safe
 *                       functions' operations carry SPIR-V RelaxedPrecision
 *   hlsl float          FRESNEL_MP defined as float: <= 1e-5
 *   hlsl min16float     the port's default: min16float in the mediump-safe
 *                       functions, RelaxedPrecision in SPIR-V
 *   glsl mediump as Float16   the mediump module after spirv-opt
 *                       --convert-relaxed-to-half: its relaxed operations
 *                       in explicit 16-bit floats (SPIR-V Float16), run
 *                       where the device has shaderFloat16 (lavapipe
 *                       does): within each model's binary16 bound
 *                       (port_float16_bound)
 * The two relaxed variants are measured, not asserted (a Vulkan driver may
 * compute RelaxedPrecision at 32 bits, and lavapipe does: NOTE lines say
 * whether the results differ from the full-precision modules at all);
 * every result must still be finite and in [0, 1]. With the default scene
 * the port functions no scene model calls (the dielectric from both sides,
 * internal and generalized Schlick, F0 in a medium and from the IOR,
 * Gulbrandsen's (r, g) and (n, k), the latter relative to max(|C|, 1)) also
 * run at full precision, within 1e-5. The table at the end
 * (NOTE table lines) is ports/README.md's.
 *
 * Usage: vulkan_test [--device cpu|gpu|INDEX] OUT_DIR MANIFEST IDENT SCENE.glsl SCENE.hlsl
 * (tests/shader_ports/test_vulkan.sh; OUT_DIR receives the shader sources, SPIR-V and
 * tool logs). --device: the CPU device by default (lavapipe), "gpu" the
 * first GPU, INDEX a device of the loader's list (ports/vulkan/vkrun.h); a
 * NOTE names the device, and the table's lines carry its name. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel.h"
#include "fresnel_f16.h"
#include "common/cli.h"
#include "harness.h"
#include "model/registry.h"
#include "scene/scene.h"
#include "model/encoded_scene.h"
#include "1_spectral/spectral.h"
#include "port_checks.h"
#include "vkrun.h"

#define GROUP 64

enum { V_GLSL, V_GLSL_MP, V_HLSL, V_HLSL_MP, V_GLSL_HALF, NVARIANTS };
static const struct variant {
    const char *name, *ext;
    int hlsl, relaxed, half;
} variants[NVARIANTS] = {
    {"glsl highp", "comp", 0, 0, 0},
    {"glsl mediump", "comp", 0, 1, 0},
    {"hlsl float", "hlsl", 1, 0, 0},
    {"hlsl min16float", "hlsl", 1, 1, 0},
    {"glsl mediump as Float16", "comp", 0, 0, 1},
};

/* What a user of the HLSL port writes; build_module passes -Iports/hlsl. */
static const char hlsl_port[] = "#include \"fresnel.hlsl\"\n";

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *b = NULL;
    long n;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (b = malloc((size_t)n + 1)) != NULL) {
        if (fread(b, 1, (size_t)n, f) != (size_t)n) {
            free(b);
            b = NULL;
        } else {
            b[n] = '\0';
        }
    }
    fclose(f);
    return b;
}

/* The thin film runs from a storage buffer, as a GPU application hands it
 * the tables: the input buffer holds every material's fresnel_film
 * (FILM_FLOATS floats each, the order of the C struct and of `gen
 * --tables`, material i in row i) and then the cosines. In GLSL the scene's
 * own function reads it (the generated GLSL's storage route, the default in
 * Vulkan, at set 0, binding 0: the input buffer itself); in HLSL the
 * port's FRESNEL_FILM_RGB_READ over the input buffer. */
#define FILM_FLOATS (sizeof(fresnel_film) / sizeof(float)) /* the port's FRESNEL_FILM_FLOATS */

/* The shader's main(): invocation i evaluates at cosine fr_c[i] the model
 * and material that specialisation constants 0 and 1 select (so each
 * pipeline compiles one function), and writes the three channels; the
 * thin film at thickness FILM_D, from the tables before the cosines. */
static void write_main(FILE *f, const scene *sc, const char *ident, int hlsl, int m)
{
    int i, film = (model_of(sc->models[m].row)->offered & MODEL_FILM) != 0;
    char id[32];
    if (hlsl)
        fprintf(f, "\n[[vk::binding(0, 0)]] StructuredBuffer<float> fr_c;\n"
                   "[[vk::binding(1, 0)]] RWStructuredBuffer<float> fr_out;\n"
                   "[[vk::constant_id(0)]] const int fr_material = 0;\n");
    else
        fprintf(f, "\nlayout(local_size_x = %d) in;\n"
                   "layout(std430, set = 0, binding = 0) readonly buffer FrIn { highp float fr_c[]; };\n"
                   "layout(std430, set = 0, binding = 1) writeonly buffer FrOut { highp float fr_out[]; };\n"
                   "layout(constant_id = 0) const int fr_material = 0;\n",
                GROUP);
    if (film && hlsl)
        fprintf(f, "#define FR_FILM_READ(row, i) fr_c[(row) * FRESNEL_FILM_FLOATS + (i)]\n"
                   "float3 fr_film(int row, float c, float d_nm)\n{\n    FRESNEL_FILM_RGB_READ(FR_FILM_READ, row, c, d_nm)\n}\n");
    if (hlsl)
        fprintf(f, "[numthreads(%d, 1, 1)]\nvoid main(uint3 fr_id : SV_DispatchThreadID)\n{\n"
                   "    int i = (int)fr_id.x;\n    float3 r = float3(-1.0, -1.0, -1.0);\n    float c;\n",
                GROUP);
    else
        fprintf(f, "void main()\n{\n    int i = int(gl_GlobalInvocationID.x);\n    vec3 r = vec3(-1.0);\n"
                   "    highp float c;\n");
    fprintf(f, "    if (i >= %d)\n        return;\n    c = fr_c[%d * FRESNEL_FILM_FLOATS * %d + i];\n", NCOS,
            sc->material_count, film);
    snprintf(id, sizeof id, "%s", sc->models[m].ident);
    if (film && hlsl)
        /* the row as a parameter: glslang's HLSL front end crashes on the
         * spec constant inside the reader */
        fputs("    r = fr_film(fr_material, c, " FILM_D ");\n", f);
    else
        for (i = 0; i < sc->material_count; i++)
            fprintf(f, "    %sif (fr_material == %d) r = fresnel_%s_%s_%s_rgb(c%s);\n", i ? "else " : "", i, ident,
                    sc->materials[i], id, film ? ", " FILM_D : "");
    fprintf(f, "    fr_out[3 * i] = r.x;\n    fr_out[3 * i + 1] = r.y;\n    fr_out[3 * i + 2] = r.z;\n}\n");
}

static int build_module(const char *base, const char *label, const struct variant *va);

/* The port functions no scene model calls (port_checks.h), on the same grid
 * against the C runtime: one module per front end, a specialisation constant
 * picks the expression, the result in the first channel. */
static void write_funcs_main(FILE *f, int hlsl)
{
    int k;
    if (hlsl)
        fprintf(f, "\n[[vk::binding(0, 0)]] StructuredBuffer<float> fr_c;\n"
                   "[[vk::binding(1, 0)]] RWStructuredBuffer<float> fr_out;\n"
                   "[[vk::constant_id(0)]] const int fr_func = 0;\n"
                   "[numthreads(%d, 1, 1)]\nvoid main(uint3 fr_id : SV_DispatchThreadID)\n{\n"
                   "    int i = (int)fr_id.x;\n    float r = -1.0;\n    float c;\n",
                GROUP);
    else
        fprintf(f, "\nlayout(local_size_x = %d) in;\n"
                   "layout(std430, set = 0, binding = 0) readonly buffer FrIn { highp float fr_c[]; };\n"
                   "layout(std430, set = 0, binding = 1) writeonly buffer FrOut { highp float fr_out[]; };\n"
                   "layout(constant_id = 0) const int fr_func = 0;\n"
                   "void main()\n{\n    int i = int(gl_GlobalInvocationID.x);\n    highp float r = -1.0;\n"
                   "    highp float c;\n",
                GROUP);
    fprintf(f, "    if (i >= %d)\n        return;\n    c = fr_c[i];\n", NCOS);
    for (k = 0; k < NFUNCS; k++)
        fprintf(f, "    %sif (fr_func == %d) r = %s;\n", k ? "else " : "", k, port_funcs[k].expr);
    fprintf(f, "    fr_out[3 * i] = r;\n    fr_out[3 * i + 1] = 0.0;\n    fr_out[3 * i + 2] = 0.0;\n}\n");
}

/* The full-precision variants (V_GLSL, V_HLSL) of port_funcs[]: within HIGHP_BOUND. */
static void run_funcs(vkrun *v, const char *dir, char **src, const float *cosines)
{
    static const int which[2] = {V_GLSL, V_HLSL};
    int w, k, j;
    for (w = 0; w < 2; w++) {
        const struct variant *va = &variants[which[w]];
        char base[1100], path[1200], name[256], err[512];
        uint32_t *words;
        size_t nbytes = 0;
        FILE *f;
        snprintf(base, sizeof base, "%s/functions_%d", dir, which[w]);
        snprintf(path, sizeof path, "%s.%s", base, va->ext);
        snprintf(name, sizeof name, "vulkan: the port functions no scene model calls, %s", va->name);
        if (!(f = fopen(path, "w"))) {
            CHECK(name, 0, "cannot write %s", path);
            continue;
        }
        if (va->hlsl) {
            fputs("#define FRESNEL_MP float\n", f);
            fputs(hlsl_port, f);
        } else {
            fputs(src[0], f);
            fputs("precision highp float;\n", f);
            fputs(src[1], f);
        }
        write_funcs_main(f, va->hlsl);
        if (fclose(f) || build_module(base, name, va))
            continue;
        snprintf(path, sizeof path, "%s.spv", base);
        if (!(words = vkrun_read_spirv(path, &nbytes))) {
            CHECK(name, 0, "cannot read %s", path);
            continue;
        }
        for (k = 0; k < NFUNCS; k++) {
            static float o[3 * NCOS];
            int32_t spec = k;
            vkrun_pipe p;
            double worst = 0.0;
            char fname[320];
            snprintf(fname, sizeof fname, "vulkan: %s, %s", port_funcs[k].expr, va->name);
            if (vkrun_pipeline(v, words, nbytes, &spec, 1, 0, &p, err, sizeof err) ||
                vkrun_dispatch(v, &p, NULL, cosines, NCOS, o, 3 * NCOS, (NCOS + GROUP - 1) / GROUP, err, sizeof err)) {
                CHECK(fname, 0, "%s", err);
                vkrun_pipeline_free(v, &p);
                continue;
            }
            vkrun_pipeline_free(v, &p);
            for (j = 0; j < NCOS; j++) {
                double d = port_func_diff(k, o[3 * j], cosines[j]);
                if (!(d <= worst))
                    worst = d;
            }
            NOTE("%s: max |GPU - C|%s %.2g (bound %.2g)", fname, port_funcs[k].rel ? " / max(|C|, 1)" : "", worst,
                 HIGHP_BOUND);
            CHECK(fname, worst <= HIGHP_BOUND, "max difference %.3g (bound %.3g)", worst, HIGHP_BOUND);
        }
        free(words);
    }
}

/* SPIR-V decorations RelaxedPrecision (OpDecorate/OpMemberDecorate with
 * decoration 0): how many results the module lets a driver relax. */
static int count_relaxed(const uint32_t *w, size_t nbytes)
{
    size_t n = nbytes / 4, k = 5;
    int count = 0;
    while (k < n) {
        uint32_t wc = w[k] >> 16, op = w[k] & 0xffffu;
        if (wc == 0)
            break;
        if ((op == 71 && k + 2 < n && w[k + 2] == 0) || (op == 72 && k + 3 < n && w[k + 3] == 0))
            count++;
        k += wc;
    }
    return count;
}

/* A module from base.EXT (base without the extension): glslangValidator,
 * then spirv-val, each logged to base.*.log. 0, or -1 after a FAIL line. */
static int build_module(const char *base, const char *label, const struct variant *va)
{
    char cmd[4096], name[512];
    snprintf(name, sizeof name, "vulkan: %s compiles to SPIR-V and passes spirv-val", label);
    snprintf(cmd, sizeof cmd, "glslangValidator -V --target-env vulkan1.0 %s-S comp -o '%s.spv' '%s.%s' >'%s.glslang.log' 2>&1",
             va->hlsl ? "-D -e main -Iports/hlsl " : "", base, base, va->ext, base);
    if (system(cmd) != 0) {
        CHECK(name, 0, "%s: see %s.glslang.log", cmd, base);
        return -1;
    }
    /* the Float16 variant: the mediump module's relaxed operations turned
     * into explicit 16-bit floats, as a driver that honours mediump runs them */
    if (va->half) {
        snprintf(cmd, sizeof cmd, "spirv-opt --convert-relaxed-to-half -O '%s.spv' -o '%s.spv' >'%s.spirv-opt.log' 2>&1",
                 base, base, base);
        if (system(cmd) != 0) {
            CHECK(name, 0, "%s: see %s.spirv-opt.log", cmd, base);
            return -1;
        }
    }
    snprintf(cmd, sizeof cmd, "spirv-val --target-env vulkan%s '%s.spv' >'%s.spirv-val.log' 2>&1",
             va->half ? "1.2" : "1.0", base, base);
    if (system(cmd) != 0) {
        CHECK(name, 0, "%s: see %s.spirv-val.log", cmd, base);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    static scene sc;
    static gen_context gc;
    static double worst[NVARIANTS][SCENE_MAX_MODELS];
    static int differs[NVARIANTS][SCENE_MAX_MODELS], ran[NVARIANTS];
    char err[512], path[1100];
    const char *dir, *ident;
    char *src[2];
    material_params *params;
    spectrum *spectra;
    scene_model *models; /* [material][model] */
    float *film_in = NULL; /* the film's tables, then the cosines */
    float cosines[NCOS], *ref, *out[NVARIANTS];
    size_t nout;
    vkrun v;
    int i, m, k, vi, nmat, highp_only = 1;
    const char *device = "cpu";
    if (argc > 1 && !strcmp(argv[1], "--device")) {
        if (argc < 3 || !vkrun_device_valid(argv[2])) {
            fprintf(stderr, "vulkan_test: --device takes cpu, gpu or a device index, got '%s'\n",
                    argc < 3 ? "" : argv[2]);
            return 2;
        }
        device = argv[2];
        argc -= 2;
        argv += 2;
    }
    if (argc != 6) {
        fprintf(stderr, "usage: vulkan_test [--device cpu|gpu|INDEX] OUT_DIR MANIFEST IDENT SCENE.glsl SCENE.hlsl\n");
        return 2;
    }
    dir = argv[1];
    ident = argv[3];
    if (port_scene_load("vulkan", argv[2], &sc, &gc, &params, &spectra, &models))
        return harness_exit();
    nmat = sc.material_count;
    for (m = 0; m < sc.model_count; m++)
        highp_only &= (model_of(sc.models[m].row)->offered & MODEL_FILM) != 0;
    nout = (size_t)3 * NCOS * (size_t)nmat;
    if (!(ref = malloc(nout * (size_t)sc.model_count * sizeof *ref)))
        return 1;
    for (vi = 0; vi < NVARIANTS; vi++)
        if (!(out[vi] = malloc(nout * (size_t)sc.model_count * sizeof *out[vi])))
            return 1;
    for (i = 0; i < NCOS; i++)
        cosines[i] = (float)(i + C_LO) / 1024.0f;
    if (port_scene_refs(&sc, &gc, params, spectra, models, ref))
        return 1;
    snprintf(path, sizeof path, "ports/glsl/prelude_450.glsl");
    src[0] = read_file(path);
    src[1] = read_file("ports/glsl/fresnel.glsl");
    if (!src[0] || !src[1]) {
        CHECK("vulkan: port sources", 0, "cannot read ports/glsl/prelude_450.glsl or ports/glsl/fresnel.glsl "
                                         "(run from the top of the tree)");
        return harness_exit();
    }
    if (vkrun_open(&v, device, err, sizeof err)) {
        CHECK("vulkan: the Vulkan device asked for (--device)", 0, "%s", err);
        return harness_exit();
    }
    NOTE("vulkan: %s: device %s (%s)", ident, v.device_name, v.device_info);

    for (vi = 0; vi < NVARIANTS; vi++) {
        const struct variant *va = &variants[vi];
        char *scene_src;
        int relaxed_min = -1, relaxed_max = 0, built = 0;
        if (va->half && !v.float16) {
            NOTE("vulkan: %s %s: not run: the device has no shaderFloat16", ident, va->name);
            continue;
        }
        scene_src = read_file(argv[va->hlsl ? 5 : 4]);
        if (!scene_src) {
            CHECK("vulkan: scene shader source", 0, "cannot read %s", argv[va->hlsl ? 5 : 4]);
            continue;
        }
        for (m = 0; m < sc.model_count; m++) {
            float *o = out[vi] + (size_t)m * nout;
            const float *r = ref + (size_t)m * nout;
            char name[256], base[1024];
            uint32_t *words = NULL;
            size_t nbytes = 0;
            int bad = 0, ok = 1, relaxed;
            FILE *f;
            snprintf(name, sizeof name, "vulkan: %s %s, %d materials, %s", ident, sc.models[m].name, nmat, va->name);
            snprintf(base, sizeof base, "%s/%s_%d_%d", dir, ident, vi, m);
            snprintf(path, sizeof path, "%s.%s", base, va->ext);
            if (!(f = fopen(path, "w"))) {
                CHECK(name, 0, "cannot write %s", path);
                continue;
            }
            fprintf(f, "// vulkan_test: %s, scene %s, model %s\n", va->name, ident, sc.models[m].name);
            if (va->hlsl) {
                if (!va->relaxed)
                    fputs("#define FRESNEL_MP float\n", f);
                fputs(hlsl_port, f);
            } else {
                fputs(src[0], f);
                fputs(va->relaxed || va->half ? "precision mediump float;\n" : "precision highp float;\n", f);
                fputs(src[1], f);
            }
            fputs(scene_src, f);
            write_main(f, &sc, ident, va->hlsl, m);
            if (fclose(f) || build_module(base, name, va))
                continue;
            snprintf(path, sizeof path, "%s.spv", base);
            if (!(words = vkrun_read_spirv(path, &nbytes))) {
                CHECK(name, 0, "cannot read %s", path);
                continue;
            }
            built++;
            relaxed = count_relaxed(words, nbytes);
            if (relaxed_min < 0 || relaxed < relaxed_min)
                relaxed_min = relaxed;
            if (relaxed > relaxed_max)
                relaxed_max = relaxed;
            for (i = 0; i < nmat && ok; i++) {
                int32_t spec = i;
                vkrun_pipe p;
                const float *in = cosines;
                size_t nin = NCOS;
                if (models[i * sc.model_count + m].film) {
                    int r;
                    if (!film_in && !(film_in = malloc(((size_t)nmat * FILM_FLOATS + NCOS) * sizeof *film_in)))
                        return 1;
                    for (r = 0; r < nmat; r++)
                        memcpy(film_in + (size_t)r * FILM_FLOATS, &models[r * sc.model_count + m].film->f32,
                               sizeof(fresnel_film));
                    memcpy(film_in + (size_t)nmat * FILM_FLOATS, cosines, sizeof cosines);
                    in = film_in;
                    nin = (size_t)nmat * FILM_FLOATS + NCOS;
                }
                if (vkrun_pipeline(&v, words, nbytes, &spec, 1, 0, &p, err, sizeof err) ||
                    vkrun_dispatch(&v, &p, NULL, in, nin, o + (size_t)3 * NCOS * (size_t)i, (size_t)3 * NCOS,
                                   (NCOS + GROUP - 1) / GROUP, err, sizeof err)) {
                    CHECK(name, 0, "%s: %s", sc.materials[i], err);
                    ok = 0;
                }
                vkrun_pipeline_free(&v, &p);
            }
            free(words);
            if (!ok)
                continue;
            for (k = 0; k < (int)nout; k++) {
                double d = fabs((double)o[k] - r[k]);
                if (!(o[k] >= 0.0f && o[k] <= 1.0f))
                    bad++;
                if (!(d <= worst[vi][m]))
                    worst[vi][m] = d;
                if (va->relaxed)
                    differs[vi][m] += ran[vi - 1] && o[k] != out[vi - 1][(size_t)m * nout + (size_t)k];
            }
            if (va->relaxed) {
                NOTE("%s: max |GPU - C| %.2g (measured; relaxed precision)", name, worst[vi][m]);
                CHECK(name, bad == 0, "%d results not in [0, 1] (NaN or out of range)", bad);
            } else if (va->half) {
                double hb = port_float16_bound(&sc, m);
                NOTE("%s: max |GPU - C| %.2g (bound %.2g)", name, worst[vi][m], hb);
                CHECK(name, bad == 0 && worst[vi][m] <= hb, "max difference %.3g (bound %.3g), %d results not in "
                      "[0, 1]", worst[vi][m], hb, bad);
            } else {
                NOTE("%s: max |GPU - C| %.2g (bound %.2g)", name, worst[vi][m], HIGHP_BOUND);
                CHECK(name, bad == 0 && worst[vi][m] <= HIGHP_BOUND, "max difference %.3g (bound %.3g), %d results "
                      "not in [0, 1]", worst[vi][m], HIGHP_BOUND, bad);
            }
        }
        free(scene_src);
        ran[vi] = built == sc.model_count;
        if (built && va->relaxed && highp_only) {
            /* the film's port function is highp throughout */
            NOTE("vulkan: %s %s: %d to %d RelaxedPrecision decorations per module (the scene's functions are "
                 "highp throughout)", ident, va->name, relaxed_min, relaxed_max);
        } else if (built && !va->half) {
            char name[256];
            snprintf(name, sizeof name, "vulkan: %s %s: %s RelaxedPrecision decorations (%d to %d per module)", ident,
                     va->name, va->relaxed ? "the modules have" : "no module has", relaxed_min, relaxed_max);
            CHECK(name, va->relaxed ? relaxed_max > 0 : relaxed_max == 0, "%d to %d", relaxed_min, relaxed_max);
        }
        if (va->relaxed && ran[vi] && ran[vi - 1]) {
            int total = 0;
            for (m = 0; m < sc.model_count; m++)
                total += differs[vi][m];
            NOTE("vulkan: %s %s: %d of %d results differ from the %s modules'%s", ident, va->name, total,
                 (int)nout * sc.model_count, variants[vi - 1].name,
                 total ? "" : ": the driver computes RelaxedPrecision in binary32");
        }
    }
    if (!strcmp(ident, "default"))
        run_funcs(&v, dir, src, cosines);
    /* The table of ports/README.md, after the device it was measured on. */
    NOTE("table device: %s (%s)", v.device_name, v.device_info);
    NOTE("table | %s | model | GLSL 4.50 highp | GLSL mediump | HLSL float | HLSL min16float | GLSL as Float16 | "
         "Float16 bound |",
         ident);
    for (m = 0; m < sc.model_count; m++) {
        char cell[NVARIANTS][32];
        for (vi = 0; vi < NVARIANTS; vi++)
            port_cell(cell[vi], ran[vi], worst[vi][m]);
        NOTE("table | %s | %s | %s | %s | %s | %s | %s | %.2g |", ident, sc.models[m].name, cell[0], cell[1], cell[2],
             cell[3], cell[4], port_float16_bound(&sc, m));
    }
    vkrun_close(&v);
    for (i = 0; i < nmat * sc.model_count; i++)
        scene_model_free(&models[i]);
    for (vi = 0; vi < NVARIANTS; vi++)
        free(out[vi]);
    for (i = 0; i < 2; i++)
        free(src[i]);
    free(models);
    free(film_in);
    free(params);
    free(spectra);
    free(ref);
    return harness_exit();
}
