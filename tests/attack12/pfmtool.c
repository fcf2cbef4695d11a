/*
 * pfmtool.c - rewrites a little-endian PF file (as refray writes it) the
 * ways another program might, for the conform attacks of tests/attack12:
 *
 *   pfmtool set  IN OUT X Y V      pixel (X, Y) (row 0 on top) to V in every channel
 *                                  (V may be nan, inf, -inf)
 *   pfmtool gray IN OUT            a one-channel "Pf" file of the red channel
 *   pfmtool be   IN OUT            the same floats big-endian (scale +1.0)
 *   pfmtool crlf IN OUT            the header lines ended by CR LF
 *   pfmtool scale IN OUT K         every value times K
 *   pfmtool tail IN OUT N          N zero bytes appended after the raster
 *   pfmtool mag  IN OUT S          the header's scale written as -S (little-endian,
 *                                  magnitude S: a scale factor in HDRShop's sense)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static float *load(const char *path, int *w, int *h)
{
    FILE *f = fopen(path, "rb");
    char magic[3] = "";
    double scale = 0;
    if (!f || fscanf(f, "%2s %d %d %lf", magic, w, h, &scale) != 4 || strcmp(magic, "PF") || scale >= 0) {
        fprintf(stderr, "pfmtool: %s is not a little-endian PF file\n", path);
        exit(2);
    }
    fgetc(f);
    size_t n = 3 * (size_t)*w * (size_t)*h;
    float *v = malloc(4 * n);
    if (!v || fread(v, 4, n, f) != n) {
        fprintf(stderr, "pfmtool: %s is short\n", path);
        exit(2);
    }
    fclose(f);
    return v; /* file order: rows bottom to top; a little-endian host */
}

static void put_be(FILE *f, float x)
{
    unsigned char b[4], r[4];
    memcpy(b, &x, 4);
    for (int i = 0; i < 4; i++)
        r[i] = b[3 - i];
    fwrite(r, 1, 4, f);
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: pfmtool set|gray|be|crlf|scale|tail|mag IN OUT [ARGS]\n");
        return 2;
    }
    int w, h;
    float *v = load(argv[2], &w, &h);
    size_t n = 3 * (size_t)w * (size_t)h;
    FILE *o = fopen(argv[3], "wb");
    if (!o)
        return 2;
    const char *op = argv[1];
    if (strcmp(op, "set") == 0 && argc == 7) {
        int x = atoi(argv[4]), y = atoi(argv[5]);
        float val = (float)strtod(argv[6], NULL);
        for (int c = 0; c < 3; c++)
            v[3 * ((size_t)(h - 1 - y) * (size_t)w + (size_t)x) + (size_t)c] = val;
        fprintf(o, "PF\n%d %d\n-1.0\n", w, h);
        fwrite(v, 4, n, o);
    } else if (strcmp(op, "gray") == 0) {
        fprintf(o, "Pf\n%d %d\n-1.0\n", w, h);
        for (size_t i = 0; i < n; i += 3)
            fwrite(&v[i], 4, 1, o);
    } else if (strcmp(op, "be") == 0) {
        fprintf(o, "PF\n%d %d\n1.0\n", w, h);
        for (size_t i = 0; i < n; i++)
            put_be(o, v[i]);
    } else if (strcmp(op, "crlf") == 0) {
        fprintf(o, "PF\r\n%d %d\r\n-1.0\r\n", w, h);
        fwrite(v, 4, n, o);
    } else if (strcmp(op, "scale") == 0 && argc == 5) {
        float k = (float)strtod(argv[4], NULL);
        for (size_t i = 0; i < n; i++)
            v[i] *= k;
        fprintf(o, "PF\n%d %d\n-1.0\n", w, h);
        fwrite(v, 4, n, o);
    } else if (strcmp(op, "tail") == 0 && argc == 5) {
        fprintf(o, "PF\n%d %d\n-1.0\n", w, h);
        fwrite(v, 4, n, o);
        for (long i = atol(argv[4]); i > 0; i--)
            fputc(0, o);
    } else if (strcmp(op, "mag") == 0 && argc == 5) {
        fprintf(o, "PF\n%d %d\n-%s\n", w, h, argv[4]);
        fwrite(v, 4, n, o);
    } else {
        fprintf(stderr, "pfmtool: bad operation\n");
        return 2;
    }
    return fclose(o) != 0;
}
