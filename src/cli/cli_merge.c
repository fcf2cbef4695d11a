/*
 * cli_merge.c - `refray merge TILE... -o OUT`: tiles rendered apart
 * (render --tile, --region; on other processes or machines) put back
 * together into one image, written atomically (spec/scaling.md,
 * [SCALE-MERGE-1..4]).  Every tile's header is read and checked before a
 * pixel is: one render (the same key and image size), no two tiles
 * sharing a pixel, no pixel without a tile.  The tiles carry exact
 * doubles, so OUT has the bytes a render in one piece writes with the same
 * image options.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "api/convert.h"
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"
#include "io/tile_file.h"

static const char merge_help[] =
    "usage: refray merge TILE... -o OUT [OPTIONS]\n"
    "Puts the tiles of one render (refray render --tile or --region, .exr or .pfm\n"
    "with its .pfm.tile sidecar) back together and writes OUT atomically, with the\n"
    "bytes a render in one piece writes; the format follows OUT's extension.\n"
    "The tiles must come from the same scene and settings (their key) and image\n"
    "size, and cover every pixel once: a gap or an overlap is an error naming it.\n"
    "options:\n"
    "  -o, --output OUT      the image (.png .exr .pfm .ppm)\n"
    "  --exr-float, --bit-depth 8|16, --linear, --exposure STOPS, --tone clamp|reinhard\n"
    "                        as for refray render\n"
    "  --max-pixels N        refuse tiles of an image of more pixels (67108864),\n"
    "                        before anything is allocated for them\n"
    "  -q, --quiet           (accepted; merge prints nothing on success)\n"
    "exit: 0 written; 64 usage; 65 tiles that are not one render's or do not cover\n"
    "the image exactly once, or a file that is not a tile; 66 a missing tile;\n"
    "74 OUT could not be written; 130, 143, 129 interrupted by SIGINT, SIGTERM, SIGHUP.\n";

typedef struct merge_args {
    const char **tiles;
    int count;
    const char *output;
    rf_write_options image;
    img_read_opts read;   /* --max-pixels: what a tile's image size may be */
} merge_args;

/* 0: go on; -1: help printed; else the usage exit code. */
static int parse_args(merge_args *a, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        const char *opt = argv[i];
        if (strcmp(opt, "--help") == 0 || strcmp(opt, "-h") == 0) {
            fputs(merge_help, stdout);
            return -1;
        }
        if (opt[0] != '-' || !opt[1]) {
            a->tiles[a->count++] = opt;
            continue;
        }
        int r = strcmp(opt, "-q") == 0 || strcmp(opt, "--quiet") == 0 ? 1 : cli_image_option(&a->image, argc, argv, &i);
        if (r < 0 && (strcmp(opt, "-o") == 0 || strcmp(opt, "--output") == 0))
            r = cli_take_value(argc, argv, &i, &a->output);
        if (r < 0 && strcmp(opt, "--max-pixels") == 0) {
            const char *v;
            r = cli_take_value(argc, argv, &i, &v) && cli_parse_long(opt, v, 1, 1000000000, &a->read.max_pixels);
        }
        if (r == 0)
            return STATUS_USAGE;
        if (r < 0)
            return cli_usage_error("merge: unknown option '%s'", opt);
    }
    if (a->count == 0)
        return cli_usage_error("merge: no tiles given");
    if (!a->output)
        return cli_usage_error("merge: no output given (-o OUT)");
    if (strcmp(a->output, "-") == 0)
        return cli_usage_error("merge: OUT is a file (written atomically), not standard output");
    return 0;
}

/* The first tile that is not of the same render as tile 0. */
static int check_one_render(const merge_args *a, const tile_info *t)
{
    char k0[17], ki[17];
    for (int i = 1; i < a->count; i++) {
        if (t[i].width != t[0].width || t[i].height != t[0].height) {
            cli_error("'%s' is a tile of a %dx%d image, '%s' of a %dx%d one; nothing written",
                    a->tiles[i], t[i].width, t[i].height, a->tiles[0], t[0].width, t[0].height);
            return STATUS_DATA;
        }
        if (t[i].key != t[0].key) {
            tile_key_text(t[i].key, ki);
            tile_key_text(t[0].key, k0);
            cli_error("'%s' comes from another render than '%s' (key %s, not %s): another "
                    "scene, or other samples, max-depth or light samples; nothing written", a->tiles[i],
                    a->tiles[0], ki, k0);
            return STATUS_DATA;
        }
    }
    return STATUS_OK;
}

/* Every pixel covered exactly once: no overlap of two tiles, then no gap. */
static int check_cover(const merge_args *a, const tile_info *t, tile_rect *regions)
{
    char r1[64], r2[64], r3[64];
    tile_rect both, gap;
    long area = 0;
    for (int i = 0; i < a->count; i++) {
        regions[i] = t[i].region;
        area += tile_area(&t[i].region);
    }
    for (int i = 0; i < a->count; i++)
        for (int j = i + 1; j < a->count; j++)
            if (tile_overlap(&regions[i], &regions[j], &both)) {
                cli_error("the tiles '%s' (%s) and '%s' (%s) overlap in %s; nothing written",
                        a->tiles[i], tile_rect_text(&regions[i], r1, sizeof r1), a->tiles[j],
                        tile_rect_text(&regions[j], r2, sizeof r2), tile_rect_text(&both, r3, sizeof r3));
                return STATUS_DATA;
            }
    if (tile_find_gap(regions, a->count, t[0].width, t[0].height, &gap)) {
        cli_error("no tile covers %s (%ld of the %dx%d image's pixels have no tile); "
                "nothing written", tile_rect_text(&gap, r1, sizeof r1), (long)t[0].width * t[0].height - area,
                t[0].width, t[0].height);
        return STATUS_DATA;
    }
    return STATUS_OK;
}

/* Reads every header, then checks them together. */
static int check_tiles(const merge_args *a, tile_info *t, tile_rect *regions)
{
    char why[700];
    for (int i = 0; i < a->count; i++) {
        int status = tile_file_read(a->tiles[i], &a->read, &t[i], NULL, why, sizeof why);
        if (status != STATUS_OK) {
            cli_error("%s; nothing written", why);
            return status;
        }
    }
    int status = check_one_render(a, t);
    return status == STATUS_OK ? check_cover(a, t, regions) : status;
}

/* Copies the pixels of every tile into img. */
static int gather(const merge_args *a, const tile_info *t, img_buf *img)
{
    char why[700];
    for (int i = 0; i < a->count; i++) {
        img_buf px;
        tile_info again;
        if (cli_signal_cancel(NULL))
            return STATUS_CANCELLED;
        int status = tile_file_read(a->tiles[i], &a->read, &again, &px, why, sizeof why);
        if (status == STATUS_OK && !tile_info_equal(&again, &t[i])) {
            snprintf(why, sizeof why, "'%s' changed while it was merged", a->tiles[i]);
            img_free(&px);
            status = STATUS_DATA;
        }
        if (status != STATUS_OK) {
            cli_error("%s; nothing written", why);
            return status;
        }
        const tile_rect *r = &t[i].region;
        for (int y = r->y0; y < r->y1; y++)
            memcpy(img_pixel(img, r->x0, y), img_pixel(&px, 0, y - r->y0), 3 * (size_t)px.width * sizeof(double));
        img_free(&px);
    }
    return STATUS_OK;
}

static int merge(const merge_args *a, tile_info *t, tile_rect *regions)
{
    rf_image *img = NULL;
    char err[700];
    int status = check_tiles(a, t, regions);
    if (status == STATUS_OK && (status = (int)rf_image_create(t[0].width, t[0].height, NULL, &img)) != STATUS_OK)
        fputs("refray: error: out of memory; nothing written\n", stderr);
    if (status == STATUS_OK)
        status = gather(a, t, &img->buf);
    if (status == STATUS_OK && cli_signal_cancel(NULL))
        status = STATUS_CANCELLED;
    if (status == STATUS_OK && (status = (int)rf_image_write(img, a->output, &a->image, NULL, err, sizeof err)) != 0 &&
        status != STATUS_CANCELLED)
        cli_error("%s", err);
    if (status == STATUS_CANCELLED)
        fputs("refray: interrupted; nothing written\n", stderr);
    rf_image_free(img);
    return status;
}

int cli_merge(int argc, char **argv)
{
    merge_args a;
    memset(&a, 0, sizeof a);
    rf_write_options_init(&a.image);
    a.image.cancel = cli_signal_cancel;
    a.read = img_read_opts_default();
    a.tiles = malloc((size_t)(argc > 0 ? argc : 1) * sizeof *a.tiles);
    tile_info *t = malloc((size_t)(argc > 0 ? argc : 1) * sizeof *t);
    tile_rect *regions = malloc((size_t)(argc > 0 ? argc : 1) * sizeof *regions);
    int status = a.tiles && t && regions ? parse_args(&a, argc, argv) : STATUS_NO_MEMORY;
    if (status == STATUS_NO_MEMORY)
        fputs("refray: error: out of memory\n", stderr);
    else if (status < 0)
        status = STATUS_OK;
    else if (status == 0 && (status = cli_check_output_file("merge", a.output)) == 0) {
        cli_signal_cooperate(1);
        status = merge(&a, t, regions);
    }
    free(regions);
    free(t);
    free(a.tiles);
    return status;
}
