/*
 * api_overflow.c - attack 24: what rf_render_image reports after
 * RF_ERR_DATA (a ray tree over max_tree_rays) or RF_ERR_CANCELLED, through
 * the public API: status, overflow pixel, and the counts of
 * rf_render_stats that [BVH-BEAM-1]'s tiles must not move (camera,
 * reflection, refraction, total-internal-reflection rays, light samples,
 * medium overflows).  Linked once with this tree's library and once with
 * the base's; the two outputs must be the same.
 *   cc -std=c99 -O2 -Iinclude -o /tmp/api_overflow tests/attack24/api_overflow.c \
 *      build/librefray-internal.a -ljansson -lm
 *   /tmp/api_overflow FILE.scene MAX_TREE_RAYS [W H [SAMPLES [CANCEL_AT]]]
 */
#include <stdio.h>
#include <stdlib.h>
#include <refray.h>

static long calls, stop_at;
static int cancel_cb(void *user)
{
    (void)user;
    return stop_at > 0 && ++calls >= stop_at;
}

int main(int argc, char **argv)
{
    if (argc < 3)
        return 2;
    rf_load_options lo;
    rf_load_options_init(&lo);
    rf_scene *scene;
    if (rf_scene_load_file(argv[1], &lo, &scene) != RF_OK) {
        printf("load failed\n");
        return 2;
    }
    rf_render_options o;
    rf_render_options_init(&o);
    o.max_tree_rays = atol(argv[2]);
    if (argc > 4) {
        o.width = atoi(argv[3]);
        o.height = atoi(argv[4]);
    }
    if (argc > 5)
        o.samples = atoi(argv[5]);
    if (argc > 6) {
        stop_at = atol(argv[6]);
        o.cancel = cancel_cb;
    }
    rf_image *img = NULL;
    rf_render_stats s;
    rf_status st = rf_render_image(scene, &o, &img, &s);
    printf("status %d overflow (%d, %d) camera %ld reflection %ld refraction %ld tir %ld light_samples %ld "
           "on_surface %ld medium_overflows %ld\n", (int)st, s.overflow_x, s.overflow_y, s.camera_rays,
           s.reflection_rays, s.refraction_rays, s.total_internal_reflection_rays, s.light_samples,
           s.light_samples_on_surface, s.medium_overflows);
    rf_image_free(img);
    rf_scene_free(scene);
    return 0;
}
