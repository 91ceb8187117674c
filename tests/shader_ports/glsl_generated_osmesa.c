/* `fresnel gen --glsl` in a real GL pipeline: a scene's generated GLSL,
 * compiled after ports/glsl/fresnel.glsl, evaluates on the GPU (OSMesa,
 * llvmpipe) to what the C runtime computes from the same manifest
 * (gen/model/encoded_scene.c, the evaluation `fresnel curve` and the report use),
 * for every material and model of the scene, in GLSL 3.30, ES 3.00 and
 * ES 1.00. ES 1.00 reads the LUT models from the packed RGBA8 texture that
 * `--tables` wrote (included here as FR_TEX_HEADER, the C header a
 * program uploads); ES 3.00 also runs that path with FRESNEL_LUT_ARRAYS 0.
 *
 * Bounds (highp): analytic models and const-array tables 1e-5, as the
 * port's own test, and the thin film too (thicknesses 0-1195 nm scattered
 * over the cosines) on each of its routes: its RGBA32F texture (GLSL 3.30,
 * ES 3.00 by texelFetch, ES 1.00 by texture2D at texel centres), its uniform block (ES 3.00, where the scene's tables fit 16 KiB)
 * and its storage buffer (GLSL 4.30), the GPU's exp standing for the C
 * runtime's polynomial. Texture tables: within 1e-5 of the C runtime on the
 * decoded 16-bit nodes, and within the quantisation bound of the C runtime
 * on the binary32 nodes: 2^-16 for linear interpolation, 1.25 * 2^-16 for
 * Catmull-Rom (the sum of its weights' magnitudes is at most 1.25), plus
 * 1e-6 of binary32 rounding. ES 1.00 without highp in fragment shaders
 * (FRESNEL_HIGHP forced to mediump): measured and bounded, see
 * MEDIUMP_BOUND. Built and run by tests/shader_ports/test_glsl_generated_osmesa.sh, once per scene. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "4_emit/emit_glsl.h"
#include "3_encode/encode.h"
#include "glctx.h"
#include "harness.h"
#include "port_scene.h"
#include "scene/scene.h"
#include "model/encoded_scene.h"
#include "1_spectral/spectral.h"

#include FR_TEX_HEADER

#define FILM_FLOATS ((int)(sizeof(fresnel_film) / sizeof(float))) /* the port's FRESNEL_FILM_FLOATS */
#define W 260 /* pixel x: c = (x - 1) / 256, from -1/256 to 1 + 2/256, exact in binary32 */
#define HIGHP_BOUND 1e-5
/* FRESNEL_HIGHP = mediump: the table position x (n - 1) in binary16 and
 * the binary16 result; measured at most 1.1e-3 here (NOTE lines: residual tables, where the
 * binary16 Schlick adds its own rounding), asserted with
 * the margin of the port's mediump bounds. */
#define MEDIUMP_BOUND 2.5e-3

/* The film reads its tables by the texture route (330, es300, es100), the uniform
 * block (FRESNEL_FILM_UNIFORM, where the tables fit GLES 3's 16 KiB) or
 * the storage buffer (FRESNEL_FILM_STORAGE, GLSL 4.30); film_only: a
 * variant for the film's route alone. A prelude starting with '#' is the
 * text itself, else a file of ports/glsl/. */
enum { V_330, V_ES300, V_ES100, V_ES300_TEX, V_ES100_MEDIUMP, V_UNIFORM, V_STORAGE, NVARIANTS };
static const struct variant {
    const char *name, *prelude, *defines;
    int es, version, texture, lut_only, film_only;
} variants[NVARIANTS] = {
    {"330", "prelude_330.glsl", "", 0, 330, 0, 0, 0},
    {"es300", "prelude_es300.glsl", "precision highp float;\n", 1, 300, 0, 0, 0},
    {"es100", "prelude_es100.glsl", "precision highp float;\n", 1, 100, 1, 0, 0},
    {"es300, FRESNEL_LUT_ARRAYS 0", "prelude_es300.glsl", "precision highp float;\n#define FRESNEL_LUT_ARRAYS 0\n", 1,
     300, 1, 1, 0},
    {"es100, FRESNEL_HIGHP mediump", "prelude_es100.glsl", "#define FRESNEL_HIGHP mediump\n", 1, 100, 1, 1, 0},
    {"es300, FRESNEL_FILM_UNIFORM", "prelude_es300.glsl", "precision highp float;\n#define FRESNEL_FILM_UNIFORM 1\n", 1,
     300, 0, 0, 1},
    {"430, FRESNEL_FILM_STORAGE", "#version 430\n", "#define FRESNEL_FILM_STORAGE 1\n", 0, 330, 0, 0, 1},
};

static char glsl_log[16384];

static GLuint program(const struct variant *v, const char *prelude, const char *port, const char *scene,
                      const char *body)
{
    const char *parts[6];
    const char *vsrc = glctx_vertex_source(v->es, v->version);
    GLuint vs, fs;
    parts[0] = prelude;
    parts[1] = v->defines;
    parts[2] = port;
    parts[3] = scene;
    parts[4] = v->version >= 300 ? "in highp vec2 fr_uv;\nout highp vec4 fr_out;\n#define FR_OUT fr_out\n"
                                 : "varying highp vec2 fr_uv;\n#define FR_OUT gl_FragColor\n";
    parts[5] = body;
    if (!(fs = glctx_shader(GL_FRAGMENT_SHADER, parts, 6, glsl_log, sizeof glsl_log)))
        return 0;
    if (!(vs = glctx_shader(GL_VERTEX_SHADER, &vsrc, 1, glsl_log, sizeof glsl_log))) {
        glDeleteShader(fs);
        return 0;
    }
    return glctx_program(vs, fs, glsl_log, sizeof glsl_log);
}

/* The thin film's thickness at pixel x, the same binary32 value in GLSL
 * and here: 0-1195 nm, scattered over x (every product exact). */
#define FILM_D_GLSL "mod(floor(fr_uv.x * 260.0) * 157.0, 256.0) * 4.6875"
static float film_d(int x) { return (float)((x * 157) % 256) * 4.6875f; }

/* main(): row r of the viewport evaluates material r's function (the thin
 * film's at FILM_D_GLSL). */
static char *main_body(const scene *sc, const char *ident, const char *id, int film)
{
    size_t size = 4096 + (size_t)sc->material_count * 256;
    char *b = malloc(size);
    size_t len;
    int i;
    if (!b)
        return NULL;
    len = (size_t)snprintf(b, size,
                           "void main() {\n    highp float c = (floor(fr_uv.x * %d.0) - 1.0) * (1.0 / 256.0);\n"
                           "    highp float row = floor(fr_uv.y * %d.0);\n    vec3 r = vec3(0.0);\n",
                           W, sc->material_count);
    for (i = 0; i < sc->material_count; i++)
        len += (size_t)snprintf(b + len, size - len, "    %sif (row < %d.5) r = fresnel_%s_%s_%s_rgb(c%s);\n",
                                i ? "else " : "", i, ident, sc->materials[i], id, film ? ", " FILM_D_GLSL : "");
    snprintf(b + len, size - len, "    FR_OUT = vec4(r, 1.0);\n}\n");
    return b;
}

int main(int argc, char **argv)
{
    static scene sc;
    static gen_context gc;
    char err[256], path[1024];
    char *port, *scene_src, *prelude[NVARIANTS];
    const char *ident;
    material_params *params;
    spectrum *spectra;
    scene_model *models; /* [material][model] */
    float *out;
    glctx g;
    GLuint fbo, target, tex, film_tex = 0, film_buf[2] = {0, 0};
    long film_bytes = 0;
    int i, m, v, x, ch, nmat;
    if (argc != 5) {
        fprintf(stderr, "usage: glsl_generated_osmesa PORT_DIR MANIFEST IDENT SCENE.glsl\n");
        return 2;
    }
    ident = argv[3];
    if (port_scene_load("glsl gen", argv[2], &sc, &gc, &params, &spectra, &models))
        return harness_exit();
    nmat = sc.material_count;
    if (!(out = malloc((size_t)W * (size_t)nmat * 4 * sizeof *out)))
        return 1;
    for (i = 0; i < nmat; i++) {
        material_source ms = scene_material(&sc, i);
        if (derive_parameters(&gc, &ms, sc.sigma, sc.n1, &spectra[i], &params[i]))
            return 1;
        for (m = 0; m < sc.model_count; m++)
            if (scene_model_prepare(&sc.models[m], sc.spacing, &spectra[i], &gc, &params[i],
                                    &models[i * sc.model_count + m]))
                return 1;
    }
    snprintf(path, sizeof path, "%s/fresnel.glsl", argv[1]);
    port = glctx_read_file(path);
    scene_src = glctx_read_file(argv[4]);
    if (!port || !scene_src || glctx_open(&g, W, nmat, err, sizeof err)) {
        CHECK("glsl gen: context and sources", 0, "%s", port && scene_src ? err : "cannot read sources");
        return harness_exit();
    }
    for (v = 0; v < NVARIANTS; v++) {
        snprintf(path, sizeof path, "%s/%s", argv[1], variants[v].prelude);
        prelude[v] = variants[v].prelude[0] == '#' ? strdup(variants[v].prelude) : glctx_read_file(path);
    }
    /* the film's tables (row i: material i), as --tables writes them, on
     * every route at once: texture unit 1, uniform and storage binding 0 */
    for (m = 0; m < sc.model_count; m++)
        if (models[m].film) {
            float *t = malloc((size_t)nmat * FILM_FLOATS * sizeof *t);
            if (!t)
                return 1;
            for (i = 0; i < nmat; i++)
                memcpy(t + (size_t)i * FILM_FLOATS, &models[i * sc.model_count + m].film->f32, sizeof(fresnel_film));
            film_bytes = (long)nmat * FILM_FLOATS * 4;
            glGenTextures(1, &film_tex);
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_2D, film_tex);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, FILM_FLOATS / 4, nmat, 0, GL_RGBA, GL_FLOAT, t);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glActiveTexture(GL_TEXTURE0);
            glGenBuffers(2, film_buf);
            glBindBuffer(GL_UNIFORM_BUFFER, film_buf[0]);
            glBufferData(GL_UNIFORM_BUFFER, film_bytes, t, GL_STATIC_DRAW);
            glBindBufferBase(GL_UNIFORM_BUFFER, 0, film_buf[0]);
            glBindBuffer(GL_SHADER_STORAGE_BUFFER, film_buf[1]);
            glBufferData(GL_SHADER_STORAGE_BUFFER, film_bytes, t, GL_STATIC_DRAW);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, film_buf[1]);
            free(t);
        }
    fbo = glctx_float_target(W, nmat, &target);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, FR_TEX_WIDTH, FR_TEX_HEIGHT, 0, GL_RGBA, GL_UNSIGNED_BYTE, FR_TEX);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    for (m = 0; m < sc.model_count; m++) {
        int film = models[m].film != NULL;
        char *body = main_body(&sc, ident, sc.models[m].ident, film);
        int is_lut = models[m].lut.n > 0, form = models[m].lut.form;
        for (v = 0; v < NVARIANTS && body; v++) {
            const struct variant *va = &variants[v];
            int texture = is_lut && va->texture, mediump = v == V_ES100_MEDIUMP;
            double worst = 0.0, worst_q = 0.0, bound, bound_q = HIGHP_BOUND;
            char name[256], sampler[128];
            GLuint prog;
            if ((va->lut_only && !is_lut) || (film && mediump) || (va->film_only && !film))
                continue; /* the film: highp only */
            if (v == V_UNIFORM && film_bytes > 16384) {
                NOTE("glsl gen: %s: the film's uniform route not run: %ld bytes of tables, over 16384", ident,
                     film_bytes);
                continue;
            }
            bound = mediump ? MEDIUMP_BOUND
                  : texture ? (form == LUT_CUBIC ? 1.25 : 1.0) * ldexp(1.0, -16) + 1e-6
                            : HIGHP_BOUND;
            snprintf(name, sizeof name, "glsl gen: %s %s, %d materials, %s%s", ident, sc.models[m].name, nmat, va->name,
                     is_lut ? (texture ? " (packed texture)" : " (const arrays)")
                            : (film && !va->film_only ? " (RGBA32F texture)" : ""));
            prog = prelude[v] ? program(va, prelude[v], port, scene_src, body) : 0;
            if (!prog) {
                CHECK(name, 0, "compile/link failed:\n%s", glsl_log);
                continue;
            }
            glUseProgram(prog);
            snprintf(sampler, sizeof sampler, "fresnel_%s_lut_texture", ident);
            if (texture) {
                GLint loc = glGetUniformLocation(prog, sampler);
                CHECK(name, loc >= 0, "no sampler uniform %s", sampler);
                glActiveTexture(GL_TEXTURE0);
                glBindTexture(GL_TEXTURE_2D, tex);
                glUniform1i(loc, 0);
            }
            if (film && !va->film_only) {
                char film_sampler[128];
                GLint loc;
                snprintf(film_sampler, sizeof film_sampler, "fresnel_%s_film_texture", ident);
                loc = glGetUniformLocation(prog, film_sampler);
                CHECK(name, loc >= 0, "no sampler uniform %s", film_sampler);
                glUniform1i(loc, 1);
            }
            if (v == V_UNIFORM) {
                char block[128];
                GLuint at;
                snprintf(block, sizeof block, "fresnel_%s_film_block", ident);
                at = glGetUniformBlockIndex(prog, block);
                CHECK(name, at != GL_INVALID_INDEX, "no uniform block %s", block);
                glUniformBlockBinding(prog, at, 0);
            }
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            glViewport(0, 0, W, nmat);
            glctx_draw(&g);
            glReadPixels(0, 0, W, nmat, GL_RGBA, GL_FLOAT, out);
            for (i = 0; i < nmat; i++) {
                const scene_model *sm = &models[i * sc.model_count + m];
                scene_model qm = *sm;
                float qtab[3 * SCENE_LUT_MAX];
                if (texture) { /* the nodes as the texture holds them */
                    int k;
                    for (k = 0; k < 3 * sm->lut.n; k++)
                        qtab[k] = (float)((emit_glsl_node_code(sm->lut.nodes[k]) - 16384) / 32768.0);
                    qm.lut.f32 = qtab;
                }
                for (x = 0; x < W; x++) {
                    float c = (float)(x - 1) / 256.0f, ref[3], refq[3];
                    const float *gpu = out + 4 * ((size_t)i * W + (size_t)x);
                    scene_model_eval(sm, c, ref);
                    scene_model_eval(&qm, c, refq);
                    if (film) {
                        model_rgb q = scene_model_rgb(sm);
                        fresnel_rgb v;
                        q.d_nm = film_d(x);
                        v = q.def->f32->scene(&q, c);
                        ref[0] = refq[0] = v.r, ref[1] = refq[1] = v.g, ref[2] = refq[2] = v.b;
                    }
                    for (ch = 0; ch < 3; ch++) {
                        double d = fabs(gpu[ch] - ref[ch]), dq = fabs(gpu[ch] - refq[ch]);
                        if (!(d <= worst))
                            worst = d;
                        if (!(dq <= worst_q))
                            worst_q = dq;
                    }
                }
            }
            if (texture && !mediump) {
                NOTE("%s: max |GPU - C| %.2g (bound %.2g), on the decoded nodes %.2g", name, worst, bound, worst_q);
                CHECK(name, worst <= bound && worst_q <= bound_q, "max difference %.3g (bound %.3g), decoded %.3g",
                      worst, bound, worst_q);
            } else {
                NOTE("%s: max |GPU - C| %.2g (bound %.2g)", name, worst, bound);
                CHECK(name, worst <= bound, "max difference %.3g (bound %.3g)", worst, bound);
            }
            glDeleteProgram(prog);
        }
        free(body);
    }
    /* The quantisation itself: every node of every table of the scene. */
    {
        double q = 0.0;
        for (i = 0; i < nmat * sc.model_count; i++)
            for (x = 0; x < 3 * models[i].lut.n; x++) {
                double d = fabs((emit_glsl_node_code(models[i].lut.nodes[x]) - 16384) / 32768.0 - models[i].lut.f32[x]);
                if (d > q)
                    q = d;
            }
        NOTE("glsl gen: %s: max |16-bit texture node - binary32 node| %.3g (2^-16 = %.3g)", ident, q, ldexp(1.0, -16));
        CHECK("glsl gen: texture nodes within 2^-16 of the binary32 tables", q <= ldexp(1.0, -16), "%.3g", q);
    }
    glDeleteTextures(1, &tex);
    if (film_bytes) {
        glDeleteTextures(1, &film_tex);
        glDeleteBuffers(2, film_buf);
    }
    glctx_close(&g);
    for (i = 0; i < nmat * sc.model_count; i++)
        scene_model_free(&models[i]);
    for (v = 0; v < NVARIANTS; v++)
        free(prelude[v]);
    free(models);
    free(params);
    free(spectra);
    free(out);
    free(port);
    free(scene_src);
    return harness_exit();
}
