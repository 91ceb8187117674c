/* Replays a fuzz target's corpus without libFuzzer (`make test`): each
 * argument is a corpus file or a directory of them, fed in name order to
 * LLVMFuzzerTestOneInput. Targets built with -DFUZZ_REPLAY count oracle
 * violations in fuzz_failures instead of aborting, so every file is tried.
 * Prints one FAIL line per failing file and one PASS line for the target. */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
extern int fuzz_failures;

static int files, failed_files;

static void replay_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    uint8_t *buf = NULL;
    size_t cap = 0, len = 0;
    int before = fuzz_failures;
    if (!f) {
        printf("FAIL fuzz replay: cannot open %s\n", path);
        failed_files++;
        return;
    }
    for (;;) {
        size_t got;
        if (len == cap) {
            uint8_t *grown;
            cap = cap ? 2 * cap : 4096;
            grown = realloc(buf, cap);
            if (!grown)
                break;
            buf = grown;
        }
        got = fread(buf + len, 1, cap - len, f);
        if (got == 0)
            break;
        len += got;
    }
    fclose(f);
    /* A copy of exactly len bytes, so ASan sees any read past the input. */
    {
        uint8_t *exact = malloc(len ? len : 1);
        if (exact) {
            if (len)
                memcpy(exact, buf, len);
            LLVMFuzzerTestOneInput(exact, len);
            free(exact);
        }
    }
    free(buf);
    files++;
    if (fuzz_failures != before) {
        printf("FAIL fuzz replay %s: %d oracle violations\n", path, fuzz_failures - before);
        failed_files++;
    }
    fflush(stdout);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static void replay(const char *path)
{
    struct stat st;
    DIR *d;
    struct dirent *e;
    char **names = NULL;
    size_t n = 0, cap = 0, i;
    if (stat(path, &st) != 0 || !S_ISDIR(st.st_mode)) {
        replay_file(path);
        return;
    }
    d = opendir(path);
    if (!d) {
        printf("FAIL fuzz replay: cannot open directory %s\n", path);
        failed_files++;
        return;
    }
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        if (n == cap) {
            char **grown = realloc(names, (cap = cap ? 2 * cap : 64) * sizeof *names);
            if (!grown)
                break;
            names = grown;
        }
        names[n] = malloc(strlen(path) + strlen(e->d_name) + 2);
        if (!names[n])
            break;
        sprintf(names[n], "%s/%s", path, e->d_name);
        n++;
    }
    closedir(d);
    qsort(names, n, sizeof *names, by_name);
    for (i = 0; i < n; i++) {
        replay_file(names[i]);
        free(names[i]);
    }
    free(names);
}

int main(int argc, char **argv)
{
    int i;
    const char *name = argc > 0 ? strrchr(argv[0], '/') : NULL;
    name = name ? name + 1 : argv[0];
    for (i = 1; i < argc; i++)
        replay(argv[i]);
    if (files == 0)
        printf("FAIL fuzz replay %s: no corpus files\n", name);
    else if (failed_files == 0)
        printf("PASS fuzz replay %s: %d corpus files, no oracle violation\n", name, files);
    return files == 0 || failed_files ? 1 : 0;
}
