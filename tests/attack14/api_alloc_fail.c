/* api_alloc_fail.c - every allocation of a load, a render and a write made
 * to fail in turn.
 *
 * An allocator that fails its N-th request (alloc, or a resize that grows),
 * for N = 1, 2, ... until a whole run succeeds.  Each run loads a scene
 * that includes a file and reads an OBJ mesh through a resolver, renders a
 * region and a whole image, and writes it as PNG, PFM and EXR to a pipe
 * (an EXR to a stream that cannot seek is built from the allocator).
 * refray.h: "Out of memory is always RF_ERR_NO_MEMORY.  On failure no
 * output handle is set (it is NULL) and nothing is left to free."  Checked:
 * every status is RF_OK or RF_ERR_NO_MEMORY, every block is released with
 * the size it was given, nothing is left at the end, and a run that
 * succeeds has the reference pixels.  Exit 1 on the first breach. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>

struct arena { long n, fail_at, live; size_t bytes; int bad_size; };

/* A header before each block holds its size, so that release can check it. */
static void *a_alloc(void *u, size_t size)
{
    struct arena *a = u;
    if (++a->n == a->fail_at)
        return NULL;
    size_t *p = malloc(size + 16);
    if (!p)
        return NULL;
    p[0] = size;
    a->live++;
    a->bytes += size;
    return (char *)p + 16;
}

static void a_release(void *u, void *q, size_t size)
{
    struct arena *a = u;
    if (!q)
        return;
    size_t *p = (size_t *)((char *)q - 16);
    if (p[0] != size)
        a->bad_size = 1;
    a->live--;
    a->bytes -= p[0];
    free(p);
}

static void *a_resize(void *u, void *q, size_t old_size, size_t new_size)
{
    struct arena *a = u;
    size_t *p = (size_t *)((char *)q - 16);
    if (p[0] != old_size)
        a->bad_size = 1;
    if (new_size > old_size && ++a->n == a->fail_at)
        return NULL;
    size_t *n = realloc(p, new_size + 16);
    if (!n)
        return NULL;
    n[0] = new_size;
    a->bytes += new_size - old_size;
    return (char *)n + 16;
}

static const char main_scene[] =
    "include \"mat.scene\"\n"
    "image { width 12 height 8 samples 2 max_depth 5 background [0.1, 0.2, 0.3] }\n"
    "camera { perspective eye [0, 1, -5] look_at [0, 0.5, 0] up [0, 1, 0] fov 45 }\n"
    "ambient { color [0.2, 0.2, 0.2] }\n"
    "point_light { position [5, 10, -5] power 60 d0 1 falloff linear }\n"
    "distributed_light { disk [0, 5, 0] [0, -1, 0] 1 power 5 samples 4 d0 1 falloff linear }\n"
    "for i in 0 .. 3 { sphere { center [i - 1.5, 0.3, 1] radius 0.3 material red } }\n"
    "mesh { file \"quad.obj\" material glass }\n"
    "torus { center [1.5, 0.3, 0] axis [0, 1, 0] major 0.5 minor 0.15 material red }\n"
    "plane { point [0, 0, 0] normal [0, 1, 0] material red }\n";
static const char mat_scene[] =
    "material red { Kd [0.8, 0.1, 0.1] Ks 0.3 n 40 }\n"
    "material glass { Kd 0 Ks 0.1 n 200 t 0.9 ior 1.5 }\n";
static const char quad_obj[] =
    "v -1 0 0\nv 1 0 0\nv 1 2 0.5\nv -1 2 0.5\nv 0 1 -0.3\n"
    "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 1 2 3 4\n";

static rf_status fetch(void *u, const char *from, const char *name, rf_source *out, char *m, size_t ms)
{
    (void)u; (void)from; (void)m; (void)ms;
    memset(out, 0, sizeof *out);
    if (strcmp(name, "mat.scene") == 0) {
        out->text = mat_scene;
        out->size = strlen(mat_scene);
    } else if (strcmp(name, "quad.obj") == 0) {
        out->text = quad_obj;
        out->size = strlen(quad_obj);
    } else
        return RF_ERR_NO_INPUT;
    return RF_OK;
}

static int ok_or_nomem(rf_status s) { return s == RF_OK || s == RF_ERR_NO_MEMORY; }

/* One run; returns the first status that was not RF_OK (RF_OK: all went
 * through) or -1 for a breach, printed. */
static int run(struct arena *a, const float *ref, float *px)
{
    rf_allocator al = {a_alloc, a_resize, a_release, a};
    rf_load_options lo;
    rf_load_options_init(&lo);
    lo.allocator = &al;
    lo.resolver.fetch = fetch;
    rf_scene *sc = (rf_scene *)&lo;            /* must become NULL on failure */
    rf_status s = rf_scene_load_memory("main.scene", main_scene, strlen(main_scene), &lo, &sc);
    if (!ok_or_nomem(s) || (s != RF_OK && sc != NULL)) {
        printf("load: %s, handle %p\n", rf_status_string(s), (void *)sc);
        return -1;
    }
    if (s != RF_OK)
        return s;
    rf_renderer *r = (rf_renderer *)&lo;
    s = rf_renderer_create(sc, NULL, &r);
    if (!ok_or_nomem(s) || (s != RF_OK && r != NULL)) {
        printf("renderer_create: %s\n", rf_status_string(s));
        return -1;
    }
    rf_status result = s;
    if (s == RF_OK) {
        s = rf_render_region(r, 0, 0, 12, 8, px, 36);
        if (s != RF_OK) {
            printf("render_region (allocates nothing): %s\n", rf_status_string(s));
            return -1;
        }
        if (ref && memcmp(px, ref, 12 * 8 * 3 * sizeof *px) != 0) {
            printf("render_region: pixels differ from the reference\n");
            return -1;
        }
        rf_renderer_free(r);
        rf_image *img = (rf_image *)&lo;
        s = rf_render_image(sc, NULL, &img, NULL);
        if (!ok_or_nomem(s) || (s != RF_OK && img != NULL)) {
            printf("render_image: %s\n", rf_status_string(s));
            return -1;
        }
        result = s;
        if (s == RF_OK) {
            static const rf_format fmts[] = {RF_FORMAT_PNG, RF_FORMAT_PFM, RF_FORMAT_EXR};
            for (int f = 0; f < 3 && result == RF_OK; f++) {
                FILE *pipe = popen("cat > /dev/null", "w");
                char msg[256] = "";
                s = rf_image_write_stream(img, pipe, fmts[f], NULL, NULL, msg, sizeof msg);
                pclose(pipe);
                if (!ok_or_nomem(s)) {
                    printf("write_stream format %d: %s (%s)\n", (int)fmts[f], rf_status_string(s), msg);
                    return -1;
                }
                result = s;
            }
            rf_image_free(img);
        }
    }
    rf_scene_free(sc);
    return result;
}

int main(void)
{
    static float ref[12 * 8 * 3], px[12 * 8 * 3];
    struct arena a;
    memset(&a, 0, sizeof a);
    if (run(&a, NULL, ref) != RF_OK || a.live != 0) {
        printf("the run without failures did not succeed\n");
        return 2;
    }
    long total = a.n;
    for (long n = 1; n <= total + 1; n++) {
        memset(&a, 0, sizeof a);
        a.fail_at = n;
        int s = run(&a, ref, px);
        if (s < 0 || a.live != 0 || a.bad_size) {
            printf("allocation %ld of %ld failed: %s; blocks left %ld (%zu bytes); a release with another size: %s\n",
                   n, total, s < 0 ? "a breach (above)" : rf_status_string((rf_status)s), a.live, a.bytes,
                   a.bad_size ? "yes" : "no");
            return 1;
        }
    }
    printf("%ld allocations, each made to fail in turn: RF_ERR_NO_MEMORY or RF_OK, nothing left\n", total);
    return 0;
}
