/*
 * api_two_threads.c - two scenes in one process: each loaded, rendered on
 * a thread of its own while the other renders (twice over, each thread
 * loading its scene itself and then sharing one scene between two
 * renderers), and compared bit for bit with the same renders done one
 * after the other.  Exit 1 when any pixel differs.
 *
 *   api_two_threads SCENE_A SCENE_B
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>

typedef struct job {
    const char *path;
    rf_scene *shared;   /* when set, render it instead of loading path */
    double *pixels;
    int width, height;
    rf_status status;
} job;

static void *run(void *arg)
{
    job *j = arg;
    rf_scene *scene = j->shared;
    rf_image *img = NULL;
    rf_load_options o;
    rf_load_options_init(&o);
    o.warnings = 0;
    j->status = scene ? RF_OK : rf_scene_load_file(j->path, &o, &scene);
    if (j->status == RF_OK)
        j->status = rf_render_image(scene, NULL, &img, NULL);
    if (j->status == RF_OK) {
        j->width = rf_image_width(img);
        j->height = rf_image_height(img);
        size_t n = 3 * (size_t)j->width * (size_t)j->height;
        j->pixels = malloc(n * sizeof *j->pixels);
        if (j->pixels)
            memcpy(j->pixels, rf_image_pixels(img), n * sizeof *j->pixels);
    }
    rf_image_free(img);
    if (!j->shared)
        rf_scene_free(scene);
    return NULL;
}

static int same(const job *a, const job *b)
{
    return a->status == RF_OK && b->status == RF_OK && a->pixels && b->pixels && a->width == b->width &&
           a->height == b->height &&
           memcmp(a->pixels, b->pixels, 3 * sizeof(double) * (size_t)a->width * (size_t)a->height) == 0;
}

int main(int argc, char **argv)
{
    if (argc != 3)
        return 2;
    job alone[2] = {{argv[1], NULL, NULL, 0, 0, RF_OK}, {argv[2], NULL, NULL, 0, 0, RF_OK}};
    job both[2] = {{argv[1], NULL, NULL, 0, 0, RF_OK}, {argv[2], NULL, NULL, 0, 0, RF_OK}};
    run(&alone[0]);
    run(&alone[1]);
    pthread_t t[2];
    for (int i = 0; i < 2; i++)
        pthread_create(&t[i], NULL, run, &both[i]);
    for (int i = 0; i < 2; i++)
        pthread_join(t[i], NULL);
    int bad = 0;
    for (int i = 0; i < 2; i++) {
        printf("%s: alone %s, beside the other %s: %s\n", argv[i + 1], rf_status_string(alone[i].status),
               rf_status_string(both[i].status), same(&alone[i], &both[i]) ? "identical" : "DIFFERENT");
        bad += !same(&alone[i], &both[i]);
    }
    /* one scene, two renderers on two threads */
    rf_scene *s = NULL;
    rf_load_options o;
    rf_load_options_init(&o);
    o.warnings = 0;
    if (rf_scene_load_file(argv[1], &o, &s) != RF_OK)
        return 2;
    job sh[2] = {{argv[1], s, NULL, 0, 0, RF_OK}, {argv[1], s, NULL, 0, 0, RF_OK}};
    for (int i = 0; i < 2; i++)
        pthread_create(&t[i], NULL, run, &sh[i]);
    for (int i = 0; i < 2; i++)
        pthread_join(t[i], NULL);
    for (int i = 0; i < 2; i++) {
        printf("%s shared, renderer %d: %s\n", argv[1], i, same(&alone[0], &sh[i]) ? "identical" : "DIFFERENT");
        bad += !same(&alone[0], &sh[i]);
    }
    rf_scene_free(s);
    for (int i = 0; i < 2; i++) {
        free(alone[i].pixels);
        free(both[i].pixels);
        free(sh[i].pixels);
    }
    return bad != 0;
}
