/*
 * rect_ratio.c - E(rect) / E(point light at its corner) at the floor point
 * (0, 0, 0) (normal +y), inverse square, d0 0: the mean over the rectangle
 * of (N.L)/d^2 by composite Gauss-Legendre (P x P panels of 24 x 24 nodes,
 * long double), over its value at the corner.  An independent route to
 * what the rect_light oracle's image over plane_point's must show.
 * cc -std=c99 -O2 -o /tmp/rect_ratio tests/attack11/rect_ratio.c -lm
 * /tmp/rect_ratio CX CY CZ EX EZ [PANELS]   (edges [EX, 0, 0] and [0, 0, EZ])
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static long double f(long double x, long double y, long double z)
{
    long double d2 = x * x + y * y + z * z;
    return (y / sqrtl(d2)) / d2;
}

int main(int argc, char **argv)
{
    if (argc < 6)
        return 2;
    long double cx = strtold(argv[1], NULL), cy = strtold(argv[2], NULL), cz = strtold(argv[3], NULL);
    long double ex = strtold(argv[4], NULL), ez = strtold(argv[5], NULL);
    int panels = argc > 6 ? atoi(argv[6]) : 64;
    enum { N = 24 };
    long double xg[N], wg[N];
    for (int i = 0; i < N; i++) {
        long double x = cosl(3.14159265358979323846264338327950288L * (i + 0.75L) / (N + 0.5L)), dp = 0;
        for (int it = 0; it < 100; it++) {
            long double p0 = 1, p1 = x;
            for (int k = 2; k <= N; k++) {
                long double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = N * (x * p1 - p0) / (x * x - 1);
            long double dx = p1 / dp;
            x -= dx;
            if (fabsl(dx) < 1e-30L)
                break;
        }
        xg[i] = x;
        wg[i] = 2 / ((1 - x * x) * dp * dp);
    }
    long double sum = 0, h = 1.0L / panels;
    for (int a = 0; a < panels; a++)
        for (int b = 0; b < panels; b++)
            for (int i = 0; i < N; i++)
                for (int j = 0; j < N; j++) {
                    long double s = (a + (xg[i] + 1) / 2) * h, t = (b + (xg[j] + 1) / 2) * h;
                    sum += wg[i] * wg[j] * f(cx + ex * s, cy, cz + ez * t);
                }
    long double mean = sum * h * h / 4;
    printf("%.12Lg\n", mean / f(cx, cy, cz));
    return 0;
}
