/*
 * render_file.c - refray embedded the plain way: load a scene file, render
 * it, write the image, through the public API alone.
 *
 *   render_file SCENE OUT [WIDTH HEIGHT]
 *
 * OUT's extension chooses the format (.png .exr .pfm .ppm).  Diagnostics
 * are printed as the refray program prints them.  Exit status: 0, or 1
 * with the reason on stderr.
 */
#include <stdio.h>
#include <stdlib.h>
#include <refray.h>

static void progress(void *user, int done, int total)
{
    int *last = user;
    int percent = (int)(100L * done / total);
    if (percent / 25 != *last / 25)
        fprintf(stderr, "render_file: %d%%\n", percent);
    *last = percent;
}

int main(int argc, char **argv)
{
    if (argc != 3 && argc != 5) {
        fprintf(stderr, "usage: render_file SCENE OUT [WIDTH HEIGHT]\n");
        return 1;
    }
    rf_load_options lo;
    rf_load_options_init(&lo);
    lo.diagnostic = rf_diagnostic_print;
    lo.diagnostic_user = stderr;
    rf_scene *scene;
    rf_status status = rf_scene_load_file(argv[1], &lo, &scene);
    if (status != RF_OK) {
        fprintf(stderr, "render_file: %s: %s\n", argv[1], rf_status_string(status));
        return 1;
    }
    int last = 0;
    rf_render_options ro;
    rf_render_options_init(&ro);
    if (argc == 5) {
        ro.width = atoi(argv[3]);
        ro.height = atoi(argv[4]);
    }
    ro.progress = progress;
    ro.user = &last;
    rf_image *img;
    rf_render_stats stats;
    status = rf_render_image(scene, &ro, &img, &stats);
    rf_scene_free(scene);
    if (status != RF_OK) {
        fprintf(stderr, "render_file: rendering: %s\n", rf_status_string(status));
        return 1;
    }
    char message[256];
    status = rf_image_write(img, argv[2], NULL, NULL, message, sizeof message);
    rf_image_free(img);
    if (status != RF_OK) {
        fprintf(stderr, "render_file: %s\n", message);
        return 1;
    }
    printf("wrote %s: %dx%d, %ld camera rays, %ld shadow rays (refray %s)\n", argv[2], stats.width, stats.height,
           stats.camera_rays, stats.shadow_rays, rf_version());
    return 0;
}
