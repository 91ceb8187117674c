/* Where the spectral data pack lives (see spectral.h). */
#include <stdlib.h>

#include "spectral.h"

#ifndef FRESNEL_DATA_DIR
#define FRESNEL_DATA_DIR "data"
#endif

const char *data_dir(const char *override)
{
    const char *env;
    if (override && *override)
        return override;
    env = getenv("FRESNEL_DATA");
    if (env && *env)
        return env;
    return FRESNEL_DATA_DIR;
}
