/*
 * api_hidden.c - attack 24h: [SHADE-SHORTCUT-HIDDEN-1] and the cancel
 * callback.  A scene of Kd 0 glass and mirrors under two disk lights (16
 * and 9 samples) and a point light, where the shortcut leaves many light
 * loops out, is rendered through rf_render_region_double with a cancel
 * callback that counts its calls: once never stopping (the number of polls
 * printed), then stopping at its k-th call for every k from 1 to that
 * number: each line prints k, the status and an FNV-1a hash of the pixels
 * written before the stop (the buffer zeroed first).  Built against this
 * tree's library and against the base's (api_hidden.sh), the two outputs
 * must be the same line for line: the same polls, each stop landing where
 * it landed before.  Build:
 *   cc -std=c99 -O2 -Iinclude -o /tmp/api_hidden tests/attack24h/api_hidden.c \
 *      build/librefray-internal.a -ljansson -lm
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>
#include "../fnv_doubles.h"

static const char scene_text[] =
    "image { width 24 height 18 samples 1 max_depth 4 background [0.2, 0.3, 0.5] }\n"
    "camera { perspective eye [0, 2, 5] look_at [0, 0.5, 0] up [0, 1, 0] fov 55 }\n"
    "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0 Ks 0.9 n 1000 } }\n"
    "sphere { center [-0.8, 0.6, 0] radius 0.6 material { Kd 0 Ks 0.5 n 200 t 0.9 ior 1.5 } }\n"
    "sphere { center [0.9, 0.5, 0.3] radius 0.5 material { Kd 0 Ks 1 n 1e5 } }\n"
    "sphere { center [0, 0.3, 1.2] radius 0.3 material { Kd 0.6 Ks 0.2 n 10 } }\n"
    "distributed_light { disk [0, 3, 0] [0, -1, 0] 0.5 power 20 samples 16 }\n"
    "distributed_light { disk [2, 2, 2] [-1, -1, -1] 0.3 power 10 samples 9 }\n"
    "point_light { position [-2, 3, 1] power 5 }\n";

static long calls, stop_at;
static int cancel_cb(void *user)
{
    (void)user;
    calls++;
    return stop_at > 0 && calls >= stop_at;
}

/* Pixels with some channel not 0 (written before the stop). */
static int written(const double *p, int n)
{
    int w = 0;
    for (int i = 0; i < n; i++)
        w += p[3 * i] != 0 || p[3 * i + 1] != 0 || p[3 * i + 2] != 0;
    return w;
}

int main(void)
{
    enum { W = 24, H = 18 };
    static double px[W * H * 3];
    rf_load_options lo;
    rf_load_options_init(&lo);
    rf_scene *scene = NULL;
    if (rf_scene_load_memory("api_hidden.scene", scene_text, sizeof scene_text - 1, &lo, &scene) != RF_OK) {
        printf("FAIL: load\n");
        return 1;
    }
    rf_render_options o;
    rf_render_options_init(&o);
    o.cancel = cancel_cb;
    rf_renderer *r = NULL;
    if (rf_renderer_create(scene, &o, &r) != RF_OK) {
        printf("FAIL: renderer\n");
        return 1;
    }
    calls = 0;
    stop_at = 0;
    rf_status st = rf_render_region_double(r, 0, 0, W, H, px, 3 * W);
    long total = calls;
    rf_render_stats s;
    rf_renderer_stats(r, &s);
    printf("whole: status %d pixels %016llx polls %ld light_samples %ld on_surface %ld\n", (int)st,
           fnv(px, W * H * 3), total, s.light_samples, s.light_samples_on_surface);
    for (long k = 1; k <= total + 1; k++) {
        calls = 0;
        stop_at = k;
        memset(px, 0, sizeof px);
        st = rf_render_region_double(r, 0, 0, W, H, px, 3 * W);
        /* The bytes of a stopped region are not specified (spec/embedding.md):
         * on stderr, not compared; the polls and the pixels written are. */
        printf("stop at poll %ld: status %d written %d\n", k, (int)st, written(px, W * H));
        fprintf(stderr, "stop at poll %ld: pixels %016llx\n", k, fnv(px, W * H * 3));
    }
    rf_renderer_free(r);
    rf_scene_free(scene);
    return 0;
}
