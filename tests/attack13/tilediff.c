/*
 * tilediff.c - the largest difference between the exact doubles of two
 * tile sidecars (NAME.pfm.tile, spec/scaling.md: five text lines, then
 * little-endian doubles), for comparing renders below the PFM's float.
 *   tilediff A.pfm.tile B.pfm.tile
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

static FILE *skip_header(const char *path)
{
    FILE *f = fopen(path, "rb");
    int lines = 0, c;
    while (f && lines < 5 && (c = fgetc(f)) != EOF)
        lines += c == '\n';
    return f;
}

int main(int argc, char **argv)
{
    if (argc != 3)
        return 2;
    FILE *a = skip_header(argv[1]), *b = skip_header(argv[2]);
    double x, y, worst = 0;
    long n = 0, at = -1;
    if (!a || !b)
        return 2;
    while (fread(&x, 8, 1, a) == 1 && fread(&y, 8, 1, b) == 1) {
        if (fabs(x - y) > worst) {
            worst = fabs(x - y);
            at = n;
        }
        n++;
    }
    printf("%ld values, max abs %.3e at value %ld (pixel %ld)\n", n, worst, at, at / 3);
    return 0;
}
