/* fresnel import: a user's n,k file, in any format the importers read, as
 * the data pack's wavelength_nm,n,k CSV (the file's own rows in nm; a
 * formula sampled on the 0.1 nm grid inside its range). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "1_spectral/spectral.h"

#define WHERE "fresnel import"

static void import_usage(void)
{
    printf("usage: fresnel import FILE -o OUT.csv [--format NAME]\n"
           "\n"
           "Converts a user's n,k file into the data pack's CSV (header wavelength_nm,n,k):\n"
           "the file's own rows with wavelengths in nm, nothing resampled; a dispersion\n"
           "formula is evaluated every 0.1 nm of 360-830 nm inside its wavelength_range.\n"
           "OUT ('-' for stdout) is written whole or not at all, and is none of the files\n"
           "read (FILE, the other half of a .spd pair). To add the material to a\n"
           "data directory, put OUT there as <id>.csv and add a line id,name,dataset,kind to\n"
           "its materials.csv (data/README.md). --nk FILE (params, curve, bench) and\n"
           "'material ID = FILE' in a manifest read the same formats without converting.\n"
           "\n"
           "Formats, told from the first line that is neither blank nor a '#' comment\n"
           "(--format auto|csv|rii-yaml|rii-csv|sopra|spd overrides):\n"
           "  rii-yaml  a refractiveindex.info database file (database/data/.../*.yml): DATA\n"
           "            entries 'tabulated nk', 'tabulated n', 'tabulated k' and 'formula 1'..\n"
           "            'formula 9' with wavelength_range and coefficients; um. n2 files refused.\n"
           "  rii-csv   a refractiveindex.info CSV export: 'wl,n' then optionally 'wl,k' blocks,\n"
           "            or one 'wl,n,k' block; um.\n"
           "  sopra     a SOPRA .nk file: 'unit start end intervals' (unit 1 eV, 2 um, 4 nm;\n"
           "            3 is refused as ambiguous), then intervals + 1 pairs n k.\n"
           "  spd       pbrt / Mitsuba .spd: 'wavelength_nm value' pairs, '#' comments;\n"
           "            NAME.eta.spd is read with NAME.k.spd beside it (given either).\n"
           "  csv       the data pack's own wavelength_nm,n,k.\n"
           "Every row is held to the data pack's rules (increasing wavelengths, n > 0,\n"
           "k >= 0, values a binary32 float holds); errors name file:line, exit status 2.\n");
}

int cmd_import(int argc, char **argv)
{
    static const char *const options[] = {"-o", "--format", "--help", NULL};
    const char *in = NULL, *out_path = NULL, *val;
    nk_format format = NK_FORMAT_AUTO;
    nk_file_info info;
    nk_table t;
    cli_outfile out;
    spectrum *s;
    int i, status;
    for (i = 1; i < argc; i++) {
        const char *opt = argv[i];
        if (!strcmp(opt, "--help") || !strcmp(opt, "-h")) {
            import_usage();
            return 0;
        }
        if (!cli_looks_like_option(opt) || !strcmp(opt, "-")) {
            if (in)
                return cli_error(WHERE, "expected one input FILE, got '%s' and '%s'", in, opt);
            in = opt;
            continue;
        }
        if (!cli_in_list(opt, options))
            return cli_bad_argument(WHERE, opt, options);
        if (!(val = cli_option_value(WHERE, argc, argv, &i)))
            return CLI_BAD_INPUT;
        if (!strcmp(opt, "-o"))
            out_path = val;
        else {
            int f;
            for (f = 0; nk_format_names[f] && strcmp(nk_format_names[f], val); f++)
                ;
            if (!nk_format_names[f])
                return cli_unknown(WHERE, "format", val, nk_format_names);
            format = (nk_format)f;
        }
    }
    if (!in || !out_path)
        return cli_error(WHERE, "expected FILE and -o OUT.csv (fresnel import --help)");
    /* The output may be none of the files read, the implicit half of a .spd
     * pair included: cli_out_open refuses them. */
    if ((status = nk_import(in, format, &t, &info)))
        return status;
    /* The pipeline's coverage rule, so a file that misses the visible is
     * refused here too, and one that covers part of it warned about. */
    if (!(s = malloc(sizeof *s))) {
        nk_table_free(&t);
        return cli_oom(WHERE);
    }
    status = spectrum_from_table(in, &t, s);
    free(s);
    if (status) {
        nk_table_free(&t);
        return status;
    }
    if ((status = cli_out_open(&out, out_path))) {
        nk_table_free(&t);
        return status;
    }
    fprintf(out.f, "wavelength_nm,n,k\n");
    for (i = 0; i < t.rows; i++)
        fprintf(out.f, "%.10g,%.10g,%.10g\n", t.wl[i], t.n[i], t.k[i]);
    status = cli_out_commit(&out);
    if (!status) {
        fprintf(stderr, "%s: %s (%s), %d rows, %.10g-%.10g nm -> %s\n", WHERE, info.file, info.format, t.rows,
                t.wl[0], t.wl[t.rows - 1], out.shown);
    }
    nk_table_free(&t);
    return status;
}
