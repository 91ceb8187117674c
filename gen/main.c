/* build/fresnel: the project's one command-line program. */
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "cli/commands.h"
#include "common/cli.h"
#include "fresnel.h"
#include "1_spectral/spectral.h"

struct command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
};

static const struct command commands[] = {
    {"eval", cmd_eval, "evaluate one model on eta,kappa,cos lines from stdin"},
    {"wavelengths", cmd_wavelengths, "dominant wavelengths of a colour space's primaries"},
    {"materials", cmd_materials, "list the materials in data/ and their measured ranges"},
    {"import", cmd_import, "convert your own n,k file (refractiveindex.info, SOPRA, .spd) to the data pack's CSV"},
    {"gen", cmd_gen, "write a scene's constants and tables as a C, GLSL or HLSL header"},
    {"params", cmd_params, "every parameter derived for one material in a colour space"},
    {"curve", cmd_curve, "ground truth and every model over angle for one material (CSV)"},
    {"bench", cmd_bench, "time per evaluation of every model and number type (make bench)"},
    {"viewer", cmd_viewer, "a scene as one HTML page that renders every model beside the spectral reference"},
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
    fprintf(out, "  %-12s %s\n", "version", "print the version (also --version)");
    fprintf(out, "\nOptions naming an output file take '-' for stdout. Exit status: 0 success,\n"
                 "1 a read or write failure, 2 bad input or usage, 3 out of memory.\n");
}

int main(int argc, char **argv)
{
    const char *names[sizeof commands / sizeof commands[0] + 2];
    char where[64];
    size_t i;
    int status;
    data_dir_program(argv[0]);
    if (argc < 2) {
        usage(stderr);
        return CLI_BAD_INPUT;
    }
    /* A file size limit (ulimit -f) then fails the write with EFBIG, which
     * the output code reports and cleans up after, instead of killing the
     * process with a partial temporary left behind. */
    signal(SIGXFSZ, SIG_IGN);
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return cli_finish_stdout("fresnel");
    }
    if (!strcmp(argv[1], "--version") || !strcmp(argv[1], "version")) {
        if (argc == 3 && (!strcmp(argv[2], "--help") || !strcmp(argv[2], "-h"))) {
            printf("usage: fresnel version   (or fresnel --version)\n\n"
                   "Prints \"fresnel X.Y.Z\": the version of the tool and of the runtime it was\n"
                   "built with (FRESNEL_VERSION in include/fresnel.h).\n");
            return cli_finish_stdout("fresnel version");
        }
        if (argc > 2)
            return cli_error("fresnel version", "unexpected argument '%s'", argv[2]);
        printf("fresnel %s\n", FRESNEL_VERSION);
        return cli_finish_stdout("fresnel version");
    }
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name)) {
            status = commands[i].run(argc - 1, argv + 1);
            snprintf(where, sizeof where, "fresnel %s", commands[i].name);
            if (cli_finish_stdout(where) && status == 0)
                status = CLI_FAILURE;
            return cli_exit_status(status);
        }
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        names[i] = commands[i].name;
    names[i++] = "version";
    names[i] = NULL;
    if (cli_looks_like_option(argv[1]) || !cli_suggest(argv[1], names))
        return cli_error("fresnel", "unknown command '%s' (try fresnel --help)", argv[1]);
    return cli_unknown("fresnel", "command", argv[1], names);
}
