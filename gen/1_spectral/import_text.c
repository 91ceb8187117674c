/* The importers' shared parts (import.h): a file read whole, its lines and
 * numbers, columns of n or k against wavelength, and their merge into one
 * n,k table. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "1_spectral/import.h"

/* Largest file read. The biggest refractiveindex.info data files are a few
 * hundred kB; the cap keeps a hostile input from filling memory. */
#define IMPORT_MAX_BYTES (16L * 1024 * 1024)
/* Most rows in one column, as load_nk's cap on the data pack's tables. */
#define IMPORT_MAX_ROWS 100000

int text_error(const text_file *t, int line, const char *fmt, ...)
{
    va_list ap;
    char where[1100];
    if (line > 0)
        snprintf(where, sizeof where, "%s:%d", t->path, line);
    else
        snprintf(where, sizeof where, "%s", t->path);
    va_start(ap, fmt);
    cli_verror(where, fmt, ap);
    va_end(ap);
    return CLI_BAD_INPUT;
}

int text_read(const char *path, text_file *t)
{
    FILE *f;
    size_t cap = 0, i;
    int line = 1;
    int status;
    memset(t, 0, sizeof *t);
    t->path = path;
    if ((status = cli_open_input(path, &f)))
        return status;
    for (;;) {
        size_t got;
        if (t->size == cap) {
            unsigned char *grown;
            cap = cap ? 2 * cap : 65536;
            if ((long)cap > IMPORT_MAX_BYTES + 1)
                cap = IMPORT_MAX_BYTES + 1;
            if (t->size == cap) {
                fclose(f);
                text_free(t);
                return cli_error(path, "expected a file of at most %ld bytes", IMPORT_MAX_BYTES);
            }
            if (!(grown = realloc(t->data, cap + 1))) {
                fclose(f);
                text_free(t);
                return cli_oom(path);
            }
            t->data = grown;
        }
        got = fread(t->data + t->size, 1, cap - t->size, f);
        t->size += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        int err = errno;
        fclose(f);
        text_free(t);
        return cli_read_failure(path, err);
    }
    fclose(f);
    for (i = 0; i < t->size; i++) {
        const char *bad = t->data[i] == '\0' ? "expected text, found a NUL byte"
                        : t->data[i] == '\r' && i + 1 < t->size && t->data[i + 1] != '\n'
                            ? "expected lines ending in LF or CR LF, found a CR alone (classic Mac OS line ends)"
                            : NULL;
        if (t->data[i] == '\n')
            line++;
        else if (bad) {
            text_error(t, line, "%s", bad);
            text_free(t);
            return CLI_BAD_INPUT;
        }
    }
    t->data[t->size] = '\0';
    if (!(t->text = malloc(t->size + 1))) {
        text_free(t);
        return cli_oom(path);
    }
    memcpy(t->text, t->data, t->size + 1);
    /* A byte-order mark (spreadsheet exports write one) is not content. */
    t->pos = cli_skip_bom(t->text);
    return 0;
}

int text_next(text_file *t, char **line)
{
    char *start, *end;
    if (t->pos >= t->size)
        return 0;
    start = t->text + t->pos;
    end = strchr(start, '\n');
    if (end) {
        t->pos = (size_t)(end - t->text) + 1;
        *end = '\0';
    } else {
        t->pos = t->size;
        end = start + strlen(start);
    }
    if (end > start && end[-1] == '\r')
        end[-1] = '\0';
    t->line++;
    *line = start;
    return 1;
}

void text_free(text_file *t)
{
    free(t->data);
    free(t->text);
    t->data = NULL;
    t->text = NULL;
    t->size = t->pos = 0;
}

int text_numbers(const text_file *t, int line, char *s, const char *seps, double *out, int max)
{
    char delim[16];
    int count = 0;
    char *word;
    snprintf(delim, sizeof delim, " \t%s", seps);
    for (word = strtok(s, delim); word; word = strtok(NULL, delim)) {
        double v;
        if (cli_parse_double(word, &v))
            return text_error(t, line, "expected a finite number, got '%.40s'", word), -1;
        if (count == max)
            return text_error(t, line, "expected at most %d numbers on the line", max), -1;
        out[count++] = v;
    }
    return count;
}

double nm_from_um(double um)
{
    char buf[48], *e;
    int exponent;
    snprintf(buf, sizeof buf, "%.14e", um);
    if (!(e = strchr(buf, 'e')))
        return um * 1000.0;
    exponent = atoi(e + 1);
    snprintf(e, sizeof buf - (size_t)(e - buf), "e%d", exponent + 3);
    return strtod(buf, NULL);
}

int column_push(const text_file *t, nk_column *c, double wl, double v, int line)
{
    /* Every reader converts its wavelengths to nm (um x 1000, 1239.84 / eV): a
     * finite number in the file can overflow there. */
    if (!isfinite(wl))
        return text_error(t, line, "the wavelength converts to %g nm, expected a finite number of nm", wl);
    if (!isfinite(v))
        return text_error(t, line, "the value converts to %g, expected a finite number", v);
    if (c->rows > 0 && !(wl > c->wl[c->rows - 1]))
        return text_error(t, line, "wavelength %.10g nm not greater than the previous row's %.10g nm "
                                   "(rows must be in increasing wavelength, each once)",
                          wl, c->wl[c->rows - 1]);
    if (c->rows == IMPORT_MAX_ROWS)
        return text_error(t, line, "expected at most %d rows", IMPORT_MAX_ROWS);
    if (c->rows == c->cap) {
        int cap = c->cap ? 2 * c->cap : 256;
        double *w = realloc(c->wl, (size_t)cap * sizeof *w), *x;
        int *l;
        if (w)
            c->wl = w;
        x = w ? realloc(c->v, (size_t)cap * sizeof *x) : NULL;
        if (x)
            c->v = x;
        l = x ? realloc(c->line, (size_t)cap * sizeof *l) : NULL;
        if (!l)
            return cli_oom(t->path);
        c->line = l;
        c->cap = cap;
    }
    c->wl[c->rows] = wl;
    c->v[c->rows] = v;
    c->line[c->rows] = line;
    c->rows++;
    return 0;
}

void column_free(nk_column *c)
{
    free(c->wl);
    free(c->v);
    free(c->line);
    memset(c, 0, sizeof *c);
}

/* c at wavelength wl: linear between rows, the end value beyond them. *seg
 * walks forward with ascending wl. */
static double column_at(const nk_column *c, double wl, int *seg)
{
    int last = c->rows - 1;
    double u;
    if (wl <= c->wl[0])
        return c->v[0];
    if (wl >= c->wl[last])
        return c->v[last];
    while (c->wl[*seg + 1] < wl)
        (*seg)++;
    u = (wl - c->wl[*seg]) / (c->wl[*seg + 1] - c->wl[*seg]);
    return (1.0 - u) * c->v[*seg] + u * c->v[*seg + 1];
}

/* A k that stops short of n's range is held there; say so when that part
 * is seen (inside 360-830 nm). */
static void warn_k_held(const char *k_path, const nk_column *n, const nk_column *k)
{
    double lo = n->wl[0] > SPEC_LO_NM ? n->wl[0] : SPEC_LO_NM;
    double hi = n->wl[n->rows - 1] < SPEC_HI_NM ? n->wl[n->rows - 1] : SPEC_HI_NM;
    double klo = k->wl[0], khi = k->wl[k->rows - 1];
    char where[1100];
    if (!(klo > lo || khi < hi))
        return;
    snprintf(where, sizeof where, "%s:%d", k_path, klo > lo ? k->line[0] : k->line[k->rows - 1]);
    fprintf(stderr, "%s: warning: k is tabulated over %.10g-%.10g nm only; held at its end values over the rest "
                    "of n's %.10g-%.10g nm\n",
            where, klo, khi, n->wl[0], n->wl[n->rows - 1]);
}

int nk_merge(const text_file *t, const char *unit, const nk_column *n, const char *k_path, const nk_column *k,
             nk_table *out)
{
    int i = 0, j = 0, seg_n = 0, seg_k = 0, rows = 0, cap;
    double lo, hi;
    memset(out, 0, sizeof *out);
    if (n->rows < 2)
        return text_error(t, n->rows ? n->line[0] : t->line,
                          "expected at least two rows of n, got %d", n->rows);
    if (k && k->rows < 1)
        k = NULL;
    for (i = 0; i < n->rows; i++)
        if (nk_check_row(t->path, n->line[i], n->wl[i], n->v[i], 0.0))
            return CLI_BAD_INPUT;
    if (!k_path)
        k_path = t->path;
    for (i = 0; k && i < k->rows; i++)
        if (nk_check_row(k_path, k->line[i], k->wl[i], 1.0, k->v[i]))
            return CLI_BAD_INPUT;
    if (k)
        warn_k_held(k_path, n, k);
    lo = n->wl[0];
    hi = n->wl[n->rows - 1];
    cap = n->rows + (k ? k->rows : 0);
    out->wl = malloc((size_t)cap * sizeof *out->wl);
    out->n = malloc((size_t)cap * sizeof *out->n);
    out->k = malloc((size_t)cap * sizeof *out->k);
    if (!out->wl || !out->n || !out->k) {
        nk_table_free(out);
        return cli_oom(t->path);
    }
    /* The union of both columns' wavelengths inside n's range, in order. */
    i = j = 0;
    while (k && j < k->rows && k->wl[j] < lo)
        j++;
    while (i < n->rows || (k && j < k->rows && k->wl[j] <= hi)) {
        double wl;
        if (k && j < k->rows && k->wl[j] <= hi && (i == n->rows || k->wl[j] < n->wl[i]))
            wl = k->wl[j++];
        else {
            wl = n->wl[i++];
            if (k && j < k->rows && k->wl[j] == wl)
                j++;
        }
        out->wl[rows] = wl;
        out->n[rows] = column_at(n, wl, &seg_n);
        out->k[rows] = k ? column_at(k, wl, &seg_k) : 0.0;
        rows++;
    }
    out->rows = rows;
    out->first_line = n->line[0];
    out->last_line = n->line[n->rows - 1];
    out->unit = unit;
    return 0;
}
