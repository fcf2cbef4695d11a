/*
 * eva_isect.c - Eva's drivers for the hit tests (src/render/isect_common.c,
 * src/render/intersect.c; spec/proofs.md, "Hit tests"; tests/prove/prove.sh
 * isect-eva runs them).  Coordinates are in [-2^500, 2^500] (the scene's
 * extent, [LANG-EXTENT-1]), f = o - c in [-2^501, 2^501] (wider for
 * isect_sphere_roots, below), radii in [2^-500, 2^500], a ray's direction in the box of vec_normalize's bound,
 * [-4, 4].  intersect.c's static functions are reached by including it.
 *
 * Four entry points:
 *   eva_isect_sphere: isect_sphere_roots (with isect_quotient's body, so
 *     that each box keeps the range of the foot -b/a), held_root and the
 *     vec.h lengths by their contracts, over its precondition's box (f
 *     within 2^505, R in [2^-500, 2^501], d within 64: the cylinder's
 *     and the torus's calls).  It divides b = f.d by a = d.d, whose ratio
 *     to |d| an analysis of intervals loses when |d| ranges from 2^-1074
 *     to 64; so d is split as in eva_vec.c, its largest component in one
 *     binade [2^k, 2^(k+1)) for k = -538 .. 5 (below 2^-509 the foot's
 *     test bounds it, by 2^1020 times the spread of a in the box; above,
 *     one binade keeps l = f - (b/a) d within 13 |f|, 2^509, its square
 *     finite), then 64 itself, one box for every smaller d (each square
 *     rounds to 0, so a = 0), and the zero vector: 3278 calls.
 *   eva_isect: isect_hit_set, plane_t, box_slabs, with isect_quotient by
 *     its contract.
 *   eva_isect_quotient: isect_quotient and held_root, the divisor in each
 *     binade of either sign and 0, the dividend anywhere their precondition
 *     allows.
 *   eva_isect_triangle: isect_shear_make, and triangle_solve given the
 *     shear's ranges (-DEVA_ISECT_TRIANGLE; not in make prove: its alarms
 *     are open, spec/proofs.md).
 * The boxes come from isect_boxes.h (BOX(2^k, 2^(k+1)), k = -1074 ..
 * 1022, then BOX(2^1023, DBL_MAX)) and sphere_boxes.h (SBOX(lo, hi)),
 * which prove.sh writes.
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
    r.tmax = any(0, DBL_MAX);   /* +Inf compares as DBL_MAX: every t is within 2^1021 */
    return r;
}

static void sphere_roots(vec3 d)
{
    real t[2] = {0, 0};
    int n = isect_sphere_roots(any_vec(-0x1p505, 0x1p505), d, any(0x1p-500, 0x1p501), t);
    if (n >= 1)
        eva_isect_real = t[0];
    if (n == 2)
        eva_isect_real = t[1];
}

static void sphere_box(real lo, real hi)
{
    for (int axis = 0; axis < 3; axis++) {
        sphere_roots(largest_at(axis, 1, lo, hi));
        sphere_roots(largest_at(axis, -1, lo, hi));
    }
}

void eva_isect_sphere(void)
{
    sphere_roots(vec_make(0, 0, 0));
    sphere_box(0x1p-1074, binade_top(0x1p-538));
#define SBOX(lo, hi) sphere_box(lo, lo == 64 ? lo : binade_top(hi));
#include "sphere_boxes.h"
#undef SBOX
}

void eva_isect(void)
{
    ray r = any_ray();
    hit h;
    real t;
    isect_hit_set(&h, any(-DBL_MAX, DBL_MAX), any_point(), any_dir(), any_dir());
    eva_isect_int = plane_t(any_point(), any_dir(), &r, &t);
    real tt[2];
    int axis[2];
    eva_isect_int = box_slabs(any_point(), any_point(), &r, tt, axis);
}

static void quotient_binade(real lo, real hi)
{
    real q;
    hi = binade_top(hi);
    eva_isect_int = isect_quotient(any(-0x1p1017, 0x1p1017), any(lo, hi), &q);
    eva_isect_real = q;
    eva_isect_int = isect_quotient(any(-0x1p1017, 0x1p1017), any(-hi, -lo), &q);
    eva_isect_real = q;
    eva_isect_real = held_root(any(-0x1p1017, 0x1p1017), any(lo, hi));
    eva_isect_real = held_root(any(-0x1p1017, 0x1p1017), any(-hi, -lo));
}

void eva_isect_quotient(void)
{
    real q;
    eva_isect_int = isect_quotient(any(-0x1p1017, 0x1p1017), any(-0.0, 0.0), &q);
    eva_isect_real = q;
    eva_isect_real = held_root(any(-0x1p1017, 0x1p1017), any(-0.0, 0.0));
#define BOX(lo, hi) quotient_binade(lo, hi);
#include "isect_boxes.h"
#undef BOX
}

#ifdef EVA_ISECT_TRIANGLE
/* The ray's shear (isect_shear_make) over every direction of the box, its
 * largest component in one box [2^k, 2^(k+3)) (shear_boxes.h: k = -1074,
 * -1071, .., the last one cut at 4), then 4 itself, and the zero vector;
 * and triangle_solve given the ranges the shear has: sx, sy in [-1, 1]
 * (the ratios of the other components to the largest: Eva shows them
 * finite, within 8 in these boxes), dz nonzero of either sign, each of the
 * six axis permutations. */
static const int eva_isect_perm[6][3] = {{1, 2, 0}, {2, 1, 0}, {2, 0, 1}, {0, 2, 1}, {0, 1, 2}, {1, 0, 2}};

static void shear_box(real lo, real hi)
{
    for (int axis = 0; axis < 3; axis++)
        for (int sign = -1; sign <= 1; sign += 2) {
            ray r = any_ray();
            isect_shear sh;
            r.dir = largest_at(axis, sign, lo, hi);
            isect_shear_make(&r, &sh);
            eva_isect_real = sh.sx;
            eva_isect_real = sh.sy;
        }
}

void eva_isect_triangle(void)
{
    ray r = any_ray();
    isect_shear sh;
    r.dir = vec_make(0, 0, 0);
    isect_shear_make(&r, &sh);
#define TBOX(lo, hi) shear_box(lo, binade_top(hi > 4 ? 4 : hi));
#include "shear_boxes.h"
#undef TBOX
    shear_box(4, 4);
    for (int p = 0; p < 6; p++)
        for (int sign = -1; sign <= 1; sign += 2) {
            sh.kx = eva_isect_perm[p][0];
            sh.ky = eva_isect_perm[p][1];
            sh.kz = eva_isect_perm[p][2];
            sh.dz = sign > 0 ? any(0x1p-1074, 4) : any(-4, -0x1p-1074);
            sh.sx = any(-1, 1);
            sh.sy = any(-1, 1);
            vec3 v[3] = {any_point(), any_point(), any_point()};
            tri_bary s = {0, {0, 0, 0}};
            eva_isect_int = triangle_solve(v, Frama_C_int_interval(0, 7), &r, &sh, &s);
            eva_isect_real = s.t;
            eva_isect_real = s.b[0];
        }
}
#endif
