/*
 * validate.c - checks that need the whole scene (an empty scene, unused
 * materials, lights buried in opaque objects) and the record of features
 * the tracer uses to leave out whole passes.
 */
#include <math.h>
#include "scene/loader.h"

static int material_used_by_scene(const loader *L, int m)
{
    return L->material_uses[m] > 0;
}

static void warn_unused_materials(loader *L)
{
    const rf_scene *s = L->scene;
    for (int i = 0; i < s->material_count; i++)
        if (s->materials[i].name && !material_used_by_scene(L, i))
            diag_report(&L->diag, DIAG_WARNING, s->materials[i].where, "material '%s' is never used",
                        s->materials[i].name);
}

/* Kd + Ks > 1 reflects more than arrives (legal, but rarely meant). */
static void warn_energy(loader *L)
{
    const rf_scene *s = L->scene;
    for (int i = 0; i < s->material_count; i++) {
        const rf_material *m = &s->materials[i];
        rgb sum = vec_add(m->kd, m->ks);
        if (vec_max_component(sum) > 1 && material_used_by_scene(L, i))
            diag_report(&L->diag, DIAG_WARNING, m->where,
                        "Kd + Ks = %g exceeds 1: this surface reflects more light than it receives",
                        (double)vec_max_component(sum));
    }
}

/* Strictly inside a sphere or box, in the primitive's own frame. */
static int strictly_inside(const rf_prim *prim, vec3 p)
{
    if (prim->has_xform)
        p = xform_point(&prim->to_local, p);
    if (prim->kind == PRIM_SPHERE)
        return vec_length(vec_sub(p, prim->u.sphere.center)) < prim->u.sphere.radius;
    if (prim->kind == PRIM_BOX) {
        vec3 lo = prim->u.box.lo, hi = prim->u.box.hi;
        return p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y && p.z > lo.z && p.z < hi.z;
    }
    return 0;
}

static void warn_buried_lights(loader *L)
{
    const rf_scene *s = L->scene;
    for (int i = 0; i < s->light_count; i++) {
        const rf_light *light = &s->lights[i];
        if (light->kind == LIGHT_DISTANT)
            continue;
        vec3 center = light->position;
        if (light->kind == LIGHT_RECTANGLE)
            center = vec_add(center, vec_scale(vec_add(light->edge_u, light->edge_v), 0.5));
        for (int j = 0; j < s->prim_count; j++) {
            const rf_prim *prim = &s->prims[j];
            if (s->materials[prim->material].t == 0 && strictly_inside(prim, center)) {
                diag_report(&L->diag, DIAG_WARNING, light->where,
                            "this light is inside an opaque %s: it lights nothing outside it",
                            prim->kind == PRIM_SPHERE ? "sphere" : "box");
                break;
            }
        }
    }
}

static void record_features(rf_scene *s, const loader *L)
{
    rf_features *f = &s->features;
    for (int i = 0; i < s->material_count; i++) {
        if (!material_used_by_scene(L, i))
            continue;
        int shiny = vec_max_component(s->materials[i].ks) > 0;
        f->specular |= shiny;
        f->reflection |= shiny;
        f->refraction |= s->materials[i].t > 0;
    }
    for (int i = 0; i < s->light_count; i++)
        f->sampled_lights |= s->lights[i].kind == LIGHT_RECTANGLE || s->lights[i].kind == LIGHT_DISK;
    f->meshes = s->mesh_count > 0;
    /* With N.L > 0 required, one opaque convex or flat primitive never
     * shadows itself; only a second primitive can stand in the way, another
     * part of a mesh, or the far side of a transparent solid seen from
     * inside it (the light reaches its back face through its front). */
    f->shadows = s->light_count > 0 && (s->prim_count >= 2 || s->mesh_count > 0 || f->refraction);
}

int validate_scene(loader *L)
{
    rf_scene *s = L->scene;
    if (s->prim_count == 0) {
        src_span whole = {0, 0, 0};
        diag_report(&L->diag, DIAG_ERROR, whole, "the scene has no primitives: nothing to render");
        return 0;
    }
    warn_unused_materials(L);
    warn_energy(L);
    warn_buried_lights(L);
    record_features(s, L);
    return 1;
}
