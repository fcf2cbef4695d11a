/*
 * api_arena.c - the outside attack on scene.kept (the arena that holds
 * transformed shapes' frames): load a scene of shapes that keep a local
 * frame through the public API with an allocator that counts bytes, checks
 * that each release gives the size allocated, and fails its n-th request,
 * for every n until a load succeeds (with "render", until a load and a
 * render do); then load and free it 200 times.
 * Exit 0: every load freed all it allocated and every size matched.
 *
 * Build: cc -std=c99 -Iinclude tests/attack8/api_arena.c build/lib/librefray.a \
 *        $(pkg-config --libs of the project's libraries) -o /tmp/api_arena
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "refray.h"

typedef struct counter {
    long live, calls, fail_at, bad;
    size_t bytes;
} counter;

/* A header before each block records its size, to check release's. */
#define HEAD 16

static void *c_alloc(void *user, size_t size)
{
    counter *c = user;
    if (++c->calls == c->fail_at)
        return NULL;
    char *p = malloc(size + HEAD);
    if (!p)
        return NULL;
    memcpy(p, &size, sizeof size);
    c->live++;
    c->bytes += size;
    return p + HEAD;
}

static void c_release(void *user, void *p, size_t size)
{
    counter *c = user;
    if (!p)
        return;
    char *b = (char *)p - HEAD;
    size_t had;
    memcpy(&had, b, sizeof had);
    if (had != size) {
        fprintf(stderr, "release of %zu bytes given %zu\n", had, size);
        c->bad++;
    }
    c->live--;
    c->bytes -= had;
    free(b);
}

static char *scene_text(int n)
{
    size_t cap = 256 + (size_t)n * 200, len = 0;
    char *t = malloc(cap);
    len += (size_t)sprintf(t + len, "image { width 8 height 6 }\n"
                                     "camera { perspective eye [0, 0, 10] look_at [0, 0, 0] up [0, 1, 0] fov 60 }\n"
                                     "point_light { position [5, 5, 5] power 1 }\n");
    for (int i = 0; i < n; i++)
        len += (size_t)sprintf(t + len,
                               i % 3 == 0   ? "cylinder { from [0, %d, 0] to [1, 0, 0] radius 0.1 scale [1, 2, 3] }\n"
                               : i % 3 == 1 ? "cone { from [%d, 0, 0] to [0, 1, 0] radii 0.2 0 scale [3, 1, 2] }\n"
                                            : "torus { center [0, 0, %d] major 1 minor 0.2 scale [1, 1, 2] }\n",
                               i % 5);
    return t;
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 1200;
    /* argv[2] "render": also render each loaded scene (the BVH build's own
     * allocations then fail in turn too; see README.md, finding 2). */
    int render = argc > 2 && strcmp(argv[2], "render") == 0;
    char *text = scene_text(n);
    int failures = 0;
    long fail_at;
    for (fail_at = 1;; fail_at++) {
        counter c = {0, 0, fail_at, 0, 0};
        rf_allocator a = {c_alloc, NULL, c_release, &c};
        rf_load_options o;
        rf_load_options_init(&o);
        o.allocator = &a;
        rf_scene *s = NULL;
        rf_status st = rf_scene_load_memory("attack.scene", text, strlen(text), &o, &s);
        if (s && render) {
            rf_image *img = NULL;
            if (rf_render_image(s, NULL, &img, NULL) == RF_OK)
                rf_image_free(img);
        }
        rf_scene_free(s);
        if (c.live || c.bytes || c.bad) {
            fprintf(stderr, "fail_at %ld: status %d, %ld blocks (%zu bytes) left, %ld bad sizes\n", fail_at,
                    (int)st, c.live, c.bytes, c.bad);
            failures++;
        }
        if (st == RF_OK && c.calls < fail_at)
            break;
    }
    counter c = {0, 0, -1, 0, 0};
    rf_allocator a = {c_alloc, NULL, c_release, &c};
    for (int i = 0; i < 200; i++) {
        rf_load_options o;
        rf_load_options_init(&o);
        o.allocator = &a;
        rf_scene *s = NULL;
        if (rf_scene_load_memory("attack.scene", text, strlen(text), &o, &s) != RF_OK) {
            fprintf(stderr, "load %d failed\n", i);
            failures++;
        }
        rf_scene_free(s);
    }
    if (c.live || c.bad) {
        fprintf(stderr, "after 200 loads: %ld blocks left, %ld bad sizes\n", c.live, c.bad);
        failures++;
    }
    printf("%ld fault points tried, %d failures\n", fail_at, failures);
    free(text);
    return failures != 0;
}
