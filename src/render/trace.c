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
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "render/intersect.h"
#include "render/ray_copy.h"
#include "render/camera.h"
#include "base/sampler.h"
#include "base/sampler_counters.h"
#include "render/gather_alone.h"
#include "render/glass_near.h"
#include "render/glass_touch.h"
#include "render/interface.h"
#include "render/medium.h"
#include "render/shade.h"
#include "render/trace.h"
#include "base/xform.h"

/* What shade() knows about the point it shades. */
typedef struct surface {
    const scene_material *m;
    const scene_prim *prim;
    const hit *h;
    const hit *shadow_from;  /* h, or a copy at the lifted point (smooth triangles) */
    real magnitude;  /* isect_part_magnitude of h's part: found once a point, for its shadow rays'
                        start, its mirror ray and its transmitted ray */
    vec3 v;          /* unit, toward where the ray came from */
    vec3 n;          /* shading normal turned toward v */
    int highlight;   /* the Phong lobe is evaluated: Ks > 0 (or no shortcuts) */
    int no_body;     /* Kd = 0: a light adds its highlight alone */
    real lobe_floor; /* V.R at or below it: the lobe is 0 ([SHADE-SHORTCUT-LOBE-2]) */
    shadow_start from; /* where its shadow rays start */
    int near_glass;  /* its shadow rays' start may touch what their walk misses ([NUM-GLASS-3]): opaque,
                        with glass within reach; glass, with a touch */
    const glass_contact *touch; /* glass met at a mirror ray's start: the opaque surface there (NULL: none) */
    int hints;       /* its shadow rays' blocker hints: trace_stats.blocker from here */
} surface;

static int light_cells_build(tracer *t, const scene_model *s);

int tracer_init(tracer *t, const scene_model *s, int max_depth, int light_samples)
{
    return tracer_build(t, s, max_depth, light_samples, NULL) == STATUS_OK;
}

/* A distributed light (rectangle, disk): samples, keys, a ball; point and
 * distant lights are one source each. */
static int light_distributed(const scene_light *light)
{
    return light->kind != LIGHT_POINT && light->kind != LIGHT_DISTANT;
}

/* The mirror direction of the view about the normal, M = 2 (N.V) N - V:
 * V.R = L.M for every light direction L ([SHADE-SHORTCUT-DARK-1]). */
static vec3 view_mirror(const surface *s)
{
    return vec_sub(vec_scale(s->n, 2 * vec_dot(s->n, s->v)), s->v);
}

int tracer_build(tracer *t, const scene_model *s, int max_depth, int light_samples, cancel_poll *cancel)
{
    memset(t, 0, sizeof *t);
    t->scene = s;
    t->max_depth = max_depth > 0 ? max_depth : s->image.max_depth;
    if (t->max_depth > SCENE_DEPTH_CEILING) /* the front doors refuse it first, with a message */
        return STATUS_USAGE;
    t->shadows = s->features.shadows;
    t->specular = s->features.specular;
    t->reflection = s->features.reflection && t->max_depth > 1;
    t->refraction = s->features.refraction && t->max_depth > 1;
    t->glass = s->features.refraction;
    t->terminator_offset = 1;
    t->bundles = 1;
    for (int i = 0; i < s->prim_count; i++)
        for (int k = 0; k < 3 && s->prims[i].frame; k++)
            t->frame_shift = fmax(t->frame_shift, fabs(s->prims[i].frame->to_world.m[k][3]));
    t->lights = mem_calloc(&s->mem, (size_t)s->light_count, sizeof *t->lights);
    t->lobe_floors = mem_calloc(&s->mem, (size_t)s->material_count, sizeof *t->lobe_floors);
    t->material_terms = mem_calloc(&s->mem, (size_t)s->material_count, sizeof *t->material_terms);
    int status = t->lights && t->lobe_floors && t->material_terms
                     ? bvh_build_polled(&t->accel, s->prims, s->prim_count, &s->mem, cancel)
                     : STATUS_NO_MEMORY;
    if (status == STATUS_OK && t->glass && (!glass_near_build(t, s) || !gather_alone_build(t, s)))
        status = STATUS_NO_MEMORY;
    if (status != STATUS_OK) {
        tracer_free(t);
        return status;
    }
    /* A cosine c_hi with c_hi^n <= 2^-1030 makes pow's result, times the
     * lobe's correction (within 2e-4 of 1 there), less than DBL_MIN: the lobe
     * flushes it to 0.  c_hi is V.R or 1 - h, which for unit V and R (|.|^2
     * within 2^-20 of 1, vunit) is at most V.R (1 + 2^-19); the factor
     * 1 - 2^-18 covers that and exp2's rounding (spec/shading.md).  A function
     * of n alone, so once a material here, not once a shaded point in shade
     * (an exp2 call a glass hit): the same double. */
    /* With it, what shade reads of a material at every point: Ks > 0 and
     * Kd = 0 (vec_max_component, Ks and Kd in [0, 1]: [LANG-MAT-1]). */
    /* [SHADE-SHORTCUT-ANY-1] needs every t to be +0: a t of -0 makes the
     * counting walk carry -0, whose bits the ray-tree hash reads. */
    t->any_walk = !t->glass;
    for (int i = 0; i < s->material_count; i++) {
        const scene_material *m = &s->materials[i];
        t->any_walk &= !signbit(m->t);
        t->lobe_floors[i] = m->n > 0 ? exp2(-1030 / m->n) * (1 - 0x1p-18) : 0;
        t->material_terms[i] = (vec_max_component(m->ks) > 0 ? TRACE_KS : 0) |
                               (vec_max_component(m->kd) > 0 ? 0 : TRACE_NO_BODY);
    }
    for (int i = 0; i < s->light_count; i++) {
        t->keyed |= light_distributed(&s->lights[i]);
        t->lights[i] = trace_light_setup(&s->lights[i], light_samples > 0 ? light_samples : s->lights[i].samples);
    }
    if (!light_cells_build(t, s)) {
        tracer_free(t);
        return STATUS_NO_MEMORY;
    }
    t->camera_half = camera_half(&s->camera);
    if (s->camera.kind == CAMERA_PERSPECTIVE) {
        trace_stats none;
        memset(&none, 0, sizeof none);
        trace_media_at(t, s->camera.eye, &t->eye_media, &none);
        t->eye_overflow = none.medium_overflow;
    }
    return STATUS_OK;
}

void tracer_no_shortcuts(tracer *t)
{
    t->no_shortcuts = 1;
    t->shadows = t->specular = t->reflection = t->refraction = 1;
    t->accel.exhaustive = 1;
    t->bundles = 0;
    t->glass_boxes = -1;
    if (t->scene->camera.kind == CAMERA_PERSPECTIVE) {
        trace_stats none;
        memset(&none, 0, sizeof none);
        trace_media_at(t, t->scene->camera.eye, &t->eye_media, &none);
    }
}

void tracer_free(tracer *t)
{
    bvh_free(&t->accel);
    if (t->scene) {
        mem_free(&t->scene->mem, t->lights, (size_t)t->scene->light_count * sizeof *t->lights);
        mem_free(&t->scene->mem, t->cells, (size_t)t->cell_count * sizeof *t->cells);
        mem_free(&t->scene->mem, t->lobe_floors, (size_t)t->scene->material_count * sizeof *t->lobe_floors);
        mem_free(&t->scene->mem, t->material_terms, (size_t)t->scene->material_count * sizeof *t->material_terms);
        glass_near_free(t);
        gather_alone_free(t);
    }
    t->lights = NULL;
    t->cells = NULL;
    t->cell_count = 0;
    t->lobe_floors = NULL;
    t->material_terms = NULL;
}

/* Folds v into st->path (FNV-1a over 64-bit words) when the caller asked
 * for the hash (st->record_path); a render does not, and pays one test. */
static void path_note(trace_stats *st, uint64_t v)
{
    if (st->record_path)
        st->path = (st->path ^ v) * 0x100000001b3u;
}

static uint64_t bits_of(real x)
{
    double d = (double)x;
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}

/* Which piece of a primitive made of pieces a hit is on: a box's face (its
 * normal, constant over it), a cylinder's or cone's cap or side (a cap's
 * normal is the axis), a mesh's triangle; 0 for the others. */
static uint64_t piece_of(const scene_prim *p, const hit *h)
{
    if (p->kind == PRIM_MESH)
        return (uint64_t)h->part;
    if (p->kind == PRIM_BOX)
        return bits_of(h->normal.x) ^ bits_of(h->normal.y) << 1 ^ bits_of(h->normal.z) << 2;
    if (p->kind != PRIM_CYLINDER && p->kind != PRIM_CONE)
        return 0;
    vec3 a = p->kind == PRIM_CYLINDER ? vec_sub(p->u.cylinder.to, p->u.cylinder.from)
                                      : vec_sub(p->u.cone.to, p->u.cone.from);
    real c = vec_dot(h->normal, vec_normalize(p->frame ? xform_vector(&p->frame->to_world, a) : a));
    return c > 1 - 1e-9 ? 1 : c < -(1 - 1e-9) ? 2 : 3;
}

typedef struct shadow_walk {
    const scene_model *scene;
    real carried;
    int walk_on;     /* no stop at 0: the shortcuts-off mode */
    bvh_ref opaque;  /* the opaque part the walk stopped at (prim -1: none) */
} shadow_walk;

/* Slide 47: every surface on the way lets through its t (opaque: 0).
 * [SHADE-SHORTCUT-STOP-1] Once 0 is carried the product stays 0, so the
 * walk stops there. */
static int shadow_crossing(void *ctx, bvh_ref ref, int crossings)
{
    shadow_walk *w = ctx;
    const scene_material *m = &w->scene->materials[w->scene->prims[ref.prim].material];
    for (int i = 0; i < crossings; i++) {
        w->carried = shade_shadow_transmission(w->carried, m->t);
        if (w->carried == 0 && !w->walk_on)
            break;
    }
    if (m->t == 0)
        w->opaque = ref;
    return w->carried == 0 && !w->walk_on;
}

/*
 * The walk of a shadow ray from the root (no bundle).
 * [SHADE-SHORTCUT-ANY-1] With every material opaque (every t +0:
 * t->any_walk) and the shortcuts on, shadow_crossing carries +0 from the
 * first crossing on and stops there, so the walk's answer is 0 where r crosses some part and 1
 * where it crosses none, whatever the order of its tests: the
 * any-crossing walk (bvh_any_crossing, nearer the light first) gives it,
 * with an opaque part it crossed as the blocker.  Out of line: in
 * shadow_transmission the branch cost demo.scene's bundle path 0.5 % more
 * instructions.
 */
static HINT_OUT_OF_LINE void shadow_from_root(const tracer *t, const ray *r, shadow_walk *w, trace_stats *st)
{
    if (!t->any_walk || t->no_shortcuts) {
        bvh_visit_counts(&t->accel, t->scene->prims, r, shadow_crossing, w, &st->bvh);
        return;
    }
    if (bvh_any_crossing(&t->accel, t->scene->prims, r, &w->opaque, &st->bvh))
        w->carried = shade_shadow_transmission(w->carried, 0);
}

/*
 * The fraction of light `light` that reaches the surface along r.
 * [SHADE-SHORTCUT-BLOCKER-1] Neighbouring shadow rays toward one light
 * (the samples of an area light from one point, the rays of the next
 * pixel) are mostly stopped by the same opaque surface, so the one that
 * stopped the last is tested first: when r crosses it (the walk's own
 * test, on the same interval) the walk would report that crossing too and
 * carry 0 whatever else it met, so 0 is the answer without the walk.  Off
 * in the shortcuts-off mode.
 */
static real shadow_transmission(const tracer *t, const ray *r, int light, int hints, const bvh_bundle *bundle,
                                trace_stats *st)
{
    shadow_walk w = {t->scene, 1.0, t->no_shortcuts, {-1, 0}};
    bvh_ref *slot = &st->blocker[hints + light % TRACE_BLOCKERS];
    int hint = slot->prim - 1;
    st->shadow_rays++;
    if (bundle && bundle->count == 0 && bundle->crosses_nothing) {
        /* [SHADE-SHORTCUT-PLANE-1] The hint's test and the walk would
         * cross nothing: the walk's 1, the slot as it leaves it. */
        slot->prim = 0;
        return 1;
    }
    if (hint >= 0 && hint < t->scene->prim_count && slot->part >= 0 &&
        slot->part < isect_part_count(&t->scene->prims[hint]) && !t->no_shortcuts) {
        st->bvh.prims_tested++;
        if (isect_part_crossed(&t->scene->prims[hint], slot->part, r))
            return 0;
    }
    if (bundle && bundle->count >= 0)
        bvh_visit_counts_bundle(&t->accel, t->scene->prims, r, bundle, shadow_crossing, &w, &st->bvh);
    else
        shadow_from_root(t, r, &w, st);
    if (w.carried == 0 && w.opaque.prim >= 0) {
        slot->prim = w.opaque.prim + 1;
        slot->part = w.opaque.part;
    } else {
        slot->prim = 0;
    }
    return w.carried;
}

/* [NUM-GLASS-3] What the surfaces at the start of the shadow ray toward l
 * from s let through that its walk misses: at an opaque point the
 * transparent ones there (glass_start_gather), at a glass point the opaque
 * surface it touches (s->touch), 0 toward it. */
static real start_transmission(const tracer *t, const surface *s, const ray *shadow, vec3 l, trace_stats *st)
{
    if (s->touch)
        return glass_contact_meets(s->touch, l) ? 0 : 1;
    start_zone z;
    glass_start_gather(t, s->shadow_from, s->from.offset, shadow, &z, st);
    return z.carried;
}

typedef struct direct_sum {
    rgb body;        /* diffuse, before the (1 - t) weight */
    rgb highlight;
} direct_sum;

/*
 * The side of the point's normal n every sample of the light lies on, as
 * spawn_origin sees it (the sign of vec_dot(q - P, n), each rounded): 1
 * (>= 0 for every sample), -1 (< 0 for every one), 0 (not known).  Over
 * the light's box [L, H] the least value of (q - P).n is
 * sum_a n_a ((n_a >= 0 ? L_a : H_a) - P_a), the greatest the other
 * corner's.  Every |q_a - P_a| is at most S = the sum of the magnitudes of
 * P, L and H, so the rounding of q - P and of the dot product moves
 * spawn_origin's value by at most 4 eps N S (N = |n_x| + |n_y| + |n_z|),
 * and the rounding of this bound by as much: a bound past 2^-40 N S +
 * 2^-1000 decides (the term covers subnormal rounding).  |n|^2 >= 1/2 (a
 * unit normal) makes vec_dot(-n, n) < 0, so ray_shadow_origin(-n) gives
 * the origin of the -1 side.  Magnitudes past 2^400: 0.
 */
int trace_light_side(const shadow_start *from, const light_setup *setup)
{
    vec3 p = from->point, n = from->normal, lo = setup->box_lo, hi = setup->box_hi;
    real size = vec_sum_abs(p) + vec_sum_abs(lo) + vec_sum_abs(hi), nsum = vec_sum_abs(n);
    if (!(size < 0x1p400 && nsum < 16 && vec_length2(n) >= 0.5))
        return 0;
    const real pa[3] = {p.x, p.y, p.z}, na[3] = {n.x, n.y, n.z};
    const real la[3] = {lo.x, lo.y, lo.z}, ha[3] = {hi.x, hi.y, hi.z};
    real least = 0, most = 0, tol = 0x1p-40 * nsum * size + 0x1p-1000;
    for (int a = 0; a < 3; a++) {
        least += na[a] * ((na[a] >= 0 ? la[a] : ha[a]) - pa[a]);
        most += na[a] * ((na[a] >= 0 ? ha[a] : la[a]) - pa[a]);
    }
    return least > tol ? 1 : most < -tol ? -1 : 0;
}

/*
 * [SHADE-SHORTCUT-BUNDLE-1] The nodes of the tree the shadow rays from this
 * point toward a distributed light may reach, made at its first shadow ray
 * (bvh_bundle_make): each ray starts at one of the two origins spawn_origin
 * makes, within offset * max |n_a| <= offset (|n_x| + |n_y| + |n_z|) of
 * the point (at exactly one of them where trace_light_side names its
 * side), and is aimed at a sample inside the light's box (light_box).
 */
static const bvh_bundle *light_bundle(const tracer *t, const surface *s, const scene_light *light,
                                      bvh_bundle *bundle, trace_stats *st)
{
    if (bundle && bundle->count == BVH_BUNDLE_UNMADE) {
        const light_setup *setup = &t->lights[light - t->scene->lights];
        vec3 n = s->from.normal;
        bvh_bundle_rays rays;
        rays.apex = s->from.point;
        rays.slack = s->from.offset * vec_sum_abs(n);
        rays.lo = setup->reach >= 0 ? setup->box_lo : vec_splat(1);
        rays.hi = setup->reach >= 0 ? setup->box_hi : vec_splat(-1);   /* lo > hi: no bundle */
        rays.exact = 0;
        int side = setup->reach >= 0 ? trace_light_side(&s->from, setup) : 0;
        if (side != 0) {
            rays.exact = 1;
            rays.origin = ray_shadow_origin(&s->from, side > 0 ? n : vec_neg(n));
        }
        bvh_bundle_make(&t->accel, &rays, bundle, &st->bvh);
        bvh_bundle_planes(&t->accel, t->scene->prims, &rays, bundle);
    }
    return bundle;
}

/*
 * [SHADE-SHORTCUT-ABSORB-1] The lobe is pow(c_hi, n) with c_hi <= c (1 +
 * 2^-19) <= 1, times pow's ulp and the correction exp(n c_lo / c_hi)
 * (within 2^-32 of 1 for n < 2^20): at most c_hi^n (1 + 2^-31).  With x
 * = 1 - c, ln c = -(x + x^2/2 + x^3/3 + ...) <= -S, S = x + x^2/2 + x^3/3,
 * and ln c_hi <= ln c + 2^-19, so the lobe is at most 2^-(w log2(e) -
 * 2^-30), w = n S - n 2^-19.  z is below that exponent: log2(e) and 1/3
 * taken low, the factor 1 - 2^-40 more than the roundings of x (none for
 * c >= 1/2), S and the products, n 2^-18 more than n 2^-19 log2(e) +
 * 2^-30; so 2^-floor(z) bounds the lobe.  Past 2^-1000 the lobe is below
 * DBL_MIN, flushed to 0.  No pow, no loop.
 */
real trace_lobe_above(real c, real n)
{
    if (!(c > 0))
        return 0;   /* shade_phong_lobe's own 0 */
    if (!(c < 1 && n >= 1 && n < 0x1p20))
        return 1;
    real x = 1 - c, sum = x * (1 + x * (0.5 + x * 0.33333333333333));
    real z = n * sum * 1.44269504088896 * (1 - 0x1p-40) - n * 0x1p-18;
    if (!(z >= 1))
        return 1;
    uint64_t bits = (uint64_t)(1023 - (z < 1000 ? (int)z : 1000)) << 52;   /* 2^-floor(z), a normal double */
    double b;   /* double, not real: the bits are a double's (real is long double in the ld build) */
    memcpy(&b, &bits, sizeof b);
    return b;
}

/* A source's intensity at distance d before its shadow: a distant light's
 * power, a point source's through the falloff (a pure function: made
 * before or after the shadow ray, the same bits). */
static rgb source_intensity(const scene_light *light, const rgb *emits, real d)
{
    return light->kind == LIGHT_DISTANT ? *emits : shade_falloff(*emits, d, light->d0, light->falloff);
}

static int sum_has_highlight(const direct_sum *sum)
{
    return sum->highlight.x != 0 || sum->highlight.y != 0 || sum->highlight.z != 0;
}

/*
 * [SHADE-SHORTCUT-ABSORB-1] Whether a Kd = 0 sample's highlight, Ks I
 * lobe with I the unshadowed *intensity times the transmission (in [0, 1])
 * and lobe <= trace_lobe_above, surely leaves the running sum's bits as they
 * are: sum + U rounds to sum for U = Ks I trace_lobe_above, so sum + t does for
 * every t in [0, U] (rounding is monotone, and each product the term is
 * made of is at most its counterpart in U).
 */
static int highlight_absorbed(const surface *s, const rgb *intensity, real c, const direct_sum *sum)
{
    rgb u = vec_scale(vec_mul(s->m->ks, *intensity), trace_lobe_above(c, s->m->n));
    rgb a = vec_add(sum->highlight, u);
    return a.x == sum->highlight.x && a.y == sum->highlight.y && a.z == sum->highlight.z;
}

/* One point source at *at (distant: at infinity along -direction) of power
 * *emits; bundle: the distributed light's (NULL for the others).  The point
 * and power by address: by value they were six doubles copied onto the
 * stack a sample. */
static void add_source(const tracer *t, const surface *s, const scene_light *light, const vec3 *at, const rgb *emits,
                       bvh_bundle *bundle, direct_sum *sum, trace_stats *st)
{
    vec3 l;
    real d = HUGE_VAL;
    st->light_samples++;
    if (light->kind == LIGHT_DISTANT) {
        l = vec_neg(light->direction);
    } else {
        vec3 to = vec_sub(*at, s->h->point);
        d = vec_length_fast(to);
        if (!(d > 0)) {
            st->lights_on_surface++;
            return;
        }
        /* Defensive: 1/d overflows for d below 2^-1024 (a light 1e-310 from
         * the point), and to * Inf is no direction (shade_direct's L must be
         * finite); to / d is, as |to_i| <= d. */
        real inv = 1.0 / d;
        l = inv <= REAL_MAX ? vec_scale(to, inv) : vec_make(to.x / d, to.y / d, to.z / d);
    }
    int lit = vec_dot(s->n, l) > 0;
    path_note(st, (uint64_t)lit + 1);
    /* [SHADE-SHORTCUT-GATE-1] Where N.L <= 0 both terms are 0: no shadow ray. */
    if (!lit && !t->no_shortcuts)
        return;
    /* [SHADE-SHORTCUT-LOBE-2] Where Kd = 0 a light adds its highlight alone,
     * Ks I lobe: a sample whose lobe is surely 0 (V.R, formed as
     * shade_phong_lobe forms it, at or below lobe_floor) adds +0 whatever
     * its shadow ray would find, so it sends none. */
    rgb intensity = vec_splat(0);
    int intensity_made = 0;
    if (s->no_body && !t->no_shortcuts) {
        real c = s->highlight ? vec_dot(s->v, shade_reflect_about(l, s->n)) : 0;
        if (!s->highlight || c <= s->lobe_floor)
            return;
        /* [SHADE-SHORTCUT-ABSORB-1] A highlight too small to change the
         * sum's bits, however lit: no shadow ray.  The falloff is made
         * here, once; the same pure function as below. */
        if (!st->record_path && sum_has_highlight(sum)) {
            intensity = source_intensity(light, emits, d);
            intensity_made = 1;
            if (highlight_absorbed(s, &intensity, c, sum)) {
                st->absorbed++;
                return;
            }
        }
    }
    /* The shadow ray first: a blocked sample needs no falloff (a pure
     * function, so computing it after changes no bit). */
    real through = 1;
    if (t->shadows) {
        /* Assigned in each branch, not from a conditional expression: that
         * made the ray in a temporary and copied it with 16-byte loads
         * straddling its 8-byte stores (store forwarding failed, about 4 %
         * of mesh.scene's time). */
        ray r;
        if (light->kind == LIGHT_DISTANT)
            r = ray_shadow_along_sized(&s->from, l, t->lights[light - t->scene->lights].along_length);
        else
            r = ray_shadow_to(&s->from, *at);
        through = shadow_transmission(t, &r, (int)(light - t->scene->lights), s->hints,
                                      light_bundle(t, s, light, bundle, st), st);
        if (through > 0 && s->near_glass)
            through = shade_shadow_transmission(through, start_transmission(t, s, &r, l, st));
        path_note(st, bits_of(through));
        if (through == 0 && !t->no_shortcuts)
            return;
    }
    if (!intensity_made)
        intensity = source_intensity(light, emits, d);
    if (t->shadows)
        intensity = vec_scale(intensity, through);
    if (s->highlight) {
        shade_terms terms = shade_direct(s->m->kd, s->m->ks, s->m->n, intensity, s->n, l, s->v);
        sum->body = shade_saturate(vec_add(sum->body, terms.body));
        sum->highlight = shade_saturate(vec_add(sum->highlight, terms.highlight));
    } else {
        sum->body = shade_saturate(vec_add(sum->body, shade_diffuse(s->m->kd, intensity, s->n, l)));
    }
}

/*
 * The box of light_ball's samples, axis by axis ([SHADE-SHORTCUT-BUNDLE-1]).
 * A rectangle's point is position + (s edge_u + t edge_v), s, t in [0, 1),
 * so its coordinate a lies between position_a plus the negative parts of
 * the edges' and position_a plus their positive parts; a disk's is
 * position_a + t1_a (x r) + t2_a (y r) with x^2 + y^2 <= 1 (a few ulps
 * more), within r (|t1_a| + |t2_a|) of position_a, and within the ball's
 * r sqrt(spread) (light_ball: spread_root is its sqrt(spread)) too.  The
 * rounding of the point (a few ulps of size) and of these bounds is
 * covered as the ball's is: the factor 2^-30 of the half-width and the
 * term 2^-40 4 size.  Called with size < 2^400, a finite ball.
 */
static void light_box(const scene_light *light, light_setup *setup, real size, real spread_root)
{
    real lo[3], hi[3];
    const real p[3] = {light->position.x, light->position.y, light->position.z};
    if (light->kind == LIGHT_RECTANGLE) {
        const real u[3] = {light->edge_u.x, light->edge_u.y, light->edge_u.z};
        const real v[3] = {light->edge_v.x, light->edge_v.y, light->edge_v.z};
        for (int a = 0; a < 3; a++) {
            real below = (u[a] < 0 ? u[a] : 0) + (v[a] < 0 ? v[a] : 0);
            real above = (u[a] > 0 ? u[a] : 0) + (v[a] > 0 ? v[a] : 0);
            real pad = 0x1p-30 * (above - below) + 0x1p-40 * 4 * size;
            lo[a] = (p[a] + below) - pad;
            hi[a] = (p[a] + above) + pad;
        }
    } else {
        const real t1[3] = {setup->t1.x, setup->t1.y, setup->t1.z}, t2[3] = {setup->t2.x, setup->t2.y, setup->t2.z};
        for (int a = 0; a < 3; a++) {
            real w = fabs(t1[a]) + fabs(t2[a]);
            w = light->radius * (w < spread_root ? w : spread_root);
            real pad = 0x1p-30 * w + 0x1p-40 * 4 * size;
            lo[a] = (p[a] - w) - pad;
            hi[a] = (p[a] + w) + pad;
        }
    }
    setup->box_lo = vec_make(lo[0], lo[1], lo[2]);
    setup->box_hi = vec_make(hi[0], hi[1], hi[2]);
}

/* A disk's frame spread: |t1 x + t2 y| <= |(x, y)| disk_spread_root
 * (light_ball), and the magnitude of its coordinates, the size its
 * rounding terms scale with. */
static real disk_spread_root(const light_setup *setup)
{
    real t11 = vec_length2(setup->t1), t22 = vec_length2(setup->t2);
    return sqrt((t11 > t22 ? t11 : t22) + fabs(vec_dot(setup->t1, setup->t2)));
}

static real disk_size(const scene_light *light)
{
    return vec_max_abs(light->position) + light->radius;
}

/*
 * [SHADE-SHORTCUT-DARK-1] The ball around a distributed light that holds
 * every point light_point returns.  A disk's point is position + t1 (x r) +
 * t2 (y r) with x^2 + y^2 <= 1 (+ a few ulps: r cos, r sin of libm), so
 * |t1 x + t2 y|^2 <= (x^2 + y^2) (max(|t1|^2, |t2|^2) + |t1.t2|) (from
 * 2|xy| <= x^2 + y^2); a rectangle's point is within half its longer
 * diagonal of its centre.  The factor 1 + 2^-30 and the term 2^-40 of the
 * coordinates' size cover the rounding of the bound and of the point (a
 * few ulps each).  Coordinates past 2^400: no ball (reach -1).
 */
static void light_ball(const scene_light *light, light_setup *setup)
{
    real size, spread_root = 0;
    setup->reach = -1;
    if (light->kind == LIGHT_DISK) {
        spread_root = disk_spread_root(setup);
        size = disk_size(light);
        setup->centre = light->position;
        setup->reach = light->radius * spread_root;
    } else if (light->kind == LIGHT_RECTANGLE) {
        vec3 across = vec_add(light->edge_u, light->edge_v), along = vec_sub(light->edge_u, light->edge_v);
        /* The scaled length: a squared length below 2^-1022 is subnormal
         * and its square root off by up to 2^-13 of itself. */
        real a = vec_length(across), b = vec_length(along);
        size = vec_max_abs(light->position) + vec_max_abs(light->edge_u) + vec_max_abs(light->edge_v);
        setup->centre = vec_add(light->position, vec_scale(across, 0.5));
        setup->reach = 0.5 * (a > b ? a : b);
    } else {
        return;
    }
    setup->reach = setup->reach * (1 + 0x1p-30) + 0x1p-40 * 4 * size;
    if (!(size < 0x1p400 && setup->reach < 0x1p400))
        setup->reach = -1;
    else
        light_box(light, setup, size, spread_root);
}

/* [SHADE-SHORTCUT-DARK-2] What light_cell_dark needs of a shaded point,
 * made by light_dark where the whole light is not dark: its gap and
 * dist + reach bound |p - P| for every sample point p (all in the light's
 * ball), a cell's ball bounds w.(p - P). */
typedef struct light_view {
    int some;             /* a cell may be dark: the rest is made */
    vec3 m;               /* M = 2(N.V)N - V (lobe only) */
    real n_at, n_u, n_v;  /* N.(position - P), N.t1, N.t2 */
    real m_at, m_u, m_v;  /* the same of M (lobe only) */
    real n_len, n_lim;    /* |N|; the N.L test's bound */
    real m_len, m_lim;    /* |M|; the lobe test's bound */
    int lobe;             /* Kd = 0 with a highlight: the lobe gate too */
} light_view;

/*
 * [SHADE-SHORTCUT-DARK-1] Whether every sample of a distributed light is
 * surely skipped at this point by add_source's own gates: N.L <= 0
 * ([SHADE-SHORTCUT-GATE-1]) for every sample, or, where Kd = 0, V.R <=
 * lobe_floor ([SHADE-SHORTCUT-LOBE-2]) for every sample.  A sample L is
 * (p - P)/|p - P| with p in the light's ball (centre C, reach R), and
 * V.R = L.M exactly for M = 2(N.V)N - V; so with D = C - P, for a fixed
 * w (N or M), w.L <= (D.w + R|w|) / |p - P|, |p - P| in [|D| - R,
 * |D| + R].  The sample's own rounding (its L from p - P, the dot
 * products) moves its w.L by less than 2^-32: p - P is off by a few ulps
 * of the coordinates' size, at most 2^-16 of |p - P| >= |D| - R, and
 * |D| - R >= 2^-400 keeps |p - P|^2, of which add_source takes the square
 * root, out of the subnormal range (where it has as few as 2^-13 of
 * relative precision: a scene 1e-160 across lost highlight pixels to this
 * shortcut before, test_shortcuts_dark_light_subnormal_distance).  The
 * margin E = 2^-20 covers it, and the rounding of this bound (|D| from the
 * scaled length) many times over.  Where it returns 0, v->some says whether
 * a grid cell may still be dark (the ball's least w.(p - P) within a
 * bound), and then v holds N's and M's bounds for the cells; v comes
 * zeroed (add_distributed's), so a field left unset reads 0.
 */
static int light_dark(const surface *s, const light_setup *setup, light_view *v)
{
    const real e = 0x1p-20;
    vec3 p = s->h->point;
    real size = vec_max_abs(p) + vec_max_abs(setup->centre) + setup->reach;
    if (!(setup->reach >= 0 && size < 0x1p400))
        return 0;
    vec3 d = vec_sub(setup->centre, p);
    real dist = vec_length(d), gap = dist - setup->reach;
    if (!(gap >= 0x1p-16 * size && gap >= 0x1p-400))
        return 0;
    real dn = vec_dot(d, s->n), spread = setup->reach * sqrt(vec_length2(s->n)), lim = -e * (dist + setup->reach);
    if (dn + spread <= lim)
        return 1;
    v->n_len = sqrt(vec_length2(s->n));
    v->n_lim = lim;
    v->some = dn - spread <= lim;
    if (!s->no_body)
        return 0;
    if (!s->highlight)
        return 1;
    vec3 m = view_mirror(s);
    real dm = vec_dot(d, m), m_spread = setup->reach * sqrt(vec_length2(m)), floor = s->lobe_floor - e;
    real m_lim = floor * (floor >= 0 ? gap : dist + setup->reach);
    if (dm + m_spread <= m_lim)
        return 1;
    v->lobe = 1;
    v->m = m;
    v->m_len = sqrt(vec_length2(m));
    v->m_lim = m_lim;
    v->some |= dm - m_spread <= m_lim;
    return 0;
}

/*
 * [SHADE-SHORTCUT-DARK-2] The rest of light_cell_dark's view, where some
 * cell may be dark (v->some): the dot products of N (and M) with the
 * light's position and frame, once a point.
 */
static void light_view_fill(const surface *s, const scene_light *light, const light_setup *setup, light_view *v)
{
    vec3 at = vec_sub(light->position, s->h->point);
    v->n_at = vec_dot(at, s->n);
    v->n_u = vec_dot(setup->t1, s->n);
    v->n_v = vec_dot(setup->t2, s->n);
    v->m_at = v->m_u = v->m_v = 0;
    if (v->lobe) {
        v->m_at = vec_dot(at, v->m);
        v->m_u = vec_dot(setup->t1, v->m);
        v->m_v = vec_dot(setup->t2, v->m);
    }
}

/* Whether every point within reach of the cell's centre (and in the
 * light's ball) is surely skipped by add_source's N.L or lobe gate at v's
 * point: w.(C - P) formed as w.(position - P) + u w.t1 + v w.t2. */
static int light_cell_dark(const light_view *v, light_cell c, real reach)
{
    if (v->n_at + c.u * v->n_u + c.v * v->n_v + reach * v->n_len <= v->n_lim)
        return 1;
    return v->lobe && v->m_at + c.u * v->m_u + c.v * v->m_v + reach * v->m_len <= v->m_lim;
}

/*
 * [SHADE-SHORTCUT-DARK-2] The centre of each sample's grid cell on a disk
 * light (light_point of the cell's middle) and one reach for all: the
 * concentric map is 1.5-Lipschitz (spec/shading.md), a cell's (a, b) lie
 * within sqrt(1/cols^2 + 1/rows^2) of its middle, and |t1 x + t2 y| <=
 * |(x, y)| spread_root as in light_ball; the factor 1 + 2^-30 and the term
 * 2^-40 4 size cover the rounding as there.  Only a disk with a ball
 * (reach >= 0) and at least 4 samples; TRACE_CELLS_MAX centres in all.
 */
static int light_cells_wanted(const scene_light *light, const light_setup *setup)
{
    return light->kind == LIGHT_DISK && setup->reach >= 0 && setup->samples >= 4 &&
           setup->samples <= TRACE_CELLS_MAX;
}

static void light_cells_fill(const scene_light *light, light_setup *setup, light_cell *cells)
{
    light_grid g = setup->grid;
    real spread_root = disk_spread_root(setup), size = disk_size(light);
    real half = sqrt(1.0 / ((real)g.cols * g.cols) + 1.0 / ((real)g.rows * g.rows));
    for (int j = 0; j < setup->samples; j++) {
        double a, b;
        light_cell_point(g, j, 0.5, 0.5, &a, &b);
        double x, y;
        light_concentric(a, b, &x, &y);
        cells[j].u = x * light->radius;
        cells[j].v = y * light->radius;
    }
    setup->cells = cells;
    setup->cell_reach = light->radius * (1.5 * half) * spread_root * (1 + 0x1p-30) + 0x1p-40 * 4 * size;
}

/* 0: out of memory. */
static int light_cells_build(tracer *t, const scene_model *s)
{
    int total = 0;
    for (int i = 0; i < s->light_count; i++)
        if (light_cells_wanted(&s->lights[i], &t->lights[i]) && total + t->lights[i].samples <= TRACE_CELLS_MAX)
            total += t->lights[i].samples;
    if (total == 0)
        return 1;
    t->cells = mem_calloc(&s->mem, (size_t)total, sizeof *t->cells);
    if (!t->cells)
        return 0;
    t->cell_count = total;
    int at = 0;
    for (int i = 0; i < s->light_count; i++)
        if (light_cells_wanted(&s->lights[i], &t->lights[i]) && at + t->lights[i].samples <= total) {
            light_cells_fill(&s->lights[i], &t->lights[i], t->cells + at);
            at += t->lights[i].samples;
        }
    return 1;
}

light_setup trace_light_setup(const scene_light *light, int samples)
{
    light_setup setup;
    memset(&setup, 0, sizeof setup);
    setup.samples = samples;
    if (light->kind == LIGHT_RECTANGLE || light->kind == LIGHT_DISK) {
        setup.grid = light_grid_for(samples);
        setup.power = shade_sample_power(light->power, samples);
    }
    if (light->kind == LIGHT_DISK)
        light_frame(light->normal, &setup.t1, &setup.t2);
    if (light->kind == LIGHT_DISTANT)
        setup.along_length = vec_length(vec_neg(light->direction));
    light_ball(light, &setup);
    return setup;
}

/* Sample j of a light whose key at this hit is light_key:
 * sampler_key(key, TRACE_KEY_LIGHT + index), the same for every sample.
 * Flattened (light_point inlined: it was a call a sample, t1 and t2 passed
 * by value) and kept out of add_source's loop; only inlining, the same
 * operations. */
HINT_FLATTEN HINT_OUT_OF_LINE static vec3 light_point_keyed(const scene_light *light, const light_setup *setup,
                                                  uint64_t light_key, int j)
{
    uint64_t c1, c2;   /* sampler_mix of the counters 2j, 2j + 1: sampler_key's own */
    if (j < SAMPLER_MIXED_COUNTERS / 2) {
        c1 = sampler_mixed_counter[2 * j];
        c2 = sampler_mixed_counter[2 * j + 1];
    } else {
        c1 = sampler_mix(2 * (uint64_t)j);
        c2 = sampler_mix(2 * (uint64_t)j + 1);
    }
    double u1 = sampler_uniform(sampler_key_mixed(light_key, c1));
    double u2 = sampler_uniform(sampler_key_mixed(light_key, c2));
    double a, b;   /* the sample's place in the light's unit square: model data, double */
    light_cell_point(setup->grid, j, u1, u2, &a, &b);
    return light_point(light, setup->t1, setup->t2, a, b);
}

vec3 trace_light_point(const scene_light *light, const light_setup *setup, int index, uint64_t key, int j)
{
    return light_point_keyed(light, setup, sampler_key(key, TRACE_KEY_LIGHT + (uint64_t)index), j);
}

/* A batch of light points: 64 (demo and cornell take 64 samples, room 49, mesh
 * 36) is 1.5 KB of add_distributed's frame, which the recursion does not hold
 * (direct_light is out of line). */
enum { LIGHT_POINT_BATCH = 64 };

/* The samples of a distributed light, each a point source of E/samples. */
static void add_distributed(const tracer *t, const surface *s, int index, uint64_t key, direct_sum *sum,
                            trace_stats *st)
{
    const scene_light *light = &t->scene->lights[index];
    const light_setup *setup = &t->lights[index];
    uint64_t light_key = sampler_key(key, TRACE_KEY_LIGHT + (uint64_t)index);
    /* [SHADE-SHORTCUT-DARK-1] Every sample would add nothing and send no
     * shadow ray: none is made.  The ray-tree hash notes each sample's side
     * of the light, so it takes them one by one. */
    /* Zeroed whole, once: light_dark sets only what it finds (and is not
     * called with the shortcuts off), and gcc at -O1 and -Os cannot see
     * that the rest is read only where it set some (maybe-uninitialized
     * under -Werror). */
    light_view view = {0};
    if (!t->no_shortcuts && !st->record_path && light_dark(s, setup, &view)) {
        st->light_samples += setup->samples;
        st->dark_lights++;
        cancel_steps(st->cancel, setup->samples);
        return;
    }
    bvh_bundle bundle;
    bundle.count = t->bundles ? BVH_BUNDLE_UNMADE : -1;
    /* The points first, LIGHT_POINT_BATCH at a time, then their samples.
     * A disk's point calls libm's sincos, which saves the rounding mode
     * (stmxcsr); made between two samples' shadow walks, a third of sincos's
     * time (perf annotate, about 3.5 % of mesh.scene's) sat just after it,
     * waiting, as it seems, for the walk before it.  Back to back they wait
     * only for each other.  light_point_keyed is a pure function of
     * (light, setup, key, j): the same points, added in the same order, and
     * cancel_step is asked before each sample as before; a cancelled batch
     * made points it does not use. */
    /* [SHADE-SHORTCUT-DARK-2] A sample whose cell is dark is skipped by
     * add_source's gates wherever in the cell it lies: no point is made
     * for it, and it counts as add_source counts it. */
    int by_cell = view.some && setup->cells;
    if (by_cell)
        light_view_fill(s, light, setup, &view);
    vec3 points[LIGHT_POINT_BATCH];
    for (int j0 = 0; j0 < setup->samples; j0 += LIGHT_POINT_BATCH) {
        int n = setup->samples - j0 < LIGHT_POINT_BATCH ? setup->samples - j0 : LIGHT_POINT_BATCH;
        uint64_t dark = 0;   /* bit k: sample j0 + k's cell is dark (LIGHT_POINT_BATCH = 64 bits) */
        for (int k = 0; by_cell && k < n; k++)
            dark |= (uint64_t)light_cell_dark(&view, setup->cells[j0 + k], setup->cell_reach) << k;
        for (int k = 0; k < n; k++)
            if (!(dark >> k & 1))
                points[k] = light_point_keyed(light, setup, light_key, j0 + k);
        for (int k = 0; k < n; k++) {
            if (cancel_step(st->cancel))
                return;
            if (dark >> k & 1) {
                st->light_samples++;
                st->dark_cells++;
            } else
                add_source(t, s, light, &points[k], &setup->power, &bundle, sum, st);
        }
    }
}

/* Out of line ([REL-STACK-1]): the light loop's bundle (its node list) and
 * samples are done with before the mirrored and transmitted rays recurse,
 * so they stay off the recursion's frame.  The sum by address, added to in
 * place: returned by value it was copied in 16-byte blocks straddling
 * add_source's 16 + 8-byte stores of each colour (a failed store
 * forwarding at every shaded point). */
static HINT_OUT_OF_LINE void direct_light(const tracer *t, const surface *s, uint64_t key, direct_sum *sum,
                                       trace_stats *st)
{
    sum->body = shade_ambient(s->m->kd, t->scene->ambient);
    sum->highlight = vec_splat(0);
    for (int i = 0; i < t->scene->light_count; i++) {
        const scene_light *light = &t->scene->lights[i];
        if (light_distributed(light))
            add_distributed(t, s, i, key, sum, st);
        else
            add_source(t, s, light, &light->position, &light->power, NULL, sum, st);
    }
}

/* The samples direct_light takes of light i: a point or distant light's
 * one (its setup's count is not its), a distributed light's setup count. */
static int light_loop_samples(const tracer *t, int i)
{
    return light_distributed(&t->scene->lights[i]) ? t->lights[i].samples : 1;
}

/* The samples a skipped light loop would have counted, and its cancel
 * steps (a distributed light's samples each, as add_distributed asks). */
static void light_loop_counted(const tracer *t, trace_stats *st)
{
    for (int i = 0; i < t->scene->light_count; i++) {
        st->light_samples += light_loop_samples(t, i);
        if (light_distributed(&t->scene->lights[i]))
            cancel_steps(st->cancel, t->lights[i].samples);
    }
}

/*
 * [SHADE-SHORTCUT-HIDDEN-1] Every sample point p of the ball (centre P + d,
 * reach r < |d|) is seen from P within alpha of d's direction, sin alpha =
 * r / |d|, so its direction makes an angle of at least theta - alpha with
 * m (cos theta = d.m / (|d| |m|)), and L.m <= |m| cos(max(0, theta -
 * alpha)).  The margin 2^-20 covers the sample's rounding (light_dark's
 * argument: below 2^-32 where |d| - r >= 2^-16 of the coordinates' size
 * and >= 2^-400, which the caller checks) and this bound's (cos alpha and
 * sin theta are square roots of 1 - x^2: within 2^-26 where x is near 1).
 * 1 (no bound) for |m| outside [1/2, 2].
 */
real trace_ball_cosine_above(vec3 d, real reach, vec3 m)
{
    real m_len = sqrt(vec_length2(m)), dist = vec_length(d);
    if (!(m_len >= 0.5 && m_len <= 2 && dist > reach))
        return 1;
    real cos_t = vec_dot(d, m) / (dist * m_len), sin_a = reach / dist;
    cos_t = cos_t < -1 ? -1 : cos_t > 1 ? 1 : cos_t;
    real cos_a = sqrt(1 - sin_a * sin_a), sin_t = sqrt(1 - cos_t * cos_t);
    if (cos_t >= cos_a)
        return 1;
    return m_len * (cos_t * cos_a + sin_t * sin_a) + 0x1p-20;
}

/*
 * [SHADE-SHORTCUT-HIDDEN-1] An upper bound on the highlight one sample of
 * the light adds at a Kd = 0 point, Ks I lobe: +Inf where none is known (a
 * light with no ball, sizes past 2^400, a point nearer the ball than
 * light_dark allows).  V.R = L.M exactly; trace_lobe_above grows with c,
 * so it bounds the lobe at the cosine's bound.  The distance is at least
 * gap (1 - 2^-20), and the falloff, rounded, shrinks with the distance
 * below 2^1000 (plain quotients), so I is at most its value there; the
 * shadow's factor is at most 1.  A distant light's L is -direction itself
 * (unit, rounded) and its I its power.
 */
static rgb highlight_above(const tracer *t, const surface *s, int index, vec3 m)
{
    const scene_light *light = &t->scene->lights[index];
    const light_setup *setup = &t->lights[index];
    rgb none = vec_splat(HUGE_VAL);
    int point = light->kind == LIGHT_POINT;
    if (light->kind == LIGHT_DISTANT) {
        vec3 l = vec_neg(light->direction);
        real l2 = vec_length2(l);
        if (!(l2 >= 0.25 && l2 <= 4))
            return none;
        return vec_scale(vec_mul(s->m->ks, light->power), trace_lobe_above(vec_dot(l, m) + 0x1p-20, s->m->n));
    }
    if (!point && !(setup->reach >= 0))
        return none;
    vec3 centre = point ? light->position : setup->centre, p = s->h->point;
    real reach = point ? 0 : setup->reach;
    real size = vec_max_abs(p) + vec_max_abs(centre) + reach;
    if (!(size < 0x1p400))
        return none;
    vec3 d = vec_sub(centre, p);
    real gap = vec_length(d) - reach;
    if (!(gap >= 0x1p-16 * size && gap >= 0x1p-400))
        return none;
    rgb i = source_intensity(light, point ? &light->power : &setup->power, gap * (1 - 0x1p-20));
    if (!(i.x < 0x1p1000 && i.y < 0x1p1000 && i.z < 0x1p1000))
        return none;
    return vec_scale(vec_mul(s->m->ks, i), trace_lobe_above(trace_ball_cosine_above(d, reach, m), s->m->n));
}

/*
 * [SHADE-SHORTCUT-HIDDEN-1] Whether the highlight of a Kd = 0 point cannot
 * change its colour: U, twice the sum over the lights of samples x
 * highlight_above (at least every highlight sum the light loop can make,
 * its roundings included), finite, leaves shade_combine where 0 leaves
 * it, on all three channels.  body is the
 * point's Kd Ia, which the loop leaves as it is.  Out of line: its colours
 * stay off shade's frame, which the recursion holds ([REL-STACK-1]).
 */
static HINT_OUT_OF_LINE int highlight_hidden(const tracer *t, const surface *s, rgb body, rgb mirror, rgb through)
{
    vec3 m = view_mirror(s);
    rgb u = vec_splat(0);
    for (int i = 0; i < t->scene->light_count; i++) {
        rgb one = highlight_above(t, s, i, m);
        u = vec_add(u, vec_scale(one, (real)light_loop_samples(t, i)));
    }
    u = vec_scale(u, 2);
    /* No bound (a light's +Inf, or the sum past DBL_MAX): the loop runs,
     * and counts what it counts (a sample on the surface: attack 24h). */
    if (!(u.x >= 0 && u.y >= 0 && u.z >= 0 && u.x <= DBL_MAX && u.y <= DBL_MAX && u.z <= DBL_MAX))
        return 0;
    rgb lo = shade_combine(body, vec_splat(0), s->m->ks, s->m->t, mirror, through);
    rgb hi = shade_combine(body, u, s->m->ks, s->m->t, mirror, through);
    return lo.x == hi.x && lo.y == hi.y && lo.z == hi.z;
}


/* With the shortcuts off a ray of weight 0 (Ks = 0, or t = 0 on the
 * interface) is traced too, and its colour, finite, is multiplied by 0.
 * A medium stack overflow inside it (or in a stack no ray goes on with)
 * cannot make the image wrong, so it is forgotten: the stack's overflow
 * refuses a render exactly where it refuses the default one
 * ([SHADE-SHORTCUT-OFF-1]). */
static void forget_overflow(trace_stats *st, long overflow_before, int harmless)
{
    if (harmless)
        st->medium_overflow = overflow_before;
}

/*
 * The transmitted ray: straight on through a sheet, bent by Snell's law
 * where the interface changes the medium (n1 the medium before, the top of
 * the stack; n2 the one after), or mirrored on total internal reflection.
 * A solid left that the stack does not hold (its overflow) keeps its own
 * ior as n1.
 */
/* The transmitted ray's setup, in a frame of its own: the interface's
 * INTERFACE_MAX hits (about 1.2 KiB) are not needed once the ray is spawned,
 * so they stay off the recursion's stack, which holds a frame a bounce
 * ([REL-STACK-1]).  Returns 0 where [SHADE-SHORTCUT-RAYS-1]'s zero weight
 * leaves the ray out, with the overflow count restored. */
static HINT_OUT_OF_LINE int transmit_setup(const tracer *t, const surface *s, const ray *in, const medium_stack *media,
                                        medium_stack *next, ray *r, real *through, int *refracts, hit *end,
                                        trace_stats *st)
{
    interface f;
    long overflow_before = st->medium_overflow;
    interface_gather(t, s->prim, s->h, s->magnitude, in, &f, st);
    end->prim = interface_end(t, &f, media, end) ? end->prim : -1;
    int solids = interface_cross(t, &f, media, next, st);
    *through = f.through;
    /* Solids crossed here past INTERFACE_MAX are missing from `next`: the
     * media of the ray would be wrong, so the render refuses, as on the
     * stack's own overflow. */
    st->medium_overflow += f.solids_lost > 0;
    if (*through == 0 && !t->no_shortcuts) {
        st->medium_overflow = overflow_before;
        return 0;
    }
    vec3 dir = in->dir;
    *refracts = 1;
    if (solids > 0) {
        int solid = medium_solid_id(t->scene, s->h->prim);
        int left = solid >= 0 && s->prim->kind != PRIM_MESH && !s->h->entering;
        real n1 = left && medium_find(media, solid) < 0 ? s->m->ior : medium_top_ior(media);
        *refracts = shade_refract(in->dir, s->n, n1, medium_top_ior(next), &dir);
    }
    /* Totally reflected, the ray stays in the glass and never meets the
     * opaque surface. */
    if (!*refracts)
        end->prim = -1;
    ray spawned = ray_spawn_hit_sized(f.spawn_prim, f.spawn_hit, dir, f.spawn_magnitude);
    ray_copy(r, &spawned);
    return 1;
}

static rgb trace_end(const tracer *t, const ray *r, hit *end, int depth, const medium_stack *media, uint64_t key,
                     const glass_contact *touch, trace_stats *st);

/* The mirror ray of a shaded point as `mirrored` traced it, for
 * [SHADE-SHORTCUT-TIR-1]: its colour and what its tree added to the
 * counters.  Not the ray itself: it lives in shade's frame, which every
 * bounce of the recursion holds ([REL-STACK-1]), and tir_is_mirror makes
 * the ray again from the same arguments (the same pure functions, the
 * same bits). */
typedef struct mirror_trace {
    int traced;          /* 1: by trace_ray itself (no contact at its start) */
    int clean;           /* 1: its tree added nothing to medium_overflow and nonfinite */
    long tree_rays;
    rgb c;
} mirror_trace;

/* The mirror ray of the point of s for the incoming ray in. */
static ray mirror_ray(const surface *s, const ray *in)
{
    return ray_spawn_hit_sized(s->prim, s->h, shade_mirror(in->dir, s->n), s->magnitude);
}

/*
 * [SHADE-SHORTCUT-TIR-1] The totally reflected ray r is the mirror ray of
 * the same point when their bits are equal (shade_refract mirrors as
 * shade_mirror does, both spawn from the hit when the interface is the
 * hit alone), and both go on with the same depth and media.  trace_ray is
 * then the same function of the same arguments but the key, which only a
 * distributed light's samples read (t->keyed), and the trace_stats, whose
 * blocker hints change no value ([SHADE-SHORTCUT-BLOCKER-1]): so its
 * colour is the mirror ray's, to the bit.  Taken only where its tree
 * added nothing to the counters that refuse a render (medium_overflow,
 * nonfinite) and its ray count, added again, keeps within the budget:
 * then tracing it again would have added the same and no more.  Not with
 * the ray-tree hash (record_path), which would miss the second tree, nor
 * with the shortcuts off.  Returns 1 with the colour in *c.  Out of line:
 * the mirror ray made again stays off the frame of `transmitted`, which a
 * chain of total reflections holds once a bounce ([REL-STACK-1]).
 */
static HINT_OUT_OF_LINE int tir_is_mirror(const tracer *t, const surface *s, const ray *in, const ray *r,
                                       const mirror_trace *m, trace_stats *st, rgb *c)
{
    if (!m->traced || t->no_shortcuts || t->keyed || st->record_path || st->tree_overflow || !m->clean)
        return 0;
    ray mirror = mirror_ray(s, in);
    if (memcmp(r, &mirror, sizeof *r) != 0)
        return 0;
    if (t->max_tree_rays > 0 && st->tree_rays + m->tree_rays > t->max_tree_rays)
        return 0;
    st->tree_rays += m->tree_rays;
    *c = m->c;
    return 1;
}

/*
 * The transmitted ray: straight on through a sheet, bent by Snell's law
 * where the interface changes the medium (n1 the medium before, the top of
 * the stack; n2 the one after), or mirrored on total internal reflection.
 * A solid left that the stack does not hold (its overflow) keeps its own
 * ior as n1.  Kept out of shade (HINT_OUT_OF_LINE): `next` is in its frame,
 * which only a transmitted bounce then pays for.
 */
static HINT_OUT_OF_LINE rgb transmitted(const tracer *t, const surface *s, const ray *in, int depth,
                                     const medium_stack *media, uint64_t key, const mirror_trace *mirror,
                                     trace_stats *st)
{
    medium_stack next = *media;
    /* An overflow of `next` (the stack past the interface) matters only
     * to a ray that goes on with it and carries weight. */
    long overflow_before = st->medium_overflow;
    ray r;
    real through;
    int refracts;
    hit end;
    if (!transmit_setup(t, s, in, media, &next, &r, &through, &refracts, &end, st))
        return vec_splat(0);
    path_note(st, (uint64_t)refracts + 3);
    rgb c;
    if (refracts) {
        st->refraction_rays++;
        c = end.prim >= 0 ? trace_end(t, &r, &end, depth + 1, &next, key, NULL, st)
                          : trace_ray(t, &r, depth + 1, &next, key, st);
        c = vec_scale(c, through);
    } else {
        /* Totally reflected, the ray stays in `media`: `next` is not used. */
        st->medium_overflow = overflow_before;
        st->tir_rays++;
        if (!tir_is_mirror(t, s, in, &r, mirror, st, &c))
            c = trace_ray(t, &r, depth + 1, media, key, st);
        c = vec_scale(c, through);
    }
    forget_overflow(st, overflow_before, through == 0 || s->m->t == 0);
    return c;
}

/* [NUM-GLASS-3] The mirror ray r from the opaque point of s, when it meets
 * a transparent surface within reach that its walk would miss (start_zone):
 * its colour in *c, and 1.  Out of line: the zone's hit stays off the
 * recursion's frame of an ordinary mirror bounce ([REL-STACK-1]). */
static HINT_OUT_OF_LINE int mirror_meets_glass(const tracer *t, const surface *s, const ray *r, int depth,
                                            const medium_stack *media, uint64_t key, trace_stats *st, rgb *c)
{
    start_zone z;
    real offset = ray_shadow_start_sized(s->h, s->magnitude).offset;
    if (!glass_near(t, s->h->point, 2 * offset))
        return 0;
    glass_start_gather(t, s->h, offset, r, &z, st);
    if (z.first.prim < 0)
        return 0;
    glass_contact touch = {s->h, z.side};
    *c = trace_end(t, r, &z.first, depth, media, key, &touch, st);
    return 1;
}

/* [NUM-GLASS-3] The mirror ray r from the glass point of s that a mirror
 * ray from the opaque surface s->touch met at its start: in the limit of a
 * gap the glass lies off that surface, so a ray back toward it meets it at
 * distance 0 (its colour in *c, and 1).  Out of line as mirror_meets_glass. */
static HINT_OUT_OF_LINE int mirror_meets_opaque(const tracer *t, const surface *s, const ray *r, int depth,
                                             const medium_stack *media, uint64_t key, trace_stats *st, rgb *c)
{
    if (!glass_contact_meets(s->touch, r->dir))
        return 0;
    hit end = *s->touch->opaque;
    *c = trace_end(t, r, &end, depth, media, key, NULL, st);
    return 1;
}

static rgb mirrored(const tracer *t, const surface *s, const ray *in, int depth, const medium_stack *media,
                    uint64_t key, int weightless, mirror_trace *m, trace_stats *st)
{
    ray r = mirror_ray(s, in);
    st->reflection_rays++;
    long overflow_before = st->medium_overflow;
    rgb c;
    int met = 0;
    if (s->touch)
        met = mirror_meets_opaque(t, s, &r, depth + 1, media, key, st, &c);
    else if (t->glass && !(s->m->t > 0))
        met = mirror_meets_glass(t, s, &r, depth + 1, media, key, st, &c);
    if (!met && (t->keyed || !(s->m->t > 0))) {
        c = trace_ray(t, &r, depth + 1, media, key, st);
    } else if (!met) {
        /* Kept for the totally reflected ray (glass, no key read). */
        long tree = st->tree_rays, overflow = st->medium_overflow, nonfinite = st->nonfinite;
        c = trace_ray(t, &r, depth + 1, media, key, st);
        m->traced = 1;
        m->clean = st->medium_overflow == overflow && st->nonfinite == nonfinite;
        m->tree_rays = st->tree_rays - tree;
        m->c = c;
    }
    forget_overflow(st, overflow_before, weightless);
    return c;
}

/* The key of a mirror or transmitted ray: only a distributed light's samples
 * read a key (add_distributed; t->keyed says the scene has one), so without
 * one the key is passed on as it is, its mix not made at every point. */
static uint64_t child_key(const tracer *t, uint64_t key, uint64_t which)
{
    return t->keyed ? sampler_key(key, which) : key;
}

static rgb shade(const tracer *t, const ray *in, const hit *h, int depth, const medium_stack *media, uint64_t key,
                 const glass_contact *touch, trace_stats *st)
{
    surface s;
    hit lifted;
    s.prim = &t->scene->prims[h->prim];
    s.m = &t->scene->materials[s.prim->material];
    s.h = s.shadow_from = h;
    s.magnitude = isect_part_magnitude(s.prim, h->part);
    if (t->terminator_offset && t->shadows && isect_smooth(s.prim)) {
        lifted = *h;
        lifted.point = isect_shadow_point(s.prim, h);
        s.shadow_from = &lifted;
    }
    s.v = vec_neg(in->dir);
    s.n = shade_face_forward(h->shading_normal, s.v);
    /* Ks > 0 and Kd = 0: tracer_build found them once a material. */
    int terms = t->material_terms[s.prim->material], ks = (terms & TRACE_KS) != 0;
    /* [SHADE-SHORTCUT-LOBE-1] Ks = 0 makes the highlight 0 * I * lobe = 0. */
    s.highlight = t->specular && (ks || t->no_shortcuts);
    s.no_body = (terms & TRACE_NO_BODY) != 0;
    /* The floor of [SHADE-SHORTCUT-LOBE-2]: tracer_build made it (a function
     * of n alone, the same double). */
    s.lobe_floor = s.no_body && s.highlight ? t->lobe_floors[s.prim->material] : 0;
    if (t->shadows)
        s.from = ray_shadow_start_sized(s.shadow_from, s.magnitude);
    /* Once a point, not once a light sample. */
    s.touch = touch;
    s.hints = depth > 1 ? TRACE_BLOCKERS : 0;
    s.near_glass =
        t->shadows && (touch || (t->glass && !(s.m->t > 0) && glass_near(t, s.from.point, 2 * s.from.offset)));
    /* [SHADE-SHORTCUT-HIDDEN-1] A Kd = 0 point's mirrored and transmitted
     * colours first: its light loop only where its highlight may show. */
    int deferred = s.no_body && s.highlight && !t->no_shortcuts && !st->record_path;
    direct_sum sum;
    if (!deferred)
        direct_light(t, &s, key, &sum, st);
    rgb mirror = vec_splat(0), through = vec_splat(0);
    mirror_trace m;
    m.traced = 0;
    /* [SHADE-SHORTCUT-RAYS-1] A ray whose weight (Ks, t) is 0 adds 0. */
    if (depth < t->max_depth) {
        if (t->reflection && (ks || t->no_shortcuts))
            mirror = mirrored(t, &s, in, depth, media, child_key(t, key, TRACE_KEY_MIRROR), !ks, &m, st);
        if (t->refraction && (s.m->t > 0 || t->no_shortcuts))
            through = transmitted(t, &s, in, depth, media, child_key(t, key, TRACE_KEY_REFRACT), &m, st);
    }
    if (deferred) {
        sum.body = shade_ambient(s.m->kd, t->scene->ambient);
        if (highlight_hidden(t, &s, sum.body, mirror, through)) {
            sum.highlight = vec_splat(0);
            light_loop_counted(t, st);
            st->hidden_highlights++;
        } else {
            direct_light(t, &s, key, &sum, st);
        }
    }
    return shade_combine(sum.body, sum.highlight, s.m->ks, s.m->t, mirror, through);
}

/* ---- where a ray starts: the media around a point ---------------------- */

/* Solids the probe ray crosses: count and nearest crossing of each. */
enum { PROBE_MAX = 64 };
typedef struct probe {
    const scene_model *scene;
    int count;
    int overflow;          /* a transparent solid past PROBE_MAX was crossed */
    int solid[PROBE_MAX], prim[PROBE_MAX], crossings[PROBE_MAX];
    real first[PROBE_MAX];
} probe;

static int probe_crossing(void *ctx, const hit *h)
{
    probe *pr = ctx;
    int solid = medium_solid_id(pr->scene, h->prim), k = 0;
    if (solid < 0 || !(pr->scene->materials[pr->scene->prims[h->prim].material].t > 0))
        return 0;
    while (k < pr->count && pr->solid[k] != solid)
        k++;
    if (k == pr->count) {
        if (k == PROBE_MAX) {
            pr->overflow = 1;
            return 0;
        }
        pr->count++;
        pr->solid[k] = solid;
        pr->prim[k] = h->prim;
        pr->crossings[k] = 0;
        pr->first[k] = h->t;
    }
    pr->crossings[k]++;
    if (h->t < pr->first[k])
        pr->first[k] = h->t;
    return 0;
}

/* Strictly inside a solid primitive (in its own frame); for a mesh, an odd
 * number of crossings of the probe. */
static int contains(const scene_prim *p, vec3 point, int crossings)
{
    if (scene_prim_is_solid(p))
        return scene_prim_contains(p, point);
    return crossings % 2 == 1;
}

void trace_media_at(const tracer *t, vec3 point, medium_stack *out, trace_stats *st)
{
    probe pr;
    out->count = 0;
    if (!t->refraction)
        return;
    pr.scene = t->scene;
    pr.count = 0;
    pr.overflow = 0;
    /* A direction along no axis and no simple diagonal, so the probe does
     * not run along the faces and edges of boxes and axis-aligned meshes. */
    ray r;
    r.origin = point;
    r.dir = vec_normalize(vec_make(0.2971, 0.5309, 0.7936));
    r.tmin = 0;
    r.tmax = HUGE_VAL;
    bvh_visit_stats(&t->accel, t->scene->prims, &r, probe_crossing, &pr, &st->bvh);
    st->medium_overflow += pr.overflow;
    /* Outermost first: the solid the probe leaves last goes on first. */
    for (;;) {
        int best = -1;
        for (int k = 0; k < pr.count; k++)
            if (pr.crossings[k] >= 0 && contains(&t->scene->prims[pr.prim[k]], point, pr.crossings[k]) &&
                (best < 0 || pr.first[k] > pr.first[best]))
                best = k;
        if (best < 0)
            return;
        const scene_prim *p = &t->scene->prims[pr.prim[best]];
        medium_push(out, pr.solid[best], t->scene->materials[p->material].ior, st);
        pr.crossings[best] = -1;
    }
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

/* The nearest hit, in a frame of its own: the BVH walk's stack (BVH_MAX_DEPTH
 * entries, 1.5 KiB) is not needed once the hit is found, so it stays off
 * the recursion's stack ([REL-STACK-1]). */
static HINT_OUT_OF_LINE int nearest_hit(const tracer *t, ray *nearest, const bvh_beam_tree *beam, hit *h, int *tied,
                                        trace_stats *st)
{
    return bvh_beam_intersect(&t->accel, beam, t->scene->prims, nearest, h, &st->bvh, tied);
}

/* The colour of ray r given its nearest hit h (met), or the background. */
static rgb ray_colour(const tracer *t, const ray *r, int met, const hit *h, int depth, const medium_stack *media,
                      uint64_t key, const glass_contact *touch, trace_stats *st)
{
    rgb c = t->scene->image.background;
    path_note(st, met ? (uint64_t)h->prim + 5 : 0);
    if (met && st->record_path)
        path_note(st, piece_of(&t->scene->prims[h->prim], h));
    if (met)
        c = shade(t, r, h, depth, media, key, touch, st);
    if (!vec_is_finite(c)) {
        st->nonfinite++;
        c = vec_splat(0);
    }
    return c;
}

/* [NUM-GLASS-3] The ray r (spawned) meets the surface `end` at distance
 * 0: a transmitted ray the opaque surface of its interface, a mirror ray
 * from an opaque point the glass there.  That surface is its hit, seen
 * along r.  Here, not in glass_touch.c: it is a step of the recursion. */
static rgb trace_end(const tracer *t, const ray *r, hit *end, int depth, const medium_stack *media, uint64_t key,
                     const glass_contact *touch, trace_stats *st)
{
    ray at;
    ray_copy(&at, r);
    if (over_budget(t, st) || cancel_step(st->cancel))
        return t->scene->image.background;
    at.tmin = at.tmax = end->t = 0;
    end->entering = vec_dot(r->dir, end->normal) < 0;
    return ray_colour(t, &at, 1, end, depth, media, key, touch, st);
}

/* trace_ray, its nearest hit found on beam (NULL: the whole tree). */
static rgb trace_ray_on(const tracer *t, const ray *r, int depth, const medium_stack *media, uint64_t key,
                        const bvh_beam_tree *beam, trace_stats *st)
{
    ray nearest;
    hit h;
    ray_copy(&nearest, r);
    if (over_budget(t, st) || cancel_step(st->cancel))
        return t->scene->image.background;
    int tied;
    int met = nearest_hit(t, &nearest, beam, &h, &tied, st);
    /* A hit alone in its window was tied with nothing. */
    if (met && t->glass && tied > 1)
        glass_first_of_tie(t, r, &h, media, st);
    return ray_colour(t, &nearest, met, &h, depth, media, key, NULL, st);
}

rgb trace_ray(const tracer *t, const ray *r, int depth, const medium_stack *media, uint64_t key, trace_stats *st)
{
    return trace_ray_on(t, r, depth, media, key, NULL, st);
}

rgb trace_camera_ray(const tracer *t, const ray *r, const bvh_beam_tree *beam, const medium_stack *media, uint64_t key,
                     trace_stats *st)
{
    return trace_ray_on(t, r, 1, media, key, beam, st);
}
