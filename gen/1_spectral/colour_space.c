/* Spectral step 4 of 7: XYZ -> linear RGB of a target colour space, for reflectances lit by
 * the D65 SPD [Hof20 "Computing RGB parameter values": XYZ, chromatic
 * adaptation where the space's white differs, then the space's matrix].
 *
 * The source white of the adaptation is always the white of the D65 SPD as
 * integrated against the CMFs (x 0.31273, y 0.32902), even for the D65
 * spaces whose nominal white is (0.3127, 0.3290). Treating every space the
 * same way avoids a "close enough to D65" threshold; for the D65 spaces the
 * adaptation is then a change of about 1e-4, and the final per-channel scale
 * makes a perfect reflector (1,1,1) either way, to the last place: each row
 * meets white with a rounding of its own (Rec.2020's green is 1 + 2.2e-16,
 * build/tests/test_gamut; gamut_contains in 2_derive/derive.h counts that
 * as the boundary). */
#include <math.h>
#include <string.h>
#include <strings.h>

#include "common/cli.h"
#include "1_spectral/spectral.h"

const char *const colour_space_ids[] = {"srgb",    "display-p3", "dci-p3", "adobe-rgb",
                                        "rec2020", "acescg",     NULL};

/* The row of data/colorspaces.csv each id stands for, in the same order. */
static const char *const csv_names[] = {"sRGB",     "Display P3", "DCI-P3", "Adobe RGB (1998)",
                                        "Rec.2020", "ACEScg (AP1)"};

#define SPACES_HEADER                                                                              \
    "name,red_x,red_y,green_x,green_y,blue_x,blue_y,white_name,white_x,white_y,standard"

/* Bradford cone response matrix [Lam 1985], as tabulated in ICC.1:2010
 * Annex E and on Lindbloom's "Chromatic Adaptation" page. */
/* Wrapped in a struct because C99 cannot pass a double[3][3] where a
 * const double[3][3] is expected without a cast. */
typedef struct mat3 {
    double m[3][3];
} mat3;

static const mat3 bradford = {{
    {0.8951, 0.2664, -0.1614},
    {-0.7502, 1.7135, 0.0367},
    {0.0389, -0.0685, 1.0296},
}};

static mat3 mat_mul(const mat3 *a, const mat3 *b)
{
    mat3 t;
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            t.m[i][j] = 0.0;
            for (k = 0; k < 3; k++)
                t.m[i][j] += a->m[i][k] * b->m[k][j];
        }
    return t;
}

static void mat_vec(const mat3 *a, const double v[3], double out[3])
{
    double t[3];
    int i;
    for (i = 0; i < 3; i++)
        t[i] = a->m[i][0] * v[0] + a->m[i][1] * v[1] + a->m[i][2] * v[2];
    memcpy(out, t, sizeof t);
}

/* Inverse by cofactors; -1 when a is singular or too close to it for the
 * result to mean anything (collinear primaries). */
static int mat_inverse(const mat3 *a, mat3 *out)
{
    double c[3][3], det, scale = 0.0;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = a->m[i1][j1] * a->m[i2][j2] - a->m[i1][j2] * a->m[i2][j1];
            if (fabs(a->m[i][j]) > scale)
                scale = fabs(a->m[i][j]);
        }
    det = a->m[0][0] * c[0][0] + a->m[0][1] * c[0][1] + a->m[0][2] * c[0][2];
    if (!(fabs(det) > 1e-12 * scale * scale * scale))
        return -1;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            out->m[i][j] = c[j][i] / det;
    return 0;
}

static void xy_to_xyz(const double xy[2], double xyz[3])
{
    xyz[0] = xy[0] / xy[1];
    xyz[1] = 1.0;
    xyz[2] = (1.0 - xy[0] - xy[1]) / xy[1];
}

/* The standard RGB -> XYZ construction (SMPTE RP 177-1993): primaries' XYZ
 * as columns, each scaled so that RGB (1,1,1) lands on the space's white. */
static int rgb_to_xyz_matrix(const colour_space *cs, mat3 *out)
{
    mat3 p, p_inv;
    double white[3], gain[3];
    int i, j;
    for (j = 0; j < 3; j++) {
        double col[3];
        xy_to_xyz(cs->primary[j], col);
        for (i = 0; i < 3; i++)
            p.m[i][j] = col[i];
    }
    if (mat_inverse(&p, &p_inv))
        return -1;
    xy_to_xyz(cs->white, white);
    mat_vec(&p_inv, white, gain);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            out->m[i][j] = p.m[i][j] * gain[j];
    return 0;
}

/* Von Kries scaling in Bradford cone space from src to dst (both XYZ). */
static mat3 bradford_adaptation(const double src[3], const double dst[3])
{
    mat3 bradford_inv, gain = {{{0.0}}}, scaled;
    double cone_src[3], cone_dst[3];
    int i;
    mat_inverse(&bradford, &bradford_inv); /* well conditioned: cannot fail */
    mat_vec(&bradford, src, cone_src);
    mat_vec(&bradford, dst, cone_dst);
    for (i = 0; i < 3; i++)
        gain.m[i][i] = cone_dst[i] / cone_src[i];
    scaled = mat_mul(&gain, &bradford);
    return mat_mul(&bradford_inv, &scaled);
}

/* Other common spellings of the same spaces (matched ignoring case). */
static const struct {
    const char *alias, *id;
} space_aliases[] = {
    {"rec709", "srgb"},      {"rec.709", "srgb"},         {"bt709", "srgb"},          {"bt.709", "srgb"},
    {"p3", "display-p3"},    {"displayp3", "display-p3"}, {"display_p3", "display-p3"}, {"dcip3", "dci-p3"},
    {"dci_p3", "dci-p3"},    {"adobergb", "adobe-rgb"},   {"adobe_rgb", "adobe-rgb"}, {"bt2020", "rec2020"},
    {"bt.2020", "rec2020"},  {"rec.2020", "rec2020"},     {"rec_2020", "rec2020"},    {"aces-cg", "acescg"},
};

const char *colour_space_find(const char *name)
{
    size_t i;
    for (i = 0; colour_space_ids[i]; i++)
        if (!strcasecmp(name, colour_space_ids[i]))
            return colour_space_ids[i];
    for (i = 0; i < sizeof space_aliases / sizeof space_aliases[0]; i++)
        if (!strcasecmp(name, space_aliases[i].alias))
            return space_aliases[i].id;
    return NULL;
}

static int space_index(const char *name)
{
    const char *id = colour_space_find(name);
    int i;
    for (i = 0; id && colour_space_ids[i]; i++)
        if (!strcmp(id, colour_space_ids[i]))
            return i;
    return -1;
}

static int chromaticity(const csv_reader *r, char *const *field, int at, const char *column,
                        double xy[2])
{
    char column_y[32];
    int i;
    snprintf(column_y, sizeof column_y, "%.24s_y", column);
    if (csv_number(r, field[at], column, &xy[0]) || csv_number(r, field[at + 1], column_y, &xy[1]))
        return CLI_BAD_INPUT;
    for (i = 0; i < 2; i++)
        if (!(xy[i] > 0.0 && xy[i] < 1.0))
            return csv_error(r, "%s: chromaticity %.10g, expected 0 < x, y < 1",
                             i ? column_y : column, xy[i]);
    return 0;
}

/* Finds the row named `name` in colorspaces.csv and fills primaries and white. */
static int read_space(const char *dir, const char *name, colour_space *cs)
{
    char path[1024];
    csv_reader r;
    char *row, *field[12];
    int got;
    if ((size_t)snprintf(path, sizeof path, "%s/colorspaces.csv", dir) >= sizeof path)
        return cli_error(dir, "data directory path too long");
    if (csv_open(&r, path, SPACES_HEADER))
        return CLI_BAD_INPUT;
    while ((got = csv_next_row(&r, &row)) == 1) {
        int count = csv_split(row, field, 12);
        if (count != 11) {
            csv_error(&r, "expected 11 columns (" SPACES_HEADER "), got %d", count);
            break;
        }
        if (strcmp(field[0], name))
            continue;
        if (chromaticity(&r, field, 1, "red_x", cs->primary[0]) ||
            chromaticity(&r, field, 3, "green_x", cs->primary[1]) ||
            chromaticity(&r, field, 5, "blue_x", cs->primary[2]) ||
            chromaticity(&r, field, 8, "white_x", cs->white))
            break;
        csv_close(&r);
        return 0;
    }
    csv_close(&r);
    if (got == 0)
        cli_error(path, "expected a row named '%s'", name);
    return CLI_BAD_INPUT;
}

int colour_space_load(const char *dir, const char *id, const colorimetry *cm, colour_space *cs)
{
    mat3 rgb_to_xyz, xyz_to_space, adapt, composite;
    double spd_white[3], space_white[3], unit_rgb[3];
    int which = space_index(id), i, j;
    if (which < 0)
        return cli_unknown("fresnel", "colour space", id, colour_space_ids);
    memset(cs, 0, sizeof *cs);
    strcpy(cs->id, colour_space_ids[which]);
    if (read_space(dir, csv_names[which], cs))
        return CLI_BAD_INPUT;
    if (rgb_to_xyz_matrix(cs, &rgb_to_xyz) || mat_inverse(&rgb_to_xyz, &xyz_to_space))
        return cli_error(cs->id, "primaries in %s/colorspaces.csv are collinear", dir);
    illuminant_white(cm, spd_white);
    xy_to_xyz(cs->white, space_white);
    adapt = bradford_adaptation(spd_white, space_white);
    composite = mat_mul(&xyz_to_space, &adapt);
    /* The composite maps spd_white to (1,1,1) only up to rounding; the
     * explicit rescale brings the perfect reflector to (1,1,1) in the last
     * place (the rescaled row's own rounding remains), so a white metal
     * cannot come out tinted by the arithmetic. */
    mat_vec(&composite, spd_white, unit_rgb);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            cs->xyz_to_rgb[i][j] = composite.m[i][j] / unit_rgb[i];
    return 0;
}
