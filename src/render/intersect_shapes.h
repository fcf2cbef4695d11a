/*
 * intersect_shapes.h - the hit tests of the cylinder, cone and torus
 * (intersect_quadric.c, intersect_torus.c), which intersect.c calls; what
 * all of them share is below, in isect_common.h.  Internal to the render
 * layer: the entry points are isect_prim, isect_prim_all and the isect_* of
 * intersect.h.
 *
 * Each SHAPE_hits writes up to max accepted hits (t in (tmin, tmax)) in
 * increasing t and returns how many, with the contract of intersect.h.
 * The contracts (make prove, spec/proofs.md "Hit tests: cylinder, cone,
 * torus") are here, on the prototypes, so that WP checks their
 * preconditions at intersect.c's calls: what validation guarantees
 * ([LANG-VALID-2]: finite data; check_radius: radius > 0; [LANG-EXTENT-1],
 * check_extent.c: from != to; check.c: a cone's radii not both 0, a ring
 * torus), and the hits: at most max, each t in (tmin, tmax) (doubles too:
 * the comparisons that keep a hit; with tmin >= 0 and t < tmax <= +Inf, t
 * is finite), a quadric's two in order.  The relations between two doubles
 * are EXACT: WP proves them (comparisons and copies, the same for the
 * doubles), Eva's intervals keep no relation to show them by.
 */
#ifndef REFRAY_INTERSECT_SHAPES_H
#define REFRAY_INTERSECT_SHAPES_H

#include "render/ray.h"

/* intersect_quadric.c: a cylinder from `from` to `to` of radius r, a cone
 * with radius r0 at from and r1 at to; open: no end caps (a sheet). */
/*@ requires \valid_read(r) && max >= 0 && \valid(out + (0 .. max - 1)) && \separated(out + (0 .. max - 1), r);
    requires vfinite(from) && vfinite(to) && EXACT(!veq(from, to));   // [LANG-VALID-2], [LANG-EXTENT-1]; Eva: any (axial_of)
    requires \is_finite(radius) && radius > 0;                     // check_radius
    requires vfinite(r->origin) && vfinite(r->dir) && \is_finite(r->tmin) && r->tmin >= 0;   // [NUM-FINITE-1]
    assigns out[0 .. max - 1];
    ensures 0 <= \result <= max;
    ensures EXACT(\forall integer i; 0 <= i < \result ==> \old(r->tmin) < out[i].t < \old(r->tmax));
    ensures EXACT(\result == 2 ==> out[0].t <= out[1].t); */
int isect_cylinder_hits(vec3 from, vec3 to, real radius, int open, const ray *r, hit *out, int max);
/*@ requires \valid_read(r) && max >= 0 && \valid(out + (0 .. max - 1)) && \separated(out + (0 .. max - 1), r);
    requires vfinite(from) && vfinite(to) && EXACT(!veq(from, to));   // [LANG-VALID-2], [LANG-EXTENT-1]; Eva: any (axial_of)
    requires \is_finite(r0) && \is_finite(r1) && r0 >= 0 && r1 >= 0 && (r0 > 0 || r1 > 0);   // check.c: not both 0
    requires vfinite(r->origin) && vfinite(r->dir) && \is_finite(r->tmin) && r->tmin >= 0;   // [NUM-FINITE-1]
    assigns out[0 .. max - 1];
    ensures 0 <= \result <= max;
    ensures EXACT(\forall integer i; 0 <= i < \result ==> \old(r->tmin) < out[i].t < \old(r->tmax));
    ensures EXACT(\result == 2 ==> out[0].t <= out[1].t); */
int isect_cone_hits(vec3 from, vec3 to, real r0, real r1, int open, const ray *r, hit *out, int max);

/* intersect_torus.c: up to 4 crossings. */
/*@ requires \valid_read(r) && max >= 0 && \valid(out + (0 .. max - 1)) && \separated(out + (0 .. max - 1), r);
    requires vfinite(center) && vfinite(axis);                               // [LANG-VALID-2]
    requires \is_finite(major) && \is_finite(minor) && 0 < minor < major;     // a ring torus (check.c)
    requires vfinite(r->origin) && vfinite(r->dir) && \is_finite(r->tmin) && r->tmin >= 0;   // [NUM-FINITE-1]
    assigns out[0 .. max - 1];
    ensures 0 <= \result <= max;
    ensures EXACT(\forall integer i; 0 <= i < \result ==> \old(r->tmin) < out[i].t < \old(r->tmax)); */
int isect_torus_hits(vec3 center, vec3 axis, real major, real minor, const ray *r, hit *out, int max);

#endif
