/* Stage 4, emit: a material's thin-film table (include/fresnel_film.h) in
 * each number type of the scene, as the encoder made it (encoded_film,
 * 3_encode/encode.h). One writer serves the three layouts: each is the
 * same sequence of arrays (the poles, the weights, 32 nodes), written with
 * every brace of its struct. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "common/cli.h"
#include "4_emit/emit.h"

#define J FRESNEL_FILM_POLES
#define NODES FRESNEL_FILM_NODES

/* A table's values in the order of its struct, as doubles. */
typedef struct film_values {
    int pole_rows; /* binary32, binary16: freq, damp; Q1.15: turn_nu, turn_gamma, octave_nu, octave_gamma */
    double pole[4][J];
    double weight[3][J][2];
    double a0[NODES][3], opd[NODES], decay[NODES];
    double term[NODES][8][J]; /* a_re, a_im, b_re, b_im, p_re, p_im, q_re, q_im */
} film_values;

/* The weights and the 32 nodes, named alike in the three layouts: a macro
 * over the table's type, each value converted to double. */
#define FILM_WEIGHTS_AND_NODES(t, v)                                                                        \
    do {                                                                                                    \
        int j_, k_, ch_;                                                                                    \
        for (j_ = 0; j_ < J; j_++)                                                                          \
            for (ch_ = 0; ch_ < 3; ch_++)                                                                   \
                (v)->weight[ch_][j_][0] = (double)(t)->weight[ch_][j_][0],                                  \
                (v)->weight[ch_][j_][1] = (double)(t)->weight[ch_][j_][1];                                  \
        for (k_ = 0; k_ < NODES; k_++) {                                                                    \
            for (ch_ = 0; ch_ < 3; ch_++)                                                                   \
                (v)->a0[k_][ch_] = (double)(t)->node[k_].a0[ch_];                                           \
            (v)->opd[k_] = (double)(t)->node[k_].opd;                                                       \
            (v)->decay[k_] = (double)(t)->node[k_].decay;                                                   \
            for (j_ = 0; j_ < J; j_++) {                                                                    \
                (v)->term[k_][0][j_] = (double)(t)->node[k_].a_re[j_];                                      \
                (v)->term[k_][1][j_] = (double)(t)->node[k_].a_im[j_];                                      \
                (v)->term[k_][2][j_] = (double)(t)->node[k_].b_re[j_];                                      \
                (v)->term[k_][3][j_] = (double)(t)->node[k_].b_im[j_];                                      \
                (v)->term[k_][4][j_] = (double)(t)->node[k_].p_re[j_];                                      \
                (v)->term[k_][5][j_] = (double)(t)->node[k_].p_im[j_];                                      \
                (v)->term[k_][6][j_] = (double)(t)->node[k_].q_re[j_];                                      \
                (v)->term[k_][7][j_] = (double)(t)->node[k_].q_im[j_];                                      \
            }                                                                                               \
        }                                                                                                   \
    } while (0)

static void values_f32(const fresnel_film *t, film_values *v)
{
    int j;
    v->pole_rows = 2;
    for (j = 0; j < J; j++)
        v->pole[0][j] = t->freq[j], v->pole[1][j] = t->damp[j];
    FILM_WEIGHTS_AND_NODES(t, v);
}

static void values_q15(const fresnel_film_q15 *t, film_values *v)
{
    int j;
    v->pole_rows = 4;
    for (j = 0; j < J; j++) {
        v->pole[0][j] = t->turn_nu[j];
        v->pole[1][j] = t->turn_gamma[j];
        v->pole[2][j] = t->octave_nu[j];
        v->pole[3][j] = t->octave_gamma[j];
    }
    FILM_WEIGHTS_AND_NODES(t, v);
}

#if FRESNEL_HAS_F16
static void values_f16(const fresnel_film_f16 *t, film_values *v)
{
    int j;
    v->pole_rows = 2;
    for (j = 0; j < J; j++)
        v->pole[0][j] = (double)t->freq[j], v->pole[1][j] = (double)t->damp[j];
    FILM_WEIGHTS_AND_NODES(t, v);
}
#endif

static void put(FILE *f, double v, int is_float)
{
    if (is_float)
        emit_c_float(f, v);
    else
        fprintf(f, "%.0f", v);
}

static void put_array(FILE *f, const double *v, int n, int is_float)
{
    int i;
    fputc('{', f);
    for (i = 0; i < n; i++) {
        if (i)
            fputs(", ", f);
        put(f, v[i], is_float);
    }
    fputc('}', f);
}

static void put_values(FILE *f, const film_values *v, int is_float)
{
    int r, j, ch, k, t;
    fputs("{\n    ", f);
    for (r = 0; r < v->pole_rows; r++) {
        put_array(f, v->pole[r], J, is_float);
        fputs(",\n    ", f);
    }
    fputc('{', f);
    for (ch = 0; ch < 3; ch++) {
        fputs(ch ? ",\n     {" : "{", f);
        for (j = 0; j < J; j++) {
            if (j)
                fputs(", ", f);
            put_array(f, v->weight[ch][j], 2, is_float);
        }
        fputc('}', f);
    }
    fputs("},\n    {", f);
    for (k = 0; k < NODES; k++) {
        fputs(k ? ",\n     {" : "{", f);
        put_array(f, v->a0[k], 3, is_float);
        fputs(", ", f);
        put(f, v->opd[k], is_float);
        fputs(", ", f);
        put(f, v->decay[k], is_float);
        for (t = 0; t < 8; t++) {
            fputs(t % 2 ? ", " : ",\n      ", f);
            put_array(f, v->term[k][t], J, is_float);
        }
        fputc('}', f);
    }
    fputs("}\n};\n", f);
}

/* The comment every type's table opens with. */
static void film_comment(FILE *f, const emit_input *in, int mi, const scene_entry *e, const char *type_note,
                         const char *call)
{
    const scene *sc = in->sc;
    fprintf(f, "/* %s: a film of index %g on %s in n1 %g, thickness %g-%g nm%s (include/fresnel_film.h),\n"
               " * %s. Evaluate with %s. */\n",
            e->name, in->films[mi].n_film, in->params[mi].info.id, sc->n1, sc->film_d_lo, sc->film_d_hi,
            sc->film_d_lo == 0.0 && sc->film_d_hi == FRESNEL_FILM_D_MAX ? " (set at run time)" : "", type_note, call);
}

static const scene_entry *film_entry(const scene *sc)
{
    int m;
    for (m = 0; m < sc->model_count; m++)
        if (model_of(sc->models[m].row)->offered & MODEL_FILM)
            return &sc->models[m];
    return NULL;
}

/* The table of `type` as values. */
static void film_values_of(const encoded_film *film, number_type_id type, film_values *v)
{
    if (type == TYPE_F32)
        values_f32(&film->f32, v);
    else if (type == TYPE_Q15)
        values_q15(&film->q15, v);
#if FRESNEL_HAS_F16
    else
        values_f16(&film->f16, v);
#endif
}

void emit_film_initializer(FILE *f, const encoded_film *film, number_type_id type)
{
    film_values v;
    film_values_of(film, type, &v);
    put_values(f, &v, number_type_catalog[type].floating);
}

int emit_film(FILE *f, const emit_input *in, int mi, const char *prefix, number_type_id type)
{
    const scene_entry *e = film_entry(in->sc);
    const encoded_film *film = in->films ? &in->films[mi] : NULL;
    const number_type_facts *t = &number_type_catalog[type];
    if (!e || !film || !t->available)
        return 0;
    film_comment(f, in, mi, e, t->film_layout, t->film_call);
    fprintf(f, "static const %s %s_%s%s FRESNEL_GEN_UNUSED = ", t->film_struct, prefix, e->ident, t->suffix);
    emit_film_initializer(f, film, type);
    return 0;
}
