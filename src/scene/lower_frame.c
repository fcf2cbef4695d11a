/*
 * lower_frame.c - what the lowering of every kind of shape does with its
 * transforms once they are read: whether they mirror, the world normal,
 * and the local frame kept when the shape cannot absorb them
 * (lower_prims.c, lower_quadrics.c, lower_mesh.c).
 */
#include "scene/loader.h"

static double determinant(const xform *a)
{
    const double(*m)[4] = a->m;
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

int lower_mirrors(const xform *w)
{
    return determinant(w) < 0;
}

/* A normal taken through the inverse transpose, made unit.  When that is
 * impossible the raw result (zero or not finite) is kept, and in_range
 * refuses the primitive. */
vec3 lower_transformed_normal(const xform *to_local, vec3 n)
{
    vec3 raw = xform_normal(to_local, n), unit;
    return loader_unit(raw, &unit) ? unit : raw;
}

/* Keeps the local frame when the shape cannot absorb the transform. */
int lower_keep_frame(loader *L, scene_prim *prim, const xform *to_world, const xform *to_local)
{
    scene_frame *f = arena_alloc(&L->scene->kept, sizeof *f);
    if (!f) {
        loader_oom(L);
        return 0;
    }
    f->to_world = *to_world;
    f->to_local = *to_local;
    prim->frame = f;
    return 1;
}
