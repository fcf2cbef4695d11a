/*
 * api_thread_stack.c - renders one pixel of a mirror corridor through the
 * public API on a thread whose stack is STACK_KIB (argv[1]) KiB, with the
 * scene's max_depth argv[2] (at most the default limit, 1000).  The
 * tracer recurses trace_ray -> shade -> mirrored once a bounce, about
 * 2.6 KiB a level on x86-64 (the program crashes between max_depth 3187
 * and 3218 with an 8 MiB stack), so the default limit needs about 2.6 MiB.
 * Build (from the repository root, after make build/lib/librefray.a):
 *   cc -std=c99 -Iinclude tests/attack9/api_thread_stack.c build/lib/librefray.a \
 *      $(pkg-config --libs jansson libpng) -lOpenEXRCore -lm -lpthread -o /tmp/api_thread_stack
 * Run: /tmp/api_thread_stack 2048 1000   # SIGSEGV (exit 139 from a shell)
 *      /tmp/api_thread_stack 4096 1000   # "rendered: 0.632304549" = 1 - 0.999^1000, exit 0
 */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "refray.h"

static char scene[1024];

static void *render(void *arg)
{
    (void)arg;
    rf_load_options o;
    rf_load_options_init(&o);
    rf_scene *s = NULL;
    rf_renderer *r = NULL;
    float rgb[3] = {0, 0, 0};
    if (rf_scene_load_memory("corridor.scene", scene, strlen(scene), &o, &s) != RF_OK ||
        rf_renderer_create(s, NULL, &r) != RF_OK || rf_render_region(r, 0, 0, 1, 1, rgb, 3) != RF_OK) {
        fprintf(stderr, "load or render failed\n");
        exit(2);
    }
    printf("rendered: %.9g\n", rgb[0]);
    rf_renderer_free(r);
    rf_scene_free(s);
    return NULL;
}

int main(int argc, char **argv)
{
    size_t kib = argc > 1 ? strtoul(argv[1], NULL, 10) : 2048;
    int depth = argc > 2 ? atoi(argv[2]) : 1000;
    snprintf(scene, sizeof scene,
             "image  { width 1  height 1  max_depth %d }\n"
             "camera { eye [0, 0, 0]  look_at [0, 0, -1]  fov 1 }\n"
             "ambient { color 1 }\n"
             "plane  { point [0, 0, -1]  normal [0, 0, 1]  material { Kd 0.001  Ks 0.999 } }\n"
             "plane  { point [0, 0, 1]  normal [0, 0, -1]  material { Kd 0.001  Ks 0.999 } }\n",
             depth);
    pthread_attr_t a;
    pthread_t t;
    pthread_attr_init(&a);
    if (pthread_attr_setstacksize(&a, kib * 1024) != 0 || pthread_create(&t, &a, render, NULL) != 0)
        return 3;
    pthread_join(t, NULL);
    return 0;
}
