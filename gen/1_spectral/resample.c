/* Spectral step 2 of 7: the measured table onto the common 0.1 nm grid over 360-830 nm
 * [MS18 section 5]. n and k are interpolated linearly in wavelength, as
 * data/README.md prescribes (its F0 check column was computed that way).
 * Beyond the measured range the end value is held: the only tables that stop
 * short are dielectrics with flat dispersion there, where README.md bounds
 * the effect on XYZ below 1e-4. */
#include <stdio.h>
#include <string.h>

#include "common/cli.h"
#include "1_spectral/spectral.h"

/* Grid wavelengths come from integers so that node i is the double nearest
 * to 360 + i/10 nm, with no error accumulated along the grid. */
static double grid_nm(int i) { return (3600 + i) / 10.0; }

static double clamp_to_grid(double nm)
{
    return nm < SPEC_LO_NM ? SPEC_LO_NM : nm > SPEC_HI_NM ? SPEC_HI_NM : nm;
}

void resample(const nk_table *t, spectrum *s)
{
    int last = t->rows - 1, seg = 0, i;
    for (i = 0; i < SPEC_N; i++) {
        double nm = grid_nm(i);
        if (nm <= t->wl[0]) {
            s->n[i] = t->n[0];
            s->k[i] = t->k[0];
        } else if (nm >= t->wl[last]) {
            s->n[i] = t->n[last];
            s->k[i] = t->k[last];
        } else {
            double u;
            while (t->wl[seg + 1] < nm)
                seg++;
            u = (nm - t->wl[seg]) / (t->wl[seg + 1] - t->wl[seg]);
            /* (1-u)a + ub returns the table value itself at a node (u = 0 or
             * 1), which a + u(b-a) does not always do. */
            s->n[i] = (1.0 - u) * t->n[seg] + u * t->n[seg + 1];
            s->k[i] = (1.0 - u) * t->k[seg] + u * t->k[seg + 1];
        }
    }
    /* A table entirely outside 360-830 nm leaves an empty range here
     * (lo == hi at the nearer end). */
    s->measured_lo = clamp_to_grid(t->wl[0]);
    s->measured_hi = clamp_to_grid(t->wl[last]);
}

/* Holding the end values is a fair extension over a few nm of flat
 * dispersion, so a partial range proceeds with a warning; a table with no
 * measured point strictly inside 360-830 nm would turn into a constant n, k
 * that nobody measured, so it is an error. Data row i is on line i + 2 of
 * the file (header first, no blank lines between rows: load_nk's rules). */
/* Whether path was warned about before in this process (a report loads a
 * material more than once; one warning per file is enough). Host code: the
 * runtime's no-mutable-state rule does not apply here. */
static int warned_before(const char *path)
{
    static unsigned long seen[256];
    static int count;
    unsigned long h = 2166136261ul;
    int i;
    for (; *path; path++)
        h = ((h ^ (unsigned char)*path) * 16777619ul) & 0xfffffffful;
    for (i = 0; i < count; i++)
        if (seen[i] == h)
            return 1;
    if (count < 256)
        seen[count++] = h;
    return 0;
}

int spectrum_coverage_warnings = 1;

/* How the wavelengths were read, for a message about the range: a table in
 * the wrong unit is the usual cause of a range that misses the visible. */
static const char *unit_note(const nk_table *t, char *buf, size_t size)
{
    const char *unit = t->unit ? t->unit : "nm";
    const char *hint = "";
    /* The file's numbers, read in the other unit, would meet the visible. */
    double lo = t->wl[0], hi = t->wl[t->rows - 1];
    if (!strcmp(unit, "nm") && lo * 1000.0 < SPEC_HI_NM && hi * 1000.0 > SPEC_LO_NM)
        hint = "; the values look like micrometres: a refractiveindex.info file or export is read in um "
               "(fresnel import FILE converts it)";
    else if (!strcmp(unit, "um") && lo / 1000.0 < SPEC_HI_NM && hi / 1000.0 > SPEC_LO_NM)
        hint = "; were the numbers meant as nm? this format's wavelengths are micrometres";
    snprintf(buf, size, " (wavelengths read as %s%s)", unit, hint);
    return buf;
}

static int coverage(const char *path, const nk_table *t)
{
    int last = t->rows - 1;
    int first_line = t->first_line > 0 ? t->first_line : 2;
    int last_line = t->last_line > 0 ? t->last_line : last + 2;
    char where[1100], note[256];
    if (t->wl[last] <= SPEC_LO_NM || t->wl[0] >= SPEC_HI_NM) {
        int line = t->wl[0] >= SPEC_HI_NM ? first_line : last_line;
        snprintf(where, sizeof where, "%s:%d", path, line);
        return cli_error(where, "the table covers %.10g-%.10g nm, expected it to reach into %g-%g nm%s",
                         t->wl[0], t->wl[last], SPEC_LO_NM, SPEC_HI_NM, unit_note(t, note, sizeof note));
    }
    if ((t->wl[0] > SPEC_LO_NM || t->wl[last] < SPEC_HI_NM) && spectrum_coverage_warnings &&
        !warned_before(path)) {
        int line = t->wl[0] > SPEC_LO_NM ? first_line : last_line;
        snprintf(where, sizeof where, "%s:%d", path, line);
        fprintf(stderr, "%s: warning: measured %.10g-%.10g nm, n and k held at the end values over the rest of %g-%g nm\n",
                where, t->wl[0], t->wl[last], SPEC_LO_NM, SPEC_HI_NM);
    }
    return 0;
}

int spectrum_from_table(const char *path, const nk_table *t, spectrum *s)
{
    if (coverage(path, t))
        return CLI_BAD_INPUT;
    resample(t, s);
    return 0;
}

int spectrum_load(const char *dir, const char *id, spectrum *s)
{
    char path[1024];
    nk_table t;
    int status;
    /* The id names a file inside dir; refuse anything that would leave it. */
    if (*id == '\0' || strchr(id, '/') || *id == '.')
        return cli_error("material", "expected a material id, got '%s'", id);
    if ((size_t)snprintf(path, sizeof path, "%s/%s.csv", dir, id) >= sizeof path)
        return cli_error(dir, "data directory path too long");
    if (load_nk(path, &t))
        return CLI_BAD_INPUT;
    status = spectrum_from_table(path, &t, s);
    nk_table_free(&t);
    return status;
}
