/*
 * trace.c - trace() and shade() of the seed's pseudocode (slides 45-48),
 * step for step; every formula is a function of shade.c.
 *
 *   trace(ray, depth):  nearest hit -> shade(), else the background    (46)
 *   shade():  color = Kd*Ia                                            (47, 11)
 *             for each light (each sample of a distributed one):
 *               if N.L > 0: scale diffuse and specular by what the
 *               surfaces on the way let through, add them              (47)
 *             if depth < max_depth:
 *               + Ks * trace(mirror ray)                               (48)
 *               + t * trace(refracted ray), or on total internal
 *                 reflection t * trace(mirror ray)                     (48, 36)
 *   with the body colour weighted by (1 - t) (slide 37, t = transparency).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "intersect.h"
#include "sampler.h"
#include "shade.h"
#include "trace.h"

/* What shade() knows about the point it shades. */
typedef struct surface {
    const rf_material *m;
    const rf_prim *prim;
    const hit *h;
    vec3 v;          /* unit, toward where the ray came from */
    vec3 n;          /* shading normal turned toward v */
} surface;

int trace_solid_id(const rf_scene *s, int prim)
{
    const rf_prim *p = &s->prims[prim];
    if (p->kind == PRIM_SPHERE || p->kind == PRIM_BOX)
        return prim;
    if (p->kind == PRIM_TRIANGLE && p->mesh >= 0)
        return s->prim_count + p->mesh;
    return -1;
}

int tracer_init(tracer *t, const rf_scene *s, int max_depth, int light_samples)
{
    memset(t, 0, sizeof *t);
    t->scene = s;
    t->max_depth = max_depth > 0 ? max_depth : s->image.max_depth;
    t->shadows = s->features.shadows;
    t->specular = s->features.specular;
    t->reflection = s->features.reflection && t->max_depth > 1;
    t->refraction = s->features.refraction && t->max_depth > 1;
    t->lights = calloc((size_t)(s->light_count ? s->light_count : 1), sizeof *t->lights);
    if (!t->lights || !bvh_build(&t->accel, s->prims, s->prim_count)) {
        tracer_free(t);
        return 0;
    }
    for (int i = 0; i < s->light_count; i++) {
        const rf_light *light = &s->lights[i];
        t->lights[i].samples = light_samples > 0 ? light_samples : light->samples;
        if (light->kind == LIGHT_RECTANGLE || light->kind == LIGHT_DISK)
            t->lights[i].grid = light_grid_for(t->lights[i].samples);
        if (light->kind == LIGHT_DISK)
            light_frame(light->normal, &t->lights[i].t1, &t->lights[i].t2);
    }
    return 1;
}

void tracer_free(tracer *t)
{
    bvh_free(&t->accel);
    free(t->lights);
    t->lights = NULL;
}

typedef struct shadow_walk {
    const rf_scene *scene;
    real carried;
} shadow_walk;

/* Slide 47: every surface on the way lets through its t (opaque: 0). */
static int shadow_crossing(void *ctx, const hit *h)
{
    shadow_walk *w = ctx;
    const rf_material *m = &w->scene->materials[w->scene->prims[h->prim].material];
    w->carried = shade_shadow_transmission(w->carried, m->t);
    return w->carried == 0;
}

/* The fraction of a light that reaches the surface along r. */
static real shadow_transmission(const tracer *t, const ray *r, trace_stats *st)
{
    shadow_walk w = {t->scene, 1.0};
    st->shadow_rays++;
    bvh_visit_stats(&t->accel, t->scene->prims, r, shadow_crossing, &w, &st->bvh);
    return w.carried;
}

typedef struct direct_sum {
    rgb body;        /* diffuse, before the (1 - t) weight */
    rgb highlight;
} direct_sum;

/* One point source at pos (distant: at infinity along -direction). */
static void add_source(const tracer *t, const surface *s, const rf_light *light, vec3 pos, rgb power,
                       direct_sum *sum, trace_stats *st)
{
    vec3 l;
    real d = HUGE_VAL;
    st->light_samples++;
    if (light->kind == LIGHT_DISTANT) {
        l = vec_neg(light->direction);
    } else {
        vec3 to = vec_sub(pos, s->h->point);
        d = vec_length(to);
        if (!(d > 0)) {
            st->lights_on_surface++;
            return;
        }
        l = vec_scale(to, 1.0 / d);
    }
    if (!(vec_dot(s->n, l) > 0))
        return;
    rgb intensity = light->kind == LIGHT_DISTANT ? power : shade_falloff(power, d, light->d0, light->falloff);
    if (t->shadows) {
        ray r = light->kind == LIGHT_DISTANT ? ray_spawn_hit(s->prim, s->h, l) : ray_spawn_hit_to(s->prim, s->h, pos);
        real through = shadow_transmission(t, &r, st);
        if (through == 0)
            return;
        intensity = vec_scale(intensity, through);
    }
    if (t->specular) {
        shade_terms terms = shade_direct(s->m->kd, s->m->ks, s->m->n, intensity, s->n, l, s->v);
        sum->body = vec_add(sum->body, terms.body);
        sum->highlight = vec_add(sum->highlight, terms.highlight);
    } else {
        sum->body = vec_add(sum->body, shade_diffuse(s->m->kd, intensity, s->n, l));
    }
}

/* The samples of a distributed light, each a point source of E/samples. */
static void add_distributed(const tracer *t, const surface *s, int index, uint64_t key, direct_sum *sum,
                            trace_stats *st)
{
    const rf_light *light = &t->scene->lights[index];
    const light_setup *setup = &t->lights[index];
    rgb power = shade_sample_power(light->power, setup->samples);
    uint64_t light_key = sampler_key(key, 0x100u + (uint64_t)index);
    for (int j = 0; j < setup->samples; j++) {
        double u1 = sampler_uniform(sampler_key(light_key, 2 * (uint64_t)j));
        double u2 = sampler_uniform(sampler_key(light_key, 2 * (uint64_t)j + 1));
        double a, b;   /* the sample's place in the light's unit square: model data, double */
        light_cell_point(setup->grid, j, u1, u2, &a, &b);
        add_source(t, s, light, light_point(light, setup->t1, setup->t2, a, b), power, sum, st);
    }
}

static direct_sum direct_light(const tracer *t, const surface *s, uint64_t key, trace_stats *st)
{
    direct_sum sum = {shade_ambient(s->m->kd, t->scene->ambient), vec_splat(0)};
    for (int i = 0; i < t->scene->light_count; i++) {
        const rf_light *light = &t->scene->lights[i];
        if (light->kind == LIGHT_POINT || light->kind == LIGHT_DISTANT)
            add_source(t, s, light, light->position, light->power, &sum, st);
        else
            add_distributed(t, s, i, key, &sum, st);
    }
    return sum;
}

static real top_ior(const medium_stack *media)
{
    return media->count > 0 ? media->ior[media->count - 1] : 1.0;
}

static void media_push(medium_stack *media, int solid, real ior, trace_stats *st)
{
    if (media->count == MEDIUM_MAX) {
        st->medium_overflow++;
        return;
    }
    media->solid[media->count] = solid;
    media->ior[media->count++] = ior;
}

/* Leaving a solid takes it off the stack wherever it is (solids may overlap). */
static void media_remove(medium_stack *media, int solid)
{
    for (int i = media->count - 1; i >= 0; i--) {
        if (media->solid[i] != solid)
            continue;
        memmove(&media->solid[i], &media->solid[i + 1], (size_t)(media->count - 1 - i) * sizeof media->solid[0]);
        memmove(&media->ior[i], &media->ior[i + 1], (size_t)(media->count - 1 - i) * sizeof media->ior[0]);
        media->count--;
        return;
    }
}

/* The transmitted ray: straight through a sheet, bent by Snell's law into
 * or out of a solid, or mirrored on total internal reflection. */
static rgb transmitted(const tracer *t, const surface *s, const ray *in, int depth, const medium_stack *media,
                       uint64_t key, trace_stats *st)
{
    int solid = trace_solid_id(t->scene, s->h->prim);
    ray r;
    if (solid < 0) {
        st->refraction_rays++;
        r = ray_spawn_hit(s->prim, s->h, in->dir);
        return trace_ray(t, &r, depth + 1, media, key, st);
    }
    medium_stack next = *media;
    real n1, n2;
    if (s->h->entering) {
        n1 = top_ior(media);
        n2 = s->m->ior;
        media_push(&next, solid, s->m->ior, st);
    } else {
        n1 = s->m->ior;
        media_remove(&next, solid);
        n2 = top_ior(&next);
    }
    vec3 dir;
    if (shade_refract(in->dir, s->n, n1, n2, &dir)) {
        st->refraction_rays++;
        r = ray_spawn_hit(s->prim, s->h, dir);
        return trace_ray(t, &r, depth + 1, &next, key, st);
    }
    st->tir_rays++;
    r = ray_spawn_hit(s->prim, s->h, dir);
    return trace_ray(t, &r, depth + 1, media, key, st);
}

static rgb mirrored(const tracer *t, const surface *s, const ray *in, int depth, const medium_stack *media,
                    uint64_t key, trace_stats *st)
{
    ray r = ray_spawn_hit(s->prim, s->h, shade_mirror(in->dir, s->n));
    st->reflection_rays++;
    return trace_ray(t, &r, depth + 1, media, key, st);
}

static rgb shade(const tracer *t, const ray *in, const hit *h, int depth, const medium_stack *media, uint64_t key,
                 trace_stats *st)
{
    surface s;
    s.prim = &t->scene->prims[h->prim];
    s.m = &t->scene->materials[s.prim->material];
    s.h = h;
    s.v = vec_neg(in->dir);
    s.n = shade_face_forward(h->shading_normal, s.v);
    direct_sum sum = direct_light(t, &s, key, st);
    rgb mirror = vec_splat(0), through = vec_splat(0);
    if (depth < t->max_depth) {
        if (t->reflection && vec_max_component(s.m->ks) > 0)
            mirror = mirrored(t, &s, in, depth, media, sampler_key(key, 1), st);
        if (t->refraction && s.m->t > 0)
            through = transmitted(t, &s, in, depth, media, sampler_key(key, 2), st);
    }
    return shade_combine(sum.body, sum.highlight, s.m->ks, s.m->t, mirror, through);
}

/* Both branches of a glass surface recurse, so a ray tree can grow as
 * 2^max_depth: past the budget the tree stops growing and the render is
 * declared void (the caller reports it), never silently wrong or endless. */
static int over_budget(const tracer *t, trace_stats *st)
{
    if (st->tree_overflow)
        return 1;
    if (t->max_tree_rays > 0 && ++st->tree_rays > t->max_tree_rays)
        st->tree_overflow = 1;
    return st->tree_overflow;
}

rgb trace_ray(const tracer *t, const ray *r, int depth, const medium_stack *media, uint64_t key, trace_stats *st)
{
    ray nearest = *r;
    hit h;
    rgb c = t->scene->image.background;
    if (over_budget(t, st))
        return c;
    if (bvh_intersect_stats(&t->accel, t->scene->prims, &nearest, &h, &st->bvh))
        c = shade(t, &nearest, &h, depth, media, key, st);
    if (!vec_is_finite(c)) {
        st->nonfinite++;
        c = vec_splat(0);
    }
    return c;
}
