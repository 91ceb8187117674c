/* fresnel report: accuracy, speed and size of every model x number type for
 * the materials of a scene, as report.md plus SVG plots. */
#include <stdio.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "cli/material_options.h"
#include "report/report.h"

#define WHERE "fresnel report"

static void report_usage(FILE *out)
{
    fprintf(out, "usage: fresnel report [--scene FILE] [-o DIR] [--data DIR] [--cross FILE] [--size FILE]\n"
                 "                      [--spirv FILE] [--speed FILE]... [--gamut map|clip|keep] [--no-timing]\n"
                 "                      [--no-instructions]\n\n"
                 "Measures every material x model x number type of the scene (default\n"
                 "data/scenes/report.scene) against the spectral ground truth and writes\n"
                 "DIR/report.md, DIR/pareto.svg, DIR/sigma.svg and DIR/curves/<material>.svg\n"
                 "(default DIR build/report), and for the developers DIR/targets.md: the\n"
                 "project's goals, each with the value measured and a pass/MISS mark.\n"
                 "Timing: median of 5 batches of 2^20 evaluations; instructions: valgrind\n"
                 "--tool=callgrind (skipped when valgrind is missing). --no-timing and\n"
                 "--no-instructions skip those (for tests). --cross FILE and --size FILE:\n"
                 "the output of `make cross-count` and of `make size`, for the report's\n"
                 "instruction-count and code-size sections and the Cortex-M0 rows of\n"
                 "targets.md (make report passes both). --spirv FILE: the output of\n"
                 "`make spirv-count`, for the report's GPU instruction-count section.\n"
                 "--speed FILE (up to 4): the output\n"
                 "of `make bench` at one flag set, for the report's host speed section and\n"
                 "the speed rows of targets.md (make report passes -O2 and -O3\n"
                 "-march=native). --gamut overrides the scene's gamut policy.\n");
}

int cmd_report(int argc, char **argv)
{
    report_options o;
    static const char *const options[] = {"--scene", "-o", "--cross", "--size", "--spirv", "--speed", "--data", "--gamut",
                                          "--no-timing", "--no-instructions", "--help", NULL};
    int i;
    memset(&o, 0, sizeof o);
    o.scene_path = "data/scenes/report.scene";
    o.out_dir = "build/report";
    o.timing = o.instructions = 1;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            report_usage(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--no-timing")) {
            o.timing = 0;
        } else if (!strcmp(argv[i], "--no-instructions")) {
            o.instructions = 0;
        } else if (!cli_in_list(argv[i], options)) {
            return cli_bad_argument(WHERE, argv[i], options);
        } else {
            const char *v = cli_option_value(WHERE, argc, argv, &i);
            if (!v)
                return CLI_BAD_INPUT;
            if (!strcmp(argv[i - 1], "--scene"))
                o.scene_path = v;
            else if (!strcmp(argv[i - 1], "-o"))
                o.out_dir = v;
            else if (!strcmp(argv[i - 1], "--cross"))
                o.cross_path = v;
            else if (!strcmp(argv[i - 1], "--size"))
                o.size_path = v;
            else if (!strcmp(argv[i - 1], "--spirv"))
                o.spirv_path = v;
            else if (!strcmp(argv[i - 1], "--speed")) {
                if (o.speed_count == REPORT_MAX_SPEED)
                    return cli_error(WHERE, "--speed: at most %d files", REPORT_MAX_SPEED);
                o.speed_paths[o.speed_count++] = v;
            }
            else if (!strcmp(argv[i - 1], "--gamut")) {
                if (gamut_option(WHERE, v, &o.gamut))
                    return CLI_BAD_INPUT;
                o.gamut_given = 1;
            }
            else
                o.data_dir = v;
        }
    }
    if (!strcmp(o.out_dir, "-"))
        return cli_error(WHERE, "-o -: the report is several files (report.md and its plots); expected a directory");
    return report_write(&o);
}
