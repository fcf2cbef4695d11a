/*
 * cli_render.c - `refray render`: arrives with the tracer.
 */
#include "cli.h"

int cli_render(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return cli_usage_error("render is not built yet");
}
