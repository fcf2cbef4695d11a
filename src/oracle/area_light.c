/*
 * area_light.c - see area_light.h and spec/analytic.md (section `area_lights`).
 *
 * Antiderivatives of the falloffs g (section "Radial integral"):
 *   none            g = 1             G = s
 *   linear          g = 1/(s+d0)      G = ln(s + d0)
 *   inverse_square  g = 1/(s+d0)^2    G = -1/(s + d0)
 * With D = sqrt(h^2+u), S = D + h and D - h = u/S:
 *   none            Q = h / S
 *   linear          Q = h log1p(x) / (u) ,  x = u / (S (h+d0))
 *   inverse_square  Q = h / (S (h+d0) (D+d0))
 * Green's theorem (div of (x, y) Q(x^2+y^2) is 2 d/du (u Q) = phi) gives
 *   integral over R of phi dA = contour integral over dR of Q (x dy - y dx).
 * Along a segment A -> B, x dy - y dx = (A x B) dt for t in [0, 1]; along a
 * circle c + r(cos t, sin t) it is (r^2 + r c.(cos t, sin t)) dt.
 */
#include <math.h>
#include "oracle/area_light.h"
#include "oracle/elliptic.h"
#include "oracle/quadrature.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Requested accuracy of every 1-D integral (the rounding floor of the
 * quadrature applies when the contour's parts cancel). */
#define AREA_REL_TOL 1e-13

/* More than the series of area_disk_mean_far needs at q = 1/16 (17). */
#define AREA_FAR_TERMS 40

double area_phi(const area_kernel *k, double d)
{
    double s = d + k->d0;
    if (k->falloff == FALLOFF_NONE)
        return k->h / d;
    if (k->falloff == FALLOFF_LINEAR)
        return k->h / (d * s);
    return k->h / (d * s * s);
}

/* phi' for phi = h/d, h/(d (d+d0)), h/(d (d+d0)^2):
 *   -h/d^2,  -h (2d+d0)/(d^2 (d+d0)^2),  -h (3d+d0)/(d^2 (d+d0)^3). */
double area_phi_slope(const area_kernel *k, double d)
{
    double s = d + k->d0;
    if (k->falloff == FALLOFF_NONE)
        return k->h / (d * d);
    if (k->falloff == FALLOFF_LINEAR)
        return k->h * (2 * d + k->d0) / (d * d * s * s);
    return k->h * (3 * d + k->d0) / (d * d * s * s * s);
}

double area_contour_weight(const area_kernel *k, double u)
{
    double h = k->h, dd = sqrt(h * h + u), sum = dd + h;
    if (k->falloff == FALLOFF_NONE)
        return h / sum;
    if (k->falloff == FALLOFF_LINEAR) {
        double x = u / (sum * (h + k->d0));
        return h / (sum * (h + k->d0)) * (x > 0 ? log1p(x) / x : 1.0);
    }
    return h / (sum * (h + k->d0) * (dd + k->d0));
}

typedef struct edge_ctx {
    const area_kernel *k;
    double ax, ay, ex, ey;   /* start A and direction B - A */
} edge_ctx;

static double edge_integrand(void *ctx, double t)
{
    const edge_ctx *e = ctx;
    double x = e->ax + t * e->ex, y = e->ay + t * e->ey;
    return area_contour_weight(e->k, x * x + y * y);
}

/* (A x B) times the integral of Q over the segment A -> B. */
static double edge_integral(const area_kernel *k, const double *a, const double *b)
{
    double cross = a[0] * b[1] - a[1] * b[0];
    if (cross == 0)
        return 0;
    edge_ctx e = {k, a[0], a[1], b[0] - a[0], b[1] - a[1]};
    quad_result r;
    return cross * quad_interval(edge_integrand, &e, 0, 1, 0, AREA_REL_TOL, &r);
}

double area_polygon(const area_kernel *k, const double (*v)[2], int n)
{
    double sum = 0, twice_area = 0;
    for (int i = 0; i < n; i++) {
        const double *a = v[i], *b = v[(i + 1) % n];
        sum += edge_integral(k, a, b);
        twice_area += a[0] * b[1] - a[1] * b[0];
    }
    return twice_area < 0 ? -sum : sum;
}

typedef struct arc_ctx {
    const area_kernel *k;
    double cx, cy, r;
} arc_ctx;

static double arc_integrand(void *ctx, double t)
{
    const arc_ctx *a = ctx;
    double c = cos(t), s = sin(t);
    double x = a->cx + a->r * c, y = a->cy + a->r * s;
    return area_contour_weight(a->k, x * x + y * y) * a->r * (a->r + a->cx * c + a->cy * s);
}

double area_arc(const area_kernel *k, double cx, double cy, double r, double t0, double t1)
{
    arc_ctx a = {k, cx, cy, r};
    quad_result res;
    return quad_interval(arc_integrand, &a, t0, t1, 0, AREA_REL_TOL, &res);
}

typedef struct disk_ctx {
    const area_kernel *k;
    double c, r;     /* distance of the centre from the foot point; radius */
} disk_ctx;

/* The circle turned so its centre lies on the +x axis; u and the weight
 * r (r + c cos t) are written so that neither cancels at the rim (c ~ r,
 * t ~ pi): 1 + cos t = 2 cos^2(t/2). */
static double disk_integrand(void *ctx, double t)
{
    const disk_ctx *d = ctx;
    double half = cos(t / 2), one_plus = 2 * half * half;
    double u = (d->c - d->r) * (d->c - d->r) + 2 * d->r * d->c * one_plus;
    return area_contour_weight(d->k, u) * d->r * (d->r - d->c + d->c * one_plus);
}

double area_disk(const area_kernel *k, double cx, double cy, double r)
{
    disk_ctx d = {k, hypot(cx, cy), r};
    quad_result res;
    return 2 * quad_interval(disk_integrand, &d, 0, M_PI, 0, AREA_REL_TOL, &res);
}

static double clamp_unit(double x)
{
    return x < -1 ? -1 : (x > 1 ? 1 : x);
}

double area_disk_minus_disk(const area_kernel *k, double lx, double ly, double lr, double sx, double sy, double sr)
{
    double dx = sx - lx, dy = sy - ly, d = hypot(dx, dy);
    if (!(sr > 0) || d >= lr + sr)
        return area_disk(k, lx, ly, lr);
    if (d + lr <= sr)
        return 0;
    if (d + sr <= lr)
        return area_disk(k, lx, ly, lr) - area_disk(k, sx, sy, sr);
    /* The circles cross at two points, seen from L's centre at alpha +- bl
     * and from S's centre at alpha + pi +- bs (law of cosines).  The
     * boundary of L \ S: L's arc outside S counter-clockwise, then S's arc
     * inside L clockwise. */
    double alpha = atan2(dy, dx);
    double bl = acos(clamp_unit((d * d + lr * lr - sr * sr) / (2 * d * lr)));
    double bs = acos(clamp_unit((d * d + sr * sr - lr * lr) / (2 * d * sr)));
    return area_arc(k, lx, ly, lr, alpha + bl, alpha + 2 * M_PI - bl) -
           area_arc(k, sx, sy, sr, alpha + M_PI - bs, alpha + M_PI + bs);
}

double area_disk_on_axis(const area_kernel *k, double a)
{
    /* 2 pi h (G(D) - G(h)) = 2 pi u Q(u) with u = a^2. */
    return 2 * M_PI * a * a * area_contour_weight(k, a * a);
}

/* The solid angle of [0,a] x [0,b] seen from height h over the origin,
 * signed like a*b (so corner rectangles superpose). */
static double corner(double h, double a, double b)
{
    return atan(a * b / (h * sqrt(h * h + a * a + b * b)));
}

double area_rect_solid_angle(double h, double x0, double x1, double y0, double y1)
{
    return corner(h, x1, y1) - corner(h, x0, y1) - corner(h, x1, y0) + corner(h, x0, y0);
}

/* The exterior series (spec/analytic.md, "A small disk"): with R the
 * distance to the centre, x = h/R, q = (a/R)^2 and c_k = C(2k,k)/4^k,
 *   Omega / (pi a^2) = (2/R^2) sum_{k>=1} (-1)^(k+1) c_k q^(k-1) P_{2k-1}(x).
 * For q <= 1/16 the terms after the first add at most 0.45 of it (|P_n(x)|
 * <= |x| n(n+1)/2 for odd n), so the sum keeps its digits at every x; the
 * loop stops when the bound on what is left, c_k q^k k(2k+1) |x| / (1 - q),
 * is below 2^-60 of the first term.  Legendre's recurrence is forward
 * stable on [-1, 1]. */
double area_disk_mean_far(double h, double r0, double a)
{
    double big = hypot(h, r0), x = h / big, ratio = a / big, q = ratio * ratio;
    double p_prev = 1, p = x, c = 0.5, qk = 1, sum = 0, sign = 1;
    int n = 1;
    for (int k = 1; k <= AREA_FAR_TERMS; k++) {
        sum += sign * c * qk * p;
        c *= (2.0 * k + 1) / (2.0 * k + 2);
        qk *= q;
        if (c * qk * (k + 1) * (2.0 * k + 1) / (1 - q) <= 0x1p-60 * 0.5)
            break;
        for (int step = 0; step < 2; step++, n++) {
            double next = ((2 * n + 1) * x * p - n * p_prev) / (n + 1);
            p_prev = p;
            p = next;
        }
        sign = -sign;
    }
    return 2 / big * (sum / big);
}

typedef struct far_ctx {
    const area_kernel *k;
    double c, a, s;   /* the centre's distance from the foot; radius; current s */
} far_ctx;

/* phi at the point a s (cos t, sin t) of the disk turned to centre (c, 0). */
static double far_inner(void *ctx, double t)
{
    const far_ctx *f = ctx;
    double x = f->c + f->a * f->s * cos(t), y = f->a * f->s * sin(t);
    return area_phi(f->k, hypot(f->k->h, hypot(x, y)));
}

static double far_outer(void *ctx, double s)
{
    far_ctx *f = ctx;
    quad_result res;
    f->s = s;
    return s * quad_interval(far_inner, f, 0, M_PI, 0, AREA_REL_TOL, &res);
}

/* In polar coordinates about the centre, rho = a s: the mean is
 * (2/pi) int_0^1 s int_0^pi phi dt ds, a positive integrand smooth on the
 * disk (d >= h > 0), a^2 never formed. */
double area_disk_mean_far_quadrature(const area_kernel *k, double r0, double a)
{
    far_ctx f = {k, r0, a, 0};
    quad_result res;
    return 2 / M_PI * quad_interval(far_outer, &f, 0, 1, 0, AREA_REL_TOL, &res);
}

/* Paxton (1959): with R1, Rmax the nearest and farthest rim distances from
 * the point, k^2 = 1 - R1^2/Rmax^2 = 4 r0 a / Rmax^2, xi = atan(h/|r0-a|),
 *   r0 < a:  2 pi - 2h K(k)/Rmax - pi Lambda0(xi, k)
 *   r0 = a:  pi - 2h K(k)/Rmax
 *   r0 > a:  -2h K(k)/Rmax + pi Lambda0(xi, k)
 * (Lambda0(pi/2, k) = 1, so the three agree at the rim). */
double area_disk_solid_angle(double h, double r0, double a)
{
    double rmax2 = h * h + (r0 + a) * (r0 + a), rmax = sqrt(rmax2);
    double k = sqrt(4 * r0 * a / rmax2);
    double first = 2 * h * elliptic_k(k) / rmax;
    double lambda = elliptic_heuman_lambda(atan2(h, fabs(r0 - a)), k);
    if (r0 < a)
        return 2 * M_PI - first - M_PI * lambda;
    return M_PI * lambda - first;
}

typedef struct para_ctx {
    const area_kernel *k;
    double ox, oy, ux, uy, vx, vy;   /* corner O, edges U and V, about the foot */
    double s;                        /* current s */
} para_ctx;

/* phi at O + s U + t V. */
static double para_inner(void *ctx, double t)
{
    const para_ctx *p = ctx;
    double x = p->ox + p->s * p->ux + t * p->vx, y = p->oy + p->s * p->uy + t * p->vy;
    return area_phi(p->k, hypot(p->k->h, hypot(x, y)));
}

static double para_outer(void *ctx, double s)
{
    para_ctx *p = ctx;
    quad_result res;
    p->s = s;
    return quad_interval(para_inner, p, 0, 1, 0, AREA_REL_TOL, &res);
}

/* The map (s, t) -> O + s U + t V has a constant Jacobian, so the mean over
 * the parallelogram is the mean over the unit square: a positive integrand,
 * smooth (d >= h > 0), nothing subtracted and no area divided by. */
double area_parallelogram_mean(const area_kernel *k, const double *o, const double *u, const double *v)
{
    para_ctx p = {k, o[0], o[1], u[0], u[1], v[0], v[1], 0};
    quad_result res;
    return quad_interval(para_outer, &p, 0, 1, 0, AREA_REL_TOL, &res);
}
