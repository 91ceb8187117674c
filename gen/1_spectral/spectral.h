/* The generator's spectral pipeline, one step per file, in the order the
 * papers give it [MS18 sections 4-5; Hof20 "Computing RGB parameter values"]:
 *
 *   load_nk.c              measured wavelength,n,k table, validated
 *   import*.c, load_*.c    the same table from a user's file in another format
 *                          (refractiveindex.info YAML or CSV, SOPRA .nk, .spd)
 *   resample.c             0.1 nm grid over 360-830 nm, ends held
 *   colorimetry.c          CIE 1931 2-degree CMFs and the D65 SPD
 *   colour_space.c         primaries/white -> XYZ->RGB with Bradford adaptation
 *   dominant_wavelength.c  white->primary ray meets the spectral locus
 *   gaussian_window.c      RGB eta', kappa' around the dominant wavelengths
 *   ground_truth.c         spectral Fresnel x illuminant x CMFs -> RGB
 *   film_truth.c           the same for a thin film on a substrate (Airy)
 *   fit.c                  black-box RGB eta, kappa fit to the ground truth
 *
 * Host only (stdio, libm, malloc allowed). Errors are printed as
 * "file:line: what was expected" through cli_error and reported as
 * CLI_BAD_INPUT. */
#ifndef FRESNEL_SPECTRAL_H
#define FRESNEL_SPECTRAL_H

#include <stddef.h>
#include <stdio.h>

#define SPEC_LO_NM 360.0
#define SPEC_HI_NM 830.0
#define SPEC_STEP_NM 0.1
#define SPEC_N 4701 /* (830 - 360) / 0.1 + 1 */
#define CMF_N 471   /* 360..830 at 1 nm */

/* Where data/ is: --data DIR, else $FRESNEL_DATA, else the installed pack
 * next to the program (BINDIR/../share/fresnel/data), else the build's copy
 * (data_dir.c). data_dir_program records argv[0], the fallback where
 * /proc/self/exe is missing. */
const char *data_dir(const char *override);
void data_dir_program(const char *argv0);

/* ---- load_nk.c: a measured table as read (ascending unique wavelengths,
 * finite numbers, n > 0, k >= 0, at least two rows, header line). */
typedef struct nk_table {
    int rows;
    double *wl, *n, *k; /* malloc'd; nk_table_free */
    /* For messages about the table as a whole (coverage): the file lines of
     * the first and last rows, and how the file's wavelengths were read
     * ("nm", "um", "eV", "um, formula 2"). */
    int first_line, last_line;
    const char *unit;
} nk_table;
int load_nk(const char *path, nk_table *t); /* 0, or CLI_BAD_INPUT after a file:line message */
void nk_table_free(nk_table *t);
/* The per-row rules every format shares (wavelength > 0, n > 0, k >= 0, both
 * representable in binary32), reported at path:line; 0 or CLI_BAD_INPUT. */
int nk_check_row(const char *path, int line, double wl_nm, double n, double k);

/* The other data tables (CMFs, illuminant, colour spaces, materials) are read
 * through the same strict line reader as the n,k tables, so every file in
 * data/ reports errors the same way. Lines may end in LF or CRLF; blank lines
 * are allowed only at the end of the file. */
typedef struct csv_reader {
    FILE *f;
    const char *path;
    int line; /* 1-based number of the line last read */
    char *buf;
    size_t cap;
} csv_reader;
/* Open path (cli_open_input) and require its first line to be exactly `header`; 0 or a status after a message. */
int csv_open(csv_reader *r, const char *path, const char *header);
/* Next data row, its line ending removed: 1 (row set), 0 at the end, or -1 after a message. */
int csv_next_row(csv_reader *r, char **row);
/* Split row in place at commas; returns the number of fields (only the first max are stored). */
int csv_split(char *row, char **field, int max);
/* Parse a whole field as a finite number, else a message naming the column; 0 or CLI_BAD_INPUT. */
int csv_number(const csv_reader *r, const char *field, const char *column, double *out);
/* "path:line: message" for the line last read; returns CLI_BAD_INPUT. */
int csv_error(const csv_reader *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void csv_close(csv_reader *r);

/* ---- import.c: a user's n,k file. The format is told from the content
 * (--format overrides); import.c's opening comment gives each format's rules.
 * The table comes back in nm, ascending, checked as load_nk's rows are. */
typedef enum nk_format {
    NK_FORMAT_AUTO,
    NK_FORMAT_CSV,      /* the data pack's wavelength_nm,n,k */
    NK_FORMAT_RII_YAML, /* refractiveindex.info database file */
    NK_FORMAT_RII_CSV,  /* refractiveindex.info CSV export */
    NK_FORMAT_SOPRA,    /* SOPRA .nk */
    NK_FORMAT_SPD       /* pbrt / Mitsuba .spd, n and k in two files */
} nk_format;
extern const char *const nk_format_names[]; /* indexed by nk_format, NULL-terminated */
/* What a generated header records of a file so a build can be reproduced. */
typedef struct nk_file_info {
    char file[256];   /* base name(s): "TiN.yml", "Au.eta.spd + Au.k.spd" */
    const char *format;
    long bytes;       /* size of the file(s) read */
    char sha256[65];  /* of the bytes read (both files, in that order, for a .spd pair) */
} nk_file_info;

/* ---- materials: data/materials.csv indexes the <id>.csv files. */
typedef struct material_info {
    char id[32];
    char name[96];
    char dataset[160];
    char kind[16]; /* "metal" or "dielectric" */
    nk_file_info file; /* a user's file: file.file[0] != 0 */
} material_info;
/* Look up id; 0, or CLI_BAD_INPUT (unknown id) after a message naming `where`. */
int material_lookup(const char *dir, const char *id, material_info *out, const char *where);
/* All ids in file order; returns the count (<= max) or -1 after a message. */
int material_list(const char *dir, material_info *out, int max);

/* ---- resample.c */
typedef struct spectrum {
    double n[SPEC_N], k[SPEC_N]; /* at SPEC_LO_NM + i * SPEC_STEP_NM */
    double measured_lo, measured_hi; /* part of 360-830 the table covered; outside it the end value is held */
} spectrum;
void resample(const nk_table *t, spectrum *s);
/* 1 (the default): spectrum_load warns, once per file, when a table covers
 * only part of 360-830 nm. `fresnel materials` lists the coverage as
 * columns and clears it unless --verbose. */
extern int spectrum_coverage_warnings;
/* load + resample of data/<id>.csv; 0 or CLI_BAD_INPUT. */
int spectrum_load(const char *dir, const char *id, spectrum *s);
/* The coverage rule and the resampling for a table read from path. */
int spectrum_from_table(const char *path, const nk_table *t, spectrum *s);

/* Read path in `format` (NK_FORMAT_AUTO: told from the content) into t, and
 * what identifies the bytes read into info; 0 or CLI_BAD_INPUT after a
 * file:line message. A table that covers only part of 360-830 nm is read;
 * spectrum_from_table applies the coverage rule. */
int nk_import(const char *path, nk_format format, nk_table *t, nk_file_info *info);

/* A material: a data-pack id (path NULL or ""), or a user's file in any
 * format nk_import reads, named id in generated code. */
typedef struct material_source {
    const char *id;
    const char *path;
    nk_format format;
    double film_n; /* a thin film of this real index on the material (the thin-film model); 0: none */
} material_source;
/* Load and resample a material; info gets the data pack's row or, for a
 * file, id, the file's name and provenance, and a kind from its k. 0 or
 * CLI_BAD_INPUT. */
int material_load(const char *dir, const material_source *m, material_info *info, spectrum *s);
/* A material id from a file name: the base name up to its first '.',
 * lower-cased, every run of characters outside a-z 0-9 one '_' ("TiN.yml" ->
 * "tin", "Au.eta.spd" -> "au"). */
void material_id_from_path(const char *path, char out[32]);

/* ---- colorimetry.c */
typedef struct colorimetry {
    double xbar[CMF_N], ybar[CMF_N], zbar[CMF_N]; /* 360..830 nm, 1 nm */
    double d65[CMF_N];                              /* relative SPD at the same wavelengths */
} colorimetry;
int colorimetry_load(const char *dir, colorimetry *cm);
/* XYZ of a perfect reflector under the D65 SPD, normalised to Y = 1 with the
 * same sums ground_truth uses (x = 0.31273, y = 0.32902 for the CIE tables). */
void illuminant_white(const colorimetry *cm, double xyz[3]);

/* ---- colour_space.c: spaces srgb, display-p3, dci-p3, adobe-rgb, rec2020, acescg. */
typedef struct colour_space {
    char id[16];
    double primary[3][2]; /* xy of R, G, B */
    double white[2];      /* the space's white, xy */
    /* XYZ (D65-illuminated) -> linear RGB of the space: Bradford from the D65
     * SPD's white to the space's white where they differ, then the space's
     * matrix, then a per-channel scale so a perfect reflector is (1,1,1) to
     * the last place (colour_space.c). */
    double xyz_to_rgb[3][3];
} colour_space;
int colour_space_load(const char *dir, const char *id, const colorimetry *cm, colour_space *cs);
extern const char *const colour_space_ids[]; /* NULL-terminated */
/* The id a colour-space name stands for, ignoring case and taking common
 * aliases (sRGB, rec709/bt709, p3, bt2020, ACEScg, ...), or NULL. */
const char *colour_space_find(const char *name);

/* ---- dominant_wavelength.c: nm[0..2] for R, G, B. */
void dominant_wavelengths(const colorimetry *cm, const colour_space *cs, double nm[3]);

/* ---- gaussian_window.c: sigma in nm, 0 = point sampling (linear interpolation). */
void gaussian_window(const spectrum *s, const double nm[3], double sigma, double eta[3],
                     double kappa[3]);

/* ---- ground_truth.c: RGB reflectance at cosine c, incident medium of index n1. */
void ground_truth(const spectrum *s, const colorimetry *cm, const colour_space *cs, double n1,
                  double c, double rgb[3]);
/* The integration itself, for any spectral reflectance: reflectance(ctx,
 * node, nm) at the 0.1 nm grid node `node` (a whole nanometre, nm), summed
 * against D65 and the CMFs at 1 nm and mapped to cs's RGB. ground_truth is
 * this with the bare interface's exact Fresnel, film_truth (film_truth.c)
 * with a thin film's. */
typedef double spectral_reflectance(const void *ctx, int node, double nm);
void ground_truth_of(spectral_reflectance *reflectance, const void *ctx, const colorimetry *cm,
                     const colour_space *cs, double rgb[3]);

/* ---- film_truth.c: a thin film between the incident medium and a
 * substrate (film_truth.c's opening comment gives the optics). */
typedef struct film_stack {
    double n1;                 /* incident medium, real index */
    const spectrum *film;      /* the film's n, k per node, or NULL: film_n below */
    double film_n;             /* a non-dispersive, non-absorbing film (film == NULL) */
    const spectrum *substrate; /* any material: metal or dielectric */
} film_stack;
/* The largest thickness the spectral truth resolves (film_truth.c). */
#define FILM_TRUTH_D_MAX_NM 5000.0
/* RGB reflectance of the stack at cosine c (in the incident medium, clamped
 * to [0, 1]) and film thickness d nm (clamped to [0, FILM_TRUTH_D_MAX_NM];
 * NaN gives 0). d = 0 and a film matching n1 give ground_truth's result. */
void film_truth(const film_stack *f, const colorimetry *cm, const colour_space *cs, double c,
                double d_nm, double rgb[3]);
/* The same for many thicknesses at one cosine: the interface amplitudes at
 * every CMF wavelength, computed once (film_truth_prepare; malloc'd, NULL
 * when out of memory; free()), then film_truth_at per thickness. */
typedef struct film_optics_table film_optics_table;
film_optics_table *film_truth_prepare(const film_stack *f, double c);
void film_truth_at(const film_optics_table *t, const colorimetry *cm, const colour_space *cs, double d_nm,
                   double rgb[3]);
/* The stack's n, k at CMF sample j (360 + j nm): film and substrate. */
void film_stack_index(const film_stack *f, int j, double n_film[2], double n_sub[2]);

#endif
