/* A small SVG writer for the report's plots: panels with linear or log10
 * axes, polylines, labelled points, legends and colour strips.
 *
 * Output goes to a FILE* the caller owns (typically cli_outfile.f, committed
 * with cli_out_commit). Byte-identical output for identical calls: fixed
 * number formats (coordinates to 0.01 unit, no negative zero), no dates, no
 * generated ids. Write errors are not reported call by call; svg_end says
 * whether any write failed.
 *
 * Coordinates: document units with the origin at the top left, y down. Data
 * are drawn in panels, which map their axes' ranges onto a plot area, y up.
 * Text is UTF-8; XML's special characters are escaped. Host only. */
#ifndef FRESNEL_SVG_H
#define FRESNEL_SVG_H

#include <stdio.h>

typedef struct svg_doc {
    FILE *f;
    double width, height;
} svg_doc;

/* Writes the XML declaration, the <svg> element with a white background, and
 * <title> (may be NULL). */
void svg_begin(svg_doc *d, FILE *f, double width, double height, const char *title);
/* Closes the document and flushes; 0, or -1 when any write failed. */
int svg_end(svg_doc *d);

typedef enum svg_anchor { SVG_START, SVG_MIDDLE, SVG_END } svg_anchor;

typedef struct svg_style {
    const char *colour; /* any SVG colour ("#d55e00", "black"); NULL = black */
    double width;       /* stroke width; <= 0 means 1 */
    const char *dash;   /* stroke-dasharray ("6 3"); NULL = solid */
} svg_style;

typedef enum svg_marker {
    SVG_NO_MARKER,
    SVG_CIRCLE,
    SVG_SQUARE,
    SVG_TRIANGLE,
    SVG_DIAMOND,
    SVG_CROSS
} svg_marker;

/* ---- document coordinates */
void svg_text(svg_doc *d, double x, double y, double size, svg_anchor anchor, const char *colour,
              const char *text);
/* fill and stroke may be NULL (none). */
void svg_rect(svg_doc *d, double x, double y, double w, double h, const char *fill,
              const char *stroke);
void svg_line(svg_doc *d, double x1, double y1, double x2, double y2, const svg_style *s);
void svg_marker_at(svg_doc *d, double x, double y, svg_marker m, double size, const char *colour);

/* A colour strip (Hoffman's figures): n rectangles side by side filling the
 * box left to right, rect i filled with rgb[i] (linear sRGB, encoded with
 * svg_srgb_hex). Neighbours overlap slightly so no background shows between
 * them when the strip is rendered with anti-aliasing. */
void svg_strip(svg_doc *d, double x, double y, double w, double h, const double (*rgb)[3], int n);

/* Linear sRGB in [0, 1] -> 8-bit sRGB code value with the sRGB transfer
 * function (IEC 61966-2-1), rounded; values outside [0, 1] are clamped and
 * NaN is 0. */
unsigned svg_srgb8(double linear);
/* "#rrggbb" (lower case) of a linear sRGB triple; out has room for 8 chars. */
void svg_srgb_hex(const double rgb[3], char out[8]);

/* Categorical colours that stay distinguishable for colour-blind readers
 * (Okabe and Ito 2008, "Color Universal Design"), i taken modulo 8; and dash
 * patterns to tell apart more series than that, i modulo 4 (0 = solid). */
const char *svg_palette(int i);
const char *svg_dash(int i);

/* ---- panels */
typedef enum svg_scale { SVG_LINEAR, SVG_LOG10 } svg_scale;

typedef struct svg_axis {
    double lo, hi;      /* log10: both > 0 */
    svg_scale scale;
    double tick;        /* linear: tick spacing, <= 0 picks a 1-2-5 step; log10: unused
                           (labelled ticks at decades, unlabelled ones at 2..9 x decade) */
    const char *label;  /* axis title, may be NULL */
    const char *format; /* printf format of one double for tick labels; NULL = "%g" */
} svg_axis;

typedef struct svg_panel {
    svg_doc *doc;
    double x, y, w, h; /* plot area (inside the margins), document units */
    svg_axis xa, ya;
} svg_panel;

/* Margins between a panel's box and its plot area, for the title, tick
 * labels and axis titles. */
#define SVG_MARGIN_LEFT 62.0
#define SVG_MARGIN_RIGHT 14.0
#define SVG_MARGIN_TOP 26.0
#define SVG_MARGIN_BOTTOM 44.0

/* A panel in the box (x, y, w, h) of the document: draws grid, frame, ticks,
 * tick labels, axis titles and the title (may be NULL). Returns 0, or -1
 * (nothing drawn) when an axis range is not finite, empty, or not positive
 * on a log axis, or the box is smaller than the margins. */
int svg_panel_begin(svg_panel *p, svg_doc *d, double x, double y, double w, double h,
                    const svg_axis *xa, const svg_axis *ya, const char *title);
/* Data -> document coordinates; not finite for data <= 0 on a log axis. */
double svg_panel_px(const svg_panel *p, double x);
double svg_panel_py(const svg_panel *p, double y);

/* Connects the n points, clipped to the plot area: a point that is not
 * finite or not positive on a log axis breaks the line. */
void svg_polyline(const svg_panel *p, const double *x, const double *y, int n, const svg_style *s);

typedef enum svg_label_pos { SVG_LABEL_RIGHT, SVG_LABEL_LEFT, SVG_LABEL_ABOVE, SVG_LABEL_BELOW }
    svg_label_pos;
/* A marker (size = its width) at a data point, with an optional label
 * (NULL) beside it. Returns 1, or 0 (nothing drawn) when the point is outside
 * the plot area. */
int svg_point(const svg_panel *p, double x, double y, svg_marker m, double size,
              const char *colour, const char *label, svg_label_pos pos);

/* ---- legends: entries stacked downwards from (x, y) in document units. */
typedef struct svg_legend {
    svg_doc *doc;
    double x, y;
    int n;
} svg_legend;
#define SVG_LEGEND_ROW 14.0 /* height of one entry */
void svg_legend_begin(svg_legend *l, svg_doc *d, double x, double y);
/* A line sample (line may be NULL), a marker on it (SVG_NO_MARKER for none,
 * marker_colour NULL = the line's colour) and the label. */
void svg_legend_entry(svg_legend *l, const svg_style *line, svg_marker m, const char *marker_colour,
                      const char *label);

#endif
