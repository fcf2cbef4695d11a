/* api_cancel_every.c - one renderer stopped at each of its cancel polls in
 * turn, then asked again (the callback now says go on), over a scene of
 * glass, a mirror, a mesh-free torus and a shadowed floor at max_depth 8:
 * the second region must be the fresh renderer's, byte for byte, and so
 * must a third, smaller region asked after it ([EMBED-API-3]: a stop ends
 * the region, not the renderer).  Exit 1 when one differs.
 *   nice make -j2 build/lib/librefray.a
 *   cc -std=c99 -Iinclude tests/attack15/api_cancel_every.c build/lib/librefray.a -ljansson \
 *      $(pkg-config --libs OpenEXR libpng) -lm -lpthread -lstdc++ -o /tmp/ace && /tmp/ace */
#include <stdio.h>
#include <string.h>
#include <refray.h>

enum { W = 24, H = 12 };

static const char scene[] =
    "image { width 24 height 12 samples 2 max_depth 8 background [0.1, 0.2, 0.3] }\n"
    "camera { perspective eye [0, 1.5, -5] look_at [0, 1, 0] up [0, 1, 0] fov 50 }\n"
    "ambient { color [0.2, 0.2, 0.2] }\n"
    "point_light { position [5, 10, -5] power 60 d0 1 falloff linear }\n"
    "material glass { Kd 0.05 Ks 0.3 n 60 t 0.85 ior 1.5 }\n"
    "material mirror { Kd 0.1 Ks 0.9 n 200 }\n"
    "material red { Kd [0.8, 0.1, 0.1] Ks 0.3 n 40 }\n"
    "sphere { center [-1, 1, 0] radius 0.9 material glass }\n"
    "sphere { center [-1, 1, 0] radius 0.4 material red }\n"
    "box { from [0.6, 0, -0.5] to [1.6, 2, 0.5] material glass }\n"
    "torus { center [0, 0.5, -1.5] major 0.6 minor 0.2 material mirror }\n"
    "plane { point [0, 0, 0] normal [0, 1, 0] material red }\n";

/* Says stop at the poll that brings the countdown to 0, go on at every
 * other: the host that cancelled and then asks again. */
static int cancel(void *user)
{
    long *left = user;
    return *left > 0 && --*left == 0;
}

int main(void)
{
    rf_load_options lo;
    rf_load_options_init(&lo);
    rf_scene *sc;
    if (rf_scene_load_memory("s.scene", scene, strlen(scene), &lo, &sc) != RF_OK) {
        printf("the scene did not load\n");
        return 2;
    }
    static float ref[W * H * 3], part[W * H * 3], again[W * H * 3];
    rf_renderer *fresh;
    if (rf_renderer_create(sc, NULL, &fresh) != RF_OK || rf_render_region(fresh, 0, 0, W, H, ref, W * 3) != RF_OK ||
        rf_render_region(fresh, 5, 3, 17, 9, part, W * 3) != RF_OK) {
        printf("the fresh renderer failed\n");
        return 2;
    }
    rf_renderer_free(fresh);
    int bad = 0;
    long k;
    for (k = 1;; k++) {
        long left = k;
        rf_render_options ro;
        rf_render_options_init(&ro);
        ro.cancel = cancel;
        ro.user = &left;
        rf_renderer *r;
        rf_status made = rf_renderer_create(sc, &ro, &r);
        if (made == RF_ERR_CANCELLED)
            continue; /* the stop landed in the build */
        if (made != RF_OK)
            return 2;
        rf_status first = rf_render_region(r, 0, 0, W, H, again, W * 3);
        left = 0; /* the host goes on now, wherever the count stood */
        memset(again, 0, sizeof again);
        rf_status second = rf_render_region(r, 0, 0, W, H, again, W * 3);
        int same = second == RF_OK && memcmp(again, ref, sizeof ref) == 0;
        memset(again, 0, sizeof again);
        rf_status third = rf_render_region(r, 5, 3, 17, 9, again, W * 3);
        same &= third == RF_OK && memcmp(again, part, sizeof part) == 0;
        if (!same) {
            printf("stop at poll %ld: first %s, then %s, %s: not the fresh renderer's pixels\n", k,
                   rf_status_string(first), rf_status_string(second), rf_status_string(third));
            bad = 1;
        }
        rf_renderer_free(r);
        if (first == RF_OK)
            break;
    }
    printf("%ld stop points tried: %s\n", k, bad ? "some differ" : "every one renders the fresh pixels again");
    rf_scene_free(sc);
    return bad;
}
