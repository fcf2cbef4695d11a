/*
 * gen_ply_corpus.c - the PLY test corpus (tests/check_ply.c, spec/language.md
 * section 8):
 *
 *     build/gen_ply_corpus [ROOT]             (make fixtures)
 *
 * ROOT/tests/ply/uvsphere.obj and uvsphere_{ascii,le,be}.ply: one smooth
 * mesh (a UV sphere of 8 x 6 cells: quads, triangle fans at the poles, unit
 * vertex normals) in OBJ and in the three PLY encodings, with the same
 * numbers: every coordinate is a float32 value, written in text as the
 * shortest decimal that reads back as that very value, so all four files
 * describe the same doubles and must render the same image.  The PLY files
 * add what a reader must skip: colour properties of every integer type, a
 * texture coordinate list on the faces, an element of its own with a
 * property of every scalar type.
 *
 * ROOT/tests/bad/inc/{truncated,index_range,list_count,nan}.ply: binary files
 * for the error corpus (tests/bad/ply-truncated.scene and the others).
 */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "gen.h"

enum { U = 8, V = 6, VERTS = U * (V - 1) + 2, FACES = U * V, CORNERS_MAX = 4 };

typedef struct sphere {
    double vert[VERTS][3], norm[VERTS][3];
    int face[FACES][CORNERS_MAX], corners[FACES];
} sphere;

/* x rounded to float32.  Through a volatile: gcc 12.2 at -O2 vectorizes
 * the loop that calls this and drops the round trip (double)(float)x of
 * two of the three coordinates (seen with -O2, fixed by
 * -fno-tree-slp-vectorize or this). */
static double f32(double x)
{
    volatile float v = (float)x;
    return v;
}

static void add_face(sphere *s, int k, int n, int a, int b, int c, int d)
{
    int v[4] = {a, b, c, d};
    s->corners[k] = n;
    memcpy(s->face[k], v, sizeof v);
}

static void make_sphere(sphere *s)
{
    for (int j = 1; j < V; j++) {
        double b = GEN_PI * j / V;
        for (int i = 0; i < U; i++) {
            double a = 2 * GEN_PI * i / U, n[3] = {sin(b) * cos(a), cos(b), sin(b) * sin(a)};
            for (int c = 0; c < 3; c++) {
                s->vert[(j - 1) * U + i][c] = f32(n[c] * 1.5);
                s->norm[(j - 1) * U + i][c] = f32(n[c]);
            }
        }
    }
    const double poles[2][3] = {{0, 1, 0}, {0, -1, 0}};
    for (int p = 0; p < 2; p++)
        for (int c = 0; c < 3; c++) {
            s->vert[VERTS - 2 + p][c] = 1.5 * poles[p][c];
            s->norm[VERTS - 2 + p][c] = poles[p][c];
        }
    int top = VERTS - 2, bottom = VERTS - 1, k = 0, last = (V - 2) * U;
    for (int i = 0; i < U; i++) {
        int i1 = (i + 1) % U;
        add_face(s, k++, 3, top, i1, i, 0);
        for (int j = 0; j < V - 2; j++)
            add_face(s, k++, 4, j * U + i, j * U + i1, j * U + i1 + U, j * U + i + U);
        add_face(s, k++, 3, bottom, last + i, last + i1, 0);
    }
}

static void put_triple(FILE *f, const double *p)
{
    for (int c = 0; c < 3; c++) {
        if (c)
            fputc(' ', f);
        gen_put(f, p[c]);
    }
}

static void write_obj(const char *root, const sphere *s)
{
    const char *path = "tests/ply/uvsphere.obj";
    FILE *f = gen_open(root, path);
    fputs("# A UV sphere of 8 x 6 cells, smooth (tests/gen/gen_ply_corpus.c).\n", f);
    for (int k = 0; k < VERTS; k++) {
        fputs("v ", f);
        put_triple(f, s->vert[k]);
        fputc('\n', f);
    }
    for (int k = 0; k < VERTS; k++) {
        fputs("vn ", f);
        put_triple(f, s->norm[k]);
        fputc('\n', f);
    }
    for (int k = 0; k < FACES; k++) {
        fputc('f', f);
        for (int c = 0; c < s->corners[k]; c++)
            fprintf(f, " %d//%d", s->face[k][c] + 1, s->face[k][c] + 1);
        fputc('\n', f);
    }
    gen_close(f, path);
}

static const char header[] = "ply\n"
                             "format %s 1.0\n"
                             "comment A UV sphere of 8 x 6 cells (tests/gen/gen_ply_corpus.c)\n"
                             "obj_info the same numbers as uvsphere.obj\n"
                             "element vertex %d\n"
                             "property float x\n"
                             "property float y\n"
                             "property float z\n"
                             "property uchar red\n"
                             "property short green\n"
                             "property uint blue\n"
                             "property float nx\n"
                             "property float ny\n"
                             "property float nz\n"
                             "element face %d\n"
                             "property list uchar int vertex_indices\n"
                             "property list int float texcoord\n"
                             "element extra 2\n"
                             "property char c\n"
                             "property ushort us\n"
                             "property int i\n"
                             "property double d\n"
                             "property list ushort double values\n"
                             "end_header\n";

/* The element `extra`: c, us, i, d and a list of doubles. */
typedef struct extra {
    int c, us;
    long i;
    double d;
    int count;
    double values[2];
} extra;

static const extra extras[2] = {{-5, 65000, -70000, 0.25, 2, {1.5, 2.5}}, {7, 1, 2, -1e300, 0, {0, 0}}};

/* Binary values: `bytes` bytes of u, most significant first when big. */
static void put_bytes(FILE *f, uint64_t u, int bytes, int big)
{
    for (int k = 0; k < bytes; k++)
        fputc((int)(u >> 8 * (big ? bytes - 1 - k : k) & 0xff), f);
}

static void put_int(FILE *f, long v, int bytes, int big)
{
    put_bytes(f, (uint64_t)v, bytes, big);
}

static void put_float(FILE *f, double x, int big)
{
    float v = (float)x;
    uint32_t u;
    memcpy(&u, &v, sizeof u);
    put_bytes(f, u, 4, big);
}

static void put_double(FILE *f, double x, int big)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    put_bytes(f, u, 8, big);
}

static void ascii_body(FILE *f, const sphere *s)
{
    for (int k = 0; k < VERTS; k++) {
        put_triple(f, s->vert[k]);
        fprintf(f, " %d %d %d ", k % 256, -k, 70000 + k);
        put_triple(f, s->norm[k]);
        fputc('\n', f);
    }
    for (int k = 0; k < FACES; k++) {
        fprintf(f, "%d", s->corners[k]);
        for (int c = 0; c < s->corners[k]; c++)
            fprintf(f, " %d", s->face[k][c]);
        fputs(" 2 0.5 0.25\n", f);
    }
    for (int e = 0; e < 2; e++) {
        fprintf(f, "%d %d %ld ", extras[e].c, extras[e].us, extras[e].i);
        gen_put(f, extras[e].d);
        fprintf(f, " %d ", extras[e].count);
        for (int v = 0; v < extras[e].count; v++) {
            if (v)
                fputc(' ', f);
            gen_put(f, extras[e].values[v]);
        }
        fputc('\n', f);
    }
}

static void binary_body(FILE *f, const sphere *s, int big)
{
    for (int k = 0; k < VERTS; k++) {
        for (int c = 0; c < 3; c++)
            put_float(f, s->vert[k][c], big);
        put_int(f, k % 256, 1, big);
        put_int(f, -k, 2, big);
        put_int(f, 70000 + k, 4, big);
        for (int c = 0; c < 3; c++)
            put_float(f, s->norm[k][c], big);
    }
    for (int k = 0; k < FACES; k++) {
        put_int(f, s->corners[k], 1, big);
        for (int c = 0; c < s->corners[k]; c++)
            put_int(f, s->face[k][c], 4, big);
        put_int(f, 2, 4, big);
        put_float(f, 0.5, big);
        put_float(f, 0.25, big);
    }
    for (int e = 0; e < 2; e++) {
        put_int(f, extras[e].c, 1, big);
        put_int(f, extras[e].us, 2, big);
        put_int(f, extras[e].i, 4, big);
        put_double(f, extras[e].d, big);
        put_int(f, extras[e].count, 2, big);
        for (int v = 0; v < extras[e].count; v++)
            put_double(f, extras[e].values[v], big);
    }
}

static void write_ply(const char *root, const sphere *s, const char *name, const char *format)
{
    char path[64];
    snprintf(path, sizeof path, "tests/ply/uvsphere_%s.ply", name);
    FILE *f = gen_open(root, path);
    fprintf(f, header, format, VERTS, FACES);
    if (strcmp(format, "ascii") == 0)
        ascii_body(f, s);
    else
        binary_body(f, s, strcmp(format, "binary_big_endian") == 0);
    gen_close(f, path);
}

/* A bad file: the format line, the header of a triangle, the corners
 * (3 floats each), then the face's bytes as given. */
static void write_bad(const char *root, const char *name, int big, const double corners[9],
                      const unsigned char *face, int face_bytes)
{
    char path[64];
    snprintf(path, sizeof path, "tests/bad/inc/%s.ply", name);
    FILE *f = gen_open(root, path);
    fprintf(f, "ply\nformat binary_%s_endian 1.0\n", big ? "big" : "little");
    fputs("element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
          "element face 1\nproperty list uchar int vertex_indices\nend_header\n", f);
    for (int k = 0; k < 9; k++)
        put_float(f, corners[k], big);
    fwrite(face, 1, (size_t)face_bytes, f);
    gen_close(f, path);
}

static void write_bad_files(const char *root)
{
    const double tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    double with_nan[9];
    memcpy(with_nan, tri, sizeof tri);
    with_nan[4] = NAN;
    static const unsigned char truncated[5] = {3, 0, 0, 0, 0};
    static const unsigned char out_of_range[13] = {3, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 7};
    static const unsigned char list_count[13] = {200};
    static const unsigned char good[13] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
    write_bad(root, "truncated", 0, tri, truncated, 5);
    write_bad(root, "index_range", 1, tri, out_of_range, 13);
    write_bad(root, "list_count", 0, tri, list_count, 13);
    write_bad(root, "nan", 0, with_nan, good, 13);
}

int main(int argc, char **argv)
{
    const char *root = gen_root(argc, argv, "gen_ply_corpus [ROOT]");
    static sphere s;
    make_sphere(&s);
    write_obj(root, &s);
    write_ply(root, &s, "ascii", "ascii");
    write_ply(root, &s, "le", "binary_little_endian");
    write_ply(root, &s, "be", "binary_big_endian");
    write_bad_files(root);
    return 0;
}
