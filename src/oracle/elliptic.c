/*
 * elliptic.c - see elliptic.h.
 *
 * R_F: with A0 = (x+y+z)/3, each step sets lambda = sqrt(xy) + sqrt(xz) +
 * sqrt(yz) and replaces x, y, z, A by (. + lambda)/4; after m steps with
 * 4^-m Q < |A| (Q = max |A0 - x|... scaled by (3 eps)^(-1/6)) the deviations
 * X = (A0 - x0)/(4^m A), Y likewise, Z = -X - Y are below eps^(1/6), and
 *   R_F = A^(-1/2) (1 - E2/10 + E3/14 + E2^2/24 - 3 E2 E3/44),
 *   E2 = XY - Z^2, E3 = XYZ   (DLMF 19.36.1).
 * R_D: the same with A0 = (x+y+3z)/5, plus the sum of
 * 4^-j / (sqrt(z_j)(z_j + lambda_j)), and the series of DLMF 19.36.2.
 */
#include <float.h>
#include <math.h>
#include "oracle/elliptic.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static double max3(double a, double b, double c)
{
    return fmax(a, fmax(b, c));
}

double elliptic_rf(double x, double y, double z)
{
    double a0 = (x + y + z) / 3, a = a0;
    double q = pow(3 * DBL_EPSILON, -1.0 / 6) * max3(fabs(a0 - x), fabs(a0 - y), fabs(a0 - z));
    double x0 = x, y0 = y, scale = 1;
    while (scale * q >= fabs(a)) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z), lambda = sx * sy + sx * sz + sy * sz;
        x = (x + lambda) / 4;
        y = (y + lambda) / 4;
        z = (z + lambda) / 4;
        a = (a + lambda) / 4;
        scale /= 4;
    }
    double xd = (a0 - x0) * scale / a, yd = (a0 - y0) * scale / a, zd = -xd - yd;
    double e2 = xd * yd - zd * zd, e3 = xd * yd * zd;
    return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / sqrt(a);
}

double elliptic_rd(double x, double y, double z)
{
    double a0 = (x + y + 3 * z) / 5, a = a0;
    double q = pow(DBL_EPSILON / 4, -1.0 / 6) * max3(fabs(a0 - x), fabs(a0 - y), fabs(a0 - z));
    double x0 = x, y0 = y, scale = 1, sum = 0;
    while (scale * q >= fabs(a)) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z), lambda = sx * sy + sx * sz + sy * sz;
        sum += scale / (sz * (z + lambda));
        x = (x + lambda) / 4;
        y = (y + lambda) / 4;
        z = (z + lambda) / 4;
        a = (a + lambda) / 4;
        scale /= 4;
    }
    double xd = (a0 - x0) * scale / a, yd = (a0 - y0) * scale / a, zd = -(xd + yd) / 3;
    double xy = xd * yd, z2 = zd * zd;
    double e2 = xy - 6 * z2, e3 = (3 * xy - 8 * z2) * zd, e4 = 3 * (xy - z2) * z2, e5 = xy * z2 * zd;
    double series = 1 - 3 * e2 / 14 + e3 / 6 + 9 * e2 * e2 / 88 - 3 * e4 / 22 - 9 * e2 * e3 / 52 + 3 * e5 / 26;
    return scale * series / (a * sqrt(a)) + 3 * sum;
}

/* K(k) = R_F(0, 1-k^2, 1); E(k) = R_F(0, 1-k^2, 1) - k^2/3 R_D(0, 1-k^2, 1)
 * (DLMF 19.25.1). */
double elliptic_k(double k)
{
    return elliptic_rf(0, 1 - k * k, 1);
}

double elliptic_e(double k)
{
    double m = k * k;
    return elliptic_rf(0, 1 - m, 1) - m / 3 * elliptic_rd(0, 1 - m, 1);
}

/* F(phi, k) = s R_F(c^2, 1 - k^2 s^2, 1), E(phi, k) = F - k^2 s^3/3 R_D(c^2,
 * 1 - k^2 s^2, 1), s = sin phi, c = cos phi (DLMF 19.25.5, 19.25.9).  At
 * phi = 0 both are 0 (R_F would see two zero arguments only if also k = 1
 * and phi = pi/2, which is F's logarithmic pole and not used here). */
double elliptic_f_inc(double phi, double k)
{
    double s = sin(phi), c = cos(phi);
    if (s == 0)
        return 0;
    return s * elliptic_rf(c * c, 1 - k * k * s * s, 1);
}

double elliptic_e_inc(double phi, double k)
{
    double s = sin(phi), c = cos(phi), m = k * k;
    if (s == 0)
        return 0;
    double y = 1 - m * s * s;
    return s * elliptic_rf(c * c, y, 1) - m * s * s * s / 3 * elliptic_rd(c * c, y, 1);
}

double elliptic_heuman_lambda(double xi, double k)
{
    double kp = sqrt(fmax(0, 1 - k * k));
    double kk = elliptic_k(k), ee = elliptic_e(k);
    double f = elliptic_f_inc(xi, kp), e = elliptic_e_inc(xi, kp);
    return 2 / M_PI * (ee * f + kk * e - kk * f);
}
