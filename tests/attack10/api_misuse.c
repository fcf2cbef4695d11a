/*
 * api_misuse.c - calls the public API with arguments a careless host may
 * pass; each call must return a status (never crash, never write past a
 * buffer, never leak: run under valgrind).  Prints one line a case.
 * Build (repository root, after make build/lib/librefray.a):
 *   cc -std=c99 -g -Iinclude tests/attack10/api_misuse.c build/lib/librefray.a \
 *      $(pkg-config --libs jansson libpng) -lOpenEXRCore -lm -lpthread -o /tmp/api_misuse
 *   valgrind --leak-check=full --error-exitcode=9 /tmp/api_misuse
 */
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "refray.h"

static const char scene[] = "image { width 4 height 3 max_depth 5 }\n"
                            "camera { eye [0, 0, 5] look_at [0, 0, 0] fov 40 }\n"
                            "ambient { color 0.5 }\n"
                            "sphere { center [0, 0, 0] radius 1 material { Kd 0.5 Ks 0.3 t 0.2 } }\n";

static rf_scene *load(const char *text, const rf_load_options *o)
{
    rf_scene *s = NULL;
    rf_status st = rf_scene_load_memory("m.scene", text, strlen(text), o, &s);
    printf("  load: %d\n", (int)st);
    return s;
}

static void opts_case(const char *what, rf_render_options o)
{
    rf_scene *s = load(scene, NULL);
    rf_renderer *r = NULL;
    rf_status st = rf_renderer_create(s, &o, &r);
    printf("%s: create %d\n", what, (int)st);
    if (st == RF_OK) {
        int w, h;
        rf_renderer_size(r, &w, &h);
        float *buf = calloc(3 * (size_t)w * h + 3, sizeof *buf);
        buf[3 * (size_t)w * h] = 12345;
        st = rf_render_region(r, 0, 0, w, h, buf, 3 * (size_t)w);
        printf("  render %dx%d: %d, guard %s\n", w, h, (int)st, buf[3 * (size_t)w * h] == 12345 ? "kept" : "OVERWRITTEN");
        free(buf);
        rf_renderer_free(r);
    }
    rf_scene_free(s);
}

int main(void)
{
    rf_render_options o;
    const int ints[] = {-1, INT_MIN, 1001, INT_MAX};
    static const char *const names[] = {"max_depth", "width", "samples", "light_samples"};
    for (int k = 0; k < 16; k++) {
        char what[64];
        int v = ints[k % 4];
        rf_render_options_init(&o);
        int *field[] = {&o.max_depth, &o.width, &o.samples, &o.light_samples};
        /* samples over the limit hang: api_samples.c shows them accepted */
        *field[k / 4] = k / 4 == 2 && v > 0 ? 2 : v;
        snprintf(what, sizeof what, "%s %d", names[k / 4], v);
        opts_case(what, o);
    }
    rf_render_options_init(&o);
    o.max_tree_rays = -1;
    opts_case("max_tree_rays -1", o);
    rf_render_options_init(&o);
    o.max_tree_rays = LONG_MIN;
    opts_case("max_tree_rays LONG_MIN", o);
    rf_render_options_init(&o);
    o.no_shortcuts = 7;
    opts_case("no_shortcuts 7", o);

    /* limits: max_depth over the ceiling in the limits and the scene */
    rf_load_options lo;
    rf_load_options_init(&lo);
    lo.limits.max_depth = 5000;
    rf_scene *s = load("image { width 1 height 1 max_depth 2000 }\ncamera { eye [0, 0, 5] look_at [0, 0, 0] fov 40 }\n", &lo);
    printf("limits max_depth 5000, scene 2000: %s\n", s ? "LOADED" : "refused");
    rf_scene_free(s);
    rf_load_options_init(&lo);
    lo.limits.max_depth = -5;
    s = load(scene, &lo);
    printf("limits max_depth -5: %s\n", s ? "loaded" : "refused");
    rf_scene_free(s);
    rf_load_options_init(&lo);
    lo.limits.max_width = -1;
    lo.limits.max_pixels = LONG_MIN;
    s = load(scene, &lo);
    printf("limits negative sizes: %s\n", s ? "loaded" : "refused");
    rf_scene_free(s);

    /* loads with odd text */
    s = NULL;
    printf("load NULL text size 5: %d\n", (int)rf_scene_load_memory("m.scene", NULL, 5, NULL, &s));
    rf_scene_free(s);
    s = NULL;
    printf("load NULL name: %d\n", (int)rf_scene_load_memory(NULL, scene, strlen(scene), NULL, &s));
    rf_scene_free(s);
    s = NULL;
    printf("load size 0: %d\n", (int)rf_scene_load_memory("m.scene", scene, 0, NULL, &s));
    rf_scene_free(s);
    s = NULL;
    printf("load json empty: %d\n", (int)rf_scene_load_memory("m.json", "", 0, NULL, &s));
    rf_scene_free(s);
    s = NULL;
    printf("load json 'null': %d\n", (int)rf_scene_load_memory("m.json", "null", 4, NULL, &s));
    rf_scene_free(s);
    s = NULL;
    printf("load text with NUL inside: %d\n", (int)rf_scene_load_memory("m.scene", "image\0{", 7, NULL, &s));
    rf_scene_free(s);

    /* images */
    rf_image *img = NULL;
    printf("image INT_MAX x INT_MAX: %d\n", (int)rf_image_create(INT_MAX, INT_MAX, NULL, &img));
    rf_image_free(img);
    img = NULL;
    printf("image 0 x 5: %d\n", (int)rf_image_create(0, 5, NULL, &img));
    rf_image_free(img);
    img = NULL;
    printf("image -3 x -3: %d\n", (int)rf_image_create(-3, -3, NULL, &img));
    rf_image_free(img);
    img = NULL;
    rf_image_create(2, 2, NULL, &img);
    double *p = rf_image_pixels(img);
    p[0] = 0.0 / 0.0;
    p[1] = 1e300;
    p[2] = -1;
    char msg[8];
    rf_write_stats ws;
    printf("write to /nonexistent/x.png: %d\n", (int)rf_image_write(img, "/nonexistent/x.png", NULL, &ws, msg, sizeof msg));
    printf("  message (8 bytes) '%s'\n", msg);
    printf("write with message NULL size 100: %d\n", (int)rf_image_write(img, "/nonexistent/x.png", NULL, NULL, NULL, 100));
    printf("write message size 0: %d\n", (int)rf_image_write(img, "/nonexistent/x.png", NULL, NULL, msg, 0));
    rf_write_options wo;
    memset(&wo, 0, sizeof wo);
    wo.png_bits = 12;
    printf("write png_bits 12: %d\n", (int)rf_image_write(img, "/tmp/api_misuse.png", &wo, NULL, msg, sizeof msg));
    memset(&wo, 0, sizeof wo);
    wo.exposure_stops = 1e308;
    wo.png_bits = 8;
    printf("write exposure 1e308: %d\n", (int)rf_image_write(img, "/tmp/api_misuse.png", &wo, NULL, msg, sizeof msg));
    wo.exposure_stops = 0.0 / 0.0;
    printf("write exposure NaN: %d\n", (int)rf_image_write(img, "/tmp/api_misuse.png", &wo, NULL, msg, sizeof msg));
    memset(&wo, 0, sizeof wo);
    wo.tone = 99;
    printf("write tone 99: %d\n", (int)rf_image_write(img, "/tmp/api_misuse.png", &wo, NULL, msg, sizeof msg));
    printf("write unknown fmt stream: %d\n", (int)rf_image_write_stream(img, stdout, (rf_format)77, NULL, NULL, msg, sizeof msg));
    printf("write stream NULL: %d\n", (int)rf_image_write_stream(img, NULL, RF_FORMAT_PFM, NULL, NULL, msg, sizeof msg));
    rf_image_free(img);

    /* regions */
    s = load(scene, NULL);
    rf_renderer *r = NULL;
    rf_renderer_create(s, NULL, &r);
    float f[64];
    printf("region stride SIZE_MAX: %d\n", (int)rf_render_region(r, 0, 0, 4, 2, f, SIZE_MAX));
    printf("region stride SIZE_MAX/2: %d\n", (int)rf_render_region(r, 0, 0, 4, 2, f, SIZE_MAX / 2));
    printf("region x1 INT_MIN: %d\n", (int)rf_render_region(r, 0, 0, INT_MIN, 1, f, 12));
    printf("region NULL renderer: %d\n", (int)rf_render_region(NULL, 0, 0, 1, 1, f, 3));
    printf("region one pixel stride 3: %d\n", (int)rf_render_region(r, 3, 2, 4, 3, f, 3));
    printf("fingerprint NULL: %llu\n", rf_renderer_fingerprint(NULL));
    rf_render_stats rs;
    rf_renderer_stats(NULL, &rs);
    rf_renderer_size(NULL, NULL, NULL);
    rf_renderer_free(r);
    rf_scene_free(s);
    rf_image *out = NULL;
    printf("render_image NULL scene: %d\n", (int)rf_render_image(NULL, NULL, &out, NULL));
    printf("create NULL out: %d\n", (int)rf_renderer_create(NULL, NULL, NULL));
    return 0;
}
