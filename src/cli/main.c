/*
 * main.c - the refray program: everything is in the driver (cli.c).
 */
#include <stdlib.h>
#include "cli/cli.h"
#include "cli/cli_signal.h"

int main(int argc, char **argv)
{
    /* The one place a status becomes an exit code (128 + the signal for
     * a command a signal stopped). */
    exit(cli_signal_exit_code(cli_main(argc, argv)));
}
