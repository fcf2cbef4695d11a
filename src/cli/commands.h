/*
 * commands.h - the commands of the refray program, each called with argv
 * from the command name on and returning a status (base/status.h).
 */
#ifndef REFRAY_COMMANDS_H
#define REFRAY_COMMANDS_H

int cli_check(int argc, char **argv);
int cli_render(int argc, char **argv);
int cli_export(int argc, char **argv);
int cli_verify(int argc, char **argv);
int cli_oracle(int argc, char **argv);
int cli_compare(int argc, char **argv);
int cli_stability(int argc, char **argv);
int cli_kit(int argc, char **argv);
int cli_conform(int argc, char **argv);
int cli_merge(int argc, char **argv);

#endif
