/*
 * eva_quadric.c - Eva's drivers for the cylinder, cone and torus hit
 * tests (src/render/intersect_quadric.c, intersect_torus.c; spec/proofs.md,
 * "Hit tests: cylinder, cone, torus"): eva_cylinder, eva_cone and
 * eva_torus in make prove and make prove-quick (0 alarms each).
 * Coordinates within 2^500 ([LANG-EXTENT-1]),
 * radii in [2^-500, 2^500] (a cone's: 0 or in that range, not both 0), the ray's direction in
 * vec_normalize's box [-4, 4], tmin in [0, 2^500]; the ends anywhere in
 * the extent, independently (the length's hold in axial_of makes the
 * relation check_extent.c gives, |to - from| >= 2^-500, unneeded).
 * eva_torus: the torus, centre within 2^500 ([LANG-EXTENT-1]), an axis of
 * length within 1e-9 of 1 (check.c, lower_quadric_in_range), both radii in
 * [2^-500, 2^500] (check_extent.c) with minor < major (check_torus).
 */
#include "eva.h"
#include "render/isect_common.c"
#include "render/intersect_quadric.c"
#include "render/intersect_torus.c"

volatile int eva_quadric_int;
volatile real eva_quadric_real;

/* The ray and the ends: any two points of the extent, equal ones too
 * (axial_of holds the length at 2^-501, so no box needs the relation
 * between them that validation gives). */
static void quadric_setup(ray *r, vec3 *from, vec3 *to)
{
    r->origin = any_vec(-0x1p500, 0x1p500);
    r->dir = any_dir();
    r->tmin = any(0, 0x1p500);
    r->tmax = any(0, DBL_MAX);
    *from = any_vec(-0x1p500, 0x1p500);
    *to = any_vec(-0x1p500, 0x1p500);
}

void eva_cylinder(void)
{
    ray r;
    hit out[2] = {{0}, {0}};
    vec3 from, to;
    quadric_setup(&r, &from, &to);
    int n = isect_cylinder_hits(from, to, any(0x1p-500, 0x1p500), Frama_C_int_interval(0, 1), &r, out, 2);
    if (n >= 1)
        eva_quadric_real = out[0].t;
}

void eva_cone(void)
{
    ray r;
    hit out[2] = {{0}, {0}};
    vec3 from, to;
    quadric_setup(&r, &from, &to);
    /* Two boxes: r0 > 0 and any r1, or r0 = 0 and r1 > 0 (check.c: not
     * both 0; a non-zero radius at least 2^-500, check_extent.c). */
    real r0 = 0, r1 = any(0x1p-500, 0x1p500);
    if (Frama_C_int_interval(0, 1)) {
        r0 = any(0x1p-500, 0x1p500);
        r1 = any(0, 0x1p500);
    }
    int n = isect_cone_hits(from, to, r0, r1, Frama_C_int_interval(0, 1), &r, out, 2);
    if (n >= 1)
        eva_quadric_real = out[0].t;
}

void eva_torus(void)
{
    ray r;
    hit out[4] = {{0}, {0}, {0}, {0}};
    r.origin = any_vec(-0x1p500, 0x1p500);
    r.dir = any_dir();
    r.tmin = any(0, 0x1p500);
    r.tmax = any(0, DBL_MAX);
    /* check.c, lower_quadric_in_range: |axis| within 1e-9 of 1, so each
     * component within 1 + 2^-29 (vec_length(axis) >= |axis_i|). */
    vec3 axis = any_vec(-1 - 0x1p-29, 1 + 0x1p-29);
    /* check_extent.c: both radii in [2^-500, 2^500]; check_torus: minor <
     * major (a relation Eva's intervals do not keep: the call's
     * precondition is WP's, prove.sh runs it after Eva, hence the builtin's
     * contract in place of any()). */
    real major = Frama_C_double_interval(0x1p-500, 0x1p500), minor = Frama_C_double_interval(0x1p-500, 0x1p500);
    if (!(minor < major))
        return;
    int n = isect_torus_hits(any_vec(-0x1p500, 0x1p500), axis, major, minor, &r, out, 4);
    if (n >= 1)
        eva_quadric_real = out[0].t;
}
