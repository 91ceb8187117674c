/* What the importers share (import.c and the load_<format>.c files): a file
 * read whole and walked line by line, columns of one quantity against
 * wavelength, and the merge of an n and a k column into an nk_table. Host
 * only. Every error is "path:line: what was expected" and CLI_BAD_INPUT. */
#ifndef FRESNEL_IMPORT_H
#define FRESNEL_IMPORT_H

#include <stddef.h>

#include "1_spectral/spectral.h"

/* A whole file in memory. data holds the bytes as read (what the hash
 * covers) with a NUL after them; text_next cuts lines in a copy. */
typedef struct text_file {
    const char *path;
    unsigned char *data; /* as read */
    size_t size;
    char *text;          /* copy walked by text_next, byte-order mark skipped */
    size_t pos;
    int line;            /* line last returned, 1-based */
} text_file;
int text_read(const char *path, text_file *t);
/* Next line without its LF or CRLF: 1, or 0 at the end. */
int text_next(text_file *t, char **line);
void text_free(text_file *t);
int text_error(const text_file *t, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* The numbers of s, separated by blanks, tabs and any character of seps:
 * their count (at most max stored, more is an error), or -1 after a message
 * naming the word that is not a finite number. */
int text_numbers(const text_file *t, int line, char *s, const char *seps, double *out, int max);

/* um in nm as the decimal the file wrote would read in nm: 0.1879 um is
 * the double nearest 187.9, where 0.1879 * 1000 is one unit in the last
 * place off, and the data pack's CSV of the same rows would then resample
 * differently in the last bits. Exact for up to 15 significant digits. */
double nm_from_um(double um);

/* One quantity (n or k) against wavelength in nm, strictly ascending, with
 * the file line of each row. */
typedef struct nk_column {
    int rows, cap;
    double *wl, *v;
    int *line;
} nk_column;
/* Append a row; a wavelength not above the previous one is an error at line. */
int column_push(const text_file *t, nk_column *c, double wl_nm, double v, int line);
void column_free(nk_column *c);

/* Merge n with k (NULL: k = 0 everywhere; k_path names its file, NULL: t's) into out: the rows are n's
 * wavelengths and k's within n's range; each quantity is interpolated
 * linearly in its own column and k is held at its end values beyond its
 * range (a warning when that reaches into 360-830 nm). Every row is checked
 * with nk_check_row. unit describes the file's wavelengths for messages. */
int nk_merge(const text_file *t, const char *unit, const nk_column *n, const char *k_path, const nk_column *k,
             nk_table *out);

/* The format readers. load_spd takes the k file or NULL (k = 0). */
int load_rii_yaml(text_file *t, nk_table *out);
int load_rii_csv(text_file *t, nk_table *out);
int load_sopra(text_file *t, nk_table *out);
int load_spd(text_file *eta, text_file *k, nk_table *out);

/* SHA-256 (FIPS 180-4) of size bytes, as 64 lower-case hex digits. */
void sha256_hex(const unsigned char *data, size_t size, char out[65]);

#endif
