/*
 * memory.c - `make memory`: what the library allocates, measured through
 * the allocator hook of the public API (refray.h) with a counting
 * allocator (spec/embedding.md).  Figures, not tests.
 *
 *   memory [SCENE...]
 *
 * Prints the bytes a scene holds per sphere, per mesh triangle and per
 * light sample (the difference between two scenes that differ only in
 * that count, divided by the difference), then for each SCENE the bytes
 * held after loading, while rendering, and at the peak.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>
#include "../memcheck.h"

/* Bytes held after the load, after the renderer is made (the scene and
 * everything a render needs), and at the peak of both. */
typedef struct held {
    size_t scene, render, peak;
} held;

static rf_status obj_fetch(void *user, const char *from, const char *name, rf_source *out, char *message,
                           size_t size)
{
    (void)from;
    (void)message;
    (void)size;
    out->path = name;
    out->text = user;
    out->size = strlen(user);
    return RF_OK;
}

static held measure(const char *name, const char *text, const char *path, const char *obj)
{
    memcheck c;
    memcheck_init(&c);
    rf_allocator a = {memcheck_alloc, memcheck_resize, memcheck_release, &c};
    rf_load_options o;
    rf_load_options_init(&o);
    o.allocator = &a;
    o.warnings = 0;
    o.diagnostic = rf_diagnostic_print;
    o.diagnostic_user = stderr;
    o.limits.max_primitives = 100000000;
    o.limits.max_mesh_triangles = 100000000;
    o.limits.max_light_samples = 1000000;
    if (obj) {
        o.resolver.fetch = obj_fetch;
        o.resolver.user = (void *)obj;
    }
    rf_scene *s;
    held h = {0, 0, 0};
    rf_status st = path ? rf_scene_load_file(path, &o, &s) : rf_scene_load_memory(name, text, strlen(text), &o, &s);
    if (st != RF_OK) {
        fprintf(stderr, "memory: %s: %s\n", path ? path : name, rf_status_string(st));
        exit(1);
    }
    h.scene = c.live;
    rf_renderer *r;
    if ((st = rf_renderer_create(s, NULL, &r)) != RF_OK) {
        fprintf(stderr, "memory: %s: %s\n", path ? path : name, rf_status_string(st));
        exit(1);
    }
    h.render = c.live;
    h.peak = c.peak;
    rf_renderer_free(r);
    rf_scene_free(s);
    if (c.live != 0) {
        fprintf(stderr, "memory: %s: %zu bytes not returned\n", path ? path : name, c.live);
        exit(1);
    }
    return h;
}

static char *spheres(long n)
{
    char *t = malloc(256);
    snprintf(t, 256, "point_light { position [0, 10, 0] power 1 }\n"
                     "for i in 0 .. %ld { sphere { center [i, 0, 0] radius 0.4 } }\n", n - 1);
    return t;
}

/* n separate triangles as OBJ text. */
static char *triangles(long n)
{
    size_t cap = (size_t)n * 64 + 64, used = 0;
    char *t = malloc(cap);
    for (long i = 0; i < n; i++)
        used += (size_t)snprintf(t + used, cap - used, "v %ld 0 0\nv %ld 1 0\nv %ld 0 1\nf -3 -2 -1\n", i, i, i);
    return t;
}

static char *light(long samples)
{
    char *t = malloc(256);
    snprintf(t, 256, "distributed_light { rectangle [-1, 4, -1] [2, 0, 0] [0, 0, 2] power 1 samples %ld }\n"
                     "sphere {}\n", samples);
    return t;
}

static void per_item(const char *what, held a, held b, long n)
{
    printf("  %-14s %10.1f %10.1f %10.1f\n", what, ((double)b.scene - (double)a.scene) / (double)n,
           ((double)b.render - (double)a.render) / (double)n, ((double)b.peak - (double)a.peak) / (double)n);
}

int main(int argc, char **argv)
{
    enum { N = 20000, S = 4096 };
    printf("bytes per item (refray %s, %zu-bit pointers): difference of two scenes / difference of counts\n",
           rf_version(), 8 * sizeof(void *));
    printf("  %-14s %10s %10s %10s\n", "item", "scene", "rendering", "peak");
    char *t1 = spheres(N), *t2 = spheres(2 * N);
    per_item("sphere", measure("a.scene", t1, NULL, NULL), measure("b.scene", t2, NULL, NULL), N);
    free(t1);
    free(t2);
    static const char mesh[] = "mesh { file \"m.obj\" }\n";
    t1 = triangles(N);
    t2 = triangles(2 * N);
    per_item("mesh triangle", measure("a.scene", mesh, NULL, t1), measure("b.scene", mesh, NULL, t2), N);
    free(t1);
    free(t2);
    t1 = light(S);
    t2 = light(2 * S);
    per_item("light sample", measure("a.scene", t1, NULL, NULL), measure("b.scene", t2, NULL, NULL), S);
    free(t1);
    free(t2);
    if (argc > 1)
        printf("\nbytes held (scene: after loading; rendering: with a renderer made; peak: of both)\n");
    for (int i = 1; i < argc; i++) {
        held h = measure(NULL, NULL, argv[i], NULL);
        printf("  %-36s %12zu %12zu %12zu\n", argv[i], h.scene, h.render, h.peak);
    }
    return 0;
}
