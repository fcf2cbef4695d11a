/*
 * api_dark.c - attack 22: [SHADE-SHORTCUT-DARK-2] through the public API.
 * A scene with two disk lights whose cells are partly dark (one standing
 * across the floor, one tilted over Kd = 0 spheres of n 1 and 1e6) is
 * rendered: whole (rf_render_image); on one renderer twice in a row; after
 * a render cancelled midway (the cancel callback says stop at its 3rd
 * call) on the same renderer; as 12 regions in reverse order; with
 * light_samples 4096 and 7; each with no_shortcuts too.  Exit 1 when a
 * render that must give the same pixels does not; prints, for the default
 * and the light_samples 4096 and 7 renders, an FNV-1a hash of the doubles
 * and the counted results (shadow rays, light samples, on-surface
 * samples), so that a build against another library (the old main's) can
 * be compared line by line (api_dark.sh).  Build:
 *   cc -std=c99 -O2 -Iinclude -o /tmp/api_dark tests/attack22/api_dark.c \
 *      build/librefray-internal.a -ljansson -lm
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>
#include "../fnv_doubles.h"

static const char scene_text[] =
    "image { width 40 height 30 samples 1 max_depth 3 background [0.1, 0.1, 0.1] }\n"
    "camera { perspective eye [0, 3, 6] look_at [0, 0.3, 0] up [0, 1, 0] fov 60 }\n"
    "ambient { color 0.02 }\n"
    "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.8 } }\n"
    "sphere { center [-1.2, 0.5, 0] radius 0.5 material { Kd 0 Ks 0.9 n 1000000 } }\n"
    "sphere { center [1.2, 0.5, 0] radius 0.5 material { Kd 0 Ks 0.7 n 1 } }\n"
    "sphere { center [0, 0.4, 1.2] radius 0.4 material { Kd 0.5 Ks 0.3 n 5 } }\n"
    "box { from [-0.4, 0, -1.6] to [0.4, 0.8, -0.8] material { Kd 0 Ks 0.8 n 30 } }\n"
    "distributed_light { disk [2.2, 0.3, -0.5] [1, 0, 0] 1 power 40 samples 64 }\n"
    "distributed_light { disk [-1.5, 2.5, 1] [1, -1, 0.3] 1 power 40 samples 36 }\n";

static long calls, stop_at;
static int cancel_cb(void *user)
{
    (void)user;
    return stop_at > 0 && ++calls >= stop_at;
}

static int fails;
static void expect(int ok, const char *what)
{
    if (!ok) {
        printf("FAIL: %s\n", what);
        fails = 1;
    }
}

/* The whole image on renderer r into px (w * h * 3 doubles), as `tiles`
 * bands from the bottom up (1: one region). */
static rf_status whole(rf_renderer *r, double *px, int w, int h, int tiles)
{
    for (int k = tiles - 1; k >= 0; k--) {
        int y0 = k * h / tiles, y1 = (k + 1) * h / tiles;
        if (y1 <= y0)
            continue;
        rf_status st = rf_render_region_double(r, 0, y0, w, y1, px + (size_t)y0 * 3 * w, 3 * (size_t)w);
        if (st != RF_OK)
            return st;
    }
    return RF_OK;
}

static void run(const rf_scene *scene, int light_samples, int w, int h)
{
    size_t n = (size_t)w * h * 3;
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    rf_render_options o;
    rf_render_options_init(&o);
    o.light_samples = light_samples;
    o.cancel = cancel_cb;
    rf_renderer *r = NULL;
    stop_at = 0;
    if (!a || !b || rf_renderer_create(scene, &o, &r) != RF_OK) {
        printf("FAIL: renderer (light_samples %d)\n", light_samples);
        exit(1);
    }
    expect(whole(r, a, w, h, 1) == RF_OK, "first render");
    rf_render_stats s;
    rf_renderer_stats(r, &s);
    /* No shadow rays since the twenty-first round: [SHADE-SHORTCUT-ABSORB-1]
     * sends fewer of them by design. */
    printf("light_samples %d: pixels %016llx light_samples %ld on_surface %ld nonfinite %ld\n", light_samples,
           fnv(a, n), s.light_samples, s.light_samples_on_surface, s.nonfinite);
    expect(whole(r, b, w, h, 1) == RF_OK && memcmp(a, b, n * sizeof *a) == 0, "second render on one renderer");
    /* where a stop lands: the pixels written before it, on stderr, not
     * compared with the old library's: since attack 24 the camera beams'
     * tiles make the rows below first, so other pixels are written before
     * the same poll (the API promises none: a stopped region is partly
     * written); the render after the stops is compared below */
    for (long at = 3; at <= 3000; at *= 10) {
        calls = 0;
        stop_at = at;
        memset(b, 0, n * sizeof *b);
        rf_status st = whole(r, b, w, h, 1);
        fprintf(stderr, "  a stop at poll %ld: status %d, pixels %016llx\n", at, (int)st, fnv(b, n));
    }
    stop_at = 0;
    memset(b, 0, n * sizeof *b);
    expect(whole(r, b, w, h, 1) == RF_OK && memcmp(a, b, n * sizeof *a) == 0, "render after a cancel");
    memset(b, 0, n * sizeof *b);
    expect(whole(r, b, w, h, 12) == RF_OK && memcmp(a, b, n * sizeof *a) == 0, "12 bands in reverse order");
    rf_renderer_free(r);
    o.no_shortcuts = 1;
    r = NULL;
    expect(rf_renderer_create(scene, &o, &r) == RF_OK, "no_shortcuts renderer");
    memset(b, 0, n * sizeof *b);
    expect(r && whole(r, b, w, h, 1) == RF_OK && memcmp(a, b, n * sizeof *a) == 0, "no_shortcuts: the same pixels");
    rf_renderer_free(r);
    rf_image *img = NULL;
    o.no_shortcuts = 0;
    o.cancel = NULL;
    expect(rf_render_image(scene, &o, &img, NULL) == RF_OK && memcmp(rf_image_pixels(img), a, n * sizeof *a) == 0,
           "rf_render_image: the same pixels");
    rf_image_free(img);
    free(a);
    free(b);
}

int main(void)
{
    rf_load_options lo;
    rf_load_options_init(&lo);
    rf_scene *scene = NULL;
    if (rf_scene_load_memory("api_dark.scene", scene_text, sizeof scene_text - 1, &lo, &scene) != RF_OK) {
        printf("FAIL: load\n");
        return 1;
    }
    run(scene, 0, 40, 30);
    run(scene, 4096, 40, 30);
    run(scene, 7, 40, 30);
    rf_scene_free(scene);
    return fails;
}
