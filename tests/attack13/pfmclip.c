/*
 * pfmclip.c - rewrites a little-endian PF file (as refray writes it) into a
 * clearly wrong picture, for the conform attacks of tests/attack13:
 *
 *   pfmclip low   IN OUT T     every channel value below T set to 0 (the dark
 *                              part of the picture black: lost ambient, lost
 *                              fill light)
 *   pfmclip shift IN OUT N     the picture moved N pixels right (columns
 *                              shifted in from the left are copies of column 0)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    char magic[3] = "";
    int w, h;
    double scale;
    if (argc != 5) {
        fputs("usage: pfmclip low|shift IN OUT ARG\n", stderr);
        return 2;
    }
    FILE *f = fopen(argv[2], "rb");
    if (!f || fscanf(f, "%2s %d %d %lf", magic, &w, &h, &scale) != 4 || strcmp(magic, "PF") || scale >= 0) {
        fprintf(stderr, "pfmclip: %s is not a little-endian PF file\n", argv[2]);
        return 2;
    }
    fgetc(f);
    size_t n = 3 * (size_t)w * (size_t)h;
    float *v = malloc(4 * n), *o = malloc(4 * n);
    if (!v || !o || fread(v, 4, n, f) != n)
        return 2;
    fclose(f);
    double a = atof(argv[4]);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int c = 0; c < 3; c++) {
                size_t i = 3 * ((size_t)y * w + x) + c;
                if (strcmp(argv[1], "low") == 0)
                    o[i] = v[i] < a ? 0.0f : v[i];
                else {
                    int sx = x - (int)a;
                    o[i] = v[3 * ((size_t)y * w + (sx < 0 ? 0 : sx)) + c];
                }
            }
    FILE *g = fopen(argv[3], "wb");
    if (!g)
        return 2;
    fprintf(g, "PF\n%d %d\n-1.0\n", w, h);
    fwrite(o, 4, n, g);
    return fclose(g) != 0;
}
