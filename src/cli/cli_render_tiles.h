/*
 * cli_render_tiles.h - refray render with --region, --tile, --jobs or
 * --checkpoint (cli_render_tiles.c).
 */
#ifndef REFRAY_CLI_RENDER_TILES_H
#define REFRAY_CLI_RENDER_TILES_H

#include "cli/cli_render_out.h"

/* The render of a region, tile, on workers, with a checkpoint. */
int cli_render_tiles(const render_args *a, const rf_scene *scene);

#endif
