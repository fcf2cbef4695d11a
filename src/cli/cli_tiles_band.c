/*
 * cli_tiles_band.c - see cli_tiles_band.h.
 */
#include "cli/cli_tiles_band.h"

int cli_tiles_band_count(int rows, int jobs)
{
    long n = 4L * jobs;
    if (n < 64)
        n = 64;
    return n > rows ? rows : (int)n;
}

tile_rect cli_tiles_band(const cli_tiles *t, int b)
{
    tile_rect r = t->target.region;
    tile_band(t->target.region.y0, t->target.region.y1, t->bands, b, &r.y0, &r.y1);
    return r;
}
