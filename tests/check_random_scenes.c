/*
 * The renderer under random valid scenes: a generator writes scene text
 * with every primitive, light, material and transform, with extreme but
 * legal values (1e-6 .. 1e6 scales, n up to 1e6, ior from 0.01 to 100, d0 0,
 * lights on surfaces, cameras inside objects), loads it and renders it tiny.
 * Every scene must load, render, and give finite pixels with no non-finite
 * value counted by the tracer.  The seed is fixed, so a failure repeats;
 * the failing scene's text is printed.  (Run under ASan/UBSan by
 * `make check SANITIZE=1`.)
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "testlib.h"
#include "render/render.h"
#include "base/sampler.h"
#include "io/scene_file.h"
#include "scene/scene.h"

enum { SCENES = 150, TEXT_MAX = 16384 };

typedef struct gen {
    uint64_t key;
    uint64_t counter;
    char text[TEXT_MAX];
    size_t len;
} gen;

static double uniform(gen *g)
{
    return sampler_uniform(sampler_key(g->key, g->counter++));
}

static int pick(gen *g, int n)
{
    int k = (int)(uniform(g) * n);
    return k < n ? k : n - 1;
}

/* A magnitude spread over many decades, with exact 0 and 1 now and then. */
static double magnitude(gen *g)
{
    switch (pick(g, 6)) {
    case 0: return 0;
    case 1: return 1;
    default: return pow(10, -6 + 12 * uniform(g));
    }
}

static double signed_value(gen *g, double scale)
{
    return (uniform(g) < 0.5 ? -1 : 1) * scale * uniform(g);
}

static void emit(gen *g, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(g->text + g->len, sizeof g->text - g->len, fmt, ap);
    va_end(ap);
    if (n > 0 && g->len + (size_t)n < sizeof g->text)
        g->len += (size_t)n;
}

static void emit_vector(gen *g, double scale)
{
    emit(g, "[%.17g, %.17g, %.17g]", signed_value(g, scale), signed_value(g, scale), signed_value(g, scale));
}

static void emit_direction(gen *g)
{
    double x, y, z;
    do {
        x = signed_value(g, 1);
        y = signed_value(g, 1);
        z = signed_value(g, 1);
    } while (x * x + y * y + z * z < 1e-6);
    emit(g, "[%.17g, %.17g, %.17g]", x, y, z);
}

static void emit_unit_interval(gen *g)
{
    double v[] = {0, 1, uniform(g)};
    emit(g, "%.17g", v[pick(g, 3)]);
}

static void emit_material(gen *g)
{
    double ior[] = {1, 1.5, 0.01, 100, 1 + 1e-12, 2.4};
    double n[] = {0, 1, 40, 1e6, 1e-3};
    emit(g, "material { Kd ");
    emit_unit_interval(g);
    emit(g, " Ks ");
    emit_unit_interval(g);
    emit(g, " n %.17g t ", n[pick(g, 5)]);
    emit_unit_interval(g);
    emit(g, " ior %.17g }", ior[pick(g, 6)]);
}

static void emit_transforms(gen *g)
{
    int count = pick(g, 3);
    for (int i = 0; i < count; i++) {
        switch (pick(g, 3)) {
        case 0: emit(g, " translate "); emit_vector(g, magnitude(g)); break;
        case 1: emit(g, " rotate "); emit_vector(g, 360); break;
        default: {
            double s[] = {1e-3, -1, 2, 1e3};
            emit(g, " scale [%.17g, %.17g, %.17g]", s[pick(g, 4)], s[pick(g, 4)], s[pick(g, 4)]);
        }
        }
    }
}

static void emit_primitive(gen *g)
{
    double size = magnitude(g) + 1e-6, far = magnitude(g);
    switch (pick(g, 6)) {
    case 0:
        emit(g, "sphere { center ");
        emit_vector(g, far);
        emit(g, " radius %.17g", size);
        break;
    case 1:
        emit(g, "plane { point ");
        emit_vector(g, far);
        emit(g, " normal ");
        emit_direction(g);
        break;
    case 2:
        emit(g, "triangle { vertices [0, 0, 0] [%.17g, 0, 0] [0, %.17g, %.17g]", size, size, signed_value(g, size));
        break;
    case 3:
        emit(g, "disk { center ");
        emit_vector(g, far);
        emit(g, " normal ");
        emit_direction(g);
        emit(g, " radius %.17g", size);
        break;
    case 4:
        emit(g, "box { from [0, 0, 0] to [%.17g, %.17g, %.17g]", size, size * 2, size + 1);
        break;
    default:
        emit(g, "mesh { file \"tests/obj/%s\"", pick(g, 2) ? "tetrahedron.obj" : "cube.obj");
    }
    emit(g, " ");
    emit_material(g);
    emit_transforms(g);
    emit(g, " }\n");
}

static void emit_light(gen *g)
{
    const char *falloff[] = {"linear", "inverse_square", "none"};
    double power = magnitude(g);
    switch (pick(g, 4)) {
    case 0:
        emit(g, "point_light { position ");
        emit_vector(g, magnitude(g));
        break;
    case 1:
        emit(g, "distant_light { direction ");
        emit_direction(g);
        emit(g, " power %.17g }\n", power);
        return;
    case 2:
        emit(g, "distributed_light { rectangle ");
        emit_vector(g, magnitude(g));
        emit(g, " [%.17g, 0, 0] [0, 0, %.17g] samples %d", magnitude(g) + 1e-3, magnitude(g) + 1e-3, 1 + pick(g, 5));
        break;
    default:
        emit(g, "distributed_light { disk ");
        emit_vector(g, magnitude(g));
        emit(g, " ");
        emit_direction(g);
        emit(g, " %.17g samples %d", magnitude(g) + 1e-3, 1 + pick(g, 5));
    }
    emit(g, " power %.17g d0 %.17g falloff %s }\n", power, pick(g, 2) ? 0 : magnitude(g), falloff[pick(g, 3)]);
}

static void generate(gen *g, int index)
{
    g->key = sampler_key(0x72616e64u, (uint64_t)index);
    g->counter = 0;
    g->len = 0;
    g->text[0] = '\0';
    emit(g, "image { width 6 height 4 samples %d max_depth %d background [0.1, 0.2, 0.3] }\n", 1 + pick(g, 2),
         1 + pick(g, 6));
    emit(g, "camera { %s eye ", pick(g, 2) ? "perspective" : "orthographic");
    emit_vector(g, magnitude(g) + 1);
    emit(g, " look_at [0, 0, 0] up [0, 1, 0.001] }\n");
    emit(g, "ambient { color %.17g }\n", magnitude(g));
    for (int i = pick(g, 4); i > 0; i--)
        emit_light(g);
    for (int i = 1 + pick(g, 6); i > 0; i--)
        emit_primitive(g);
}

static int all_finite(const img_buf *img)
{
    for (size_t i = 0; i < 3 * (size_t)img->width * (size_t)img->height; i++)
        if (!isfinite(img->rgb[i]))
            return 0;
    return 1;
}

START_TEST(test_random_valid_scenes_render_finite)
{
    static gen g; /* 16 kB of text: off the stack of the forked test */
    generate(&g, _i);
    int status;
    scene_model *s = scene_file_load_text("random.scene", g.text, g.len, NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "generated scene %d did not load (status %d):\n%s", _i, status, g.text);
    img_buf img;
    render_stats st;
    ck_assert_msg(render_image(s, NULL, &img, &st) == 0, "scene %d did not render:\n%s", _i, g.text);
    ck_assert_msg(all_finite(&img) && st.trace.nonfinite == 0,
                  "scene %d: %ld non-finite values:\n%s", _i, st.trace.nonfinite, g.text);
    img_free(&img);
    scene_free(s);
}
END_TEST

Suite *suite_random_scenes(void)
{
    Suite *s = suite_create("random_scenes");
    TCase *tc = tcase_create("render");
    tcase_set_timeout(tc, 20);
    tcase_add_loop_test(tc, test_random_valid_scenes_render_finite, 0, SCENES);
    suite_add_tcase(s, tc);
    return s;
}
