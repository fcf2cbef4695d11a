/*
 * terminator.c - `make terminator`: the shadow terminator of smooth meshes,
 * measured (spec/shading.md, [SHADE-TERMINATOR-1]).
 *
 * The scene is scenes/analytic/lambert_sphere.scene, a matte sphere of
 * radius 1.2 under a distant light, orthographic view, whose exact image
 * the `lambert_sphere` oracle family gives in closed form, with the light
 * turned to come from above (direction [0.2, -1, 0.25], as in
 * scenes/terminator.scene) so that the terminator crosses the middle of
 * the disk.  The sphere is replaced by
 * the smooth meshes scenes/models/sphere_UxV.obj (scaled by 1.2; exact
 * vertex normals) and each is rendered twice: with shadow rays from the hit
 * point on the flat facet (the seed's way, refray before issue 13) and from
 * Hanika's lifted point (refray).
 *
 * Columns: every render against the exact image over the pixels whose
 * sample points all lie within 0.85 of the radius of the centre (inside
 * every mesh's outline: the coarsest has an inradius of cos(15 deg)
 * cos(22.5 deg) = 0.89 radii): RMS and largest error; the same over the
 * terminator band, those of the pixels whose exact N.L is in (0, 0.3); and
 * the self-shadow: the pixels (of the whole image) where the render differs
 * from the same mesh rendered with no shadow rays at all, and by how much
 * at most.  A convex mesh cannot shadow itself where its shading normal
 * faces the light, so every such pixel is the terminator artefact.  The
 * error that remains after the fix is the mesh's: its facets are not the
 * sphere, and interpolated normals are not the sphere's normals there.
 *
 *   build/terminator [-o DIR]     DIR: where to write the renders (PFM, and
 *                                 PNG when built with libpng)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image/image_file.h"
#include "oracle/oracle.h"
#include "render/render.h"
#include "render/trace.h"
#include "scene/scene.h"

#define SCENE "scenes/analytic/lambert_sphere.scene"
#define LIGHT "distant_light { direction [0.2, -1, 0.25]  power [1, 0.9, 0.8] }"
#define REGION 0.85
#define BAND 0.3

typedef struct measure {
    double rms, max_abs, band_max, shadow_max;
    int pixels, band, shadowed;
} measure;

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *text = calloc(1, 1 << 16);
    if (text)
        fread(text, 1, (1 << 16) - 1, f);
    fclose(f);
    return text;
}

/* The analytic scene with its light turned (LIGHT) and, for a mesh, the
 * sphere statement replaced by the mesh and the `oracle` line left out. */
static scene_model *variant(const char *analytic, const char *mesh)
{
    char *text = malloc(strlen(analytic) + 512), *out = text;
    const char *line = analytic;
    while (*line) {
        size_t n = strcspn(line, "\n");
        if (strncmp(line, "distant_light ", 14) == 0) {
            out += sprintf(out, "%s\n", LIGHT);
        } else if (mesh && strncmp(line, "sphere ", 7) == 0) {
            const char *material = strstr(line, "material");
            out += sprintf(out, "mesh { file \"models/%s.obj\" scale 1.2 %.*s\n", mesh,
                           (int)(line + n - material), material);
        } else if (!mesh || strncmp(line, "oracle ", 7) != 0) {
            memcpy(out, line, n);
            out += n;
            *out++ = '\n';
        }
        line += n + (line[n] == '\n');
    }
    *out = '\0';
    int status;
    scene_model *s = scene_load_text(mesh ? "scenes/terminator.scene" : SCENE, text, strlen(text), NULL, stderr, 1,
                                  &status);
    free(text);
    return s;
}

/* Renders with the tracer's terminator offset on or off (-1: no shadow
 * rays at all). */
static img_buf render(const scene_model *s, int offset)
{
    img_buf img;
    tracer t;
    trace_stats st;
    int w = s->image.width, h = s->image.height, k = s->image.samples;
    memset(&st, 0, sizeof st);
    if (!tracer_init(&t, s, 0, 0) || img_create(&img, w, h) != 0)
        exit(70);
    t.terminator_offset = offset > 0;
    t.shadows &= offset >= 0;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            rgb c = render_pixel(&t, w, h, k, i, j, &st);
            double *p = img_pixel(&img, i, j);
            p[0] = c.x;
            p[1] = c.y;
            p[2] = c.z;
        }
    tracer_free(&t);
    return img;
}

/* Where pixel (i, j) is on the screen, in radii from the sphere's centre
 * (the camera looks at it), and the sphere's N.L at its centre. */
static void pixel_geometry(const scene_model *s, int i, int j, double *r, double *nl)
{
    double half = s->camera.width / 2, radius = 1.2;
    double x = (2 * (i + 0.5) / s->image.width - 1) * half;
    double y = (1 - 2 * (j + 0.5) / s->image.height) * half * s->image.height / s->image.width;
    *r = sqrt(x * x + y * y) / radius;
    *nl = -2;
    if (*r >= 1)
        return;
    vec3 n = vec_make(x / radius, y / radius, sqrt(1 - *r * *r));
    vec3 l = vec_normalize(vec_neg(s->lights[0].direction));
    *nl = vec_dot(n, l);
}

static double pixel_diff(const img_buf *a, const img_buf *b, int i, int j)
{
    double d = 0;
    for (int c = 0; c < 3; c++)
        d = fmax(d, fabs(img_pixel(a, i, j)[c] - img_pixel(b, i, j)[c]));
    return d;
}

/* got against exact in the region and the band; against unshadowed (when
 * not NULL) everywhere. */
static measure compare(const scene_model *s, const img_buf *got, const img_buf *exact, const img_buf *unshadowed,
                       const unsigned char *excluded)
{
    measure m = {0, 0, 0, 0, 0, 0, 0};
    double sum = 0;
    double margin = 1.5 * s->camera.width / s->image.width / 1.2; /* a pixel and a half, in radii */
    for (int j = 0; j < got->height; j++)
        for (int i = 0; i < got->width; i++) {
            double r, nl;
            pixel_geometry(s, i, j, &r, &nl);
            if (unshadowed && pixel_diff(got, unshadowed, i, j) > 1e-12) {
                m.shadowed++;
                m.shadow_max = fmax(m.shadow_max, pixel_diff(got, unshadowed, i, j));
            }
            if (excluded[j * got->width + i] || r > REGION - margin)
                continue;
            double d = pixel_diff(got, exact, i, j);
            m.pixels++;
            sum += d * d;
            m.max_abs = fmax(m.max_abs, d);
            if (nl > 0 && nl < BAND) {
                m.band++;
                m.band_max = fmax(m.band_max, d);
            }
        }
    m.rms = sqrt(sum / (m.pixels > 0 ? m.pixels : 1));
    return m;
}

static void row(const char *name, const char *method, measure m)
{
    printf("| %s | %s | %.3g | %.3g | %.3g | %d | %.3g |\n", name, method, m.rms, m.max_abs, m.band_max, m.shadowed,
           m.shadow_max);
}

static void save(const char *dir, const char *name, const img_buf *img)
{
    char path[512], err[256];
    if (!dir)
        return;
    img_write_opts o = img_write_opts_default();
    for (int k = 0; k < 2; k++) {
        snprintf(path, sizeof path, "%s/%s.%s", dir, name, k ? "png" : "pfm");
        if (img_format_available(img_format_from_path(path)) && img_write(path, img, &o, err, sizeof err) != 0)
            fprintf(stderr, "terminator: %s\n", err);
    }
}

int main(int argc, char **argv)
{
    static const char *const meshes[] = {"sphere_12x8", "sphere_24x16", "sphere_48x32"};
    const char *dir = argc == 3 && strcmp(argv[1], "-o") == 0 ? argv[2] : NULL;
    char *text = read_text(SCENE);
    scene_model *analytic = text ? variant(text, NULL) : NULL;
    if (!analytic) {
        fprintf(stderr, "terminator: cannot load %s (run from the repository root)\n", SCENE);
        return 66;
    }
    const oracle_family *f = oracle_find("lambert_sphere");
    oracle_view v = {analytic, analytic->image.width, analytic->image.height, analytic->image.samples,
                     analytic->image.max_depth};
    img_buf exact, sphere = render(analytic, 1);
    unsigned char *excluded = calloc((size_t)v.width * (size_t)v.height, 1);
    long count;
    if (!excluded || oracle_image(f, &v, &exact, excluded, &count) != 0)
        return 70;
    measure m = compare(analytic, &sphere, &exact, NULL, excluded);
    printf("Shadow terminator: %s with %s, %dx%d pixels, %dx%d samples; errors against the exact image "
           "(lambert_sphere) over %d pixels within %.2f radii, the terminator band (0 < N.L < %.1f) %d of them; "
           "largest over the channels\n\n",
           SCENE, LIGHT, v.width, v.height, v.samples, v.samples, m.pixels, REGION, BAND, m.band);
    printf("| surface | shadow rays from | RMS | max | band max | self-shadowed pixels | by at most |\n"
           "|---|---|---|---|---|---|---|\n");
    row("analytic sphere", "the hit point", m);
    save(dir, "sphere", &sphere);
    for (int k = 0; k < 3; k++) {
        scene_model *s = variant(text, meshes[k]);
        if (!s)
            return 65;
        img_buf before = render(s, 0), after = render(s, 1), none = render(s, -1);
        char name[64];
        row(meshes[k], "the facet (before)", compare(s, &before, &exact, &none, excluded));
        row(meshes[k], "the lifted point (after)", compare(s, &after, &exact, &none, excluded));
        snprintf(name, sizeof name, "%s_before", meshes[k]);
        save(dir, name, &before);
        snprintf(name, sizeof name, "%s_after", meshes[k]);
        save(dir, name, &after);
        img_free(&before);
        img_free(&after);
        img_free(&none);
        scene_free(s);
    }
    img_free(&sphere);
    img_free(&exact);
    free(excluded);
    free(text);
    scene_free(analytic);
    return 0;
}
