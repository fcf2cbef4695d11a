/*
 * glass_touch.c - [NUM-GLASS-3] glass touching an opaque surface
 * (glass_touch.h, spec/numerics.md 2.8a).
 */
#include "render/glass_touch.h"
#include "render/interface.h"
#include "render/shade.h"

static int start_crossing(void *ctx, const hit *h)
{
    start_zone *z = ctx;
    const scene_prim *p = &z->scene->prims[h->prim];
    real tc = interface_hit_t(z->scene, h);
    if (!(tc > 0) || (h->prim == z->self->prim && h->part == z->self->part))
        return 0;
    if (!(vec_max_abs(vec_sub(h->point, z->point)) <= z->reach) || (scene_prim_is_solid(p) && !h->entering))
        return 0;
    vec3 m = h->normal;
    real dm = vec_dot(z->dir, m);
    if (dm > 0) {
        m = vec_neg(m);
        dm = -dm;
    }
    /* s - offset (side.m)/(dm) > tmin, times dm < 0 */
    if ((h->t - z->back) * dm < z->tmin * dm + z->offset * vec_dot(z->side, m))
        return 0;
    z->carried = shade_shadow_transmission(z->carried, tc);
    if (z->first.prim < 0 || interface_hit_before(h, &z->first))
        z->first = *h;
    return 0;
}

void glass_start_gather(const tracer *t, const hit *h, real offset, const ray *r, start_zone *z, trace_stats *st)
{
    vec3 n = h->normal;
    z->scene = t->scene;
    z->self = h;
    z->point = h->point;
    z->side = vec_dot(vec_sub(r->origin, z->point), n) >= 0 ? n : vec_neg(n);
    z->dir = r->dir;
    z->offset = offset;
    z->tmin = r->tmin;
    z->reach = 2 * z->offset;
    z->back = 2 * z->reach;
    z->carried = 1;
    z->first.prim = -1;
    if (!(r->tmax > r->tmin))
        return;
    ray line = {vec_sub(z->point, vec_scale(z->dir, z->back)), z->dir, 0, 2 * z->back};
    bvh_visit_stats(&t->accel, t->scene->prims, &line, start_crossing, z, &st->bvh);
}

HINT_OUT_OF_LINE void glass_first_of_tie(const tracer *t, const ray *r, hit *h, const medium_stack *media,
                                      trace_stats *st)
{
    const scene_model *sc = t->scene;
    interface f;
    hit self = *h;
    const scene_prim *p = &sc->prims[h->prim];
    interface_gather(t, p, &self, isect_part_magnitude(p, h->part), r, &f, st);
    real near = h->t;
    for (int k = 1; k < f.count; k++)
        if (f.h[k].t > r->tmin && f.h[k].t < near)
            near = f.h[k].t;
    real end = bvh_tie_end(near, r->origin);
    int best = 0, best_order = interface_gap_order(sc, &f, media, 0), kinds = 1 << (best_order == 1);
    for (int k = 1; k < f.count; k++) {
        if (!(f.h[k].t > r->tmin && f.h[k].t <= end))
            continue;
        int order = interface_gap_order(sc, &f, media, k);
        kinds |= 1 << (order == 1);
        if (order < best_order || (order == best_order && interface_hit_before(&f.h[k], &f.h[best]))) {
            best = k;
            best_order = order;
        }
    }
    if (kinds == 3)
        *h = f.h[best];
}

int glass_contact_meets(const glass_contact *c, vec3 dir)
{
    return vec_dot(dir, c->side) < 0;
}
