/* pfmdump.c - prints a PFM's red channel as a grid (top row first), or
 * with a second argument x,y the pixel's three channels to 9 digits.
 * cc -std=c99 -O2 -o /tmp/pfmdump tests/attack10/pfmdump.c */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
int main(int argc, char **argv)
{
    FILE *f = argc > 1 ? fopen(argv[1], "rb") : NULL;
    char type[3];
    int w, h;
    double scale;
    if (!f || fscanf(f, "%2s %d %d %lf", type, &w, &h, &scale) != 4 || strcmp(type, "PF") != 0)
        return 2;
    fgetc(f);
    float *p = malloc(sizeof *p * 3 * (size_t)w * h);
    if (!p || fread(p, sizeof *p, 3 * (size_t)w * h, f) != 3 * (size_t)w * h)
        return 2;
    if (argc > 2) { /* PFM rows go bottom to top */
        int x, y;
        if (sscanf(argv[2], "%d,%d", &x, &y) != 2 || x < 0 || y < 0 || x >= w || y >= h)
            return 2;
        float *q = p + 3 * ((size_t)(h - 1 - y) * w + x);
        printf("%.9g %.9g %.9g\n", q[0], q[1], q[2]);
        return 0;
    }
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++)
            printf("%6.3g ", p[3 * ((size_t)(h - 1 - y) * w + x)]);
        printf("\n");
    }
    return 0;
}
