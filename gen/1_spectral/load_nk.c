/* Spectral step 1 of 7: a measured wavelength,n,k table, read
 * strictly. A wrong file must stop the generator with the line to fix rather
 * than quietly turn into wrong RGB constants, so every rule of data/README.md
 * ("File format") is checked here. The line reader is shared with the other
 * data tables (see spectral.h). */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "1_spectral/spectral.h"

#define NK_HEADER "wavelength_nm,n,k"
/* Most data rows accepted. Measured tables have tens to a few thousand rows
 * (even 0.005 nm spacing over 360-830 nm is 94001); the cap bounds the
 * memory and time a hostile file (100 MB of rows) can take. */
#define NK_MAX_ROWS 100000

int csv_error(const csv_reader *r, const char *fmt, ...)
{
    va_list ap;
    char where[1100];
    snprintf(where, sizeof where, "%s:%d", r->path, r->line);
    va_start(ap, fmt);
    cli_verror(where, fmt, ap);
    va_end(ap);
    return CLI_BAD_INPUT;
}

/* Longest line accepted in a data file. The real tables' lines are under
 * 200 bytes; the cap keeps a hostile file (one 100 MB line, say) from being
 * read into memory whole, as getline would. */
#define CSV_MAX_LINE 4096

/* Reads one physical line into r->buf without its LF or CRLF ending.
 * 1 = line read, 0 = end of file, -1 = error (message printed). */
static int read_line(csv_reader *r, char **line)
{
    size_t len = 0;
    int ch;
    if (!r->buf) {
        r->buf = malloc(CSV_MAX_LINE + 1);
        if (!r->buf) {
            cli_oom(r->path);
            return -1;
        }
        r->cap = CSV_MAX_LINE + 1;
    }
    while ((ch = getc(r->f)) != EOF && ch != '\n') {
        /* A CR is a line end only before LF; alone, the file has classic
         * Mac OS line ends and would read as one long line. */
        if (ch == '\0' || len == CSV_MAX_LINE || (len > 0 && r->buf[len - 1] == '\r')) {
            r->line++;
            if (ch == '\0')
                csv_error(r, "expected text, found a NUL byte");
            else if (len > 0 && r->buf[len - 1] == '\r')
                csv_error(r, "expected lines ending in LF or CR LF, found a CR alone (classic Mac OS line ends)");
            else
                csv_error(r, "expected a line of at most %d bytes", CSV_MAX_LINE);
            return -1;
        }
        r->buf[len++] = (char)ch;
    }
    if (ch == EOF) {
        if (ferror(r->f)) {
            char where[1100];
            snprintf(where, sizeof where, "%s:%d", r->path, r->line + 1);
            cli_read_failure(where, errno);
            return -1;
        }
        if (len == 0)
            return 0;
    }
    r->line++;
    if (len > 0 && r->buf[len - 1] == '\r')
        len--;
    r->buf[len] = '\0';
    *line = r->buf;
    return 1;
}

int csv_open(csv_reader *r, const char *path, const char *header)
{
    static const char utf8_bom[] = "\xEF\xBB\xBF";
    char *line;
    int got;
    r->path = path;
    r->line = 0;
    r->buf = NULL;
    r->cap = 0;
    if ((got = cli_open_input(path, &r->f)))
        return got;
    got = read_line(r, &line);
    if (got < 0) {
        csv_close(r);
        return CLI_BAD_INPUT;
    }
    if (got == 0) {
        r->line = 1;
        csv_error(r, "expected the header line '%s', got an empty file", header);
        csv_close(r);
        return CLI_BAD_INPUT;
    }
    /* Spreadsheet exports often start with a byte-order mark; it is not part of the header. */
    if (!strncmp(line, utf8_bom, 3))
        line += 3;
    if (strcmp(line, header) != 0) {
        csv_error(r, "expected the header line '%s', got '%.60s'", header, line);
        csv_close(r);
        return CLI_BAD_INPUT;
    }
    return 0;
}

int csv_next_row(csv_reader *r, char **row)
{
    int first_blank = 0;
    for (;;) {
        char *line;
        int got = read_line(r, &line);
        if (got <= 0)
            return got;
        if (line[strspn(line, " \t")] == '\0') {
            /* Trailing blank lines are harmless; a gap inside the table is
             * more likely a truncated or hand-merged file. */
            if (!first_blank)
                first_blank = r->line;
            continue;
        }
        if (first_blank) {
            r->line = first_blank;
            csv_error(r, "expected a data row, got an empty line");
            return -1;
        }
        *row = line;
        return 1;
    }
}

int csv_split(char *row, char **field, int max)
{
    int count = 0;
    char *p = row;
    for (;;) {
        char *comma = strchr(p, ',');
        if (count < max)
            field[count] = p;
        count++;
        if (!comma)
            return count;
        *comma = '\0';
        p = comma + 1;
    }
}

int csv_number(const csv_reader *r, const char *field, const char *column, double *out)
{
    char *end;
    double v = strtod(field, &end);
    if (end == field)
        return csv_error(r, "column %s: expected a number, got '%.40s'", column, field);
    end += strspn(end, " \t");
    if (*end != '\0')
        return csv_error(r, "column %s: expected a number, got '%.40s'", column, field);
    /* Overflow comes back as infinity and is caught here; underflow to
     * zero is a harmless rounding of a tiny k. */
    if (!isfinite(v))
        return csv_error(r, "column %s: expected a finite number, got '%.40s'", column, field);
    *out = v;
    return 0;
}

void csv_close(csv_reader *r)
{
    if (r->f)
        fclose(r->f);
    r->f = NULL;
    free(r->buf);
    r->buf = NULL;
    r->cap = 0;
}

void nk_table_free(nk_table *t)
{
    free(t->wl);
    free(t->n);
    free(t->k);
    t->wl = t->n = t->k = NULL;
    t->rows = 0;
}

static int grow(nk_table *t, int *capacity)
{
    int cap = *capacity ? 2 * *capacity : 64;
    double *wl = realloc(t->wl, (size_t)cap * sizeof *wl);
    double *n, *k;
    if (!wl)
        return -1;
    t->wl = wl;
    n = realloc(t->n, (size_t)cap * sizeof *n);
    if (!n)
        return -1;
    t->n = n;
    k = realloc(t->k, (size_t)cap * sizeof *k);
    if (!k)
        return -1;
    t->k = k;
    *capacity = cap;
    return 0;
}

int nk_check_row(const char *path, int line, double wl, double n, double k)
{
    char where[1100];
    snprintf(where, sizeof where, "%s:%d", path, line);
    if (!(wl > 0.0) || !isfinite(wl))
        return cli_error(where, "wavelength %.10g nm, expected a finite positive number", wl);
    /* n <= 0 has no physical passive medium behind it and would make eta/n1
     * meaningless; k < 0 would be a gain medium. */
    if (!(n > 0.0))
        return cli_error(where, "n = %.10g, expected n > 0", n);
    if (!(k >= 0.0))
        return cli_error(where, "k = %.10g, expected k >= 0", k);
    /* Headers hold n and k (and what derives from them) as binary32: a value
     * beyond FLT_MAX would be an infinity there, an n below FLT_MIN zero or
     * a subnormal. A tiny k flushing to 0 changes nothing measurable. */
    if (n > FLT_MAX || n < FLT_MIN)
        return cli_error(where, "n = %.10g, expected n in [%.9g, %.9g] (binary32, the generated headers' float)", n,
                         (double)FLT_MIN, (double)FLT_MAX);
    if (k > FLT_MAX)
        return cli_error(where, "k = %.10g, expected k <= %.9g (binary32, the generated headers' float)", k,
                         (double)FLT_MAX);
    return 0;
}

/* One data row into wl, n, k, with the per-row rules; 0 or CLI_BAD_INPUT. */
static int parse_nk_row(const csv_reader *r, char *row, double *wl, double *n, double *k)
{
    char *field[3];
    int count = csv_split(row, field, 3);
    if (count != 3)
        return csv_error(r, "expected 3 columns (" NK_HEADER "), got %d", count);
    if (csv_number(r, field[0], "wavelength_nm", wl) || csv_number(r, field[1], "n", n) ||
        csv_number(r, field[2], "k", k))
        return CLI_BAD_INPUT;
    return nk_check_row(r->path, r->line, *wl, *n, *k);
}

int load_nk(const char *path, nk_table *t)
{
    csv_reader r;
    int capacity = 0, got, last_row_line = 1;
    char *row;
    t->rows = 0;
    t->wl = t->n = t->k = NULL;
    t->first_line = 2;
    t->unit = "nm";
    if (csv_open(&r, path, NK_HEADER))
        return CLI_BAD_INPUT;
    while ((got = csv_next_row(&r, &row)) == 1) {
        double wl, n, k;
        if (parse_nk_row(&r, row, &wl, &n, &k))
            goto fail;
        /* Interpolation needs a function of wavelength: a repeated or
         * backwards wavelength is a merged or mis-sorted file. */
        if (t->rows > 0 && !(wl > t->wl[t->rows - 1])) {
            csv_error(&r, "wavelength %.10g not greater than previous %.10g", wl,
                      t->wl[t->rows - 1]);
            goto fail;
        }
        if (t->rows == NK_MAX_ROWS) {
            csv_error(&r, "expected at most %d data rows", NK_MAX_ROWS);
            goto fail;
        }
        if (t->rows == capacity && grow(t, &capacity)) {
            cli_oom(path);
            goto fail;
        }
        t->wl[t->rows] = wl;
        t->n[t->rows] = n;
        t->k[t->rows] = k;
        t->rows++;
        last_row_line = r.line;
    }
    if (got < 0)
        goto fail;
    if (t->rows < 2) {
        r.line = last_row_line + 1;
        csv_error(&r, "expected at least two data rows (" NK_HEADER "), got %d", t->rows);
        goto fail;
    }
    t->last_line = last_row_line;
    csv_close(&r);
    return 0;
fail:
    csv_close(&r);
    nk_table_free(t);
    return CLI_BAD_INPUT;
}
