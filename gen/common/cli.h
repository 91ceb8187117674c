/* Shared conventions of the `fresnel` command-line program (host only). */
#ifndef FRESNEL_CLI_H
#define FRESNEL_CLI_H

#include <stdio.h>

#include <stdarg.h>
#include <stddef.h>

/* The tool's version, printed by `fresnel version` and in every generated file. */
#define GEN_VERSION "0.1.0"

/* Exit statuses: 0 success, 1 a failure to read or write (disk full, a
 * closed pipe, a read-only target, a directory or an I/O error as input),
 * 2 bad input or usage, 3 out of memory. */
#define CLI_FAILURE 1
#define CLI_BAD_INPUT 2
#define CLI_NO_MEMORY 3

/* The exit status of a command that returned status: 0 stays 0; a failure
 * reports the worst class of error printed on the way (cli_oom: 3, then
 * cli_read_failure and failed output: 1), whatever status the callers in
 * between passed up; otherwise status. */
int cli_exit_status(int status);

/* Print "where: message" to stderr (where = "file:line", "file:line:col",
 * "<stdin>:3", or a subcommand name) and return CLI_BAD_INPUT. Control
 * characters in the message (input quoted in it) are shown escaped. */
int cli_error(const char *where, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void cli_verror(const char *where, const char *fmt, va_list ap);
/* "where: out of memory"; returns CLI_NO_MEMORY. */
int cli_oom(const char *where);
/* "where: cannot read: strerror(err)"; returns CLI_FAILURE. */
int cli_read_failure(const char *where, int err);

/* Parse a whole string as a finite double (subnormals included); 0 on
 * success, -1 otherwise. */
int cli_parse_double(const char *s, double *out);
/* Parse a whole string as an int in [lo, hi]; 0 on success, -1 otherwise. */
int cli_parse_int(const char *s, int lo, int hi, int *out);

/* Option parsing shared by the subcommands. cli_option_value: argv[*i] is
 * an option taking a value; returns the value (advancing *i), or NULL after
 * a message when there is none or the next word is itself an option.
 * cli_bad_argument: the message for a word no option matched (a stray
 * positional argument or an unknown option, with a suggestion from the
 * NULL-terminated options list); returns CLI_BAD_INPUT. */
int cli_looks_like_option(const char *s);
int cli_in_list(const char *s, const char *const *list); /* 1 if s is in the NULL-terminated list */
const char *cli_option_value(const char *where, int argc, char **argv, int *i);
int cli_bad_argument(const char *where, const char *arg, const char *const *options);

/* The candidate (NULL-terminated list) within a few edits of name, ignoring
 * case, or NULL. cli_unknown prints "unknown WHAT 'name' (did you mean
 * 'x'?)", or the list of valid names, and returns CLI_BAD_INPUT. */
const char *cli_suggest(const char *name, const char *const *candidates);
int cli_unknown(const char *where, const char *what, const char *name, const char *const *candidates);

/* The first len bytes of s as an identifier part: letters lower-cased,
 * every run of other characters one '_', none at either end, at most size - 1
 * characters; fallback when nothing is left. */
void cli_identifier(const char *s, size_t len, char *out, size_t size, const char *fallback);

/* Length of a leading UTF-8 byte-order mark in s (3 or 0). */
size_t cli_skip_bom(const char *s);

/* Opens an input file for reading (binary): *f, or a status after a
 * message naming path. A missing or unopenable file is CLI_BAD_INPUT, a
 * directory CLI_FAILURE (a read failure), anything but a regular file or a
 * pipe (a device, a socket) CLI_BAD_INPUT. A FIFO is opened without waiting
 * for a writer (with none, it reads as empty). The file is remembered: no
 * output of this run may replace it (cli_out_open, cli_out_commit). */
int cli_open_input(const char *path, FILE **f);

/* After reading f to its end: 0, or CLI_FAILURE after "where: reading
 * NAME: reason" when the stream had a read error. */
int cli_check_input(const char *where, FILE *f, const char *name);
/* Flush and close stdout: 0, or CLI_FAILURE after "where: writing
 * <stdout>: reason". */
int cli_finish_stdout(const char *where);

/* Safe output. PATH "-" is stdout. A regular file (new or existing) is
 * written to an unpredictable temporary beside it (mkstemp) and renamed over
 * it on commit, keeping an existing file's mode; a symlink is resolved and
 * its target replaced that way; a device, FIFO or socket is written in
 * place. A read-only target or a directory is an error (CLI_FAILURE); a
 * file this run read as input (cli_open_input) is refused (CLI_BAD_INPUT).
 * The temporary is removed on every error path and by a handler for
 * SIGHUP, SIGINT, SIGQUIT, SIGTERM and SIGPIPE. open and commit print their
 * own message ("PATH: reason") and return 0 or that status. A command that
 * writes several files commits them with cli_out_commit_all: each is
 * written and closed first, and only when all of them succeeded are they
 * renamed into place; otherwise none is. */
#define CLI_PATH_MAX 4096
/* Temporaries that can exist at once: report -o DIR writes one per
 * material (at most 64) and three more, all committed together. */
#define CLI_TMP_SLOTS 80
enum { CLI_OUT_ATOMIC, CLI_OUT_DIRECT, CLI_OUT_STDOUT };
typedef struct cli_outfile {
    FILE *f;
    int kind, slot;
    char path[CLI_PATH_MAX]; /* the file finally written (symlinks resolved) */
    char shown[1024];        /* the name messages use */
} cli_outfile;
int cli_out_open(cli_outfile *o, const char *path);
int cli_out_commit(cli_outfile *o);
void cli_out_abort(cli_outfile *o); /* close; remove the temporary */
/* Commits the n open outputs o[0..n-1] together, or none of them: 0 or a
 * status after a message; either way every one is closed and no
 * temporary is left. */
int cli_out_commit_all(cli_outfile *const *o, int n);
void cli_out_abort_all(cli_outfile *const *o, int n);
/* 1 when out names the same existing file as in (through links). */
int cli_out_is_input(const char *out, const char *in);
/* The signal handler's cleanup, callable from a test: removes every listed
 * temporary, then re-raises sig with its default action. */
void cli_out_test_signal_cleanup(int sig);

#endif
