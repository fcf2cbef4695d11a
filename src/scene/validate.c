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
    const scene_model *s = L->scene;
    for (int i = 0; i < s->material_count; i++)
        if (s->materials[i].name && !material_used_by_scene(L, i))
            diag_report(&L->diag, DIAG_WARNING, s->materials[i].where, "material '%s' is never used",
                        s->materials[i].name);
}

/* Kd + Ks > 1 reflects more than arrives (legal, but rarely meant). */
static void warn_energy(loader *L)
{
    const scene_model *s = L->scene;
    for (int i = 0; i < s->material_count; i++) {
        const scene_material *m = &s->materials[i];
        rgb sum = vec_add(m->kd, m->ks);
        if (vec_max_component(sum) > 1 && material_used_by_scene(L, i))
            diag_report(&L->diag, DIAG_WARNING, m->where,
                        "Kd + Ks = %g exceeds 1: this surface reflects more light than it receives",
                        (double)vec_max_component(sum));
    }
}

static void warn_buried_lights(loader *L)
{
    const scene_model *s = L->scene;
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *light = &s->lights[i];
        if (light->kind == LIGHT_DISTANT)
            continue;
        vec3 center = light->position;
        if (light->kind == LIGHT_RECTANGLE)
            center = vec_add(center, vec_scale(vec_add(light->edge_u, light->edge_v), 0.5));
        for (int j = 0; j < s->prim_count && !cancel_step(&L->cancel); j++) {
            const scene_prim *prim = &s->prims[j];
            if (s->materials[prim->material].t == 0 && scene_prim_contains(prim, center)) {
                diag_report(&L->diag, DIAG_WARNING, light->where,
                            "this light is inside an opaque %s: it lights nothing outside it",
                            scene_prim_name(prim->kind));
                break;
            }
        }
    }
}

/* The most rays one camera ray can branch into at the scene's max_depth:
 * a hit on a material that both reflects (Ks > 0) and transmits (t > 0)
 * spawns two rays, one that does either spawns one, so the tree holds at
 * most sum over d < max_depth of b^d rays, b the largest branching of a
 * material in use (the tracer's count, trace.c's over_budget).  When that
 * passes --max-ray-tree the render may stop with an error: said at load,
 * so `check` says it too ([REL-RAYTREE-1]).  Not an error: rays that
 * leave the scene end their branch early. */
static void warn_ray_tree(loader *L)
{
    const scene_model *s = L->scene;
    long limit = L->limits->max_ray_tree;
    int branching = 0, depth = s->image.max_depth;
    for (int i = 0; i < s->material_count; i++) {
        const scene_material *m = &s->materials[i];
        int b = (vec_max_component(m->ks) > 0) + (m->t > 0);
        if (material_used_by_scene(L, i) && b > branching)
            branching = b;
    }
    if (limit <= 0 || depth <= 1 || branching == 0)
        return;
    /* 2^depth - 1 or depth rays; in double, as 2^1000 is. */
    double rays = branching == 2 ? ldexp(1.0, depth) - 1 : (double)depth;
    if (rays <= (double)limit)
        return;
    src_span at = L->max_depth_where.file >= 0 ? L->max_depth_where : L->image_where;
    if (branching == 2)
        diag_report(&L->diag, DIAG_WARNING, at, "with max_depth %d and a material that both reflects and transmits, "
                    "one camera ray may branch into 2^%d - 1 rays, over --max-ray-tree %ld: the render stops at the "
                    "first pixel that passes it", depth, depth, limit);
    else
        diag_report(&L->diag, DIAG_WARNING, at, "with max_depth %d one camera ray may be followed by %d rays, over "
                    "--max-ray-tree %ld: the render stops at the first pixel that passes it", depth, depth, limit);
}

static void record_features(scene_model *s, const loader *L)
{
    scene_features *f = &s->features;
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
    /* [LANG-FEATURES-2] A ray that leaves a flat primitive never meets it
     * again, so a lone plane, disk or triangle cannot shadow itself; any
     * other primitive can (a torus, an open tube, and any solid seen from
     * inside: a camera in it, a ray refracted into it). */
    f->shadows = s->light_count > 0 && (s->prim_count >= 2 || scene_prim_self_shadows(&s->prims[0]));
}

/* The whole scene against --max-memory, now that the image is known. */
static int check_memory(loader *L)
{
    const scene_model *s = L->scene;
    double need = scene_memory_estimate(s->prim_count, (double)s->image.width * s->image.height,
                                        loader_memory_extra(L));
    if (need <= (double)L->limits->max_memory_mb * 1048576.0)
        return 1;
    src_span at = L->image_where.file >= 0 ? L->image_where : src_span_none();
    diag_report(&L->diag, DIAG_ERROR, at, "this scene would need about %.0f MiB to load and render (%d primitives, "
                "%dx%d pixels), over --max-memory %ld MiB", need / 1048576.0, s->prim_count, s->image.width,
                s->image.height, L->limits->max_memory_mb);
    return 0;
}

int validate_scene(loader *L)
{
    scene_model *s = L->scene;
    if (!check_memory(L) || !check_view_extent(L, s))
        return 0;
    if (s->prim_count == 0) {
        src_span whole = {0, 0, 0};
        diag_report(&L->diag, DIAG_ERROR, whole, "the scene has no primitives: nothing to render");
        return 0;
    }
    warn_unused_materials(L);
    warn_energy(L);
    warn_buried_lights(L);
    warn_ray_tree(L);
    record_features(s, L);
    return 1;
}
