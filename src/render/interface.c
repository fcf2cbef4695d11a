/*
 * interface.c - the crossings a transmitted ray makes at once where
 * surfaces coincide (interface.h), what they do to the medium stack, and
 * where an opaque one among them ends the ray ([NUM-GLASS-3]).
 */
#include <math.h>
#include "render/interface.h"
#include "render/gather_alone.h"
#include "render/intersect.h"
#include "render/medium.h"
#include "render/shade.h"

int interface_hit_before(const hit *a, const hit *b)
{
    return a->prim != b->prim ? a->prim < b->prim : a->part < b->part;
}

real interface_hit_t(const scene_model *sc, const hit *h)
{
    return sc->materials[sc->prims[h->prim].material].t;
}

static int gather_crossing(void *ctx, const hit *h)
{
    interface *f = ctx;
    if (h->prim == f->self->prim && h->part == f->self->part && h->entering == f->self->entering)
        return 0;
    if (!(vec_max_abs(vec_sub(h->point, f->self->point)) <= f->reach))
        return 0;
    const scene_prim *p = &f->scene->prims[h->prim];
    f->through = shade_shadow_transmission(f->through, f->scene->materials[p->material].t);
    if (f->count < INTERFACE_MAX)
        f->h[f->count++] = *h;
    else
        f->solids_lost += medium_solid_id(f->scene, h->prim) >= 0;
    return 0;
}

/* Sets where the ray past f is spawned: from the crossing of largest
 * magnitude, prim's hit f->self first. */
static void interface_spawn(const tracer *t, const scene_prim *prim, real magnitude, interface *f)
{
    f->spawn_prim = prim;
    f->spawn_hit = f->self;
    f->spawn_magnitude = magnitude;
    for (int k = 1; k < f->count; k++) {
        const scene_prim *p = &t->scene->prims[f->h[k].prim];
        real m = isect_part_magnitude(p, f->h[k].part);
        if (m > f->spawn_magnitude) {
            f->spawn_prim = p;
            f->spawn_hit = &f->h[k];
            f->spawn_magnitude = m;
        }
    }
}

/*
 * [SHADE-SHORTCUT-GATHER-1] Where the gather's walk may start: no crossing
 * whose point lies within reach of the hit has t at or below
 * t_h - D, D |d|_max = 2 reach + 2^-17 (|t_h| |d|_max + |o|_max + |p|_max +
 * frame_shift) (spec/shading.md has the argument: a hit point lies within
 * 2^-20 (|t| |d|_max + |o - T|_max) of o + t d, T its frame's translation).
 * NaN or below the ray's own tmin: the ray's tmin (bvh_visit_window).
 */
static real gather_from(const tracer *t, const hit *h, const ray *r, real reach)
{
    real dm = vec_max_abs(r->dir), at = fabs(h->t);
    real spread = at * dm + vec_max_abs(r->origin) + vec_max_abs(h->point) + t->frame_shift;
    return h->t - (2 * reach + 0x1p-17 * spread) / dm;
}

/* [SHADE-SHORTCUT-GATHER-2] The walk on a primitive alone would report
 * within reach only the crossings of the hit's own part, found by the same
 * test of the same ray: they are all it gathers, and none besides h where
 * they are surely apart (then f holds h alone already). */
static void gather_self(const tracer *t, const hit *h, const ray *r, interface *f, trace_stats *st)
{
    hit out[ISECT_MAX_CROSSINGS];
    if (gather_self_apart(t, h, r, f->reach))
        return;
    int n = isect_part_all(&t->scene->prims[h->prim], h->part, r, out);
    st->bvh.prims_tested++;
    for (int i = 0; i < n; i++) {
        out[i].prim = h->prim;
        gather_crossing(f, &out[i]);
    }
}

void interface_gather(const tracer *t, const scene_prim *prim, const hit *h, real magnitude, const ray *in,
                      interface *f, trace_stats *st)
{
    /* Comparisons, not fmax calls: of these (never NaN, never -0) they
     * take the same value. */
    real m = magnitude, at = vec_max_abs(h->point);
    m = m > at ? m : at;
    ray r = *in;
    f->scene = t->scene;
    f->self = h;
    f->reach = 2 * (SPAWN_REL * m + SPAWN_ABS);
    f->through = 1;
    f->solids_lost = 0;
    f->count = 1;
    f->h[0] = *h;
    /* The crossings' t may differ from the hit's by the rounding of t itself,
     * which for a far-away origin is more than the reach: 2^-40 |t| covers it. */
    r.tmax = h->t + f->reach + 0x1p-40 * fabs(h->t);
    if (gather_alone(t, h, in, f->reach))
        gather_self(t, h, &r, f, st);
    else
        bvh_visit_window(&t->accel, t->scene->prims, &r, t->no_shortcuts ? r.tmin : gather_from(t, h, &r, f->reach),
                         gather_crossing, f, &st->bvh);
    interface_spawn(t, prim, magnitude, f);
}

/* What crossing k of the interface does to the medium stack: 1 enters its
 * solid, -1 leaves it, 0 nothing (a sheet).  A sphere or box says which by
 * its outward normal.  A closed mesh is toggled by an odd number of its
 * crossings here (on its first one; the others do nothing): entered when it
 * was not on the stack before, left when it was.  Its winding is not
 * trusted (a file may wind it inward, or inconsistently). */
static int crossing_effect(const scene_model *sc, const interface *f, const medium_stack *before, int k)
{
    int solid = medium_solid_id(sc, f->h[k].prim), odd = 0;
    if (solid < 0)
        return 0;
    if (sc->prims[f->h[k].prim].kind != PRIM_MESH)
        return f->h[k].entering ? 1 : -1;
    for (int j = 0; j < f->count; j++) {
        if (medium_solid_id(sc, f->h[j].prim) != solid)
            continue;
        if (j < k)
            return 0;
        odd ^= 1;
    }
    return !odd ? 0 : medium_find(before, solid) >= 0 ? -1 : 1;
}

int interface_cross(const tracer *t, const interface *f, const medium_stack *before, medium_stack *next,
                    trace_stats *st)
{
    const scene_model *sc = t->scene;
    /* Each crossing's solid and effect once: the effect reads f and
     * `before` alone, which the removals from `next` leave as they are. */
    int solids = 0, solid[INTERFACE_MAX], effect[INTERFACE_MAX];
    for (int k = 0; k < f->count; k++) {
        solid[k] = medium_solid_id(sc, f->h[k].prim);
        effect[k] = crossing_effect(sc, f, before, k);
        solids += solid[k] >= 0;
        if (effect[k] < 0)
            medium_remove(next, solid[k]);
    }
    for (int k = 0; k < f->count; k++)
        if (effect[k] > 0 && medium_find(next, solid[k]) < 0)
            medium_push(next, solid[k], sc->materials[sc->prims[f->h[k].prim].material].ior, st);
    return solids;
}

int interface_gap_order(const scene_model *sc, const interface *f, const medium_stack *before, int k)
{
    if (!(interface_hit_t(sc, &f->h[k]) > 0))
        return 1;
    return crossing_effect(sc, f, before, k) > 0 ? 2 : 0;
}

int interface_end(const tracer *t, interface *f, const medium_stack *before, hit *end)
{
    const scene_model *sc = t->scene;
    int stop = -1, order[INTERFACE_MAX], kept = 1;
    if (f->count == INTERFACE_MAX)
        return 0;
    for (int k = 1; k < f->count; k++) {
        order[k] = interface_gap_order(sc, f, before, k);
        if (order[k] == 1 && (stop < 0 || interface_hit_before(&f->h[k], &f->h[stop])))
            stop = k;
    }
    if (stop < 0)
        return 0;
    *end = f->h[stop];
    f->through = 1;
    for (int k = 1; k < f->count; k++)
        if (order[k] == 0) {
            f->through = shade_shadow_transmission(f->through, interface_hit_t(sc, &f->h[k]));
            f->h[kept++] = f->h[k];
        }
    f->count = kept;
    const scene_prim *self = &sc->prims[f->self->prim];
    interface_spawn(t, self, isect_part_magnitude(self, f->self->part), f);
    return 1;
}
