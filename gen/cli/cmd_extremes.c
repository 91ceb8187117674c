/* fresnel extremes: what every model returns in every number type on the
 * extreme and stiff cases (gen/report/extremes.c), as Markdown. */
#include <stdio.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "report/extremes.h"

static void extremes_usage(FILE *out)
{
    fprintf(out,
            "usage: fresnel extremes\n\n"
            "Prints Markdown tables of what every model returns, in every number type\n"
            "the runtime has (binary32, Q15 fixed point, binary16 where the compiler has\n"
            "_Float16), on extreme and stiff inputs, against the double reference of the\n"
            "same model on the same rounded inputs: cosines 0, one LSB of the type, 1e-30,\n"
            "1e-8, 1 - 1e-7, 1, outside [0, 1], NaN and +-Inf; eta -> 0, matched index,\n"
            "eta ~ n1, total internal reflection, eta 100 and 1e4, kappa 0, 1e-6 and 1000,\n"
            "incident media water, glass, diamond; F0 0, 1 and 1.04, F82 far from F0;\n"
            "Gulbrandsen r, g at the ends. tests/runtime/every_type/test_extremes.c asserts the properties.\n");
}

/* "1.2e-07"; bold where the documented bound is exceeded inside the type's
 * domain, a dagger outside it, and a mark for a result that is not a number
 * in [0, 1]. */
int cmd_extremes(int argc, char **argv)
{
    int i;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            extremes_usage(stdout);
            return 0;
        }
        {
            static const char *const options[] = {"--help", NULL};
            return cli_bad_argument("fresnel extremes", argv[i], options);
        }
    }
    extremes_print();
    return 0;
}
