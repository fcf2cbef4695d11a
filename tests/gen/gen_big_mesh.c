/*
 * gen_big_mesh.c - a closed torus mesh of 2 U V triangles (default
 * 1,000,000) for the scale measurement of spec/numerics.md ("Meshes at
 * scale"), and a scene that renders it:
 *
 *     build/gen_big_mesh OUT_DIR [--u U] [--v V] [--ply]
 *
 * OUT_DIR/torus.obj (or torus.ply, binary little-endian, with --ply) holds
 * U x V vertices on a torus of radii 2 and 0.75, each grid cell cut into
 * two triangles wound outward; OUT_DIR/torus.scene reads it.  Coordinates
 * are written with 17 significant digits, so the mesh is closed to the bit:
 * every edge is shared by exactly two triangles and consecutive rings share
 * their vertices by index.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "gen.h"

static const char usage[] = "gen_big_mesh OUT_DIR [--u U] [--v V] [--ply]";

static void usage_error(void)
{
    fprintf(stderr, "usage: %s\n", usage);
    exit(64);
}

static void vertex(int u, int v, long k, double p[3])
{
    long i = k / v, j = k % v;
    double a = 2 * GEN_PI * i / u, b = 2 * GEN_PI * j / v;
    double r = 2.0 + 0.75 * cos(b);
    p[0] = r * cos(a);
    p[1] = 0.75 * sin(b);
    p[2] = r * sin(a);
}

/* Triangle t (two per grid cell, 0-based corners). */
static void triangle(int u, int v, long t, long c[3])
{
    long cell = t / 2, i = cell / v, j = cell % v;
    long i1 = (i + 1) % u, j1 = (j + 1) % v;
    long a = i * v + j, b = i1 * v + j, cc = i1 * v + j1, d = i * v + j1;
    long first[3] = {a, d, cc}, second[3] = {a, cc, b};
    memcpy(c, t % 2 ? second : first, sizeof first);
}

static void put_le(FILE *f, const void *p, size_t bytes)
{
    const unsigned char *b = p;
    unsigned probe = 1;
    int little = *(const unsigned char *)&probe == 1;
    for (size_t k = 0; k < bytes; k++)
        fputc(b[little ? k : bytes - 1 - k], f);
}

static void write_obj(FILE *f, int u, int v)
{
    long verts = (long)u * v, tris = 2 * verts;
    fprintf(f, "# closed torus, %ld triangles (tests/gen/gen_big_mesh.c)\n", tris);
    for (long k = 0; k < verts; k++) {
        double p[3];
        vertex(u, v, k, p);
        fprintf(f, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    }
    for (long t = 0; t < tris; t++) {
        long c[3];
        triangle(u, v, t, c);
        fprintf(f, "f %ld %ld %ld\n", c[0] + 1, c[1] + 1, c[2] + 1);
    }
}

static void write_ply(FILE *f, int u, int v)
{
    long verts = (long)u * v, tris = 2 * verts;
    fprintf(f, "ply\nformat binary_little_endian 1.0\ncomment tests/gen/gen_big_mesh.c\n");
    fprintf(f, "element vertex %ld\nproperty double x\nproperty double y\nproperty double z\n", verts);
    fprintf(f, "element face %ld\nproperty list uchar int vertex_indices\nend_header\n", tris);
    for (long k = 0; k < verts; k++) {
        double p[3];
        vertex(u, v, k, p);
        for (int c = 0; c < 3; c++)
            put_le(f, &p[c], sizeof p[c]);
    }
    for (long t = 0; t < tris; t++) {
        long c[3];
        triangle(u, v, t, c);
        fputc(3, f);
        for (int k = 0; k < 3; k++) {
            int32_t index = (int32_t)c[k];
            put_le(f, &index, sizeof index);
        }
    }
}

static int count_arg(const char *s)
{
    char *end;
    long n = strtol(s, &end, 10);
    if (*end || n < 3 || n > 30000)
        usage_error();
    return (int)n;
}

int main(int argc, char **argv)
{
    const char *out = NULL;
    int u = 1000, v = 500, ply = 0;
    for (int k = 1; k < argc; k++) {
        if (strcmp(argv[k], "--ply") == 0)
            ply = 1;
        else if (strcmp(argv[k], "--u") == 0 && k + 1 < argc)
            u = count_arg(argv[++k]);
        else if (strcmp(argv[k], "--v") == 0 && k + 1 < argc)
            v = count_arg(argv[++k]);
        else if (argv[k][0] != '-' && !out)
            out = argv[k];
        else
            usage_error();
    }
    if (!out)
        usage_error();
    const char *name = ply ? "torus.ply" : "torus.obj";
    FILE *f = gen_open(out, name);
    (ply ? write_ply : write_obj)(f, u, v);
    gen_close(f, name);
    f = gen_open(out, "torus.scene");
    fprintf(f, "# %ld triangles: tests/gen/gen_big_mesh.c\n", 2L * u * v);
    fputs("image  { width 320 height 240 }\n"
          "camera { perspective eye [0, 5, 6] look_at [0, 0, 0] up [0, 1, 0] fov 45 }\n"
          "ambient { color 0.1 }\n"
          "distant_light { direction [-1, -2, -1] power 0.9 }\n", f);
    fprintf(f, "mesh { file \"%s\" material { Kd [0.7, 0.5, 0.3] } }\n", name);
    gen_close(f, "torus.scene");
    return 0;
}
