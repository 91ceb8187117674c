/* Shared by the parser fuzz targets: the input goes to a scratch file (the
 * parsers take a path), and stderr is captured so the oracle can require
 * exactly one "path:..." message on every rejection and none on success. */
#ifndef FRESNEL_FUZZ_PARSER_H
#define FRESNEL_FUZZ_PARSER_H

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fuzz.h"

static char fuzz_dir[256], fuzz_file[512];

static void fuzz_remove_scratch(void)
{
    if (fuzz_file[0])
        remove(fuzz_file);
    rmdir(fuzz_dir);
}

/* A private directory for the scratch file, made once per process and
 * removed at exit (a crash leaves it for the post-mortem). */
static inline const char *fuzz_scratch_dir(void)
{
    if (!fuzz_dir[0]) {
        const char *tmp = getenv("TMPDIR");
        snprintf(fuzz_dir, sizeof fuzz_dir, "%s/fresnel-fuzz-XXXXXX", tmp && *tmp ? tmp : "/tmp");
        if (!mkdtemp(fuzz_dir)) {
            perror("fuzz: mkdtemp");
            abort();
        }
        atexit(fuzz_remove_scratch);
    }
    return fuzz_dir;
}

/* path must be the same on every call (one scratch file per target). */
static inline void fuzz_write_file(const char *path, const uint8_t *data, size_t size)
{
    FILE *f;
    snprintf(fuzz_file, sizeof fuzz_file, "%s", path);
    f = fopen(path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f)) {
        perror(path);
        abort();
    }
}

/* glibc makes stderr an assignable variable; the parsers print through it,
 * so pointing it at a memory stream for the call captures their message
 * without touching file descriptor 2 (where libFuzzer and the sanitizers
 * report). */
typedef struct fuzz_capture {
    FILE *saved, *mem;
    char *text;
    size_t len;
} fuzz_capture;

static inline void fuzz_capture_begin(fuzz_capture *c)
{
    c->text = NULL;
    c->len = 0;
    c->saved = stderr;
    c->mem = open_memstream(&c->text, &c->len);
    if (!c->mem)
        abort();
    stderr = c->mem;
}

static inline void fuzz_capture_end(fuzz_capture *c)
{
    stderr = c->saved;
    fclose(c->mem);
}

/* Lines in the captured text (each ends in '\n'); -1 if the text does not end in one. */
static inline int fuzz_lines(const char *text, size_t len)
{
    int n = 0;
    size_t i;
    if (len == 0)
        return 0;
    if (text[len - 1] != '\n')
        return -1;
    for (i = 0; i < len; i++)
        n += text[i] == '\n';
    return n;
}

/* A rejection names the file and a line inside it (or one past its last
 * line, where a missing row would go): "path:N: ..." with 1 <= N <= lines+1. */
static inline int fuzz_message_names_line(const char *msg, const char *path, const uint8_t *data, size_t size)
{
    size_t plen = strlen(path), i;
    long line, lines = 1;
    char *end;
    if (strncmp(msg, path, plen) != 0 || msg[plen] != ':')
        return 0;
    line = strtol(msg + plen + 1, &end, 10);
    if (end == msg + plen + 1 || *end != ':')
        return 0;
    for (i = 0; i < size; i++)
        lines += data[i] == '\n';
    return line >= 1 && line <= lines + 1;
}

#endif
