/*
 * rect_mean.c - the exact value of refray's rect_light family at the floor
 * point (0, 0, 0) (normal +y), by an independent route: the mean over the
 * rectangle of (N.L) / d^2, by a 2-D Gauss-Legendre rule of 24 x 24 nodes in
 * long double (the integrand is smooth on the rectangle: far from it), over
 * the same at the rectangle's corner (the point light of plane_point).  So
 * the printed ratio is E(rect) / E(point at the corner), which the oracles'
 * images must show, pixel(rect) / pixel(point) with ambient 0.
 * cc -std=c99 -O2 -o /tmp/rect_mean tests/attack10/rect_mean.c -lm
 * /tmp/rect_mean EDGE   (corner [-1, 2, -0.75], edges [EDGE, 0, 0] and [0, 0, EDGE])
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static long double f(long double x, long double y, long double z)
{
    long double d2 = x * x + y * y + z * z;
    return (y / sqrtl(d2)) / d2; /* N.L with N = +y, L toward the light point */
}

int main(int argc, char **argv)
{
    long double e = argc > 1 ? strtold(argv[1], NULL) : 1e-4L;
    enum { N = 24 };
    long double xg[N], wg[N];
    for (int i = 0; i < N; i++) { /* Legendre nodes by Newton from Chebyshev guesses */
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
    long double cx = -1, cy = 2, cz = -0.75L, sum = 0;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            sum += wg[i] * wg[j] * f(cx + e * (xg[i] + 1) / 2, cy, cz + e * (xg[j] + 1) / 2);
    long double mean = sum / 4, corner = f(cx, cy, cz);
    printf("E(rect)/E(corner) = %.12Lg\n", mean / corner);
    return 0;
}
