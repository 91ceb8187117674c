/* build/fresnel: the project's one command-line program. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "fresnel.h"
#include "spectral.h"

struct command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
};

static const struct command commands[] = {
    {"eval", cmd_eval, "evaluate one model on eta,kappa,cos lines from stdin"},
    {"wavelengths", cmd_wavelengths, "dominant wavelengths of a colour space's primaries"},
    {"materials", cmd_materials, "list the materials in data/ and their measured ranges"},
    {"gen", cmd_gen, "write a scene's C header from its manifest"},
    {"params", cmd_params, "every parameter derived for one material in a colour space"},
    {"curve", cmd_curve, "ground truth and every model over angle for one material (CSV)"},
    {"bench", cmd_bench, "time per evaluation of every model and number type (make bench)"},
    {"report", cmd_report, "accuracy, speed and size of every model and type, with plots"},
    {"extremes", cmd_extremes, "every model and type on extreme inputs against the reference (Markdown)"},
    {"accuracy", cmd_accuracy, "each model's error against exact Fresnel for measured materials"},
};

static void usage(FILE *out)
{
    size_t i;
    fprintf(out, "usage: fresnel COMMAND [options]   (fresnel COMMAND --help for details)\n\n"
                 "Fresnel reflectance: models, reference and code generator, version %s.\n\n"
                 "commands:\n",
            FRESNEL_VERSION);
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(out, "  %-12s %s\n", commands[i].name, commands[i].summary);
    fprintf(out, "\nExit status: 0 success, 2 bad input or usage, 1 other failure.\n");
}

int main(int argc, char **argv)
{
    size_t i;
    data_dir_program(argv[0]);
    if (argc < 2) {
        usage(stderr);
        return CLI_BAD_INPUT;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return 0;
    }
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name))
            return commands[i].run(argc - 1, argv + 1);
    cli_error("fresnel", "unknown command '%s' (try fresnel --help)", argv[1]);
    return CLI_BAD_INPUT;
}
