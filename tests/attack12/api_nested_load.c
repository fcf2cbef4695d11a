/*
 * api_nested_load.c - reentrancy: the diagnostic callback of one load
 * starts another load (of a second scene with its own error) and renders
 * it, before the outer load has returned.  Then the outer scene renders.
 * Exit 0 when every status is as expected and the images match the same
 * loads done one after the other; run it under valgrind too.
 */
#include <stdio.h>
#include <string.h>
#include <refray.h>

static const char outer_text[] =
    "image { width 8 height 6 }\nmaterial unused { Kd 0.5 }\n"
    "sphere { center [0, 0, 0] radius 1 }\npoint_light { position [2, 2, 3] power 4 }\n";
static const char inner_text[] =
    "image { width 8 height 6 }\nsphere { center [0, 0, 0] radius 1.5 material { Kd [1, 0, 0] } }\n"
    "ambient { color 0.5 }\nsphere { center [1, 0, 0] radius -1 }\n";
static const char inner_ok[] =
    "image { width 8 height 6 }\nsphere { center [0, 0, 0] radius 1.5 material { Kd [1, 0, 0] } }\n"
    "ambient { color 0.5 }\n";

typedef struct state {
    int depth, calls;
    rf_status inner_bad, inner_good;
    double inner_pixel;
} state;

static double centre(rf_scene *s)
{
    rf_image *img = NULL;
    double v = -1;
    if (rf_render_image(s, NULL, &img, NULL) == RF_OK)
        v = rf_image_pixels(img)[3 * (3 * 8 + 4)];
    rf_image_free(img);
    return v;
}

static void on_diag(void *user, const rf_diagnostic *d)
{
    state *st = user;
    rf_load_options o;
    rf_scene *s = NULL;
    st->calls++;
    printf("depth %d: %s\n", st->depth, d->message);
    if (st->depth > 0)
        return;
    st->depth++;
    rf_load_options_init(&o);
    o.diagnostic = on_diag;
    o.diagnostic_user = st;
    st->inner_bad = rf_scene_load_memory("inner.scene", inner_text, strlen(inner_text), &o, &s);
    rf_scene_free(s);
    s = NULL;
    st->inner_good = rf_scene_load_memory("inner_ok.scene", inner_ok, strlen(inner_ok), &o, &s);
    st->inner_pixel = st->inner_good == RF_OK ? centre(s) : -1;
    rf_scene_free(s);
    st->depth--;
}

int main(void)
{
    state st = {0, 0, RF_OK, RF_OK, 0};
    rf_load_options o;
    rf_scene *outer = NULL, *plain = NULL;
    rf_load_options_init(&o);
    o.diagnostic = on_diag;
    o.diagnostic_user = &st;
    rf_status so = rf_scene_load_memory("outer.scene", outer_text, strlen(outer_text), &o, &outer);
    double po = so == RF_OK ? centre(outer) : -1;
    rf_load_options_init(&o);
    rf_status sp = rf_scene_load_memory("inner_ok.scene", inner_ok, strlen(inner_ok), &o, &plain);
    double pp = sp == RF_OK ? centre(plain) : -1;
    rf_scene_free(plain);
    rf_load_options_init(&o);
    o.warnings = 0;
    sp = rf_scene_load_memory("outer.scene", outer_text, strlen(outer_text), &o, &plain);
    double pq = sp == RF_OK ? centre(plain) : -1;
    rf_scene_free(plain);
    rf_scene_free(outer);
    printf("outer %s (%.9g, alone %.9g); inner bad %s; inner good %s (%.9g, alone %.9g); %d callbacks\n",
           rf_status_string(so), po, pq, rf_status_string(st.inner_bad), rf_status_string(st.inner_good),
           st.inner_pixel, pp, st.calls);
    return !(so == RF_OK && st.inner_bad == RF_ERR_DATA && st.inner_good == RF_OK && po == pq &&
             st.inner_pixel == pp && po >= 0 && pp >= 0);
}
