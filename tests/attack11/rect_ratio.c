/*
 * rect_ratio.c - E(rect) / E(point light at its corner) at the floor point
 * (0, 0, 0) (normal +y), inverse square, d0 0: the mean over the rectangle
 * of (N.L)/d^2 by composite 5-point Gauss-Legendre (P x P panels, nodes in
 * closed form, long double), over its value at the corner.  An independent
 * route to what the rect_light oracle's image over plane_point's must show.
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
    int panels = argc > 6 ? atoi(argv[6]) : 256;
    /* The 5-point rule on [-1, 1]: 0 and +-sqrt(5 -+ 2 sqrt(10/7)) / 3. */
    long double r = 2 * sqrtl(10.0L / 7);
    long double node[5] = {0, sqrtl(5 - r) / 3, -sqrtl(5 - r) / 3, sqrtl(5 + r) / 3, -sqrtl(5 + r) / 3};
    long double q = 13 * sqrtl(70.0L);
    long double weight[5] = {128.0L / 225, (322 + q) / 900, (322 + q) / 900, (322 - q) / 900, (322 - q) / 900};
    long double sum = 0, h = 1.0L / panels;
    for (int a = 0; a < panels; a++)
        for (int b = 0; b < panels; b++)
            for (int i = 0; i < 5; i++)
                for (int j = 0; j < 5; j++) {
                    long double s = (a + (node[i] + 1) / 2) * h, t = (b + (node[j] + 1) / 2) * h;
                    sum += weight[i] * weight[j] * f(cx + ex * s, cy, cz + ez * t);
                }
    long double mean = sum * h * h / 4;
    printf("%.12Lg\n", mean / f(cx, cy, cz));
    return 0;
}
