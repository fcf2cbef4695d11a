/*
 * area_light.h - the exact light a distributed (area) light sends to a point
 * of a Lambert receiver parallel to it (spec/analytic.md (section `area_lights`)).
 *
 * The tracer's distributed light is `samples` isotropic point sources of
 * power E/samples spread uniformly over the light, each with the light's
 * falloff g and the receiver's cosine N.L = h/d (no emitter cosine).  As the
 * samples grow the light at the receiver converges to
 *     (E/A) * integral over the visible part of the light of  phi(d) dA,
 *     phi(d) = g(d) h / d,
 * with h the distance between the receiver and the light's plane and d the
 * distance to the light's point.  Everything below works in the light's
 * plane, in coordinates centred on the foot F of the perpendicular from the
 * receiver: there phi depends on rho^2 = x^2 + y^2 only.
 *
 * The route: with u = rho^2 and D = sqrt(h^2 + u), the radial integral is
 * closed: int_0^R phi rho drho = h (G(D) - G(h)), G an antiderivative of g.
 * Green's theorem turns the area integral into a contour integral of
 *     Q(u) (x dy - y dx),   Q(u) = h (G(D) - G(h)) / u,
 * valid wherever F lies (inside, outside, on the rim) because Q is analytic
 * at u = 0: the 1-D integrand is smooth and Gauss-Kronrod converges fast.
 */
#ifndef REFRAY_AREA_LIGHT_H
#define REFRAY_AREA_LIGHT_H

#include "scene/scene.h"

typedef struct area_kernel {
    double h;              /* distance from the receiver to the light's plane, > 0 */
    double d0;             /* the falloff's offset, >= 0 */
    scene_falloff falloff;
} area_kernel;

/* phi(d) = g(d) h / d, the density the light is integrated with. */
double area_phi(const area_kernel *k, double d);

/* |phi'(d)|, for the tolerance's gradient bound. */
double area_phi_slope(const area_kernel *k, double d);

/* Q(u) = h (G(sqrt(h^2+u)) - G(h)) / u, with its limit at u = 0, computed
 * without cancellation (log1p, D - h = u / (D + h)). */
double area_contour_weight(const area_kernel *k, double u);

/* The integral of phi over the polygon v[0..n-1] (coordinates relative to
 * the foot point, either orientation, simple polygon). */
double area_polygon(const area_kernel *k, const double (*v)[2], int n);

/* The contour integral of Q (x dy - y dx) along the arc of the circle of
 * centre (cx, cy) and radius r from angle t0 to t1 (counter-clockwise when
 * t1 > t0). */
double area_arc(const area_kernel *k, double cx, double cy, double r, double t0, double t1);

/* The integral of phi over the disk of centre (cx, cy), radius r. */
double area_disk(const area_kernel *k, double cx, double cy, double r);

/* The integral of phi over the disk L (centre lx, ly, radius lr) minus the
 * disk S (centre sx, sy, radius sr): a light partly hidden by a shadow. */
double area_disk_minus_disk(const area_kernel *k, double lx, double ly, double lr, double sx, double sy,
                            double sr);

/* The integral of phi over a disk of radius a centred on the foot point, in
 * closed form for every falloff: 2 pi h (G(sqrt(h^2+a^2)) - G(h)). */
double area_disk_on_axis(const area_kernel *k, double a);

/* The solid angle of the rectangle [x0,x1] x [y0,y1] of a plane at distance
 * h, seen from the point over the origin: the corner form
 * w(a,b) = atan(ab / (h sqrt(h^2+a^2+b^2))) superposed with signs.  Equals the
 * integral of phi for inverse_square with d0 = 0. */
double area_rect_solid_angle(double h, double x0, double x1, double y0, double y1);

/* A disk is far when its radius is at most this part of the distance from
 * the point to its centre: area_disk_mean_far's series then keeps its digits. */
#define AREA_DISK_FAR 0.25

/* The solid angle of a disk of radius a at distance h whose centre is r0 off
 * the perpendicular, over the disk's area pi a^2 (the mean of h/d^3 over
 * it), by its exterior series in Legendre polynomials, without the
 * cancellation of Paxton's form (1e-16 / a^2 absolute); for a <=
 * AREA_DISK_FAR hypot(h, r0). */
double area_disk_mean_far(double h, double r0, double a);

/* The mean of phi over a disk of radius a whose centre is r0 from the foot,
 * for any falloff, by nested Gauss-Kronrod about the disk's centre: the
 * contour form of area_disk cancels terms of the order of r0/a, so it is
 * used for a <= AREA_DISK_FAR hypot(h, r0) in its place. */
double area_disk_mean_far_quadrature(const area_kernel *k, double r0, double a);

/* The mean of phi over the parallelogram O + s U + t V (s, t in [0, 1]),
 * O, U, V in the light's plane about the foot point, for any falloff, by
 * nested Gauss-Kronrod: the corner form and the contour lose 1e-16 of their
 * O(1) parts, 1e-16 / area on the mean, so a light within AREA_DISK_FAR of
 * its distance uses this in their place ([ORACLE-RECT-FAR]). */
double area_parallelogram_mean(const area_kernel *k, const double *o, const double *u, const double *v);

/* The solid angle of a disk of radius a at distance h whose centre is r0
 * off the perpendicular, in complete elliptic integrals (Paxton 1959). */
double area_disk_solid_angle(double h, double r0, double a);

#endif
