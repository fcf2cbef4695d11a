/*
 * beam_fuzz.c - attack 23: [BVH-BEAM-1] hit by hit (with BEAM_FUZZ_TILES
 * defined, attack 24's tile_fuzz.c: the camera's runs as 2-D tiles).  For each scene file
 * given, its tracer's tree (renderer_init) is walked by runs of rays that
 * share an origin: the camera's own runs (camera_ray of every pixel, runs
 * of 1 .. 32 pixels starting anywhere in the row, k x k samples), and
 * random runs (an origin at the eye, at a part's box corner or face
 * centre, or anywhere in the scene's box; 1 .. 256 directions in a cone
 * of spread 0 .. 1 about a random direction or about an axis, some
 * components exactly 0 or tiny).  Each run is pruned with the render's
 * cap (64) and with caps 2, 3, 1024 and 8192; every ray's hit by
 * bvh_beam_intersect on each pruned tree is compared with
 * bvh_intersect_ties on the whole tree: met, t, prim, part, point,
 * normal, tmax and the tie count, to the bit.  A difference prints
 * DEFECT and exits 1.
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/beamf \
 *      tests/attack23/beam_fuzz.c build/librefray-internal.a -ljansson -lm
 *   /tmp/beamf SEED RUNS FILE.scene...
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/scene_file.h"
#include "render/bvh_beam.h"
#include "render/camera.h"
#include "render/render.h"

#include "../fuzz_rng.h"

static long defects, rays_cmp, runs_pruned;

static int same_hit(const hit *a, const hit *b)
{
    return memcmp(&a->t, &b->t, sizeof a->t) == 0 && a->prim == b->prim && a->part == b->part &&
           memcmp(&a->point, &b->point, sizeof a->point) == 0 && memcmp(&a->normal, &b->normal, sizeof a->normal) == 0;
}

static void check_run(const char *file, const tracer *t, const ray *rays, int n)
{
    static bvh_node nodes[8192];
    static const int caps[] = {64, 2, 3, 1024, 8192};
    bvh_beam beam;
    if (!bvh_beam_bounds(rays, n, &beam))
        return;
    for (size_t c = 0; c < sizeof caps / sizeof caps[0]; c++) {
        bvh_beam_tree tree = {nodes, caps[c], -1};
        if (!bvh_beam_prune(&t->accel, &beam, &tree))
            continue;
        runs_pruned++;
        for (int i = 0; i < n; i++) {
            ray a = rays[i], b = rays[i];
            hit ha, hb;
            memset(&ha, 0, sizeof ha);
            memset(&hb, 0, sizeof hb);
            int ta = -1, tb = -1;
            int ma = bvh_intersect_ties(&t->accel, t->scene->prims, &a, &ha, NULL, &ta);
            int mb = bvh_beam_intersect(&t->accel, &tree, t->scene->prims, &b, &hb, NULL, &tb);
            rays_cmp++;
            if (ma != mb || ta != tb || memcmp(&a.tmax, &b.tmax, sizeof a.tmax) != 0 || (ma && !same_hit(&ha, &hb))) {
                if (++defects <= 10)
                    printf("DEFECT %s cap %d: ray o (%.17g %.17g %.17g) d (%.17g %.17g %.17g): whole %d t %.17g prim %d "
                           "tied %d; beam %d t %.17g prim %d tied %d\n",
                           file, caps[c], (double)rays[i].origin.x, (double)rays[i].origin.y,
                           (double)rays[i].origin.z, (double)rays[i].dir.x, (double)rays[i].dir.y,
                           (double)rays[i].dir.z, ma, (double)ha.t, ha.prim, ta, mb, (double)hb.t, hb.prim, tb);
            }
        }
    }
}

static vec3 rnd_dir(void)
{
    switch (R64() % 5) {
    case 0: {
        vec3 d = vec_make(0, 0, 0);
        real s = R64() & 1 ? 1 : -1;
        int k = (int)(R64() % 3);
        if (k == 0) d.x = s; else if (k == 1) d.y = s; else d.z = s;
        return d;
    }
    default:
        return vec_normalize(vec_make(2 * U() - 1, 2 * U() - 1, 2 * U() - 1));
    }
}

static void random_runs(const char *file, const tracer *t, int count)
{
    static ray rays[256];
    const bvh *b = &t->accel;
    if (b->node_count == 0)
        return;
    vec3 lo = b->nodes[0].lo, hi = b->nodes[0].hi;
    for (int q = 0; q < count; q++) {
        vec3 o;
        int kind = (int)(R64() % 4);
        if (kind == 0)
            o = t->scene->camera.eye;
        else if (kind == 1 && b->node_count > 1) {
            const bvh_node *nd = &b->nodes[R64() % (uint64_t)b->node_count];
            o = vec_make(R64() & 1 ? nd->lo.x : nd->hi.x, R64() & 1 ? nd->lo.y : nd->hi.y, R64() & 1 ? nd->lo.z : nd->hi.z);
            if (R64() & 1)
                o.x = (nd->lo.x + nd->hi.x) / 2;
        } else
            o = vec_make(lo.x + (hi.x - lo.x) * (1.5 * U() - 0.25), lo.y + (hi.y - lo.y) * (1.5 * U() - 0.25),
                         lo.z + (hi.z - lo.z) * (1.5 * U() - 0.25));
        vec3 axis = rnd_dir();
        double spread = R64() % 3 == 0 ? 0 : pow(10, -8 * U());
        int n = 1 + (int)(R64() % 256);
        for (int i = 0; i < n; i++) {
            vec3 d = vec_add(axis, vec_scale(vec_make(2 * U() - 1, 2 * U() - 1, 2 * U() - 1), spread));
            if (R64() % 8 == 0)
                d.x = axis.x;
            rays[i] = (ray){o, vec_normalize(d), 0, INFINITY};
            if (!(vec_length2(rays[i].dir) > 0))
                rays[i].dir = axis;
        }
        check_run(file, t, rays, n);
    }
}

#ifdef BEAM_FUZZ_TILES
#define FUZZ_NAME "tile_fuzz"
/* Tiles as renderer_region makes them ([BVH-BEAM-1] since scale24): k x k
 * samples (k 1 .. 4), tiles of up to min(256 / k^2, 16) pixels a row and
 * up to 16 rows, at most 256 rays; first the render's own tiling of the
 * whole image, then random tiles (any size within the cap, anywhere, cut
 * at the image's edges). */
static void tile_check(const char *file, const tracer *t, int w, int h, int k, int i0, int i1, int j0, int j1)
{
    static ray rays[256];
    int at = 0;
    for (int j = j0; j < j1; j++)
        for (int x = i0; x < i1; x++)
            for (int b = 0; b < k; b++)
                for (int a = 0; a < k; a++)
                    rays[at++] = camera_ray(&t->scene->camera, t->camera_half, w, h, x + render_sample_offset(k, a),
                                            j + render_sample_offset(k, b));
    check_run(file, t, rays, at);
}

static void camera_runs(const char *file, const tracer *t, int w, int h)
{
    int k = 1 + (int)(R64() % 4);
    int n = 256 / (k * k), width = n < 16 ? n : 16, band = n / width < 16 ? n / width : 16;
    for (int j0 = 0; j0 < h; j0 += band)
        for (int i0 = 0; i0 < w; i0 += width)
            tile_check(file, t, w, h, k, i0, i0 + width < w ? i0 + width : w, j0, j0 + band < h ? j0 + band : h);
    for (int m = 0; m < 2 * (w + h); m++) {
        int tw = 1 + (int)(R64() % (unsigned)width), th = 1 + (int)(R64() % (unsigned)(n / tw < 16 ? n / tw : 16));
        int i0 = (int)(R64() % (unsigned)w), j0 = (int)(R64() % (unsigned)h);
        tile_check(file, t, w, h, k, i0, i0 + tw < w ? i0 + tw : w, j0, j0 + th < h ? j0 + th : h);
    }
}

#else
#define FUZZ_NAME "beam_fuzz"
static void camera_runs(const char *file, const tracer *t, int w, int h)
{
    static ray rays[256];
    int k = 1 + (int)(R64() % 3);
    for (int j = 0; j < h; j++) {
        int i = 0;
        while (i < w) {
            int n = 1 + (int)(R64() % 32);
            if (n * k * k > 256)
                n = 256 / (k * k);
            if (n > w - i)
                n = w - i;
            int at = 0;
            for (int x = i; x < i + n; x++)
                for (int b = 0; b < k; b++)
                    for (int a = 0; a < k; a++)
                        rays[at++] = camera_ray(&t->scene->camera, t->camera_half, w, h, x + render_sample_offset(k, a),
                                                j + render_sample_offset(k, b));
            check_run(file, t, rays, at);
            i += n;
        }
    }
}

#endif

int main(int argc, char **argv)
{
    rng = argc > 1 ? strtoull(argv[1], NULL, 10) : 1;
    int runs = argc > 2 ? atoi(argv[2]) : 200;
    int files = 0;
    for (int f = 3; f < argc; f++) {
        int status;
        scene_model *s = scene_file_load(argv[f], NULL, NULL, 0, &status);
        if (!s)
            continue;
        renderer r;
        if (renderer_init(&r, s, NULL) != STATUS_OK) {
            scene_free(s);
            continue;
        }
        files++;
        if (s->camera.kind != CAMERA_ORTHOGRAPHIC)
            camera_runs(argv[f], &r.tracer, r.stats.width, r.stats.height);
        random_runs(argv[f], &r.tracer, runs);
        renderer_free(&r);
        scene_free(s);
    }
    printf("%s: %d scenes, %ld pruned runs, %ld rays compared, %ld defects\n", FUZZ_NAME, files, runs_pruned, rays_cmp,
           defects);
    return defects != 0;
}
