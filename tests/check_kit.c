/*
 * check_kit.c - the conformance kit (`refray kit`, verify/kit.h), its
 * manifest (verify/manifest.h) and `refray compare --manifest`,
 * spec/conformance.md.  A kit of three small scenes (cli_testlib.h) is
 * built once for the suite; its exact images must be, byte for byte, what
 * `refray oracle` writes, and its numbers are checked against the scene
 * files and the images themselves.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/fileio.h"
#include "io/filewrite.h"
#include "cli_testlib.h"
#include "io/image_io.h"
#include "oracle/oracle.h"
#include "scene/scene.h"
#include "io/scene_file.h"
#include "verify/manifest.h"
#include "verify/verify.h"

static char kit_dir[64];
static int kit_status = -1;

static void kit_setup(void)
{
    kit_status = cli_kit_setup(kit_dir, sizeof kit_dir);
}

static void kit_teardown(void)
{
    cli_kit_teardown(kit_dir);
}

#if REFRAY_HAVE_JSON

/* The suite's kit directory and its manifest, read back. */
static const char *kit(char *buf, size_t size, manifest *m)
{
    char why[1024], path[256];
    ck_assert_msg(kit_status == 0, "`refray kit` failed (exit %d)", kit_status);
    snprintf(buf, size, "%s/kit", kit_dir);
    if (m)
        ck_assert_msg(manifest_read(cli_path(path, sizeof path, buf, "manifest.json"), m, why, sizeof why) == 0,
                      "%s", why);
    return buf;
}

static int same_bytes(const char *a, const char *b)
{
    char *x, *y;
    size_t nx, ny;
    char why[512];
    int ok = file_read_all(a, -1, NULL, &x, &nx, why, sizeof why) == 0;
    ck_assert_msg(ok, "%s", why);
    ok = file_read_all(b, -1, NULL, &y, &ny, why, sizeof why) == 0;
    ck_assert_msg(ok, "%s", why);
    int same = nx == ny && memcmp(x, y, nx) == 0;
    free(x);
    free(y);
    return same;
}

/* [KIT-LAYOUT-1] Every file the manifest names exists; the absent ones
 * carry their reason; README.md states the rule. */
START_TEST(test_kit_layout)
{
    char dir[128], path[512], why[512];
    manifest m;
    kit(dir, sizeof dir, &m);
    ck_assert_int_eq(m.scene_count, CLI_KIT_SCENES);
    ck_assert_str_eq(m.scenes[0].name, "plane_point_linear");
    for (int i = 0; i < m.scene_count; i++) {
        const manifest_scene *s = &m.scenes[i];
        snprintf(path, sizeof path, "scenes/%s/%s.scene", s->name, s->name);
        ck_assert_str_eq(s->files[MANIFEST_FILE_SCENE], path);
        ck_assert(same_bytes(cli_path(path, sizeof path, dir, s->files[MANIFEST_FILE_SCENE]), cli_kit_scenes[i]));
        for (int f = 0; f < MANIFEST_FILE_COUNT; f++) {
            if (s->files[f][0])
                ck_assert_msg(cli_exists(cli_path(path, sizeof path, dir, s->files[f])), "%s is missing", path);
            else
                ck_assert_msg(s->missing[f][0], "%s: %s absent without a reason", s->name,
                              manifest_file_key((manifest_file)f));
        }
        ck_assert(s->files[MANIFEST_FILE_EXACT_PFM][0] && s->files[MANIFEST_FILE_MASK_PGM][0]);
    }
    ck_assert(!m.scenes[2].files[MANIFEST_FILE_POV][0]);
    ck_assert_msg(strstr(m.scenes[2].missing[MANIFEST_FILE_POV], "refused by the POV-Ray export"), "%s",
                  m.scenes[2].missing[MANIFEST_FILE_POV]);
    char *readme;
    size_t n;
    ck_assert_int_eq(file_read_all(cli_path(path, sizeof path, dir, "README.md"), -1, NULL, &readme, &n, why, sizeof why),
                     0);
    ck_assert(strstr(readme, "|OUT_c - EXACT_c| > relative * |EXACT_c| + absolute") != NULL);
    ck_assert(strstr(readme, "| disk_light | disk_light | 80x60 | 1 | 1 |") != NULL);
    free(readme);
    manifest_free(&m);
}
END_TEST

/* [KIT-EXACT-1] The kit's exact images and masks are the files `refray
 * oracle` writes for the scene. */
START_TEST(test_kit_exact_is_oracle)
{
    char dir[128], work[64], path[512], mine[300], mask[300];
    manifest m;
    cli_run *r = malloc(sizeof *r);
    kit(dir, sizeof dir, &m);
    cli_scratch(work, sizeof work, "kitoracle");
    for (int i = 0; i < m.scene_count; i++) {
        const manifest_scene *s = &m.scenes[i];
        for (int exr = 0; exr < 2; exr++) {
            if (exr && !img_format_available(IMG_FORMAT_EXR))
                continue;
            const char *args[] = {"oracle", cli_kit_scenes[i], "-o",
                                  cli_path(mine, sizeof mine, work, exr ? "e.exr" : "e.pfm"), "--mask",
                                  cli_path(mask, sizeof mask, work, "m.pgm"), NULL};
            cli_refray(r, args);
            ck_assert_msg(r->code == 0, "oracle %s: %s", cli_kit_scenes[i], r->err);
            manifest_file f = exr ? MANIFEST_FILE_EXACT_EXR : MANIFEST_FILE_EXACT_PFM;
            ck_assert_msg(same_bytes(mine, cli_path(path, sizeof path, dir, s->files[f])), "%s differs", path);
            ck_assert(same_bytes(mask, cli_path(path, sizeof path, dir, s->files[MANIFEST_FILE_MASK_PGM])));
        }
    }
    cli_remove(work);
    free(r);
    manifest_free(&m);
}
END_TEST

/* The largest value of the compared pixels and the count of masked ones,
 * from the kit's own PFM (floats) and PGM. */
static void measure(const char *dir, const manifest_scene *s, double *peak, long *masked)
{
    char path[512], err[512];
    img_buf img;
    unsigned char *mask;
    ck_assert_int_eq(img_read(cli_path(path, sizeof path, dir, s->files[MANIFEST_FILE_EXACT_PFM]), NULL, &img, err,
                              sizeof err), 0);
    ck_assert_int_eq(verify_mask_read(cli_path(path, sizeof path, dir, s->files[MANIFEST_FILE_MASK_PGM]), img.width,
                                      img.height, &mask, err, sizeof err), 0);
    *peak = 0;
    *masked = 0;
    for (int p = 0; p < img.width * img.height; p++) {
        *masked += mask[p] != 0;
        for (int c = 0; c < 3 && !mask[p]; c++)
            *peak = fmax(*peak, fabs(img.rgb[3 * p + c]));
    }
    ck_assert_int_eq(img.width, s->width);
    ck_assert_int_eq(img.height, s->height);
    free(mask);
    img_free(&img);
}

/* [KIT-TOL-1] [KIT-SCALE-1] The numbers of each scene: image settings as
 * the scene files write them, peak and masked pixels as the images show,
 * the scale and the tolerance by their definitions. */
START_TEST(test_kit_manifest_numbers)
{
    static const int want[CLI_KIT_SCENES][4] = {{96, 72, 1, 1}, {80, 60, 1, 1}, {120, 90, 2, 1}};
    char dir[128];
    manifest m;
    kit(dir, sizeof dir, &m);
    for (int i = 0; i < m.scene_count; i++) {
        const manifest_scene *s = &m.scenes[i];
        double peak;
        long masked;
        measure(dir, s, &peak, &masked);
        ck_assert_int_eq(s->width, want[i][0]);
        ck_assert_int_eq(s->height, want[i][1]);
        ck_assert_int_eq(s->samples, want[i][2]);
        ck_assert_int_eq(s->max_depth, want[i][3]);
        ck_assert_rel(s->peak, peak, 1e-7); /* the PFM holds floats */
        ck_assert_int_eq(s->masked, masked);
        int e;
        double scaled = s->peak * s->png16_scale;
        ck_assert_msg(frexp(s->png16_scale, &e) == 0.5 && scaled > 0.4 && scaled <= 0.8, "scale %g, peak %g",
                      s->png16_scale, s->peak);
        ck_assert(s->absolute_png == 1.0 / (65535.0 * s->png16_scale));
        ck_assert(s->absolute == 0x1p-20 * s->peak); /* a float picture's: [KIT-TOL-1] */
    }
    ck_assert(!m.scenes[0].sampled && m.scenes[0].relative == 1e-4 && m.scenes[0].light_count == 0);
    ck_assert_str_eq(m.scenes[1].family, "disk_light");
    ck_assert(m.scenes[1].sampled && m.scenes[1].expected_order == -1);
    ck_assert_int_eq(m.scenes[1].light_count, 1);
    ck_assert_int_eq(m.scenes[1].light_samples[0], 256); /* `samples 256` in disk_light.scene */
    /* The sampled tolerance is the family's at the scene's own samples. */
    int status;
    scene_model *sc = scene_file_load(cli_kit_scenes[1], NULL, stderr, 0, &status);
    ck_assert_ptr_nonnull(sc);
    oracle_view v = verify_view(sc, NULL);
    ck_assert(m.scenes[1].relative == oracle_find("disk_light")->tolerance(&v, 0));
    scene_free(sc);
    ck_assert_msg(m.scenes[1].note_count == 2 && strstr(m.scenes[1].notes[1], "cell"), "notes of the .pov");
    manifest_free(&m);
}
END_TEST

/* A manifest with awkward values survives the file exactly. */
static void sample_manifest(manifest *m)
{
    memset(m, 0, sizeof *m);
    snprintf(m->refray_version, sizeof m->refray_version, "9.8.7");
    m->scene_count = 2;
    m->scenes = calloc(2, sizeof *m->scenes);
    ck_assert_ptr_nonnull(m->scenes);
    manifest_scene *a = &m->scenes[0], *b = &m->scenes[1];
    snprintf(a->name, sizeof a->name, "first");
    snprintf(a->family, sizeof a->family, "fam \"quoted\" \xc3\xa9");
    snprintf(a->files[MANIFEST_FILE_EXACT_PFM], MANIFEST_PATH_LEN, "scenes/first/first.exact.pfm");
    snprintf(a->missing[MANIFEST_FILE_POV], MANIFEST_TEXT_LEN, "refused: because\nof a line");
    a->width = 3, a->height = 2, a->samples = 4, a->max_depth = 9, a->sampled = 1;
    a->light_count = 2, a->light_samples[0] = 1, a->light_samples[1] = 1000;
    a->relative = 1.0 / 3, a->absolute = 1e-300, a->absolute_png = 2e-300, a->peak = 0.1, a->masked = 5;
    a->png16_scale = 0.125;
    a->expected_order = -0.75;
    snprintf(a->order_note, sizeof a->order_note, "note");
    ck_assert_int_eq(manifest_add_note(a, "tab\there"), 0);
    ck_assert_int_eq(manifest_add_note(a, ""), 0);
    snprintf(b->name, sizeof b->name, "b.2-x");
    snprintf(b->family, sizeof b->family, "f");
    snprintf(b->files[MANIFEST_FILE_EXACT_EXR], MANIFEST_PATH_LEN, "e.exr");
    b->width = b->height = b->samples = b->max_depth = 1;
    b->relative = 1e-4, b->absolute = b->absolute_png = 1.0 / 65535, b->peak = 0, b->png16_scale = 1;
}

START_TEST(test_manifest_round_trip)
{
    char work[64], path[300], why[512];
    manifest m, back;
    sample_manifest(&m);
    cli_scratch(work, sizeof work, "manifest");
    ck_assert_int_eq(manifest_write(cli_path(path, sizeof path, work, "manifest.json"), &m, why, sizeof why), 0);
    ck_assert_msg(manifest_read(path, &back, why, sizeof why) == 0, "%s", why);
    ck_assert_str_eq(back.refray_version, "9.8.7");
    ck_assert_int_eq(back.scene_count, 2);
    for (int i = 0; i < 2; i++) {
        const manifest_scene *x = &m.scenes[i], *y = &back.scenes[i];
        ck_assert_str_eq(x->name, y->name);
        ck_assert_str_eq(x->family, y->family);
        for (int f = 0; f < MANIFEST_FILE_COUNT; f++) {
            ck_assert_str_eq(x->files[f], y->files[f]);
            if (!x->files[f][0])
                ck_assert_str_eq(x->missing[f][0] ? x->missing[f] : "not written", y->missing[f]);
        }
        ck_assert(x->width == y->width && x->height == y->height && x->samples == y->samples &&
                  x->max_depth == y->max_depth && x->sampled == y->sampled && x->masked == y->masked);
        ck_assert_int_eq(x->light_count, y->light_count);
        for (int k = 0; k < x->light_count; k++)
            ck_assert_int_eq(x->light_samples[k], y->light_samples[k]);
        /* Bit for bit: 17 significant digits. */
        ck_assert(x->relative == y->relative && x->absolute == y->absolute && x->absolute_png == y->absolute_png &&
                  x->peak == y->peak &&
                  x->png16_scale == y->png16_scale && x->expected_order == y->expected_order);
        ck_assert_str_eq(x->order_note, y->order_note);
        ck_assert_int_eq(x->note_count, y->note_count);
        for (int k = 0; k < x->note_count; k++)
            ck_assert_str_eq(x->notes[k], y->notes[k]);
    }
    manifest_free(&m);
    manifest_free(&back);
    cli_remove(work);
}
END_TEST


/* A relative tolerance of 1/2 or more passes half the image (|v/2 - v| <=
 * tol |v| for every v), one of 1 or more an image of zeros: a manifest
 * holding one is refused, whoever wrote it (attack 10, finding 7; attack
 * 11, finding 4: 0.992 passed an image of 1 %; [VERIFY-UNBOUNDED-2]). */
START_TEST(test_manifest_refuses_a_bound_of_one_half_or_more)
{
    static const double bounds[] = {0.5, 0.992, 1, 1.0000000000000002, 5.86};
    char work[64], path[300], why[512];
    cli_scratch(work, sizeof work, "manifest");
    for (size_t i = 0; i < sizeof bounds / sizeof bounds[0]; i++) {
        manifest m, back;
        sample_manifest(&m);
        m.scenes[1].relative = bounds[i];
        ck_assert_int_eq(manifest_write(cli_path(path, sizeof path, work, "manifest.json"), &m, why, sizeof why), 0);
        ck_assert_int_eq(manifest_read(path, &back, why, sizeof why), STATUS_DATA);
        ck_assert_msg(strstr(why, "scenes[1] ('b.2-x'): 'relative' is 1/2 or more") != NULL, "why: %s", why);
        manifest_free(&m);
    }
    manifest m, back;
    sample_manifest(&m);
    m.scenes[1].relative = 0.49999999999999994;
    ck_assert_int_eq(manifest_write(path, &m, why, sizeof why), 0);
    ck_assert_msg(manifest_read(path, &back, why, sizeof why) == 0, "%s", why);
    manifest_free(&back);
    manifest_free(&m);
    cli_remove(work);
}
END_TEST
/* [KIT-SCALE-1] png16_scale is a power of two; [KIT-TOL-1] absolute_png
 * is at most one 16-bit step at it, 1 / (65535 png16_scale), and absolute
 * (a float picture's) at most absolute_png: a manifest that breaks any is
 * refused, whoever wrote it.  Before, png16_scale 3 and
 * absolute 10 loaded, and conform passed a black picture under them
 * (attack 12, finding 6). */
START_TEST(test_manifest_refuses_a_scale_or_absolute_off_its_definition)
{
    /* {png16_scale, absolute_png, absolute, refused}; the sample's first
     * scene has png16_scale 1/8, whose step is 8 / 65535. */
    static const struct {
        double scale, absolute_png, absolute;
        const char *why;
    } cases[] = {
        {3, 1e-5, 0, "'png16_scale' is not a power of two"},
        {0.75, 1e-5, 0, "'png16_scale' is not a power of two"},
        {0.125, 10, 0, "'absolute_png' is more than one step of a 16-bit PNG"},
        {0.125, 8 / 65535.0 * (1 + 1e-9), 0, "'absolute_png' is more than one step"},
        {0.125, 8 / 65535.0, 8 / 65535.0 * (1 + 1e-9), "'absolute' is more than absolute_png"},
        {0.125, 8 / 65535.0, 8 / 65535.0, NULL},
        {0.125, 8 / 65535.0, 1e-7, NULL},
        {0x1p-40, 0x1p40 / 65535, 0, NULL},
        {0.125, 0, 0, NULL},
    };
    char work[64], path[300], why[512];
    cli_scratch(work, sizeof work, "manifest");
    cli_path(path, sizeof path, work, "manifest.json");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        manifest m, back;
        sample_manifest(&m);
        m.scenes[0].png16_scale = cases[i].scale;
        m.scenes[0].absolute_png = cases[i].absolute_png;
        m.scenes[0].absolute = cases[i].absolute;
        ck_assert_int_eq(manifest_write(path, &m, why, sizeof why), 0);
        why[0] = '\0';
        int status = manifest_read(path, &back, why, sizeof why);
        if (cases[i].why) {
            ck_assert_msg(status == STATUS_DATA && strstr(why, "scenes[0] ('first'): ") && strstr(why, cases[i].why),
                          "case %zu: status %d, %s", i, status, why);
        } else {
            ck_assert_msg(status == 0, "case %zu: %s", i, why);
            manifest_free(&back);
        }
        manifest_free(&m);
    }
    cli_remove(work);
}
END_TEST

/* [VERIFY-UNBOUNDED-3] A scene whose exact image is black: no tolerance
 * tells a picture from half of it, so `refray kit` refuses it (65) rather
 * than write a manifest no verdict can rest on. */
START_TEST(test_cli_kit_refuses_a_black_image)
{
    char work[64], dir[300];
    cli_run *r = malloc(sizeof *r);
    cli_scratch(work, sizeof work, "kitblack");
    const char *args[] = {"kit", "-q", "-o", cli_path(dir, sizeof dir, work, "k"), "tests/conform/black.scene", NULL};
    cli_refray(r, args);
    ck_assert_int_eq(r->code, 65);
    ck_assert_msg(strstr(r->err, "passes a picture of half the light of the exact image, whose largest value is 0") &&
                  strstr(r->err, "[VERIFY-UNBOUNDED-3]"), "stderr: %s", r->err);
    ck_assert_int_eq(cli_entries(work), 0);
    cli_remove(work);
    free(r);
}
END_TEST

/* Writes text as work/name and reads it as a manifest: the status, and
 * the message in why. */
static int read_text_manifest(const char *work, const char *text, char *why, size_t size)
{
    char path[300];
    manifest m;
    ck_assert_int_eq(file_write_bytes(cli_path(path, sizeof path, work, "bad.json"), text, strlen(text), why, size),
                     0);
    int status = manifest_read(path, &m, why, size);
    if (status == 0)
        manifest_free(&m);
    return status;
}

START_TEST(test_manifest_read_errors)
{
    char work[64], why[1024], path[300];
    manifest m;
    cli_scratch(work, sizeof work, "manifest");
    ck_assert_int_eq(manifest_read(cli_path(path, sizeof path, work, "none.json"), &m, why, sizeof why), STATUS_NO_INPUT);
    ck_assert_int_eq(read_text_manifest(work, "{\"scenes\": [\n  1,,\n]}", why, sizeof why), STATUS_DATA);
    ck_assert_msg(strstr(why, "bad.json:2:") != NULL, "why: %s", why);
    ck_assert_int_eq(read_text_manifest(work, "{\"format_version\": 1}", why, sizeof why), STATUS_DATA);
    ck_assert_msg(strstr(why, "'scenes'") != NULL, "why: %s", why);
    ck_assert_int_eq(read_text_manifest(work, "{\"format_version\": 2, \"scenes\": []}", why, sizeof why), STATUS_DATA);
    static const char no_width[] =
        "{\"format_version\": 1, \"scenes\": [{\"name\": \"s\", \"family\": \"f\", "
        "\"files\": {\"exact_pfm\": \"s.pfm\"}}]}";
    ck_assert_int_eq(read_text_manifest(work, no_width, why, sizeof why), STATUS_DATA);
    ck_assert_msg(strstr(why, "scenes[0] ('s'): 'width'") != NULL, "why: %s", why);
    static const char outside[] =
        "{\"format_version\": 1, \"scenes\": [{\"name\": \"s\", \"family\": \"f\", "
        "\"files\": {\"exact_pfm\": \"../../etc/x.pfm\"}}]}";
    ck_assert_int_eq(read_text_manifest(work, outside, why, sizeof why), STATUS_DATA);
    ck_assert_msg(strstr(why, "outside the kit") != NULL, "why: %s", why);
    static const char bad_name[] = "{\"format_version\": 1, \"scenes\": [{\"name\": \"a/b\"}]}";
    ck_assert_int_eq(read_text_manifest(work, bad_name, why, sizeof why), STATUS_DATA);
    cli_remove(work);
}
END_TEST

/* `refray kit` refuses what it cannot make whole, and leaves nothing. */
START_TEST(test_cli_kit_errors)
{
    char work[64], dir[300], path[300];
    cli_run *r = malloc(sizeof *r);
    cli_scratch(work, sizeof work, "kitcli");
    cli_path(dir, sizeof dir, work, "k");
    const char *no_out[] = {"kit", cli_kit_scenes[0], NULL};
    cli_refray(r, no_out);
    ck_assert_int_eq(r->code, 64);
    const char *demo[] = {"kit", "-q", "-o", dir, cli_kit_scenes[0], "scenes/demo.scene", NULL};
    cli_refray(r, demo);
    ck_assert_int_eq(r->code, 65);
    ck_assert_msg(strstr(r->err, "no exact image") != NULL, "stderr: %s", r->err);
    /* One light sample of a disk: a bound of 5.86, which a black image meets
     * ([VERIFY-UNBOUNDED-2]). */
    const char *unbounded[] = {"kit", "-q", "-o", dir, "tests/attack10/disk_light_1sample.scene", NULL};
    cli_refray(r, unbounded);
    ck_assert_int_eq(r->code, 65);
    ck_assert_msg(strstr(r->err, "cannot tell the image from one of half its light") != NULL, "stderr: %s", r->err);
    /* 16 light samples of a disk at 32 x 24: a bound of 0.992, which an image
     * of 1 % meets (attack 11, finding 4). */
    const char *dim[] = {"kit", "-q", "-o", dir, "tests/attack11/disk_light_16.scene", NULL};
    cli_refray(r, dim);
    ck_assert_int_eq(r->code, 65);
    ck_assert_msg(strstr(r->err, "half its light") != NULL, "stderr: %s", r->err);
    const char *missing[] = {"kit", "-q", "-o", dir, "scenes/analytic/nonexistent.scene", NULL};
    cli_refray(r, missing);
    ck_assert_int_eq(r->code, 66);
    const char *twice[] = {"kit", "-q", "-o", dir, cli_kit_scenes[0], cli_kit_scenes[0], NULL};
    cli_refray(r, twice);
    ck_assert_int_eq(r->code, 64);
    ck_assert_msg(cli_entries(work) == 0, "a failed kit left files in %s", work);
    /* A directory that is not a kit is not replaced. */
    char why[256];
    ck_assert_int_eq(file_make_dirs(dir, why, sizeof why), 0);
    ck_assert_int_eq(file_write_bytes(cli_path(path, sizeof path, dir, "mine.txt"), "x", 1, why, sizeof why), 0);
    const char *over[] = {"kit", "-q", "-o", dir, cli_kit_scenes[0], NULL};
    cli_refray(r, over);
    ck_assert_int_eq(r->code, 64);
    ck_assert(cli_exists(path));
    /* Nor is one that holds someone else's manifest.json (a web extension's):
     * the name alone made it "a kit", and the directory was deleted whole. */
    char other[300];
    static const char ext[] = "{\"manifest_version\": 3, \"name\": \"an extension\"}\n";
    cli_path(other, sizeof other, dir, "manifest.json");
    ck_assert_int_eq(file_write_bytes(other, ext, sizeof ext - 1, why, sizeof why), 0);
    cli_refray(r, over);
    ck_assert_int_eq(r->code, 64);
    ck_assert(cli_exists(path));
    ck_assert(cli_exists(other));
    /* A kit is: the old one goes whole. */
    cli_remove(dir);
    cli_refray(r, over);
    ck_assert_int_eq(r->code, 0);
    ck_assert_int_eq(file_write_bytes(path, "x", 1, why, sizeof why), 0);
    const char *again[] = {"kit", "-q", "-o", dir, cli_kit_scenes[1], NULL};
    cli_refray(r, again);
    ck_assert_int_eq(r->code, 0);
    ck_assert(!cli_exists(path));
    ck_assert(cli_exists(cli_path(path, sizeof path, dir, "scenes/disk_light/disk_light.exact.pfm")));
    ck_assert(!cli_exists(cli_path(path, sizeof path, dir, "scenes/plane_point_linear")));
    cli_remove(work);
    free(r);
}
END_TEST

/* The exact image scaled by (1 + f), written as PFM at path. */
static void perturbed(const char *dir, const manifest_scene *s, double f, const char *path)
{
    char src[512], err[512];
    img_buf img;
    ck_assert_int_eq(img_read(cli_path(src, sizeof src, dir, s->files[MANIFEST_FILE_EXACT_PFM]), NULL, &img, err,
                              sizeof err), 0);
    for (int i = 0; i < 3 * img.width * img.height; i++)
        img.rgb[i] *= 1 + f;
    ck_assert_int_eq(img_write(path, &img, NULL, err, sizeof err), 0);
    img_free(&img);
}

/* [KIT-RULE-1] compare --manifest: the scene's tolerance and mask, B its
 * exact image by default.  plane_point_linear is deterministic: relative
 * 1e-4, so 1 + 2e-4 is over and 1 + 2e-5 is within. */
START_TEST(test_cli_compare_manifest)
{
    char dir[128], work[64], mf[300], a[300];
    manifest m;
    cli_run *r = malloc(sizeof *r);
    kit(dir, sizeof dir, &m);
    cli_scratch(work, sizeof work, "kitcompare");
    cli_path(mf, sizeof mf, dir, "manifest.json");
    perturbed(dir, &m.scenes[0], 2e-5, cli_path(a, sizeof a, work, "a.pfm"));
    const char *within[] = {"compare", a, "--manifest", mf, "--scene", "plane_point_linear", "--json", NULL};
    cli_refray(r, within);
    ck_assert_msg(r->code == 0, "stdout %s stderr %s", r->out, r->err);
    ck_assert(strstr(r->out, "\"over\": 0,") && strstr(r->out, "\"scene\": \"plane_point_linear\""));
    perturbed(dir, &m.scenes[0], 2e-4, a);
    cli_refray(r, within);
    ck_assert_int_eq(r->code, 1);
    /* The scene found from B's name. */
    char b[512];
    const char *by_b[] = {"compare", a, cli_path(b, sizeof b, dir, m.scenes[0].files[MANIFEST_FILE_EXACT_PFM]),
                          "--manifest", mf, NULL};
    cli_refray(r, by_b);
    ck_assert_int_eq(r->code, 1);
    ck_assert_msg(strstr(r->out, "scene plane_point_linear") != NULL, "stdout: %s", r->out);
    const char *no_scene[] = {"compare", a, "--manifest", mf, NULL};
    cli_refray(r, no_scene);
    ck_assert_int_eq(r->code, 64);
    const char *unknown[] = {"compare", a, "--manifest", mf, "--scene", "nope", NULL};
    cli_refray(r, unknown);
    ck_assert_int_eq(r->code, 64);
    const char *both[] = {"compare", a, "--manifest", mf, "--scene", "x", "--tolerance", "1", NULL};
    cli_refray(r, both);
    ck_assert_int_eq(r->code, 64);
    const char *lone[] = {"compare", a, a, "--scale", "manifest", NULL};
    cli_refray(r, lone);
    ck_assert_int_eq(r->code, 64);
    cli_remove(work);
    manifest_free(&m);
    free(r);
}
END_TEST

#endif /* REFRAY_HAVE_JSON */

/*
 * [KIT-ADJUST-1] compare --downsample 2 --scale 0.5: B is 2 x 1 of
 * (0.25, 0.5, 1) and (1, 1, 1); A is 4 x 2, each 2 x 2 block holding four
 * values whose mean is twice B's (0.375, 0.625, 0.5, 0.5 for 0.25): equal
 * after the adjustment, every value a short binary fraction, exact in float.
 */
START_TEST(test_cli_compare_downsample_scale)
{
    static const double quarter[4] = {0.75, 1.25, 1.0, 1.0}; /* mean 1 */
    char work[64], pa[300], pb[300], err[256];
    img_buf a, b;
    cli_run *r = malloc(sizeof *r);
    cli_scratch(work, sizeof work, "adjust");
    ck_assert_int_eq(img_create(&b, 2, 1), 0);
    ck_assert_int_eq(img_create(&a, 4, 2), 0);
    double bv[2][3] = {{0.25, 0.5, 1}, {1, 1, 1}};
    for (int x = 0; x < 2; x++)
        for (int c = 0; c < 3; c++) {
            img_pixel(&b, x, 0)[c] = bv[x][c];
            for (int q = 0; q < 4; q++)
                img_pixel(&a, 2 * x + q % 2, q / 2)[c] = 2 * bv[x][c] * quarter[q];
        }
    ck_assert_int_eq(img_write(cli_path(pa, sizeof pa, work, "a.pfm"), &a, NULL, err, sizeof err), 0);
    ck_assert_int_eq(img_write(cli_path(pb, sizeof pb, work, "b.pfm"), &b, NULL, err, sizeof err), 0);
    const char *adjusted[] = {"compare", pa, pb, "--downsample", "2", "--scale", "0.5", "--tolerance", "0", NULL};
    cli_refray(r, adjusted);
    ck_assert_msg(r->code == 0, "stdout %s stderr %s", r->out, r->err);
    ck_assert(strstr(r->out, "PSNR:     inf") && strstr(r->out, "averaged over 2x2 blocks, then times 0.5"));
    const char *unscaled[] = {"compare", pa, pb, "--downsample", "2", "--tolerance", "0.1", NULL};
    cli_refray(r, unscaled);
    ck_assert_int_eq(r->code, 1);
    const char *plain[] = {"compare", pa, pb, NULL};
    cli_refray(r, plain);
    ck_assert_int_eq(r->code, 65);
    const char *three[] = {"compare", pa, pb, "--downsample", "3", NULL};
    cli_refray(r, three);
    ck_assert_int_eq(r->code, 65);
    ck_assert_msg(strstr(r->err, "must be 6x3") != NULL, "stderr: %s", r->err);
    const char *zero[] = {"compare", pa, pb, "--scale", "0", NULL};
    cli_refray(r, zero);
    ck_assert_int_eq(r->code, 64);
    img_free(&a);
    img_free(&b);
    cli_remove(work);
    free(r);
}
END_TEST

#if !REFRAY_HAVE_JSON
/* A build without jansson cannot write manifests: kit and compare
 * --manifest are usage errors that name the missing feature. */
START_TEST(test_cli_kit_needs_json)
{
    char work[64], dir[300];
    cli_run *r = malloc(sizeof *r);
    cli_scratch(work, sizeof work, "kitnojson");
    const char *args[] = {"kit", "-o", cli_path(dir, sizeof dir, work, "k"), cli_kit_scenes[0], NULL};
    cli_refray(r, args);
    ck_assert_int_eq(r->code, 64);
    ck_assert_msg(strstr(r->err, "JSON") != NULL, "stderr: %s", r->err);
    ck_assert(!cli_exists(dir));
    const char *cmp[] = {"compare", "a.pfm", "--manifest", "m.json", "--scene", "x", NULL};
    cli_refray(r, cmp);
    ck_assert_int_eq(r->code, 64);
    cli_remove(work);
    free(r);
}
END_TEST
#endif

Suite *suite_kit(void)
{
    Suite *s = suite_create("kit");
    TCase *tc = tcase_create("kit");
    tcase_add_unchecked_fixture(tc, kit_setup, kit_teardown);
    tcase_set_timeout(tc, 20);
#if REFRAY_HAVE_JSON
    tcase_add_test(tc, test_kit_layout);
    tcase_add_test(tc, test_kit_exact_is_oracle);
    tcase_add_test(tc, test_kit_manifest_numbers);
    tcase_add_test(tc, test_manifest_round_trip);
    tcase_add_test(tc, test_manifest_read_errors);
    tcase_add_test(tc, test_manifest_refuses_a_bound_of_one_half_or_more);
    tcase_add_test(tc, test_manifest_refuses_a_scale_or_absolute_off_its_definition);
    tcase_add_test(tc, test_cli_kit_refuses_a_black_image);
    tcase_add_test(tc, test_cli_kit_errors);
    tcase_add_test(tc, test_cli_compare_manifest);
#else
    tcase_add_test(tc, test_cli_kit_needs_json);
#endif
    tcase_add_test(tc, test_cli_compare_downsample_scale);
    suite_add_tcase(s, tc);
    return s;
}
