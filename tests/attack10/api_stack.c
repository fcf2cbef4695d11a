/*
 * api_stack.c - renders pixel (0, 0) of a scene file through the public
 * API on a thread whose stack is argv[1] KiB ([EMBED-STACK-1] promises
 * 2 MiB is enough at max_depth 1000), and prints its red channel.
 * Build (repository root, after make build/lib/librefray.a):
 *   cc -std=c99 -O2 -Iinclude tests/attack10/api_stack.c build/lib/librefray.a \
 *      $(pkg-config --libs jansson libpng) -lOpenEXRCore -lm -lpthread -o /tmp/api_stack
 * Run: /tmp/api_stack 2048 tests/attack10/SCENE
 */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include "refray.h"

static const char *path;

static void *render(void *arg)
{
    (void)arg;
    rf_load_options o;
    rf_load_options_init(&o);
    rf_scene *s = NULL;
    rf_renderer *r = NULL;
    float rgb[3] = {0, 0, 0};
    rf_status st = rf_scene_load_file(path, &o, &s);
    if (st == RF_OK)
        st = rf_renderer_create(s, NULL, &r);
    if (st == RF_OK)
        st = rf_render_region(r, 0, 0, 1, 1, rgb, 3);
    if (st != RF_OK) {
        fprintf(stderr, "status %d\n", (int)st);
        exit(2);
    }
    rf_render_stats stats;
    rf_renderer_stats(r, &stats);
    printf("rendered: %.9g (reflection %ld, refraction %ld, tir %ld)\n", rgb[0], stats.reflection_rays,
           stats.refraction_rays, stats.total_internal_reflection_rays);
    rf_renderer_free(r);
    rf_scene_free(s);
    return NULL;
}

int main(int argc, char **argv)
{
    if (argc < 3)
        return 64;
    size_t kib = strtoul(argv[1], NULL, 10);
    path = argv[2];
    pthread_attr_t a;
    pthread_t t;
    pthread_attr_init(&a);
    if (pthread_attr_setstacksize(&a, kib * 1024) != 0 || pthread_create(&t, &a, render, NULL) != 0)
        return 3;
    pthread_join(t, NULL);
    return 0;
}
