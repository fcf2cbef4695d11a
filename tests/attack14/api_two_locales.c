/* api_two_locales.c - two host threads, each in its own locale (POSIX
 * uselocale: de_DE.UTF-8 with ',' and the C locale), loading and rendering
 * at once, 200 times each.  [EMBED-LOCALE-1]: each load runs in the C
 * locale on its thread, the thread's own locale back in its diagnostic
 * callback and after the load.  Checked per load: the pixel on the sphere
 * is Kd 1 x ambient 0.25 = 0.25 (a load reading `0.25` as 0 gives the
 * background 0.5), the warning's callback sees the thread's decimal point,
 * and the thread's locale object is current after the load.
 * usage: api_two_locales LOCALE    (LOCPATH may point at a localedef output)
 * Exit 1 on any wrong load, 0 when all hold. */
#define _POSIX_C_SOURCE 200809L
#include <locale.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include <refray.h>

static const char scene[] =
    "image { width 5 height 3 background [0.5, 0.5, 0.5] }\n"
    "camera { orthographic eye [0, 0, -5] look_at [0, 0, 0] up [0, 1, 0] width 1.75 }\n"
    "ambient { color [0.25, 0.25, 0.25] }\n"
    "material m { Kd 1.0 Ks 0 }\n"
    "material hot { Kd 0.75 Ks 0.5 }\n"       /* Kd + Ks over 1: a warning */
    "sphere { center [0, 0, 0] radius 0.75 material m }\n"
    "sphere { center [100.5, 0, 0] radius 0.5 material hot }\n";

struct job { locale_t loc; char point; int bad, diag_bad, after_bad, runs; };

static void diag(void *user, const rf_diagnostic *d)
{
    struct job *j = user;
    (void)d;
    if (localeconv()->decimal_point[0] != j->point)
        j->diag_bad++;
}

static void *work(void *arg)
{
    struct job *j = arg;
    uselocale(j->loc);
    for (int i = 0; i < 200; i++) {
        rf_load_options o;
        rf_load_options_init(&o);
        o.diagnostic = diag;
        o.diagnostic_user = j;
        rf_scene *s;
        float px[5 * 3 * 3];
        if (rf_scene_load_memory("t.scene", scene, strlen(scene), &o, &s) != RF_OK) {
            j->bad++;
            continue;
        }
        if (uselocale((locale_t)0) != j->loc)
            j->after_bad++;
        rf_renderer *r;
        if (rf_renderer_create(s, NULL, &r) != RF_OK || rf_render_region(r, 0, 0, 5, 3, px, 15) != RF_OK ||
            px[(1 * 5 + 2) * 3] != 0.25f)
            j->bad++;
        rf_renderer_free(r);
        rf_scene_free(s);
        j->runs++;
    }
    return NULL;
}

int main(int argc, char **argv)
{
    if (argc != 2)
        return 2;
    struct job a = {newlocale(LC_ALL_MASK, argv[1], (locale_t)0), ',', 0, 0, 0, 0};
    struct job b = {newlocale(LC_ALL_MASK, "C", (locale_t)0), '.', 0, 0, 0, 0};
    if (a.loc == (locale_t)0 || b.loc == (locale_t)0) {
        printf("no locale %s\n", argv[1]);
        return 2;
    }
    pthread_t ta, tb;
    pthread_create(&ta, NULL, work, &a);
    pthread_create(&tb, NULL, work, &b);
    pthread_join(ta, NULL);
    pthread_join(tb, NULL);
    printf("%s thread: %d loads, %d wrong, %d callbacks in another locale, %d times not its locale after\n",
           argv[1], a.runs, a.bad, a.diag_bad, a.after_bad);
    printf("C thread: %d loads, %d wrong, %d callbacks in another locale, %d times not its locale after\n", b.runs,
           b.bad, b.diag_bad, b.after_bad);
    return a.bad + a.diag_bad + a.after_bad + b.bad + b.diag_bad + b.after_bad ? 1 : 0;
}
