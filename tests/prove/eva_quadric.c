/*
 * eva_quadric.c - Eva's driver for the cylinder and cone hit tests
 * (src/render/intersect_quadric.c; spec/proofs.md, "Hit tests: cylinder,
 * cone, torus"; tests/prove/prove.sh isect-quadric runs it, not make
 * prove: its alarms are open).  Coordinates within 2^500 ([LANG-EXTENT-1]),
 * radii in [2^-500, 2^500] (a cone's in [0, 2^500]), the ray's direction in
 * vec_normalize's box [-4, 4], tmin in [0, 2^500]; the axis to - from has
 * one component of at least 2^-251 in magnitude (its squared length is at
 * least 2^-500, check_extent.c), on each axis and of either sign.
 * eva_torus: the torus, centre within 2^500, a unit axis (vec_normalize's
 * box), 0 < minor < major within 2^500 (the box of each: minor in
 * [2^-500, 2^499], major in [2^-499, 2^500]).
 */
#include "eva.h"
#include "render/isect_common.c"
#include "render/intersect_quadric.c"
#include "render/intersect_torus.c"

volatile int eva_quadric_int;
volatile real eva_quadric_real;

/* The ray and the ends of one box: the axis's largest component on axis
 * `axis` with sign `sign`. */
static vec3 quadric_setup(ray *r, int axis, real sign, vec3 *from)
{
    r->origin = any_vec(-0x1p500, 0x1p500);
    r->dir = any_dir();
    r->tmin = any(0, 0x1p500);
    r->tmax = any(0, DBL_MAX);
    *from = any_vec(-0x1p500, 0x1p500);
    return vec_add(*from, largest_at(axis, sign, 0x1p-251, 0x1p501));
}

static void cylinder_box(int axis, real sign)
{
    ray r;
    hit out[2];
    vec3 from, to = quadric_setup(&r, axis, sign, &from);
    int n = isect_cylinder_hits(from, to, any(0x1p-500, 0x1p500), Frama_C_int_interval(0, 1), &r, out, 2);
    if (n >= 1)
        eva_quadric_real = out[0].t;
}

static void cone_box(int axis, real sign)
{
    ray r;
    hit out[2];
    vec3 from, to = quadric_setup(&r, axis, sign, &from);
    int n = isect_cone_hits(from, to, any(0, 0x1p500), any(0, 0x1p500), Frama_C_int_interval(0, 1), &r, out, 2);
    if (n >= 1)
        eva_quadric_real = out[0].t;
}

void eva_cylinder(void)
{
    for (int axis = 0; axis < 3; axis++) {
        cylinder_box(axis, 1);
        cylinder_box(axis, -1);
    }
}

void eva_cone(void)
{
    for (int axis = 0; axis < 3; axis++) {
        cone_box(axis, 1);
        cone_box(axis, -1);
    }
}

void eva_torus(void)
{
    ray r;
    hit out[4];
    r.origin = any_vec(-0x1p500, 0x1p500);
    r.dir = any_dir();
    r.tmin = any(0, 0x1p500);
    r.tmax = any(0, DBL_MAX);
    int n = isect_torus_hits(any_vec(-0x1p500, 0x1p500), any_dir(), any(0x1p-499, 0x1p500), any(0x1p-500, 0x1p499), &r,
                             out, 4);
    if (n >= 1)
        eva_quadric_real = out[0].t;
}
