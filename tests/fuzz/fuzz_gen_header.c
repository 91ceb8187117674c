/* Fuzzes the generator end to end: a manifest and one material's n,k table
 * through `fresnel gen` (cmd_gen) to a C header, whose every value is then
 * checked without a compiler (tests/common/header_check.h).
 *
 * Input: the manifest, then optionally a line "%%" and the CSV of material
 * `fz` (wavelength_nm,n,k); without it, fz is a plain dielectric. The data
 * pack is the repository's data/ (read from the working directory) plus fz.
 *
 * Oracle:
 *   - no crash, no sanitizer report, no leak;
 *   - exit 0: the header exists, and every declaration has a type the
 *     checker knows and values inside that type and the range the runtime
 *     documents (a wrapped int16_t, an inf.0f, a clamped code all fail);
 *   - exit 2: no header and no temporary file left, and the message names
 *     the manifest or the data file as "path:line:" (or "path:");
 *   - any other exit status fails. */
#include "fuzz_parser.h"

#include <limits.h>
#include <sys/stat.h>

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

#include "cli/commands.h"
#include "common/cli.h"
#include "../common/header_check.h"

static char data_dir_path[300], scene_path[300], csv_path[400], out_path[300], materials_path[400];
static char link_paths[64][400];
static int links;
static hc_header hh;

static void remove_all(void)
{
    int i;
    for (i = 0; i < links; i++)
        remove(link_paths[i]);
    remove(csv_path);
    remove(materials_path);
    remove(scene_path);
    remove(out_path);
    rmdir(data_dir_path);
}

/* The scratch data pack: links to the colour tables and every material of
 * data/, and a materials.csv that adds fz. Made once per process. */
static void setup(void)
{
    static const char *const files[] = {"cie1931_2deg.csv", "illuminant_d65.csv", "illuminant_a.csv",
                                        "colorspaces.csv"};
    char repo[PATH_MAX], src[PATH_MAX + 40], line[512];
    FILE *in, *out;
    size_t i;
    const char *dir = fuzz_scratch_dir();
    if (!getcwd(repo, sizeof repo - 8)) {
        perror("fuzz_gen_header: getcwd");
        abort();
    }
    strcat(repo, "/data"); /* run from the repository root */
    snprintf(data_dir_path, sizeof data_dir_path, "%s/data", dir);
    snprintf(scene_path, sizeof scene_path, "%s/s.scene", dir);
    snprintf(out_path, sizeof out_path, "%s/out.h", dir);
    snprintf(csv_path, sizeof csv_path, "%s/fz.csv", data_dir_path);
    snprintf(materials_path, sizeof materials_path, "%s/materials.csv", data_dir_path);
    if (mkdir(data_dir_path, 0700) != 0)
        abort();
    atexit(remove_all);
    for (i = 0; i < sizeof files / sizeof files[0]; i++) {
        snprintf(src, sizeof src, "%s/%s", repo, files[i]);
        snprintf(link_paths[links], sizeof link_paths[0], "%s/%s", data_dir_path, files[i]);
        if (symlink(src, link_paths[links++]) != 0)
            abort();
    }
    /* every material of the pack, as links, and fz */
    snprintf(src, sizeof src, "%s/materials.csv", repo);
    if (!(in = fopen(src, "r")) || !(out = fopen(materials_path, "w")))
        abort();
    while (fgets(line, sizeof line, in)) {
        char id[64], target[PATH_MAX + 80];
        fputs(line, out);
        if (sscanf(line, "%63[a-z0-9_],", id) == 1 && strcmp(id, "id") != 0 && links < 64) {
            snprintf(target, sizeof target, "%s/%s.csv", repo, id);
            snprintf(link_paths[links], sizeof link_paths[0], "%s/%s.csv", data_dir_path, id);
            if (symlink(target, link_paths[links++]) != 0)
                abort();
        }
    }
    fputs("fz,Fuzz material,fuzz input,dielectric\n", out);
    fclose(in);
    fclose(out);
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    long len;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (len = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (buf = (char *)malloc((size_t)len + 1)) != NULL) {
        if (fread(buf, 1, (size_t)len, f) != (size_t)len) {
            free(buf);
            buf = NULL;
        } else {
            buf[len] = '\0';
        }
    }
    fclose(f);
    return buf;
}

/* A temporary output (out.h.tmp...) left in the scratch directory. */
static int leftover_tmp(void)
{
    char cmd[700];
    struct stat st;
    snprintf(cmd, sizeof cmd, "%s.tmp.%ld", out_path, (long)getpid());
    return stat(cmd, &st) == 0;
}

/* Length of the prefix "path:" or "path:N:" of line when path is one of
 * the inputs (the manifest, the data file, the data directory), else 0. */
static size_t input_prefix(const char *line)
{
    const char *const paths[] = {scene_path, csv_path, data_dir_path};
    size_t i, len;
    for (i = 0; i < 3; i++) {
        len = strlen(paths[i]);
        if (strncmp(line, paths[i], len) != 0)
            continue;
        while (line[len] && line[len] != ':' && line[len] != '\n') /* data_dir/<file> */
            len++;
        if (line[len] != ':')
            continue;
        len++;
        if (line[len] >= '0' && line[len] <= '9') {
            while (line[len] >= '0' && line[len] <= '9')
                len++;
            if (line[len] != ':')
                continue;
            len++;
        }
        return len;
    }
    return 0;
}

/* Some line is an error (not a warning) that names an input. */
static int names_input(const char *msg)
{
    const char *line = msg;
    while (line && *line) {
        size_t p = input_prefix(line);
        if (p && strncmp(line + p, " warning:", 9) != 0)
            return 1;
        line = strchr(line, '\n');
        if (line)
            line++;
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char default_csv[] = "wavelength_nm,n,k\n360,1.52,0\n830,1.50,0\n";
    const uint8_t *sep = NULL;
    size_t i, scene_len = size;
    char *argv[7], *text;
    fuzz_capture cap;
    int rc;
    if (!data_dir_path[0])
        setup();
    for (i = 0; i + 4 <= size; i++)
        if (!memcmp(data + i, "\n%%\n", 4)) {
            sep = data + i;
            break;
        }
    if (sep)
        scene_len = (size_t)(sep - data) + 1;
    fuzz_write_file(scene_path, data, scene_len);
    if (sep)
        fuzz_write_file(csv_path, sep + 4, size - scene_len - 3);
    else
        fuzz_write_file(csv_path, (const uint8_t *)default_csv, sizeof default_csv - 1);
    remove(out_path);
    argv[0] = (char *)"gen";
    argv[1] = scene_path;
    argv[2] = (char *)"-o";
    argv[3] = out_path;
    argv[4] = (char *)"--data";
    argv[5] = data_dir_path;
    argv[6] = NULL;
    fuzz_capture_begin(&cap);
    rc = cmd_gen(6, argv);
    fuzz_capture_end(&cap);
    text = slurp(out_path);
    if (leftover_tmp())
        FUZZ_FAIL("fresnel gen left a temporary output behind (exit %d)", rc);
    if (rc == 0) {
        if (!text)
            FUZZ_FAIL("fresnel gen exited 0 without writing %s", out_path);
        else if (hc_parse(text, &hh))
            FUZZ_FAIL("header value outside its type or range: %.300s", hh.err);
        hc_free(&hh);
    } else if (rc == CLI_BAD_INPUT) {
        if (text)
            FUZZ_FAIL("fresnel gen exited 2 but wrote %s", out_path);
        if (!cap.text || !names_input(cap.text))
            FUZZ_FAIL("exit 2 without a message naming the manifest or the data: '%.300s'",
                      cap.text ? cap.text : "");
    } else {
        FUZZ_FAIL("fresnel gen exited %d, expected 0 or 2: '%.300s'", rc, cap.text ? cap.text : "");
    }
    free(text);
    free(cap.text);
    return 0;
}
