/*
 * bench.c - `make bench`: renders each scene given several times and
 * prints the median wall time and rays per second, and the cost of a ray
 * relative to the first scene.  Medians, because the machine is shared.
 *
 *   bench [-r RUNS] [-w WIDTH] SCENE...
 *
 * -w renders every scene WIDTH pixels wide (height in the scene's aspect),
 * so a slow scene can be measured at a size that repeats quickly.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "render/render.h"
#include "io/scene_file.h"
#include "scene/scene.h"

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static long total_rays(const trace_stats *t)
{
    return t->camera_rays + t->shadow_rays + t->reflection_rays + t->refraction_rays + t->tir_rays;
}

/* Renders runs times; writes the median time, rays of one render and build time. */
static int measure(const scene_model *s, int runs, int width, double *median, long *rays, double *build)
{
    double times[64];
    render_opts o;
    memset(&o, 0, sizeof o);
    if (width > 0) {
        o.width = width;
        o.height = (int)((double)width * s->image.height / s->image.width + 0.5);
        o.height = o.height < 1 ? 1 : o.height;
    }
    for (int r = 0; r < runs; r++) {
        img_buf img;
        render_stats st;
        if (render_image(s, &o, &img, &st) != 0)
            return 0;
        img_free(&img);
        times[r] = st.seconds;
        *rays = total_rays(&st.trace);
        *build = st.build_seconds;
    }
    qsort(times, (size_t)runs, sizeof times[0], by_value);
    *median = times[runs / 2];
    return 1;
}

int main(int argc, char **argv)
{
    int runs = 5, width = 0, first = 1;
    while (first + 1 < argc && (strcmp(argv[first], "-r") == 0 || strcmp(argv[first], "-w") == 0)) {
        *(argv[first][1] == 'r' ? &runs : &width) = atoi(argv[first + 1]);
        first += 2;
    }
    if (runs < 1 || runs > 64 || width < 0 || first >= argc) {
        fprintf(stderr, "usage: bench [-r RUNS (1-64)] [-w WIDTH] SCENE...\n");
        return 64;
    }
    double base = 0;
    printf("%-32s %10s %12s %10s %12s %10s %9s\n", "scene", "primitives", "rays", "median s", "rays/s", "build s",
           "ns/ray");
    for (int i = first; i < argc; i++) {
        int status;
        scene_model *s = scene_file_load(argv[i], NULL, stderr, 0, &status);
        double median, build;
        long rays;
        if (!s || !measure(s, runs, width, &median, &rays, &build)) {
            fprintf(stderr, "bench: %s failed\n", argv[i]);
            scene_free(s);
            return 1;
        }
        double ns = 1e9 * median / (double)rays;
        if (i == first)
            base = ns;
        printf("%-32s %10d %12ld %10.3f %12.0f %10.3f %9.1f (x%.2f)\n", argv[i], s->prim_count, rays, median,
               rays / median, build, ns, ns / base);
        scene_free(s);
    }
    printf("(median of %d runs each; ns/ray relative to the first scene in parentheses)\n", runs);
    return 0;
}
