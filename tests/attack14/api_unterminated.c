/* api_unterminated.c - texts handed to the library exactly as long as their
 * size, with no NUL after them (refray.h: a resolver's text "need not be
 * NUL-terminated"; rf_scene_load_memory takes a size), each in a block of
 * its own so that valgrind or ASan sees a read past the end.  The last
 * number of each file runs up to the block's end (no final new line):
 * a scene, an included scene, an OBJ and an ASCII PLY.
 * Run under valgrind: exit 0 and no error when the library reads only
 * what it was given. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <refray.h>

static char *exact(const char *s)
{
    size_t n = strlen(s);
    char *p = malloc(n);
    memcpy(p, s, n);
    return p;
}

static const char *texts[][2] = {
    {"inc.scene", "material m { Kd 0.5 Ks 0 }\nlet last = 0.25"},
    {"q.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0.0\nf 1 2 3 4"},
    {"q.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 2\n1 0 2\n0 1 2\n3 0 1 2"},
};

static rf_status fetch(void *u, const char *from, const char *name, rf_source *out, char *m, size_t ms)
{
    (void)u; (void)from; (void)m; (void)ms;
    memset(out, 0, sizeof *out);
    for (int i = 0; i < 3; i++)
        if (strcmp(name, texts[i][0]) == 0) {
            out->text = exact(texts[i][1]);
            out->size = strlen(texts[i][1]);
            return RF_OK;
        }
    return RF_ERR_NO_INPUT;
}

static void release(void *u, rf_source *s)
{
    (void)u;
    free((void *)s->text);
}

int main(void)
{
    const char *main_text = "include \"inc.scene\"\nimage { width 8 height 6 }\n"
                            "camera { perspective eye [0, 0, 5] look_at [0, 0, 0] up [0, 1, 0] fov 60 }\n"
                            "ambient { color [last, last, last] }\n"
                            "mesh { file \"q.obj\" material m }\nmesh { file \"q.ply\" material m }\n"
                            "sphere { center [0, 0, -3] radius 1 material m }";
    char *text = exact(main_text);
    rf_load_options o;
    rf_load_options_init(&o);
    o.resolver.fetch = fetch;
    o.resolver.release = release;
    o.diagnostic = rf_diagnostic_print;
    o.diagnostic_user = stderr;
    rf_scene *s;
    rf_status st = rf_scene_load_memory("main.scene", text, strlen(main_text), &o, &s);
    printf("load: %s\n", rf_status_string(st));
    if (st == RF_OK) {
        rf_image *img;
        st = rf_render_image(s, NULL, &img, NULL);
        printf("render: %s\n", rf_status_string(st));
        if (st == RF_OK)
            rf_image_free(img);
        rf_scene_free(s);
    }
    free(text);
    return st == RF_OK ? 0 : 1;
}
