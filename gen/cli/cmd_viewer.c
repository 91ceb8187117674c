/* fresnel viewer: a scene manifest in, one self-contained HTML page out. */
#include <stdio.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "viewer/viewer.h"

#define WHERE "fresnel viewer"

int cmd_viewer(int argc, char **argv)
{
    const char *manifest = NULL, *out_dir = NULL, *dir_option = NULL, *cross_path = NULL;
    static const char *const options[] = {"-o", "--data", "--cross", "--help", NULL};
    int i;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: fresnel viewer SCENE -o DIR [--cross FILE] [--data DIR]\n\n"
                   "Writes DIR/index.html (-o -: to stdout): one self-contained page (JavaScript,\n"
                   "GLSL and the scene's constants inline; no network access) that renders the\n"
                   "scene's materials as a sphere over a plate, lit by a sky and three lights, with\n"
                   "GGX (Smith G2) or normalised Blinn-Phong, each model of the scene beside (or\n"
                   "split with, or differenced against) the spectral reference; with the model's\n"
                   "CIEDE2000 figures and a plot of its curves. WebGL 2; output in sRGB or, where\n"
                   "the browser has one, a Display-P3 drawing buffer. The models run the GLSL port\n"
                   "(ports/glsl/fresnel.glsl) on the constants `fresnel gen --glsl` emits. `make\n"
                   "viewer` writes the default scene's to build/viewer/. Beside each model: its\n"
                   "CIEDE2000 figures, its time per call on this host and, with --cross FILE (the\n"
                   "output of `make cross-count`), its instructions on the Cortex-M0.\n");
            return 0;
        }
        if (argv[i][0] == '-' && argv[i][1]) {
            const char *v;
            if (!cli_in_list(argv[i], options))
                return cli_bad_argument(WHERE, argv[i], options);
            if (!(v = cli_option_value(WHERE, argc, argv, &i)))
                return CLI_BAD_INPUT;
            if (!strcmp(argv[i - 1], "-o"))
                out_dir = v;
            else if (!strcmp(argv[i - 1], "--cross"))
                cross_path = v;
            else
                dir_option = v;
        } else if (!manifest)
            manifest = argv[i];
        else
            return cli_error(WHERE, "unexpected argument '%s' (one scene manifest)", argv[i]);
    }
    if (!manifest || !out_dir)
        return cli_error(WHERE, "expected a scene manifest and -o DIR (fresnel viewer --help)");
    return viewer_write(manifest, out_dir, dir_option, cross_path);
}
