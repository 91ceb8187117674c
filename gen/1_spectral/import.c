/* A user's n,k file, in whichever format it came (spectral.h: nk_import,
 * material_load). The format is told from the first line that is neither
 * blank nor a '#' comment:
 *
 *   wavelength_nm,n,k          the data pack's CSV (load_nk.c), nm
 *   wl,n / wl,k / wl,n,k       refractiveindex.info CSV export (load_rii_csv.c), um
 *   KEY: (upper-case key)      refractiveindex.info database YAML (load_rii_yaml.c), um
 *   four numbers, no comment,  SOPRA .nk header (load_sopra.c), eV, um or nm
 *     a unit digit first and
 *     whole intervals last
 *   other blank-separated      .spd pairs, one or more to a line (load_spd.c), nm
 *     numbers
 *
 * --format NAME skips the guess. Each reader's opening comment states its
 * rules; all of them end in the same per-row checks (nk_check_row) and the
 * same coverage rule (spectrum_from_table), so a user's file is held to the
 * data pack's standard. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "common/cli.h"
#include "1_spectral/import.h"

const char *const nk_format_names[] = {"auto", "csv", "rii-yaml", "rii-csv", "sopra", "spd", NULL};

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* How many whitespace/';'/','-separated words of s are numbers (stored in
 * v, up to 4), or -1 if some word is not one. A '#' ends the words (.spd
 * comments follow the values). */
static int count_numbers(const char *s, double v[4])
{
    int count = 0;
    while (*s && *s != '#') {
        char word[64];
        size_t len;
        double x;
        s += strspn(s, " \t;,\r");
        len = strcspn(s, " \t;,\r#");
        if (len == 0)
            continue;
        if (len >= sizeof word)
            return -1;
        memcpy(word, s, len);
        word[len] = '\0';
        if (cli_parse_double(word, &x))
            return -1;
        if (count < 4)
            v[count] = x;
        count++;
        s += len;
    }
    return count;
}

static int detect(const text_file *t, nk_format *format)
{
    const char *p = (const char *)t->data + cli_skip_bom((const char *)t->data);
    int line = 1, comments = 0, count;
    double v[4];
    while (*p) {
        char buf[256];
        size_t len = strcspn(p, "\n"), skip;
        const char *s;
        snprintf(buf, sizeof buf, "%.*s", (int)(len < sizeof buf - 1 ? len : sizeof buf - 1), p);
        buf[strcspn(buf, "\r")] = '\0';
        s = buf + strspn(buf, " \t");
        p += len + (p[len] == '\n');
        if (*s == '\0') {
            line++;
            continue;
        }
        if (*s == '#') {
            comments = 1;
            line++;
            continue;
        }
        skip = strspn(s, "ABCDEFGHIJKLMNOPQRSTUVWXYZ_");
        if (!strcmp(s, "wavelength_nm,n,k"))
            *format = NK_FORMAT_CSV;
        else if (!strncmp(s, "wl,", 3) || !strncmp(s, "wl ,", 4))
            *format = NK_FORMAT_RII_CSV;
        else if (skip > 0 && s[skip] == ':')
            *format = NK_FORMAT_RII_YAML;
        /* A SOPRA header is four numbers, a unit code (a digit) first and a
         * whole number of intervals last; .spd pairs may run several to a
         * line, so four numbers that are not such a header are pairs. */
        else if ((count = count_numbers(s, v)) == 4 && !comments && v[0] >= 0.0 && v[0] <= 9.0 &&
                 v[0] == floor(v[0]) && v[3] >= 1.0 && v[3] == floor(v[3]))
            *format = NK_FORMAT_SOPRA;
        else if (count >= 2 && strcspn(s, ",;") >= strcspn(s, "#")) /* .spd: blanks between values */
            *format = NK_FORMAT_SPD;
        else
            return text_error(t, line,
                              "cannot tell the format from '%.40s': expected a refractiveindex.info YAML file (KEY: "
                              "lines), its CSV export (wl,n ...), the data pack's CSV (wavelength_nm,n,k), a SOPRA .nk "
                              "(unit start end intervals) or .spd pairs (wavelength_nm value); --format NAME overrides",
                              s);
        return 0;
    }
    return text_error(t, line > 1 ? line - 1 : 1, "expected n,k data, the file is empty");
}

static int ends_with(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && !strcmp(s + a - b, suffix);
}

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* The .spd pair: NAME.eta.spd with NAME.k.spd. *eta_path/ *k_path are set
 * (k_path "" when there is no k file). */
static int spd_pair(const char *path, char *eta_path, char *k_path, size_t size)
{
    size_t len = strlen(path);
    if (len + 8 > size)
        return cli_error(path, "path too long");
    strcpy(eta_path, path);
    k_path[0] = '\0';
    if (ends_with(path, ".k.spd")) {
        snprintf(eta_path, size, "%.*s.eta.spd", (int)(len - 6), path);
        strcpy(k_path, path);
        if (!exists(eta_path))
            return cli_error(path, "a k file needs its n beside it: expected %s", eta_path);
    } else if (ends_with(path, ".eta.spd")) {
        snprintf(k_path, size, "%.*s.k.spd", (int)(len - 8), path);
        if (!exists(k_path)) {
            fprintf(stderr, "%s: warning: no %s beside it; k = 0 (a dielectric)\n", path, base_name(k_path));
            k_path[0] = '\0';
        }
    }
    return 0;
}

int nk_import(const char *path, nk_format format, nk_table *t, nk_file_info *info)
{
    text_file file, k_file;
    char eta_path[CLI_PATH_MAX], k_path[CLI_PATH_MAX];
    int status;
    memset(info, 0, sizeof *info);
    memset(t, 0, sizeof *t);
    memset(&k_file, 0, sizeof k_file);
    if ((status = text_read(path, &file)))
        return status;
    if (format == NK_FORMAT_AUTO && (status = detect(&file, &format))) {
        text_free(&file);
        return status;
    }
    info->format = nk_format_names[format];
    snprintf(info->file, sizeof info->file, "%s", base_name(path));
    if (format == NK_FORMAT_SPD) {
        if ((status = spd_pair(path, eta_path, k_path, sizeof eta_path))) {
            text_free(&file);
            return status;
        }
        if (strcmp(eta_path, path)) { /* given the k file: read n first */
            k_file = file;
            k_file.path = path;
            if ((status = text_read(eta_path, &file))) {
                text_free(&k_file);
                return status;
            }
        } else if (k_path[0] && (status = text_read(k_path, &k_file))) {
            text_free(&file);
            return status;
        }
        if (k_file.data)
            snprintf(info->file, sizeof info->file, "%.120s + %.120s", base_name(file.path), base_name(k_file.path));
    }
    info->bytes = (long)(file.size + k_file.size);
    if (k_file.data) {
        unsigned char *both = malloc(file.size + k_file.size + 1);
        if (!both) {
            text_free(&file);
            text_free(&k_file);
            return cli_oom(path);
        }
        memcpy(both, file.data, file.size);
        memcpy(both + file.size, k_file.data, k_file.size);
        sha256_hex(both, file.size + k_file.size, info->sha256);
        free(both);
    } else
        sha256_hex(file.data, file.size, info->sha256);
    switch (format) {
    case NK_FORMAT_CSV: status = load_nk(path, t); break;
    case NK_FORMAT_RII_YAML: status = load_rii_yaml(&file, t); break;
    case NK_FORMAT_RII_CSV: status = load_rii_csv(&file, t); break;
    case NK_FORMAT_SOPRA: status = load_sopra(&file, t); break;
    default: status = load_spd(&file, k_file.data ? &k_file : NULL, t); break;
    }
    text_free(&file);
    text_free(&k_file);
    return status;
}

void material_id_from_path(const char *path, char out[32])
{
    const char *base = base_name(path);
    cli_identifier(base, strcspn(base, "."), out, 32, "material");
}

int material_load(const char *dir, const material_source *m, material_info *info, spectrum *s)
{
    nk_table t;
    double k_sum = 0.0;
    int i, status;
    if (!m->path || !*m->path)
        return material_lookup(dir, m->id, info, "material") || spectrum_load(dir, m->id, s) ? CLI_BAD_INPUT : 0;
    memset(info, 0, sizeof *info);
    if ((status = nk_import(m->path, m->format, &t, &info->file)))
        return status;
    status = spectrum_from_table(m->path, &t, s);
    nk_table_free(&t);
    if (status)
        return status;
    snprintf(info->id, sizeof info->id, "%s", m->id);
    snprintf(info->name, sizeof info->name, "%s", info->file.file);
    snprintf(info->dataset, sizeof info->dataset, "%s file, %ld bytes, sha256 %s", info->file.format,
             info->file.bytes, info->file.sha256);
    /* The report sorts metals from dielectrics. Over the 0.1 nm grid the
     * data pack's metals have a mean k of 2.7 or more, silicon (listed with
     * them) 0.146, its glasses and liquids under 2e-6: a threshold of 0.1
     * gives every data-pack table the kind materials.csv gives it. */
    for (i = 0; i < SPEC_N; i++)
        k_sum += s->k[i];
    snprintf(info->kind, sizeof info->kind, "%s", k_sum / SPEC_N >= 0.1 ? "metal" : "dielectric");
    return 0;
}
