/*
 * main.c - the refray program: everything is in the driver (cli.c).
 */
#include <stdlib.h>
#include "base/status.h"
#include "cli/cli.h"

int main(int argc, char **argv)
{
    /* The one place a status becomes an exit code. */
    exit(status_exit_code(cli_main(argc, argv)));
}
