/* api_cancel_reuse.c - a renderer whose render was cancelled, used again.
 *
 * A host (a viewer) cancels a region when the user moves on, then asks the
 * same renderer for a region again with a cancel that says go on.  The
 * header says nothing of a cancelled renderer being spent; a stop at a row
 * boundary leaves it usable.  Here the stop lands inside a row (the ray
 * poll): the second call must render the region as a fresh renderer does.
 * Exit 1 when the second call fails or differs, 0 when it matches. */
#include <stdio.h>
#include <string.h>
#include <refray.h>

static const char scene[] =
    "image { width 16 height 4 samples 4 max_depth 4 background [0.1, 0.2, 0.3] }\n"
    "camera { perspective eye [0, 1, -5] look_at [0, 1, 0] up [0, 1, 0] fov 45 }\n"
    "ambient { color [0.2, 0.2, 0.2] }\n"
    "point_light { position [5, 10, -5] power 60 d0 1 falloff linear }\n"
    "material red { Kd [0.8, 0.1, 0.1] Ks 0.3 n 40 }\n"
    "sphere { center [0, 1, 0] radius 1.5 material red }\n"
    "plane { point [0, 0, 0] normal [0, 1, 0] material red }\n";

struct stop { long calls, stop_at; };

static int cancel(void *user)
{
    struct stop *s = user;
    s->calls++;
    return s->stop_at > 0 && s->calls == s->stop_at;
}

int main(void)
{
    rf_load_options lo;
    rf_load_options_init(&lo);
    rf_scene *sc;
    if (rf_scene_load_memory("s.scene", scene, strlen(scene), &lo, &sc) != RF_OK)
        return 2;
    float ref[16 * 4 * 3], again[16 * 4 * 3];
    rf_renderer *fresh;
    if (rf_renderer_create(sc, NULL, &fresh) != RF_OK || rf_render_region(fresh, 0, 0, 16, 4, ref, 48) != RF_OK)
        return 2;
    rf_renderer_free(fresh);

    int bad = 0;
    for (long k = 2; k <= 6; k++) {
        struct stop s = {0, k};
        rf_render_options ro;
        rf_render_options_init(&ro);
        ro.cancel = cancel;
        ro.user = &s;
        rf_renderer *r;
        if (rf_renderer_create(sc, &ro, &r) != RF_OK)
            return 2;
        s.calls = 0;
        rf_status first = rf_render_region(r, 0, 0, 16, 4, again, 48);
        s.stop_at = 0;                         /* the host says: go on now */
        long asked = s.calls;
        memset(again, 0, sizeof again);
        rf_status second = rf_render_region(r, 0, 0, 16, 4, again, 48);
        int same = second == RF_OK && memcmp(again, ref, sizeof ref) == 0;
        printf("stop at cancel call %ld: first %s; second call (cancel now 0, asked %ld more times): %s, %s\n", k,
               rf_status_string(first), s.calls - asked, rf_status_string(second),
               same ? "the fresh renderer's pixels" : "not the fresh renderer's pixels");
        bad |= first == RF_ERR_CANCELLED && !same;
        rf_renderer_free(r);
    }
    rf_scene_free(sc);
    return bad;
}
