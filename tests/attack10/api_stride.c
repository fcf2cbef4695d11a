/*
 * api_stride.c - rf_render_region's stride check (api_render.c: "a stride
 * so large that this wraps around would write before pixels") counts
 * floats, but the address wraps in bytes: row_stride SIZE_MAX / 2 floats
 * puts row 1 at pixels + (2^65 - 4) bytes, that is 4 bytes BEFORE pixels.
 * The call returns RF_OK and writes pixels[-1].  Expected: RF_ERR_USAGE
 * (refray.h: "RF_ERR_USAGE for a region outside the image, empty, or a
 * short stride"; the comment's own intent), nothing written.
 * Build (repository root, after make build/lib/librefray.a):
 *   cc -std=c99 -g -Iinclude tests/attack10/api_stride.c build/lib/librefray.a \
 *      $(pkg-config --libs jansson libpng) -lOpenEXRCore -lm -lpthread -o /tmp/api_stride
 * Run: /tmp/api_stride   # prints the status and whether the guard before the buffer changed
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "refray.h"

static const char scene[] = "image { width 4 height 2 }\n"
                            "camera { eye [0, 0, 5] look_at [0, 0, 0] fov 40 }\n"
                            "ambient { color 0.5 }\n"
                            "sphere { center [0, 0, 0] radius 1 material { Kd 0.5 } }\n";

int main(void)
{
    rf_scene *s = NULL;
    rf_renderer *r = NULL;
    if (rf_scene_load_memory("s.scene", scene, strlen(scene), NULL, &s) != RF_OK ||
        rf_renderer_create(s, NULL, &r) != RF_OK)
        return 2;
    float *block = malloc(64 * sizeof *block);
    if (!block)
        return 2;
    for (int k = 0; k < 64; k++)
        block[k] = -7;
    float *pixels = block + 16; /* 48 floats: room for 4 x 2 pixels at any sane stride */
    rf_status st = rf_render_region(r, 0, 0, 4, 2, pixels, SIZE_MAX / 2);
    int before = 0;
    for (int k = 0; k < 16; k++)
        before += block[k] != -7;
    printf("status %d (RF_OK is %d); floats changed before the buffer: %d (pixels[-1] = %g)\n", (int)st, (int)RF_OK,
           before, pixels[-1]);
    double *dblock = malloc(64 * sizeof *dblock);
    if (!dblock)
        return 2;
    for (int k = 0; k < 64; k++)
        dblock[k] = -7;
    rf_status dst = rf_render_region_double(r, 0, 0, 4, 2, dblock + 16, SIZE_MAX / 2);
    int dbefore = 0;
    for (int k = 0; k < 16; k++)
        dbefore += dblock[k] != -7;
    printf("double: status %d; doubles changed before the buffer: %d\n", (int)dst, dbefore);
    free(dblock);
    before += dbefore;
    st = st == RF_OK ? st : dst;
    free(block);
    rf_renderer_free(r);
    rf_scene_free(s);
    return st == RF_OK || before ? 1 : 0;
}
