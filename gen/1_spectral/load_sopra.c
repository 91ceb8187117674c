/* A SOPRA .nk file: a first line "unit start end intervals", then the n,k
 * pairs at start, start + step, ..., end (intervals + 1 pairs, step =
 * (end - start) / intervals), in the unit the code names:
 *
 *   1 eV (photon energy: wavelength nm = 1239.841984 / E)
 *   2 um
 *   4 nm
 *
 * Code 3 is read as cm^-1 by some readers and as a length by others, so it
 * is refused rather than guessed. Values may be separated by blanks, tabs or
 * ';' and need not be one pair per line. A pair count other than intervals +
 * 1, an odd count of values and an unknown code are errors. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "1_spectral/import.h"

/* h c in eV nm (CODATA 2018: h and c exact, e exact). */
#define HC_EV_NM 1239.8419843320026

int load_sopra(text_file *t, nk_table *out)
{
    double head[5], *values = NULL;
    int *lines = NULL, count = 0, cap = 0, intervals, unit, i, status = CLI_BAD_INPUT, got;
    nk_column n, k;
    char *line;
    const char *unit_name;
    memset(&n, 0, sizeof n);
    memset(&k, 0, sizeof k);
    if (!text_next(t, &line))
        return text_error(t, 1, "expected the SOPRA header 'unit start end intervals', got an empty file");
    if (!strchr("0123456789.+-", line[strspn(line, " \t")]))
        return text_error(t, 1, "expected the SOPRA header 'unit start end intervals', got '%.40s'", line);
    if ((got = text_numbers(t, 1, line, ";", head, 5)) < 0)
        return CLI_BAD_INPUT;
    if (got != 4)
        return text_error(t, 1, "expected the SOPRA header 'unit start end intervals' (4 numbers), got %d numbers", got);
    /* Range first: converting a double outside int's range is undefined. */
    if (!(head[0] >= 1.0 && head[0] <= 4.0) || head[0] != floor(head[0]))
        return text_error(t, 1, "expected unit code 1 (eV), 2 (um) or 4 (nm), got %.10g", head[0]);
    unit = (int)head[0];
    if (unit == 3)
        return text_error(t, 1, "unit code 3 is read as cm^-1 by some programs and as a length by others: "
                                "expected 1 (eV), 2 (um) or 4 (nm); convert the file");
    if (!(head[3] >= 1.0 && head[3] <= 100000.0) || head[3] != floor(head[3]))
        return text_error(t, 1, "expected a whole number of intervals in 1..100000, got %.10g", head[3]);
    intervals = (int)head[3];
    if (!(head[1] > 0.0) || !(head[2] > head[1]))
        return text_error(t, 1, "expected 0 < start < end, got start %.10g, end %.10g", head[1], head[2]);
    unit_name = unit == 1 ? "eV" : unit == 2 ? "um" : "nm";
    while (text_next(t, &line)) {
        double v[64];
        if ((got = text_numbers(t, t->line, line, ";", v, 64)) < 0)
            goto done;
        for (i = 0; i < got; i++) {
            if (count == cap) {
                int new_cap = cap ? 2 * cap : 512;
                double *nv = realloc(values, (size_t)new_cap * sizeof *nv);
                int *nl = nv ? realloc(lines, (size_t)new_cap * sizeof *nl) : NULL;
                if (nv)
                    values = nv;
                if (!nl) {
                    cli_oom(t->path);
                    goto done;
                }
                lines = nl;
                cap = new_cap;
            }
            if (count == 2 * (intervals + 1)) {
                text_error(t, t->line, "expected %d n,k pairs (the header's %d intervals from %.10g to %.10g %s), got more",
                           intervals + 1, intervals, head[1], head[2], unit_name);
                goto done;
            }
            values[count] = v[i];
            lines[count++] = t->line;
        }
    }
    if (count != 2 * (intervals + 1)) {
        text_error(t, t->line, "expected %d n,k pairs (the header's %d intervals from %.10g to %.10g %s), got %d%s",
                   intervals + 1, intervals, head[1], head[2], unit_name, count / 2,
                   count % 2 ? " and an n without its k" : "");
        goto done;
    }
    /* Energies ascend while wavelengths descend: walk eV files backwards. */
    for (i = 0; i <= intervals; i++) {
        int j = unit == 1 ? intervals - i : i;
        double x = head[1] + (head[2] - head[1]) * j / intervals;
        double nm = unit == 1 ? HC_EV_NM / x : unit == 2 ? nm_from_um(x) : x;
        if (column_push(t, &n, nm, values[2 * j], lines[2 * j]) ||
            column_push(t, &k, nm, values[2 * j + 1], lines[2 * j + 1]))
            goto done;
    }
    status = nk_merge(t, unit_name, &n, NULL, &k, out);
    /* The coverage message's lines follow the file, not the wavelengths. */
    if (!status && unit == 1) {
        int swap = out->first_line;
        out->first_line = out->last_line;
        out->last_line = swap;
    }
done:
    free(values);
    free(lines);
    column_free(&n);
    column_free(&k);
    return status;
}
