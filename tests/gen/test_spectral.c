/* The generator's spectral pipeline (gen/1_spectral/spectral.h, steps up to the ground
 * truth), each step against an independent computation written here. */
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "harness.h"
#include "common/reference.h"
#include "1_spectral/spectral.h"

#define MAX_MATERIALS 256

static char scratch_dir[] = "/tmp/test_spectral.XXXXXX";

/* ---- capturing what a call prints on a standard stream ---- */

typedef struct capture {
    int fd, saved;
    char path[256];
} capture;

static void capture_begin(capture *cap, int fd, const char *name)
{
    int file;
    fflush(stdout);
    fflush(stderr);
    snprintf(cap->path, sizeof cap->path, "%s/%s", scratch_dir, name);
    cap->fd = fd;
    cap->saved = dup(fd);
    file = open(cap->path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    dup2(file, fd);
    close(file);
}

/* Restores the stream; what was printed is left in text (truncated to size). */
static void capture_end(capture *cap, char *text, size_t size)
{
    FILE *f;
    size_t len = 0;
    fflush(stdout);
    fflush(stderr);
    dup2(cap->saved, cap->fd);
    close(cap->saved);
    f = fopen(cap->path, "rb");
    if (f) {
        len = fread(text, 1, size - 1, f);
        fclose(f);
    }
    text[len] = '\0';
    remove(cap->path);
}

/* ---- independent helpers ---- */

static const double cie_xy_eps = 5e-6;

static void locus_at(const colorimetry *cm, double nm, double xy[2])
{
    /* Linear in the CMFs, not in chromaticity: a different curve between
     * the 1 nm samples from the one the library intersects. */
    double pos = nm - SPEC_LO_NM, u, x, y, z;
    int j = (int)pos;
    if (j >= CMF_N - 1)
        j = CMF_N - 2;
    u = pos - j;
    x = (1 - u) * cm->xbar[j] + u * cm->xbar[j + 1];
    y = (1 - u) * cm->ybar[j] + u * cm->ybar[j + 1];
    z = (1 - u) * cm->zbar[j] + u * cm->zbar[j + 1];
    xy[0] = x / (x + y + z);
    xy[1] = y / (x + y + z);
}

/* Brute force: the locus point at 0.01 nm steps whose direction from the
 * white is closest in angle to the primary's, on the primary's side. */
static double brute_dominant(const colorimetry *cm, const double white[2], const double primary[2])
{
    double best_angle = HUGE_VAL, best_nm = NAN;
    double d[2];
    int i;
    d[0] = primary[0] - white[0];
    d[1] = primary[1] - white[1];
    for (i = 0; i <= 47000; i++) {
        double nm = SPEC_LO_NM + i / 100.0, xy[2], v[2], dot, angle;
        locus_at(cm, nm, xy);
        v[0] = xy[0] - white[0];
        v[1] = xy[1] - white[1];
        dot = v[0] * d[0] + v[1] * d[1];
        if (dot <= 0.0)
            continue;
        angle = atan2(fabs(v[0] * d[1] - v[1] * d[0]), dot);
        if (angle < best_angle) {
            best_angle = angle;
            best_nm = nm;
        }
    }
    return best_nm;
}

static void xyz_to_rgb(const colour_space *cs, const double xyz[3], double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = cs->xyz_to_rgb[ch][0] * xyz[0] + cs->xyz_to_rgb[ch][1] * xyz[1] +
                  cs->xyz_to_rgb[ch][2] * xyz[2];
}

/* Normal-incidence reflectance from air, integrated like the ground truth. */
static void f0_rgb(const spectrum *s, const colorimetry *cm, const colour_space *cs, double rgb[3])
{
    double xyz[3] = {0.0, 0.0, 0.0}, norm = 0.0;
    int j;
    for (j = 0; j < CMF_N; j++) {
        double n = s->n[10 * j], k = s->k[10 * j];
        double f0 = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
        xyz[0] += f0 * cm->d65[j] * cm->xbar[j];
        xyz[1] += f0 * cm->d65[j] * cm->ybar[j];
        xyz[2] += f0 * cm->d65[j] * cm->zbar[j];
        norm += cm->d65[j] * cm->ybar[j];
    }
    for (j = 0; j < 3; j++)
        xyz[j] /= norm;
    xyz_to_rgb(cs, xyz, rgb);
}

/* Largest channel difference; NaN anywhere counts as infinitely wrong. */
static double max_abs3(const double a[3], const double b[3])
{
    double m = 0.0;
    int i;
    for (i = 0; i < 3; i++) {
        double d = fabs(a[i] - b[i]);
        if (d != d)
            return HUGE_VAL;
        m = d > m ? d : m;
    }
    return m;
}

/* ---- tests ---- */

static void test_colorimetry(const colorimetry *cm)
{
    double sum_y = 0.0, w[3], x, y;
    int j;
    for (j = 0; j < CMF_N; j++)
        sum_y += cm->ybar[j];
    /* data/README.md: sum of ybar over 360-830 at 1 nm, and D65's white. */
    CHECK("colorimetry: sum ybar = 106.856917", fabs(sum_y - 106.856917) < 1e-6, "got %.9f",
          sum_y);
    CHECK("colorimetry: ybar(555) = 1", cm->ybar[555 - 360] == 1.0, "got %.9g",
          cm->ybar[555 - 360]);
    illuminant_white(cm, w);
    x = w[0] / (w[0] + w[1] + w[2]);
    y = w[1] / (w[0] + w[1] + w[2]);
    CHECK("colorimetry: D65 SPD white = (0.31273, 0.32902)",
          fabs(x - 0.31273) < cie_xy_eps && fabs(y - 0.32902) < cie_xy_eps, "got (%.6f, %.6f)", x,
          y);
}

static void test_dominant(const colorimetry *cm, const colour_space *spaces, int count)
{
    int i, ch;
    for (i = 0; i < count; i++) {
        double nm[3], worst = 0.0;
        dominant_wavelengths(cm, &spaces[i], nm);
        for (ch = 0; ch < 3; ch++) {
            double brute = brute_dominant(cm, spaces[i].white, spaces[i].primary[ch]);
            double d = fabs(nm[ch] - brute);
            if (!(d <= worst))
                worst = d;
        }
        {
            char name[96];
            snprintf(name, sizeof name, "dominant wavelengths %.15s match a brute-force search",
                     spaces[i].id);
            CHECK(name, worst <= 0.05, "worst difference %.4f nm", worst);
        }
        NOTE("dominant wavelengths %-10s %.2f %.2f %.2f nm (brute force within %.4f nm)",
             spaces[i].id, nm[0], nm[1], nm[2], worst);
    }
    /* Rec.2020's primaries are monochromatic by definition (ITU-R BT.2020:
     * 630, 532, 467 nm), so the ray must land on those wavelengths. */
    for (i = 0; i < count; i++)
        if (!strcmp(spaces[i].id, "rec2020")) {
            double nm[3];
            dominant_wavelengths(cm, &spaces[i], nm);
            CHECK("rec2020 primaries are 630/532/467 nm",
                  fabs(nm[0] - 630) < 0.1 && fabs(nm[1] - 532) < 0.1 && fabs(nm[2] - 467) < 0.2,
                  "got %.3f %.3f %.3f", nm[0], nm[1], nm[2]);
        }
}

static void test_perfect_reflector(const colorimetry *cm, const colour_space *spaces, int count,
                                   const spectrum *cu)
{
    double worst = 0.0, worst_grazing = 0.0, one[3] = {1.0, 1.0, 1.0}, w[3], rgb[3];
    int i;
    illuminant_white(cm, w);
    for (i = 0; i < count; i++) {
        double d;
        xyz_to_rgb(&spaces[i], w, rgb);
        d = max_abs3(rgb, one);
        worst = d > worst ? d : worst;
        /* At grazing incidence every material reflects everything. */
        ground_truth(cu, cm, &spaces[i], 1.0, 0.0, rgb);
        d = max_abs3(rgb, one);
        worst_grazing = d > worst_grazing ? d : worst_grazing;
    }
    CHECK("perfect reflector -> (1,1,1) in every space", worst <= 1e-12, "worst %.3g", worst);
    CHECK("ground truth at c = 0 -> (1,1,1) in every space", worst_grazing <= 1e-12, "worst %.3g",
          worst_grazing);
}

static void test_constant_ior(const colorimetry *cm, const colour_space *spaces, int count)
{
    static const double iors[2][2] = {{0.27, 3.4}, {1.52, 0.0}}; /* copper-like, glass-like */
    static const double n1s[2] = {1.0, 1.33};
    static const double cosines[] = {0.0, 0.05, 0.2, 0.5, 0.8, 1.0};
    spectrum *s = malloc(sizeof *s);
    int m, i, a, b, ch;
    if (!s)
        return;
    for (m = 0; m < 2; m++) {
        double worst = 0.0;
        for (i = 0; i < SPEC_N; i++) {
            s->n[i] = iors[m][0];
            s->k[i] = iors[m][1];
        }
        s->measured_lo = SPEC_LO_NM;
        s->measured_hi = SPEC_HI_NM;
        for (i = 0; i < count; i++)
            for (a = 0; a < 2; a++)
                for (b = 0; b < (int)(sizeof cosines / sizeof cosines[0]); b++) {
                    double rgb[3], r = ref_conductor(iors[m][0] / n1s[a], iors[m][1] / n1s[a],
                                                     cosines[b]);
                    ground_truth(s, cm, &spaces[i], n1s[a], cosines[b], rgb);
                    for (ch = 0; ch < 3; ch++)
                        if (!(fabs(rgb[ch] - r) <= worst))
                            worst = fabs(rgb[ch] - r);
                }
        CHECK(m ? "constant-IOR dielectric: ground truth = exact Fresnel in every channel"
                : "constant-IOR conductor: ground truth = exact Fresnel in every channel",
              worst <= 1e-9, "worst %.3g", worst);
    }
    free(s);
}

static void test_f0_every_material(const char *dir, const colorimetry *cm,
                                   const colour_space *spaces, int count)
{
    material_info *list = malloc(MAX_MATERIALS * sizeof *list);
    spectrum *s = malloc(sizeof *s);
    int n, i, sp, loaded = 0;
    double worst = 0.0;
    char worst_id[32] = "";
    if (!list || !s) {
        free(list);
        free(s);
        return;
    }
    n = material_list(dir, list, MAX_MATERIALS);
    CHECK("materials.csv lists the 34 materials of data/README.md", n == 34, "got %d", n);
    for (i = 0; i < n; i++) {
        if (spectrum_load(dir, list[i].id, s))
            continue;
        loaded++;
        for (sp = 0; sp < count; sp++) {
            double gt[3], f0[3], d;
            ground_truth(s, cm, &spaces[sp], 1.0, 1.0, gt);
            f0_rgb(s, cm, &spaces[sp], f0);
            d = max_abs3(gt, f0);
            if (!(d <= worst)) {
                worst = d;
                strcpy(worst_id, list[i].id);
            }
        }
    }
    CHECK("every material loads", loaded == n && n > 0, "%d of %d", loaded, n);
    CHECK("GT(c=1) = integrated F0 spectrum, every material and space", worst <= 1e-9,
          "worst %.3g (%s)", worst, worst_id);
    free(list);
    free(s);
}

static void test_resample(const char *dir)
{
    char path[1024];
    nk_table t;
    spectrum *s = malloc(sizeof *s);
    int i, exact = 1, inside = 0;
    if (!s)
        return;
    snprintf(path, sizeof path, "%s/cu.csv", dir);
    if (load_nk(path, &t) == 0) {
        resample(&t, s);
        /* Every table node that falls on the grid is reproduced bit for bit. */
        for (i = 0; i < t.rows; i++) {
            double pos = (t.wl[i] - SPEC_LO_NM) * 10.0;
            int node = (int)floor(pos + 0.5);
            if (node < 0 || node >= SPEC_N || (3600 + node) / 10.0 != t.wl[i])
                continue;
            inside++;
            if (s->n[node] != t.n[i] || s->k[node] != t.k[i])
                exact = 0;
        }
        CHECK("resample reproduces cu.csv's nodes on the grid", exact && inside >= 10,
              "exact %d, nodes checked %d", exact, inside);
        /* Halfway between cu.csv's 450.9 and 471.4 nm rows lies 461.15 nm,
         * not a grid node; 461.1 is 0.05 nm before it. */
        {
            double u = (461.1 - 450.9) / (471.4 - 450.9), n = 1.24 + u * (1.25 - 1.24);
            CHECK("resample interpolates linearly between rows",
                  fabs(s->n[(4611 - 3600)] - n) < 1e-12, "got %.15g want %.15g",
                  s->n[4611 - 3600], n);
        }
        CHECK("resample holds the ends (cu covers 360-830)",
              s->measured_lo == 360.0 && s->measured_hi == 830.0, "got %g-%g", s->measured_lo,
              s->measured_hi);
        nk_table_free(&t);
    } else {
        CHECK("load cu.csv", 0, "failed");
    }
    if (spectrum_load(dir, "moissanite", s) == 0) {
        double first_n;
        snprintf(path, sizeof path, "%s/moissanite.csv", dir);
        load_nk(path, &t);
        first_n = t.n[0];
        nk_table_free(&t);
        CHECK("resample: moissanite measured from 405 nm, held below",
              s->measured_lo == 405.0 && s->measured_hi == 830.0 && s->n[0] == first_n &&
                  s->n[(4050 - 3600) - 1] == first_n,
              "range %g-%g", s->measured_lo, s->measured_hi);
    }
    free(s);
}

static void test_sigma_limit(const char *dir, const colorimetry *cm, const colour_space *srgb)
{
    static const char *const ids[] = {"cu", "au", "si", "bk7"};
    static const double odd_centres[3] = {400.0371, 500.0629, 700.0444};
    spectrum *s = malloc(sizeof *s);
    double nm[3], worst = 0.0;
    int m, set, ch;
    if (!s)
        return;
    dominant_wavelengths(cm, srgb, nm);
    for (m = 0; m < 4; m++) {
        if (spectrum_load(dir, ids[m], s))
            continue;
        for (set = 0; set < 2; set++) {
            const double *centre = set ? odd_centres : nm;
            double eta0[3], kappa0[3], eta[3], kappa[3];
            gaussian_window(s, centre, 0.0, eta0, kappa0);
            gaussian_window(s, centre, 1e-3, eta, kappa);
            for (ch = 0; ch < 3; ch++) {
                double d = fabs(eta[ch] - eta0[ch]) > fabs(kappa[ch] - kappa0[ch])
                               ? fabs(eta[ch] - eta0[ch])
                               : fabs(kappa[ch] - kappa0[ch]);
                if (!(d <= worst))
                    worst = d;
            }
        }
    }
    CHECK("gaussian window, sigma 1e-3 nm = point sampling", worst <= 1e-6, "worst %.3g", worst);
    NOTE("gaussian window at sigma 1e-3 nm differs from point sampling by %.3g", worst);
    /* A constant spectrum is its own window mean, however wide the window. */
    {
        int i;
        double eta[3], kappa[3], d = 0.0;
        for (i = 0; i < SPEC_N; i++) {
            s->n[i] = 1.7;
            s->k[i] = 0.25;
        }
        gaussian_window(s, nm, 50.0, eta, kappa);
        for (ch = 0; ch < 3; ch++)
            d = fmax(d, fmax(fabs(eta[ch] - 1.7), fabs(kappa[ch] - 0.25)));
        CHECK("gaussian window of a constant is the constant", d <= 1e-12, "worst %.3g", d);
    }
    free(s);
}

/* Metzgar's Fig. 13: the wider the window, the further the RGB eta', kappa'
 * drift from the spectral ground truth. */
static void test_copper_sigma(const char *dir, const colorimetry *cm, const colour_space *srgb)
{
    static const double sigmas[3] = {12.0, 25.0, 50.0};
    spectrum *s = malloc(sizeof *s);
    double nm[3], err[3];
    int i, a, ch;
    if (!s || spectrum_load(dir, "cu", s)) {
        CHECK("load copper", 0, "failed");
        free(s);
        return;
    }
    dominant_wavelengths(cm, srgb, nm);
    for (i = 0; i < 3; i++) {
        double eta[3], kappa[3];
        gaussian_window(s, nm, sigmas[i], eta, kappa);
        err[i] = 0.0;
        for (a = 0; a <= 90; a++) {
            double c = cos(a * 3.14159265358979323846 / 180.0), gt[3];
            ground_truth(s, cm, srgb, 1.0, c, gt);
            for (ch = 0; ch < 3; ch++)
                err[i] = fmax(err[i], fabs(ref_conductor(eta[ch], kappa[ch], c) - gt[ch]));
        }
    }
    NOTE("copper srgb: max |exact(window eta,kappa) - GT| = %.4f (12 nm), %.4f (25 nm), %.4f (50 nm)",
         err[0], err[1], err[2]);
    CHECK("copper: window error grows with sigma 12 < 25 < 50 nm",
          err[0] < err[1] && err[1] < err[2], "%.5f %.5f %.5f", err[0], err[1], err[2]);
    free(s);
}

/* ---- load_nk error cases ---- */

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* Writes text to a scratch file, loads it, and checks that loading fails
 * with "path:line:" (and `detail`, when given) on stderr. */
static void expect_nk_error(const char *name, const char *text, int line, const char *detail)
{
    char path[512], want[600], message[2048], check[160];
    capture cap;
    nk_table t;
    int rc;
    snprintf(path, sizeof path, "%s/%s.csv", scratch_dir, name);
    write_file(path, text);
    capture_begin(&cap, 2, "stderr.txt");
    rc = load_nk(path, &t);
    capture_end(&cap, message, sizeof message);
    snprintf(want, sizeof want, "%s:%d: ", path, line);
    snprintf(check, sizeof check, "load_nk rejects %s", name);
    CHECK(check,
          rc == CLI_BAD_INPUT && strstr(message, want) && (!detail || strstr(message, detail)) &&
              t.wl == NULL && t.rows == 0,
          "rc %d, wanted '%s'%s%s, got '%s'", rc, want, detail ? " and " : "",
          detail ? detail : "", message);
    remove(path);
}

static void test_load_nk_errors(void)
{
    static const char header[] = "wavelength_nm,n,k\n";
    char text[512], path[512], message[1024];
    capture cap;
    nk_table t;
    int rc;
    expect_nk_error("empty", "", 1, "empty file");
    expect_nk_error("header_only", header, 2, "at least two data rows");
    snprintf(text, sizeof text, "%s500,1.5,0\n", header);
    expect_nk_error("one_row", text, 3, "at least two data rows");
    snprintf(text, sizeof text, "%s500,1.5,0\n510,1.5,0\n505,1.5,0\n", header);
    expect_nk_error("unsorted", text, 4, "wavelength 505 not greater than previous 510");
    snprintf(text, sizeof text, "%s500,1.5,0\n500,1.6,0\n", header);
    expect_nk_error("duplicate", text, 3, "not greater than previous");
    snprintf(text, sizeof text, "%s500,1.5,0\n510,-1.5,0\n", header);
    expect_nk_error("negative_n", text, 3, "n > 0");
    snprintf(text, sizeof text, "%s500,1.5,0\n510,1.5,-0.1\n", header);
    expect_nk_error("negative_k", text, 3, "k >= 0");
    snprintf(text, sizeof text, "%s500,1.5,0\n510,nan,0\n", header);
    expect_nk_error("nan", text, 3, "column n");
    snprintf(text, sizeof text, "%s500,1.5,0\n510,1.5,0\n520,1.5,abc\n", header);
    expect_nk_error("text", text, 4, "column k");
    snprintf(text, sizeof text, "%s500,1.5,0\n510,1.5\n", header);
    expect_nk_error("missing_column", text, 3, "expected 3 columns");
    snprintf(text, sizeof text, "%s500,1.5,0,7\n510,1.5,0\n", header);
    expect_nk_error("extra_column", text, 2, "expected 3 columns");
    expect_nk_error("no_header", "500,1.5,0\n510,1.5,0\n", 1, "header");
    snprintf(text, sizeof text, "%s500,1.5,0\n\n510,1.5,0\n", header);
    expect_nk_error("blank_inside", text, 3, "empty line");
    snprintf(text, sizeof text, "%s500,1.5,0\n510,inf,0\n", header);
    expect_nk_error("infinite", text, 3, "column n");
    snprintf(text, sizeof text, "%s500,,0\n510,1.5,0\n", header);
    expect_nk_error("empty_field", text, 2, "column n");

    /* CRLF endings, no final newline, trailing blank lines: all fine. */
    snprintf(path, sizeof path, "%s/crlf.csv", scratch_dir);
    write_file(path, "wavelength_nm,n,k\r\n500,1.5,0.25\r\n510,1.25,0.5\r\n520,1.125,1\r\n\r\n");
    rc = load_nk(path, &t);
    CHECK("load_nk accepts CRLF line endings",
          rc == 0 && t.rows == 3 && t.wl[2] == 520.0 && t.n[1] == 1.25 && t.k[2] == 1.0,
          "rc %d rows %d", rc, t.rows);
    if (rc == 0)
        nk_table_free(&t);
    remove(path);
    snprintf(path, sizeof path, "%s/no_final_newline.csv", scratch_dir);
    write_file(path, "wavelength_nm,n,k\n500,1.5,0.25\n510,1.25,0.5");
    rc = load_nk(path, &t);
    CHECK("load_nk accepts a missing final newline", rc == 0 && t.rows == 2 && t.k[1] == 0.5,
          "rc %d", rc);
    if (rc == 0)
        nk_table_free(&t);
    remove(path);

    snprintf(path, sizeof path, "%s/does_not_exist.csv", scratch_dir);
    capture_begin(&cap, 2, "stderr.txt");
    rc = load_nk(path, &t);
    capture_end(&cap, message, sizeof message);
    CHECK("load_nk reports a missing file", rc == CLI_BAD_INPUT && strstr(message, path),
          "rc %d, '%s'", rc, message);
}

/* ---- the two subcommands, called in-process ---- */

static int run_command(int (*cmd)(int, char **), int argc, const char **argv, char *out,
                       size_t out_size, char *err, size_t err_size)
{
    capture cap_out, cap_err;
    int rc;
    capture_begin(&cap_out, 1, "stdout.txt");
    capture_begin(&cap_err, 2, "stderr.txt");
    rc = cmd(argc, (char **)argv);
    capture_end(&cap_err, err, err_size);
    capture_end(&cap_out, out, out_size);
    return rc;
}

static void test_commands(void)
{
    char out[8192], err[2048];
    int rc;
    {
        const char *argv[] = {"wavelengths", "--space", "srgb", NULL};
        rc = run_command(cmd_wavelengths, 3, argv, out, sizeof out, err, sizeof err);
        CHECK("fresnel wavelengths --space srgb",
              rc == 0 && !strncmp(out, "red_nm,green_nm,blue_nm\n", 24) &&
                  strspn(out + 24, "0123456789.,") == strlen(out + 24) - 1,
              "rc %d out '%s' err '%s'", rc, out, err);
    }
    {
        const char *argv[] = {"wavelengths", "--space", "cmyk", NULL};
        rc = run_command(cmd_wavelengths, 3, argv, out, sizeof out, err, sizeof err);
        CHECK("fresnel wavelengths rejects an unknown space, naming the valid ones",
              rc == CLI_BAD_INPUT && strstr(err, "cmyk") && strstr(err, "acescg") && !*out,
              "rc %d err '%s'", rc, err);
    }
    {
        const char *argv[] = {"wavelengths", "--space", "srgb", "--sigma", "25", NULL};
        rc = run_command(cmd_wavelengths, 5, argv, out, sizeof out, err, sizeof err);
        CHECK("fresnel wavelengths rejects an unknown option",
              rc == CLI_BAD_INPUT && strstr(err, "--sigma") && !*out, "rc %d err '%s'", rc, err);
    }
    {
        const char *argv[] = {"wavelengths", "--space", NULL};
        rc = run_command(cmd_wavelengths, 2, argv, out, sizeof out, err, sizeof err);
        CHECK("fresnel wavelengths: option without its value", rc == CLI_BAD_INPUT, "rc %d", rc);
    }
    {
        const char *argv[] = {"wavelengths", "--help", NULL};
        rc = run_command(cmd_wavelengths, 2, argv, out, sizeof out, err, sizeof err);
        CHECK("fresnel wavelengths --help", rc == 0 && strstr(out, "usage:"), "rc %d", rc);
    }
    {
        const char *argv[] = {"materials", NULL};
        rc = run_command(cmd_materials, 1, argv, out, sizeof out, err, sizeof err);
        CHECK("fresnel materials lists every material with its measured range",
              rc == 0 &&
                  !strncmp(out, "id,name,dataset,kind,measured_lo_nm,measured_hi_nm\n", 51) &&
                  strstr(out, "\nmoissanite,") && strstr(out, ",405,830\n") &&
                  strstr(out, "\ncu,Copper Cu,Johnson & Christy 1972,metal,360,830\n"),
              "rc %d err '%s'", rc, err);
    }
    {
        const char *argv[] = {"materials", "--verbos", NULL};
        rc = run_command(cmd_materials, 2, argv, out, sizeof out, err, sizeof err);
        CHECK("fresnel materials rejects an unknown option",
              rc == CLI_BAD_INPUT && strstr(err, "'--verbos' (did you mean '--verbose'?)"), "rc %d err '%s'", rc, err);
    }
    {
        const char *argv[] = {"materials", "--data", scratch_dir, NULL};
        rc = run_command(cmd_materials, 3, argv, out, sizeof out, err, sizeof err);
        CHECK("fresnel materials with a data dir lacking materials.csv", rc == CLI_BAD_INPUT && !*out,
              "rc %d err '%s'", rc, err);
    }
}

static void test_material_lookup(const char *dir)
{
    material_info m;
    char err[512];
    capture cap;
    int rc = material_lookup(dir, "au", &m, "test");
    CHECK("material_lookup au", rc == 0 && !strcmp(m.kind, "metal") && !strcmp(m.name, "Gold Au"),
          "rc %d", rc);
    rc = material_lookup(dir, "bk7", &m, "test");
    CHECK("material_lookup bk7 is a dielectric", rc == 0 && !strcmp(m.kind, "dielectric"), "rc %d",
          rc);
    capture_begin(&cap, 2, "stderr.txt");
    rc = material_lookup(dir, "unobtainium", &m, "gen:3");
    capture_end(&cap, err, sizeof err);
    CHECK("material_lookup: unknown id reported at `where`",
          rc == CLI_BAD_INPUT && !strncmp(err, "gen:3: ", 7) && strstr(err, "unobtainium"),
          "rc %d err '%s'", rc, err);
}

int main(void)
{
    const char *dir = data_dir(NULL);
    colorimetry *cm = malloc(sizeof *cm);
    colour_space spaces[8];
    spectrum *cu = malloc(sizeof *cu);
    int count = 0, i;
    if (!mkdtemp(scratch_dir)) {
        perror("mkdtemp");
        return 1;
    }
    if (!cm || !cu || colorimetry_load(dir, cm) || spectrum_load(dir, "cu", cu)) {
        CHECK("load colorimetry and copper", 0, "from %s", dir);
        free(cm);
        free(cu);
        rmdir(scratch_dir);
        return harness_exit();
    }
    for (i = 0; colour_space_ids[i]; i++)
        if (colour_space_load(dir, colour_space_ids[i], cm, &spaces[count]) == 0)
            count++;
    CHECK("all six colour spaces load", count == 6, "loaded %d", count);

    test_colorimetry(cm);
    test_dominant(cm, spaces, count);
    test_perfect_reflector(cm, spaces, count, cu);
    test_constant_ior(cm, spaces, count);
    test_f0_every_material(dir, cm, spaces, count);
    test_resample(dir);
    test_sigma_limit(dir, cm, &spaces[0]);
    test_copper_sigma(dir, cm, &spaces[0]);
    test_load_nk_errors();
    test_material_lookup(dir);
    test_commands();

    free(cm);
    free(cu);
    rmdir(scratch_dir);
    return harness_exit();
}
