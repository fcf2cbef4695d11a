/*
 * quadrature.h - adaptive Gauss-Kronrod quadrature in double, with an error
 * estimate, for the 1-D integrals the oracle's area-light families reduce to
 * (spec/analytic.md (section `area_lights`)).
 *
 * The rule is the 7-point Gauss / 15-point Kronrod pair (Kronrod 1965; the
 * node and weight values are those tabulated with QUADPACK, Piessens et al.
 * 1983).  The estimate of one interval is |K15 - G7|, which for a smooth
 * integrand overstates the error of K15 by orders of magnitude: the
 * estimate is conservative, never the heuristic rescaling QUADPACK applies.
 * The driver is global-adaptive: it bisects the interval with the largest
 * estimate until the sum of the estimates meets the request.  It keeps its
 * intervals in a fixed array on the stack: no allocation, no global state.
 */
#ifndef REFRAY_QUADRATURE_H
#define REFRAY_QUADRATURE_H

/* The integrand: a pure function of x and its context. */
typedef double (*quad_fn)(void *ctx, double x);

enum { QUAD_MAX_INTERVALS = 400, QUAD_MAX_BREAKS = 64 };

typedef struct quad_result {
    double value;
    double error;      /* sum over the final intervals of |K15 - G7| */
    double magnitude;  /* the K15 estimate of the integral of |f| */
    int intervals;     /* intervals of the final partition */
    int evaluations;   /* calls of f */
    int converged;     /* 1 when error met the request (or the rounding floor) */
} quad_result;

/* One 15-point Kronrod rule on [a, b]: returns K15; *err = |K15 - G7|,
 * *abs_value = the K15 estimate of the integral of |f|. */
double quad_gk15(quad_fn f, void *ctx, double a, double b, double *err, double *abs_value);

/*
 * The integral of f over [breaks[0], breaks[n-1]] (n >= 2, breaks
 * non-decreasing, at most QUAD_MAX_BREAKS): the breakpoints start the
 * partition, so a kink of f placed at a breakpoint costs nothing.  Stops when
 * error <= max(abs_tol, rel_tol * |value|, 50 eps * magnitude) (the last is
 * the rounding floor of the sum), or when QUAD_MAX_INTERVALS are in use or an
 * interval can no longer be halved (converged = 0: the value is still the
 * best estimate).  Returns out->value.
 */
double quad_breaks(quad_fn f, void *ctx, const double *breaks, int n, double abs_tol, double rel_tol,
                   quad_result *out);

/* The same over [a, b] with no inner breakpoints. */
double quad_interval(quad_fn f, void *ctx, double a, double b, double abs_tol, double rel_tol,
                     quad_result *out);

#endif
