/*
 * fit.h - straight lines through measurements, for convergence orders.
 *
 * An error that falls as e = C * N^p is a straight line in log-log
 * coordinates, ln e = ln C + p ln N, so the order p is the slope of the
 * ordinary least-squares line through the points (ln x_i, ln y_i)
 * (spec/verify.md, [VERIFY-FIT-1]).
 */
#ifndef REFRAY_FIT_H
#define REFRAY_FIT_H

typedef struct fit_line {
    int points;         /* points the line was fitted to */
    double slope;       /* p: the order */
    double intercept;   /* ln C (natural logarithm) */
    double slope_se;    /* standard error of the slope; NaN below 3 points */
    double r2;          /* coefficient of determination, 1 for a perfect line */
} fit_line;

/*
 * The least-squares line y = intercept + slope * x through the n points.
 * Returns 1, or 0 (with slope, intercept, slope_se and r2 NaN) when fewer
 * than two points are given or every x is the same.
 */
int fit_linear(const double *x, const double *y, int n, fit_line *out);

/*
 * The least-squares line through (ln x_i, ln y_i), over the points whose
 * x and y are both finite and > 0 (the others cannot lie on a power law
 * and are skipped; out->points says how many were used).  Returns as
 * fit_linear.
 */
int fit_loglog(const double *x, const double *y, int n, fit_line *out);

#endif
