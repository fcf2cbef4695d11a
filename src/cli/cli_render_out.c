/*
 * cli_render_out.c - see cli_render_out.h.
 */
#include <stdio.h>
#include <string.h>
#include "cli/cli_render_out.h"
#include "cli/cli_signal.h"

rf_format cli_render_stdout_format(const char *name)
{
    char probe[16];
    if (!name || strlen(name) > 4)
        return RF_FORMAT_UNKNOWN;
    snprintf(probe, sizeof probe, "x.%s", name);
    return rf_format_from_path(probe);
}

static void progress(void *ctx, int done, int total)
{
    cli_progress_show(ctx, done, total);
}

/* [MESH-SCALE-1] Load time, and the bytes of the mesh stores and of the
 * BVH per mesh triangle (spec/numerics.md, "Meshes at scale"). */
static void print_memory(const rf_scene *scene, const rf_render_stats *s, double load_seconds)
{
    rf_scene_info info;
    rf_scene_get_info(scene, &info);
    long triangles = info.mesh_triangles;
    fprintf(stderr, "  load: %.3f s; meshes: %ld triangles in %ld bytes", load_seconds, triangles, info.mesh_bytes);
    if (triangles > 0)
        fprintf(stderr, " (%.1f per triangle); bvh %ld bytes (%.1f per triangle)",
                (double)info.mesh_bytes / triangles, s->bvh_bytes, (double)s->bvh_bytes / triangles);
    else
        fprintf(stderr, "; bvh %ld bytes", s->bvh_bytes);
    fputc('\n', stderr);
}

void cli_render_print_stats(const render_args *a, const rf_scene *scene, const rf_render_stats *s,
                            const rf_write_stats *w)
{
    long rays = s->camera_rays + s->shadow_rays + s->reflection_rays + s->refraction_rays +
                s->total_internal_reflection_rays;
    fprintf(stderr, "stats: %dx%d pixels, %dx%d camera rays per pixel, max_depth %d\n", s->width, s->height,
            s->samples, s->samples, s->max_depth);
    fprintf(stderr, "  rays: %ld camera, %ld shadow, %ld reflection, %ld refraction, %ld total-internal-reflection; "
            "%ld in all\n", s->camera_rays, s->shadow_rays, s->reflection_rays, s->refraction_rays,
            s->total_internal_reflection_rays, rays);
    fprintf(stderr, "  light samples: %ld (skipped on the surface: %ld)\n", s->light_samples,
            s->light_samples_on_surface);
    fprintf(stderr, "  passes%s: shadows %s, specular %s, reflection %s, refraction %s\n",
            a->render.no_shortcuts ? " (every shortcut off)" : "",
            s->shadows ? "on" : "skipped (nothing can occlude)", s->specular ? "on" : "skipped (every Ks is 0)",
            s->reflection ? "on" : "skipped (no Ks > 0, or max_depth 1)",
            s->refraction ? "on" : "skipped (no t > 0, or max_depth 1)");
    print_memory(scene, s, a->load_seconds);
    fprintf(stderr, "  bvh: %d nodes, %d leaves, depth %d, built in %.3f s; %ld node visits, %ld primitive tests\n",
            s->bvh_nodes, s->bvh_leaves, s->bvh_depth, s->build_seconds, s->node_visits, s->primitive_tests);
    fprintf(stderr, "  time: %.3f s, %.0f rays/s\n", s->seconds, s->seconds > 0 ? rays / s->seconds : 0.0);
    fprintf(stderr, "  non-finite values: %ld traced, %zu written\n", s->nonfinite, w->nonfinite);
}

rf_render_options cli_render_options(const render_args *a, cli_progress *bar)
{
    rf_render_options o;
    rf_render_options_init(&o);
    o.width = a->render.width;
    o.height = a->render.height;
    o.samples = a->render.samples;
    o.max_depth = a->render.max_depth;
    o.light_samples = a->render.light_samples;
    o.max_tree_rays = a->scene.limits.max_ray_tree;
    o.no_shortcuts = a->render.no_shortcuts;
    o.progress = bar ? progress : NULL;
    o.cancel = cli_signal_cancel;
    o.user = bar;
    return o;
}

void cli_render_report(const render_args *a, int status, const cli_render_void *at, const char *nl)
{
    if (status == STATUS_DATA && at->medium)
        fprintf(stderr, "%srefray: error: a ray of pixel (%d, %d) is inside more than 16 nested transparent solids, "
                "or crosses more than 8 coincident surfaces at once, more than refray follows; the image "
                "would be wrong there; nothing written\n", nl, at->x, at->y);
    else if (status == STATUS_DATA)
        fprintf(stderr, "%srefray: error: the rays of pixel (%d, %d) branch into more than %ld rays "
                "(--max-ray-tree); lower max_depth or raise the limit; nothing written\n", nl, at->x, at->y,
                a->scene.limits.max_ray_tree);
    else if (status == STATUS_CANCELLED && a->checkpoint)
        cli_note(nl, "interrupted; nothing written but the finished tiles in '%s' (the same command goes on "
                 "from them)", a->checkpoint);
    else if (status == STATUS_CANCELLED)
        fprintf(stderr, "%srefray: interrupted; nothing written\n", nl);
    else if (status == STATUS_NO_MEMORY)
        cli_error("out of memory rendering '%s'", a->input);
    else
        cli_error("%s rendering '%s'", status_string(status), a->input);
}

int cli_render_write(const render_args *a, const rf_image *img, rf_write_stats *written)
{
    char err[1024];
    int status;
    if (strcmp(a->output, "-") == 0) {
        status = (int)rf_image_write_stream(img, stdout, cli_render_stdout_format(a->format), &a->image, written,
                                            err, sizeof err);
        if (status == STATUS_OK && fflush(stdout) != 0) {
            status = STATUS_IO;
            snprintf(err, sizeof err, "cannot write to standard output");
        }
    } else {
        status = (int)rf_image_write(img, a->output, &a->image, written, err, sizeof err);
    }
    if (status == STATUS_CANCELLED)
        fputs("refray: interrupted; nothing written\n", stderr);
    else if (status != STATUS_OK)
        cli_error("%s", err);
    return status;
}
