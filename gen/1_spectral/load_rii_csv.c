/* A refractiveindex.info CSV export: wavelengths in um, either one block
 *
 *   wl,n,k            rows "um,n,k"
 *
 * or a block "wl,n" (rows "um,n") optionally followed by a block "wl,k"
 * (rows "um,k"); blank lines may separate the blocks. k absent is k = 0. A
 * header other than these, a block given twice, a row with the wrong number
 * of fields and a block without rows are errors at their line. */
#include <string.h>

#include "common/cli.h"
#include "1_spectral/import.h"

enum block { BLOCK_NONE, BLOCK_N, BLOCK_K, BLOCK_NK };

static enum block header(char *line)
{
    char *p = line, *q;
    /* Spaces around the names are tolerated; the names themselves are not. */
    for (q = line; *p; p++)
        if (*p != ' ' && *p != '\t')
            *q++ = *p;
    *q = '\0';
    return !strcmp(line, "wl,n,k") ? BLOCK_NK : !strcmp(line, "wl,n") ? BLOCK_N : !strcmp(line, "wl,k") ? BLOCK_K : BLOCK_NONE;
}

int load_rii_csv(text_file *t, nk_table *out)
{
    nk_column n, k;
    enum block block = BLOCK_NONE;
    int n_line = 0, k_line = 0, block_line = 0, block_rows = 0, status = CLI_BAD_INPUT;
    char *line;
    memset(&n, 0, sizeof n);
    memset(&k, 0, sizeof k);
    while (text_next(t, &line)) {
        double v[3];
        int got, want;
        if (line[strspn(line, " \t")] == '\0')
            continue;
        if (line[strspn(line, " \t")] == 'w') {
            char copy[64];
            enum block b;
            snprintf(copy, sizeof copy, "%s", line);
            b = header(copy);
            if (b == BLOCK_NONE) {
                text_error(t, t->line, "expected a header 'wl,n', 'wl,k' or 'wl,n,k', got '%.40s'", line);
                goto done;
            }
            if (block != BLOCK_NONE && block_rows == 0) {
                text_error(t, block_line, "expected rows after this header, got none");
                goto done;
            }
            if ((b != BLOCK_K && n_line) || (b != BLOCK_N && k_line)) {
                text_error(t, t->line, "expected each of n and k once, this block repeats one given at line %d",
                           b != BLOCK_K && n_line ? n_line : k_line);
                goto done;
            }
            if (b != BLOCK_K)
                n_line = t->line;
            if (b != BLOCK_N)
                k_line = t->line;
            block = b;
            block_line = t->line;
            block_rows = 0;
            continue;
        }
        if (block == BLOCK_NONE) {
            text_error(t, t->line, "expected the header 'wl,n' or 'wl,n,k' (wavelength in um) before the rows");
            goto done;
        }
        want = block == BLOCK_NK ? 3 : 2;
        if ((got = text_numbers(t, t->line, line, ",", v, 3)) < 0)
            goto done;
        if (got != want) {
            text_error(t, t->line, "expected %d comma-separated numbers under '%s', got %d", want,
                       block == BLOCK_NK ? "wl,n,k" : block == BLOCK_N ? "wl,n" : "wl,k", got);
            goto done;
        }
        if (block != BLOCK_K && column_push(t, &n, nm_from_um(v[0]), v[1], t->line))
            goto done;
        if (block != BLOCK_N && column_push(t, &k, nm_from_um(v[0]), v[want - 1], t->line))
            goto done;
        block_rows++;
    }
    if (block != BLOCK_NONE && block_rows == 0) {
        text_error(t, block_line, "expected rows after this header, got none");
        goto done;
    }
    if (!n_line) {
        text_error(t, k_line ? k_line : 1, "expected a 'wl,n' or 'wl,n,k' block, found %s", k_line ? "only k" : "none");
        goto done;
    }
    status = nk_merge(t, "um", &n, NULL, k_line ? &k : NULL, out);
done:
    column_free(&n);
    column_free(&k);
    return status;
}
