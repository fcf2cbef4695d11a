/*
 * render_string.c - refray embedded with no file access and no malloc: a
 * scene held in a string, every allocation of the library from a fixed
 * arena handed over through rf_allocator, the image rendered a band of
 * rows at a time into a buffer of the caller's.
 *
 *   render_string [ARENA_BYTES [SCENE_FILE [ROWS]]]
 *
 * ARENA_BYTES (default 1 MiB) is the arena's size.  SCENE_FILE, when
 * given, is read here, by the program, and handed to the library as a
 * string; ROWS renders only the first ROWS rows (what a render allocates
 * does not depend on how many rows it renders, so `make arena-min` finds
 * the smallest arena for a scene with ROWS 1, quickly).
 * Exit status: 0 rendered, 3 the arena was too small (RF_ERR_NO_MEMORY, a
 * clean failure), 1 any other error.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>

static const char scene_text[] =
    "image  { width 64 height 48 samples 2 background [0.2, 0.3, 0.5] }\n"
    "camera { eye [0, 1.5, 5] look_at [0, 0.5, 0] fov 45 }\n"
    "ambient { color 0.1 }\n"
    "distributed_light { rectangle [-1, 4, -1] [2, 0, 0] [0, 0, 2] power 4 samples 16 }\n"
    "material glass { Kd 0 Ks 0.1 n 200 t 0.9 ior 1.5 }\n"
    "plane  { normal [0, 1, 0] material { Kd 0.7 } }\n"
    "sphere { center [0, 1, 0] radius 1 material glass }\n"
    "for i in 0 .. 4 { sphere { center [i - 2, 0.25, -2] radius 0.25 material { Kd [0.8, 0.3, 0.2] } } }\n";

/* A bump allocator over a fixed block: blocks are handed out in order and
 * only the last one can be given back (or grown in place), which is all
 * the library needs of it.  The sizes the library passes on release make
 * that possible without a header per block. */
typedef struct arena {
    unsigned char *base;
    size_t size, used, last, peak;
} arena;

static size_t align_up(size_t n)
{
    return (n + 15) / 16 * 16;
}

static void *arena_alloc(void *user, size_t size)
{
    arena *a = user;
    size_t at = align_up(a->used);
    if (at > a->size || size > a->size - at)
        return NULL;
    a->last = at;
    a->used = at + size;
    if (a->used > a->peak)
        a->peak = a->used;
    return a->base + at;
}

static void *arena_resize(void *user, void *p, size_t old_size, size_t new_size)
{
    arena *a = user;
    unsigned char *q = p;
    if (q == a->base + a->last && a->last + old_size == a->used && new_size <= a->size - a->last) {
        a->used = a->last + new_size;
        if (a->used > a->peak)
            a->peak = a->used;
        return p;
    }
    void *fresh = arena_alloc(user, new_size);
    if (fresh)
        memcpy(fresh, p, old_size < new_size ? old_size : new_size);
    return fresh;
}

static void arena_release(void *user, void *p, size_t size)
{
    arena *a = user;
    if ((unsigned char *)p == a->base + a->last && a->last + size == a->used)
        a->used = a->last;
}

/* SCENE_FILE read whole, by this program; NULL when it cannot be. */
static char *read_text(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    char *text = NULL;
    long n;
    if (f && fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (text = malloc((size_t)n + 1)) != NULL && fread(text, 1, (size_t)n, f) == (size_t)n) {
        *size = (size_t)n;
    } else {
        free(text);
        text = NULL;
    }
    if (f)
        fclose(f);
    return text;
}

static int render(const rf_scene *scene, float *rgb, int width, int height, int rows)
{
    height = rows > 0 && rows < height ? rows : height;
    rf_renderer *r;
    rf_status status = rf_renderer_create(scene, NULL, &r);
    for (int y = 0; status == RF_OK && y < height; y += 16) {
        int y1 = y + 16 < height ? y + 16 : height;
        status = rf_render_region(r, 0, y, width, y1, rgb + (size_t)y * 3 * (size_t)width, 3 * (size_t)width);
    }
    rf_renderer_free(r);
    return status;
}

int main(int argc, char **argv)
{
    size_t size = argc > 1 ? strtoul(argv[1], NULL, 10) : (size_t)1 << 20;
    size_t text_size = sizeof scene_text - 1;
    char *file_text = argc > 2 ? read_text(argv[2], &text_size) : NULL;
    arena a = {NULL, size, 0, 0, 0};
    if ((argc > 2 && !file_text) || !(a.base = malloc(size ? size : 1))) {
        fprintf(stderr, "render_string: cannot read the scene or make the arena\n");
        return 1;
    }
    rf_allocator alloc = {arena_alloc, arena_resize, arena_release, &a};
    rf_load_options o;
    rf_load_options_init(&o);
    o.allocator = &alloc;
    o.diagnostic = rf_diagnostic_print;
    o.diagnostic_user = stderr;
    rf_scene *scene;
    float *rgb = NULL;
    rf_scene_info info;
    rf_status status = rf_scene_load_memory(argc > 2 ? argv[2] : "string.scene", file_text ? file_text : scene_text,
                                            text_size, &o, &scene);
    if (status == RF_OK) {
        rf_scene_get_info(scene, &info);
        rgb = malloc((size_t)info.width * (size_t)info.height * 3 * sizeof *rgb);
        status = rgb ? render(scene, rgb, info.width, info.height, argc > 3 ? atoi(argv[3]) : 0)
                     : RF_ERR_NO_MEMORY;
        rf_scene_free(scene);
    }
    if (status == RF_OK) {
        const float *c = rgb + 3 * ((size_t)(info.height / 2) * (size_t)info.width + (size_t)(info.width / 2));
        if (argc > 3)
            c = rgb;
        printf("rendered %dx%d; %s pixel %.4f %.4f %.4f; arena peak %zu of %zu bytes\n", info.width, info.height,
               argc > 3 ? "first" : "centre", c[0], c[1], c[2], a.peak, a.size);
    } else {
        printf("not rendered: %s (arena of %zu bytes, %zu used at most)\n", rf_status_string(status), a.size,
               a.peak);
    }
    free(rgb);
    free(a.base);
    free(file_text);
    return status == RF_OK ? 0 : status == RF_ERR_NO_MEMORY ? 3 : 1;
}
