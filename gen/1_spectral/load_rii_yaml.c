/* A refractiveindex.info database file (a .yml under database/data), read
 * with a reader for that schema only, not for YAML at large:
 *
 *   # comment lines
 *   REFERENCES: ... | COMMENTS: ... | CONDITIONS: | PROPERTIES: | SPECS:
 *       (metadata: the key's indented lines are skipped)
 *   DATA:
 *     - type: tabulated nk          rows "um n k"
 *       data: |
 *           0.1879 1.28 1.188
 *     - type: tabulated n | tabulated k     rows "um value"
 *     - type: formula N             N = 1..9, the database's dispersion
 *       wavelength_range: lo hi     formulas [Polyanskiy, "Dispersion
 *       coefficients: C1 C2 ...     formulas", database/doc], um
 *
 * n comes from one entry (tabulated nk, tabulated n or a formula), k from
 * tabulated nk, tabulated k or nowhere (k = 0). Coefficients a formula
 * leaves out are zero, as the database's own tools take them; an empty list
 * is an error. A formula is sampled on the pipeline's 0.1 nm grid inside its
 * wavelength_range and nowhere else. The nonlinear-index files (tabulated n2,
 * formula A) describe n2, not n and k, and are refused. Tabs in indentation
 * (YAML forbids them), keys outside the schema, a block without rows and a
 * row with the wrong number of columns are errors at their line. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "1_spectral/import.h"

#define MAX_COEFFICIENTS 17

enum entry_kind { ENTRY_NONE, ENTRY_NK, ENTRY_N, ENTRY_K, ENTRY_FORMULA };

typedef struct entry {
    int line; /* of its '-' */
    enum entry_kind kind;
    int formula, type_line;
    int data_line, range_line, coefficients_line;
    double range[2];
    double c[MAX_COEFFICIENTS];
    int coefficient_count;
    nk_column n, k; /* tabulated rows */
} entry;

static const char *const top_keys[] = {"REFERENCES", "COMMENTS", "DATA", "SPECS", "CONDITIONS", "PROPERTIES", NULL};

/* Most coefficients each formula reads (C1..Cmax). */
static int formula_max_coefficients(int type)
{
    static const int max[10] = {0, 17, 17, 17, 17, 11, 11, 6, 4, 6};
    return type >= 1 && type <= 9 ? max[type] : 0;
}

/* n at um micrometres by formula `type`, or -1 when the formula gives no
 * real index there (n^2 <= 0, a pole, an overflow). c[i] is C(i+1). */
static int formula_n(int type, const double *c, double um, double *n)
{
    double l2 = um * um, v = 0.0, a;
    int i;
    switch (type) {
    case 1: /* Sellmeier: n^2 - 1 = C1 + sum C(2i) l^2 / (l^2 - C(2i+1)^2) */
        v = 1.0 + c[0];
        for (i = 1; i < 17; i += 2)
            v += c[i] * l2 / (l2 - c[i + 1] * c[i + 1]);
        break;
    case 2: /* Sellmeier-2: n^2 - 1 = C1 + sum C(2i) l^2 / (l^2 - C(2i+1)) */
        v = 1.0 + c[0];
        for (i = 1; i < 17; i += 2)
            v += c[i] * l2 / (l2 - c[i + 1]);
        break;
    case 3: /* polynomial: n^2 = C1 + sum C(2i) l^C(2i+1) */
        v = c[0];
        for (i = 1; i < 17; i += 2)
            v += c[i] * pow(um, c[i + 1]);
        break;
    case 4: /* RefractiveIndex.INFO: two poles, then powers */
        v = c[0] + c[1] * pow(um, c[2]) / (l2 - pow(c[3], c[4])) + c[5] * pow(um, c[6]) / (l2 - pow(c[7], c[8]));
        for (i = 9; i < 17; i += 2)
            v += c[i] * pow(um, c[i + 1]);
        break;
    case 5: /* Cauchy: n = C1 + sum C(2i) l^C(2i+1) */
        a = c[0];
        for (i = 1; i < 11; i += 2)
            a += c[i] * pow(um, c[i + 1]);
        if (!(a > 0.0) || !isfinite(a))
            return -1;
        *n = a;
        return 0;
    case 6: /* gases: n - 1 = C1 + sum C(2i) / (C(2i+1) - l^-2) */
        a = 1.0 + c[0];
        for (i = 1; i < 11; i += 2)
            a += c[i] / (c[i + 1] - 1.0 / l2);
        if (!(a > 0.0) || !isfinite(a))
            return -1;
        *n = a;
        return 0;
    case 7: /* Herzberger */
        a = c[0] + c[1] / (l2 - 0.028) + c[2] / ((l2 - 0.028) * (l2 - 0.028)) + c[3] * l2 + c[4] * l2 * l2 +
            c[5] * l2 * l2 * l2;
        if (!(a > 0.0) || !isfinite(a))
            return -1;
        *n = a;
        return 0;
    case 8: /* retro: (n^2 - 1) / (n^2 + 2) = C1 + C2 l^2 / (l^2 - C3) + C4 l^2 */
        a = c[0] + c[1] * l2 / (l2 - c[2]) + c[3] * l2;
        v = (1.0 + 2.0 * a) / (1.0 - a);
        break;
    case 9: /* exotic */
        v = c[0] + c[1] / (l2 - c[2]) + c[3] * (um - c[4]) / ((um - c[4]) * (um - c[4]) + c[5]);
        break;
    default: return -1;
    }
    if (!(v > 0.0) || !isfinite(v))
        return -1;
    *n = sqrt(v);
    return 0;
}

/* The formula on the 0.1 nm grid points inside its range. */
static int sample_formula(const text_file *t, const entry *e, nk_column *n)
{
    int i;
    double lo_nm = nm_from_um(e->range[0]), hi_nm = nm_from_um(e->range[1]);
    for (i = 0; i < SPEC_N; i++) {
        double nm = (3600 + i) / 10.0, v;
        if (nm < lo_nm - 1e-9 || nm > hi_nm + 1e-9)
            continue;
        if (formula_n(e->formula, e->c, nm / 1000.0, &v))
            return text_error(t, e->coefficients_line,
                              "formula %d gives no real, positive n at %.1f nm (%.4f um) with these coefficients",
                              e->formula, nm, nm / 1000.0);
        if (column_push(t, n, nm, v, e->coefficients_line))
            return CLI_BAD_INPUT;
    }
    if (n->rows < 2)
        return text_error(t, e->range_line,
                          "the formula's wavelength_range %.10g-%.10g um (%.10g-%.10g nm) has fewer than two points in "
                          "%g-%g nm, expected it to reach into the visible",
                          e->range[0], e->range[1], lo_nm, hi_nm, SPEC_LO_NM, SPEC_HI_NM);
    return 0;
}

static char *trim(char *s)
{
    char *end;
    s += strspn(s, " \t");
    end = s + strlen(s);
    while (end > s && (end[-1] == ' ' || end[-1] == '\t'))
        *--end = '\0';
    return s;
}

/* A plain scalar: a trailing " # comment" cut, one pair of quotes removed. */
static char *scalar(char *s)
{
    char *hash = strstr(s, " #");
    size_t len;
    if (hash)
        *hash = '\0';
    s = trim(s);
    len = strlen(s);
    if (len >= 2 && (s[0] == '"' || s[0] == '\'') && s[len - 1] == s[0]) {
        s[len - 1] = '\0';
        s++;
    }
    return s;
}

static int parse_type(const text_file *t, int line, const char *value, entry *e)
{
    if (e->kind != ENTRY_NONE)
        return text_error(t, line, "expected one 'type' per entry, it is already set at line %d", e->type_line);
    e->type_line = line;
    if (!strcmp(value, "tabulated nk"))
        e->kind = ENTRY_NK;
    else if (!strcmp(value, "tabulated n"))
        e->kind = ENTRY_N;
    else if (!strcmp(value, "tabulated k"))
        e->kind = ENTRY_K;
    else if (!strncmp(value, "formula ", 8) && strlen(value) == 9 && value[8] >= '1' && value[8] <= '9') {
        e->kind = ENTRY_FORMULA;
        e->formula = value[8] - '0';
    } else if (!strcmp(value, "tabulated n2") || !strcmp(value, "formula A"))
        return text_error(t, line,
                          "type '%s' is the nonlinear index n2 (the database's n2 files), not n and k: "
                          "expected a file from an nk folder",
                          value);
    else
        return text_error(t, line,
                          "expected type 'tabulated nk', 'tabulated n', 'tabulated k' or 'formula 1'..'formula 9', "
                          "got '%.40s'",
                          value);
    return 0;
}

/* One row of a data block. */
static int parse_row(const text_file *t, int line, char *s, entry *e)
{
    double v[4];
    int want = e->kind == ENTRY_NK ? 3 : 2;
    int got = text_numbers(t, line, s, "", v, 4);
    if (got < 0)
        return CLI_BAD_INPUT;
    if (got != want)
        return text_error(t, line, "expected %d numbers (%s) for type %s, got %d", want,
                          want == 3 ? "um n k" : e->kind == ENTRY_N ? "um n" : "um k",
                          want == 3 ? "tabulated nk" : e->kind == ENTRY_N ? "tabulated n" : "tabulated k", got);
    if (e->kind != ENTRY_K && column_push(t, &e->n, nm_from_um(v[0]), v[1], line))
        return CLI_BAD_INPUT;
    if (e->kind != ENTRY_N && column_push(t, &e->k, nm_from_um(v[0]), want == 3 ? v[2] : v[1], line))
        return CLI_BAD_INPUT;
    return 0;
}

static int parse_key(const text_file *t, int line, char *key, char *value, entry *e, int *block)
{
    double v[MAX_COEFFICIENTS];
    int count;
    if (!strcmp(key, "type"))
        return parse_type(t, line, scalar(value), e);
    if (!strcmp(key, "data")) {
        value = scalar(value);
        if (e->kind == ENTRY_NONE)
            return text_error(t, line, "expected 'type' before 'data' in the entry at line %d", e->line);
        if (e->kind == ENTRY_FORMULA)
            return text_error(t, line, "expected no 'data' in a formula entry (its type is at line %d)", e->type_line);
        if (e->data_line)
            return text_error(t, line, "expected one 'data' per entry, it is already at line %d", e->data_line);
        if (strcmp(value, "|") && strcmp(value, "|-") && strcmp(value, "|+"))
            return text_error(t, line, "expected 'data: |' followed by indented rows, got 'data: %.40s'", value);
        e->data_line = line;
        *block = 1;
        return 0;
    }
    if (!strcmp(key, "wavelength_range")) {
        if (e->range_line)
            return text_error(t, line, "expected one wavelength_range per entry, it is already at line %d",
                              e->range_line);
        if ((count = text_numbers(t, line, scalar(value), "", v, 2)) < 0)
            return CLI_BAD_INPUT;
        if (count != 2 || !(v[0] > 0.0) || !(v[1] > v[0]))
            return text_error(t, line, "expected wavelength_range: lo hi, two numbers of um with 0 < lo < hi");
        e->range[0] = v[0];
        e->range[1] = v[1];
        e->range_line = line;
        return 0;
    }
    if (!strcmp(key, "coefficients")) {
        if (e->coefficients_line)
            return text_error(t, line, "expected one coefficients list per entry, it is already at line %d",
                              e->coefficients_line);
        if ((count = text_numbers(t, line, scalar(value), "", v, MAX_COEFFICIENTS)) < 0)
            return CLI_BAD_INPUT;
        if (count == 0)
            return text_error(t, line, "expected coefficients: C1 C2 ..., got none");
        memcpy(e->c, v, (size_t)count * sizeof v[0]);
        e->coefficient_count = count;
        e->coefficients_line = line;
        return 0;
    }
    return text_error(t, line, "expected a key of a DATA entry (type, data, wavelength_range, coefficients), got '%.40s'",
                      key);
}

/* The finished entry's n and k go to *n, *k (each once in a file). */
static int finish_entry(const text_file *t, entry *e, nk_column *n, int *n_line, nk_column *k, int *k_line)
{
    int gives_n, gives_k;
    if (!e->line)
        return 0;
    if (e->kind == ENTRY_NONE)
        return text_error(t, e->line, "expected 'type: ...' in this DATA entry");
    if (e->kind == ENTRY_FORMULA) {
        int max = formula_max_coefficients(e->formula);
        if (!e->coefficients_line)
            return text_error(t, e->type_line, "formula %d: coefficients missing (expected 'coefficients: C1 C2 ...')",
                              e->formula);
        if (!e->range_line)
            return text_error(t, e->type_line,
                              "formula %d: wavelength_range missing (the formula holds only inside its range)",
                              e->formula);
        if (e->coefficient_count > max)
            return text_error(t, e->coefficients_line, "formula %d reads at most %d coefficients, got %d", e->formula,
                              max, e->coefficient_count);
        if (sample_formula(t, e, &e->n))
            return CLI_BAD_INPUT;
    } else {
        if (!e->data_line)
            return text_error(t, e->type_line, "expected 'data: |' and rows after this type");
        if (e->n.rows + e->k.rows == 0)
            return text_error(t, e->data_line, "expected rows after 'data: |', got none");
        /* Some tabulated entries restate their range; only coefficients
         * would be out of place. */
        if (e->coefficients_line)
            return text_error(t, e->coefficients_line, "expected coefficients only in a formula entry");
    }
    gives_n = e->kind != ENTRY_K;
    gives_k = e->kind == ENTRY_NK || e->kind == ENTRY_K;
    if (gives_n && *n_line)
        return text_error(t, e->type_line, "n is given twice: by the entry at line %d and by this one", *n_line);
    if (gives_k && *k_line)
        return text_error(t, e->type_line, "k is given twice: by the entry at line %d and by this one", *k_line);
    if (gives_n) {
        *n = e->n;
        memset(&e->n, 0, sizeof e->n);
        *n_line = e->type_line;
    }
    if (gives_k) {
        *k = e->k;
        memset(&e->k, 0, sizeof e->k);
        *k_line = e->type_line;
    }
    column_free(&e->n);
    column_free(&e->k);
    memset(e, 0, sizeof *e);
    return 0;
}

int load_rii_yaml(text_file *t, nk_table *out)
{
    enum { SECTION_NONE, SECTION_META, SECTION_DATA } section = SECTION_NONE;
    entry e;
    nk_column n, k;
    int n_line = 0, k_line = 0, data_seen = 0, block = 0, key_indent = 0, status = CLI_BAD_INPUT;
    char *line;
    memset(&e, 0, sizeof e);
    memset(&n, 0, sizeof n);
    memset(&k, 0, sizeof k);
    while (text_next(t, &line)) {
        int indent = (int)strspn(line, " ");
        char *content = line + indent, *colon;
        if (content[strspn(content, " \t")] == '\0')
            continue;
        if (content[0] == '\t') {
            text_error(t, t->line, "expected spaces for indentation, got a tab (YAML forbids tabs there)");
            goto done;
        }
        if (block) {
            if (indent > key_indent) {
                if (content[0] == '#') {
                    text_error(t, t->line, "expected a row of numbers inside the data block, got a comment");
                    goto done;
                }
                if (parse_row(t, t->line, content, &e))
                    goto done;
                continue;
            }
            block = 0;
        }
        if (content[0] == '#')
            continue;
        if (indent == 0) {
            int i;
            if (finish_entry(t, &e, &n, &n_line, &k, &k_line))
                goto done;
            colon = strchr(content, ':');
            if (colon)
                *colon = '\0';
            for (i = 0; top_keys[i] && (!colon || strcmp(top_keys[i], content)); i++)
                ;
            if (!top_keys[i]) {
                text_error(t, t->line,
                           "expected a top-level key of a refractiveindex.info file (REFERENCES, COMMENTS, DATA, "
                           "SPECS, CONDITIONS, PROPERTIES), got '%.40s'",
                           content);
                goto done;
            }
            if (!strcmp(content, "DATA")) {
                if (data_seen) {
                    text_error(t, t->line, "expected one DATA key, it is already at line %d", data_seen);
                    goto done;
                }
                if (*scalar(colon + 1)) {
                    text_error(t, t->line, "expected 'DATA:' followed by indented '- type: ...' entries");
                    goto done;
                }
                data_seen = t->line;
                section = SECTION_DATA;
            } else
                section = SECTION_META;
            continue;
        }
        if (section == SECTION_META)
            continue;
        if (section != SECTION_DATA) {
            text_error(t, t->line, "expected a top-level key before this indented line");
            goto done;
        }
        if (content[0] == '-' && (content[1] == ' ' || content[1] == '\0')) {
            if (finish_entry(t, &e, &n, &n_line, &k, &k_line))
                goto done;
            e.line = t->line;
            content++;
            indent++;
            indent += (int)strspn(content, " ");
            content += strspn(content, " ");
            if (*content == '\0')
                continue;
        } else if (!e.line || indent <= key_indent - 1) {
            text_error(t, t->line, "expected '- type: ...' to start a DATA entry");
            goto done;
        }
        key_indent = indent;
        colon = strchr(content, ':');
        if (!colon || colon == content || strspn(content, "abcdefghijklmnopqrstuvwxyz_") != (size_t)(colon - content)) {
            text_error(t, t->line, "expected 'key: value' in a DATA entry, got '%.40s'", content);
            goto done;
        }
        *colon = '\0';
        if (parse_key(t, t->line, content, colon + 1, &e, &block))
            goto done;
    }
    if (finish_entry(t, &e, &n, &n_line, &k, &k_line))
        goto done;
    if (!data_seen) {
        text_error(t, t->line, "expected a DATA key with n and k entries, found none");
        goto done;
    }
    if (!n_line) {
        text_error(t, data_seen, "expected an entry giving n (tabulated nk, tabulated n or a formula), found none");
        goto done;
    }
    status = nk_merge(t, "um", &n, NULL, k_line ? &k : NULL, out);
done:
    column_free(&e.n);
    column_free(&e.k);
    column_free(&n);
    column_free(&k);
    return status;
}
