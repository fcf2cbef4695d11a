/*
 * quadrature.c - see quadrature.h.
 *
 * On [a, b] with centre c and half-length r, K15 = r * sum wgk[i] f(c +- r xgk[i])
 * and G7 = r * sum wg[j] f(c +- r xgk[2j+1]): the Gauss nodes are every other
 * Kronrod node, so the pair costs 15 evaluations.  K15 is exact for
 * polynomials of degree 22, G7 for degree 13 (checked by the unit tests).
 */
#include <float.h>
#include <math.h>
#include <string.h>
#include "oracle/quadrature.h"

static const double xgk[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0,
};
static const double wgk[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714,
};
/* Weights of the Gauss nodes xgk[1], xgk[3], xgk[5], xgk[7]. */
static const double wg[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327,
};

double quad_gk15(quad_fn f, void *ctx, double a, double b, double *err, double *abs_value)
{
    double c = 0.5 * (a + b), r = 0.5 * (b - a);
    double fc = f(ctx, c);
    double k = wgk[7] * fc, g = wg[3] * fc, k_abs = wgk[7] * fabs(fc);
    for (int i = 0; i < 7; i++) {
        double f1 = f(ctx, c - r * xgk[i]), f2 = f(ctx, c + r * xgk[i]);
        k += wgk[i] * (f1 + f2);
        k_abs += wgk[i] * (fabs(f1) + fabs(f2));
        if (i % 2 == 1)
            g += wg[i / 2] * (f1 + f2);
    }
    *err = fabs(r * (k - g));
    *abs_value = fabs(r) * k_abs;
    return r * k;
}

typedef struct piece {
    double a, b, value, err, abs_value;
} piece;

static piece make_piece(quad_fn f, void *ctx, double a, double b)
{
    piece p;
    p.a = a;
    p.b = b;
    p.value = quad_gk15(f, ctx, a, b, &p.err, &p.abs_value);
    return p;
}

/* Sums over the partition, each time afresh so rounding cannot drift. */
static void total(const piece *p, int n, quad_result *out)
{
    out->value = out->error = out->magnitude = 0;
    for (int i = 0; i < n; i++) {
        out->value += p[i].value;
        out->error += p[i].err;
        out->magnitude += p[i].abs_value;
    }
    out->intervals = n;
}

static int worst(const piece *p, int n)
{
    int w = 0;
    for (int i = 1; i < n; i++)
        if (p[i].err > p[w].err)
            w = i;
    return w;
}

static int good_enough(const quad_result *r, double abs_tol, double rel_tol)
{
    double want = fmax(abs_tol, fmax(rel_tol * fabs(r->value), 50 * DBL_EPSILON * r->magnitude));
    return r->error <= want;
}

double quad_breaks(quad_fn f, void *ctx, const double *breaks, int n, double abs_tol, double rel_tol,
                   quad_result *out)
{
    piece p[QUAD_MAX_INTERVALS];
    int count = 0;
    memset(&p[0], 0, sizeof p[0]); /* an empty range reads no piece; say so to the compiler */
    if (n > QUAD_MAX_BREAKS)
        n = QUAD_MAX_BREAKS;
    for (int i = 0; i + 1 < n; i++)
        if (breaks[i + 1] > breaks[i])
            p[count++] = make_piece(f, ctx, breaks[i], breaks[i + 1]);
    out->converged = 1;
    total(p, count, out);
    out->evaluations = 15 * count;
    while (count > 0 && !good_enough(out, abs_tol, rel_tol)) {
        int w = worst(p, count);
        double a = p[w].a, b = p[w].b, m = 0.5 * (a + b);
        if (count == QUAD_MAX_INTERVALS || !(m > a && m < b)) {
            out->converged = 0;
            break;
        }
        p[w] = make_piece(f, ctx, a, m);
        p[count++] = make_piece(f, ctx, m, b);
        out->evaluations += 30;
        total(p, count, out);
    }
    return out->value;
}

double quad_interval(quad_fn f, void *ctx, double a, double b, double abs_tol, double rel_tol, quad_result *out)
{
    double breaks[2];
    breaks[0] = a;
    breaks[1] = b;
    return quad_breaks(f, ctx, breaks, 2, abs_tol, rel_tol, out);
}
