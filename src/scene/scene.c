/*
 * scene.c - the scene model's defaults and its release.
 */
#include <string.h>
#include "scene/scene.h"

scene_limits scene_default_limits(void)
{
    scene_limits l;
    l.max_width = 16384;
    l.max_height = 16384;
    l.max_pixels = 64L * 1024 * 1024;
    l.max_samples = 64;
    l.max_light_samples = 4096;
    l.max_depth = SCENE_DEPTH_CEILING;
    l.max_loop_iterations = 1000000;
    l.max_include_depth = 32;
    l.max_file_bytes = 64L * 1024 * 1024;
    l.max_mesh_triangles = 10L * 1000 * 1000;
    l.max_primitives = 20L * 1000 * 1000;
    l.max_errors = 20;
    l.max_ray_tree = 1000000;
    l.max_input_bytes = 256L * 1024 * 1024;
    l.max_memory_mb = 4096;
    return l;
}

double scene_memory_estimate(double prims, double pixels, double extra)
{
    return prims * (double)SCENE_BYTES_PER_PRIM + pixels * SCENE_BYTES_PER_PIXEL + extra + SCENE_BYTES_FIXED;
}

void scene_free(scene_model *s)
{
    if (!s)
        return;
    mem m = s->mem;
    arena_free(&s->kept);
    for (int i = 0; i < s->material_count; i++)
        mem_free_string(&m, s->materials[i].name);
    for (int i = 0; i < s->mesh_count; i++) {
        mem_free_string(&m, s->meshes[i].path);
        scene_trimesh_free(&m, &s->meshes[i].geom);
    }
    mem_free(&m, s->materials, (size_t)s->material_cap * sizeof *s->materials);
    mem_free(&m, s->prims, (size_t)s->prim_cap * sizeof *s->prims);
    mem_free(&m, s->meshes, (size_t)s->mesh_cap * sizeof *s->meshes);
    mem_free(&m, s->lights, (size_t)s->light_cap * sizeof *s->lights);
    mem_free_string(&m, s->oracle);
    source_set_free(&s->sources);
    mem_free(&m, s, sizeof *s);
}


void scene_load_opts_init(scene_load_opts *o)
{
    memset(o, 0, sizeof *o);
    o->limits = scene_default_limits();
    o->warnings = 1;
}

static const char *const prim_names[PRIM_KINDS][2] = {
    {"sphere", "spheres"}, {"plane", "planes"},       {"triangle", "triangles"}, {"disk", "disks"},
    {"box", "boxes"},      {"cylinder", "cylinders"}, {"cone", "cones"},         {"torus", "tori"},
    {"mesh", "meshes"},
};

const char *scene_prim_name(scene_prim_kind kind)
{
    return prim_names[kind][0];
}

const char *scene_prim_plural(scene_prim_kind kind)
{
    return prim_names[kind][1];
}

int scene_prim_is_solid(const scene_prim *p)
{
    switch (p->kind) {
    case PRIM_SPHERE:
    case PRIM_BOX:
    case PRIM_TORUS: return 1;
    case PRIM_CYLINDER: return !p->u.cylinder.open;
    case PRIM_CONE: return !p->u.cone.open;
    default: return 0;
    }
}

/* Height along the axis from `from` (0 .. len inside) and distance from it. */
static void axial_place(vec3 from, vec3 to, vec3 q, real *z, real *len, real *across)
{
    vec3 a = vec_sub(to, from);
    *len = vec_length(a);
    a = vec_scale(a, 1.0 / *len);
    vec3 f = vec_sub(q, from);
    *z = vec_dot(f, a);
    *across = vec_length(vec_madd(f, a, -*z));
}

static int inside_cone(vec3 from, vec3 to, real r0, real r1, vec3 q)
{
    real z, len, across;
    axial_place(from, to, q, &z, &len, &across);
    return z > 0 && z < len && across < r0 + (r1 - r0) * (z / len);
}

vec3 scene_frame_local(const scene_frame *f, vec3 point)
{
    const double(*w)[4] = f->to_world.m;
    return xform_vector(&f->to_local, vec_sub(point, vec_make(w[0][3], w[1][3], w[2][3])));
}

int scene_prim_contains(const scene_prim *p, vec3 point)
{
    vec3 q = p->frame ? scene_frame_local(p->frame, point) : point;
    if (!scene_prim_is_solid(p))
        return 0;
    switch (p->kind) {
    case PRIM_SPHERE:
        return vec_length(vec_sub(q, p->u.sphere.center)) < p->u.sphere.radius;
    case PRIM_BOX:
        return q.x > p->u.box.lo.x && q.x < p->u.box.hi.x && q.y > p->u.box.lo.y && q.y < p->u.box.hi.y &&
               q.z > p->u.box.lo.z && q.z < p->u.box.hi.z;
    case PRIM_CYLINDER:
        return inside_cone(p->u.cylinder.from, p->u.cylinder.to, p->u.cylinder.radius, p->u.cylinder.radius, q);
    case PRIM_CONE:
        return inside_cone(p->u.cone.from, p->u.cone.to, p->u.cone.radius[0], p->u.cone.radius[1], q);
    default: {
        vec3 f = vec_sub(q, p->u.torus.center);
        real z = vec_dot(f, p->u.torus.axis);
        real rho = vec_length(vec_madd(f, p->u.torus.axis, -z));
        return hypot(rho - p->u.torus.major, z) < p->u.torus.minor;
    }
    }
}

int scene_prim_self_shadows(const scene_prim *p)
{
    return p->kind != PRIM_PLANE && p->kind != PRIM_DISK && p->kind != PRIM_TRIANGLE;
}

void scene_trimesh_free(const mem *m, scene_trimesh *g)
{
    mem_free(m, g->positions, (size_t)g->position_cap * sizeof *g->positions);
    mem_free(m, g->normals, (size_t)g->normal_cap * sizeof *g->normals);
    mem_free(m, g->tri, (size_t)g->tri_cap * sizeof *g->tri);
    mem_free(m, g->tri_normal, (size_t)g->tri_normal_cap * sizeof *g->tri_normal);
    mem_free(m, g->open, (size_t)g->tri_count);
    memset(g, 0, sizeof *g);
}

long scene_mesh_bytes(const scene_model *s, long *triangles)
{
    long bytes = 0;
    *triangles = 0;
    for (int i = 0; i < s->mesh_count; i++) {
        const scene_trimesh *g = &s->meshes[i].geom;
        long t = g->tri_count;
        *triangles += t;
        bytes += (long)(g->position_count * sizeof *g->positions + g->normal_count * sizeof *g->normals);
        bytes += t * (long)sizeof *g->tri + (g->tri_normal ? t * (long)sizeof *g->tri_normal : 0) + (g->open ? t : 0);
    }
    return bytes;
}

