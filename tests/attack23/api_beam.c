/*
 * api_beam.c - attack 23: [BVH-BEAM-1] through the public API.  For each
 * scene file given (with its mesh files beside it), the image is rendered
 * whole (rf_render_image, the reference), then on one renderer as random
 * regions (random column and row cuts, so runs start at any x0 and end at
 * any x1; the regions in a random order), again after a render cancelled
 * at poll 3, 30 and 300, then with the allocator failing the renderer's
 * next allocations (the beam buffers: beam_alloc's out-of-memory path, no
 * beams), and with no_shortcuts.  Each must give the reference's doubles;
 * a difference prints FAIL and exits 1.
 *   cc -std=c99 -O2 -Iinclude -o /tmp/api_beam tests/attack23/api_beam.c \
 *      build/librefray-internal.a -ljansson -lm
 *   /tmp/api_beam SEED FILE.scene...
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>

static unsigned long long rng = 1;
static unsigned rnd(unsigned n)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return (unsigned)(rng >> 33) % n;
}

static long calls, stop_at;
static int cancel_cb(void *user)
{
    (void)user;
    return stop_at > 0 && ++calls >= stop_at;
}

static int failing; /* allocations still to fail */
static void *a_alloc(void *u, size_t n)
{
    (void)u;
    if (failing > 0) {
        failing--;
        return NULL;
    }
    return malloc(n);
}
static void *a_resize(void *u, void *p, size_t o, size_t n)
{
    (void)u;
    (void)o;
    return realloc(p, n);
}
static void a_release(void *u, void *p, size_t n)
{
    (void)u;
    (void)n;
    free(p);
}

static int fails;
static void expect(int ok, const char *file, const char *what)
{
    if (!ok) {
        printf("FAIL: %s: %s\n", file, what);
        fails = 1;
    }
}

static int cmp_sort(const void *a, const void *b) { return *(const int *)a - *(const int *)b; }

/* Random cuts of [0, n): returns the count of pieces, cuts in c[0..k]. */
static int cuts(int n, int *c)
{
    int k = 1 + (int)rnd(4);
    c[0] = 0;
    for (int i = 1; i < k; i++)
        c[i] = (int)rnd((unsigned)n);
    c[k] = n;
    qsort(c, (size_t)k + 1, sizeof *c, cmp_sort);
    return k;
}

static rf_status regions(rf_renderer *r, double *px, int w, int h)
{
    int cx[8], cy[8];
    int kx = cuts(w, cx), ky = cuts(h, cy);
    int order[64], m = 0;
    for (int i = 0; i < kx * ky; i++)
        order[m++] = i;
    for (int i = m - 1; i > 0; i--) {
        int j = (int)rnd((unsigned)i + 1), t = order[i];
        order[i] = order[j];
        order[j] = t;
    }
    for (int q = 0; q < m; q++) {
        int a = order[q] % kx, b = order[q] / kx;
        int x0 = cx[a], x1 = cx[a + 1], y0 = cy[b], y1 = cy[b + 1];
        if (x1 <= x0 || y1 <= y0)
            continue;
        rf_status st = rf_render_region_double(r, x0, y0, x1, y1, px + ((size_t)y0 * w + x0) * 3, 3 * (size_t)w);
        if (st != RF_OK)
            return st;
    }
    return RF_OK;
}

static void one(const char *file)
{
    rf_allocator al = {a_alloc, a_resize, a_release, NULL};
    rf_load_options lo;
    rf_load_options_init(&lo);
    lo.allocator = &al;
    rf_scene *scene = NULL;
    if (rf_scene_load_file(file, &lo, &scene) != RF_OK) {
        printf("skip: %s does not load\n", file);
        return;
    }
    rf_render_options o;
    rf_render_options_init(&o);
    rf_image *img = NULL;
    if (rf_render_image(scene, &o, &img, NULL) != RF_OK) {
        printf("skip: %s does not render\n", file);
        rf_scene_free(scene);
        return;
    }
    int w = rf_image_width(img), h = rf_image_height(img);
    size_t n = (size_t)w * h * 3;
    const double *ref = rf_image_pixels(img);
    double *b = calloc(n, sizeof *b);
    o.cancel = cancel_cb;
    rf_renderer *r = NULL;
    expect(rf_renderer_create(scene, &o, &r) == RF_OK, file, "renderer");
    for (int rep = 0; rep < 3 && r; rep++) {
        memset(b, 0, n * sizeof *b);
        expect(regions(r, b, w, h) == RF_OK && memcmp(ref, b, n * sizeof *b) == 0, file, "random regions");
    }
    for (long at = 3; at <= 300 && r; at *= 10) {
        calls = 0;
        stop_at = at;
        regions(r, b, w, h);
        stop_at = 0;
        memset(b, 0, n * sizeof *b);
        expect(regions(r, b, w, h) == RF_OK && memcmp(ref, b, n * sizeof *b) == 0, file, "regions after a cancel");
    }
    rf_renderer_free(r);
    r = NULL;
    if (rf_renderer_create(scene, &o, &r) == RF_OK) {
        failing = 2; /* beam_alloc's two blocks (the first region's first allocations) */
        memset(b, 0, n * sizeof *b);
        rf_status st = regions(r, b, w, h);
        failing = 0;
        expect(st == RF_OK && memcmp(ref, b, n * sizeof *b) == 0, file, "beam buffers out of memory");
        rf_renderer_free(r);
    }
    o.no_shortcuts = 1;
    r = NULL;
    expect(rf_renderer_create(scene, &o, &r) == RF_OK, file, "no_shortcuts renderer");
    memset(b, 0, n * sizeof *b);
    expect(r && regions(r, b, w, h) == RF_OK && memcmp(ref, b, n * sizeof *b) == 0, file, "no_shortcuts regions");
    rf_renderer_free(r);
    free(b);
    rf_image_free(img);
    rf_scene_free(scene);
}

int main(int argc, char **argv)
{
    rng = argc > 1 ? strtoull(argv[1], NULL, 10) : 1;
    for (int i = 2; i < argc; i++)
        one(argv[i]);
    printf("api_beam: %d scenes, %s\n", argc - 2, fails ? "FAILED" : "all the same");
    return fails;
}
