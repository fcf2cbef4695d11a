/*
 * main.c - the refray program: everything is in the driver (cli.c).
 */
#include <stdlib.h>
#include "cli/cli.h"

int main(int argc, char **argv)
{
    exit(cli_main(argc, argv));
}
