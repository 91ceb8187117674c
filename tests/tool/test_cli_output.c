/* gen/common/cli.c's safe output and parsing helpers, tested directly: the signal
 * handler's cleanup (deterministic here, where a real SIGTERM mid-write
 * would race), the temporary's name and mode, and the number and name
 * helpers every subcommand shares. */
#include <dirent.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "common/cli.h"
#include "harness.h"

static int count_entries(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    if (!d)
        return -1;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            n++;
    closedir(d);
    return n;
}

static int read_all(const char *path, char *buf, size_t size)
{
    FILE *f = fopen(path, "rb");
    size_t n;
    if (!f)
        return -1;
    n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
    return (int)n;
}

int main(void)
{
    char dir[] = "/tmp/fresnel_cli_out_XXXXXX", target[256], buf[64];
    struct stat st;
    cli_outfile o;
    pid_t pid;
    int status;
    double v;
    static const char *const names[] = {"schlick", "f82", "exact", "srgb", NULL};

    if (!mkdtemp(dir)) {
        CHECK("mkdtemp", 0, "cannot create a directory");
        return harness_exit();
    }
    snprintf(target, sizeof target, "%s/out.h", dir);
    {
        FILE *f = fopen(target, "w");
        fputs("old\n", f);
        fclose(f);
        chmod(target, 0600);
    }

    /* The handler: a child opens the output, writes part of it, then takes
     * the handler's path for SIGTERM. It must die of SIGTERM with the
     * temporary gone and the target as it was. */
    fflush(stdout);
    pid = fork();
    if (pid == 0) {
        if (cli_out_open(&o, target) != 0)
            _exit(3);
        fputs("partial", o.f);
        fflush(o.f);
        if (count_entries(dir) != 2)
            _exit(4); /* the temporary should exist beside the target */
        cli_out_test_signal_cleanup(SIGTERM);
        _exit(5);
    }
    waitpid(pid, &status, 0);
    CHECK("signal cleanup re-raises SIGTERM", WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM,
          "child status 0x%x", status);
    CHECK("signal cleanup removes the temporary", count_entries(dir) == 1, "%d entries in %s", count_entries(dir),
          dir);
    CHECK("signal cleanup leaves the target untouched", read_all(target, buf, sizeof buf) == 4 && !strcmp(buf, "old\n"),
          "target holds '%s'", buf);

    /* The same through a real SIGTERM: the handler cli_out_open installed
     * runs, removes the temporary, and the process dies of the signal. */
    fflush(stdout);
    pid = fork();
    if (pid == 0) {
        if (cli_out_open(&o, target) != 0)
            _exit(3);
        fputs("partial", o.f);
        fflush(o.f);
        if (count_entries(dir) != 2)
            _exit(4);
        raise(SIGTERM);
        _exit(5);
    }
    waitpid(pid, &status, 0);
    CHECK("SIGTERM during a write: killed by SIGTERM, temporary removed, target untouched",
          WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM && count_entries(dir) == 1 &&
              read_all(target, buf, sizeof buf) == 4 && !strcmp(buf, "old\n"),
          "status 0x%x, %d entries, target '%s'", status, count_entries(dir), buf);

    /* Commit keeps the mode of the file it replaces. */
    if (cli_out_open(&o, target) == 0) {
        char tmpname[512];
        DIR *d = opendir(dir);
        struct dirent *e;
        tmpname[0] = '\0';
        while (d && (e = readdir(d)) != NULL)
            if (strstr(e->d_name, ".out.h."))
                snprintf(tmpname, sizeof tmpname, "%s", e->d_name);
        if (d)
            closedir(d);
        /* mkstemp's suffix: six characters not derived from the pid. */
        {
            char pid_text[32];
            snprintf(pid_text, sizeof pid_text, "%ld", (long)getpid());
            CHECK("temporary named .out.h.XXXXXX, not after the pid",
                  strlen(tmpname) == strlen(".out.h.") + 6 && !strstr(tmpname, pid_text), "temporary '%s'", tmpname);
        }
        fputs("new\n", o.f);
        CHECK("commit succeeds", cli_out_commit(&o) == 0, "commit failed");
    }
    CHECK("commit keeps mode 0600", stat(target, &st) == 0 && (st.st_mode & 07777) == 0600, "mode %o",
          (unsigned)(st.st_mode & 07777));
    CHECK("commit wrote the new content", read_all(target, buf, sizeof buf) == 4 && !strcmp(buf, "new\n"), "'%s'",
          buf);
    /* Abort removes the temporary and leaves the target. */
    if (cli_out_open(&o, target) == 0) {
        fputs("never", o.f);
        cli_out_abort(&o);
    }
    CHECK("abort leaves no temporary and the target as it was",
          count_entries(dir) == 1 && read_all(target, buf, sizeof buf) == 4 && !strcmp(buf, "new\n"),
          "%d entries, target '%s'", count_entries(dir), buf);

    CHECK("subnormal 1e-310 is a finite number", cli_parse_double("1e-310", &v) == 0 && v > 0.0 && v < 1e-300,
          "rejected or wrong");
    CHECK("1e-400 rounds to zero, accepted", cli_parse_double("1e-400", &v) == 0 && v == 0.0, "rejected");
    CHECK("1e400 overflows, rejected", cli_parse_double("1e400", &v) != 0, "accepted");
    CHECK("nan and inf rejected", cli_parse_double("nan", &v) != 0 && cli_parse_double("-inf", &v) != 0, "accepted");
    CHECK("suggest: one edit", cli_suggest("schlik", names) && !strcmp(cli_suggest("schlik", names), "schlick"),
          "no suggestion");
    CHECK("suggest: a swap of neighbours is one edit",
          cli_suggest("srbg", names) && !strcmp(cli_suggest("srbg", names), "srgb"), "no suggestion");
    CHECK("suggest: case ignored", cli_suggest("EXACT", names) && !strcmp(cli_suggest("EXACT", names), "exact"),
          "no suggestion");
    CHECK("suggest: nothing for a far name", cli_suggest("zzzzzzzz", names) == NULL, "suggested '%s'",
          cli_suggest("zzzzzzzz", names));
    CHECK("option values: a word starting -- is not a value", cli_looks_like_option("--space") &&
                                                                  !cli_looks_like_option("-") &&
                                                                  !cli_looks_like_option("-1.5"),
          "wrong classification");

    unlink(target);
    rmdir(dir);
    return harness_exit();
}
