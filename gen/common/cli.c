/* Error reporting, number parsing, option values, name suggestions and safe
 * output for the CLI. */
#include "common/cli.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* Writes s to stderr with every control byte (and DEL) shown as \n, \t,
 * \r or \xNN, so input quoted in a message cannot move the cursor, clear
 * the terminal or hide part of the message. */
static void put_escaped(const char *s)
{
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '\n')
            fputs("\\n", stderr);
        else if (c == '\t')
            fputs("\\t", stderr);
        else if (c == '\r')
            fputs("\\r", stderr);
        else if (c < 0x20 || c == 0x7f)
            fprintf(stderr, "\\x%02x", c);
        else if (c == 0xc2 && (unsigned char)s[1] >= 0x80 && (unsigned char)s[1] <= 0x9f)
            fprintf(stderr, "\\u%04x", (unsigned char)*++s); /* a C1 control (U+0080-U+009F) in UTF-8 */
        else
            fputc(c, stderr);
    }
}

void cli_verror(const char *where, const char *fmt, va_list ap)
{
    char small[512], *msg = small;
    va_list copy;
    int n;
    va_copy(copy, ap);
    n = vsnprintf(small, sizeof small, fmt, copy);
    va_end(copy);
    if (n >= (int)sizeof small && (msg = malloc((size_t)n + 1)) != NULL)
        vsnprintf(msg, (size_t)n + 1, fmt, ap);
    if (!msg)
        msg = small; /* truncated rather than lost */
    put_escaped(where);
    fputs(": ", stderr);
    put_escaped(n < 0 ? fmt : msg);
    fputc('\n', stderr);
    if (msg != small)
        free(msg);
}

int cli_error(const char *where, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    cli_verror(where, fmt, ap);
    va_end(ap);
    return CLI_BAD_INPUT;
}

/* The worst class of failure reported so far (cli_exit_status): the
 * statuses pass through many callers, some of which only know "it failed". */
static int failure_class;

static void note_failure(int status)
{
    if (status == CLI_NO_MEMORY || (status == CLI_FAILURE && failure_class != CLI_NO_MEMORY))
        failure_class = status;
}

int cli_exit_status(int status)
{
    return status && failure_class ? failure_class : status;
}

int cli_oom(const char *where)
{
    cli_error(where, "out of memory");
    note_failure(CLI_NO_MEMORY);
    return CLI_NO_MEMORY;
}

int cli_read_failure(const char *where, int err)
{
    cli_error(where, "cannot read: %s", strerror(err ? err : EIO));
    note_failure(CLI_FAILURE);
    return CLI_FAILURE;
}

int cli_parse_double(const char *s, double *out)
{
    char *end;
    double v;
    if (s == NULL || *s == '\0')
        return -1;
    errno = 0;
    v = strtod(s, &end);
    if (end == s || *end != '\0' || !isfinite(v))
        return -1;
    /* strtod reports ERANGE for underflow too: a subnormal (1e-310) or a
     * value that rounds to zero (1e-400) is still a finite number. Only
     * overflow (returned as +-HUGE_VAL, caught above) is out of range. */
    if (errno == ERANGE && fabs(v) > DBL_MIN)
        return -1;
    *out = v;
    return 0;
}

int cli_parse_int(const char *s, int lo, int hi, int *out)
{
    char *end;
    long v;
    if (s == NULL || *s == '\0')
        return -1;
    errno = 0;
    v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE || v < lo || v > hi)
        return -1;
    *out = (int)v;
    return 0;
}

int cli_looks_like_option(const char *s)
{
    return s[0] == '-' && (s[1] == '-' || isalpha((unsigned char)s[1]));
}

const char *cli_option_value(const char *where, int argc, char **argv, int *i)
{
    if (*i + 1 >= argc || cli_looks_like_option(argv[*i + 1])) {
        cli_error(where, "option '%s' needs a value (see %s --help)", argv[*i], where);
        return NULL;
    }
    return argv[++*i];
}

int cli_in_list(const char *s, const char *const *list)
{
    int i;
    for (i = 0; list[i]; i++)
        if (!strcmp(s, list[i]))
            return 1;
    return 0;
}

int cli_bad_argument(const char *where, const char *arg, const char *const *options)
{
    const char *near;
    if (!cli_looks_like_option(arg))
        return cli_error(where, "unexpected argument '%s' (see %s --help)", arg, where);
    if ((near = cli_suggest(arg, options)) != NULL)
        return cli_error(where, "unknown option '%s' (did you mean '%s'?)", arg, near);
    return cli_error(where, "unknown option '%s' (see %s --help)", arg, where);
}

/* Edit distance counting an insertion, deletion, substitution or swap of
 * two neighbours as one edit (optimal string alignment), ASCII case folded,
 * for names of up to 63 bytes. */
static int distance(const char *a, const char *b)
{
    int d[3][64], la = (int)strlen(a), lb = (int)strlen(b), i, j;
    if (la > 63 || lb > 63)
        return INT_MAX;
    for (j = 0; j <= lb; j++)
        d[0][j] = j;
    for (i = 1; i <= la; i++) {
        int *row = d[i % 3], *up = d[(i - 1) % 3], *up2 = d[(i + 1) % 3];
        row[0] = i;
        for (j = 1; j <= lb; j++) {
            int ca = tolower((unsigned char)a[i - 1]), cb = tolower((unsigned char)b[j - 1]);
            int best = up[j - 1] + (ca != cb);
            if (up[j] + 1 < best)
                best = up[j] + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            if (i > 1 && j > 1 && ca == tolower((unsigned char)b[j - 2]) &&
                tolower((unsigned char)a[i - 2]) == cb && up2[j - 2] + 1 < best)
                best = up2[j - 2] + 1;
            row[j] = best;
        }
    }
    return d[la % 3][lb];
}

const char *cli_suggest(const char *name, const char *const *candidates)
{
    const char *best = NULL;
    int best_d = INT_MAX, len = (int)strlen(name), limit, i;
    /* Close enough to be a typo: one edit for short names, up to a third
     * of the name for longer ones. */
    limit = len <= 4 ? 1 : len / 3 < 3 ? len / 3 : 3;
    if (limit < 1)
        limit = 1;
    for (i = 0; candidates[i]; i++) {
        int d = distance(name, candidates[i]);
        if (d < best_d) {
            best_d = d;
            best = candidates[i];
        }
    }
    return best_d <= limit ? best : NULL;
}

int cli_unknown(const char *where, const char *what, const char *name, const char *const *candidates)
{
    const char *near = cli_suggest(name, candidates);
    char list[512] = "";
    size_t used = 0;
    int i;
    if (near)
        return cli_error(where, "unknown %s '%s' (did you mean '%s'?)", what, name, near);
    for (i = 0; candidates[i]; i++) {
        int n = snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", candidates[i]);
        if (n < 0 || (size_t)n >= sizeof list - used)
            break;
        used += (size_t)n;
    }
    return cli_error(where, "unknown %s '%s' (expected one of: %s)", what, name, list);
}

void cli_identifier(const char *s, size_t len, char *out, size_t size, const char *fallback)
{
    size_t i = 0;
    for (; len > 0 && i + 1 < size; s++, len--) {
        unsigned char ch = (unsigned char)*s;
        char c = ch < 128 && isalnum(ch) ? (char)tolower(ch) : '_';
        if (c == '_' && (i == 0 || out[i - 1] == '_'))
            continue; /* no leading '_', no '__' */
        out[i++] = c;
    }
    while (i > 0 && out[i - 1] == '_')
        i--;
    if (i == 0) {
        snprintf(out, size, "%s", fallback);
        return;
    }
    out[i] = '\0';
}

size_t cli_skip_bom(const char *s)
{
    return !strncmp(s, "\xEF\xBB\xBF", 3) ? 3 : 0;
}

/* ---- input files ----------------------------------------------------------- */

/* Every file opened as input, so that no output replaces one. */
typedef struct input_file {
    dev_t dev;
    ino_t ino;
    char *path;
} input_file;
static input_file *inputs;
static int input_count, input_cap;

static const char *file_kind(mode_t mode)
{
    return S_ISCHR(mode)    ? "a character device"
           : S_ISBLK(mode)  ? "a block device"
           : S_ISSOCK(mode) ? "a socket"
                            : "not a regular file";
}

int cli_open_input(const char *path, FILE **f)
{
    struct stat st;
    int fd, flags, i;
    *f = NULL;
    /* O_NONBLOCK: opening a FIFO would otherwise wait for a writer, for
     * ever if none comes. Reads block again below. */
    if ((fd = open(path, O_RDONLY | O_NOCTTY | O_NONBLOCK)) < 0)
        return cli_error(path, "cannot open: %s", strerror(errno));
    if (fstat(fd, &st) != 0) {
        int err = errno;
        close(fd);
        return cli_read_failure(path, err);
    }
    if (S_ISDIR(st.st_mode)) {
        close(fd);
        return cli_read_failure(path, EISDIR);
    }
    if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode)) {
        close(fd);
        return cli_error(path, "expected a regular file or a pipe, got %s", file_kind(st.st_mode));
    }
    if ((flags = fcntl(fd, F_GETFL)) == -1 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == -1) {
        int err = errno;
        close(fd);
        return cli_read_failure(path, err);
    }
    for (i = 0; i < input_count && (inputs[i].dev != st.st_dev || inputs[i].ino != st.st_ino); i++)
        ;
    if (i == input_count) {
        if (input_count == input_cap) {
            int cap = input_cap ? 2 * input_cap : 16;
            input_file *grown = realloc(inputs, (size_t)cap * sizeof *grown);
            if (!grown) {
                close(fd);
                return cli_oom(path);
            }
            inputs = grown;
            input_cap = cap;
        }
        if (!(inputs[i].path = malloc(strlen(path) + 1))) {
            close(fd);
            return cli_oom(path);
        }
        strcpy(inputs[i].path, path);
        inputs[i].dev = st.st_dev;
        inputs[i].ino = st.st_ino;
        input_count++;
    }
    if (!(*f = fdopen(fd, "rb"))) {
        int err = errno;
        close(fd);
        return err == ENOMEM ? cli_oom(path) : cli_read_failure(path, err);
    }
    return 0;
}

/* The input that path (through links) is, or NULL. */
static const char *input_at(const char *path)
{
    struct stat st;
    int i;
    if (stat(path, &st) != 0)
        return NULL;
    for (i = 0; i < input_count; i++)
        if (inputs[i].dev == st.st_dev && inputs[i].ino == st.st_ino)
            return inputs[i].path;
    return NULL;
}

/* ---- standard streams ---------------------------------------------------- */

int cli_check_input(const char *where, FILE *f, const char *name)
{
    if (!ferror(f))
        return 0;
    cli_error(where, "reading %s: %s", name, errno ? strerror(errno) : "read error");
    note_failure(CLI_FAILURE);
    return CLI_FAILURE;
}

int cli_finish_stdout(const char *where)
{
    int bad;
    errno = 0;
    bad = fflush(stdout) != 0 || ferror(stdout);
    if (!bad && fclose(stdout) != 0)
        bad = 1;
    if (!bad)
        return 0;
    cli_error(where, "writing <stdout>: %s", errno ? strerror(errno) : "write error");
    return CLI_FAILURE;
}

/* ---- safe output ---------------------------------------------------------- */

/* Temporary files that exist right now, for the signal handler: it may only
 * call async-signal-safe functions, so the paths live in static buffers and
 * a slot is published (used = 1) only after its path is complete. */
static char tmp_paths[CLI_TMP_SLOTS][CLI_PATH_MAX + 32];
static volatile sig_atomic_t tmp_used[CLI_TMP_SLOTS];
static int handlers_installed;

static void on_signal(int sig)
{
    int i;
    for (i = 0; i < CLI_TMP_SLOTS; i++)
        if (tmp_used[i])
            unlink(tmp_paths[i]);
    signal(sig, SIG_DFL);
    raise(sig);
}

static void install_handlers(void)
{
    static const int sigs[] = {SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGPIPE};
    size_t i;
    if (handlers_installed)
        return;
    handlers_installed = 1;
    for (i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        struct sigaction sa, old;
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue; /* started with the signal ignored (nohup): keep it so */
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(sigs[i], &sa, NULL);
    }
}

void cli_out_test_signal_cleanup(int sig)
{
    on_signal(sig);
}

static int claim_slot(void)
{
    int i;
    for (i = 0; i < CLI_TMP_SLOTS; i++)
        if (!tmp_used[i] && tmp_paths[i][0] == '\0')
            return i;
    return -1;
}

static void release_slot(cli_outfile *o)
{
    if (o->slot >= 0) {
        tmp_used[o->slot] = 0;
        tmp_paths[o->slot][0] = '\0';
        o->slot = -1;
    }
}

static int out_fail(cli_outfile *o, const char *what, int err)
{
    cli_error(o->shown, "%s: %s", what, strerror(err));
    note_failure(CLI_FAILURE);
    return CLI_FAILURE;
}

/* CLI_BAD_INPUT after a message when o's target is one of the inputs. */
static int refuse_input(const cli_outfile *o, const char *target)
{
    const char *in = input_at(target);
    if (!in)
        return 0;
    if (!strcmp(in, o->shown))
        return cli_error(o->shown, "is an input of this command; expected a different output");
    return cli_error(o->shown, "is %s, an input of this command; expected a different output", in);
}

/* Follows a chain of symbolic links from path to the file they finally name
 * (which need not exist yet); 0 or -1 with errno set. */
static int resolve_links(const char *path, char *out, size_t size, int *via_proc)
{
    char cur[CLI_PATH_MAX], link[CLI_PATH_MAX];
    struct stat st;
    int hops;
    if (strlen(path) >= sizeof cur) {
        errno = ENAMETOOLONG;
        return -1;
    }
    strcpy(cur, path);
    for (hops = 0; hops < 40; hops++) {
        ssize_t n;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
            break;
        n = readlink(cur, link, sizeof link - 1);
        if (n < 0)
            return -1;
        link[n] = '\0';
        if (!strncmp(link, "/proc/", 6))
            *via_proc = 1;
        if (link[0] == '/') {
            strcpy(cur, link);
        } else {
            char *slash = strrchr(cur, '/');
            size_t keep = slash ? (size_t)(slash - cur) + 1 : 0;
            if (keep + (size_t)n >= sizeof cur) {
                errno = ENAMETOOLONG;
                return -1;
            }
            memcpy(cur + keep, link, (size_t)n + 1);
        }
    }
    if (hops == 40) {
        errno = ELOOP;
        return -1;
    }
    if (strlen(cur) >= size) {
        errno = ENAMETOOLONG;
        return -1;
    }
    strcpy(out, cur);
    return 0;
}

int cli_out_open(cli_outfile *o, const char *path)
{
    struct stat st;
    mode_t mode;
    int fd, exists, via_proc;
    char *slash;
    o->f = NULL;
    o->kind = CLI_OUT_ATOMIC;
    o->slot = -1;
    snprintf(o->shown, sizeof o->shown, "%s", path);
    if (!strcmp(path, "-")) {
        o->kind = CLI_OUT_STDOUT;
        snprintf(o->shown, sizeof o->shown, "<stdout>");
        o->f = stdout;
        return 0;
    }
    via_proc = 0;
    if (resolve_links(path, o->path, sizeof o->path, &via_proc))
        return out_fail(o, "cannot resolve", errno);
    /* /dev/stdout and the like lead through /proc/self/fd to an open file
     * description, which may be a pipe ("pipe:[123]", no path at all) or a
     * file the shell opened for appending: written in place, appending. */
    exists = stat(via_proc ? path : o->path, &st) == 0;
    if (!exists && errno != ENOENT)
        return out_fail(o, "cannot write", errno);
    if (exists && S_ISDIR(st.st_mode))
        return out_fail(o, "cannot write", EISDIR);
    if (exists && refuse_input(o, via_proc ? path : o->path))
        return CLI_BAD_INPUT;
    if (exists && (via_proc || !S_ISREG(st.st_mode))) {
        /* A device, FIFO or socket is written in place: renaming a file over
         * /dev/null would replace the device node. */
        o->kind = CLI_OUT_DIRECT;
        fd = open(via_proc ? path : o->path, O_WRONLY | O_NOCTTY | (via_proc ? O_APPEND : 0));
        if (fd < 0)
            return out_fail(o, "cannot write", errno);
        if (!(o->f = fdopen(fd, "wb"))) {
            int err = errno;
            close(fd);
            return out_fail(o, "cannot write", err);
        }
        return 0;
    }
    /* Read-only means no write bit at all, even for root, whom access(2)
     * lets write anything: replacing such a file would silently defeat a
     * protection its owner set. */
    if (exists && access(o->path, W_OK) != 0)
        return out_fail(o, "cannot write", errno);
    if (exists && (st.st_mode & 0222) == 0)
        return out_fail(o, "cannot write a read-only file", EACCES);
    if (exists) {
        mode = st.st_mode & 07777;
    } else {
        mode_t mask = umask(0);
        umask(mask);
        mode = 0666 & ~mask;
    }
    /* The temporary is created next to the target (so rename is atomic) by
     * mkstemp: an unpredictable name, opened O_CREAT|O_EXCL, so a file or
     * symlink planted in advance is never followed or overwritten. */
    if ((o->slot = claim_slot()) < 0)
        return out_fail(o, "cannot write", EMFILE);
    slash = strrchr(o->path, '/');
    if ((size_t)snprintf(tmp_paths[o->slot], sizeof tmp_paths[o->slot], "%.*s.%s.XXXXXX",
                         slash ? (int)(slash - o->path) + 1 : 0, o->path, slash ? slash + 1 : o->path) >=
        sizeof tmp_paths[o->slot]) {
        tmp_paths[o->slot][0] = '\0';
        o->slot = -1;
        return out_fail(o, "cannot write", ENAMETOOLONG);
    }
    install_handlers();
    {
        /* Signals are held while the name is created and published, so a
         * signal in between cannot leave an unlisted temporary behind. */
        sigset_t all, old;
        sigfillset(&all);
        sigprocmask(SIG_BLOCK, &all, &old);
        fd = mkstemp(tmp_paths[o->slot]);
        if (fd >= 0)
            tmp_used[o->slot] = 1;
        sigprocmask(SIG_SETMASK, &old, NULL);
    }
    if (fd < 0) {
        int err = errno;
        tmp_paths[o->slot][0] = '\0';
        o->slot = -1;
        return out_fail(o, "cannot create a temporary file beside it", err);
    }
    if (fchmod(fd, mode) != 0 || !(o->f = fdopen(fd, "wb"))) {
        int err = errno;
        close(fd);
        unlink(tmp_paths[o->slot]);
        release_slot(o);
        return out_fail(o, "cannot write", err);
    }
    return 0;
}

/* Flushes and closes o: 0, or CLI_FAILURE after a message with o's
 * temporary removed. A temporary that succeeded stays for out_rename. */
static int out_close(cli_outfile *o)
{
    int err = 0;
    errno = 0;
    if (fflush(o->f) != 0 || ferror(o->f))
        err = errno ? errno : EIO;
    if (o->kind != CLI_OUT_STDOUT && fclose(o->f) != 0 && !err)
        err = errno ? errno : EIO;
    o->f = NULL;
    if (err && o->kind == CLI_OUT_ATOMIC) {
        unlink(tmp_paths[o->slot]);
        release_slot(o);
    }
    return err ? out_fail(o, "write error", err) : 0;
}

/* Renames a closed temporary over its target. */
static int out_rename(cli_outfile *o)
{
    int err = 0;
    if (o->kind != CLI_OUT_ATOMIC)
        return 0;
    if (rename(tmp_paths[o->slot], o->path) != 0) {
        err = errno;
        unlink(tmp_paths[o->slot]);
    }
    release_slot(o);
    return err ? out_fail(o, "write error", err) : 0;
}

/* Removes a closed temporary. */
static void out_discard(cli_outfile *o)
{
    if (o->kind == CLI_OUT_ATOMIC && o->slot >= 0) {
        unlink(tmp_paths[o->slot]);
        release_slot(o);
    }
}

int cli_out_commit(cli_outfile *o)
{
    cli_outfile *one[1];
    one[0] = o;
    return cli_out_commit_all(one, 1);
}

int cli_out_commit_all(cli_outfile *const *o, int n)
{
    int i, status = 0;
    for (i = 0; i < n; i++) {
        int s = o[i]->f ? out_close(o[i]) : 0;
        if (s && !status)
            status = s;
    }
    /* An input read after the output was opened (report's --cross) is
     * still not replaced. */
    for (i = 0; i < n && !status; i++)
        if (o[i]->kind == CLI_OUT_ATOMIC && o[i]->slot >= 0)
            status = refuse_input(o[i], o[i]->path);
    for (i = 0; i < n; i++) {
        if (status)
            out_discard(o[i]); /* after a failure, the rest are discarded */
        else
            status = out_rename(o[i]);
    }
    return status;
}

void cli_out_abort(cli_outfile *o)
{
    if (o->f && o->kind != CLI_OUT_STDOUT)
        fclose(o->f);
    o->f = NULL;
    out_discard(o);
}

void cli_out_abort_all(cli_outfile *const *o, int n)
{
    int i;
    for (i = 0; i < n; i++)
        cli_out_abort(o[i]);
}

int cli_out_is_input(const char *out, const char *in)
{
    struct stat a, b;
    if (!strcmp(out, "-") || stat(out, &a) != 0 || stat(in, &b) != 0)
        return 0;
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}
