/*
 * prim_box.c - the box around a primitive, in its own frame and in the
 * world: the one the extent check bounds ([LANG-EXTENT-1], check_extent.c)
 * and the one the BVH holds the primitive in (isect_prim_bounds), so the
 * shape validation bounds is the shape the BVH boxes.
 */
#include "scene/scene.h"

/* A disk of radius R across the unit axis a spans R sqrt(1 - a_k^2) about
 * its centre along axis k (a disk, the ends of a cylinder or cone, the
 * ring of a torus). */
static void disk_extent(vec3 a, real radius, vec3 *e)
{
    *e = vec_make(radius * sqrt(fmax(0.0, 1.0 - a.x * a.x)), radius * sqrt(fmax(0.0, 1.0 - a.y * a.y)),
                  radius * sqrt(fmax(0.0, 1.0 - a.z * a.z)));
}

/* The box of the two end disks of a cylinder or cone, radii r0 and r1. */
static void ends_box(vec3 from, vec3 to, real r0, real r1, vec3 *lo, vec3 *hi)
{
    vec3 a = vec_normalize(vec_sub(to, from)), e0, e1;
    disk_extent(a, r0, &e0);
    disk_extent(a, r1, &e1);
    *lo = vec_min(vec_sub(from, e0), vec_sub(to, e1));
    *hi = vec_max(vec_add(from, e0), vec_add(to, e1));
}

int scene_prim_local_box(const scene_prim *p, vec3 *lo, vec3 *hi)
{
    vec3 c, e;
    switch (p->kind) {
    case PRIM_SPHERE:
        c = p->u.sphere.center;
        e = vec_splat(p->u.sphere.radius);
        break;
    case PRIM_DISK:
        c = p->u.disk.center;
        disk_extent(vec_normalize(p->u.disk.normal), p->u.disk.radius, &e);
        break;
    case PRIM_TRIANGLE:
        *lo = vec_min(p->u.triangle.p[0], vec_min(p->u.triangle.p[1], p->u.triangle.p[2]));
        *hi = vec_max(p->u.triangle.p[0], vec_max(p->u.triangle.p[1], p->u.triangle.p[2]));
        return 1;
    case PRIM_BOX:
        *lo = p->u.box.lo;
        *hi = p->u.box.hi;
        return 1;
    case PRIM_CYLINDER:
        ends_box(p->u.cylinder.from, p->u.cylinder.to, p->u.cylinder.radius, p->u.cylinder.radius, lo, hi);
        return 1;
    case PRIM_CONE:
        ends_box(p->u.cone.from, p->u.cone.to, p->u.cone.radius[0], p->u.cone.radius[1], lo, hi);
        return 1;
    case PRIM_TORUS: /* the ring's disk, and the tube's radius every way */
        c = p->u.torus.center;
        disk_extent(p->u.torus.axis, p->u.torus.major, &e);
        e = vec_add(e, vec_splat(p->u.torus.minor));
        break;
    case PRIM_MESH:
        *lo = vec_splat(INFINITY);
        *hi = vec_splat(-INFINITY);
        for (int i = 0; i < p->u.mesh.position_count; i++) {
            *lo = vec_min(*lo, p->u.mesh.positions[i]);
            *hi = vec_max(*hi, p->u.mesh.positions[i]);
        }
        return p->u.mesh.position_count > 0;
    default:
        return 0;
    }
    *lo = vec_sub(c, e);
    *hi = vec_add(c, e);
    return 1;
}

int scene_prim_world_box(const scene_prim *p, vec3 *lo, vec3 *hi)
{
    vec3 l, h;
    if (!scene_prim_local_box(p, &l, &h))
        return 0;
    if (!p->frame) {
        *lo = l;
        *hi = h;
        return vec_is_finite(l) && vec_is_finite(h);
    }
    /* The box around the images of the local box's eight corners, from its
     * centre and half extent (Arvo, "Transforming Axis-Aligned Bounding
     * Boxes", Graphics Gems, 1990): the centre mapped, the half extent
     * through the absolute values of the linear part.  A third of the work
     * of mapping eight corners, which a kept-frame hit pays
     * (isect_part_padded_bounds); its rounding, a few ulps of its
     * coordinates, is well inside the BVH's pad of 2^-40 of them. */
    const double(*m)[4] = p->frame->to_world.m;
    vec3 c = vec_scale(vec_add(l, h), 0.5), e = vec_scale(vec_sub(h, l), 0.5);
    vec3 wc = xform_point(&p->frame->to_world, c);
    vec3 we = vec_make(fabs(m[0][0]) * e.x + fabs(m[0][1]) * e.y + fabs(m[0][2]) * e.z,
                       fabs(m[1][0]) * e.x + fabs(m[1][1]) * e.y + fabs(m[1][2]) * e.z,
                       fabs(m[2][0]) * e.x + fabs(m[2][1]) * e.y + fabs(m[2][2]) * e.z);
    *lo = vec_sub(wc, we);
    *hi = vec_add(wc, we);
    return vec_is_finite(*lo) && vec_is_finite(*hi);
}
