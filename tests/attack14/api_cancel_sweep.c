/* api_cancel_sweep.c - a load, a renderer's build and a whole-image render
 * cancelled at their 1st, 2nd, ... poll, with a counting allocator.
 * refray.h: a stop gives RF_ERR_CANCELLED, no handle and nothing to free.
 * Checked for each poll: the status, the handle NULL, no block left.
 * Exit 1 on a breach, 0 when all hold. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>

struct arena { long live; };
static void *a_alloc(void *u, size_t n) { ((struct arena *)u)->live++; return malloc(n); }
static void a_release(void *u, void *p, size_t n) { (void)n; if (p) { ((struct arena *)u)->live--; free(p); } }
static void *a_resize(void *u, void *p, size_t o, size_t n) { (void)u; (void)o; return realloc(p, n); }

struct stop { long calls, at; };
static int cancel(void *u) { struct stop *s = u; return ++s->calls == s->at; }

int main(void)
{
    /* 2000 spheres by a loop (many statements and a BVH of some size), a light of many samples */
    static const char text[] =
        "image { width 24 height 16 samples 2 max_depth 3 background [0.1, 0.2, 0.3] }\n"
        "camera { perspective eye [0, 5, -30] look_at [0, 0, 0] up [0, 1, 0] fov 45 }\n"
        "distributed_light { rectangle [-2, 10, -2] [4, 0, 0] [0, 0, 4] power 50 samples 64 d0 1 falloff linear }\n"
        "material m { Kd 0.5 Ks 0.3 n 20 }\n"
        "for i in 0 .. 39 { for j in 0 .. 49 { sphere { center [j - 25, 0, i - 20] radius 0.3 material m } } }\n"
        "plane { point [0, -0.3, 0] normal [0, 1, 0] material m }\n";
    int bad = 0;
    for (int stage = 0; stage < 3; stage++) {
        long at;
        for (at = 1;; at++) {
            struct arena a = {0};
            rf_allocator al = {a_alloc, a_resize, a_release, &a};
            struct stop s = {0, at};
            rf_load_options lo;
            rf_load_options_init(&lo);
            lo.allocator = &al;
            if (stage == 0) {
                lo.cancel = cancel;
                lo.cancel_user = &s;
            }
            rf_scene *sc = (rf_scene *)&lo;
            rf_status st = rf_scene_load_memory("c.scene", text, strlen(text), &lo, &sc);
            rf_status done = st;
            if (stage == 0 && st != RF_OK && (st != RF_ERR_CANCELLED || sc != NULL)) {
                printf("load stopped at poll %ld: %s, handle %s\n", at, rf_status_string(st), sc ? "set" : "NULL");
                bad = 1;
            }
            if (st == RF_OK && stage > 0) {
                rf_render_options ro;
                rf_render_options_init(&ro);
                ro.cancel = cancel;
                ro.user = &s;
                if (stage == 1) {
                    rf_renderer *r = (rf_renderer *)&lo;
                    done = rf_renderer_create(sc, &ro, &r);
                    if (done == RF_OK)
                        rf_renderer_free(r);
                    else if (done != RF_ERR_CANCELLED || r != NULL) {
                        printf("renderer_create stopped at poll %ld: %s\n", at, rf_status_string(done));
                        bad = 1;
                    }
                } else {
                    rf_image *img = (rf_image *)&lo;
                    done = rf_render_image(sc, &ro, &img, NULL);
                    if (done == RF_OK)
                        rf_image_free(img);
                    else if (done != RF_ERR_CANCELLED || img != NULL) {
                        printf("render_image stopped at poll %ld: %s\n", at, rf_status_string(done));
                        bad = 1;
                    }
                }
            }
            if (st == RF_OK)
                rf_scene_free(sc);
            if (a.live != 0) {
                printf("stage %d stopped at poll %ld: %ld blocks left\n", stage, at, a.live);
                bad = 1;
            }
            if (done == RF_OK || bad || at > 100000)
                break;
        }
        printf("%s: stopped at each of its %ld polls: RF_ERR_CANCELLED, no handle, nothing left\n",
               stage == 0 ? "load" : stage == 1 ? "renderer_create" : "render_image", at - 1);
    }
    return bad;
}
