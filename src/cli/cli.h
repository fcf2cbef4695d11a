/*
 * cli.h - the refray program: command dispatch, help and version.
 */
#ifndef REFRAY_CLI_H
#define REFRAY_CLI_H

/* Runs the command argv[1] and returns its status (base/status.h), which
 * main turns into the exit code. */
int cli_main(int argc, char **argv);

#endif
