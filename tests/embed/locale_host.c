/*
 * locale_host.c - [EMBED-LOCALE-1]: a host whose locale writes 0.5 as
 * "0,5" (it called setlocale, as GUI programs do) loads scenes through the
 * library and gets the numbers the scene says.
 *
 *   locale_host LOCALE     (a locale whose decimal point is ',')
 *
 * Checks, each against a value known without the library's own reading:
 *  1. a scene rendered in LOCALE gives the pixel of the C locale, and that
 *     pixel is the ambient 0.25 times Kd 1 (an orthographic view straight
 *     at a sphere of radius 1.75 whose centre is 0.5 off the axis: a
 *     scanner that stopped at '.' would read radius 1 and ambient 0, and
 *     the pixel 1.5 off the axis would show the background 0.5);
 *  2. a diagnostic's message prints its number with '.' ("got 1.5"), as
 *     the scene wrote it, while the host's callback runs in the host's
 *     locale (its own printf writes "0,5");
 *  3. the host's locale is back after each load.
 * Exit 0 when all hold, 1 otherwise, 2 when LOCALE cannot be set.
 */
#include <locale.h>
#include <stdio.h>
#include <string.h>
#include <refray.h>

static const char lit_scene[] =
    "image  { width 4  height 3  samples 1  max_depth 1  background [0.5, 0.5, 0.5] }\n"
    "camera { orthographic  eye [0, 0, 5]  look_at [0, 0, 0]  up [0, 1, 0]  width 4 }\n"
    "ambient { color 0.25 }\n"
    "sphere { center [0.5, 0, 0]  radius 1.75  material { Kd 1 } }\n";

static const char bad_scene[] = "sphere { center [0, 0, 0] radius 1 material { Kd 1.5 } }\n";

static int failures;

static void expect(int ok, const char *what)
{
    if (!ok) {
        printf("locale_host: FAIL: %s\n", what);
        failures++;
    }
}

/* Whether the thread formats numbers with ','. */
static int comma_now(void)
{
    char s[16];
    snprintf(s, sizeof s, "%.1f", 0.5);
    return strcmp(s, "0,5") == 0;
}

/* Pixel (2, 1)'s red channel, 1.5 off the axis; -1 on a failure. */
static double render_pixel(void)
{
    rf_scene *scene = NULL;
    rf_image *img = NULL;
    double v = -1;
    rf_status s = rf_scene_load_memory("lit.scene", lit_scene, strlen(lit_scene), NULL, &scene);
    if (s == RF_OK)
        s = rf_render_image(scene, NULL, &img, NULL);
    if (s == RF_OK)
        v = rf_image_pixels(img)[3 * (1 * 4 + 2)];
    rf_image_free(img);
    rf_scene_free(scene);
    return v;
}

struct seen {
    int calls, comma_inside, message_right;
};

static void on_diagnostic(void *user, const rf_diagnostic *d)
{
    struct seen *seen = user;
    seen->calls++;
    seen->comma_inside += comma_now();
    seen->message_right += strstr(d->message, "got 1.5") != NULL;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: locale_host LOCALE\n");
        return 2;
    }
    double in_c = render_pixel();
    expect(in_c == 0.25, "the C locale's pixel is the ambient 0.25");
    if (!setlocale(LC_ALL, argv[1]) || !comma_now()) {
        fprintf(stderr, "locale_host: %s cannot be set or does not write 0.5 as 0,5\n", argv[1]);
        return 2;
    }
    expect(render_pixel() == in_c, "the pixel in the host's locale is the C locale's");
    expect(comma_now(), "the host's locale is back after a load and a render");

    rf_load_options o;
    rf_scene *scene = NULL;
    struct seen seen = {0, 0, 0};
    rf_load_options_init(&o);
    o.diagnostic = on_diagnostic;
    o.diagnostic_user = &seen;
    rf_status s = rf_scene_load_memory("bad.scene", bad_scene, strlen(bad_scene), &o, &scene);
    expect(s == RF_ERR_DATA && !scene, "Kd 1.5 is refused");
    expect(seen.calls == 1, "one diagnostic");
    expect(seen.message_right == seen.calls, "the message writes the scene's number as 1.5");
    expect(seen.comma_inside == seen.calls, "the callback runs in the host's locale");
    expect(comma_now(), "the host's locale is back after a failed load");
    rf_scene_free(scene);
    if (failures == 0)
        printf("locale_host: a host in %s reads the scene's numbers as written\n", argv[1]);
    return failures == 0 ? 0 : 1;
}
