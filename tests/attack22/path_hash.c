/*
 * path_hash.c - attack 22: the ray-tree hash make difftest records
 * (tests/difftest/run.c path_at: trace_stats.record_path, which turns
 * [SHADE-SHORTCUT-DARK-1] and -DARK-2 off) for the camera ray through
 * every pixel centre and the pixel's four quarter points, folded into one
 * 64-bit value a scene, with the shortcuts on (tracer_init's default) and
 * off (tracer_no_shortcuts).  Built against this tree and against the old
 * main's sources and archive (its camera_ray has no camera_half:
 * -DPATH_HASH_OLD_CAMERA), the printed lines must agree (path_hash.sh).
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/ph \
 *      tests/attack22/path_hash.c build/librefray-internal.a -ljansson -lm
 */
#include <stdio.h>
#include <string.h>
#include "io/scene_file.h"
#include "render/camera.h"
#include "render/trace.h"

static uint64_t path_at(const tracer *t, double x, double y)
{
    trace_stats st;
    const scene_model *s = t->scene;
    memset(&st, 0, sizeof st);
    st.record_path = 1;
#ifdef PATH_HASH_OLD_CAMERA
    ray r = camera_ray(&s->camera, s->image.width, s->image.height, x, y);
#else
    ray r = camera_ray(&s->camera, camera_half(&s->camera), s->image.width, s->image.height, x, y);
#endif
    medium_stack media = t->eye_media;
    if (s->camera.kind == CAMERA_ORTHOGRAPHIC)
        trace_media_at(t, r.origin, &media, &st);
    (void)trace_ray(t, &r, 1, &media, 0, &st);
    return st.path;
}

int main(int argc, char **argv)
{
    int bad = 0;
    for (int a = 1; a < argc; a++) {
        scene_load_opts o;
        scene_load_opts_init(&o);
        o.warnings = 0;
        int status;
        scene_model *s = scene_file_load_with(argv[a], &o, &status);
        if (!s) {
            printf("%s: refused (%d)\n", argv[a], status);
            continue;
        }
        for (int off = 0; off < 2; off++) {
            tracer t;
            if (!tracer_init(&t, s, 0, 0)) {
                printf("%s: no tracer\n", argv[a]);
                bad = 1;
                break;
            }
            if (off)
                tracer_no_shortcuts(&t);
            uint64_t h = 1469598103934665603ull;
            for (int j = 0; j < s->image.height; j++)
                for (int i = 0; i < s->image.width; i++)
                    for (int q = 0; q < 5; q++) {
                        double x = i + (q == 0 ? 0.5 : q & 1 ? 0.25 : 0.75), y = j + (q == 0 ? 0.5 : q & 2 ? 0.25 : 0.75);
                        h = (h ^ path_at(&t, x, y)) * 1099511628211ull;
                    }
            printf("%s %s: %016llx\n", argv[a], off ? "off" : "on", (unsigned long long)h);
            tracer_free(&t);
        }
        scene_free(s);
    }
    return bad;
}
