/* SVG writer for the report's plots; see svg.h. */
#include <math.h>
#include <stdarg.h>
#include <string.h>

#include "report/svg.h"

/* ---- output: one tiny formatter so every number goes through the same
 * fixed format, which is what makes two runs byte-identical. */

/* Coordinates and sizes to 0.01 unit (far below a pixel), trailing zeros
 * dropped, never "-0". A non-finite value cannot be drawn; 0 keeps the file
 * well-formed and the plot visibly wrong rather than unreadable. */
static void put_num(FILE *f, double v)
{
    char buf[64];
    size_t len;
    if (!isfinite(v))
        v = 0.0;
    v = round(v * 100.0) / 100.0;
    if (v == 0.0)
        v = 0.0; /* turns -0 into +0 */
    snprintf(buf, sizeof buf, "%.2f", v);
    len = strlen(buf);
    while (buf[len - 1] == '0')
        buf[--len] = '\0';
    if (buf[len - 1] == '.')
        buf[--len] = '\0';
    fputs(buf, f);
}

/* Number of bytes of the valid UTF-8 sequence starting at s, or 0. Invalid
 * bytes would make the whole document unreadable to an XML parser. */
static int utf8_len(const unsigned char *s)
{
    int n, i;
    if (s[0] < 0x80)
        return 1;
    if (s[0] >= 0xc2 && s[0] <= 0xdf)
        n = 2;
    else if (s[0] >= 0xe0 && s[0] <= 0xef)
        n = 3;
    else if (s[0] >= 0xf0 && s[0] <= 0xf4)
        n = 4;
    else
        return 0;
    for (i = 1; i < n; i++)
        if ((s[i] & 0xc0) != 0x80)
            return 0;
    /* overlong 3- and 4-byte forms, surrogates, beyond U+10FFFF */
    if ((s[0] == 0xe0 && s[1] < 0xa0) || (s[0] == 0xed && s[1] >= 0xa0) ||
        (s[0] == 0xf0 && s[1] < 0x90) || (s[0] == 0xf4 && s[1] >= 0x90))
        return 0;
    return n;
}

static void put_text(FILE *f, const char *text)
{
    const unsigned char *s = (const unsigned char *)(text ? text : "");
    while (*s) {
        int n;
        switch (*s) {
        case '&': fputs("&amp;", f); s++; continue;
        case '<': fputs("&lt;", f); s++; continue;
        case '>': fputs("&gt;", f); s++; continue;
        case '"': fputs("&quot;", f); s++; continue;
        case '\'': fputs("&apos;", f); s++; continue;
        default: break;
        }
        if (*s < 0x20 && *s != '\t' && *s != '\n') { /* not allowed in XML 1.0 */
            fputc('?', f);
            s++;
            continue;
        }
        n = utf8_len(s);
        if (n == 0) {
            fputc('?', f);
            s++;
            continue;
        }
        fwrite(s, 1, (size_t)n, f);
        s += n;
    }
}

/* printf-like with its own directives: %n a coordinate (double), %t escaped
 * text, %s raw text (attribute values this file chose), %% a percent. */
static void out(const svg_doc *d, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    for (; *fmt; fmt++) {
        if (*fmt != '%') {
            fputc(*fmt, d->f);
            continue;
        }
        switch (*++fmt) {
        case 'n': put_num(d->f, va_arg(ap, double)); break;
        case 't': put_text(d->f, va_arg(ap, const char *)); break;
        case 's': fputs(va_arg(ap, const char *), d->f); break;
        case '%': fputc('%', d->f); break;
        default: fmt--; break; /* unreachable with this file's formats */
        }
    }
    va_end(ap);
}

/* ---- document */

void svg_begin(svg_doc *d, FILE *f, double width, double height, const char *title)
{
    d->f = f;
    d->width = width;
    d->height = height;
    out(d, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    out(d,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%n\" height=\"%n\" "
        "viewBox=\"0 0 %n %n\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n",
        width, height, width, height);
    if (title)
        out(d, "<title>%t</title>\n", title);
    out(d, "<rect x=\"0\" y=\"0\" width=\"%n\" height=\"%n\" fill=\"#ffffff\"/>\n", width, height);
}

int svg_end(svg_doc *d)
{
    out(d, "</svg>\n");
    if (fflush(d->f) != 0 || ferror(d->f))
        return -1;
    return 0;
}

static const char *anchor_name(svg_anchor a)
{
    return a == SVG_MIDDLE ? "middle" : a == SVG_END ? "end" : "start";
}

void svg_text(svg_doc *d, double x, double y, double size, svg_anchor anchor, const char *colour,
              const char *text)
{
    out(d, "<text x=\"%n\" y=\"%n\" font-size=\"%n\" text-anchor=\"%s\" fill=\"%t\">%t</text>\n", x,
        y, size, anchor_name(anchor), colour ? colour : "#000000", text);
}

void svg_rect(svg_doc *d, double x, double y, double w, double h, const char *fill,
              const char *stroke)
{
    out(d, "<rect x=\"%n\" y=\"%n\" width=\"%n\" height=\"%n\" fill=\"%t\"", x, y, w, h,
        fill ? fill : "none");
    if (stroke)
        out(d, " stroke=\"%t\" stroke-width=\"0.5\"", stroke);
    out(d, "/>\n");
}

static void stroke_attrs(const svg_doc *d, const svg_style *s)
{
    out(d, " fill=\"none\" stroke=\"%t\" stroke-width=\"%n\" stroke-linejoin=\"round\"",
        s && s->colour ? s->colour : "#000000", s && s->width > 0.0 ? s->width : 1.0);
    if (s && s->dash)
        out(d, " stroke-dasharray=\"%t\"", s->dash);
}

void svg_line(svg_doc *d, double x1, double y1, double x2, double y2, const svg_style *s)
{
    out(d, "<line x1=\"%n\" y1=\"%n\" x2=\"%n\" y2=\"%n\"", x1, y1, x2, y2);
    stroke_attrs(d, s);
    out(d, "/>\n");
}

void svg_marker_at(svg_doc *d, double x, double y, svg_marker m, double size, const char *colour)
{
    double r = 0.5 * size;
    const char *c = colour ? colour : "#000000";
    switch (m) {
    case SVG_NO_MARKER:
        break;
    case SVG_CIRCLE:
        out(d, "<circle cx=\"%n\" cy=\"%n\" r=\"%n\" fill=\"%t\"/>\n", x, y, r, c);
        break;
    case SVG_SQUARE:
        out(d, "<rect x=\"%n\" y=\"%n\" width=\"%n\" height=\"%n\" fill=\"%t\"/>\n", x - r, y - r,
            size, size, c);
        break;
    case SVG_TRIANGLE:
        out(d, "<polygon points=\"%n,%n %n,%n %n,%n\" fill=\"%t\"/>\n", x, y - r, x + r, y + r,
            x - r, y + r, c);
        break;
    case SVG_DIAMOND:
        out(d, "<polygon points=\"%n,%n %n,%n %n,%n %n,%n\" fill=\"%t\"/>\n", x, y - r, x + r, y, x,
            y + r, x - r, y, c);
        break;
    case SVG_CROSS:
        out(d,
            "<path d=\"M%n %nL%n %nM%n %nL%n %n\" fill=\"none\" stroke=\"%t\" "
            "stroke-width=\"%n\"/>\n",
            x - r, y - r, x + r, y + r, x - r, y + r, x + r, y - r, c, 0.25 * size);
        break;
    }
}

/* ---- colour */

unsigned svg_srgb8(double linear)
{
    double v;
    if (!(linear > 0.0)) /* also NaN */
        return 0;
    if (linear >= 1.0)
        return 255;
    v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
    return (unsigned)floor(v * 255.0 + 0.5);
}

void svg_srgb_hex(const double rgb[3], char out[8])
{
    static const char hex[] = "0123456789abcdef";
    int i;
    out[0] = '#';
    for (i = 0; i < 3; i++) {
        unsigned v = svg_srgb8(rgb[i]);
        out[1 + 2 * i] = hex[v >> 4];
        out[2 + 2 * i] = hex[v & 15];
    }
    out[7] = '\0';
}

const char *svg_palette(int i)
{
    /* Okabe-Ito order, with black last and the hard-to-see yellow late. */
    static const char *const colours[8] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                           "#e69f00", "#56b4e9", "#f0e442", "#000000"};
    return colours[((i % 8) + 8) % 8];
}

const char *svg_dash(int i)
{
    static const char *const dashes[4] = {NULL, "6 3", "2 2", "8 3 2 3"};
    return dashes[((i % 4) + 4) % 4];
}

void svg_strip(svg_doc *d, double x, double y, double w, double h, const double (*rgb)[3], int n)
{
    /* A quarter unit of overlap hides the seams anti-aliasing would show
     * between abutting rectangles, and is too small to shift a colour. */
    const double overlap = 0.25;
    int i;
    out(d, "<g shape-rendering=\"crispEdges\">\n");
    for (i = 0; i < n; i++) {
        char hex[8];
        double x0 = x + w * i / n, x1 = x + w * (i + 1) / n;
        svg_srgb_hex(rgb[i], hex);
        out(d, "<rect x=\"%n\" y=\"%n\" width=\"%n\" height=\"%n\" fill=\"%s\"/>\n", x0, y,
            x1 - x0 + (i + 1 < n ? overlap : 0.0), h, hex);
    }
    out(d, "</g>\n");
}

/* ---- panels */

static double axis_t(const svg_axis *a, double v)
{
    if (a->scale == SVG_LOG10)
        return v > 0.0 ? log10(v) : NAN;
    return v;
}

double svg_panel_px(const svg_panel *p, double x)
{
    double lo = axis_t(&p->xa, p->xa.lo), hi = axis_t(&p->xa, p->xa.hi);
    return p->x + p->w * (axis_t(&p->xa, x) - lo) / (hi - lo);
}

double svg_panel_py(const svg_panel *p, double y)
{
    double lo = axis_t(&p->ya, p->ya.lo), hi = axis_t(&p->ya, p->ya.hi);
    return p->y + p->h - p->h * (axis_t(&p->ya, y) - lo) / (hi - lo);
}

static int axis_valid(const svg_axis *a)
{
    if (!(isfinite(a->lo) && isfinite(a->hi) && a->lo < a->hi))
        return 0;
    return a->scale != SVG_LOG10 || a->lo > 0.0;
}

/* 1, 2 or 5 times a power of ten, near span / 6: five to eight ticks. */
static double nice_step(double span)
{
    double raw = span / 6.0, mag = pow(10.0, floor(log10(raw))), f = raw / mag;
    return mag * (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0);
}

static void tick_label(char *buf, size_t size, const svg_axis *a, double v)
{
    /* The format is the caller's; it is applied to one double. */
    snprintf(buf, size, a->format ? a->format : "%g", v);
}

/* One tick of the x (vertical == 0) or y axis at value v: grid line for
 * labelled ticks, tick mark, label. */
static void draw_tick(const svg_panel *p, int vertical, double v, int labelled)
{
    const svg_axis *a = vertical ? &p->ya : &p->xa;
    const double len = labelled ? 4.0 : 2.0;
    char label[64];
    if (vertical) {
        double y = svg_panel_py(p, v);
        if (labelled)
            out(p->doc,
                "<line x1=\"%n\" y1=\"%n\" x2=\"%n\" y2=\"%n\" stroke=\"#e0e0e0\" "
                "stroke-width=\"0.5\"/>\n",
                p->x, y, p->x + p->w, y);
        out(p->doc, "<line x1=\"%n\" y1=\"%n\" x2=\"%n\" y2=\"%n\" stroke=\"#000000\"/>\n",
            p->x - len, y, p->x, y);
        if (labelled) {
            tick_label(label, sizeof label, a, v);
            svg_text(p->doc, p->x - 6.0, y + 3.5, 10.0, SVG_END, NULL, label);
        }
    } else {
        double x = svg_panel_px(p, v);
        if (labelled)
            out(p->doc,
                "<line x1=\"%n\" y1=\"%n\" x2=\"%n\" y2=\"%n\" stroke=\"#e0e0e0\" "
                "stroke-width=\"0.5\"/>\n",
                x, p->y, x, p->y + p->h);
        out(p->doc, "<line x1=\"%n\" y1=\"%n\" x2=\"%n\" y2=\"%n\" stroke=\"#000000\"/>\n", x,
            p->y + p->h, x, p->y + p->h + len);
        if (labelled) {
            tick_label(label, sizeof label, a, v);
            svg_text(p->doc, x, p->y + p->h + 15.0, 10.0, SVG_MIDDLE, NULL, label);
        }
    }
}

static void draw_ticks(const svg_panel *p, int vertical)
{
    const svg_axis *a = vertical ? &p->ya : &p->xa;
    if (a->scale == SVG_LOG10) {
        int k, m, k0 = (int)floor(log10(a->lo)), k1 = (int)ceil(log10(a->hi)), decades = 0;
        double lo = a->lo * (1.0 - 1e-9), hi = a->hi * (1.0 + 1e-9);
        for (k = k0; k <= k1; k++)
            if (pow(10.0, k) >= lo && pow(10.0, k) <= hi)
                decades++;
        /* With fewer than two decades in range, decade labels alone would
         * not tell the scale: label every tick. */
        for (k = k0; k <= k1; k++)
            for (m = 1; m <= 9; m++) {
                double v = m * pow(10.0, k);
                if (v >= lo && v <= hi)
                    draw_tick(p, vertical, v, m == 1 || decades < 2);
            }
    } else {
        double span = a->hi - a->lo, step = a->tick > 0.0 ? a->tick : nice_step(span), k, k0, k1;
        if (span / step > 100.0)
            step = nice_step(span);
        k0 = ceil(a->lo / step - 1e-9);
        k1 = floor(a->hi / step + 1e-9);
        for (k = k0; k <= k1; k++) {
            double v = k * step;
            if (fabs(v) < 1e-9 * step)
                v = 0.0;
            draw_tick(p, vertical, v, 1);
        }
    }
}

int svg_panel_begin(svg_panel *p, svg_doc *d, double x, double y, double w, double h,
                    const svg_axis *xa, const svg_axis *ya, const char *title)
{
    if (!axis_valid(xa) || !axis_valid(ya) || !(w > SVG_MARGIN_LEFT + SVG_MARGIN_RIGHT) ||
        !(h > SVG_MARGIN_TOP + SVG_MARGIN_BOTTOM))
        return -1;
    p->doc = d;
    p->x = x + SVG_MARGIN_LEFT;
    p->y = y + SVG_MARGIN_TOP;
    p->w = w - SVG_MARGIN_LEFT - SVG_MARGIN_RIGHT;
    p->h = h - SVG_MARGIN_TOP - SVG_MARGIN_BOTTOM;
    p->xa = *xa;
    p->ya = *ya;
    out(d, "<g font-size=\"10\">\n");
    draw_ticks(p, 0);
    draw_ticks(p, 1);
    svg_rect(d, p->x, p->y, p->w, p->h, NULL, "#000000");
    if (xa->label)
        svg_text(d, p->x + 0.5 * p->w, p->y + p->h + 33.0, 11.0, SVG_MIDDLE, NULL, xa->label);
    if (ya->label)
        out(d,
            "<text transform=\"translate(%n,%n) rotate(-90)\" font-size=\"11\" "
            "text-anchor=\"middle\" fill=\"#000000\">%t</text>\n",
            x + 14.0, p->y + 0.5 * p->h, ya->label);
    if (title)
        svg_text(d, p->x + 0.5 * p->w, y + 16.0, 12.0, SVG_MIDDLE, NULL, title);
    out(d, "</g>\n");
    return 0;
}

/* Liang-Barsky: the part t0..t1 of the segment a + t (b - a), t in [0, 1],
 * inside the plot area; 0 when none is. */
static int clip_segment(const svg_panel *p, const double a[2], const double b[2], double *t0,
                        double *t1)
{
    double dx = b[0] - a[0], dy = b[1] - a[1];
    double pp[4], q[4];
    int i;
    pp[0] = -dx, q[0] = a[0] - p->x;
    pp[1] = dx, q[1] = p->x + p->w - a[0];
    pp[2] = -dy, q[2] = a[1] - p->y;
    pp[3] = dy, q[3] = p->y + p->h - a[1];
    *t0 = 0.0;
    *t1 = 1.0;
    for (i = 0; i < 4; i++) {
        if (pp[i] == 0.0) {
            if (q[i] < 0.0)
                return 0;
        } else {
            double r = q[i] / pp[i];
            if (pp[i] < 0.0) {
                if (r > *t0)
                    *t0 = r;
            } else if (r < *t1) {
                *t1 = r;
            }
        }
    }
    return *t0 <= *t1;
}

void svg_polyline(const svg_panel *p, const double *x, const double *y, int n, const svg_style *s)
{
    int i, open = 0;
    for (i = 1; i < n; i++) {
        double a[2], b[2], t0, t1;
        a[0] = svg_panel_px(p, x[i - 1]);
        a[1] = svg_panel_py(p, y[i - 1]);
        b[0] = svg_panel_px(p, x[i]);
        b[1] = svg_panel_py(p, y[i]);
        if (!(isfinite(a[0]) && isfinite(a[1]) && isfinite(b[0]) && isfinite(b[1])) ||
            !clip_segment(p, a, b, &t0, &t1)) {
            if (open)
                out(p->doc, "\"/>\n");
            open = 0;
            continue;
        }
        /* A run continues only where the previous segment ended unclipped
         * (open) and this one starts unclipped (t0 == 0): the same point. */
        if (open && t0 != 0.0) {
            out(p->doc, "\"/>\n");
            open = 0;
        }
        if (!open) {
            out(p->doc, "<polyline");
            stroke_attrs(p->doc, s);
            out(p->doc, " points=\"%n,%n", a[0] + t0 * (b[0] - a[0]), a[1] + t0 * (b[1] - a[1]));
            open = 1;
        }
        out(p->doc, " %n,%n", a[0] + t1 * (b[0] - a[0]), a[1] + t1 * (b[1] - a[1]));
        if (t1 < 1.0) {
            out(p->doc, "\"/>\n");
            open = 0;
        }
    }
    if (open)
        out(p->doc, "\"/>\n");
}

int svg_point(const svg_panel *p, double x, double y, svg_marker m, double size,
              const char *colour, const char *label, svg_label_pos pos)
{
    const double slack = 1e-9 * (p->w + p->h);
    double px = svg_panel_px(p, x), py = svg_panel_py(p, y), gap = 0.5 * size + 2.0;
    if (!(px >= p->x - slack && px <= p->x + p->w + slack && py >= p->y - slack &&
          py <= p->y + p->h + slack))
        return 0;
    svg_marker_at(p->doc, px, py, m, size, colour);
    if (label) {
        switch (pos) {
        case SVG_LABEL_RIGHT:
            svg_text(p->doc, px + gap, py + 3.0, 9.0, SVG_START, NULL, label);
            break;
        case SVG_LABEL_LEFT:
            svg_text(p->doc, px - gap, py + 3.0, 9.0, SVG_END, NULL, label);
            break;
        case SVG_LABEL_ABOVE:
            svg_text(p->doc, px, py - gap, 9.0, SVG_MIDDLE, NULL, label);
            break;
        case SVG_LABEL_BELOW:
            svg_text(p->doc, px, py + gap + 7.0, 9.0, SVG_MIDDLE, NULL, label);
            break;
        }
    }
    return 1;
}

/* ---- legends */

void svg_legend_begin(svg_legend *l, svg_doc *d, double x, double y)
{
    l->doc = d;
    l->x = x;
    l->y = y;
    l->n = 0;
}

void svg_legend_entry(svg_legend *l, const svg_style *line, svg_marker m, const char *marker_colour,
                      const char *label)
{
    double y = l->y + SVG_LEGEND_ROW * (l->n + 0.5);
    if (line)
        svg_line(l->doc, l->x, y, l->x + 24.0, y, line);
    if (m != SVG_NO_MARKER)
        svg_marker_at(l->doc, l->x + 12.0, y, m, 6.0,
                      marker_colour ? marker_colour : line ? line->colour : NULL);
    svg_text(l->doc, l->x + 30.0, y + 3.5, 10.0, SVG_START, NULL, label);
    l->n++;
}
