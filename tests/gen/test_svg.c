/* The SVG writer (gen/report/svg.c): well-formed, deterministic output, clipping,
 * escaping, sRGB encoding. With "--write PATH" it only writes its sample plot
 * to PATH, for tests/gen/test_svg_xmllint.sh to hand to an XML parser. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "harness.h"
#include "report/svg.h"

/* The kind of figure the report draws: a 0-90 degree panel and a 70-90 zoom
 * with curves leaving the zoom's range, a log-scale scatter with labelled
 * points, a legend, a colour strip, and text that needs escaping. */
static int write_sample(FILE *f)
{
    svg_doc d;
    svg_panel full, zoom, scatter;
    svg_legend legend;
    svg_axis theta = {0.0, 90.0, SVG_LINEAR, 15.0, "angle of incidence (\xce\xb8, degrees)", "%.0f"};
    svg_axis theta_zoom = {70.0, 90.0, SVG_LINEAR, 5.0, "\xce\xb8 (degrees)", "%.0f"};
    svg_axis refl = {0.0, 1.0, SVG_LINEAR, 0.0, "reflectance", NULL};
    svg_axis refl_zoom = {0.5, 1.0, SVG_LINEAR, 0.0, NULL, NULL};
    svg_axis ns = {0.3, 30.0, SVG_LOG10, 0.0, "ns per evaluation", NULL};
    svg_axis de = {1e-3, 10.0, SVG_LOG10, 0.0, "mean \xce\x94" "E2000", NULL};
    double th[91], r[91], g[91], strip[91][3];
    int i, ch;
    static const double px[4] = {0.5, 2.0, 9.0, 40.0}, py[4] = {1.2, 0.05, 0.004, 0.0};
    static const char *const names[4] = {"schlick <f32>", "f82 & co", "LUT-16 \"Q15\"", "off-plot"};

    for (i = 0; i <= 90; i++) {
        double c = cos(i * 3.14159265358979323846 / 180.0), w = pow(1.0 - c, 5.0);
        th[i] = i;
        r[i] = 0.95 + 0.05 * w;
        g[i] = 0.6 + 0.4 * w;
        strip[i][0] = r[i];
        strip[i][1] = g[i];
        strip[i][2] = 0.3 + 0.7 * w;
    }
    strip[0][0] = 1.04; /* out-of-gamut gold red: clamped */
    strip[1][2] = -0.01;

    svg_begin(&d, f, 760.0, 620.0, "copper <Schlick> & \"ground truth\" \xe2\x80\x94 bad \xff byte");
    if (svg_panel_begin(&full, &d, 0.0, 0.0, 380.0, 260.0, &theta, &refl, "0\xe2\x80\x93" "90\xc2\xb0") ||
        svg_panel_begin(&zoom, &d, 380.0, 0.0, 380.0, 260.0, &theta_zoom, &refl_zoom, "zoom") ||
        svg_panel_begin(&scatter, &d, 0.0, 300.0, 500.0, 320.0, &ns, &de, "Pareto"))
        return -1;
    for (ch = 0; ch < 2; ch++) {
        svg_style s = {svg_palette(ch), 1.5, svg_dash(ch)};
        svg_polyline(&full, th, ch ? g : r, 91, &s);
        svg_polyline(&zoom, th, ch ? g : r, 91, &s);
    }
    for (i = 0; i < 4; i++)
        svg_point(&scatter, px[i], py[i], (svg_marker)(SVG_CIRCLE + i), 6.0, svg_palette(i),
                  names[i], (svg_label_pos)i);
    svg_polyline(&scatter, px, py, 4, NULL);
    svg_legend_begin(&legend, &d, 520.0, 330.0);
    for (i = 0; i < 4; i++) {
        svg_style s = {svg_palette(i), 1.0, svg_dash(i)};
        svg_legend_entry(&legend, &s, (svg_marker)(SVG_CIRCLE + i), NULL, names[i]);
    }
    svg_legend_entry(&legend, NULL, SVG_CROSS, "#000000", "marker only");
    svg_strip(&d, 520.0, 420.0, 220.0, 20.0, (const double(*)[3])strip, 91);
    svg_text(&d, 520.0, 455.0, 10.0, SVG_START, NULL, "\xce\xb8 0\xe2\x86\x92" "90\xc2\xb0");
    svg_rect(&d, 518.0, 418.0, 224.0, 24.0, NULL, "#000000");
    return svg_end(&d);
}

/* ---- a minimal XML well-formedness check: balanced, properly nested
 * elements with quoted attributes, one root, no stray '<' or '&'. */

static const char *skip_name(const char *s)
{
    while ((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') ||
           *s == '-' || *s == ':' || *s == '_')
        s++;
    return s;
}

/* Checks an entity or text run up to '<'; returns the position of '<' or NULL. */
static const char *check_text(const char *s)
{
    while (*s && *s != '<') {
        if (*s == '>')
            return NULL;
        if (*s == '&') {
            static const char *const ents[] = {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"};
            size_t k;
            int ok = 0;
            for (k = 0; k < 5; k++)
                if (!strncmp(s, ents[k], strlen(ents[k]))) {
                    s += strlen(ents[k]);
                    ok = 1;
                    break;
                }
            if (!ok)
                return NULL;
            continue;
        }
        s++;
    }
    return s;
}

static int well_formed(const char *s, char *why, size_t why_size)
{
    char stack[64][32];
    int depth = 0, roots = 0;
    if (strncmp(s, "<?xml ", 6) || !(s = strstr(s, "?>"))) {
        snprintf(why, why_size, "no XML declaration");
        return 0;
    }
    s += 2;
    for (;;) {
        const char *name, *end;
        s = check_text(s);
        if (!s) {
            snprintf(why, why_size, "bad character data");
            return 0;
        }
        if (!*s)
            break;
        if (s[1] == '/') { /* end tag */
            name = s + 2;
            end = skip_name(name);
            if (depth == 0 || (size_t)(end - name) != strlen(stack[depth - 1]) ||
                strncmp(name, stack[depth - 1], (size_t)(end - name)) || *end != '>') {
                snprintf(why, why_size, "unbalanced </%.*s>", (int)(end - name), name);
                return 0;
            }
            depth--;
            s = end + 1;
            continue;
        }
        name = s + 1;
        end = skip_name(name);
        if (end == name || end - name >= 32 || depth == 64) {
            snprintf(why, why_size, "bad tag name");
            return 0;
        }
        if (depth == 0 && ++roots > 1) {
            snprintf(why, why_size, "more than one root element");
            return 0;
        }
        memcpy(stack[depth], name, (size_t)(end - name));
        stack[depth][end - name] = '\0';
        s = end;
        for (;;) { /* attributes: name="value" */
            while (*s == ' ' || *s == '\n')
                s++;
            if (*s == '>' || (s[0] == '/' && s[1] == '>'))
                break;
            end = skip_name(s);
            if (end == s || end[0] != '=' || end[1] != '"') {
                snprintf(why, why_size, "bad attribute in <%s>", stack[depth]);
                return 0;
            }
            s = end + 2;
            while (*s && *s != '"' && *s != '<')
                s++;
            if (*s != '"') {
                snprintf(why, why_size, "unterminated attribute in <%s>", stack[depth]);
                return 0;
            }
            s++;
        }
        if (*s == '>') {
            depth++;
            s++;
        } else {
            s += 2;
        }
    }
    if (depth != 0 || roots != 1) {
        snprintf(why, why_size, "depth %d at the end, %d roots", depth, roots);
        return 0;
    }
    return 1;
}

static char *read_all(const char *path, long *size)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)n + 1);
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    if (buf)
        buf[n] = '\0';
    *size = n;
    return buf;
}

static int write_file(const char *path)
{
    FILE *f = fopen(path, "wb");
    int rc;
    if (!f)
        return -1;
    rc = write_sample(f);
    return fclose(f) || rc ? -1 : 0;
}

/* Every point of every polyline drawn in `p` lies inside its plot area. */
static int polylines_inside(const char *text, const svg_panel *p, int *count)
{
    const char *s = text;
    *count = 0;
    while ((s = strstr(s, "points=\"")) != NULL) {
        s += 8;
        while (*s != '"') {
            char *end;
            double x = strtod(s, &end), y;
            if (*end != ',')
                return 0;
            y = strtod(end + 1, &end);
            if (x < p->x - 0.005 || x > p->x + p->w + 0.005 || y < p->y - 0.005 ||
                y > p->y + p->h + 0.005)
                return 0;
            (*count)++;
            s = end;
            while (*s == ' ')
                s++;
        }
    }
    return 1;
}

static void test_clipping(const char *dir)
{
    char path[256];
    svg_doc d;
    svg_panel zoom;
    svg_axis xa = {70.0, 90.0, SVG_LINEAR, 5.0, NULL, NULL}, ya = {0.5, 1.0, SVG_LINEAR, 0.1, NULL, NULL};
    static const double x[8] = {0.0, 60.0, 75.0, 80.0, 95.0, 85.0, 85.0, NAN},
                        y[8] = {0.2, 0.4, 0.8, 2.0, 0.7, 0.6, 0.9, 0.9};
    FILE *f;
    char *text;
    long size;
    int inside, count = 0;
    snprintf(path, sizeof path, "%s/clip.svg", dir);
    f = fopen(path, "wb");
    if (!f) {
        CHECK("clip: temp file", 0, "%s", path);
        return;
    }
    svg_begin(&d, f, 400.0, 300.0, NULL);
    svg_panel_begin(&zoom, &d, 0.0, 0.0, 400.0, 300.0, &xa, &ya, NULL);
    /* Only the polylines come after this mark; the axes have no points="". */
    svg_polyline(&zoom, x, y, 8, NULL);
    svg_end(&d);
    fclose(f);
    text = read_all(path, &size);
    if (!text) {
        CHECK("clip: read back", 0, "%s", path);
        return;
    }
    inside = polylines_inside(text, &zoom, &count);
    CHECK("polyline: every drawn point inside the zoom panel's plot area", inside && count >= 4,
          "inside %d, %d points", inside, count);
    {
        /* 60 -> 75 enters at the left edge, 75 -> 80 leaves through the top,
         * 80 -> 95 passes outside the corner, 95 -> 85 re-enters through the
         * right edge, and the NaN ends that run: two runs. */
        int runs = 0;
        const char *s = text;
        while ((s = strstr(s, "<polyline")) != NULL) {
            runs++;
            s++;
        }
        CHECK("polyline: leaving the panel and a NaN break the line (2 runs)", runs == 2,
              "%d runs", runs);
    }
    free(text);
    remove(path);
}

static void test_srgb(void)
{
    char hex[8];
    static const double spots[3] = {0.0, 1.0, 0.5}, clamp[3] = {-0.2, 1.7, NAN};
    svg_srgb_hex(spots, hex);
    CHECK("srgb hex: linear 0, 1, 0.5 -> #00ffbc", !strcmp(hex, "#00ffbc"), "%s", hex);
    svg_srgb_hex(clamp, hex);
    CHECK("srgb hex: -0.2, 1.7, NaN clamp to #00ff00", !strcmp(hex, "#00ff00"), "%s", hex);
    /* 0.0031308 ends the linear segment: 12.92 x 0.0031308 x 255 = 10.3;
     * 0.18 (mid grey) encodes to 0.4614 x 255 = 117.7. */
    CHECK("srgb8: linear segment end 0.0031308 -> 10", svg_srgb8(0.0031308) == 10, "%u",
          svg_srgb8(0.0031308));
    CHECK("srgb8: 0.18 -> 118", svg_srgb8(0.18) == 118, "%u", svg_srgb8(0.18));
    CHECK("srgb8: 0.001 -> 3 (12.92 x 0.001 x 255 = 3.29)", svg_srgb8(0.001) == 3, "%u",
          svg_srgb8(0.001));
    {
        unsigned prev = 0, v;
        int i, monotone = 1;
        for (i = 0; i <= 10000; i++) {
            v = svg_srgb8(i / 10000.0);
            if (v < prev)
                monotone = 0;
            prev = v;
        }
        CHECK("srgb8: monotone over [0, 1]", monotone, "not monotone");
    }
}

static void test_panel_rejects(void)
{
    svg_doc d;
    svg_panel p;
    svg_axis good = {0.0, 1.0, SVG_LINEAR, 0.0, NULL, NULL}, empty = {1.0, 1.0, SVG_LINEAR, 0.0, NULL, NULL},
             log_zero = {0.0, 10.0, SVG_LOG10, 0.0, NULL, NULL}, nan_axis = {NAN, 1.0, SVG_LINEAR, 0.0, NULL, NULL};
    FILE *f = tmpfile();
    long before, after;
    if (!f) {
        CHECK("panel: tmpfile", 0, "tmpfile failed");
        return;
    }
    svg_begin(&d, f, 300.0, 200.0, NULL);
    before = ftell(f);
    CHECK("panel: empty range rejected", svg_panel_begin(&p, &d, 0, 0, 300, 200, &empty, &good, NULL) == -1, "accepted");
    CHECK("panel: log axis from 0 rejected", svg_panel_begin(&p, &d, 0, 0, 300, 200, &good, &log_zero, NULL) == -1, "accepted");
    CHECK("panel: NaN range rejected", svg_panel_begin(&p, &d, 0, 0, 300, 200, &nan_axis, &good, NULL) == -1, "accepted");
    CHECK("panel: box smaller than the margins rejected", svg_panel_begin(&p, &d, 0, 0, 50, 200, &good, &good, NULL) == -1, "accepted");
    after = ftell(f);
    CHECK("panel: a rejected panel writes nothing", before == after, "%ld bytes", after - before);
    {
        svg_axis lx = {0.01, 100.0, SVG_LOG10, 0.0, NULL, NULL};
        double mid;
        svg_panel_begin(&p, &d, 0, 0, 300, 200, &lx, &lx, NULL);
        mid = svg_panel_px(&p, 1.0);
        CHECK("panel: log10 axis puts 1 halfway between 0.01 and 100",
              fabs(mid - (p.x + 0.5 * p.w)) < 1e-9, "%.6f vs %.6f", mid, p.x + 0.5 * p.w);
        CHECK("panel: y grows upwards", svg_panel_py(&p, 100.0) < svg_panel_py(&p, 0.01), "%.3f %.3f",
              svg_panel_py(&p, 100.0), svg_panel_py(&p, 0.01));
        CHECK("panel: data <= 0 on a log axis maps to a non-finite coordinate",
              !isfinite(svg_panel_px(&p, 0.0)), "%.3f", svg_panel_px(&p, 0.0));
    }
    CHECK("svg_end: 0 on a good stream", svg_end(&d) == 0, "-1");
    fclose(f);
}

int main(int argc, char **argv)
{
    char dir[] = "/tmp/test_svg.XXXXXX", a[256], b[256];
    char *ta, *tb, why[128] = "";
    long na = 0, nb = 0;

    if (argc == 3 && !strcmp(argv[1], "--write"))
        return write_file(argv[2]) ? 1 : 0;

    test_srgb();
    test_panel_rejects();
    if (!mkdtemp(dir)) {
        CHECK("temp directory", 0, "mkdtemp failed");
        return harness_exit();
    }
    snprintf(a, sizeof a, "%s/a.svg", dir);
    snprintf(b, sizeof b, "%s/b.svg", dir);
    CHECK("sample plot written (svg_end reports no error)", write_file(a) == 0 && write_file(b) == 0,
          "write failed in %s", dir);
    ta = read_all(a, &na);
    tb = read_all(b, &nb);
    if (ta && tb) {
        CHECK("deterministic: two writes are byte-identical", na == nb && !memcmp(ta, tb, (size_t)na),
              "%ld vs %ld bytes", na, nb);
        CHECK("well-formed: balanced, nested, quoted, escaped", well_formed(ta, why, sizeof why),
              "%s", why);
        CHECK("title escaped, invalid UTF-8 replaced",
              strstr(ta, "<title>copper &lt;Schlick&gt; &amp; &quot;ground truth&quot; \xe2\x80\x94 bad ? byte</title>") != NULL,
              "title not found as expected");
        CHECK("no NaN, Inf or negative zero printed",
              !strstr(ta, "nan") && !strstr(ta, "inf") && !strstr(ta, "\"-0\"") && !strstr(ta, " -0,") &&
                  !strstr(ta, "\"-0,"),
              "found one");
        {
            /* 91 rects in the strip's group, the first with gold's red clamped to ff. */
            const char *g = strstr(ta, "<g shape-rendering=\"crispEdges\">"), *s = g;
            int rects = 0;
            while (s && (s = strstr(s + 1, "<rect")) != NULL && s < strstr(g, "</g>"))
                rects++;
            CHECK("strip: 91 rects, the out-of-gamut first one clamped to red ff",
                  g && rects == 91 && strstr(g, "fill=\"#ff") == strstr(g, "fill=\""), "%d rects",
                  rects);
        }
        {
            /* "off-plot" is also a legend entry: only that one may be there. */
            const char *first = strstr(ta, ">off-plot</text>");
            CHECK("point outside the log panel (y = 0) is not drawn",
                  first && !strstr(first + 1, ">off-plot</text>"), "drawn");
        }
        CHECK("log axis labels decades", strstr(ta, ">0.001</text>") && strstr(ta, ">10</text>"),
              "decade labels missing");
    } else {
        CHECK("sample plot read back", 0, "%s or %s", a, b);
    }
    free(ta);
    free(tb);
    remove(a);
    remove(b);
    test_clipping(dir);
    rmdir(dir);
    {
        /* The tiny checker itself must reject what it is there to catch. */
        CHECK("checker rejects unbalanced tags", !well_formed("<?xml ?><svg><g></svg>", why, sizeof why), "accepted");
        CHECK("checker rejects a raw &", !well_formed("<?xml ?><svg><text>a & b</text></svg>", why, sizeof why), "accepted");
        CHECK("checker rejects an unquoted attribute", !well_formed("<?xml ?><svg x=1></svg>", why, sizeof why), "accepted");
    }
    return harness_exit();
}
