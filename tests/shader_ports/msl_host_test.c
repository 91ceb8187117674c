/* The MSL port on the host. Apple's Metal compiler runs on macOS only, so
 * for one scene the output of `fresnel gen --msl` after ports/msl/fresnel.metal
 * is compiled as C++ by g++ and by clang through the project's map of the
 * part of metal_stdlib it uses (tests/shader_ports/msl/metal_stdlib: half is
 * binary16, rounded after every operation; MSL's implicit conversions and
 * none of the vector conversions it refuses), run on every cosine
 * c = i/1024, i = -1..1025 for every material and model of the scene (the
 * thin film at thicknesses 0-1195 nm scattered over the cosines), and
 * compared with what the C runtime computes from the same manifest
 * (gen/model/encoded_scene.c, the evaluation of the C header).
 *
 * Four variants:
 *   g++ float      the port's default, every function in float, with
 *                  -fsingle-precision-constant (MSL has no double: 1.0 is a
 *                  float): max |MSL - C| <= 1e-5
 *   g++ half       FRESNEL_MSL_HALF: the mediump-safe functions in half, each
 *                  operation between halves rounded to binary16, each with a
 *                  float literal in float, as MSL does: within the model's
 *                  binary16 bound (fresnel_f16.h) beside the C binary32
 *                  runtime, and in [0, 1]
 *   clang float    clang has no -fsingle-precision-constant: an expression
 *                  with a float literal is evaluated in double and rounded
 *                  once, closer to exact: <= 1e-5
 *   clang half     as g++ half
 * and two more, the same functions reached another way: the scene's GLSL
 * (`fresnel gen --glsl`, after ports/glsl/fresnel.glsl) in a compute
 * shader that evaluates one material and model per dispatch, compiled by
 * glslangValidator, optimised by spirv-opt and translated to MSL by
 * SPIRV-Cross, then compiled by g++ through the same map and run:
 *   spirv-cross float  precision highp: within 1e-5
 *   spirv-cross half   precision mediump, spirv-opt --convert-relaxed-to-half
 *                      (what an engine that goes GLSL -> SPIR-V -> MSL gets
 *                      for half): within port_float16_bound
 * (not the thin film, whose tables a kernel would take as another buffer).
 * With the default scene the port functions no scene model calls
 * (port_checks.h) also run, in the float variants, within 1e-5. The table
 * at the end (NOTE table lines) is ports/README.md's.
 *
 * Usage: msl_host_test OUT_DIR MANIFEST IDENT SCENE.metal SCENE.glsl
 * (tests/shader_ports/test_msl.sh; OUT_DIR receives the C++ sources,
 * programs, compiler logs and outputs). Run from the top of the tree. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel_f16.h"
#include "common/cli.h"
#include "harness.h"
#include "port_checks.h"
#include "1_spectral/spectral.h"

enum { V_GCC, V_GCC_HALF, V_CLANG, V_CLANG_HALF, V_SX, V_SX_HALF, NVARIANTS };
static const struct variant {
    const char *name, *compile;
    int half, sx; /* sx: SPIRV-Cross's translation of the GLSL */
} variants[NVARIANTS] = {
    {"g++ float", "g++ -std=c++14 -O1 -fsingle-precision-constant", 0, 0},
    {"g++ half", "g++ -std=c++14 -O1 -fsingle-precision-constant -DFRESNEL_MSL_HALF", 1, 0},
    {"clang float", "clang++ -std=c++14 -O1", 0, 0},
    {"clang half", "clang++ -std=c++14 -O1 -DFRESNEL_MSL_HALF", 1, 0},
    {"spirv-cross float", "g++ -std=c++17 -O1 -fsingle-precision-constant -Wno-attributes -Wno-unknown-pragmas", 0, 1},
    {"spirv-cross half", "g++ -std=c++17 -O1 -fsingle-precision-constant -Wno-attributes -Wno-unknown-pragmas", 1, 1},
};

static int is_film(const scene *sc, int m) { return (model_of(sc->models[m].row)->offered & MODEL_FILM) != 0; }

/* The compute shader of the SPIRV-Cross variants: fr_in[0] selects
 * material x model (sel = m nmat + i), fr_in[1 + k] is cosine k. */
static int write_compute(const char *path, const scene *sc, const char *ident, const char *glsl, int half)
{
    FILE *f = fopen(path, "w");
    int i, m, first = 1;
    if (!f)
        return -1;
    if (port_append_file(f, "ports/glsl/prelude_450.glsl"))
        return fclose(f), -1;
    /* the film's storage buffer (unused here) off the kernel's bindings */
    fprintf(f, "precision %s float;\n#define FRESNEL_FILM_BINDING 2\n", half ? "mediump" : "highp");
    if (port_append_file(f, "ports/glsl/fresnel.glsl") || port_append_file(f, glsl))
        return fclose(f), -1;
    fputs("\nlayout(local_size_x = 1) in;\n"
          "layout(std430, set = 0, binding = 0) readonly buffer FrIn { highp float fr_in[]; };\n"
          "layout(std430, set = 0, binding = 1) writeonly buffer FrOut { highp float fr_out[]; };\n"
          "void main()\n{\n    int i = int(gl_GlobalInvocationID.x), sel = int(fr_in[0]);\n"
          "    highp float c = fr_in[1 + i];\n    vec3 r = vec3(-1.0);\n",
          f);
    for (m = 0; m < sc->model_count; m++)
        for (i = 0; i < sc->material_count && !is_film(sc, m); i++, first = 0)
            fprintf(f, "    %sif (sel == %d)\n        r = fresnel_%s_%s_%s_rgb(c);\n", first ? "" : "else ",
                    m * sc->material_count + i, ident, sc->materials[i], sc->models[m].ident);
    fputs("    fr_out[3 * i] = r.x;\n    fr_out[3 * i + 1] = r.y;\n    fr_out[3 * i + 2] = r.z;\n}\n", f);
    return fclose(f);
}

/* The host program around SPIRV-Cross's kernel main0: every material and
 * model but the film, every cosine, printed as write_program's lines. */
static int write_sx_program(const char *path, const scene *sc, const char *metal)
{
    FILE *f = fopen(path, "w");
    int nmat = sc->material_count;
    if (!f)
        return -1;
    fprintf(f, "// msl_host_test: SPIRV-Cross's MSL of the scene's GLSL\n#include \"%s\"\n#include <cstdio>\n\n"
               "int main()\n{\n    static float in[1 + %d], out[3 * %d];\n    static const int film[] = {",
            metal, NCOS, NCOS);
    for (int m = 0; m < sc->model_count; m++)
        fprintf(f, "%s%d", m ? ", " : "", is_film(sc, m));
    fprintf(f, "};\n    for (int k = 0; k < %d; k++)\n        in[1 + k] = float(k + (%d)) / 1024.0f;\n"
               "    for (int m = 0; m < %d; m++)\n        for (int mat = 0; mat < %d && !film[m]; mat++) {\n"
               "            in[0] = float(m * %d + mat);\n"
               "            for (int k = 0; k < %d; k++)\n"
               "                main0(*reinterpret_cast<const FrIn *>(in), *reinterpret_cast<FrOut *>(out), "
               "uint3(k, 0, 0));\n"
               "            for (int k = 0; k < %d; k++)\n"
               "                std::printf(\"%%d %%d %%d %%a %%a %%a\\n\", m, mat, k, (double)out[3 * k], "
               "(double)out[3 * k + 1], (double)out[3 * k + 2]);\n        }\n    return 0;\n}\n",
            NCOS, C_LO, sc->model_count, nmat, nmat, NCOS, NCOS);
    return fclose(f);
}

/* glslangValidator, spirv-opt (with --convert-relaxed-to-half for half),
 * spirv-val and spirv-cross --msl: base.comp to base.metal. 0, or -1 with
 * the failing command in cmd. */
static int sx_translate(const char *base, int half, char *cmd, size_t size)
{
    snprintf(cmd, size,
             "glslangValidator -V --target-env vulkan1.0 -S comp -o '%s.spv' '%s.comp' >'%s.sx.log' 2>&1 && "
             "spirv-opt %s-O '%s.spv' -o '%s.opt.spv' >>'%s.sx.log' 2>&1 && "
             "spirv-val --target-env vulkan1.0 '%s.opt.spv' >>'%s.sx.log' 2>&1 && "
             "spirv-cross --msl --msl-force-native-arrays '%s.opt.spv' --output '%s.metal' >>'%s.sx.log' 2>&1",
             base, base, base, half ? "--convert-relaxed-to-half " : "", base, base, base, base, base, base, base,
             base);
    return system(cmd) == 0 ? 0 : -1;
}

/* The C++ program: the port, the scene, and a main() printing every model
 * of every material at every cosine (hexadecimal floats, three per line),
 * then with funcs the port functions no scene model calls. */
static int write_program(const char *path, const scene *sc, const char *ident, const char *scene_path, int funcs)
{
    FILE *f = fopen(path, "w");
    int i, m, k;
    if (!f)
        return -1;
    fprintf(f, "// msl_host_test: scene %s\n#include \"fresnel.metal\"\n#include \"%s\"\n#include <cstdio>\n\n"
               "int main()\n{\n    for (int i = 0; i < %d; i++) {\n        float c = float(i + (%d)) / 1024.0;\n"
               "        float3 r;\n        (void)c;\n",
            ident, scene_path, NCOS, C_LO);
    for (m = 0; m < sc->model_count; m++)
        for (i = 0; i < sc->material_count; i++) {
            int film = (model_of(sc->models[m].row)->offered & MODEL_FILM) != 0;
            fprintf(f, "        r = fresnel_%s_%s_%s_rgb(c%s);\n", ident, sc->materials[i], sc->models[m].ident,
                    film ? ", " FILM_D : "");
            fprintf(f, "        std::printf(\"%%d %%d %%d %%a %%a %%a\\n\", %d, %d, i, (double)r.x, (double)r.y, "
                       "(double)r.z);\n",
                    m, i);
        }
    for (k = 0; funcs && k < NFUNCS; k++)
        fprintf(f, "        std::printf(\"f %%d %%d %%a\\n\", %d, i, (double)(%s));\n", k, port_funcs[k].expr);
    fprintf(f, "    }\n    return 0;\n}\n");
    return fclose(f);
}

int main(int argc, char **argv)
{
    static scene sc;
    static gen_context gc;
    static double worst[NVARIANTS][SCENE_MAX_MODELS], fworst[NVARIANTS][64];
    static int ran[NVARIANTS];
    char path[1300], exe[1200], cmd[8192], line[512], metal[512];
    const char *dir, *ident;
    material_params *params;
    spectrum *spectra;
    scene_model *models;
    float *ref;
    int i, m, vi, nmat, funcs, sx_models = 0;
    if (argc != 6) {
        fprintf(stderr, "usage: msl_host_test OUT_DIR MANIFEST IDENT SCENE.metal SCENE.glsl\n");
        return 2;
    }
    dir = argv[1];
    ident = argv[3];
    funcs = !strcmp(ident, "default");
    if (port_scene_load("msl", argv[2], &sc, &gc, &params, &spectra, &models))
        return harness_exit();
    nmat = sc.material_count;
    if (!(ref = malloc((size_t)3 * NCOS * (size_t)nmat * (size_t)sc.model_count * sizeof *ref)))
        return 1;
    if (port_scene_refs(&sc, &gc, params, spectra, models, ref)) {
        CHECK("msl: the scene's materials derive", 0, "%s", argv[2]);
        return harness_exit();
    }
    for (vi = 0; vi < NVARIANTS; vi++) {
        const struct variant *va = &variants[vi];
        char name[256];
        int bad = 0, count = 0;
        FILE *out;
        snprintf(path, sizeof path, "%s/%s_%d.cpp", dir, ident, vi);
        snprintf(exe, sizeof exe, "%s/%s_%d", dir, ident, vi);
        snprintf(name, sizeof name, "msl: %s, %s", ident, va->name);
        if (va->sx) {
            for (m = sx_models = 0; m < sc.model_count; m++)
                sx_models += !is_film(&sc, m);
            if (!sx_models)
                continue; /* the film alone */
            snprintf(metal, sizeof metal, "%s/%s_%d", dir, ident, vi);
            snprintf(path, sizeof path, "%s.comp", metal);
            if (write_compute(path, &sc, ident, argv[5], va->half)) {
                CHECK(name, 0, "cannot write %s", path);
                continue;
            }
            if (sx_translate(metal, va->half, cmd, sizeof cmd)) {
                CHECK(name, 0, "%s: see %s.sx.log", cmd, metal);
                continue;
            }
            snprintf(path, sizeof path, "%s_sx.cpp", metal);
            strcat(metal, ".metal");
            if (write_sx_program(path, &sc, metal)) {
                CHECK(name, 0, "cannot write %s", path);
                continue;
            }
        } else if (write_program(path, &sc, ident, argv[4], funcs && !va->half)) {
            CHECK(name, 0, "cannot write %s", path);
            continue;
        }
        snprintf(cmd, sizeof cmd, "%s -Wall -Wextra -Werror -Iports/msl -Itests/shader_ports/msl -I. '%s' -o '%s' >'%s.log' 2>&1",
                 va->compile, path, exe, exe);
        if (system(cmd) != 0) {
            CHECK(name, 0, "%s: see %s.log", cmd, exe);
            continue;
        }
        snprintf(cmd, sizeof cmd, "'%s' >'%s.out'", exe, exe);
        if (system(cmd) != 0) {
            CHECK(name, 0, "%s failed", exe);
            continue;
        }
        snprintf(path, sizeof path, "%s.out", exe);
        if (!(out = fopen(path, "r"))) {
            CHECK(name, 0, "cannot read %s", path);
            continue;
        }
        while (fgets(line, sizeof line, out)) {
            int mm, ii, k;
            double v[3], fv;
            if (sscanf(line, "f %d %d %la", &mm, &k, &fv) == 3 && mm >= 0 && mm < NFUNCS && k >= 0 && k < NCOS) {
                double d = port_func_diff(mm, fv, port_cosine(k));
                if (!(d <= fworst[vi][mm]))
                    fworst[vi][mm] = d;
                continue;
            }
            if (sscanf(line, "%d %d %d %la %la %la", &mm, &ii, &k, &v[0], &v[1], &v[2]) != 6 || mm < 0 ||
                mm >= sc.model_count || ii < 0 || ii >= nmat || k < 0 || k >= NCOS) {
                bad++;
                continue;
            }
            for (i = 0; i < 3; i++) {
                double d = fabs(v[i] - ref[3 * (((size_t)mm * nmat + ii) * NCOS + k) + i]);
                bad += !(v[i] >= 0.0 && v[i] <= 1.0);
                if (!(d <= worst[vi][mm]))
                    worst[vi][mm] = d;
            }
            count++;
        }
        fclose(out);
        ran[vi] = count == (va->sx ? sx_models : sc.model_count) * nmat * NCOS;
        CHECK(name, ran[vi] && bad == 0, "%d of %d lines read, %d results not in [0, 1] or malformed", count,
              (va->sx ? sx_models : sc.model_count) * nmat * NCOS, bad);
        for (m = 0; m < sc.model_count && ran[vi]; m++) {
            /* the half variants: the mediump-safe functions in half; the
             * others (and the tables, the film) in float whatever; through
             * SPIR-V's relaxed precision, the result in half too */
            double bound = va->sx && va->half ? port_float16_bound(&sc, m)
                         : va->half           ? port_half_bound(&sc, m)
                                              : HIGHP_BOUND;
            if (va->sx && is_film(&sc, m))
                continue;
            snprintf(name, sizeof name, "msl: %s %s, %d materials, %s", ident, sc.models[m].name, nmat, va->name);
            NOTE("%s: max |MSL - C| %.2g (bound %.2g)", name, worst[vi][m], bound);
            CHECK(name, worst[vi][m] <= bound, "max difference %.3g (bound %.3g)", worst[vi][m], bound);
        }
        for (m = 0; funcs && !va->half && m < NFUNCS; m++) {
            snprintf(name, sizeof name, "msl: %s, %s", port_funcs[m].expr, va->name);
            NOTE("%s: max |MSL - C|%s %.2g (bound %.2g)", name, port_funcs[m].rel ? " / max(|C|, 1)" : "",
                 fworst[vi][m], HIGHP_BOUND);
            CHECK(name, fworst[vi][m] <= HIGHP_BOUND, "max difference %.3g (bound %.3g)", fworst[vi][m], HIGHP_BOUND);
        }
    }
    for (m = 0; m < sc.model_count; m++) { /* the table's header: test_msl.sh */
        char cell[NVARIANTS][32];
        for (vi = 0; vi < NVARIANTS; vi++)
            port_cell(cell[vi], ran[vi] && !(variants[vi].sx && is_film(&sc, m)), worst[vi][m]);
        NOTE("table | %s | %s | %s | %s | %s | %s | %.2g | %s | %s | %.2g |", ident, sc.models[m].name, cell[0],
             cell[1], cell[2], cell[3], port_half_bound(&sc, m), cell[V_SX], cell[V_SX_HALF],
             port_float16_bound(&sc, m));
    }
    free(params);
    free(spectra);
    free(models);
    free(ref);
    return harness_exit();
}
