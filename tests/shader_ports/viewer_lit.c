/* The viewer's lit probes (ports/webgl/viewer.html, test hook) recomputed
 * on the host: the same camera, sphere and plate, sky, three lights, GGX or
 * normalised Blinn-Phong, in double, with the Fresnel term from the C
 * runtime (binary32, the scene's constants; the thin film at the page's
 * starting thickness) or the page's reference tables (the bare material's,
 * the film's).
 * Reads the page's "LIT material model dist u v r g b" lines on stdin;
 * prints, for tests/shader_ports/test_viewer.sh, the largest relative difference
 * |page - host| / max(|host|, 0.01) and how many values were compared.
 *   viewer_lit SCENE < lines
 *   viewer_lit --peers SCENE < lines   (the film's peers: peers() below) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "4_emit/emit.h"
#include "bench/peers.h"
#include "model/encoded_scene.h"
#include "viewer/viewer.h"

#define PI 3.14159265358979

typedef struct vec3 {
    double x, y, z;
} vec3;
static vec3 v3(double x, double y, double z)
{
    vec3 r;
    r.x = x;
    r.y = y;
    r.z = z;
    return r;
}
static vec3 add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static vec3 scale(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static vec3 mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static double dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec3 normalize(vec3 a) { return scale(a, 1.0 / sqrt(dot(a, a))); }
static vec3 cross(vec3 a, vec3 b) { return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static vec3 mix(vec3 a, vec3 b, double t) { return add(scale(a, 1.0 - t), scale(b, t)); }
static double clampd(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* What the page's fresnel_of evaluates for one row: a model (the thin film
 * at the page's starting thickness d_nm) or a reference table of n nodes. */
typedef struct row {
    const scene_model *model; /* NULL: the reference table */
    const double *ref;        /* n x 3 */
    int n;
    double d_nm;
} row;

static vec3 fresnel(const row *r, double c)
{
    if (r->model) {
        model_rgb q = scene_model_rgb(r->model);
        fresnel_rgb v;
        q.d_nm = r->d_nm;
        v = q.def->f32->scene(&q, (float)c);
        return v3(v.r, v.g, v.b);
    } else {
        double x = sqrt(clampd(c, 0.0, 1.0)) * (r->n - 1), t;
        int i = (int)x;
        if (i > r->n - 2)
            i = r->n - 2;
        t = x - i;
        return mix(v3(r->ref[3 * i], r->ref[3 * i + 1], r->ref[3 * i + 2]),
                   v3(r->ref[3 * i + 3], r->ref[3 * i + 4], r->ref[3 * i + 5]), t);
    }
}

static vec3 sky(vec3 d)
{
    double t = clampd(d.y, -1.0, 1.0);
    vec3 up = mix(v3(0.55, 0.6, 0.7), v3(0.12, 0.22, 0.5), clampd(t * 1.6, 0.0, 1.0));
    vec3 ground = mix(v3(0.2, 0.18, 0.15), v3(0.05, 0.045, 0.04), clampd(-t * 3.0, 0.0, 1.0));
    return t >= 0.0 ? up : ground;
}

static double distribution(int dist, double nh, double a)
{
    if (dist == 1) {
        double a2 = a * a, d = nh * nh * (a2 - 1.0) + 1.0;
        return a2 / (PI * d * d);
    } else {
        double s = fmax(2.0 / (a * a) - 2.0, 0.0);
        return (s + 2.0) / (2.0 * PI) * pow(fmax(nh, 0.0), s);
    }
}

static double visibility(int dist, double nl, double nv, double a)
{
    if (dist == 1) {
        double a2 = a * a, gv = nl * sqrt(nv * nv * (1.0 - a2) + a2), gl = nv * sqrt(nl * nl * (1.0 - a2) + a2);
        return 0.5 / fmax(gv + gl, 1e-7);
    }
    return 0.25;
}

static vec3 light(const row *r, int dist, vec3 n, vec3 v, vec3 l, vec3 radiance, double a)
{
    vec3 h;
    double nl, nv;
    l = normalize(l);
    h = normalize(add(l, v));
    nl = dot(n, l);
    nv = fmax(dot(n, v), 1e-4);
    if (nl <= 0.0)
        return v3(0.0, 0.0, 0.0);
    return scale(mul(fresnel(r, dot(v, h)), radiance),
                 distribution(dist, dot(n, h), a) * visibility(dist, nl, nv, a) * nl);
}

static vec3 shade(const row *r, int dist, double u, double w)
{
    const double yaw = 0.6, pitch = 0.35, rough = 0.25;
    double cy = cos(yaw), sy = sin(yaw), cp = cos(pitch), sp = sin(pitch), b, cc, disc, t = -1.0, a;
    vec3 fwd = v3(-sy * cp, -sp, -cy * cp), ro = scale(fwd, -4.2), right, up, rd, p, n = v3(0, 0, 0), vv, refl, col,
         env;
    right = normalize(cross(fwd, v3(0.0, 1.0, 0.0)));
    up = cross(right, fwd);
    rd = normalize(add(add(scale(fwd, 1.8), scale(right, u)), scale(up, w)));
    b = dot(ro, rd);
    cc = dot(ro, ro) - 1.0;
    disc = b * b - cc;
    if (disc > 0.0) {
        t = -b - sqrt(disc);
        p = add(ro, scale(rd, t));
        n = normalize(p);
    }
    if (t < 0.0 && rd.y < 0.0) {
        t = (-1.0 - ro.y) / rd.y;
        p = add(ro, scale(rd, t));
        n = v3(0.0, 1.0, 0.0);
        if (fabs(p.x) > 2.5 || fabs(p.z) > 2.5)
            t = -1.0;
    }
    if (t < 0.0)
        return scale(sky(rd), 0.6);
    vv = scale(rd, -1.0);
    refl = add(rd, scale(n, -2.0 * dot(n, rd)));
    a = fmax(rough * rough, 0.002);
    col = add(add(light(r, dist, n, vv, v3(0.5, 0.7, 0.5), v3(4.0, 3.8, 3.5), a),
                  light(r, dist, n, vv, v3(-0.7, 0.3, 0.4), v3(1.2, 1.4, 1.8), a)),
              light(r, dist, n, vv, v3(0.0, 0.2, -1.0), v3(2.5, 2.5, 2.5), a));
    env = mix(sky(refl), v3(0.25, 0.27, 0.3), clampd(rough * 1.2, 0.0, 1.0));
    return add(col, mul(fresnel(r, dot(n, vv)), env));
}

/* viewer_lit --peers SCENE < lines: the page's "PEER key material theta r g
 * b" lines (the film's peers in its place, at the page's starting
 * thickness) against their binary32 transcriptions (gen/bench/peers.h) on
 * the inputs gen/viewer/viewer.c gives the page; prints the largest
 * |page - host|, how many values were compared and how many lines named
 * nothing known. */
static int peers(const char *scene_path)
{
    emit_loaded l;
    char line[512], key[32], mat[64];
    double worst = 0.0;
    int count = 0, bad = 0, i, ch;
    if (emit_load(scene_path, NULL, emit_backend_find("--glsl"), &l))
        return 2;
    while (fgets(line, sizeof line, stdin)) {
        double theta, got[3];
        float f0[3], eta[3], kappa[3], want[3], c, d = (float)viewer_film_d(l.sc, VIEWER_FILM_START);
        const material_params *p;
        int mi = -1;
        if (sscanf(line, "PEER %31s %63s %lf %lf %lf %lf", key, mat, &theta, &got[0], &got[1], &got[2]) != 6)
            continue;
        for (i = 0; i < l.sc->material_count; i++)
            if (!strcmp(l.sc->materials[i], mat))
                mi = i;
        if (mi < 0 || (strcmp(key, "khr") && strcmp(key, "polarised"))) {
            bad++;
            continue;
        }
        p = &l.es.params[mi];
        for (ch = 0; ch < 3; ch++) {
            f0[ch] = (float)p->f0[ch];
            eta[ch] = (float)(p->eta_fit[ch] * p->n1);
            kappa[ch] = (float)(p->kappa_fit[ch] * p->n1);
        }
        c = (float)cos(theta * PI / 180.0);
        c = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
        if (!strcmp(key, "khr"))
            peer_khr_iridescence_rgb((float)p->film_n, d, c, f0, want);
        else
            peer_belcour_polarised_rgb((float)p->film_n, d, c, eta, kappa, want);
        for (ch = 0; ch < 3; ch++) {
            worst = fmax(worst, fabs(got[ch] - peer_clamp01(want[ch])));
            count++;
        }
    }
    printf("%.3g %d %d\n", worst, count, bad);
    emit_loaded_free(&l);
    return 0;
}

int main(int argc, char **argv)
{
    emit_loaded l;
    char line[512], mat[64], model[64];
    double worst = 0.0, *refs, *film_refs, d0;
    int count = 0, bad = 0, i, k;
    if (argc == 3 && !strcmp(argv[1], "--peers"))
        return peers(argv[2]);
    if (argc != 2 || emit_load(argv[1], NULL, emit_backend_find("--glsl"), &l))
        return 2;
    d0 = viewer_film_d(l.sc, VIEWER_FILM_START);
    refs = malloc((size_t)l.sc->material_count * VIEWER_REF_NODES * 3 * sizeof *refs);
    film_refs = malloc((size_t)l.sc->material_count * VIEWER_FILM_REF_NODES * 3 * sizeof *film_refs);
    if (!refs || !film_refs)
        return 2;
    for (i = 0; i < l.sc->material_count; i++) {
        for (k = 0; k < VIEWER_REF_NODES; k++) {
            double x = (double)k / (VIEWER_REF_NODES - 1);
            ground_truth(l.es.spectra[i], &l.es.g->cm, &l.es.g->cs, l.es.params[i].n1, x * x, refs + (i * VIEWER_REF_NODES + k) * 3);
        }
        for (k = 0; l.es.params[i].film_n > 0.0 && k < VIEWER_FILM_REF_NODES; k++) { /* the film's, at d0 */
            double x = (double)k / (VIEWER_FILM_REF_NODES - 1);
            film_stack f;
            f.n1 = l.es.params[i].n1;
            f.film = NULL;
            f.film_n = l.es.params[i].film_n;
            f.substrate = l.es.spectra[i];
            film_truth(&f, &l.es.g->cm, &l.es.g->cs, x * x, d0, film_refs + (i * VIEWER_FILM_REF_NODES + k) * 3);
        }
    }
    while (fgets(line, sizeof line, stdin)) {
        double u, w, got[3];
        int dist, mi = -1, mo = -1;
        row r;
        vec3 e;
        if (sscanf(line, "LIT %63s %63s %d %lf %lf %lf %lf %lf", mat, model, &dist, &u, &w, &got[0], &got[1],
                   &got[2]) != 8)
            continue;
        for (i = 0; i < l.sc->material_count; i++)
            if (!strcmp(l.sc->materials[i], mat))
                mi = i;
        for (k = 0; k < l.sc->model_count; k++)
            if (!strcmp(l.sc->models[k].name, model))
                mo = k;
        if (mi < 0 || (mo < 0 && strcmp(model, "reference") && strcmp(model, "film-reference"))) {
            bad++;
            continue;
        }
        r.model = mo < 0 ? NULL : encoded_scene_model(&l.es, mi, mo);
        r.d_nm = d0;
        if (!strcmp(model, "film-reference")) {
            r.ref = film_refs + mi * VIEWER_FILM_REF_NODES * 3;
            r.n = VIEWER_FILM_REF_NODES;
        } else {
            r.ref = refs + mi * VIEWER_REF_NODES * 3;
            r.n = VIEWER_REF_NODES;
        }
        e = shade(&r, dist, u, w);
        worst = fmax(worst, fabs(got[0] - e.x) / fmax(fabs(e.x), 0.01));
        worst = fmax(worst, fabs(got[1] - e.y) / fmax(fabs(e.y), 0.01));
        worst = fmax(worst, fabs(got[2] - e.z) / fmax(fabs(e.z), 0.01));
        count += 3;
    }
    printf("%.3g %d %d\n", worst, count, bad);
    free(refs);
    free(film_refs);
    emit_loaded_free(&l);
    return 0;
}
