/* pbrt / Mitsuba spectrum files (.spd): "wavelength_nm value" pairs, '#'
 * comments (whole lines or after the values), blank lines anywhere, values
 * separated by blanks or tabs and not necessarily one pair per line. A metal
 * is two files, NAME.eta.spd (n) and NAME.k.spd (k), as Mitsuba ships them;
 * import.c finds the partner. An odd count of values, wavelengths not
 * increasing and a file without two pairs are errors. */
#include <string.h>

#include "common/cli.h"
#include "1_spectral/import.h"

static int read_pairs(text_file *t, nk_column *c)
{
    double pending = 0.0;
    int have_pending = 0, pending_line = 0;
    char *line;
    while (text_next(t, &line)) {
        double v[64];
        char *hash = strchr(line, '#');
        int got, i;
        if (hash)
            *hash = '\0';
        if ((got = text_numbers(t, t->line, line, "", v, 64)) < 0)
            return CLI_BAD_INPUT;
        for (i = 0; i < got; i++) {
            if (!have_pending) {
                pending = v[i];
                pending_line = t->line;
                have_pending = 1;
            } else {
                if (column_push(t, c, pending, v[i], pending_line))
                    return CLI_BAD_INPUT;
                have_pending = 0;
            }
        }
    }
    if (have_pending)
        return text_error(t, pending_line, "expected a value after wavelength %.10g nm (pairs 'wavelength_nm value')",
                          pending);
    if (c->rows < 2)
        return text_error(t, t->line > 0 ? t->line : 1,
                          "expected at least two 'wavelength_nm value' pairs, got %d", c->rows);
    return 0;
}

int load_spd(text_file *eta, text_file *k, nk_table *out)
{
    nk_column n, kc;
    int status = CLI_BAD_INPUT;
    memset(&n, 0, sizeof n);
    memset(&kc, 0, sizeof kc);
    if (read_pairs(eta, &n) || (k && read_pairs(k, &kc)))
        goto done;
    status = nk_merge(eta, "nm", &n, k ? k->path : NULL, k ? &kc : NULL, out);
done:
    column_free(&n);
    column_free(&kc);
    return status;
}
