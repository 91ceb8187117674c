/* Where the spectral data pack lives (see spectral.h). In order:
 *   1. --data DIR;
 *   2. $FRESNEL_DATA;
 *   3. the installed pack, BINDIR/../share/fresnel/data, where BINDIR is the
 *      directory of the running program (/proc/self/exe, else argv[0] when
 *      it names a path); used when it holds materials.csv, so `make install`
 *      gives a tool that needs no --data wherever PREFIX is;
 *   4. the source tree's data/ the tool was built from (FRESNEL_DATA_DIR). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "1_spectral/spectral.h"

#ifndef FRESNEL_DATA_DIR
#define FRESNEL_DATA_DIR "data"
#endif

#define INSTALLED_DATA "/../share/fresnel/data"

/* The host tool is single-threaded; these are set once, at start-up. */
static const char *program_path;
static char installed[4096];

void data_dir_program(const char *argv0)
{
    program_path = argv0;
}

/* DIR/../share/fresnel/data for the program's DIR, or NULL if it has no
 * materials.csv. */
static const char *installed_dir(void)
{
    char exe[4096], probe[sizeof installed + 16];
    char *slash;
    struct stat st;
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0)
        exe[n] = '\0';
    else if (program_path && strchr(program_path, '/') && strlen(program_path) < sizeof exe)
        strcpy(exe, program_path);
    else
        return NULL;
    if (!(slash = strrchr(exe, '/')))
        return NULL;
    *slash = '\0';
    n = snprintf(installed, sizeof installed, "%s%s", exe, INSTALLED_DATA);
    if (n < 0 || (size_t)n >= sizeof installed)
        return NULL;
    n = snprintf(probe, sizeof probe, "%s/materials.csv", installed);
    if (n < 0 || (size_t)n >= sizeof probe)
        return NULL;
    return stat(probe, &st) == 0 && S_ISREG(st.st_mode) ? installed : NULL;
}

const char *data_dir(const char *override)
{
    const char *env, *inst;
    if (override && *override)
        return override;
    env = getenv("FRESNEL_DATA");
    if (env && *env)
        return env;
    if ((inst = installed_dir()))
        return inst;
    return FRESNEL_DATA_DIR;
}
