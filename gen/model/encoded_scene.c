/* A scene through stages 1-3, once (encoded_scene.h). */
#include "model/encoded_scene.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "2_derive/film_fit.h"
#include "common/cli.h"
#include "common/reference.h"

#define WHERE_SIZE 1100

/* Where a message about the scene's line `line` points: manifest:line, or
 * the command's name for a command line's scene. */
static const char *where_at(const encoded_scene *es, int line, char where[WHERE_SIZE])
{
    if (!es->manifest)
        return es->where;
    snprintf(where, WHERE_SIZE, "%s:%d", es->manifest, line);
    return where;
}

/* A model's table and film for a material whose constants m->mat holds. */
static int encode_model_tables(const scene_entry *e, lut_spacing spacing, const spectrum *s, const gen_context *g,
                               const material_params *p, scene_model *m)
{
    if (e->lut_n && encode_table(s, g, p, spacing, e->lut_n, model_of(e->row)->form, &m->lut))
        return cli_oom("scene model");
    return 0;
}

static void scene_model_init(const scene_entry *e, scene_model *m)
{
    memset(m, 0, sizeof *m);
    m->lut.bad = -1;
    m->def = model_of(e->row);
    strcpy(m->name, e->name);
}

/* Why no film table is: the domain's condition, or a failed fit. */
static int film_failed(const char *where, const char *id, const material_params *p, const encoded_film *film)
{
    return film->why[0] ? cli_error(where, "%s under a %g film in n1 %g: %s", id, p->film_n, p->n1, film->why)
                        : cli_error(where, "%s: fitting the thin-film model of a %g film in n1 %g failed", id,
                                    p->film_n, p->n1);
}

int scene_model_prepare(const scene_entry *e, lut_spacing spacing, const spectrum *s, const gen_context *g,
                        const material_params *p, scene_model *m)
{
    int status;
    scene_model_init(e, m);
    encode_material(p, &m->mat);
    if ((status = encode_model_tables(e, spacing, s, g, p, m)))
        return status;
    if (model_of(e->row)->offered & MODEL_FILM) {
        if (!(p->film_n > 0.0))
            return cli_error(p->info.id, "%s needs a film (a scene's film key, curve's --film N:D)", e->name);
        if (!(m->film_owned = malloc(sizeof *m->film_owned)))
            return cli_oom("scene model");
        m->film = m->film_owned;
        if (encode_film(s, g, p, NULL, m->film_owned)) {
            status = film_failed(p->info.id, p->info.id, p, m->film_owned);
            scene_model_free(m);
            return status;
        }
    }
    return 0;
}

int scene_model_prepare_name(const char *name, lut_spacing spacing, const spectrum *s, const gen_context *g,
                             const material_params *p, scene_model *m)
{
    scene_entry e;
    memset(m, 0, sizeof *m);
    m->lut.bad = -1;
    if (scene_entry_parse(name, spacing, &e))
        return cli_error("scene model", "unknown model '%s' (fresnel gen --help lists the models)", name);
    return scene_model_prepare(&e, spacing, s, g, p, m);
}

void scene_model_free(scene_model *m)
{
    encoded_lut_free(&m->lut);
    free(m->film_owned);
    m->film_owned = NULL;
    m->film = NULL;
}

model_rgb scene_model_rgb(const scene_model *m)
{
    model_rgb q;
    q.def = m->def;
    q.mat = &m->mat;
    q.lut = m->lut.n ? &m->lut : NULL;
    q.film = m->film;
    q.d_nm = 0.0;
    return q;
}

void scene_model_eval(const scene_model *m, float c, float out[3])
{
    model_rgb q = scene_model_rgb(m);
    fresnel_rgb r = m->def->f32->scene(&q, c);
    out[0] = r.r;
    out[1] = r.g;
    out[2] = r.b;
}

void scene_model_eval_ref(const scene_model *m, double c, double out[3])
{
    model_rgb q = scene_model_rgb(m);
    int ch;
    c = ref_clamp(c, 0.0, 1.0);
    for (ch = 0; ch < 3; ch++)
        out[ch] = ref_clamp(m->def->ref->scene(&q, ch, c), 0.0, 1.0);
}

const scene_model *encoded_scene_model(const encoded_scene *es, int material, int model)
{
    return &es->models[material * es->sc->model_count + model];
}

void encoded_scene_free(encoded_scene *es)
{
    int i, n = es->sc ? es->material_count * es->sc->model_count : 0;
    for (i = 0; es->models && i < n; i++)
        scene_model_free(&es->models[i]);
    for (i = 0; es->spectra && i < es->material_count; i++)
        free(es->spectra[i]);
    free(es->models);
    free(es->spectra);
    free(es->params);
    free(es->enc);
    free(es->films);
    free(es->fits);
    free(es->film_fits);
    free(es->g);
    memset(es, 0, sizeof *es);
}

/* Every derived parameter is a finite binary32 (a literal beyond FLT_MAX
 * would read inf.0f and not compile) and, in a scene with binary16
 * constants, a finite binary16 (beyond 65504 it rounds to an infinity). */
#define FIT_FLOAT_3(constant, v)                                                                                       \
    for (ch = 0; ch < 3 && !status; ch++)                                                                              \
        status = fit_float(es, p, constant, (v)[ch]);
#define FIT_FLOAT_1(constant, v) status = status ? status : fit_float(es, p, constant, v);
#define FIT_FLOAT(field, count, group, constant, row, why, q15, q15_why) FIT_FLOAT_##count(constant, p->field)
#define FIT_F16_3(v)                                                                                                   \
    for (ch = 0; ch < 3; ch++)                                                                                         \
        finite &= isfinite((double)(v)[ch]) != 0;
#define FIT_F16_1(v) finite &= isfinite((double)(v)) != 0;
#define FIT_F16(field, count, group, constant, row, why, q15, q15_why) FIT_F16_##count(e->h_##field)

static int fit_float(const encoded_scene *es, const material_params *p, const char *constant, double v)
{
    char where[WHERE_SIZE];
    if (fabs(v) <= FLT_MAX)
        return 0;
    return cli_error(where_at(es, es->sc->materials_line, where), "material %s: %s = %g does not fit a binary32 float",
                     p->info.id, constant, v);
}

/* What a scene's number types hold of material i: its parameters (every
 * one a finite binary32; in binary16 where the scene has it), its Q1.15
 * constants where the scene has Q1.15, its film's table in each type. */
static int params_fit(const encoded_scene *es, int i)
{
    const material_params *p = &es->params[i];
    const encoded_film *film = es->films ? &es->films[i] : NULL;
    const scene *sc = es->sc;
    char where[WHERE_SIZE], why[512];
    int ch, status = 0;
    DERIVED_PARAMETERS(FIT_FLOAT)
    if (status)
        return status;
    if (film && !film->f32_finite)
        return cli_error(where_at(es, sc->models_line, where),
                         "%s: the thin-film table holds a value no binary32 holds", p->info.id);
    if (scene_has_type(sc, TYPE_Q15)) {
        if (encode_q15_fits(p, &es->enc[i], scene_reads(sc, 0) | (sc->f_avg ? MP_F_AVG : 0u), scene_reads(sc, 1),
                            why, sizeof why))
            return cli_error(where_at(es, sc->models_line, where), "%s", why);
        if (film && !film->q15_ok)
            return cli_error(where_at(es, sc->types_line, where),
                             "%s: the thin-film table of a %g film leaves the Q1.15 layout's ranges "
                             "(include/fresnel_film.h)",
                             p->info.id, film->n_film);
    }
#if FRESNEL_HAS_F16
    if (scene_has_type(sc, TYPE_F16)) {
        const encoded_material *e = &es->enc[i];
        int finite = 1;
        DERIVED_PARAMETERS(FIT_F16)
        if (!finite)
            return cli_error(where_at(es, sc->types_line, where),
                             "material %s: a parameter does not fit binary16 (largest 65504)", p->info.id);
        if (film && !film->f16_finite)
            return cli_error(where_at(es, sc->models_line, where),
                             "%s: the thin-film table holds a value no binary16 (largest 65504) holds", p->info.id);
    }
#endif
    return 0;
}

/* A table every number type can hold: finite nodes, each a Q1.15 code. */
static int lut_fits(const encoded_scene *es, int i, int m)
{
    const encoded_lut *t = &encoded_scene_model(es, i, m)->lut;
    char where[WHERE_SIZE];
    if (t->bad < 0)
        return 0;
    return cli_error(where_at(es, es->sc->models_line, where), "%s: %s node %d is %g, which no %s table holds",
                     es->params[i].info.id, es->sc->models[m].name, t->bad, t->nodes[t->bad],
                     t->form == LUT_RESIDUAL ? "Q1.15 residual (int16_t at 14 fraction bits)" : "Q1.15 [0, 2)");
}

/* Stage 1 and 2 of every material: every unknown material reported first. */
static int derive_all(encoded_scene *es)
{
    const scene *sc = es->sc;
    char where[WHERE_SIZE];
    int i, k, status = 0;
    for (i = 0; i < sc->material_count; i++) {
        material_info info;
        if (!sc->material_file[i][0] &&
            material_lookup(es->g->dir, sc->materials[i], &info, where_at(es, sc->material_line[i], where)))
            status = CLI_BAD_INPUT;
    }
    if (status)
        return status;
    for (i = 0; i < sc->material_count; i++) {
        material_source m = scene_material(sc, i);
        double truth[TARGET_ANGLES][3];
        target_anchor a;
        lab_space ls;
        if (!(es->spectra[i] = malloc(sizeof *es->spectra[i])))
            return cli_oom("encode scene");
        if ((status = derive_parameters(es->g, &m, sc->sigma, sc->n1, es->spectra[i], &es->params[i])))
            return status;
        if (!sc->target_count)
            continue;
        lab_space_init(&ls, &es->g->cs);
        target_material_curve(es->spectra[i], es->g, &es->params[i], 1, truth, &a);
        for (k = 0; k < sc->target_count; k++) {
            const target *t = &target_table[sc->targets[k]];
            target_fit_curve(t, &ls, (const double(*)[3])truth, &a, &es->fits[i * sc->target_count + k]);
            /* under the scene's film, through the renderer's own film */
            if (es->params[i].film_n > 0.0 && t->film.eval &&
                target_film_fit(t, es->spectra[i], es->g, &es->params[i], es->params[i].film_n, sc->film_d_lo,
                                sc->film_d_hi, &es->film_fits[i * sc->target_count + k]))
                return cli_oom("encode scene");
        }
    }
    return 0;
}

/* Stage 3: constants, films (for the thin-film row), tables. */
static int encode_all(encoded_scene *es)
{
    const scene *sc = es->sc;
    char where[WHERE_SIZE];
    int i, m, status;
    for (i = 0; i < sc->material_count; i++)
        encode_material(&es->params[i], &es->enc[i]);
    for (m = 0; m < sc->model_count; m++)
        if (model_of(sc->models[m].row)->offered & MODEL_FILM)
            break;
    if (m < sc->model_count) { /* the scene has the thin-film model: every material has a film */
        /* the poles depend on the colour space alone: fitted once for every material */
        film_model *poles = malloc(sizeof *poles);
        int failed = 0;
        if (!poles || !(es->films = malloc((size_t)sc->material_count * sizeof *es->films))) {
            free(poles);
            return cli_oom("encode scene");
        }
        if (film_fit_poles(&es->g->cm, &es->g->cs, poles, NULL)) {
            free(poles);
            poles = NULL;
        }
        for (i = 0; i < sc->material_count && !failed; i++) {
            const material_params *p = &es->params[i];
            if (!(p->film_n > 0.0))
                failed = cli_error(where_at(es, sc->material_line[i], where),
                                   "%s needs a film (a scene's film key, curve's --film N:D)", sc->models[m].name);
            else if (encode_film(es->spectra[i], es->g, p, poles, &es->films[i]))
                failed = film_failed(where_at(es, sc->material_line[i], where), sc->materials[i], p, &es->films[i]);
        }
        free(poles);
        if (failed)
            return failed;
    }
    for (i = 0; i < sc->material_count; i++) {
        if ((status = params_fit(es, i)))
            return status;
        for (m = 0; m < sc->model_count; m++) {
            scene_model *sm = &es->models[i * sc->model_count + m];
            scene_model_init(&sc->models[m], sm);
            sm->mat = es->enc[i];
            if (model_of(sc->models[m].row)->offered & MODEL_FILM)
                sm->film = &es->films[i];
            if ((status = encode_model_tables(&sc->models[m], sc->spacing, es->spectra[i], es->g, &es->params[i], sm)) ||
                (status = lut_fits(es, i, m)))
                return status;
        }
    }
    return 0;
}

int encode_scene(const scene *sc, const char *manifest, const char *where, const char *dir_option,
                 encoded_scene *out)
{
    size_t n = (size_t)sc->material_count;
    int status;
    memset(out, 0, sizeof *out);
    out->sc = sc;
    out->manifest = manifest;
    out->where = where;
    out->material_count = sc->material_count;
    out->g = malloc(sizeof *out->g);
    out->params = calloc(n ? n : 1, sizeof *out->params);
    out->spectra = calloc(n ? n : 1, sizeof *out->spectra);
    out->enc = calloc(n ? n : 1, sizeof *out->enc);
    out->models = calloc(n * (size_t)sc->model_count + 1, sizeof *out->models);
    out->fits = calloc(n * (size_t)sc->target_count + 1, sizeof *out->fits);
    out->film_fits = calloc(n * (size_t)sc->target_count + 1, sizeof *out->film_fits);
    if (!out->g || !out->params || !out->spectra || !out->enc || !out->models || !out->fits || !out->film_fits) {
        status = cli_oom("encode scene");
        goto done;
    }
    if ((status = gen_context_load(data_dir(dir_option), sc->space, out->g)))
        goto done;
    out->g->gamut = sc->gamut;
    if (!(status = derive_all(out)))
        status = encode_all(out);
done:
    if (status) {
        /* the models encode_all has not reached are zeroed: freeing them is a no-op */
        encoded_scene_free(out);
    }
    return status;
}
