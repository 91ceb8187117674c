/* The subcommands of build/fresnel (main.c's table), one file each in
 * gen/cli/. */
#ifndef FRESNEL_COMMANDS_H
#define FRESNEL_COMMANDS_H

/* Subcommands: argv[0] is the subcommand name. Return the exit status. */
int cmd_eval(int argc, char **argv);
int cmd_wavelengths(int argc, char **argv);
int cmd_materials(int argc, char **argv);
int cmd_accuracy(int argc, char **argv);
int cmd_params(int argc, char **argv);
int cmd_gen(int argc, char **argv);
int cmd_report(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_curve(int argc, char **argv);
int cmd_extremes(int argc, char **argv);
int cmd_import(int argc, char **argv);
int cmd_viewer(int argc, char **argv);

#endif
