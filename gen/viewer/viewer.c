/* `fresnel viewer`: one self-contained HTML page that renders a scene's
 * materials with every model of the scene beside the spectral reference
 * (Metzgar & Semwal's WebGL application [MS18]). The page template
 * (ports/webgl/viewer.html) and the GLSL port (ports/glsl/fresnel.glsl) are
 * embedded in the tool at build time (embed.sh); this file fills the
 * template's slots with the scene's GLSL (`fresnel gen --glsl`), a
 * dispatcher over its materials and models, and the data the page plots and
 * tests against: the reference table, the C runtime's curves and the
 * CIEDE2000 figures of the report's measure. */
#include "viewer/viewer.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/cli.h"
#include "common/reference_film.h"
#include "common/reference.h"
#include "4_emit/emit.h"
#include "4_emit/emit_glsl.h"
#include "bench/bench.h"
#include "report/report.h"
#include "model/encoded_scene.h"

#define WHERE "fresnel viewer"

extern const unsigned char viewer_page[];      /* ports/webgl/viewer.html */
extern const unsigned char viewer_glsl_port[]; /* ports/glsl/fresnel.glsl */

/* The curves' angles: theta = 0, 0.5, ..., 90 degrees, as `fresnel curve
 * --samples VIEWER_ANGLES` prints them. */
#define VIEWER_ANGLES 181
static double viewer_cos(int k)
{
    return k == VIEWER_ANGLES - 1 ? 0.0 : cos(90.0 * k / (VIEWER_ANGLES - 1) * (3.14159265358979323846 / 180.0));
}

/* ---- text into the page, escaped for where it lands ---- */

/* A JSON string inside the page's <script>: quotes, backslashes and control
 * characters escaped as JSON requires; '<', '>' and '&' as \u escapes so
 * that no "</script>" or "<!--" can end or bend the element; U+2028 and
 * U+2029 (line terminators in older JavaScript) escaped too. */
static void put_json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c < 0x20 || c == 0x7f || c == '<' || c == '>' || c == '&')
            fprintf(f, "\\u%04x", c);
        else if (c == 0xe2 && (unsigned char)s[1] == 0x80 &&
                 ((unsigned char)s[2] == 0xa8 || (unsigned char)s[2] == 0xa9)) {
            fprintf(f, "\\u%04x", 0x2000 + ((unsigned char)s[2] - 0x80));
            s += 2;
        } else
            fputc(c, f);
    }
    fputc('"', f);
}

/* Text in an HTML element (the title and heading). */
static void put_html_text(FILE *f, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&#39;", f); break;
        default: fputc(*s, f);
        }
}

/* GLSL inside a <script type="x-shader/..."> element, which has no escape:
 * "<!--", "<script" and "</script" (any case) would end the element or
 * swallow the rest of the page, so a space follows their '<'. They can
 * only occur in the GLSL's comments (names of files and materials). */
static void put_script_text(FILE *f, const char *s)
{
    for (; *s; s++) {
        fputc(*s, f);
        if (*s == '<' && (!strncmp(s + 1, "!--", 3) || !strncasecmp(s + 1, "script", 6) ||
                          !strncasecmp(s + 1, "/script", 7)))
            fputc(' ', f);
    }
}

/* vec3 fresnel_select(int mat, int model, float c): the scene's functions
 * by index, in the scene's order of materials and models; with
 * FRESNEL_VIEWER_MATERIAL defined, only that material's (WebGL 1). */
/* The scene's thin-film model, or -1. */
static int film_row(const scene *sc)
{
    int m;
    for (m = 0; m < sc->model_count; m++)
        if (model_of(sc->models[m].row)->offered & MODEL_FILM)
            return m;
    return -1;
}

double viewer_film_d(const scene *sc, int step)
{
    return sc->film_d_lo + (sc->film_d_hi - sc->film_d_lo) * step / (VIEWER_FILM_STEPS - 1);
}

/* The page's thin-film reference of material i: the film's spectral truth
 * (unclipped) at VIEWER_FILM_REF_NODES cosines uniform in sqrt(c) for each
 * thickness step; rgb[(step nodes + node) 3 + ch]. 0, or -1 when out of
 * memory. */
static int film_reference(const emit_loaded *l, int i, double *rgb)
{
    film_stack stack;
    int k, step;
    stack.n1 = l->es.params[i].n1;
    stack.film = NULL;
    stack.film_n = l->es.params[i].film_n;
    stack.substrate = l->es.spectra[i];
    for (k = 0; k < VIEWER_FILM_REF_NODES; k++) {
        double x = (double)k / (VIEWER_FILM_REF_NODES - 1);
        film_optics_table *t = film_truth_prepare(&stack, x * x);
        if (!t)
            return -1;
        for (step = 0; step < VIEWER_FILM_STEPS; step++)
            film_truth_at(t, &l->es.g->cm, &l->es.g->cs, viewer_film_d(l->sc, step),
                          rgb + 3 * (step * VIEWER_FILM_REF_NODES + k));
        free(t);
    }
    return 0;
}

/* vec3 fresnel_select(int mat, int model, float c): the scene's functions
 * by index, in the scene's order of materials and models, the thin film at
 * the slider's thickness (uniform u_film_d; FRESNEL_FILM is 0 only in a
 * WebGL 1 without highp in fragment shaders); with FRESNEL_VIEWER_MATERIAL defined,
 * only that material's (WebGL 1). */
static void write_select(FILE *f, const emit_loaded *l)
{
    int i, m;
    fprintf(f, "uniform FRESNEL_HIGHP float u_film_d;\nvec3 fresnel_select(int mat, int model, FRESNEL_HIGHP float c)\n{\n");
    for (i = 0; i < l->sc->material_count; i++) {
        fprintf(f, "#if !defined(FRESNEL_VIEWER_MATERIAL) || FRESNEL_VIEWER_MATERIAL == %d\n", i);
        fprintf(f, "    if (mat == %d) {\n", i);
        for (m = 0; m < l->sc->model_count; m++) {
            int film = (model_of(l->sc->models[m].row)->offered & MODEL_FILM) != 0;
            fprintf(f, "%s        if (model == %d)\n            return fresnel_%s_%s_%s_rgb(c%s);\n%s",
                    film ? "#if FRESNEL_FILM\n" : "", m, l->name, l->sc->materials[i], l->sc->models[m].ident,
                    film ? ", u_film_d" : "", film ? "#endif\n" : "");
        }
        fprintf(f, "    }\n#endif\n");
    }
    fprintf(f, "    return vec3(0.0);\n}\n");
}

static void put_rgb(FILE *f, const double v[3])
{
    fprintf(f, "[%.9g,%.9g,%.9g]", v[0], v[1], v[2]);
}

/* M = out.xyz_to_rgb x (scene RGB -> XYZ), column-major for uniformMatrix3fv. */
static int write_matrix(FILE *f, const gen_context *g, const lab_space *ls, const char *out_space)
{
    colour_space cs;
    int r, c, k;
    if (colour_space_load(g->dir, out_space, &g->cm, &cs))
        return CLI_BAD_INPUT;
    fprintf(f, "\"%s\":[", out_space);
    for (c = 0; c < 3; c++)
        for (r = 0; r < 3; r++) {
            double v = 0.0;
            for (k = 0; k < 3; k++)
                v += cs.xyz_to_rgb[r][k] * ls->rgb_to_xyz[k][c];
            fprintf(f, "%s%.9g", c + r ? "," : "", v);
        }
    fprintf(f, "]");
    return 0;
}

/* What one call costs: the binary32 RGB evaluation timed on this host
 * (the report's timing: median of 3 batches of 2^16), and, given a `make
 * cross-count` output, the Q15 function's instructions on the Cortex-M0. */
static void write_cost(FILE *f, const emit_loaded *l, int m, const char *cross_path)
{
    const scene_model *sm = encoded_scene_model(&l->es, 0, m);
    model_rgb q = scene_model_rgb(sm);
    double ns = report_time(&number_types[TYPE_F32], &q, 1 << 16, 3), m0 = NAN;
    if (cross_path && sm->def->cross_row)
        m0 = report_m0_count(cross_path, sm->def->cross_row);
    char cost[512] = "";
    size_t used = 0;
    if (!isnan(ns))
        used = (size_t)snprintf(cost, sizeof cost, "%.1f ns per RGB call here (binary32, %s)", ns, bench_compiler());
    if (!isnan(m0) && used < sizeof cost)
        snprintf(cost + used, sizeof cost - used, "; %.0f instructions per %s on the Cortex-M0 (Q15)", m0,
                 model_of(l->sc->models[m].row)->offered & MODEL_FILM ? "RGB call" : "channel");
    put_json_string(f, cost);
}

/* The packed LUT texture (GLSL ES 1.00's tables, emit_glsl.c) as JSON:
 * {"w":W,"h":H,"data":[bytes]} from the C header the GLSL emitter writes,
 * or null for a scene without tables. */
static int write_lut_texture(FILE *f, const char *tex)
{
    const char *w = tex ? strstr(tex, "_LUT_TEXTURE_WIDTH ") : NULL, *h = tex ? strstr(tex, "_LUT_TEXTURE_HEIGHT ") : NULL;
    const char *p = tex ? strstr(tex, "= {") : NULL;
    long count = 0;
    if (!w || !h || !p) {
        fputs("null", f);
        return 0;
    }
    fprintf(f, "{\"w\":%ld,\"h\":%ld,\"data\":[", strtol(w + 19, NULL, 10), strtol(h + 20, NULL, 10));
    for (p += 3; *p && *p != '}'; p++)
        if (*p >= '0' && *p <= '9') {
            char *end;
            long v = strtol(p, &end, 10);
            fprintf(f, "%s%ld", count++ ? "," : "", v);
            p = end - 1;
        }
    fputs("]}", f);
    return 0;
}

/* The film's peers on material i (gen/common/reference_film.h; the
 * viewer's GLSL runs their binary32 transcriptions, gen/bench/peers.h):
 * their inputs, KHR_materials_iridescence's the material's F0 under the
 * scene's gamut policy and the polarised form's the eta, kappa fitted to the
 * material's RGB ground truth (the best of the report's three sets on
 * data/scenes/report.scene), absolute indices; and each one's CIEDE2000 on
 * the samples of the film's own numbers (every degree x every step against
 * the truth held to [0, 1]), in double precision. */
static void write_film_peers(FILE *f, const emit_loaded *l, const lab_space *ls, int i)
{
    const material_params *p = &l->es.params[i];
    const scene *sc = l->sc;
    double eta[3], kappa[3], sum[2] = {0.0, 0.0}, max[2] = {0.0, 0.0};
    film_stack stack;
    int step, a, ch, k;
    for (ch = 0; ch < 3; ch++)
        eta[ch] = p->eta_fit[ch] * p->n1, kappa[ch] = p->kappa_fit[ch] * p->n1;
    stack.n1 = p->n1;
    stack.film = NULL;
    stack.film_n = p->film_n;
    stack.substrate = l->es.spectra[i];
    for (step = 0; step < VIEWER_FILM_STEPS; step++)
        for (a = 0; a < REPORT_ANGLES; a++) {
            double c = report_cos(a), d = viewer_film_d(sc, step), truth[3], lt[3], rgb[2][3], lp[3], de;
            film_truth(&stack, &l->es.g->cm, &l->es.g->cs, c, d, truth);
            for (ch = 0; ch < 3; ch++)
                truth[ch] = ref_clamp(truth[ch], 0.0, 1.0);
            lab_space_lab(ls, truth, lt);
            ref_film_khr_iridescence(p->n1, p->film_n, d, c, p->f0, rgb[0]);
            ref_film_belcour_polarised(p->n1, p->film_n, d, c, eta, kappa, rgb[1]);
            for (k = 0; k < 2; k++) {
                for (ch = 0; ch < 3; ch++)
                    rgb[k][ch] = ref_clamp(rgb[k][ch], 0.0, 1.0);
                lab_space_lab(ls, rgb[k], lp);
                de = ciede2000(lt, lp);
                sum[k] += de;
                max[k] = fmax(max[k], de);
            }
        }
    fprintf(f, "%s{\"f0\":", i ? "," : "");
    put_rgb(f, p->f0);
    fprintf(f, ",\"eta\":");
    put_rgb(f, eta);
    fprintf(f, ",\"kappa\":");
    put_rgb(f, kappa);
    for (k = 0; k < 2; k++)
        fprintf(f, ",\"%s\":{\"mean\":%.6g,\"max\":%.6g}", k ? "polarised" : "khr",
                sum[k] / (VIEWER_FILM_STEPS * REPORT_ANGLES), max[k]);
    fprintf(f, "}");
}

/* "film": the thin film's slider, reference tables, its curves at every
 * step (binary32, every degree) and CIEDE2000 over angle and the steps
 * against the truth held to [0, 1]; null for a scene without it. */
static int write_film(FILE *f, const emit_loaded *l, const lab_space *ls)
{
    const scene *sc = l->sc;
    int fm = film_row(sc), i, k, step, a, ch;
    double *ref = malloc((size_t)VIEWER_FILM_STEPS * VIEWER_FILM_REF_NODES * 3 * sizeof *ref);
    double *de = calloc(2 * (size_t)sc->material_count, sizeof *de);
    if (fm < 0 || !ref || !de) {
        fputs("null", f);
        free(ref);
        free(de);
        return fm < 0 ? 0 : cli_oom(WHERE);
    }
    fprintf(f, "{\"model\":%d,\"steps\":%d,\"start\":%d,\"refN\":%d,\"d\":[", fm, VIEWER_FILM_STEPS,
            VIEWER_FILM_START, VIEWER_FILM_REF_NODES);
    for (step = 0; step < VIEWER_FILM_STEPS; step++)
        fprintf(f, "%s%.9g", step ? "," : "", (double)(float)viewer_film_d(sc, step));
    fprintf(f, "],\"n\":[");
    for (i = 0; i < sc->material_count; i++)
        fprintf(f, "%s%g", i ? "," : "", l->es.params[i].film_n);
    fprintf(f, "],\n\"reference\":[");
    for (i = 0; i < sc->material_count; i++) {
        if (film_reference(l, i, ref)) {
            free(ref);
            free(de);
            return cli_oom(WHERE);
        }
        for (k = 0; k < VIEWER_FILM_STEPS * VIEWER_FILM_REF_NODES * 3; k++)
            fprintf(f, "%s%.9g", i + k ? "," : "", ref[k]);
    }
    free(ref);
    /* curves[mat][step][degree] and the report's measure per material: every
     * degree x every step against the truth clipped per channel */
    fprintf(f, "],\n\"curves\":[");
    for (i = 0; i < sc->material_count; i++) {
        const scene_model *sm = encoded_scene_model(&l->es, i, fm);
        film_stack stack;
        double sum = 0.0, max = 0.0;
        stack.n1 = l->es.params[i].n1;
        stack.film = NULL;
        stack.film_n = l->es.params[i].film_n;
        stack.substrate = l->es.spectra[i];
        fprintf(f, "%s[", i ? "," : "");
        for (step = 0; step < VIEWER_FILM_STEPS; step++) {
            fprintf(f, "%s[", step ? "," : "");
            for (a = 0; a < REPORT_ANGLES; a++) {
                model_rgb q = scene_model_rgb(sm);
                fresnel_rgb v;
                double d[3], truth[3], l1[3], l2[3], de;
                q.d_nm = viewer_film_d(sc, step);
                v = q.def->f32->scene(&q, (float)report_cos(a));
                d[0] = v.r, d[1] = v.g, d[2] = v.b;
                fprintf(f, "%s", a ? "," : "");
                put_rgb(f, d);
                film_truth(&stack, &l->es.g->cm, &l->es.g->cs, report_cos(a), q.d_nm, truth);
                for (ch = 0; ch < 3; ch++)
                    truth[ch] = ref_clamp(truth[ch], 0.0, 1.0);
                lab_space_lab(ls, truth, l1);
                lab_space_lab(ls, d, l2);
                de = ciede2000(l1, l2);
                sum += de;
                max = fmax(max, de);
            }
            fprintf(f, "]");
        }
        fprintf(f, "]");
        de[2 * i] = sum / (VIEWER_FILM_STEPS * REPORT_ANGLES);
        de[2 * i + 1] = max;
    }
    fprintf(f, "],\n\"report\":[");
    for (i = 0; i < sc->material_count; i++)
        fprintf(f, "%s{\"mean\":%.6g,\"max\":%.6g}", i ? "," : "", de[2 * i], de[2 * i + 1]);
    fprintf(f, "],\n\"peers\":[");
    for (i = 0; i < sc->material_count; i++)
        write_film_peers(f, l, ls, i);
    /* the film's tables as `gen --tables` writes them (row i: material i),
     * for the scene GLSL's texture route */
    fprintf(f, "],\n\"table\":[");
    for (i = 0; i < sc->material_count; i++) {
        const float *t = &encoded_scene_model(&l->es, i, fm)->film->f32.freq[0];
        for (k = 0; k < (int)(sizeof(fresnel_film) / sizeof(float)); k++)
            fprintf(f, "%s%.9g", i + k ? "," : "", (double)t[k]);
    }
    fprintf(f, "]}");
    free(de);
    return 0;
}

static int write_data(FILE *f, const emit_loaded *l, const char *cross_path, const char *tex)
{
    const scene *sc = l->sc;
    const gen_context *g = l->es.g;
    lab_space ls;
    int i, m, k;
    lab_space_init(&ls, &g->cs);
    fputs("{\"scene\":", f);
    put_json_string(f, l->name);
    fputs(",\"space\":", f);
    put_json_string(f, sc->space);
    fputs(",\"gamut\":", f);
    put_json_string(f, gamut_policy_names[sc->gamut]);
    /* The page opens on the user's own material (the first `material ID =
     * FILE` line), else on the first. */
    for (i = 0; i < sc->material_count && !sc->material_file[i][0]; i++)
        ;
    fprintf(f, ",\"start\":%d", i < sc->material_count ? i : 0);
    fprintf(f, ",\"refN\":%d,\n\"materials\":[", VIEWER_REF_NODES);
    for (i = 0; i < sc->material_count; i++) {
        fprintf(f, "%s{\"id\":", i ? "," : "");
        put_json_string(f, sc->materials[i]);
        fputs(",\"name\":", f);
        put_json_string(f, l->es.params[i].info.name);
        fputs("}", f);
    }
    fprintf(f, "],\n\"models\":[");
    for (m = 0; m < sc->model_count; m++) {
        fputs(m ? "," : "", f);
        put_json_string(f, sc->models[m].name);
    }
    fprintf(f, "],\n\"theta\":[");
    for (k = 0; k < VIEWER_ANGLES; k++)
        fprintf(f, "%s%.6g", k ? "," : "", 90.0 * k / (VIEWER_ANGLES - 1));
    fprintf(f, "],\n\"cos\":[");
    for (k = 0; k < VIEWER_ANGLES; k++)
        fprintf(f, "%s%.9g", k ? "," : "", (double)(float)viewer_cos(k));
    fprintf(f, "],\n\"reference\":[");
    for (i = 0; i < sc->material_count; i++)
        for (k = 0; k < VIEWER_REF_NODES; k++) {
            double x = (double)k / (VIEWER_REF_NODES - 1), rgb[3];
            ground_truth(l->es.spectra[i], &g->cm, &g->cs, l->es.params[i].n1, x * x, rgb);
            fprintf(f, "%s%.9g,%.9g,%.9g", i + k ? "," : "", rgb[0], rgb[1], rgb[2]);
        }
    fprintf(f, "],\n\"unclipped\":[");
    for (i = 0; i < sc->material_count; i++) {
        fprintf(f, "%s[", i ? "," : "");
        for (k = 0; k < VIEWER_ANGLES; k++) {
            double rgb[3];
            ground_truth(l->es.spectra[i], &g->cm, &g->cs, l->es.params[i].n1, viewer_cos(k), rgb);
            fprintf(f, "%s", k ? "," : "");
            put_rgb(f, rgb);
        }
        fprintf(f, "]");
    }
    fprintf(f, "],\n\"curves\":[");
    for (i = 0; i < sc->material_count; i++) {
        fprintf(f, "%s[", i ? "," : "");
        for (m = 0; m < sc->model_count; m++) {
            const scene_model *sm = encoded_scene_model(&l->es, i, m);
            fprintf(f, "%s[", m ? "," : "");
            for (k = 0; k < VIEWER_ANGLES; k++) {
                float v[3];
                double d[3];
                scene_model_eval(sm, (float)viewer_cos(k), v);
                d[0] = v[0];
                d[1] = v[1];
                d[2] = v[2];
                fprintf(f, "%s", k ? "," : "");
                put_rgb(f, d);
            }
            fprintf(f, "]");
        }
        fprintf(f, "]");
    }
    /* The report's measure: CIEDE2000 over theta 0..90 in 1 degree steps,
     * binary32, against the truth under the policy and unclipped. */
    fprintf(f, "],\n\"report\":[");
    for (i = 0; i < sc->material_count; i++) {
        fprintf(f, "%s[", i ? "," : "");
        for (m = 0; m < sc->model_count; m++) {
            static double gt[REPORT_ANGLES][3], raw[REPORT_ANGLES][3], v[REPORT_ANGLES][3];
            double mean, rms, max, raw_mean, raw_max;
            const scene_model *sm = encoded_scene_model(&l->es, i, m);
            int a;
            for (a = 0; a < REPORT_ANGLES; a++) {
                float rgb[3];
                ground_truth_gamut(l->es.spectra[i], g, &l->es.params[i], report_cos(a), gt[a]);
                ground_truth(l->es.spectra[i], &g->cm, &g->cs, l->es.params[i].n1, report_cos(a), raw[a]);
                scene_model_eval(sm, (float)report_cos(a), rgb);
                v[a][0] = rgb[0];
                v[a][1] = rgb[1];
                v[a][2] = rgb[2];
            }
            report_curve_de(&ls, (const double(*)[3])gt, (const double(*)[3])v, &mean, &rms, &max);
            report_curve_de(&ls, (const double(*)[3])raw, (const double(*)[3])v, &raw_mean, &rms, &raw_max);
            fprintf(f, "%s{\"mean\":%.6g,\"max\":%.6g,\"raw_mean\":%.6g,\"raw_max\":%.6g}", m ? "," : "", mean, max,
                    raw_mean, raw_max);
        }
        fprintf(f, "]");
    }
    fprintf(f, "],\n\"cost\":[");
    for (m = 0; m < sc->model_count; m++) {
        fprintf(f, "%s", m ? "," : "");
        write_cost(f, l, m, cross_path);
    }
    fprintf(f, "],\n\"film\":");
    if ((k = write_film(f, l, &ls)))
        return k;
    fprintf(f, ",\n\"lutTexture\":");
    write_lut_texture(f, tex);
    fprintf(f, ",\n\"toXYZ\":[");
    for (k = 0; k < 9; k++) /* column-major */
        fprintf(f, "%s%.9g", k ? "," : "", ls.rgb_to_xyz[k % 3][k / 3]);
    fprintf(f, "],\n\"white\":[%.9g,%.9g,%.9g],\n\"toOutput\":{", ls.white[0], ls.white[1], ls.white[2]);
    if (write_matrix(f, g, &ls, "srgb"))
        return CLI_BAD_INPUT;
    fprintf(f, ",");
    if (write_matrix(f, g, &ls, "display-p3"))
        return CLI_BAD_INPUT;
    fprintf(f, "}}");
    return 0;
}

/* The template with each @@SLOT@@ replaced by what fill() writes. */
static int write_page(FILE *f, const emit_loaded *l, const char *glsl_scene, const char *tex, const char *cross_path)
{
    const char *p = (const char *)viewer_page;
    while (*p) {
        const char *slot = strstr(p, "@@");
        const char *end = slot ? strstr(slot + 2, "@@") : NULL;
        size_t len;
        int status = 0;
        if (!slot || !end) {
            fputs(p, f);
            break;
        }
        fwrite(p, 1, (size_t)(slot - p), f);
        len = (size_t)(end - slot - 2);
        if (len == 5 && !strncmp(slot + 2, "TITLE", len)) {
            char title[256];
            snprintf(title, sizeof title, "Fresnel viewer: scene %s, %s, gamut %s", l->name, l->sc->space,
                     gamut_policy_names[l->sc->gamut]);
            put_html_text(f, title);
        } else if (len == 9 && !strncmp(slot + 2, "GLSL_PORT", len))
            put_script_text(f, (const char *)viewer_glsl_port);
        else if (len == 10 && !strncmp(slot + 2, "GLSL_SCENE", len))
            put_script_text(f, glsl_scene);
        else if (len == 11 && !strncmp(slot + 2, "GLSL_SELECT", len))
            write_select(f, l);
        else if (len == 4 && !strncmp(slot + 2, "DATA", len))
            status = write_data(f, l, cross_path, tex);
        else
            return cli_error(WHERE, "the page template has an unknown slot '%.*s'", (int)len, slot + 2);
        if (status)
            return status;
        p = end + 2;
    }
    return 0;
}

int viewer_write(const char *manifest, const char *out_dir, const char *dir_option, const char *cross_path)
{
    emit_loaded l;
    cli_outfile out;
    char *glsl = NULL, *tex = NULL, path[CLI_PATH_MAX];
    size_t glsl_len = 0, tex_len = 0;
    FILE *mem, *tex_mem;
    int status, m, made_dir = 0;
    if ((status = emit_load(manifest, dir_option, emit_backend_find("--glsl"), &l)))
        return status;
    if (!(mem = open_memstream(&glsl, &glsl_len)) || !(tex_mem = open_memstream(&tex, &tex_len))) {
        if (mem)
            fclose(mem);
        status = cli_oom(WHERE);
        goto done;
    }
    for (m = 0; m < l.sc->model_count && !l.sc->models[m].lut_n; m++)
        ;
    status = emit_glsl(mem, m < l.sc->model_count ? tex_mem : NULL, &l.in); /* a texture only with tables */
    if ((fclose(mem) | fclose(tex_mem)) && !status)
        status = cli_oom(WHERE);
    if (status)
        goto done;
    /* -o - is the page itself on stdout; otherwise DIR/index.html, and a
     * DIR this run created goes again if the page fails. */
    if (!strcmp(out_dir, "-"))
        strcpy(path, "-");
    else if ((made_dir = mkdir(out_dir, 0777) == 0) == 0 && errno != EEXIST) {
        status = cli_error(out_dir, "cannot create the directory: %s", strerror(errno));
        goto done;
    } else if (snprintf(path, sizeof path, "%s/index.html", out_dir) >= (int)sizeof path) {
        status = cli_error(out_dir, "path too long");
        goto done;
    }
    if ((status = cli_out_open(&out, path)))
        goto done;
    if ((status = write_page(out.f, &l, glsl, tex_len ? tex : NULL, cross_path))) {
        cli_out_abort(&out);
        goto done;
    }
    status = cli_out_commit(&out);
    if (!status)
        fprintf(stderr, "%s: wrote %s\n", WHERE, out.shown);
done:
    if (status && made_dir)
        rmdir(out_dir);
    free(glsl);
    free(tex);
    emit_loaded_free(&l);
    return status;
}
