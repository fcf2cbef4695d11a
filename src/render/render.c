/*
 * render.c - see render.h.  Pixel (i, j) is sampled at the centres of a
 * k x k grid of equal cells, (i + (a + 0.5)/k, j + (b + 0.5)/k): with k = 1,
 * the pixel centre.  The sub-samples are not jittered, so a render is a
 * deterministic function of the scene (the light samples are jittered by a
 * counter-based hash of the pixel and sub-sample, which is deterministic
 * too).
 */
#include <string.h>
#include <time.h>
#include "render/camera.h"
#include "render/render.h"
#include "base/hash.h"
#include "base/sampler.h"
#include "render/shade.h"

/* Camera-ray beams: a tile of up to RENDER_TILE_WIDTH x RENDER_TILE_ROWS
 * pixels, the most rays, the most nodes of a pruned tree (past it, the
 * tile walks the whole tree).  Tiles, not runs of one row: a beam's tree
 * holds every node along its wedge to infinity, and where that wedge
 * crosses a deep slab of parts (grid100k: 10 layers seen at a slant) its
 * length, not its width, sets the tree's size, so rows below add rays
 * almost for free (grid100k 640x480: runs of 32 x 1 keep about 164 nodes,
 * tiles of 16 x 16 about 290 for 8 times the rays; grid1k's 12). */
enum { RENDER_TILE_WIDTH = 16, RENDER_TILE_ROWS = 16, RENDER_RUN_RAYS = 256, RENDER_BEAM_NODES = 1024 };

double render_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

uint64_t render_sample_key(int width, int k, int i, int j, int a, int b)
{
    uint64_t pixel_key = sampler_key((uint64_t)j * (uint64_t)width + (uint64_t)i, RENDER_PIXEL_SALT);
    return sampler_key(pixel_key, (uint64_t)b * (uint64_t)k + (uint64_t)a);
}

double render_sample_offset(int k, int a)
{
    return (a + 0.5) / k;
}

/* Camera sample (a, b) of pixel (i, j) with a k x k grid. */
static ray sample_ray(const tracer *t, int width, int height, int k, int i, int j, int a, int b)
{
    real x = i + render_sample_offset(k, a), y = j + render_sample_offset(k, b);
    return camera_ray(&t->scene->camera, t->camera_half, width, height, x, y);
}

/* The colour of camera ray r, sample (a, b) of pixel (i, j); beam: the
 * pruned tree of its run, or NULL. */
static rgb sample_colour(const tracer *t, const ray *r, const bvh_beam_tree *beam, int width, int k, int i, int j,
                         int a, int b, trace_stats *st)
{
    medium_stack media = t->eye_media;
    if (t->scene->camera.kind == CAMERA_ORTHOGRAPHIC)
        trace_media_at(t, r->origin, &media, st);
    st->camera_rays++;
    st->tree_rays = 0;
    st->medium_overflow += t->eye_overflow;
    return trace_camera_ray(t, r, beam, &media, render_sample_key(width, k, i, j, a, b), st);
}

rgb render_pixel(const tracer *t, int width, int height, int k, int i, int j, trace_stats *st)
{
    rgb sum = vec_splat(0);
    for (int b = 0; b < k; b++) {
        for (int a = 0; a < k; a++) {
            ray r = sample_ray(t, width, height, k, i, j, a, b);
            rgb c = sample_colour(t, &r, NULL, width, k, i, j, a, b, st);
            sum = shade_saturate(vec_add(sum, c));
        }
    }
    return vec_scale(sum, 1.0 / ((real)k * k));
}

/* render_pixel from its k x k rays already made (rays, in its order),
 * their first nearest hits on beam: the same sum in the same order. */
static rgb pixel_from_rays(const tracer *t, const ray *rays, const bvh_beam_tree *beam, int width, int k, int i, int j,
                           trace_stats *st)
{
    rgb sum = vec_splat(0);
    for (int b = 0; b < k; b++) {
        for (int a = 0; a < k; a++) {
            rgb c = sample_colour(t, &rays[b * k + a], beam, width, k, i, j, a, b, st);
            sum = shade_saturate(vec_add(sum, c));
        }
    }
    return vec_scale(sum, 1.0 / ((real)k * k));
}

static void record_setup(const tracer *t, render_stats *stats)
{
    stats->bvh_nodes = t->accel.node_count;
    stats->bvh_leaves = t->accel.leaf_count;
    stats->bvh_depth = t->accel.depth;
    stats->bvh_bytes = (long)(t->accel.node_count * sizeof(bvh_node) + t->accel.item_count * sizeof(bvh_ref) +
                              t->accel.unbounded_count * sizeof(bvh_ref));
    stats->shadows = t->shadows;
    stats->specular = t->specular;
    stats->reflection = t->reflection;
    stats->refraction = t->refraction;
    stats->no_shortcuts = t->no_shortcuts;
}

/* The buffers of the camera-ray beams (renderer_region), made with the
 * renderer: a region allocates nothing ([EMBED-MEM-3]).  Out of memory
 * leaves them NULL (no beams, the same pixels). */
static void beam_alloc(renderer *r)
{
    const mem *m = &r->tracer.scene->mem;
    r->beam_tried = 1;
    r->run_rays = mem_alloc(m, RENDER_RUN_RAYS * sizeof *r->run_rays);
    r->beam_nodes = mem_alloc(m, RENDER_BEAM_NODES * sizeof *r->beam_nodes);
    if (!r->run_rays || !r->beam_nodes) {
        mem_free(m, r->run_rays, RENDER_RUN_RAYS * sizeof *r->run_rays);
        mem_free(m, r->beam_nodes, RENDER_BEAM_NODES * sizeof *r->beam_nodes);
        r->run_rays = NULL;
        r->beam_nodes = NULL;
    }
}

int renderer_init(renderer *r, const scene_model *scene, const render_opts *opts)
{
    const render_opts *o = opts;
    render_stats *stats = &r->stats;
    memset(r, 0, sizeof *r);
    if (o)
        r->opts = *o;
    stats->width = o && o->width > 0 ? o->width : scene->image.width;
    stats->height = o && o->height > 0 ? o->height : scene->image.height;
    stats->samples = o && o->samples > 0 ? o->samples : scene->image.samples;
    double beyond;
    if (scene_view_out(&scene->camera, stats->width, stats->height, &beyond))
        return STATUS_DATA; /* a size override took the view out of the extent ([LANG-EXTENT-1]) */
    double start = render_clock();
    r->cancel = cancel_poll_make(o ? o->cancel : NULL, o ? o->cancel_ctx : NULL);
    int status = tracer_build(&r->tracer, scene, o ? o->max_depth : 0, o ? o->light_samples : 0, &r->cancel);
    if (status != STATUS_OK)
        return status;
    stats->trace.cancel = &r->cancel;
    r->tracer.max_tree_rays = o ? o->max_tree_rays : 0;
    if (o && o->no_shortcuts)
        tracer_no_shortcuts(&r->tracer);
    if (o && o->facet_shadows)
        r->tracer.terminator_offset = 0;
    stats->max_depth = r->tracer.max_depth;
    stats->build_seconds = render_clock() - start;
    record_setup(&r->tracer, stats);
    beam_alloc(r);
    return STATUS_OK;
}

void renderer_free(renderer *r)
{
    if (r->beam_tried) {
        const mem *m = &r->tracer.scene->mem;
        mem_free(m, r->run_rays, RENDER_RUN_RAYS * sizeof *r->run_rays);
        mem_free(m, r->beam_nodes, RENDER_BEAM_NODES * sizeof *r->beam_nodes);
    }
    tracer_free(&r->tracer);
}

/* A coordinate as the bits of its double: a long double `real` has
 * padding bytes, which hold nothing a process can count on. */
static uint64_t hash_real(uint64_t h, real v)
{
    double d = (double)v;
    uint64_t bits;
    memcpy(&bits, &d, sizeof bits);
    return hash_u64(h, bits);
}

static uint64_t hash_points(uint64_t h, const vec3 *p, int n)
{
    h = hash_u64(h, (uint64_t)n);
    for (int i = 0; i < n; i++)
        h = hash_real(hash_real(hash_real(h, p[i].x), p[i].y), p[i].z);
    return h;
}

/* A mesh file's text is let go once its mesh is built (source.h), so a
 * mesh counts by what was built from it: every array of its store. */
static uint64_t hash_meshes(uint64_t h, const scene_model *s)
{
    for (int i = 0; i < s->mesh_count; i++) {
        const scene_trimesh *g = &s->meshes[i].geom;
        size_t t = (size_t)g->tri_count;
        h = hash_points(h, g->positions, g->position_count);
        h = hash_points(h, g->normals, g->normals ? g->normal_count : 0);
        h = hash_u64(h, (uint64_t)t);
        h = hash_bytes(h, g->tri, t * sizeof *g->tri);
        h = hash_bytes(h, g->tri_normal, g->tri_normal ? t * sizeof *g->tri_normal : 0);
        h = hash_bytes(h, g->open, g->open ? t : 0);
        h = hash_u64(h, (uint64_t)g->closed);
    }
    return h;
}

uint64_t renderer_fingerprint(const renderer *r)
{
    const source_set *src = &r->tracer.scene->sources;
    const render_stats *st = &r->stats;
    uint64_t h = hash_bytes(HASH_FNV_START, "refray pixels 1", 15);
    for (int i = 0; i < src->count; i++) {
        h = hash_u64(h, (uint64_t)src->files[i]->len);
        h = hash_bytes(h, src->files[i]->text, src->files[i]->len);
    }
    h = hash_meshes(h, r->tracer.scene);
    h = hash_u64(h, (uint64_t)r->opts.facet_shadows);
    h = hash_u64(h, (uint64_t)st->width);
    h = hash_u64(h, (uint64_t)st->height);
    h = hash_u64(h, (uint64_t)st->samples);
    h = hash_u64(h, (uint64_t)st->max_depth);
    h = hash_u64(h, (uint64_t)r->opts.light_samples);
    return hash_u64(h, (uint64_t)sizeof(real));
}

/* v as float; beyond FLT_MAX (a radiance can reach DBL_MAX) the largest
 * float, so a float target never holds an infinity.  From the double a
 * double target would hold, so that a float region has the floats a whole
 * image written as 32-bit float has (with a long double `real` too). */
static float to_float(double v)
{
    return v > FLT_MAX ? FLT_MAX : v < -FLT_MAX ? -FLT_MAX : (float)v;
}

static void store(const render_target *target, int x, int y, rgb c)
{
    size_t at = (size_t)(y - target->y0) * target->stride + 3 * (size_t)(x - target->x0);
    if (target->f32) {
        target->f32[at] = to_float((double)c.x);
        target->f32[at + 1] = to_float((double)c.y);
        target->f32[at + 2] = to_float((double)c.z);
    } else {
        target->f64[at] = (double)c.x;
        target->f64[at + 1] = (double)c.y;
        target->f64[at + 2] = (double)c.z;
    }
}

/*
 * Camera-ray beams ([BVH-BEAM-1]): the region's rows go in bands of up to
 * RENDER_TILE_ROWS, each band in tiles of up to RENDER_TILE_WIDTH pixels
 * a row, at most RENDER_RUN_RAYS rays a tile (k x k a pixel); a tile's
 * camera rays are made first and its pruned tree serves their first
 * nearest hits.  A pixel's colour is a function of (i, j) alone
 * (render_pixel: its rays, its sample keys and the const tracer), so the
 * order the pixels are made in changes no bit.  The number of pixels of a
 * tile, or 0 for none: a perspective camera alone (one eye), and not with
 * the shortcuts off (an exhaustive tree prunes nothing: bvh_beam_prune
 * refuses it).
 */
static int tile_pixels(const renderer *r)
{
    const tracer *t = &r->tracer;
    int rays = r->stats.samples * r->stats.samples;
    if (!r->beam_nodes || t->accel.exhaustive || t->scene->camera.kind == CAMERA_ORTHOGRAPHIC ||
        rays > RENDER_RUN_RAYS)
        return 0;
    return RENDER_RUN_RAYS / rays;
}

/* A tile: pixels [i0, i1) of rows [j0, j1). */
typedef struct tile {
    int i0, i1, j0, j1;
} tile;

/* The camera rays of tile p, row by row and pixel by pixel in
 * render_pixel's order, and their pruned tree in *tree (count -1: none,
 * the whole tree; also past RENDER_BEAM_NODES, where the rays reach deep
 * into a large scene and the tree would cost more than it saves). */
static void tile_make(renderer *r, const tile *p, bvh_beam_tree *tree)
{
    const tracer *t = &r->tracer;
    int k = r->stats.samples, at = 0;
    for (int j = p->j0; j < p->j1; j++)
        for (int i = p->i0; i < p->i1; i++)
            for (int b = 0; b < k; b++)
                for (int a = 0; a < k; a++)
                    r->run_rays[at++] = sample_ray(t, r->stats.width, r->stats.height, k, i, j, a, b);
    bvh_beam beam;
    tree->nodes = r->beam_nodes;
    tree->cap = RENDER_BEAM_NODES;
    tree->count = -1;
    if (bvh_beam_bounds(r->run_rays, at, &beam))
        bvh_beam_prune(&t->accel, &beam, tree);
}

/* Pixel (i, j) stored: by render_pixel (p NULL), or from tile p's rays. */
static void make_pixel(renderer *r, const render_target *target, const tile *p, const bvh_beam_tree *tree, int i,
                       int j)
{
    render_stats *stats = &r->stats;
    int k = stats->samples;
    rgb c;
    if (!p) {
        c = render_pixel(&r->tracer, stats->width, stats->height, k, i, j, &stats->trace);
    } else {
        size_t at = (size_t)(j - p->j0) * (size_t)(p->i1 - p->i0) + (size_t)(i - p->i0);
        c = pixel_from_rays(&r->tracer, r->run_rays + at * (size_t)k * (size_t)k, tree, stats->width, k, i, j,
                            &stats->trace);
    }
    store(target, i, j, c);
}

/* After pixel (i, j): STATUS_CANCELLED when asked to stop, STATUS_DATA
 * when it overflowed (media_lost: the medium overflows before it), else
 * STATUS_OK. */
static int pixel_status(renderer *r, long media_lost)
{
    const trace_stats *st = &r->stats.trace;
    if (cancel_stopped(&r->cancel))
        return STATUS_CANCELLED;
    return st->tree_overflow || st->medium_overflow > media_lost ? STATUS_DATA : STATUS_OK;
}

/* Rows [j0, j1) of target pixel by pixel in row-major order by
 * render_pixel, stopping at the first pixel that stops or overflows
 * (where, for an overflow, r->stats says); returns its status. */
static int rows_by_pixel(renderer *r, const render_target *target, int j0, int j1)
{
    for (int j = j0; j < j1; j++) {
        for (int i = target->x0; i < target->x1; i++) {
            long media_lost = r->stats.trace.medium_overflow;
            make_pixel(r, target, NULL, NULL, i, j);
            int status = pixel_status(r, media_lost);
            if (status == STATUS_DATA) {
                r->stats.overflow_x = i;
                r->stats.overflow_y = j;
            }
            if (status != STATUS_OK)
                return status;
        }
    }
    return STATUS_OK;
}

/* Rows [j0, j1) of target tile by tile, each tile row-major.  An overflow
 * is reported at the band's first overflowing pixel in row-major order,
 * as rows_by_pixel finds it: the band is made again that way (a pixel
 * overflows or not by itself), so overflow_x, _y are the row-major walk's. */
static int band_by_tiles(renderer *r, const render_target *target, int j0, int j1, int width)
{
    bvh_beam_tree tree = {NULL, 0, -1};
    /* An overflow makes the band again row by row, from these counts: the
     * counts and the CLI's message (medium or ray tree) are those of the
     * pixels up to the row-major first overflow, each traced once. */
    const trace_stats before = r->stats.trace;
    for (int i0 = target->x0; i0 < target->x1; i0 += width) {
        tile p = {i0, target->x1 - i0 < width ? target->x1 : i0 + width, j0, j1};
        tile_make(r, &p, &tree);
        for (int j = j0; j < j1; j++) {
            for (int i = p.i0; i < p.i1; i++) {
                long media_lost = r->stats.trace.medium_overflow;
                make_pixel(r, target, &p, &tree, i, j);
                int status = pixel_status(r, media_lost);
                if (status == STATUS_DATA) {
                    r->stats.trace = before;
                    return rows_by_pixel(r, target, j0, j1);
                }
                if (status != STATUS_OK)
                    return status;
            }
        }
    }
    return STATUS_OK;
}

int renderer_region(renderer *r, const render_target *target)
{
    render_stats *stats = &r->stats;
    const render_opts *opts = &r->opts;
    int rows = target->y1 - target->y0, status = STATUS_OK;
    double start = render_clock();
    stats->trace.tree_overflow = 0;
    /* A stop ends one region, not the renderer: a host that cancelled a
     * region and asks again gets a fresh renderer's pixels, wherever the
     * earlier stop landed ([EMBED-API-3]).  The poll is reset in place, as
     * the tracer holds its address. */
    r->cancel = cancel_poll_make(opts->cancel, opts->cancel_ctx);
    stats->trace.cancel = &r->cancel;
    int n = tile_pixels(r), width = n < RENDER_TILE_WIDTH ? n : RENDER_TILE_WIDTH;
    int band = n == 0 ? 1 : n / width < RENDER_TILE_ROWS ? n / width : RENDER_TILE_ROWS;
    for (int j0 = target->y0; j0 < target->y1 && status == STATUS_OK; j0 += band) {
        int j1 = target->y1 - j0 < band ? target->y1 : j0 + band;
        status = n == 0 ? rows_by_pixel(r, target, j0, j1) : band_by_tiles(r, target, j0, j1, width);
        /* Progress per row, once its band is made. */
        for (int j = j0; j < j1 && status == STATUS_OK; j++)
            if (opts->progress && opts->progress(opts->progress_ctx, j - target->y0 + 1, rows))
                status = STATUS_CANCELLED;
    }
    stats->seconds += render_clock() - start;
    return status;
}

int render_image(const scene_model *scene, const render_opts *opts, img_buf *out, render_stats *stats)
{
    renderer r;
    int status = renderer_init(&r, scene, opts);
    if (status == STATUS_OK && img_create_mem(out, r.stats.width, r.stats.height, &scene->mem) != STATUS_OK)
        status = STATUS_NO_MEMORY;
    if (status == STATUS_OK) {
        render_target all = {0, 0, out->width, out->height, NULL, out->rgb, 3 * (size_t)out->width};
        status = renderer_region(&r, &all);
        if (status != STATUS_OK)
            img_free(out);
    }
    if (stats)
        *stats = r.stats;
    renderer_free(&r);
    return status;
}
