/* `fresnel gen --glsl` in a real GL pipeline: the default scene's GLSL
 * constants, compiled after ports/glsl/fresnel.glsl in GLSL 3.30 and ES 3.00,
 * evaluate on the GPU (OSMesa) to what the C runtime gives with the C header
 * generated from the same manifest. Built and run by tests/test_glsl_gen.sh. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fresnel.h"
#include "glctx.h"
#include "harness.h"
#include "scene_default.h"

#define W 64 /* c = (x + 0.5) / 64: exact in binary32 on both sides */

static char glsl_log[16384];

static GLuint program(const char *prelude, int es, int version, const char *port, const char *scene,
                      const char *expr)
{
    const char *parts[7];
    const char *vsrc = glctx_vertex_source(es, version);
    GLuint vs, fs;
    parts[0] = prelude;
    parts[1] = es ? "precision highp float;\n" : "";
    parts[2] = port;
    parts[3] = scene;
    parts[4] = "out highp vec4 fr_out;\nvoid main() {\n    highp float c = gl_FragCoord.x / 64.0;\n    fr_out = vec4(";
    parts[5] = expr;
    parts[6] = ", 1.0);\n}\n";
    if (!(fs = glctx_shader(GL_FRAGMENT_SHADER, parts, 7, glsl_log, sizeof glsl_log)))
        return 0;
    if (!(vs = glctx_shader(GL_VERTEX_SHADER, &vsrc, 1, glsl_log, sizeof glsl_log))) {
        glDeleteShader(fs);
        return 0;
    }
    return glctx_program(vs, fs, glsl_log, sizeof glsl_log);
}

static fresnel_rgb c_model(int which, float c)
{
    if (which == 0)
        return fresnel_lut_rgb(fresnel_default_cu_lut32, 32, c);
    if (which == 1)
        return fresnel_f82_rgb(fresnel_default_au_f0, fresnel_default_au_f82, c);
    if (which == 3)
        return fresnel_lut_cubic_rgb(fresnel_default_cr_lut16_cubic, 16, c);
    return fresnel_conductor_rgb(fresnel_default_al_eta, fresnel_default_al_kappa, c);
}

int main(int argc, char **argv)
{
    static const char *const exprs[4] = {"FRESNEL_LUT_ARRAY_RGB(fresnel_default_cu_lut32, 32, c)",
                                         "fresnel_f82_rgb(fresnel_default_au_f0, fresnel_default_au_f82, c)",
                                         "fresnel_conductor_rgb(fresnel_default_al_eta, fresnel_default_al_kappa, c)",
                                         "FRESNEL_LUT_CUBIC_ARRAY_RGB(fresnel_default_cr_lut16_cubic, 16, c)"};
    static const char *const names[4] = {"copper lut32", "gold f82", "aluminium exact", "chromium lut16-cubic"};
    static const struct {
        const char *prelude;
        int es, version;
    } dialects[2] = {{"prelude_330.glsl", 0, 330}, {"prelude_es300.glsl", 1, 300}};
    char err[256], path[1024];
    char *port, *scene, *prelude;
    glctx g;
    GLuint fbo, tex;
    int d, m, i, ch;
    if (argc != 3) {
        fprintf(stderr, "usage: glsl_gen_test PORT_DIR SCENE.glsl\n");
        return 2;
    }
    snprintf(path, sizeof path, "%s/fresnel.glsl", argv[1]);
    port = glctx_read_file(path);
    scene = glctx_read_file(argv[2]);
    if (!port || !scene || glctx_open(&g, W, 1, err, sizeof err)) {
        CHECK("glsl gen: context and sources", 0, "%s", port && scene ? err : "cannot read sources");
        return harness_exit();
    }
    fbo = glctx_float_target(W, 1, &tex);
    for (d = 0; d < 2; d++) {
        snprintf(path, sizeof path, "%s/%s", argv[1], dialects[d].prelude);
        prelude = glctx_read_file(path);
        for (m = 0; m < 4; m++) {
            static float out[W * 4];
            char name[160];
            double worst = 0.0;
            GLuint prog = prelude ? program(prelude, dialects[d].es, dialects[d].version, port, scene, exprs[m]) : 0;
            snprintf(name, sizeof name, "glsl gen: %s compiles and matches C in %s", names[m], dialects[d].prelude);
            if (!prog) {
                CHECK(name, 0, "compile/link failed:\n%s", glsl_log);
                continue;
            }
            glUseProgram(prog);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            glViewport(0, 0, W, 1);
            glctx_draw(&g);
            glReadPixels(0, 0, W, 1, GL_RGBA, GL_FLOAT, out);
            for (i = 0; i < W; i++) {
                fresnel_rgb v = c_model(m, (i + 0.5f) / W);
                float cv[3];
                cv[0] = v.r;
                cv[1] = v.g;
                cv[2] = v.b;
                for (ch = 0; ch < 3; ch++)
                    if (!(fabs(out[4 * i + ch] - cv[ch]) <= worst))
                        worst = fabs(out[4 * i + ch] - cv[ch]);
            }
            NOTE("%s: max |GPU highp - C| %.2g", name, worst);
            CHECK(name, worst <= 1e-5, "max difference %.3g", worst);
            glDeleteProgram(prog);
        }
        free(prelude);
    }
    glctx_close(&g);
    free(port);
    free(scene);
    return harness_exit();
}
