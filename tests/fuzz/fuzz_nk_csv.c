/* Fuzzes the n,k table reader (gen/1_spectral/load_nk.c, with the CSV line reader every
 * data file goes through) and its resampling (gen/1_spectral/resample.c).
 *
 * Oracle, for any bytes as data/<id>.csv:
 *   - no crash, no sanitizer report, no leak (LeakSanitizer under libFuzzer);
 *   - load_nk either succeeds with a table that keeps every rule of
 *     data/README.md (>= 2 rows, ascending wavelengths > 0, finite n > 0,
 *     finite k >= 0) and prints nothing, or returns CLI_BAD_INPUT with an
 *     empty table and exactly one message "path:N: ..." naming a line of
 *     the file;
 *   - spectrum_load (load + resample) agrees: it fails where load_nk failed,
 *     or where the table misses 360-830 nm entirely (one "path:N:" message);
 *     on success every resampled n, k lies between the table's extremes (to
 *     rounding) and
 *     anything printed is a "path:N: warning:" line. */
#include "fuzz_parser.h"

#include "common/cli.h"
#include "1_spectral/spectral.h"

static spectrum spec;

static void check_table(const nk_table *t, const char *path)
{
    int i;
    if (t->rows < 2 || !t->wl || !t->n || !t->k)
        FUZZ_FAIL("%s: accepted with %d rows", path, t->rows);
    for (i = 0; i < t->rows; i++) {
        if (!(t->wl[i] > 0.0 && t->wl[i] <= DBL_MAX && (i == 0 || t->wl[i] > t->wl[i - 1])))
            FUZZ_FAIL("row %d: wavelength %g not ascending, positive and finite", i, t->wl[i]);
        if (!(t->n[i] > 0.0 && t->n[i] <= DBL_MAX && t->k[i] >= 0.0 && t->k[i] <= DBL_MAX))
            FUZZ_FAIL("row %d: n %g k %g, expected finite n > 0, k >= 0", i, t->n[i], t->k[i]);
    }
}

static int only_warnings(const char *text, size_t len, const char *path)
{
    size_t plen = strlen(path), i = 0;
    while (i < len) {
        const char *line = text + i, *nl = memchr(line, '\n', len - i);
        if (!nl || strncmp(line, path, plen) || line[plen] != ':' || !strstr(line, ": warning: ") ||
            strstr(line, ": warning: ") > nl)
            return 0;
        i = (size_t)(nl - text) + 1;
    }
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[512];
    nk_table t;
    fuzz_capture cap;
    int rc, rc2, i;
    double nlo = 0.0, nhi = 0.0, klo = 0.0, khi = 0.0;
    const char *dir = fuzz_scratch_dir();
    snprintf(path, sizeof path, "%s/m.csv", dir);
    fuzz_write_file(path, data, size);

    fuzz_capture_begin(&cap);
    rc = load_nk(path, &t);
    fuzz_capture_end(&cap);
    if (rc == 0) {
        if (cap.len)
            FUZZ_FAIL("load_nk succeeded but printed '%.200s'", cap.text);
        check_table(&t, path);
        nlo = nhi = t.n[0];
        klo = khi = t.k[0];
        for (i = 1; i < t.rows; i++) {
            nlo = t.n[i] < nlo ? t.n[i] : nlo;
            nhi = t.n[i] > nhi ? t.n[i] : nhi;
            klo = t.k[i] < klo ? t.k[i] : klo;
            khi = t.k[i] > khi ? t.k[i] : khi;
        }
        nk_table_free(&t);
    } else {
        if (rc != CLI_BAD_INPUT)
            FUZZ_FAIL("load_nk returned %d, expected 0 or CLI_BAD_INPUT", rc);
        if (t.rows != 0 || t.wl || t.n || t.k)
            FUZZ_FAIL("load_nk failed but left a table of %d rows", t.rows);
        if (fuzz_lines(cap.text, cap.len) != 1 || !fuzz_message_names_line(cap.text, path, data, size))
            FUZZ_FAIL("load_nk rejection without exactly one 'path:line:' message: '%.300s'",
                      cap.text ? cap.text : "");
    }
    free(cap.text);

    fuzz_capture_begin(&cap);
    rc2 = spectrum_load(dir, "m", &spec);
    fuzz_capture_end(&cap);
    if (rc2 == 0) {
        if (rc != 0)
            FUZZ_FAIL("spectrum_load accepted what load_nk rejected");
        if (!only_warnings(cap.text, cap.len, path))
            FUZZ_FAIL("spectrum_load succeeded but printed '%.300s'", cap.text);
        if (!(spec.measured_lo < spec.measured_hi))
            FUZZ_FAIL("spectrum_load accepted an empty measured range %g-%g", spec.measured_lo,
                      spec.measured_hi);
        /* (1-u)a + ub may round an ulp past the ends; more would be a wrong segment. */
        nlo -= 4 * DBL_EPSILON * nlo;
        nhi += 4 * DBL_EPSILON * nhi;
        klo -= 4 * DBL_EPSILON * klo;
        khi += 4 * DBL_EPSILON * khi;
        for (i = 0; i < SPEC_N; i++)
            if (!(spec.n[i] >= nlo && spec.n[i] <= nhi && spec.k[i] >= klo && spec.k[i] <= khi)) {
                FUZZ_FAIL("resampled node %d: n %g k %g outside the table's [%g, %g] x [%g, %g]", i,
                          spec.n[i], spec.k[i], nlo, nhi, klo, khi);
                break;
            }
    } else {
        if (rc2 != CLI_BAD_INPUT)
            FUZZ_FAIL("spectrum_load returned %d", rc2);
        if (fuzz_lines(cap.text, cap.len) != 1 || !fuzz_message_names_line(cap.text, path, data, size))
            FUZZ_FAIL("spectrum_load rejection without exactly one 'path:line:' message: '%.300s'",
                      cap.text ? cap.text : "");
    }
    free(cap.text);
    return 0;
}
