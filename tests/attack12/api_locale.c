/*
 * api_locale.c - a host program that sets its locale, as every GUI
 * program and many command-line ones do (setlocale(LC_ALL, "")), then
 * loads a scene through the public API.  In a locale whose decimal point
 * is ',' (de_DE, fr_FR, ru_RU, ...) C's strtod stops at '.', so a reader
 * built on it takes "0.5" as 0 and "1.5" as 1.  The library's header and
 * spec/embedding.md say nothing of the locale; src/lang/obj.h assumes
 * "the C locale's '.' decimal point ... (the library never calls
 * setlocale)", but the host may.
 *
 *   api_locale LOCALE        (a locale name or a path, e.g. one made by
 *                             localedef -i de_DE -f UTF-8 DIR/de_DE.UTF-8)
 *
 * Renders the same scene text in the "C" locale and in LOCALE, the pixel
 * (2, 1) of a 4 x 3 image: the sphere's radius 1.75 and the ambient 0.25.
 * Prints both and exits 1 when they differ or the load fails in LOCALE.
 */
#include <locale.h>
#include <stdio.h>
#include <string.h>
#include <refray.h>

static const char scene_text[] =
    "image  { width 4  height 3  samples 1  max_depth 1  background [0.5, 0.5, 0.5] }\n"
    "camera { orthographic  eye [0, 0, 5]  look_at [0, 0, 0]  up [0, 1, 0]  width 4 }\n"
    "ambient { color 0.25 }\n"
    "sphere { center [0.5, 0, 0]  radius 1.75  material { Kd 1 } }\n";

/* Pixel (2, 1)'s red channel, or -1 when the load or the render fails. */
static double render_pixel(const char *label)
{
    rf_load_options o;
    rf_scene *scene = NULL;
    rf_image *img = NULL;
    double v = -1;
    rf_load_options_init(&o);
    o.diagnostic = rf_diagnostic_print;
    o.diagnostic_user = stderr;
    rf_status s = rf_scene_load_memory("locale.scene", scene_text, strlen(scene_text), &o, &scene);
    if (s == RF_OK)
        s = rf_render_image(scene, NULL, &img, NULL);
    if (s == RF_OK)
        v = rf_image_pixels(img)[3 * (1 * 4 + 2)];
    printf("%s: %s, pixel (2, 1) red %.17g\n", label, rf_status_string(s), v);
    rf_image_free(img);
    rf_scene_free(scene);
    return v;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: api_locale LOCALE\n");
        return 2;
    }
    double c = render_pixel("C locale");
    if (!setlocale(LC_ALL, argv[1])) {
        fprintf(stderr, "api_locale: cannot set the locale %s\n", argv[1]);
        return 2;
    }
    printf("LC_NUMERIC now %s: 0.5 prints as %.1f\n", setlocale(LC_NUMERIC, NULL), 0.5);
    double l = render_pixel(argv[1]);
    return c == l && c >= 0 ? 0 : 1;
}
