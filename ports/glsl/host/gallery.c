/* make gallery: spheres of measured metals rendered with the GLSL port
 * through OSMesa, one per Fresnel model, next to a reference sphere shaded
 * with the spectral ground truth, and the difference of each from it.
 *
 *   gallery PORT_DIR OUT_DIR METAL...
 *
 * For each metal OUT_DIR must hold METAL.params.csv (`fresnel params`) and
 * METAL.curve.csv (`fresnel curve`, the ground truth gt_r, gt_g, gt_b over
 * theta). Writes OUT_DIR/METAL-MODEL.png, OUT_DIR/METAL-MODEL-diff.png,
 * OUT_DIR/METAL-reference.png, OUT_DIR/index.html, and prints per sphere
 * the largest and mean difference from the reference in 8-bit sRGB steps.
 *
 * Shading (Cook-Torrance with GGX, the set-up of Metzgar and Semwal's
 * renders): one white directional light, GGX distribution with Smith's
 * height-correlated visibility at roughness 0.35, F at the half-vector
 * angle; plus a sky/ground gradient environment seen in the mirror direction
 * with F at the view angle. Metals: no diffuse term. Linear radiance is
 * written to an RGBA32F target, clamped to [0, 1] and encoded as sRGB here.
 * The fragment shader is GLSL ES 3.00 with mediump default, as a mobile
 * renderer would ship it; fresnel.glsl keeps its highp functions highp. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glctx.h"
#include "png.h"

#define SIZE 160     /* sphere image, pixels */
#define REF_N 256    /* reference table nodes per channel */
#define LUT16_N 16
#define MAXCURVE 20000

enum { M_REF, M_SCHLICK, M_F82, M_LSK_COMP, M_GULBRANDSEN, M_COOK_TORRANCE, M_EXACT, M_LUT16, NMODELS };
static const char *const model_names[NMODELS] = {"reference", "schlick", "f82", "lsk-comp", "gulbrandsen",
                                                  "cook-torrance", "exact", "lut16"};
static const char *const model_notes[NMODELS] = {
    "spectral ground truth (fresnel curve) as a 256-node table",
    "F0",
    "F0, F82",
    "fitted eta, kappa; a, alpha",
    "r, g",
    "F0; one eta, kappa",
    "exact Fresnel on the fitted per-channel eta, kappa",
    "16-node table of the ground truth",
};

static const char frag_main[] =
    "in highp vec2 fr_uv;\n"
    "out highp vec4 fr_out;\n"
    "uniform int MODEL;\n"
    "uniform highp vec3 P0;\nuniform highp vec3 P1;\nuniform highp vec3 P2;\nuniform highp vec3 P3;\n"
    "uniform highp sampler2D LUT;\nuniform highp vec3 STRIP_REF;\nuniform highp vec3 STRIP_16;\n"
    "highp vec3 fresnel_of(highp float c) {\n"
    "    if (MODEL == 0) return fresnel_lut_rgb(LUT, STRIP_REF, 256.0, c);\n"
    "    if (MODEL == 1) return fresnel_schlick_rgb(P0, c);\n"
    "    if (MODEL == 2) return fresnel_f82_rgb(P0, P1, c);\n"
    "    if (MODEL == 3) return fresnel_lsk_comp_rgb(P0, P1, P2, P3, c);\n"
    "    if (MODEL == 4) return fresnel_gulbrandsen_rgb(P0, P1, c);\n"
    "    if (MODEL == 5) return fresnel_cook_torrance_rgb(P0, P1.x, P1.y, c);\n"
    "    if (MODEL == 6) return fresnel_conductor_rgb(P0, P1, c);\n"
    "    return fresnel_lut_rgb(LUT, STRIP_16, 16.0, c);\n"
    "}\n"
    "highp vec3 environment(highp vec3 d) {\n"
    "    highp float t = clamp(0.5 + 0.5 * d.y, 0.0, 1.0);\n"
    "    return vec3(0.16, 0.13, 0.10) + t * t * (vec3(0.75, 0.85, 1.0) - vec3(0.16, 0.13, 0.10));\n"
    "}\n"
    "void main() {\n"
    "    highp vec2 p = fr_uv * 2.0 - 1.0;\n"
    "    highp float r2 = dot(p, p);\n"
    "    if (r2 > 1.0) { fr_out = vec4(0.045, 0.045, 0.05, 1.0); return; }\n"
    "    highp vec3 n = vec3(p, sqrt(1.0 - r2));\n"
    "    highp vec3 v = vec3(0.0, 0.0, 1.0);\n"
    "    highp vec3 l = normalize(vec3(-0.45, 0.55, 0.7));\n"
    "    highp vec3 h = normalize(l + v);\n"
    "    highp float nv = max(n.z, 1e-4), nl = max(dot(n, l), 0.0), nh = max(dot(n, h), 0.0);\n"
    "    highp float a = 0.35 * 0.35, a2 = a * a;\n"
    "    highp float dd = nh * nh * (a2 - 1.0) + 1.0;\n"
    "    highp float D = a2 / (3.14159265 * dd * dd);\n"
    "    highp float V = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2) + 1e-7);\n"
    "    highp vec3 spec = D * V * nl * 3.0 * fresnel_of(dot(v, h));\n"
    "    highp vec3 env = environment(reflect(-v, n)) * fresnel_of(nv);\n"
    "    fr_out = vec4(spec + env, 1.0);\n"
    "}\n";

struct material {
    const char *id;
    float f0[3], f82[3], eta_fit[3], kappa_fit[3], lsk_a[3], lsk_alpha[3], gr[3], gg[3], ct_eta, ct_kappa;
    float ref[3 * REF_N], lut16[3 * LUT16_N];
};

/* Reads "name,r,g,b" lines of `fresnel params`. */
static int load_params(const char *path, struct material *m)
{
    char line[512];
    FILE *f = fopen(path, "r");
    int found = 0;
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        char name[64];
        float v[3];
        if (line[0] == '#' || sscanf(line, "%63[^,],%f,%f,%f", name, &v[0], &v[1], &v[2]) != 4)
            continue;
#define TAKE(key, dst)                                   \
    if (!strcmp(name, key)) {                            \
        memcpy(dst, v, sizeof v);                        \
        found++;                                         \
    }
        TAKE("f0", m->f0)
        TAKE("f82", m->f82)
        TAKE("eta_fit", m->eta_fit)
        TAKE("kappa_fit", m->kappa_fit)
        TAKE("lsk_a", m->lsk_a)
        TAKE("lsk_alpha", m->lsk_alpha)
        TAKE("gulbrandsen_r", m->gr)
        TAKE("gulbrandsen_g", m->gg)
#undef TAKE
        if (!strcmp(name, "cook_torrance_eta")) {
            m->ct_eta = v[0];
            found++;
        }
        if (!strcmp(name, "cook_torrance_kappa")) {
            m->ct_kappa = v[0];
            found++;
        }
    }
    fclose(f);
    return found == 10 ? 0 : -1;
}

/* Ground truth over theta (uniform from 0 to 90 degrees, as `fresnel curve`
 * writes it) resampled into tables of n nodes uniform in sqrt(c), the
 * layout of fresnel_lut_rgb (red nodes, then green, then blue). */
static float curve_theta[MAXCURVE], curve_gt[MAXCURVE][3];
static int curve_n;

static int load_curve(const char *path)
{
    char line[4096];
    FILE *f = fopen(path, "r");
    int col_gt = -1;
    curve_n = 0;
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f) && curve_n < MAXCURVE) {
        char *tok, *save = line;
        int col = 0;
        float th = 0.0f, gt[3] = {0, 0, 0};
        if (line[0] == '#')
            continue;
        if (col_gt < 0) { /* the header names the columns */
            for (tok = strtok(save, ",\n"); tok; tok = strtok(NULL, ",\n"), col++)
                if (!strcmp(tok, "gt_r"))
                    col_gt = col;
            if (col_gt < 0)
                break;
            continue;
        }
        for (tok = strtok(save, ",\n"); tok; tok = strtok(NULL, ",\n"), col++) {
            if (col == 0)
                th = strtof(tok, NULL);
            else if (col >= col_gt && col < col_gt + 3)
                gt[col - col_gt] = strtof(tok, NULL);
        }
        curve_theta[curve_n] = th;
        memcpy(curve_gt[curve_n], gt, sizeof gt);
        curve_n++;
    }
    fclose(f);
    return col_gt >= 0 && curve_n >= 2 ? 0 : -1;
}

static void curve_table(float *table, int n)
{
    int i, ch;
    for (i = 0; i < n; i++) {
        double x = i / (double)(n - 1);
        double th = acos(x * x) * 180.0 / 3.14159265358979323846;
        double pos = th / 90.0 * (curve_n - 1);
        int j = (int)pos;
        double t;
        if (j >= curve_n - 1)
            j = curve_n - 2;
        t = pos - j;
        for (ch = 0; ch < 3; ch++)
            table[ch * n + i] = (float)(curve_gt[j][ch] + t * (curve_gt[j + 1][ch] - curve_gt[j][ch]));
    }
}

static unsigned char srgb8(float x)
{
    double v = x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0;
    v = v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
    return (unsigned char)lrint(v * 255.0);
}

static int set_material_uniforms(GLuint prog, const struct material *m, int model)
{
    const float zero[3] = {0, 0, 0};
    const float *p[4] = {zero, zero, zero, zero};
    float ct[3];
    switch (model) {
    case M_SCHLICK:
        p[0] = m->f0;
        break;
    case M_F82:
        p[0] = m->f0;
        p[1] = m->f82;
        break;
    case M_LSK_COMP:
        p[0] = m->eta_fit;
        p[1] = m->kappa_fit;
        p[2] = m->lsk_a;
        p[3] = m->lsk_alpha;
        break;
    case M_GULBRANDSEN:
        p[0] = m->gr;
        p[1] = m->gg;
        break;
    case M_COOK_TORRANCE:
        ct[0] = m->ct_eta;
        ct[1] = m->ct_kappa;
        ct[2] = 0.0f;
        p[0] = m->f0;
        p[1] = ct;
        break;
    case M_EXACT:
        p[0] = m->eta_fit;
        p[1] = m->kappa_fit;
        break;
    default:
        break;
    }
    glUniform1i(glGetUniformLocation(prog, "MODEL"), model);
    glUniform3fv(glGetUniformLocation(prog, "P0"), 1, p[0]);
    glUniform3fv(glGetUniformLocation(prog, "P1"), 1, p[1]);
    glUniform3fv(glGetUniformLocation(prog, "P2"), 1, p[2]);
    glUniform3fv(glGetUniformLocation(prog, "P3"), 1, p[3]);
    return 0;
}

/* One picture for README.md: chromium (Schlick's worst metal) as the
 * reference, Schlick, the F82 model and a 16-node table, each downscaled 2x
 * (a box filter on the linear values) so the uncompressed PNG stays small. */
static int write_strip(const char *out_dir, float (*img)[SIZE * SIZE * 4])
{
    static const int shown[4] = {M_REF, M_SCHLICK, M_F82, M_LUT16};
    enum { H = SIZE / 2, WS = 4 * H };
    static unsigned char strip[H * WS * 3];
    char path[1024];
    int k, y, x, ch;
    for (k = 0; k < 4; k++)
        for (y = 0; y < H; y++)
            for (x = 0; x < H; x++)
                for (ch = 0; ch < 3; ch++) {
                    const float *f = img[shown[k]];
                    /* GL rows bottom to top; PNG rows top to bottom */
                    int gy = SIZE - 2 - 2 * y, gx = 2 * x;
                    float v = 0.25f * (f[(gy * SIZE + gx) * 4 + ch] + f[(gy * SIZE + gx + 1) * 4 + ch] +
                                       f[((gy + 1) * SIZE + gx) * 4 + ch] + f[((gy + 1) * SIZE + gx + 1) * 4 + ch]);
                    strip[(y * WS + k * H + x) * 3 + ch] = srgb8(v);
                }
    snprintf(path, sizeof path, "%s/readme-cr.png", out_dir);
    if (png_write_rgb8(path, WS, H, strip) != 0) {
        fprintf(stderr, "gallery: cannot write %s\n", path);
        return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    static float img[NMODELS][SIZE * SIZE * 4];
    static unsigned char rgb[SIZE * SIZE * 3], ref8[SIZE * SIZE * 3];
    const char *port_dir, *out_dir;
    char path[1024], log[16384], err[256];
    char *port, *prelude;
    const char *parts[3], *vsrc;
    struct material *mats;
    int nmat, mi, model, i, ch;
    glctx g;
    GLuint fbo, fbo_tex, lut_tex, prog, vs, fs;
    float *lut_data;
    FILE *html;
    if (argc < 4) {
        fprintf(stderr, "usage: gallery PORT_DIR OUT_DIR METAL...\n");
        return 2;
    }
    port_dir = argv[1];
    out_dir = argv[2];
    nmat = argc - 3;
    mats = calloc((size_t)nmat, sizeof *mats);
    lut_data = calloc((size_t)nmat * 2 * 3 * REF_N, sizeof(float));
    if (!mats || !lut_data)
        return 1;
    for (mi = 0; mi < nmat; mi++) {
        struct material *m = &mats[mi];
        m->id = argv[3 + mi];
        snprintf(path, sizeof path, "%s/%s.params.csv", out_dir, m->id);
        if (load_params(path, m) != 0) {
            fprintf(stderr, "gallery: %s: cannot read the parameters (fresnel params output)\n", path);
            return 1;
        }
        snprintf(path, sizeof path, "%s/%s.curve.csv", out_dir, m->id);
        if (load_curve(path) != 0) {
            fprintf(stderr, "gallery: %s: cannot read the ground truth (fresnel curve output)\n", path);
            return 1;
        }
        curve_table(m->ref, REF_N);
        curve_table(m->lut16, LUT16_N);
        /* texture rows 2 mi (reference) and 2 mi + 1 (16 nodes), 3 REF_N wide */
        memcpy(lut_data + (size_t)(2 * mi) * 3 * REF_N, m->ref, sizeof m->ref);
        memcpy(lut_data + (size_t)(2 * mi + 1) * 3 * REF_N, m->lut16, sizeof m->lut16);
    }

    snprintf(path, sizeof path, "%s/fresnel.glsl", port_dir);
    port = glctx_read_file(path);
    snprintf(path, sizeof path, "%s/prelude_es300.glsl", port_dir);
    prelude = glctx_read_file(path);
    if (!port || !prelude) {
        fprintf(stderr, "gallery: cannot read %s/fresnel.glsl or prelude_es300.glsl\n", port_dir);
        return 1;
    }
    if (glctx_open(&g, SIZE, SIZE, err, sizeof err) != 0) {
        fprintf(stderr, "gallery: %s\n", err);
        return 1;
    }
    fbo = glctx_float_target(SIZE, SIZE, &fbo_tex);
    if (!fbo) {
        fprintf(stderr, "gallery: RGBA32F framebuffer incomplete\n");
        return 1;
    }
    parts[0] = prelude;
    parts[1] = port;
    parts[2] = frag_main;
    fs = glctx_shader(GL_FRAGMENT_SHADER, parts, 3, log, sizeof log);
    vsrc = glctx_vertex_source(1, 300);
    vs = fs ? glctx_shader(GL_VERTEX_SHADER, &vsrc, 1, log, sizeof log) : 0;
    prog = vs ? glctx_program(vs, fs, log, sizeof log) : 0;
    if (!prog) {
        fprintf(stderr, "gallery: shader: %s\n", log);
        return 1;
    }
    glActiveTexture(GL_TEXTURE0);
    lut_tex = glctx_r32f_texture(3 * REF_N, 2 * nmat, lut_data);
    glUseProgram(prog);
    glUniform1i(glGetUniformLocation(prog, "LUT"), 0);
    glViewport(0, 0, SIZE, SIZE);

    snprintf(path, sizeof path, "%s/index.html", out_dir);
    html = fopen(path, "w");
    if (!html) {
        fprintf(stderr, "gallery: cannot write %s\n", path);
        return 1;
    }
    fprintf(html, "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Fresnel models, GLSL port</title>\n"
                  "<style>body{font-family:sans-serif;background:#222;color:#ddd}td{text-align:center;"
                  "vertical-align:top;padding:4px;font-size:12px}img{display:block;margin:auto}"
                  "th{font-size:13px}</style></head><body>\n"
                  "<h1>Fresnel models through the GLSL port (OSMesa llvmpipe, GLSL ES 3.00, mediump default)</h1>\n"
                  "<p>Cook&ndash;Torrance, GGX (roughness 0.35), one directional light and a sky/ground environment. "
                  "Each model's sphere, and below it |model &minus; reference| in 8-bit sRGB steps, "
                  "multiplied by 8. The numbers are the largest and mean difference over the sphere, in 8-bit "
                  "sRGB steps. Made by <code>make gallery</code>.</p>\n<table>\n<tr><th>metal</th>");
    for (model = 0; model < NMODELS; model++)
        fprintf(html, "<th>%s<br><small>%s</small></th>", model_names[model], model_notes[model]);
    fprintf(html, "</tr>\n");
    printf("gallery: largest / mean |model - reference| over the sphere, 8-bit sRGB steps\n%-8s", "metal");
    for (model = 1; model < NMODELS; model++)
        printf(" %14s", model_names[model]);
    printf("\n");

    for (mi = 0; mi < nmat; mi++) {
        const struct material *m = &mats[mi];
        const float sref[3] = {0.5f / (3 * REF_N), (2 * mi + 0.5f) / (2 * nmat), 1.0f / (3 * REF_N)};
        const float s16[3] = {0.5f / (3 * REF_N), (2 * mi + 1.5f) / (2 * nmat), 1.0f / (3 * REF_N)};
        glUniform3fv(glGetUniformLocation(prog, "STRIP_REF"), 1, sref);
        glUniform3fv(glGetUniformLocation(prog, "STRIP_16"), 1, s16);
        fprintf(html, "<tr><th>%s</th>", m->id);
        printf("%-8s", m->id);
        for (model = 0; model < NMODELS; model++) {
            int y, x, maxd = 0;
            long sumd = 0;
            set_material_uniforms(prog, m, model);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            glctx_draw(&g);
            glReadPixels(0, 0, SIZE, SIZE, GL_RGBA, GL_FLOAT, img[model]);
            /* GL rows run bottom to top, PNG rows top to bottom */
            for (y = 0; y < SIZE; y++)
                for (x = 0; x < SIZE; x++)
                    for (ch = 0; ch < 3; ch++)
                        rgb[(y * SIZE + x) * 3 + ch] = srgb8(img[model][((SIZE - 1 - y) * SIZE + x) * 4 + ch]);
            snprintf(path, sizeof path, "%s/%s-%s.png", out_dir, m->id, model_names[model]);
            if (png_write_rgb8(path, SIZE, SIZE, rgb) != 0) {
                fprintf(stderr, "gallery: cannot write %s\n", path);
                return 1;
            }
            if (model == M_REF) {
                memcpy(ref8, rgb, sizeof rgb);
                fprintf(html, "<td><img src=\"%s-%s.png\" width=%d height=%d alt=\"\"></td>", m->id,
                        model_names[model], SIZE, SIZE);
                continue;
            }
            for (i = 0; i < SIZE * SIZE * 3; i++) {
                int d = abs((int)rgb[i] - (int)ref8[i]);
                if (d > maxd)
                    maxd = d;
                sumd += d;
                rgb[i] = (unsigned char)(d * 8 > 255 ? 255 : d * 8);
            }
            snprintf(path, sizeof path, "%s/%s-%s-diff.png", out_dir, m->id, model_names[model]);
            if (png_write_rgb8(path, SIZE, SIZE, rgb) != 0) {
                fprintf(stderr, "gallery: cannot write %s\n", path);
                return 1;
            }
            fprintf(html, "<td><img src=\"%s-%s.png\" width=%d height=%d alt=\"\">"
                          "<img src=\"%s-%s-diff.png\" width=%d height=%d alt=\"\">max %d, mean %.2f</td>",
                    m->id, model_names[model], SIZE, SIZE, m->id, model_names[model], SIZE, SIZE, maxd,
                    (double)sumd / (SIZE * SIZE * 3));
            printf(" %7d / %5.2f", maxd, (double)sumd / (SIZE * SIZE * 3));
        }
        fprintf(html, "</tr>\n");
        printf("\n");
        if (!strcmp(m->id, "cr") && write_strip(out_dir, img) != 0)
            return 1;
    }
    fprintf(html, "</table>\n<p>Parameters: <code>fresnel params --material ID</code>; ground truth: "
                  "<code>fresnel curve --material ID --samples 4097</code> (sRGB, Gaussian window 25 nm); "
                  "shaders: ports/glsl/fresnel.glsl.</p>\n</body></html>\n");
    fclose(html);
    glDeleteProgram(prog);
    glDeleteTextures(1, &lut_tex);
    glDeleteTextures(1, &fbo_tex);
    glDeleteFramebuffers(1, &fbo);
    glctx_close(&g);
    free(port);
    free(prelude);
    free(mats);
    free(lut_data);
    printf("gallery: wrote %s/index.html\n", out_dir);
    return 0;
}
