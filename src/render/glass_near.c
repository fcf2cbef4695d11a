/*
 * glass_near.c - [NUM-GLASS-3] the boxes of the transparent primitives and
 * the test whether a point lies within reach of one (glass_near.h).
 */
#include <math.h>
#include "render/glass_near.h"
#include "render/intersect.h"

/*
 * The transparent primitives' boxes, padded by 2^-20 of their size (a hit
 * point lies within a few ulps of its primitive's box).
 */
enum { GLASS_BOX_MAX = 64 };

int glass_near_padded_box(const scene_prim *p, vec3 *lo, vec3 *hi, real *size)
{
    if (!isect_prim_bounds(p, lo, hi))
        return 0;
    *size = fmax(fmax(vec_max_abs(*lo), vec_max_abs(*hi)), vec_max_abs(vec_sub(*hi, *lo)));
    *lo = vec_sub(*lo, vec_splat(0x1p-20 * *size));
    *hi = vec_add(*hi, vec_splat(0x1p-20 * *size));
    return 1;
}
int glass_near_build(tracer *t, const scene_model *s)
{
    int n = 0;
    t->glass_boxes = -1;
    for (int i = 0; i < s->prim_count; i++)
        n += s->materials[s->prims[i].material].t > 0;
    if (n == 0 || n > GLASS_BOX_MAX)
        return 1;
    t->glass_box = mem_calloc(&s->mem, 2 * (size_t)n, sizeof *t->glass_box);
    t->glass_prim = mem_calloc(&s->mem, (size_t)n, sizeof *t->glass_prim);
    t->glass_alloc = n;
    if (!t->glass_box || !t->glass_prim)
        return 0;
    n = 0;
    for (int i = 0; i < s->prim_count; i++) {
        vec3 lo, hi;
        if (!(s->materials[s->prims[i].material].t > 0))
            continue;
        real size;
        if (!glass_near_padded_box(&s->prims[i], &lo, &hi, &size))
            return 1;
        t->glass_prim[n] = i;
        t->glass_box[2 * n] = lo;
        t->glass_box[2 * n++ + 1] = hi;
    }
    t->glass_boxes = n;
    return 1;
}

/* Within sqrt(3) reach in length, and the sphere's hit points lie within
 * 2^-20 of its size of it (a few ulps); 2 reach and that pad cover both. */
int glass_near_sphere(const scene_prim *p, vec3 point, real reach)
{
    vec3 c = p->u.sphere.center;
    real r = p->u.sphere.radius, pad = 2 * reach + 0x1p-20 * (vec_max_abs(c) + r);
    return fabs(vec_length(vec_sub(point, c)) - r) <= pad;
}

/* Whether a transparent surface may lie within reach of point (glass_box;
 * a sphere kept in the world frame by its distance from the centre). */
int glass_near(const tracer *t, vec3 point, real reach)
{
    if (t->glass_boxes < 0)
        return 1;
    for (int i = 0; i < t->glass_boxes; i++) {
        vec3 lo = t->glass_box[2 * i], hi = t->glass_box[2 * i + 1];
        const scene_prim *p = &t->scene->prims[t->glass_prim[i]];
        if (point.x >= lo.x - reach && point.x <= hi.x + reach && point.y >= lo.y - reach &&
            point.y <= hi.y + reach && point.z >= lo.z - reach && point.z <= hi.z + reach &&
            (p->kind != PRIM_SPHERE || p->frame || glass_near_sphere(p, point, reach)))
            return 1;
    }
    return 0;
}

void glass_near_free(tracer *t)
{
    const scene_model *s = t->scene;
    mem_free(&s->mem, t->glass_box, 2 * (size_t)t->glass_alloc * sizeof *t->glass_box);
    mem_free(&s->mem, t->glass_prim, (size_t)t->glass_alloc * sizeof *t->glass_prim);
    t->glass_box = NULL;
    t->glass_prim = NULL;
}
