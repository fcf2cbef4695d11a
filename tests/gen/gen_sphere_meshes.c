/*
 * gen_sphere_meshes.c - the smooth sphere meshes of the shadow terminator
 * measurement (spec/shading.md, [SHADE-TERMINATOR-1]; `make terminator`,
 * scenes/terminator.scene):
 *
 *     build/gen_sphere_meshes [ROOT]          (make fixtures)
 *
 * ROOT/scenes/models/sphere_UxV.obj for U x V = 12x8, 24x16, 48x32: a unit
 * sphere cut into U slices around the y axis and V bands from pole to pole
 * (quads, triangle fans at the poles), wound outward, each vertex with its
 * exact unit normal (the sphere's), so the interpolated normals are as good
 * as a mesh can give and only the facets' positions are coarse.
 */
#include <math.h>
#include <stdlib.h>
#include "gen.h"

static void put_point(FILE *f, const char *word, const double *p)
{
    fputs(word, f);
    for (int c = 0; c < 3; c++) {
        fputc(' ', f);
        gen_put(f, p[c]);
    }
    fputc('\n', f);
}

/* The 1-based index of ring j's vertex i (i taken around). */
static int at(int u, int j, int i)
{
    return j * u + i % u + 1;
}

static void write_sphere(const char *root, int u, int v)
{
    char path[64];
    snprintf(path, sizeof path, "scenes/models/sphere_%dx%d.obj", u, v);
    int count = u * (v - 1) + 2;
    double(*p)[3] = malloc((size_t)count * sizeof *p);
    if (!p)
        exit(70);
    for (int j = 1; j < v; j++) {
        double b = GEN_PI * j / v;
        for (int i = 0; i < u; i++) {
            double a = 2 * GEN_PI * i / u, *q = p[(j - 1) * u + i];
            q[0] = sin(b) * cos(a);
            q[1] = cos(b);
            q[2] = -sin(b) * sin(a);
        }
    }
    const double poles[2][3] = {{0, 1, 0}, {0, -1, 0}};
    for (int c = 0; c < 3; c++) {
        p[count - 2][c] = poles[0][c];
        p[count - 1][c] = poles[1][c];
    }
    FILE *f = gen_open(root, path);
    fprintf(f, "# A smooth unit sphere, %d slices x %d bands, exact vertex normals.\n", u, v);
    fprintf(f, "# Written by tests/gen/gen_sphere_meshes.c for the shadow terminator measurement.\n");
    for (int k = 0; k < count; k++)
        put_point(f, "v", p[k]);
    for (int k = 0; k < count; k++)
        put_point(f, "vn", p[k]);
    int top = count - 1, bottom = count, last = v - 2;
    for (int i = 0; i < u; i++) {
        fprintf(f, "f %d//%d %d//%d %d//%d\n", top, top, at(u, 0, i), at(u, 0, i), at(u, 0, i + 1), at(u, 0, i + 1));
        for (int j = 0; j < v - 2; j++) {
            int c[4] = {at(u, j, i), at(u, j + 1, i), at(u, j + 1, i + 1), at(u, j, i + 1)};
            fprintf(f, "f %d//%d %d//%d %d//%d %d//%d\n", c[0], c[0], c[1], c[1], c[2], c[2], c[3], c[3]);
        }
        fprintf(f, "f %d//%d %d//%d %d//%d\n", bottom, bottom, at(u, last, i + 1), at(u, last, i + 1),
                at(u, last, i), at(u, last, i));
    }
    gen_close(f, path);
    free(p);
}

int main(int argc, char **argv)
{
    const char *root = gen_root(argc, argv, "gen_sphere_meshes [ROOT]");
    static const int sizes[3][2] = {{12, 8}, {24, 16}, {48, 32}};
    for (int k = 0; k < 3; k++)
        write_sphere(root, sizes[k][0], sizes[k][1]);
    return 0;
}
