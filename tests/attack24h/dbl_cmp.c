/*
 * dbl_cmp.c - attack 24h: the images in double.  refray's image files are
 * float (PFM) or half/float (EXR), which round away a highlight of a few
 * double ulps; [SHADE-SHORTCUT-HIDDEN-1] decides in double.  For each scene
 * file: rf_render_region_double with the shortcuts and with no_shortcuts
 * (options: WIDTH HEIGHT, 0 for the scene's), compared to the bit; prints
 * one line per scene: the FNV-1a hash of the doubles and the counted
 * results (camera, reflection, refraction, TIR rays, light samples, on
 * surface), so that a build against another library (the base's) can be
 * compared line by line; "DIFF" where on and off differ.  Exit 1 on a DIFF.
 *   cc -std=c99 -O2 -Iinclude -o /tmp/dbl_cmp tests/attack24h/dbl_cmp.c \
 *      build/librefray-internal.a -ljansson -lm
 *   /tmp/dbl_cmp W H FILE...
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>
#include "../fnv_doubles.h"

static int render(const rf_scene *scene, int w0, int h0, int off, double **px, int *w, int *h, rf_render_stats *s)
{
    rf_render_options o;
    rf_render_options_init(&o);
    o.width = w0;
    o.height = h0;
    o.no_shortcuts = off;
    rf_renderer *r = NULL;
    rf_status st = rf_renderer_create(scene, &o, &r);
    if (st != RF_OK)
        return (int)st;
    rf_renderer_size(r, w, h);
    *px = calloc((size_t)*w * *h * 3, sizeof **px);
    st = rf_render_region_double(r, 0, 0, *w, *h, *px, 3 * (size_t)*w);
    rf_renderer_stats(r, s);
    rf_renderer_free(r);
    return (int)st;
}

int main(int argc, char **argv)
{
    int bad = 0;
    for (int i = 3; i < argc; i++) {
        rf_load_options lo;
        rf_load_options_init(&lo);
        rf_scene *scene = NULL;
        rf_status ls = rf_scene_load_file(argv[i], &lo, &scene);
        if (ls != RF_OK) {
            printf("%s: load %d\n", argv[i], (int)ls);
            continue;
        }
        double *a = NULL, *b = NULL;
        int w, h, w2, h2;
        rf_render_stats s, s2;
        int e1 = render(scene, atoi(argv[1]), atoi(argv[2]), 0, &a, &w, &h, &s);
        int e2 = render(scene, atoi(argv[1]), atoi(argv[2]), 1, &b, &w2, &h2, &s2);
        size_t n = (size_t)w * h * 3;
        int diff = e1 != e2 || (e1 == 0 && memcmp(a, b, n * sizeof *a) != 0);
        printf("%s: %s%d %016llx rays %ld %ld %ld %ld samples %ld %ld shadow %ld\n", argv[i], diff ? "DIFF " : "", e1,
               e1 == 0 ? fnv(a, n) : 0ull, s.camera_rays, s.reflection_rays, s.refraction_rays,
               s.total_internal_reflection_rays, s.light_samples, s.light_samples_on_surface, s.shadow_rays);
        bad |= diff;
        free(a);
        free(b);
        rf_scene_free(scene);
    }
    return bad;
}
