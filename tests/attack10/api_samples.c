/*
 * api_samples.c - rf_render_options.samples and .light_samples are not held
 * to the limits the scene was loaded with (max_samples 64, max_light_samples
 * 4096 by default), where the width and height are ([EMBED-API-11]) and
 * where the refray program holds --samples and --light-samples ("--samples
 * 65 is over the limit of 64", exit 64).  samples INT_MAX is accepted:
 * 2^62 camera rays a pixel, unbounded work from a renderer a host thought
 * the scene's limits bounded.  Expected: RF_ERR_USAGE, as for a size.
 * Build (repository root, after make build/lib/librefray.a):
 *   cc -std=c99 -g -Iinclude tests/attack10/api_samples.c build/lib/librefray.a \
 *      $(pkg-config --libs jansson libpng) -lOpenEXRCore -lm -lpthread -o /tmp/api_samples
 * Run: /tmp/api_samples   # one line a case; exit 1 when any is accepted
 */
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include "refray.h"

static const char scene[] = "image { width 1 height 1 }\n"
                            "camera { eye [0, 0, 5] look_at [0, 0, 0] fov 40 }\n"
                            "ambient { color 0.5 }\n"
                            "distributed_light { disk [0, 3, 0] [0, -1, 0] 1  power 10  samples 16 }\n"
                            "sphere { center [0, 0, 0] radius 1 material { Kd 0.5 } }\n";

int main(void)
{
    rf_scene *s = NULL;
    if (rf_scene_load_memory("s.scene", scene, strlen(scene), NULL, &s) != RF_OK)
        return 2;
    int accepted = 0;
    const int samples[] = {65, INT_MAX}, light[] = {4097, INT_MAX};
    for (int k = 0; k < 4; k++) {
        rf_render_options o;
        rf_render_options_init(&o);
        if (k < 2)
            o.samples = samples[k];
        else
            o.light_samples = light[k - 2];
        rf_renderer *r = NULL;
        rf_status st = rf_renderer_create(s, &o, &r);
        printf("%s %d: rf_renderer_create %s\n", k < 2 ? "samples" : "light_samples", k < 2 ? samples[k] : light[k - 2],
               st == RF_OK ? "RF_OK (accepted)" : st == RF_ERR_USAGE ? "RF_ERR_USAGE" : "other");
        accepted += st == RF_OK;
        rf_renderer_free(r);
    }
    rf_scene_free(s);
    return accepted ? 1 : 0;
}
