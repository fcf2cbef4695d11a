/*
 * fit.c - see fit.h.
 *
 * Ordinary least squares on centred sums, which keeps an exact line exact
 * to round-off (the textbook form n*Sxy - Sx*Sy cancels badly):
 *   slope     b = Sxy / Sxx,  Sxx = sum (x - xbar)^2,  Sxy = sum (x - xbar)(y - ybar)
 *   intercept a = ybar - b * xbar
 *   residuals r_i = y_i - a - b x_i,  SSE = sum r_i^2  (summed directly, not
 *             as Syy - b Sxy, so a perfect fit gives SSE ~ 0, not noise)
 *   se(b)     = sqrt(SSE / (n - 2) / Sxx)      (n - 2 degrees of freedom)
 *   r2        = 1 - SSE / Syy  (1 when Syy = 0)
 * (any regression text, e.g. Draper & Smith, Applied Regression Analysis,
 * ch. 1).
 */
#include <math.h>
#include <stdlib.h>
#include "verify/fit.h"

static void fit_fail(fit_line *out, int points)
{
    out->points = points;
    out->slope = out->intercept = out->slope_se = out->r2 = NAN;
}

static void means(const double *x, const double *y, int n, double *xbar, double *ybar)
{
    double sx = 0, sy = 0;
    for (int i = 0; i < n; i++) {
        sx += x[i];
        sy += y[i];
    }
    *xbar = sx / n;
    *ybar = sy / n;
}

int fit_linear(const double *x, const double *y, int n, fit_line *out)
{
    if (n < 2) {
        fit_fail(out, n < 0 ? 0 : n);
        return 0;
    }
    double xbar, ybar, sxx = 0, sxy = 0, syy = 0, sse = 0;
    means(x, y, n, &xbar, &ybar);
    for (int i = 0; i < n; i++) {
        sxx += (x[i] - xbar) * (x[i] - xbar);
        sxy += (x[i] - xbar) * (y[i] - ybar);
        syy += (y[i] - ybar) * (y[i] - ybar);
    }
    if (!(sxx > 0)) {
        fit_fail(out, n);
        return 0;
    }
    out->points = n;
    out->slope = sxy / sxx;
    out->intercept = ybar - out->slope * xbar;
    for (int i = 0; i < n; i++) {
        double r = y[i] - out->intercept - out->slope * x[i];
        sse += r * r;
    }
    out->slope_se = n > 2 ? sqrt(sse / (n - 2) / sxx) : NAN;
    out->r2 = syy > 0 ? 1 - sse / syy : 1;
    return 1;
}

int fit_loglog(const double *x, const double *y, int n, fit_line *out)
{
    double *lx = malloc(2 * (size_t)(n > 0 ? n : 1) * sizeof *lx);
    if (!lx) {
        fit_fail(out, 0);
        return 0;
    }
    double *ly = lx + (n > 0 ? n : 1);
    int m = 0;
    for (int i = 0; i < n; i++) {
        if (isfinite(x[i]) && isfinite(y[i]) && x[i] > 0 && y[i] > 0) {
            lx[m] = log(x[i]);
            ly[m++] = log(y[i]);
        }
    }
    int ok = fit_linear(lx, ly, m, out);
    free(lx);
    return ok;
}
