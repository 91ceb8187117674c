/* Shared conventions of the `fresnel` command-line program (host only). */
#ifndef FRESNEL_CLI_H
#define FRESNEL_CLI_H

#include <stdio.h>

/* Exit status for bad input or usage, as the issues fix it. */
#define CLI_BAD_INPUT 2

/* Print "where: message" to stderr (where = "file:line", "file:line:col",
 * "<stdin>:3", or a subcommand name) and return CLI_BAD_INPUT. */
int cli_error(const char *where, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Parse a whole string as a finite double; 0 on success, -1 otherwise. */
int cli_parse_double(const char *s, double *out);
/* Parse a whole string as an int in [lo, hi]; 0 on success, -1 otherwise. */
int cli_parse_int(const char *s, int lo, int hi, int *out);

/* Output written to PATH.tmp.<pid> and renamed over PATH on commit, so an
 * error never leaves a half-written file behind. */
typedef struct cli_outfile {
    FILE *f;
    char path[1024];
    char tmp[1100];
} cli_outfile;
int cli_out_open(cli_outfile *o, const char *path);   /* 0 or -1 (errno set) */
int cli_out_commit(cli_outfile *o);                    /* 0 or -1; the temp file is removed on failure */
void cli_out_abort(cli_outfile *o);                    /* close and remove the temp file */

/* Subcommands: argv[0] is the subcommand name. Return the exit status. */
int cmd_eval(int argc, char **argv);
int cmd_wavelengths(int argc, char **argv);
int cmd_materials(int argc, char **argv);
int cmd_accuracy(int argc, char **argv);
int cmd_params(int argc, char **argv);
int cmd_gen(int argc, char **argv);
int cmd_report(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_curve(int argc, char **argv);
int cmd_extremes(int argc, char **argv);

#endif
