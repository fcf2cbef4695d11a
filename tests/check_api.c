/*
 * check_api.c - the public API (include/refray.h) as an embedding program
 * uses it: this file includes refray.h and nothing of src/.  Expected
 * pixels are derived by hand: an orthographic view straight down at a
 * plane with Kd 0.5 under ambient 0.2 and a distant light from straight
 * above of power 2 is 0.5 * 0.2 + 0.5 * 2 * 1 = 1.1 everywhere
 * (spec/shading.md).  IDs: spec/embedding.md.
 */
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <check.h>
#include "memcheck.h"
#include "refray.h"

static const char plane_text[] =
    "image { width 4 height 3 }\n"
    "camera { orthographic eye [0, 1, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
    "ambient { color 0.2 }\n"
    "distant_light { direction [0, -1, 0] power 2 }\n"
    "plane { material { Kd 0.5 } }\n";

/* Scene `name` from text under options o (NULL: defaults); the load must
 * succeed. */
static rf_scene *load_named(const char *name, const char *text, const rf_load_options *o)
{
    rf_scene *s = NULL;
    ck_assert_int_eq(rf_scene_load_memory(name, text, strlen(text), o, &s), RF_OK);
    ck_assert_ptr_nonnull(s);
    return s;
}

static rf_scene *load(const char *text, const rf_load_options *o)
{
    return load_named("api.scene", text, o);
}

/* A renderer of s under options o (NULL: defaults); it must be made. */
static rf_renderer *renderer(const rf_scene *s, const rf_render_options *o)
{
    rf_renderer *r = NULL;
    ck_assert_int_eq(rf_renderer_create(s, o, &r), RF_OK);
    return r;
}

/* The summary of s. */
static rf_scene_info info_of(const rf_scene *s)
{
    rf_scene_info i;
    rf_scene_get_info(s, &i);
    return i;
}

/* [EMBED-API-1] The version macros and calls agree; every status has its
 * own name. */
START_TEST(test_api_version_and_status)
{
    char want[32];
    snprintf(want, sizeof want, "%d.%d.%d", RF_VERSION_MAJOR, RF_VERSION_MINOR, RF_VERSION_PATCH);
    ck_assert_str_eq(rf_version(), want);
    ck_assert_str_eq(RF_VERSION_STRING, want);
    ck_assert_int_eq(rf_version_number(), RF_VERSION_MAJOR * 10000 + RF_VERSION_MINOR * 100 + RF_VERSION_PATCH);
    ck_assert_str_eq(rf_status_string(RF_OK), "success");
    ck_assert_str_eq(rf_status_string(RF_ERR_NO_MEMORY), "out of memory");
    for (int a = RF_OK; a <= RF_ERR_CHECK; a++)
        for (int b = a + 1; b <= RF_ERR_CHECK; b++)
            ck_assert_str_ne(rf_status_string((rf_status)a), rf_status_string((rf_status)b));
}
END_TEST

/* [EMBED-API-2] A scene from a string, rendered into a float buffer with a
 * row stride wider than the region; every pixel is 1.1, the padding is
 * left alone. */
START_TEST(test_api_render_region)
{
    rf_scene *s = load(plane_text, NULL);
    rf_renderer *r = renderer(s, NULL);
    int w, h;
    rf_renderer_size(r, &w, &h);
    ck_assert_int_eq(w, 4);
    ck_assert_int_eq(h, 3);
    enum { STRIDE = 16 };
    float buf[3 * STRIDE];
    for (int i = 0; i < 3 * STRIDE; i++)
        buf[i] = -7.0f;
    ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 3, buf, STRIDE), RF_OK);
    for (int y = 0; y < 3; y++)
        for (int i = 0; i < STRIDE; i++)
            ck_assert_float_eq(buf[y * STRIDE + i], i < 12 ? 1.1f : -7.0f);
    rf_render_stats st;
    rf_renderer_stats(r, &st);
    ck_assert_int_eq(st.camera_rays, 12);
    ck_assert_int_eq(st.width, 4);
    rf_renderer_free(r);
    rf_scene_free(s);
}
END_TEST

/* The demo scene, with options *o for a 12 x 8 image of it. */
static rf_scene *load_demo_12x8(rf_render_options *o)
{
    rf_scene *s = NULL;
    ck_assert_int_eq(rf_scene_load_file("scenes/demo.scene", NULL, &s), RF_OK);
    rf_render_options_init(o);
    o->width = 12;
    o->height = 8;
    return s;
}

/* A pixel does not depend on the region it is rendered in: the demo scene
 * in 2 x 2 tiles equals the demo scene in one piece, bit for bit. */
START_TEST(test_api_regions_tile_the_image)
{
    rf_render_options o;
    rf_scene *s = load_demo_12x8(&o);
    rf_renderer *r = renderer(s, &o);
    float whole[8 * 12 * 3], tiled[8 * 12 * 3];
    ck_assert_int_eq(rf_render_region(r, 0, 0, 12, 8, whole, 36), RF_OK);
    ck_assert_int_eq(rf_render_region(r, 0, 0, 5, 3, tiled, 36), RF_OK);
    ck_assert_int_eq(rf_render_region(r, 5, 0, 12, 3, tiled + 15, 36), RF_OK);
    ck_assert_int_eq(rf_render_region(r, 0, 3, 5, 8, tiled + 3 * 36, 36), RF_OK);
    ck_assert_int_eq(rf_render_region(r, 5, 3, 12, 8, tiled + 3 * 36 + 15, 36), RF_OK);
    ck_assert_int_eq(memcmp(whole, tiled, sizeof whole), 0);
    rf_renderer_free(r);
    rf_scene_free(s);
}
END_TEST

/* A radiance beyond the float range arrives as FLT_MAX, not infinity:
 * 0.5 * 1e300 under a distant light straight above. */
START_TEST(test_api_region_float_saturates)
{
    static const char text[] = "image { width 2 height 1 }\n"
                               "camera { orthographic eye [0, 1, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
                               "distant_light { direction [0, -1, 0] power 1e300 }\n"
                               "plane { material { Kd 0.5 } }\n";
    rf_scene *s = load(text, NULL);
    rf_renderer *r = renderer(s, NULL);
    float px[6];
    ck_assert_int_eq(rf_render_region(r, 0, 0, 2, 1, px, 6), RF_OK);
    for (int i = 0; i < 6; i++)
        ck_assert_float_eq(px[i], FLT_MAX);
    rf_renderer_free(r);
    rf_scene_free(s);
}
END_TEST

/* [EMBED-API-9] A double region holds exactly what rf_render_image stores
 * for its pixels, and rf_render_region's floats are those doubles rounded
 * to nearest (the demo in two regions, 12 x 8). */
START_TEST(test_api_region_double_is_the_image)
{
    rf_render_options o;
    rf_scene *s = load_demo_12x8(&o);
    rf_image *img;
    ck_assert_int_eq(rf_render_image(s, &o, &img, NULL), RF_OK);
    rf_renderer *r = renderer(s, &o);
    double px[8 * 12 * 3];
    float f[8 * 12 * 3];
    ck_assert_int_eq(rf_render_region_double(r, 0, 0, 12, 5, px, 36), RF_OK);
    ck_assert_int_eq(rf_render_region_double(r, 0, 5, 12, 8, px + 5 * 36, 36), RF_OK);
    ck_assert_int_eq(rf_render_region(r, 0, 0, 12, 8, f, 36), RF_OK);
    ck_assert_int_eq(memcmp(px, rf_image_pixels(img), sizeof px), 0);
    for (int i = 0; i < 8 * 12 * 3; i++)
        ck_assert_msg(f[i] == (float)px[i], "value %d", i);
    ck_assert_int_eq(rf_render_region_double(r, 0, 0, 13, 1, px, 39), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_region_double(r, 0, 0, 12, 1, NULL, 36), RF_ERR_USAGE);
    rf_renderer_free(r);
    rf_image_free(img);
    rf_scene_free(s);
}
END_TEST

/* The fingerprint of plane_text with the given text and options. */
static unsigned long long fingerprint(const char *name, const char *text, int width, int samples, int depth,
                                      int light_samples)
{
    rf_scene *s = load_named(name, text, NULL);
    rf_render_options o;
    rf_render_options_init(&o);
    o.width = width;
    o.samples = samples;
    o.max_depth = depth;
    o.light_samples = light_samples;
    rf_renderer *r = renderer(s, &o);
    unsigned long long f = rf_renderer_fingerprint(r);
    rf_renderer_free(r);
    rf_scene_free(s);
    return f;
}

/* [EMBED-API-8] The fingerprint follows the scene's text and the settings
 * that change pixels, not the scene's name. */
START_TEST(test_api_fingerprint)
{
    static const char other[] = "image { width 4 height 3 }\n"
                                "camera { orthographic eye [0, 1, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
                                "ambient { color 0.2 }\n"
                                "distant_light { direction [0, -1, 0] power 2 }\n"
                                "plane { material { Kd 0.5 } } # a comment\n";
    unsigned long long base = fingerprint("a.scene", plane_text, 0, 0, 0, 0);
    ck_assert(base == fingerprint("elsewhere/b.scene", plane_text, 0, 0, 0, 0));
    ck_assert(base == fingerprint("a.scene", plane_text, 4, 1, 0, 0));
    ck_assert(base != fingerprint("a.scene", other, 0, 0, 0, 0));
    ck_assert(base != fingerprint("a.scene", plane_text, 5, 0, 0, 0));
    ck_assert(base != fingerprint("a.scene", plane_text, 0, 2, 0, 0));
    ck_assert(base != fingerprint("a.scene", plane_text, 0, 0, 1, 0));
    ck_assert(base != fingerprint("a.scene", plane_text, 0, 0, 0, 3));
}
END_TEST

/* Bad regions and options are refused before anything is traced. */
START_TEST(test_api_render_region_refusals)
{
    rf_scene *s = load(plane_text, NULL);
    rf_renderer *r = renderer(s, NULL);
    float buf[64];
    ck_assert_int_eq(rf_render_region(r, 0, 0, 5, 1, buf, 15), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 4, buf, 12), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_region(r, 2, 0, 2, 1, buf, 12), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_region(r, -1, 0, 2, 1, buf, 12), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 1, buf, 11), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 1, NULL, 12), RF_ERR_USAGE);
    /* A stride whose second row lies past PTRDIFF_MAX bytes: refused, and
     * nothing written around the buffer (attack 10, finding 4: SIZE_MAX / 2
     * floats wrapped the byte address to pixels[-1], and returned RF_OK). */
    float guard[64];
    double guard_d[64];
    static const size_t strides[] = {(size_t)-1 / 2, (size_t)-1 / 4 + 1, (size_t)PTRDIFF_MAX / sizeof(float) + 1,
                                     (size_t)-1 / 8 + 1};
    for (size_t i = 0; i < sizeof strides / sizeof strides[0]; i++) {
        for (int k = 0; k < 64; k++)
            guard[k] = 7.0f, guard_d[k] = 7.0;
        ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 2, guard + 32, strides[i]), RF_ERR_USAGE);
        ck_assert_int_eq(rf_render_region_double(r, 0, 0, 4, 2, guard_d + 32, strides[i]), RF_ERR_USAGE);
        for (int k = 0; k < 64; k++)
            ck_assert_msg(guard[k] == 7.0f && guard_d[k] == 7.0, "stride %zu wrote element %d", strides[i], k - 32);
    }
    rf_renderer_free(r);
    rf_render_options o;
    rf_render_options_init(&o);
    o.samples = -1;
    r = (rf_renderer *)&o;
    ck_assert_int_eq(rf_renderer_create(s, &o, &r), RF_ERR_USAGE);
    ck_assert_ptr_null(r);
    /* [EMBED-STACK-1] max_depth's ceiling (1000), and the ceiling itself. */
    rf_render_options_init(&o);
    o.max_depth = 1001;
    ck_assert_int_eq(rf_renderer_create(s, &o, &r), RF_ERR_USAGE);
    ck_assert_ptr_null(r);
    o.max_depth = 1000;
    ck_assert_int_eq(rf_renderer_create(s, &o, &r), RF_OK);
    rf_renderer_free(r);
    rf_scene_free(s);
}
END_TEST

/* Neither a renderer nor an image is made for scene with o: want, and the
 * out pointers (set to something else first) NULL. */
static void assert_not_made(const rf_scene *scene, const rf_render_options *o, rf_status want)
{
    rf_renderer *r = (rf_renderer *)&r;
    ck_assert_int_eq(rf_renderer_create(scene, o, &r), want);
    ck_assert_ptr_null(r);
    rf_image *img = (rf_image *)&img;
    ck_assert_int_eq(rf_render_image(scene, o, &img, NULL), want);
    ck_assert_ptr_null(img);
}

/* [EMBED-API-11] An image size a host overrides is held to the limits the
 * scene was loaded with, as the scene's own size was: over max_pixels,
 * max_width or max_height the renderer is refused (RF_ERR_USAGE, no
 * renderer, no image); at the limits it is made.  With the default limits
 * 8192 x 8192 is exactly the 67,108,864 pixels allowed, 8193 x 8192 one
 * row over. */
START_TEST(test_api_size_override_limits)
{
    rf_load_options lo;
    rf_load_options_init(&lo);
    rf_scene *s = load(plane_text, &lo);
    rf_render_options o;
    rf_render_options_init(&o);
    o.width = 8193;
    o.height = 8192;
    assert_not_made(s, &o, RF_ERR_USAGE);
    rf_scene_free(s);
    lo.limits.max_pixels = 100;
    lo.limits.max_width = 20;
    lo.limits.max_height = 10;
    s = load(plane_text, &lo);
    static const int sizes[][3] = {
        /* width, height, made */
        {10, 10, 1}, {20, 5, 1}, {0, 0, 1}, {11, 10, 0}, {21, 1, 0}, {1, 11, 0}, {0, 34, 0}, {25, 0, 0}, {0, 10, 1},
    };
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        o.width = sizes[i][0];
        o.height = sizes[i][1];
        rf_renderer *r = NULL;
        ck_assert_msg(rf_renderer_create(s, &o, &r) == (sizes[i][2] ? RF_OK : RF_ERR_USAGE), "%dx%d", o.width,
                      o.height);
        ck_assert_int_eq(r != NULL, sizes[i][2]);
        rf_renderer_free(r);
    }
    rf_scene_free(s);
    /* The camera and light samples and the depth too (attack 10, finding 5:
     * samples INT_MAX, 2^62 camera rays a pixel, was accepted). */
    rf_load_options_init(&lo);
    lo.limits.max_samples = 4;
    lo.limits.max_light_samples = 9;
    lo.limits.max_depth = 7;
    s = load(plane_text, &lo);
    static const int counts[][4] = {
        /* samples, light_samples, max_depth, made */
        {4, 9, 7, 1}, {0, 0, 0, 1}, {5, 0, 0, 0}, {0, 10, 0, 0}, {0, 0, 8, 0}, {2147483647, 0, 0, 0},
        {0, 2147483647, 0, 0},
    };
    rf_render_options_init(&o);
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        o.samples = counts[i][0];
        o.light_samples = counts[i][1];
        o.max_depth = counts[i][2];
        if (counts[i][3]) {
            rf_renderer *r = NULL;
            ck_assert_int_eq(rf_renderer_create(s, &o, &r), RF_OK);
            rf_renderer_free(r);
        } else
            assert_not_made(s, &o, RF_ERR_USAGE);
    }
    rf_scene_free(s);
}
END_TEST

/* [LANG-EXTENT-1] [EMBED-API-11] A size a host overrides is held to the
 * scene's extent as the scene's own size was: an orthographic camera 2^487
 * wide (eye 0, up (0, 1, 0)) reaches 2^500 exactly at 1 x 16384 pixels and
 * passes it at 1 x 16385 (with --max-height raised), where the renderer is
 * refused with RF_ERR_DATA and nothing is made. */
START_TEST(test_api_size_override_keeps_the_view_in_the_extent)
{
    static const char text[] = "image { width 1 height 1 }\n"
                               "camera { orthographic eye [0, 0, 0] look_at [0, 0, -1] up [0, 1, 0] width 2 ^ 487 }\n"
                               "plane { point [0, 0, -1] normal [0, 0, 1] }\n";
    rf_load_options lo;
    rf_load_options_init(&lo);
    lo.limits.max_height = 20000;
    rf_scene *s = load(text, &lo);
    rf_render_options o;
    rf_render_options_init(&o);
    o.width = 1;
    o.height = 16385;
    assert_not_made(s, &o, RF_ERR_DATA);
    o.height = 16384;
    rf_renderer *r = NULL;
    ck_assert_int_eq(rf_renderer_create(s, &o, &r), RF_OK);
    rf_renderer_free(r);
    rf_scene_free(s);
}
END_TEST

/* [EMBED-API-NULL-1] A NULL the reference does not allow comes back as
 * RF_ERR_USAGE (the out pointer, when there is one, set to NULL) instead
 * of a crash; a stride so large that the last row's end wraps around
 * size_t is refused like a short one; and limits above INT_MAX cannot let
 * a width of 3e9 wrap to a negative int (every one of these crashed,
 * passed or wrapped before). */
START_TEST(test_api_null_arguments)
{
    rf_scene *s = (rf_scene *)&s;
    rf_renderer *r = (rf_renderer *)&r;
    rf_image *img = (rf_image *)&img;
    char msg[64] = "x";
    float buf[24];
    ck_assert_int_eq(rf_scene_load_memory(NULL, plane_text, strlen(plane_text), NULL, &s), RF_ERR_USAGE);
    ck_assert_ptr_null(s);
    ck_assert_int_eq(rf_scene_load_memory("a.scene", NULL, 10, NULL, &s), RF_ERR_USAGE);
    ck_assert_int_eq(rf_scene_load_memory("a.scene", plane_text, strlen(plane_text), NULL, NULL), RF_ERR_USAGE);
    s = (rf_scene *)&s;
    ck_assert_int_eq(rf_scene_load_file(NULL, NULL, &s), RF_ERR_USAGE);
    ck_assert_ptr_null(s);
    ck_assert_int_eq(rf_scene_load_file("a.scene", NULL, NULL), RF_ERR_USAGE);
    ck_assert_int_eq(rf_renderer_create(NULL, NULL, &r), RF_ERR_USAGE);
    ck_assert_ptr_null(r);
    ck_assert_int_eq(rf_render_image(NULL, NULL, &img, NULL), RF_ERR_USAGE);
    ck_assert_ptr_null(img);
    ck_assert_int_eq(rf_render_region(NULL, 0, 0, 1, 1, buf, 3), RF_ERR_USAGE);
    ck_assert_int_eq(rf_image_create(2, 2, NULL, NULL), RF_ERR_USAGE);
    ck_assert_int_eq(rf_image_write(NULL, "x.pfm", NULL, NULL, msg, sizeof msg), RF_ERR_USAGE);
    ck_assert_str_eq(msg, "no image to write");
    rf_scene_info info;
    info.width = 7;
    rf_scene_get_info(NULL, &info);
    ck_assert_int_eq(info.width, 0);

    s = load(plane_text, NULL);
    ck_assert_int_eq(rf_renderer_create(s, NULL, NULL), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_image(s, NULL, NULL, NULL), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_image(s, NULL, &img, NULL), RF_OK);
    ck_assert_int_eq(rf_image_write(img, NULL, NULL, NULL, msg, sizeof msg), RF_ERR_USAGE);
    ck_assert_str_eq(msg, "no path to write to");
    ck_assert_int_eq(rf_image_write_stream(img, NULL, RF_FORMAT_PFM, NULL, NULL, msg, sizeof msg), RF_ERR_USAGE);
    ck_assert_str_eq(msg, "no stream to write to");
    rf_image_free(img);
    r = renderer(s, NULL);
    ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 2, buf, (size_t)-1), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 2, buf, 12), RF_OK);
    rf_renderer_free(r);
    rf_scene_free(s);

    static const char wide[] = "image { width 3000000000 height 1 }\n"
                               "camera { orthographic eye [0, 1, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
                               "plane { }\n";
    rf_load_options o;
    rf_load_options_init(&o);
    o.limits.max_width = o.limits.max_pixels = (long)(~0UL >> 1);
    s = (rf_scene *)&s;
    ck_assert_int_eq(rf_scene_load_memory("wide.scene", wide, strlen(wide), &o, &s), RF_ERR_DATA);
    ck_assert_ptr_null(s);
}
END_TEST

/* [EMBED-API-NULL-1] Every rf_ function, each NULL argument in turn: a
 * call that returns a status returns RF_ERR_USAGE; one that returns a
 * value returns 0 (NULL, RF_FORMAT_UNKNOWN); one that fills a record
 * fills zeros; an init or free does nothing.  rf_renderer_size and
 * rf_renderer_fingerprint of NULL crashed before; Check's fork mode turns
 * a crash here into a failed test. */
START_TEST(test_api_null_everywhere)
{
    rf_scene *s = load(plane_text, NULL);
    rf_renderer *r;
    ck_assert_int_eq(rf_renderer_create(s, NULL, &r), RF_OK);
    int w = 7, h = 7;
    rf_renderer_size(NULL, &w, &h);
    ck_assert_int_eq(w, 0);
    ck_assert_int_eq(h, 0);
    rf_renderer_size(r, NULL, NULL);
    rf_renderer_size(r, &w, NULL);
    ck_assert_int_eq(w, 4);
    ck_assert_uint_eq(rf_renderer_fingerprint(NULL), 0);
    ck_assert_uint_ne(rf_renderer_fingerprint(r), 0);
    rf_render_stats st;
    memset(&st, 0xff, sizeof st);
    rf_renderer_stats(NULL, &st);
    ck_assert_int_eq(st.width, 0);
    ck_assert_int_eq(st.camera_rays, 0);
    rf_renderer_stats(r, NULL);
    double dbuf[24];
    ck_assert_int_eq(rf_render_region_double(NULL, 0, 0, 1, 1, dbuf, 3), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_region_double(r, 0, 0, 1, 1, NULL, 3), RF_ERR_USAGE);
    ck_assert_int_eq(rf_render_region(r, 0, 0, 1, 1, NULL, 3), RF_ERR_USAGE);
    rf_renderer_free(r);
    rf_renderer_free(NULL);

    rf_mesh_info m;
    ck_assert_int_eq(rf_scene_get_mesh_info(NULL, 0, &m), RF_ERR_USAGE);
    ck_assert_int_eq(rf_scene_get_mesh_info(s, 0, NULL), RF_ERR_USAGE);
    rf_scene_get_info(s, NULL);
    rf_scene_free(s);
    rf_scene_free(NULL);

    ck_assert_int_eq(rf_image_width(NULL), 0);
    ck_assert_int_eq(rf_image_height(NULL), 0);
    ck_assert_ptr_null(rf_image_pixels(NULL));
    rf_image_free(NULL);
    ck_assert_int_eq(rf_format_from_path(NULL), RF_FORMAT_UNKNOWN);
    rf_load_options_init(NULL);
    rf_render_options_init(NULL);
    rf_write_options_init(NULL);
    rf_diagnostic_print(NULL, NULL);
    rf_diagnostic_print(stderr, NULL);
    ck_assert_ptr_nonnull(rf_status_string((rf_status)-1));
    ck_assert_ptr_nonnull(rf_status_string((rf_status)1000));
    ck_assert_int_eq(rf_image_write(NULL, NULL, NULL, NULL, NULL, 0), RF_ERR_USAGE);
    ck_assert_int_eq(rf_image_write_stream(NULL, NULL, RF_FORMAT_PFM, NULL, NULL, NULL, 0), RF_ERR_USAGE);
}
END_TEST

/* The plane scene, one region, with the shortcuts on or off. */
static void render_plane(int no_shortcuts, float *px, rf_render_stats *st)
{
    rf_scene *s = load(plane_text, NULL);
    rf_render_options o;
    rf_render_options_init(&o);
    o.no_shortcuts = no_shortcuts;
    rf_renderer *r = renderer(s, &o);
    ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 3, px, 12), RF_OK);
    rf_renderer_stats(r, st);
    rf_renderer_free(r);
    rf_scene_free(s);
}

/* [EMBED-API-10] [SHADE-SHORTCUT-OFF-1] no_shortcuts changes the work, not
 * the image.  A lone plane cannot shadow itself, so with the shortcuts
 * the shadow pass is left out (0 shadow rays); without them each of the
 * 12 camera rays meets the plane once, under one light, and sends one
 * shadow ray (what leaves the plane meets nothing).  The pixels are the
 * same bits. */
START_TEST(test_api_no_shortcuts)
{
    float on[36], off[36];
    rf_render_stats st_on, st_off;
    render_plane(0, on, &st_on);
    render_plane(1, off, &st_off);
    ck_assert_int_eq(memcmp(on, off, sizeof on), 0);
    ck_assert_float_eq(on[0], 1.1f);
    ck_assert_int_eq(st_on.shadows, 0);
    ck_assert_int_eq(st_on.shadow_rays, 0);
    ck_assert_int_eq(st_off.shadows, 1);
    ck_assert_int_eq(st_off.shadow_rays, 12);
}
END_TEST

typedef struct rows {
    int calls, last_done, last_total, stop_after;
} rows;

static void on_progress(void *user, int done, int total)
{
    rows *r = user;
    r->calls++;
    r->last_done = done;
    r->last_total = total;
}

static int on_cancel(void *user)
{
    const rows *r = user;
    return r->stop_after >= 0 && r->calls >= r->stop_after;
}

/* [EMBED-API-3] Progress after every row of the region; cancel, asked
 * before the first row and after every row, stops the render with
 * RF_ERR_CANCELLED. */
START_TEST(test_api_progress_and_cancel)
{
    rf_scene *s = load(plane_text, NULL);
    rows seen = {0, 0, 0, -1};
    rf_render_options o;
    rf_render_options_init(&o);
    o.progress = on_progress;
    o.cancel = on_cancel;
    o.user = &seen;
    rf_renderer *r = renderer(s, &o);
    float buf[36];
    ck_assert_int_eq(rf_render_region(r, 1, 1, 3, 3, buf, 6), RF_OK);
    ck_assert_int_eq(seen.calls, 2);
    ck_assert_int_eq(seen.last_done, 2);
    ck_assert_int_eq(seen.last_total, 2);
    seen.calls = 0;
    seen.stop_after = 1;
    ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 3, buf, 12), RF_ERR_CANCELLED);
    ck_assert_int_eq(seen.calls, 1);
    seen.stop_after = 0;
    ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 3, buf, 12), RF_ERR_CANCELLED);
    ck_assert_int_eq(seen.calls, 1);
    rf_renderer_free(r);
    rf_image *img = (rf_image *)&seen;
    ck_assert_int_eq(rf_render_image(s, &o, &img, NULL), RF_ERR_CANCELLED);
    ck_assert_ptr_null(img);
    rf_scene_free(s);
}
END_TEST

/* A poll that says stop on its k-th call, and go on after. */
typedef struct stop_once {
    long calls, stop_at;
} stop_once;

static int stop_on_call(void *user)
{
    stop_once *s = user;
    return ++s->calls == s->stop_at;
}

/* [EMBED-API-3] A region stopped anywhere (between rows or inside one, by
 * the ray poll) leaves the renderer whole: the next region, with a cancel
 * that says go on, is the fresh renderer's to the bit.  The image is 4x3 of
 * 12 pixels of the lit plane; the ray poll asks at the first ray and then
 * every 256 steps (a pixel is 256 camera rays), so stops on calls 1 to 3
 * land at the first ray and inside the first row. */
START_TEST(test_api_cancelled_renderer_renders_again)
{
    rf_scene *s = load(plane_text, NULL);
    float again[36];
    for (long k = 1; k <= 3; k++) {
        stop_once st = {0, 0};
        rf_render_options o;
        rf_render_options_init(&o);
        o.cancel = stop_on_call;
        o.user = &st;
        o.samples = 16;
        rf_renderer *r = renderer(s, &o);
        st.calls = 0;
        st.stop_at = k;
        float buf[36];
        ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 3, buf, 12), RF_ERR_CANCELLED);
        ck_assert_int_eq(st.calls, k);
        memset(again, 0, sizeof again);
        ck_assert_int_eq(rf_render_region(r, 0, 0, 4, 3, again, 12), RF_OK);
        rf_renderer_free(r);
        st.stop_at = 0;
        rf_renderer *rs = renderer(s, &o);
        float ref[36];
        ck_assert_int_eq(rf_render_region(rs, 0, 0, 4, 3, ref, 12), RF_OK);
        rf_renderer_free(rs);
        ck_assert_int_eq(memcmp(again, ref, sizeof ref), 0);
    }
    rf_scene_free(s);
}
END_TEST

typedef struct collected {
    int count;
    char text[8][160];
} collected;

static void collect(void *user, const rf_diagnostic *d)
{
    collected *c = user;
    if (c->count == 8)
        return;
    snprintf(c->text[c->count++], sizeof c->text[0], "%s|%d|%d|%d|%s|%.*s|%zu", d->file ? d->file : "-", d->line,
             d->column, (int)d->severity, d->message, d->source_line ? (int)d->source_line_length : 1,
             d->source_line ? d->source_line : "-", d->span_length);
}

/* The files of an in-memory resolver: name -> text. */
static rf_status memory_fetch(void *user, const char *from, const char *name, rf_source *out, char *message,
                              size_t size)
{
    const char *const *files = user;
    (void)from;
    for (int i = 0; files[i]; i += 2) {
        if (strcmp(files[i], name) == 0) {
            out->path = files[i];
            out->text = files[i + 1];
            out->size = strlen(files[i + 1]);
            return RF_OK;
        }
    }
    snprintf(message, size, "no file '%s' here", name);
    return RF_ERR_NO_INPUT;
}

/* Load options whose diagnostics go to c and whose files come from files. */
static void collecting_options(rf_load_options *o, collected *c, const char *const *files)
{
    memset(c, 0, sizeof *c);
    rf_load_options_init(o);
    o->diagnostic = collect;
    o->diagnostic_user = c;
    o->resolver.fetch = memory_fetch;
    o->resolver.user = (void *)files;
}

/* A resolver that breaks its contract: RF_OK with a size but no text
 * (mode 0), or a failure with no reason (mode 1). */
static rf_status broken_fetch(void *user, const char *from, const char *name, rf_source *out, char *message,
                              size_t size)
{
    (void)from, (void)name, (void)message, (void)size;
    out->size = 100;
    return *(const int *)user == 0 ? RF_OK : RF_ERR_CANCELLED;
}

/* [EMBED-API-NULL-1] The first crashed in the copy of the text; the second
 * gave the error an empty message. */
START_TEST(test_api_broken_resolver)
{
    static const char text[] = "image { width 4 height 3 }\n"
                               "camera { orthographic eye [0, 1, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
                               "include \"x.scene\"\n";
    static const char *const want[] = {"cannot read 'x.scene': the resolver gave 100 bytes of no text",
                                       "cannot read 'x.scene': cancelled"};
    for (int mode = 0; mode < 2; mode++) {
        rf_load_options o;
        collected c;
        rf_scene *s = NULL;
        collecting_options(&o, &c, NULL);
        o.resolver.fetch = broken_fetch;
        o.resolver.user = &mode;
        ck_assert_int_eq(rf_scene_load_memory("b.scene", text, strlen(text), &o, &s), RF_ERR_DATA);
        ck_assert_int_ge(c.count, 1);
        ck_assert_msg(strstr(c.text[0], want[mode]) != NULL, "mode %d: %s", mode, c.text[0]);
    }
}
END_TEST

/* [EMBED-API-4] Diagnostics come as records with file, line, column,
 * severity, message and the source line; an error in an included file is
 * followed by the note "included from here"; the resolver's reason for a
 * missing file becomes the error. */
START_TEST(test_api_diagnostics_and_resolver)
{
    static const char *const files[] = {"part.scene", "sphere {\n  radius -1 }\n", "tri.obj",
                                        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", NULL};
    collected c;
    rf_load_options o;
    collecting_options(&o, &c, files);
    rf_scene *s = (rf_scene *)&c;
    static const char text[] = "mesh { file \"tri.obj\" }\ninclude \"part.scene\"\n";
    ck_assert_int_eq(rf_scene_load_memory("main.scene", text, strlen(text), &o, &s), RF_ERR_DATA);
    ck_assert_ptr_null(s);
    ck_assert_int_eq(c.count, 2);
    ck_assert_str_eq(c.text[0], "part.scene|2|10|0|radius must be > 0, got -1|  radius -1 }|2");
    ck_assert_str_eq(c.text[1], "main.scene|2|1|2|included from here|-|0");
    memset(&c, 0, sizeof c);
    static const char missing[] = "include \"nowhere.scene\"\n";
    ck_assert_int_eq(rf_scene_load_memory("main.scene", missing, strlen(missing), &o, &s), RF_ERR_DATA);
    ck_assert_str_eq(c.text[0], "main.scene|1|9|0|no file 'nowhere.scene' here|include \"nowhere.scene\"|15");
    memset(&c, 0, sizeof c);
    o.resolver.fetch = NULL;
    ck_assert_int_eq(rf_scene_load_memory("main.scene", missing, strlen(missing), &o, &s), RF_ERR_DATA);
    ck_assert_str_eq(c.text[0], "main.scene|1|9|0|cannot read 'nowhere.scene': this load reads no files|"
                                "include \"nowhere.scene\"|15");
    o.resolver.fetch = memory_fetch;
    static const char good[] = "mesh { file \"tri.obj\" }\nsphere { center [0, 0, -3] }\n";
    s = load_named("main.scene", good, &o);
    rf_scene_info info = info_of(s);
    ck_assert_int_eq(info.meshes, 1);
    ck_assert_int_eq(info.mesh_triangles, 1);
    ck_assert_int_eq(info.spheres, 1);
    ck_assert_int_eq(info.primitives, 2);
    ck_assert_uint_eq(info.features & RF_FEATURE_MESHES, RF_FEATURE_MESHES);
    rf_scene_free(s);
}
END_TEST

/* The plane scene above as a JSON scene (spec/json.md): every default
 * written out, the distant light's falloff "none". */
static const char plane_json[] =
    "{\"format\": {\"name\": \"refray-scene\", \"version\": 1}, \"oracle\": null,\n"
    " \"image\": {\"width\": 4, \"height\": 3, \"samples\": 1, \"max_depth\": 5, \"background\": [0, 0, 0]},\n"
    " \"camera\": {\"projection\": \"orthographic\", \"eye\": [0, 1, 0], \"look_at\": [0, 0, 0], \"up\": [0, 0, 1],"
    " \"width\": 1},\n"
    " \"ambient\": [0.2, 0.2, 0.2],\n"
    " \"materials\": [{\"name\": null, \"Kd\": [0.5, 0.5, 0.5], \"Ks\": [0, 0, 0], \"n\": 1, \"t\": 0, \"ior\": 1}],\n"
    " \"lights\": [{\"kind\": \"distant\", \"direction\": [0, -1, 0], \"power\": [2, 2, 2], \"falloff\": \"none\"}],\n"
    " \"primitives\": [{\"kind\": \"plane\", \"material\": 0, \"transform\": null, \"point\": [0, 0, 0],"
    " \"normal\": [0, 1, 0]}%s]}\n";

/* [EMBED-API-7] A name ending in ".json" makes the text a JSON scene: the
 * plane scene renders to 1.1 as in the scene language; a mesh's file comes
 * from the resolver; a diagnostic names the value by its JSON pointer.  A
 * library without JSON support refuses it with RF_ERR_USAGE. */
START_TEST(test_api_json_scenes)
{
    static const char *const files[] = {"tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", NULL};
    char text[2048];
    collected c;
    rf_load_options o;
    collecting_options(&o, &c, files);
    rf_scene *s;
    snprintf(text, sizeof text, plane_json, "");
#ifdef REFRAY_HAVE_JSON
    s = load_named("plane.JSON", text, &o);
    rf_image *img;
    ck_assert_int_eq(rf_render_image(s, NULL, &img, NULL), RF_OK);
    for (int i = 0; i < 3 * 4 * 3; i++)
        ck_assert_double_eq_tol(rf_image_pixels(img)[i], 1.1, 1e-12);
    rf_image_free(img);
    rf_scene_free(s);
    snprintf(text, sizeof text, plane_json,
             ",\n {\"kind\": \"mesh\", \"material\": 0, \"source\": null, \"file\": \"tri.obj\"}");
    s = load_named("plane.json", text, &o);
    rf_scene_info info = info_of(s);
    ck_assert_int_eq(info.planes, 1);
    ck_assert_int_eq(info.mesh_triangles, 1);
    rf_scene_free(s);
    ck_assert_int_eq(c.count, 0);
    snprintf(text, sizeof text, plane_json, "");
    char *one = strstr(text, "\"width\": 1}");
    one[9] = '0';
    ck_assert_int_eq(rf_scene_load_memory("plane.json", text, strlen(text), &o, &s), RF_ERR_DATA);
    ck_assert_int_eq(c.count, 1);
    ck_assert_msg(strstr(c.text[0], "plane.json|3|") == c.text[0] &&
                      strstr(c.text[0], "|0|/camera/width: width must be > 0, got 0|"),
                  "%s", c.text[0]);
#else
    ck_assert_int_eq(rf_scene_load_memory("plane.json", text, strlen(text), &o, &s), RF_ERR_USAGE);
    ck_assert_ptr_null(s);
    ck_assert_int_eq(c.count, 1);
    ck_assert_msg(strstr(c.text[0], "without JSON support"), "%s", c.text[0]);
#endif
}
END_TEST

/* rf_diagnostic_print writes what the refray program writes. */
START_TEST(test_api_diagnostic_print)
{
    char *out = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&out, &size);
    ck_assert_ptr_nonnull(f);
    rf_load_options o;
    rf_load_options_init(&o);
    o.diagnostic = rf_diagnostic_print;
    o.diagnostic_user = f;
    rf_scene *s;
    static const char text[] = "sphere { radius -1 }\n";
    ck_assert_int_eq(rf_scene_load_memory("t.scene", text, strlen(text), &o, &s), RF_ERR_DATA);
    ck_assert_int_eq(rf_scene_load_file("tests/no-such.scene", &o, &s), RF_ERR_NO_INPUT);
    fclose(f);
    ck_assert_str_eq(out, "t.scene:1:17: error: radius must be > 0, got -1\n"
                          "    1 | sphere { radius -1 }\n"
                          "      |                 ^~\n"
                          "refray: error: cannot open 'tests/no-such.scene': No such file or directory\n");
    free(out);
}
END_TEST

/* [EMBED-API-5] The summary of scenes/demo.scene, counted by hand from
 * the file: 1 plane, 3 + 7 spheres, 1 box, 2 lights, 5 materials. */
START_TEST(test_api_scene_info)
{
    rf_scene *s;
    ck_assert_int_eq(rf_scene_load_file("scenes/demo.scene", NULL, &s), RF_OK);
    rf_scene_info i = info_of(s);
    ck_assert_int_eq(i.width, 640);
    ck_assert_int_eq(i.height, 400);
    ck_assert_int_eq(i.samples, 2);
    ck_assert_int_eq(i.max_depth, 8);
    ck_assert_int_eq(i.planes, 1);
    ck_assert_int_eq(i.spheres, 10);
    ck_assert_int_eq(i.boxes, 1);
    ck_assert_int_eq(i.primitives, 12);
    ck_assert_int_eq(i.lights, 2);
    ck_assert_int_eq(i.materials, 5);
    ck_assert_ptr_null(i.oracle);
    ck_assert_uint_eq(i.features, RF_FEATURE_SHADOWS | RF_FEATURE_SPECULAR | RF_FEATURE_REFLECTION |
                                      RF_FEATURE_REFRACTION | RF_FEATURE_SAMPLED_LIGHTS);
    rf_scene_free(s);
}
END_TEST

/* [EMBED-API-5] Every kind of primitive is counted, cylinders, cones and
 * tori too (counted by hand from the text: 1, 2 and 3 of them, 1 sphere). */
START_TEST(test_api_scene_info_quadrics)
{
    static const char text[] =
        "sphere { center [0, 0, -9] }\n"
        "cylinder { from [0, 0, -5] to [0, 1, -5] radius 0.5 }\n"
        "cone { from [1, 0, -5] to [1, 1, -5] radii 0.5 0 }\n"
        "cone { from [2, 0, -5] to [2, 1, -5] radii 0.5 0.2 }\n"
        "torus { center [0, 0, -6] axis [0, 1, 0] major 1 minor 0.2 }\n"
        "torus { center [0, 2, -6] axis [0, 1, 0] major 1 minor 0.2 }\n"
        "torus { center [0, 4, -6] axis [1, 0, 0] major 1 minor 0.2 }\n";
    rf_scene *s = load_named("q.scene", text, NULL);
    rf_scene_info i = info_of(s);
    ck_assert_int_eq(i.primitives, 7);
    ck_assert_int_eq(i.spheres, 1);
    ck_assert_int_eq(i.cylinders, 1);
    ck_assert_int_eq(i.cones, 2);
    ck_assert_int_eq(i.tori, 3);
    ck_assert_int_eq(i.planes + i.triangles + i.disks + i.boxes + i.meshes, 0);
    rf_scene_free(s);
}
END_TEST

/* [EMBED-API-5] A mesh is one primitive; its triangles and store are
 * counted apart, and each mesh has its own record.  By hand: a closed
 * tetrahedron (4 vertices, 4 triangles, no open edge) and a quad cut into
 * 2 triangles (4 open edges, one mask byte per triangle); 3 doubles a
 * vertex, 3 ints a triangle. */
START_TEST(test_api_scene_info_meshes)
{
    static const char *const files[] = {"tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                                   "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n",
                                        "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", NULL};
    static const char text[] = "mesh { file \"tet.obj\" }\nsphere { center [0, 0, -3] }\n"
                               "mesh { file \"quad.obj\" translate [0, 0, -1] }\n";
    rf_load_options o;
    rf_load_options_init(&o);
    o.resolver.fetch = memory_fetch;
    o.resolver.user = (void *)files;
    rf_scene *s = load_named("m.scene", text, &o);
    rf_scene_info i = info_of(s);
    ck_assert_int_eq(i.primitives, 3);
    ck_assert_int_eq(i.meshes, 2);
    ck_assert_int_eq(i.spheres, 1);
    ck_assert_int_eq(i.triangles, 0);
    ck_assert_int_eq(i.mesh_triangles, 6);
    long tet = 4 * 3 * (long)sizeof(double) + 4 * 3 * (long)sizeof(int);
    long quad = 4 * 3 * (long)sizeof(double) + 2 * 3 * (long)sizeof(int) + 2;
    ck_assert_int_eq(i.mesh_bytes, tet + quad);
    rf_mesh_info m;
    ck_assert_int_eq(rf_scene_get_mesh_info(s, 0, &m), RF_OK);
    ck_assert_str_eq(m.path, "tet.obj");
    ck_assert_int_eq(m.triangles, 4);
    ck_assert_int_eq(m.faces, 4);
    ck_assert(m.closed && m.oriented);
    ck_assert_int_eq(m.pieces, 1);
    ck_assert_int_eq(m.open_edges + m.crowded_edges + m.dropped + m.nonplanar + m.fanned, 0);
    ck_assert_int_eq(rf_scene_get_mesh_info(s, 1, &m), RF_OK);
    ck_assert_str_eq(m.path, "quad.obj");
    ck_assert_int_eq(m.triangles, 2);
    ck_assert_int_eq(m.faces, 1);
    ck_assert(!m.closed && m.oriented);
    ck_assert_int_eq(m.open_edges, 4);
    ck_assert_int_eq(rf_scene_get_mesh_info(s, 2, &m), RF_ERR_USAGE);
    ck_assert_int_eq(rf_scene_get_mesh_info(s, -1, &m), RF_ERR_USAGE);
    rf_scene_free(s);
}
END_TEST

/* A bump allocator over a fixed buffer, as an embedding host would write
 * one: no header, sized releases ignored except for the last block. */
typedef struct bump {
    unsigned char *base;
    size_t size, used, last;
} bump;

static void *bump_alloc(void *user, size_t size)
{
    bump *b = user;
    size_t at = (b->used + 15) / 16 * 16;
    if (at > b->size || size > b->size - at)
        return NULL;
    b->last = at;
    b->used = at + size;
    return b->base + at;
}

static void bump_release(void *user, void *p, size_t size)
{
    bump *b = user;
    if ((unsigned char *)p == b->base + b->last && b->last + size == b->used)
        b->used = b->last;
}

/* [EMBED-API-6] Everything comes from the allocator given: with a fixed
 * arena the render succeeds when it is large enough and fails with
 * RF_ERR_NO_MEMORY, cleanly, when it is not. */
START_TEST(test_api_fixed_arena)
{
    static unsigned char arena[1 << 20];
    bump b = {arena, sizeof arena, 0, 0};
    rf_allocator a = {bump_alloc, NULL, bump_release, &b};
    rf_load_options o;
    rf_load_options_init(&o);
    o.allocator = &a;
    rf_scene *s = load(plane_text, &o);
    rf_image *img;
    ck_assert_int_eq(rf_render_image(s, NULL, &img, NULL), RF_OK);
    ck_assert_double_eq_tol(rf_image_pixels(img)[0], 1.1, 1e-15);
    rf_image_free(img);
    rf_scene_free(s);
    size_t needed = 0;
    for (size_t size = 256; size < sizeof arena; size *= 2) {
        b.size = size;
        b.used = 0;
        rf_status st = rf_scene_load_memory("api.scene", plane_text, strlen(plane_text), &o, &s);
        if (st == RF_OK) {
            st = rf_render_image(s, NULL, &img, NULL);
            rf_scene_free(s);
            if (st == RF_OK)
                rf_image_free(img);
        }
        ck_assert_msg(st == RF_OK || st == RF_ERR_NO_MEMORY, "arena %zu: %s", size, rf_status_string(st));
        if (st == RF_OK && !needed)
            needed = size;
    }
    ck_assert_uint_gt(needed, 256);
}
END_TEST

/* [EMBED-MEM-3] A counting allocator sees every byte returned; rendering
 * a region allocates nothing (everything a render needs is made with the
 * renderer). */
START_TEST(test_api_counting_allocator)
{
    memcheck c;
    memcheck_init(&c);
    rf_allocator a = {memcheck_alloc, memcheck_resize, memcheck_release, &c};
    rf_load_options o;
    rf_load_options_init(&o);
    o.allocator = &a;
    rf_scene *s;
    ck_assert_int_eq(rf_scene_load_file("scenes/mesh.scene", &o, &s), RF_OK);
    rf_image *img;
    rf_render_options ro;
    rf_render_options_init(&ro);
    ro.width = 8;
    ro.height = 6;
    ck_assert_int_eq(rf_render_image(s, &ro, &img, NULL), RF_OK);
    rf_image_free(img);
    rf_renderer *r = renderer(s, &ro);
    long calls = c.calls;
    size_t live = c.live;
    float px[8 * 6 * 3];
    ck_assert_int_eq(rf_render_region(r, 0, 0, 8, 6, px, 24), RF_OK);
    ck_assert_int_eq(c.calls, calls);
    ck_assert_uint_eq(c.live, live);
    rf_renderer_free(r);
    rf_scene_free(s);
    ck_assert_int_gt(c.calls, 20);
    ck_assert_int_eq(c.bad_sizes, 0);
    ck_assert_uint_eq(c.live, 0);
    ck_assert_int_eq(rf_image_create(0, 5, &a, &img), RF_ERR_USAGE);
    ck_assert_int_eq(rf_image_create(3, 2, &a, &img), RF_OK);
    ck_assert_uint_ge(c.live, 3 * 2 * 3 * sizeof(double));
    rf_image_free(img);
    ck_assert_uint_eq(c.live, 0);
}
END_TEST

/* Formats by extension; a PFM written through the API has the PFM header
 * of a 4 x 3 image. */
START_TEST(test_api_image_write)
{
    ck_assert_int_eq(rf_format_from_path("a.PNG"), RF_FORMAT_PNG);
    ck_assert_int_eq(rf_format_from_path("a.exr"), RF_FORMAT_EXR);
    ck_assert_int_eq(rf_format_from_path("a.pfm"), RF_FORMAT_PFM);
    ck_assert_int_eq(rf_format_from_path("a.txt"), RF_FORMAT_UNKNOWN);
    ck_assert_int_eq(rf_format_available(RF_FORMAT_PFM), 1);
    ck_assert_int_eq(rf_format_available(RF_FORMAT_UNKNOWN), 0);
    rf_scene *s = load(plane_text, NULL);
    rf_image *img;
    ck_assert_int_eq(rf_render_image(s, NULL, &img, NULL), RF_OK);
    ck_assert_int_eq(rf_image_width(img), 4);
    ck_assert_int_eq(rf_image_height(img), 3);
    const char *path = "build/check_api_out.pfm";
    char message[256];
    rf_write_stats st;
    ck_assert_int_eq(rf_image_write(img, path, NULL, &st, message, sizeof message), RF_OK);
    ck_assert_uint_eq(st.nonfinite, 0);
    FILE *f = fopen(path, "rb");
    ck_assert_ptr_nonnull(f);
    char head[16] = "";
    ck_assert_ptr_nonnull(fgets(head, sizeof head, f));
    ck_assert_str_eq(head, "PF\n");
    ck_assert_ptr_nonnull(fgets(head, sizeof head, f));
    ck_assert_str_eq(head, "4 3\n");
    fclose(f);
    remove(path);
    ck_assert_int_eq(rf_image_write(img, "build/x.nope", NULL, NULL, message, sizeof message), RF_ERR_USAGE);
    ck_assert_int_ne(message[0], '\0');
    rf_image_free(img);
    rf_scene_free(s);
}
END_TEST

Suite *suite_api(void)
{
    Suite *s = suite_create("api");
    TCase *tc = tcase_create("embedding");
    tcase_add_test(tc, test_api_version_and_status);
    tcase_add_test(tc, test_api_render_region);
    tcase_add_test(tc, test_api_regions_tile_the_image);
    tcase_add_test(tc, test_api_region_float_saturates);
    tcase_add_test(tc, test_api_render_region_refusals);
    tcase_add_test(tc, test_api_size_override_limits);
    tcase_add_test(tc, test_api_size_override_keeps_the_view_in_the_extent);
    tcase_add_test(tc, test_api_null_arguments);
    tcase_add_test(tc, test_api_null_everywhere);
    tcase_add_test(tc, test_api_broken_resolver);
    tcase_add_test(tc, test_api_region_double_is_the_image);
    tcase_add_test(tc, test_api_fingerprint);
    tcase_add_test(tc, test_api_no_shortcuts);
    tcase_add_test(tc, test_api_progress_and_cancel);
    tcase_add_test(tc, test_api_cancelled_renderer_renders_again);
    tcase_add_test(tc, test_api_diagnostics_and_resolver);
    tcase_add_test(tc, test_api_diagnostic_print);
    tcase_add_test(tc, test_api_json_scenes);
    tcase_add_test(tc, test_api_scene_info);
    tcase_add_test(tc, test_api_scene_info_quadrics);
    tcase_add_test(tc, test_api_scene_info_meshes);
    tcase_add_test(tc, test_api_fixed_arena);
    tcase_add_test(tc, test_api_counting_allocator);
    tcase_add_test(tc, test_api_image_write);
    suite_add_tcase(s, tc);
    return s;
}
