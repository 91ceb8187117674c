/* Spectral step 3 of 7: the CIE 1931 2-degree observer and the D65 SPD, both at 1 nm over
 * 360-830 nm, the tristimulus weighting of [Hof20 "Computing RGB parameter
 * values"]. Both files are CIE 1 nm tables (data/SOURCES.md), so anything
 * but consecutive whole nanometres is a damaged file, not a sampling choice
 * to interpolate around. */
#include <math.h>

#include "common/cli.h"
#include "1_spectral/spectral.h"

/* Reads a table whose first column is wavelength in whole nm, ascending in
 * 1 nm steps and covering 360..830, and keeps the columns after the first
 * for those wavelengths in out[0..ncols-2]. Rows outside 360..830 (the
 * illuminant starts at 300) are checked but not kept. */
static int read_1nm_table(const char *dir, const char *file, const char *header, int ncols,
                          const char *const *column, double *const *out)
{
    char path[1024];
    csv_reader r;
    char *row, *field[8];
    int rows = 0, got, i;
    double first_nm = 0.0, nm = 0.0;
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, file) >= sizeof path)
        return cli_error(dir, "data directory path too long");
    if (csv_open(&r, path, header))
        return CLI_BAD_INPUT;
    while ((got = csv_next_row(&r, &row)) == 1) {
        int count = csv_split(row, field, 8);
        double v;
        if (count != ncols) {
            csv_error(&r, "expected %d columns (%s), got %d", ncols, header, count);
            goto fail;
        }
        if (csv_number(&r, field[0], column[0], &nm))
            goto fail;
        if (rows == 0) {
            if (nm != floor(nm) || nm > SPEC_LO_NM) {
                csv_error(&r, "expected the table to start at a whole nm <= %g, got %.10g",
                          SPEC_LO_NM, nm);
                goto fail;
            }
            first_nm = nm;
        } else if (nm != first_nm + rows) {
            csv_error(&r, "wavelength %.10g, expected %.10g (1 nm steps)", nm, first_nm + rows);
            goto fail;
        }
        for (i = 1; i < ncols; i++) {
            if (csv_number(&r, field[i], column[i], &v))
                goto fail;
            if (v < 0.0) {
                csv_error(&r, "column %s: %.10g, expected a value >= 0", column[i], v);
                goto fail;
            }
            if (nm >= SPEC_LO_NM && nm <= SPEC_HI_NM)
                out[i - 1][(int)(nm - SPEC_LO_NM)] = v;
        }
        rows++;
    }
    if (got < 0)
        goto fail;
    if (rows == 0 || nm < SPEC_HI_NM) {
        r.line++;
        csv_error(&r, "expected rows up to %g nm, the table ends at %.10g", SPEC_HI_NM, nm);
        goto fail;
    }
    csv_close(&r);
    return 0;
fail:
    csv_close(&r);
    return CLI_BAD_INPUT;
}

int colorimetry_load(const char *dir, colorimetry *cm)
{
    static const char *const cmf_columns[] = {"wavelength_nm", "xbar", "ybar", "zbar"};
    static const char *const spd_columns[] = {"wavelength_nm", "value"};
    double *const cmf_out[] = {cm->xbar, cm->ybar, cm->zbar};
    double *const spd_out[] = {cm->d65};
    if (read_1nm_table(dir, "cie1931_2deg.csv", "wavelength_nm,xbar,ybar,zbar", 4, cmf_columns,
                       cmf_out))
        return CLI_BAD_INPUT;
    return read_1nm_table(dir, "illuminant_d65.csv", "wavelength_nm,value", 2, spd_columns,
                          spd_out);
}

void illuminant_white(const colorimetry *cm, double xyz[3])
{
    double x = 0.0, y = 0.0, z = 0.0;
    int j;
    /* Same products, same order as ground_truth with R = 1, so a perfect
     * reflector reproduces these sums bit for bit. */
    for (j = 0; j < CMF_N; j++) {
        x += cm->d65[j] * cm->xbar[j];
        y += cm->d65[j] * cm->ybar[j];
        z += cm->d65[j] * cm->zbar[j];
    }
    xyz[0] = x / y;
    xyz[1] = 1.0;
    xyz[2] = z / y;
}
