/*
 * eva_isect.c - Eva's driver for the hit tests (src/render/isect_common.c,
 * src/render/intersect.c), not yet part of make prove: its alarms are open
 * (spec/proofs.md, "Hit tests"; tests/prove/prove.sh isect-eva runs it).
 * Each call covers its function's precondition, with coordinates in
 * [-2^500, 2^500] (inside intersect.h's numeric domain) and a ray's
 * direction as the box of vec_normalize's bound.  intersect.c's static
 * functions are reached by including it; box_slabs comes last, as the sure
 * alarm of its infinite sentinels ends the analysis there.
 */
#include "eva.h"
#include "render/isect_common.c"
#include "render/intersect.c"

volatile real eva_isect_real;
volatile int eva_isect_int;

static vec3 any_point(void) { return any_vec(-0x1p500, 0x1p500); }

static ray any_ray(void)
{
    ray r;
    r.origin = any_point();
    r.dir = any_dir();
    r.tmin = any(0, 0x1p500);
    r.tmax = any(0, DBL_MAX);
    return r;
}

void eva_isect(void)
{
    real t[2];
    ray r = any_ray();
    hit h;
    int n = isect_sphere_roots(any_point(), any_dir(), any(0x1p-500, 0x1p500), t);
    if (n >= 1)
        eva_isect_real = t[0];
    if (n == 2)
        eva_isect_real = t[1];
    isect_hit_set(&h, any(-DBL_MAX, DBL_MAX), any_point(), any_dir(), any_dir());
    eva_isect_int = plane_t(any_point(), any_dir(), &r, t);
    vec3 v[3] = {any_point(), any_point(), any_point()};
    tri_bary s;
    eva_isect_int = triangle_solve(v, Frama_C_int_interval(0, 7), &r, &s);
    real tt[2];
    int axis[2];
    eva_isect_int = box_slabs(any_point(), any_point(), &r, tt, axis);
}
