/*
 * optics_util.h - closed forms shared by the mirror and refraction families
 * of the analytic oracle (parallel_mirrors, glass_slab, snell_window,
 * ball_lens; spec/analytic.md, one section per family derives each formula).
 *
 * Nothing here calls the tracer's modules (trace.c, shade.c, intersect.c,
 * camera.c): the local shading below is written again from spec/shading.md
 * so that a slip in shade.c cannot hide behind a shared function.
 */
#ifndef REFRAY_OPTICS_UTIL_H
#define REFRAY_OPTICS_UTIL_H

#include "oracle/oracle.h"
#include "oracle/oracle_geom.h"

/* The relative margin (of the value compared) inside which a sample point
 * is called ambiguous: a critical angle, a silhouette, a lobe's edge. */
#define OPTICS_MARGIN 1e-9

/* The tolerance of every family here near the picture (deterministic: the
 * issue's 1e-9; from far, the view's rounding: oracle_tolerance_exact). */
#define OPTICS_TOLERANCE 1e-9

/* A sample whose exact value moves by more than this (relative) when its
 * hit points move by twice the tracer's self-intersection offsets is
 * ambiguous: the tracer cannot meet the tolerance there (see
 * optics_spawn_offset and the specs, "Sensitivity"). */
#define OPTICS_SENSITIVITY (OPTICS_TOLERANCE / 4)

/*
 * The distance by which the tracer moves a secondary ray's origin off a
 * surface (intersect.h, Wachter and Binder): SPAWN_REL * max(m, max |p_i|)
 * + SPAWN_ABS, m the primitive's magnitude (sphere: max |c_i| + R; box:
 * max |corner_i|; plane: max |point_i|).  Its effects are the tracer's
 * documented numerical error, not part of the model: the families use it
 * only to call a sample ambiguous when that error could exceed the
 * tolerance.
 */
double optics_spawn_offset(double magnitude, vec3 point);

/* max |v_i| */
double optics_max_abs(vec3 v);

/* 1 when |b - a| <= rel |a| in every channel. */
int optics_close(rgb a, rgb b, double rel);

/*
 * sum_{k=0}^{m-1} q^k for q >= 0 and m >= 0: m for q = 1, else
 * (1 - q^m) / (1 - q), evaluated as expm1(m log1p(-x)) / -x with x = 1 - q
 * so that q near 1 keeps full relative accuracy.  0 for m <= 0.
 */
double optics_geometric_sum(double q, int m);

/* The same channel by channel. */
rgb optics_geometric_sum_rgb(rgb q, int m);

/*
 * Two parallel walls bounding the heights lo < z < hi along a unit axis
 * (z(X) = axis . X): the mirrors of parallel_mirrors, the top and bottom
 * faces of snell_window's glass box.
 */
typedef struct optics_slab {
    vec3 axis;     /* unit, from the lo wall toward the hi wall */
    double lo, hi; /* wall heights, lo < hi */
} optics_slab;

/* The k-th wall hit of a path bouncing between the walls. */
typedef struct optics_bounce {
    vec3 point;    /* on the wall */
    vec3 dir;      /* unit direction the path travels as it arrives */
    vec3 inward;   /* the wall's normal facing the inside of the slab */
    int wall;      /* 0: the lo wall, 1: the hi wall */
    double length; /* path length from the origin */
} optics_bounce;

/*
 * The k-th (k >= 0) wall hit of the path that leaves o (lo < z(o) < hi)
 * along unit d (d . axis != 0) and is mirrored at every wall, found by
 * unfolding: mirrored copies of the slab stacked along the axis turn the
 * zig-zag into the straight line o + s d, which meets the k-th copy's far
 * wall at height hi + k(hi - lo) (d going up) or lo - k(hi - lo) (going
 * down); folding that point back keeps its components across the axis and
 * puts it on the real wall, lo or hi by the parity of k.  The direction of
 * arrival is d with its axial part negated k times.
 */
void optics_slab_hit(const optics_slab *s, vec3 o, vec3 d, int k, optics_bounce *out);

/*
 * The local colour of one light at a surface point, written from
 * spec/shading.md (not shade.c): with unit L toward the light, distance d,
 * I = falloff(E, d) (point) or E (distant), and only when N.L > 0:
 *   body += Kd I S (N.L);  highlight += Ks I S max(0, V.R)^n,  R = 2(N.L)N - L.
 * n: the unit normal already facing the viewer; v: unit toward the viewer;
 * through: the shadow transmission S.  Returns 0 when the point lies within
 * the margin of a discontinuity of the model (shininess 0 with V.R about 0,
 * where the lobe jumps from 1 to 0), else 1.
 */
int optics_light_terms(const scene_light *light, const scene_material *m, vec3 point, vec3 n, vec3 v, double through,
                       rgb *body, rgb *highlight);

/* falloff(E, d, d0) of a light: linear E/(d+d0), inverse_square E/(d+d0)^2,
 * none E (spec/shading.md, slides 15-17). */
rgb optics_falloff(const scene_light *light, double d);

/*
 * Lateral displacement of a ray crossing a plane-parallel slab of thickness
 * h and index n (outside index 1) at incidence theta, given as sin and cos:
 * d = h sin(theta - theta_t) / cos(theta_t), sin theta_t = sin theta / n
 * (Snell's law, Hecht, Optics, ch. 4).  The distance between
 * the exit ray and the undeviated line, measured perpendicular to both.
 * Requires sin theta < n (no total internal reflection at entry).
 */
double optics_slab_shift(double h, double sin_theta, double cos_theta, double n);

/* A meridional ray at height y through a ball lens of radius R and index n
 * in air, the ball centred at the origin of a (z, y) plane, the ray
 * travelling toward +z. */
typedef struct optics_ball_path {
    double incidence;   /* i = asin(y/R) */
    double refraction;  /* r = asin(sin i / n) */
    double deviation;   /* delta = 2(i - r): the exit ray's angle below +z */
    double exit_z;      /* exit point R cos(2r - i) */
    double exit_y;      /*            R sin(2r - i) */
} optics_ball_path;

/* The path of the ray at height 0 <= y < R through the ball (n > 1). */
void optics_ball_trace(double y, double radius, double n, optics_ball_path *p);

/* Where the exit ray crosses the axis, from the centre:
 * z_c = R sin i / sin(2(i - r)); undefined (returns HUGE_VAL) at y = 0. */
double optics_ball_axis_crossing(double y, double radius, double n);

/* The paraxial limit of z_c: the effective focal length from the centre,
 * EFL = n R / (2 (n - 1)). */
double optics_ball_paraxial_focus(double radius, double n);

/* The height at which the exit ray meets the plane z = zs > R (signed,
 * along the ray's own side of the axis).  Valid when cos(deviation) > 0. */
double optics_ball_screen_height(const optics_ball_path *p, double zs);

/* sin of the critical angle from index n1 into n2 < n1: n2/n1 (Snell with
 * theta_2 = 90 degrees); 1 when n1 <= n2 (no total internal reflection). */
double optics_critical_sin(double n1, double n2);

/* The camera ray through corner 0..3 of the image ((0,0), (W,0), (0,H),
 * (W,H)): every sample point lies inside the rectangle they span, so a
 * condition convex over the screen that holds at the corners holds for
 * every sample (accepts uses this for view-wide assumptions). */
oracle_ray optics_corner_ray(const oracle_view *v, int corner);

#endif
