/* The back ends of `fresnel gen`, one row each (emit.h): the option that
 * chooses it, and the function that prints an encoded scene in it. A new
 * back end is its printer and one row here. */
#include <string.h>

#include "4_emit/emit.h"
#include "4_emit/emit_glsl.h"

static int print_c(FILE *f, FILE *tex, const emit_input *in)
{
    (void)tex;
    return emit_header(f, in);
}

static int print_hlsl(FILE *f, FILE *tex, const emit_input *in)
{
    (void)tex;
    return emit_hlsl(f, in);
}

const emit_backend emit_backends[] = {
    {NULL, 0, 0, print_c},
    {"--glsl", 1, 1, emit_glsl},
    {"--hlsl", 1, 0, print_hlsl},
};
const int emit_backend_count = (int)(sizeof emit_backends / sizeof emit_backends[0]);

const emit_backend *emit_backend_find(const char *option)
{
    int i;
    for (i = 0; i < emit_backend_count; i++)
        if (option ? emit_backends[i].option && !strcmp(option, emit_backends[i].option) : !emit_backends[i].option)
            return &emit_backends[i];
    return NULL;
}
