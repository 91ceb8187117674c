/* fresnel eval: one model over eta,kappa,cos lines from stdin. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "cli/material_options.h"
#include "model/registry.h"

#define WHERE "fresnel eval"
#define REFERENCE_TYPE "f64" /* --type of the double reference, beside the runtime's number types */

static void eval_usage(FILE *out)
{
    int i;
    fprintf(out,
            "usage: fresnel eval --model NAME --type f32|f64|q15|f16 [--n1 X] [--f90 X] [--p X]\n"
            "\n"
            "Reads CSV lines eta,kappa,cos on stdin and writes one reflectance per line,\n"
            "in order: %%.9g for f32 (the binary32 runtime), %%.17g for f64 (the double\n"
            "reference), %%.9g for q15 (the Q15 runtime of fresnel_q15.h: cos and\n"
            "the parameters converted to its formats, the result code divided by 32768)\n"
            "and for f16 (the binary16 runtime of fresnel_f16.h, parameters and cos\n"
            "rounded to binary16; only where the compiler has _Float16).\n"
            "eta + i kappa is the material's index, seen from a medium of\n"
            "real index n1 (default 1); cos is the cosine of the angle of incidence.\n"
            "(--type fixed is accepted as another name for q15.)\n"
            "An optional first line 'eta,kappa,cos' is a header (a leading UTF-8\n"
            "byte-order mark is skipped); empty lines and lines\n"
            "starting with '#' are ignored. Parameters a model needs (F0, F82, LSK a and\n"
            "alpha, Gulbrandsen r and g) are derived from eta, kappa and n1 by the double\n"
            "reference; f32 rounds them to binary32 before calling the runtime.\n"
            "--f90 (default 1) and --p (default 5) are the generalized Schlick parameters.\n"
            "\n"
            "Bad input (non-numeric or non-finite field, wrong number of columns, a NUL\n"
            "byte) is reported as <stdin>:LINE:COLUMN on stderr with exit status 2, and\n"
            "nothing is written to stdout. A read or write error exits with status 1.\n"
            "\nmodels:\n");
    for (i = 0; i < model_count; i++)
        if (model_table[i].offered & MODEL_EVAL)
            fprintf(out, "  %-18s %s\n", model_table[i].name, model_table[i].params);
}

/* Split s in place at commas; returns the number of fields (at most max). */
static int split_csv(char *s, char **field, int max)
{
    int n = 0;
    char *p = s;
    for (;;) {
        char *comma = strchr(p, ',');
        if (n < max)
            field[n] = p;
        n++;
        if (!comma)
            break;
        *comma = '\0';
        p = comma + 1;
    }
    return n;
}

static char *trim(char *s)
{
    char *end;
    while (*s == ' ' || *s == '\t')
        s++;
    end = s + strlen(s);
    while (end > s && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\r' || end[-1] == '\n'))
        *--end = '\0';
    return s;
}

int cmd_eval(int argc, char **argv)
{
    static const char *const options[] = {"--model", "--type", "--n1", "--f90", "--p", "--help", NULL};
    static const char *const column[3] = {"eta", "kappa", "cos"};
    const model *m = NULL;
    const number_type *type = NULL; /* NULL with f64: the double reference */
    int f64 = 0;
    int i, status = 0;
    double n1 = 1.0, f90 = 1.0, p = 5.0;
    char where[64];
    char *line = NULL;
    size_t cap = 0, count = 0, out_cap = 0;
    double *out = NULL;
    long lineno = 0;
    int seen_data = 0;

    for (i = 1; i < argc; i++) {
        const char *opt = argv[i], *val;
        if (!strcmp(opt, "--help") || !strcmp(opt, "-h")) {
            eval_usage(stdout);
            return 0;
        }
        if (!cli_looks_like_option(opt) || !cli_in_list(opt, options))
            return cli_bad_argument(WHERE, opt, options);
        if (!(val = cli_option_value(WHERE, argc, argv, &i)))
            return CLI_BAD_INPUT;
        if (!strcmp(opt, "--model")) {
            if (!(m = model_find(val))) {
                const char *names[64];
                model_names(MODEL_EVAL, names, 64);
                return cli_unknown(WHERE, "model", val, names);
            }
        } else if (!strcmp(opt, "--type")) {
            type = NULL;
            if (!(f64 = !strcmp(val, REFERENCE_TYPE)) && type_option(WHERE, val, &type))
                return CLI_BAD_INPUT;
        } else if (!strcmp(opt, "--n1")) {
            if (cli_parse_double(val, &n1) || !(n1 > 0.0))
                return cli_error(WHERE, "--n1 expects a positive number, got '%s'", val);
        } else if (!strcmp(opt, "--f90")) {
            if (cli_parse_double(val, &f90))
                return cli_error(WHERE, "--f90 expects a number, got '%s'", val);
        } else {
            if (cli_parse_double(val, &p))
                return cli_error(WHERE, "--p expects a number, got '%s'", val);
        }
    }
    if (!m)
        return cli_error(WHERE, "--model is required (see fresnel eval --help)");
    if (!type && !f64) {
        char list[64] = "";
        int t;
        for (t = 0; t < number_types_available; t++)
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", t ? ", " : "", number_types[t].name);
        return cli_error(WHERE, "--type is required: a number type (%s) or %s, the double reference", list,
                         REFERENCE_TYPE);
    }
    if (type && !type->has(m))
        return cli_error(WHERE, "--model %s has no %s evaluator", m->name, type->name);

    /* Everything is evaluated before anything is printed, so bad input on
     * line 1000 leaves stdout empty rather than half-written. */
    for (;;) {
        char *field[4], *s;
        double v[3];
        model_params mp;
        int nf, k;
        size_t len = 0;
        int ch;
        /* read one line of any length */
        while ((ch = getchar()) != EOF && ch != '\n') {
            if (ch == '\0') {
                snprintf(where, sizeof where, "<stdin>:%ld", lineno + 1);
                status = cli_error(where, "expected text, found a NUL byte");
                goto done;
            }
            if (len + 1 >= cap) {
                cap = cap ? 2 * cap : 256;
                line = realloc(line, cap);
                if (!line) {
                    status = cli_oom(WHERE);
                    goto done;
                }
            }
            line[len++] = (char)ch;
        }
        if (ch == EOF && (status = cli_check_input(WHERE, stdin, "<stdin>")))
            goto done;
        if (ch == EOF && len == 0)
            break;
        if (!line) {
            cap = 16;
            if (!(line = malloc(cap))) {
                status = cli_oom(WHERE);
                goto done;
            }
        }
        line[len] = '\0';
        lineno++;
        snprintf(where, sizeof where, "<stdin>:%ld", lineno);
        s = trim(line + (lineno == 1 ? cli_skip_bom(line) : 0));
        if (*s == '\0' || *s == '#')
            continue;
        if (!seen_data) {
            seen_data = 1;
            if (!strcmp(s, "eta,kappa,cos"))
                continue;
        }
        nf = split_csv(s, field, 4);
        if (nf != 3) {
            status = cli_error(where, "expected 3 columns eta,kappa,cos, found %d", nf);
            goto done;
        }
        for (k = 0; k < 3; k++) {
            char *f = trim(field[k]);
            if (cli_parse_double(f, &v[k])) {
                snprintf(where, sizeof where, "<stdin>:%ld:%d", lineno, k + 1);
                status = cli_error(where, "expected a finite number for %s, got '%s'", column[k], f);
                goto done;
            }
        }
        model_derive(v[0], v[1], n1, f90, p, &mp);
        if (count == out_cap) {
            double *grown;
            out_cap = out_cap ? 2 * out_cap : 1024;
            if (!(grown = realloc(out, out_cap * sizeof *out))) {
                status = cli_oom(WHERE);
                goto done;
            }
            out = grown;
        }
        if (f64) {
            out[count++] = m->ref->scalar(&mp, v[2]);
        } else {
            type->round(&mp);
            out[count++] = type->eval_params(m, &mp, v[2]);
        }
        if (ch == EOF)
            break;
    }
    {
        size_t j;
        for (j = 0; j < count; j++)
            printf(f64 ? "%.17g\n" : "%.9g\n", out[j]);
    }
done:
    free(line);
    free(out);
    return status;
}
