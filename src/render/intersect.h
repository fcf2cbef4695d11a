/*
 * intersect.h - ray/primitive intersection and the rays that leave a surface.
 *
 * Contract of every isect_* routine (SQLite-style: what it returns, what it
 * touches):
 *   - a hit is accepted only for t in the open interval (r->tmin, r->tmax);
 *   - on a hit it sets r->tmax = t, fills *h and returns 1; on a miss it
 *     returns 0 and touches neither *r nor *h;
 *   - h->normal is the unit geometric normal oriented as ray.h says (outward
 *     for sphere, box, cylinder, cone and torus, open or closed; the
 *     declared side for plane, disk and triangle),
 *     h->shading_normal the unit interpolated vertex normal of a triangle
 *     with normals, else a copy of h->normal; h->entering = dir . normal < 0;
 *   - h->prim is set to -1: the caller that knows the index (the BVH) sets
 *     it; h->part is the triangle of a mesh, else 0; h->b1, h->b2 are a
 *     triangle's barycentric weights of corners 1 and 2 (else 0).
 * r->dir need not be unit length (rays taken into a local frame are not); a
 * zero direction never hits.  Sheets (plane, disk, triangle, and an open
 * cylinder or cone) are two-sided.
 *
 * Edge cases, as defined here and tested in tests/check_intersect.c:
 *   - sphere: a ray whose line touches the sphere with discriminant exactly
 *     0 is one hit (a graze), reported once, with entering computed as usual
 *     (dir . normal is about 0 there);
 *   - a ray starting inside a sphere or box hits the far side (entering 0);
 *   - a ray starting exactly on a surface does not hit it at t = 0 (the
 *     interval is open) but does hit the far side of a solid it goes into;
 *   - plane and disk: a ray parallel to the plane misses, even in the plane;
 *     the disk includes its boundary circle (|p - c| <= radius);
 *   - box: faces are closed (a ray along a face plane hits, as does one
 *     through an edge); when entry and exit coincide (an edge or corner
 *     touched, or a flat box) it is one hit with the entry face's normal;
 *   - triangle: watertight (Woop, Benthin, Wald 2013) with exact edge
 *     signs and one tie rule: a ray through a shared edge or vertex of a
 *     mesh hits exactly one of the triangles there where the surface does
 *     not fold back around the ray, and an even number (0 or 2) where it
 *     does (a silhouette): a closed mesh is crossed once per surface; an
 *     edge of one triangle only (a lone triangle, an open mesh's rim) is
 *     part of it, so a ray through it hits (tests/check_watertight.c);
 *   - closed cylinder and cone: like the box, one interval per ray (the
 *     rim between side and cap leaves no gap); an open one has no caps
 *     and keeps the side's crossings between the end planes (closed);
 *   - torus: up to 4 crossings; a ray that only touches it (a double root
 *     of its quartic) may be a hit or a miss, as a sphere's graze.
 * Numeric domain: hit/miss decisions multiply two coordinates together, so
 * they are exact in sign only while such products stay normal doubles:
 * coordinates and sizes within 2^500 (about 3.3e150), non-zero sizes at
 * least 2^-500 (the sphere test alone is guarded against underflow).  No
 * computation multiplies three, so a scene scaled by a power of two within
 * that range renders bit for bit the same (tests/test_stability.c,
 * scale_*.scene).  Validation refuses scenes outside it ([LANG-EXTENT-1],
 * src/scene/check_extent.c); nothing here checks it again.
 */
#ifndef REFRAY_INTERSECT_H
#define REFRAY_INTERSECT_H

#include "render/ray.h"
#include "scene/scene.h"

int isect_sphere(vec3 center, real radius, ray *r, hit *h);
int isect_plane(vec3 point, vec3 normal, ray *r, hit *h);
/* p: the three vertices; normals: three unit vertex normals or NULL. */
int isect_triangle(const vec3 p[3], const vec3 *normals, ray *r, hit *h);
int isect_disk(vec3 center, vec3 normal, real radius, ray *r, hit *h);
int isect_box(vec3 lo, vec3 hi, ray *r, hit *h);
/* A cylinder between the end centres from and to (from != to), radius > 0;
 * open: no end caps. */
int isect_cylinder(vec3 from, vec3 to, real radius, int open, ray *r, hit *h);
/* A cone with radius r0 at from and r1 at to (both >= 0, not both 0). */
int isect_cone(vec3 from, vec3 to, real r0, real r1, int open, ray *r, hit *h);
/* A ring torus: unit axis, 0 < minor < major. */
int isect_torus(vec3 center, vec3 axis, real major, real minor, ray *r, hit *h);

/* The most crossings one primitive has with a line: a torus's 4. */
#define ISECT_MAX_CROSSINGS 4

/* The nearest hit of one primitive, dispatching on p->kind and taking the
 * ray into the local frame when p->frame is set (t is preserved; point and
 * normals are mapped back to the world).  A mesh is searched triangle by
 * triangle (the BVH does better: it holds the parts below). */
int isect_prim(const scene_prim *p, ray *r, hit *h);

/* The first crossings of the surface in (r->tmin, r->tmax), in increasing
 * t: 0 to ISECT_MAX_CROSSINGS (a solid crossed through: entry and exit; a
 * torus: two of each; a mesh: its first four).  r is not changed; each
 * out[i].prim is -1. */
int isect_prim_all(const scene_prim *p, const ray *r, hit out[ISECT_MAX_CROSSINGS]);

/* World-space axis-aligned bounds of a bounded primitive: scene_prim_world_box
 * (a transformed one: its local box's 8 corners mapped).  Returns 0 for a plane, or when the
 * bounds are not finite (such a primitive must be tested unconditionally). */
int isect_prim_bounds(const scene_prim *p, vec3 *lo, vec3 *hi);

/* The largest coordinate magnitude a hit point of p is computed from (its
 * vertices, centre plus radius, plane point...): the hit point's rounding
 * error is relative to this, not to the point itself. */
real isect_prim_magnitude(const scene_prim *p);

/*
 * Parts: what the BVH holds.  A mesh's parts are its triangles (part k is
 * geom.tri[k]); every other primitive is one part, 0.  The functions are
 * those above for one part; a hit's h->part says which.
 */
int isect_part_count(const scene_prim *p);
int isect_part(const scene_prim *p, int part, ray *r, hit *h);
int isect_part_all(const scene_prim *p, int part, const ray *r, hit out[ISECT_MAX_CROSSINGS]);
int isect_part_bounds(const scene_prim *p, int part, vec3 *lo, vec3 *hi);
/* The box the BVH holds the part in: its bounds widened on each axis by
 * 2^-40 of the larger of their magnitude and their width, so a hit
 * computed a few ulps outside the true box is still inside.  0 when they,
 * or the box's centre (which the build bins), are not finite: the part is
 * then tested on every ray.  A kept-frame hit outside this box is no hit
 * ([NUM-FRAME-1]). */
int isect_part_padded_bounds(const scene_prim *p, int part, vec3 *lo, vec3 *hi);
real isect_part_magnitude(const scene_prim *p, int part);
/* How many crossings isect_part_all reports, found by the same arithmetic
 * without their points and normals (a shadow ray needs only the count). */
int isect_part_crossings(const scene_prim *p, int part, const ray *r);
/* Whether isect_part_crossings is > 0 (a world-frame sphere's stops at its
 * first crossing: the same answer). */
int isect_part_crossed(const scene_prim *p, int part, const ray *r);

/* The ray's share of the watertight triangle test (Woop et al.: the axis
 * permutation, dz and the shear sx, sy), which depends on the direction
 * alone: a walk that tests many triangles with one ray makes it once.
 * The _sheared forms take it (sh made by isect_shear_make of this r's
 * direction, or NULL to make it per call) and give the same bits as the
 * plain ones. */
typedef struct isect_shear {
    real sx, sy, dz;
    int kx, ky, kz;
} isect_shear;
void isect_shear_make(const ray *r, isect_shear *sh);
/* A triangle corner's sheared x (k = kx, s = sx) or y (ky, sy) for the
 * origin o, as the watertight test rounds it: (v_k - o_k) - s (v_kz - o_kz)
 * (isect_corner_of of a = v_k - o_k and z = v_kz - o_kz rounded).  The
 * run's quick miss (intersect.c, triangle_apart) and a bundle's triangles
 * left out (bvh_bundle.c) make it by this one text. */
static inline real isect_corner_of(real a, real z, real s) { return a - s * z; }
static inline real isect_corner_at(vec3 v, vec3 o, real s, int k, int kz)
{
    real z = vec_component(v, kz) - vec_component(o, kz);
    return isect_corner_of(vec_component(v, k) - vec_component(o, k), z, s);
}
int isect_part_sheared(const scene_prim *p, int part, ray *r, const isect_shear *sh, hit *h);
int isect_part_all_sheared(const scene_prim *p, int part, const ray *r, const isect_shear *sh,
                           hit out[ISECT_MAX_CROSSINGS]);
int isect_part_crossings_sheared(const scene_prim *p, int part, const ray *r, const isect_shear *sh);
/* isect_part_crossings of a plane without a transform (point, unit
 * normal): 0 or 1. */
int isect_plane_crossings(vec3 point, vec3 normal, const ray *r);
/* The same test, its t in *t when it returns 1: the t isect_part gives
 * the plane on the same ray (plane_t, the one computation both make). */
int isect_plane_nearest(vec3 point, vec3 normal, const ray *r, real *t);

/*
 * Hot records: what the hit test of a sphere without a transform (centre,
 * radius: 4 reals), of a box without one (8) or of a triangle (its three
 * corners: 9 reals, padded to 12) reads, copied out of the scene_prim (392 bytes, the mesh's corner
 * indices) so that the BVH can keep them in its leaves' order.  The
 * record's code says which test it is and a mesh triangle's inclusive
 * edges; the tests are the shapes' own (bare: t only), so they give the
 * same bits as isect_part_crossings and the t of isect_part.
 */
enum {
    ISECT_HOT_NONE = 0,     /* no record: test through the scene_prim */
    ISECT_HOT_SPHERE = 1,
    ISECT_HOT_TRIANGLE = 2,
    ISECT_HOT_BOX = 3       /* lo, hi: 6 reals, padded to 8 */
};
#define ISECT_HOT_KIND(code) ((code) & 3)
#define ISECT_HOT_REALS 12  /* the most a record takes */
/* Fills g (up to ISECT_HOT_REALS) for part of p and returns its code, or
 * ISECT_HOT_NONE (g untouched) when p has no hot record; *reals is how many
 * of g it takes (a multiple of 4). */
int isect_hot_make(const scene_prim *p, int part, real g[ISECT_HOT_REALS], int *reals);
/* The *reals that isect_hot_make gives for each part of p (0: none). */
int isect_hot_reals(const scene_prim *p);
/* isect_part_crossings of the record's part (sh: r's shear when the record
 * is a triangle). */
int isect_hot_crossings(int code, const real *g, const ray *r, const isect_shear *sh);
/* Whether isect_hot_crossings is > 0 (the any-crossing walk's test). */
int isect_hot_crossed(int code, const real *g, const ray *r, const isect_shear *sh);
/* The nearest crossing's t in (r->tmin, r->tmax), as isect_part finds it:
 * returns 1 and sets *t, or 0. */
int isect_hot_nearest(int code, const real *g, const ray *r, const isect_shear *sh, real *t);
/* For a sphere's or a box's record: exactly isect_part (the full hit, r->tmax
 * shrunk); returns -1 for a triangle's, which needs the scene_prim (its
 * vertex normals) for a full hit. */
int isect_hot_hit(int code, const real *g, ray *r, hit *h);
/* isect_hot_hit in two halves, for the nearest walk, where a candidate
 * may lose to a nearer one: the candidate has the t, point, part and tmax of
 * isect_hot_hit (a box's hit is whole), a sphere's normal, shading normal,
 * entering, prim and weights not yet written; isect_hot_complete(code, g,
 * r->dir, h) on it then gives isect_hot_hit's hit, the same bits (prim -1),
 * reading only h's t and point (a sphere's; a box's hit it leaves as it is). */
int isect_hot_candidate(int code, const real *g, ray *r, hit *h);
void isect_hot_complete(int code, const real *g, vec3 dir, hit *h);

/* Where a record is kept (the BVH's items, bvh.h): its code, and where its
 * reals start in an array of them. */
typedef struct bvh_hot {
    int code;          /* ISECT_HOT_NONE: test through the scene_prim */
    int at;
} bvh_hot;
/* The run of triangle records at the start of hot[0..n-1] (those of kind
 * ISECT_HOT_TRIANGLE up to the first of another kind; each one's reals at
 * reals + hot[i].at), tested in order with one ray: returns the index of
 * the first that isect_hot_nearest finds crossed, its t in *t; else the
 * index where the run ends (the first record of another kind, or n).  sh:
 * r's shear.  The same tests as isect_hot_nearest (and
 * isect_hot_crossings: a triangle's count is 0 or 1) of each record in
 * turn, with the ray's permutation chosen once for the run. */
int isect_hot_triangle_run(const bvh_hot *hot, int n, const real *reals, const ray *r, const isect_shear *sh,
                           real *t);

/* Where shadow rays from a hit should start: for a triangle with vertex
 * normals the hit point lifted toward the curved surface those normals
 * describe (Hanika's shadow terminator offset, spec/shading.md
 * [SHADE-TERMINATOR-1]); for anything else the hit point itself.  The
 * tracer passes a copy of the hit with this point to ray_spawn_hit_to and
 * ray_spawn_hit_shadow. */
vec3 isect_shadow_point(const scene_prim *p, const hit *h);
/* Whether p has vertex normals (a smooth triangle or mesh), so that the
 * lifted point can differ from the hit point. */
int isect_smooth(const scene_prim *p);

/*
 * Secondary rays (Wachter and Binder, "A Fast and Robust Method for Avoiding
 * Self-Intersection", Ray Tracing Gems I, ch. 6, in the working precision): the origin
 * is pushed off the surface along the geometric normal, to the side the ray
 * goes, by the offset SPAWN_REL * m + SPAWN_ABS where m is the largest
 * coordinate magnitude involved.  Mirror and refracted rays then start at
 * tmin = 0; shadow rays at tmin = that same offset along the ray, so that a
 * surface within the offset of the point (the other side of a concave edge,
 * which the rounded point may lie just behind) does not shadow it.  No
 * epsilon is needed anywhere else.
 */
#define SPAWN_REL (1024.0 * 2.220446049250313e-16) /* 2^-42: 1024 ulps of m */
#define SPAWN_ABS 1e-300                           /* only matters at |p| ~ 0 */
/* Shadow rays stop this fraction short of their target, so a light placed
 * on a surface is not shadowed by that surface. */
#define SPAWN_SHADOW_SHRINK 1e-9

/* A ray from point in direction dir (copied, not normalised), m = max |point_i|:
 * right when the point's error is relative to its own magnitude.
 * tmin = 0, tmax = HUGE_VAL. */
ray ray_spawn(vec3 point, vec3 geometric_normal, vec3 dir);

/* A shadow ray from point toward target: unit dir, tmin = the offset, tmax =
 * distance * (1 - SPAWN_SHADOW_SHRINK).  A target within the offset gives an
 * empty interval: nothing can stand between. */
ray ray_spawn_to(vec3 point, vec3 geometric_normal, vec3 target);

/* The same for a hit on p, with m = max(|h->point|, isect_part_magnitude(p,
 * h->part)): what the tracer should use (a big triangle or sphere hit near
 * the world origin has an error relative to its vertices or centre, not to
 * the point).  A ray into a box starts inside it on every axis (see
 * intersect.c, keep_inside). */
ray ray_spawn_hit(const scene_prim *p, const hit *h, vec3 dir);
/* The same with m = isect_part_magnitude(p, h->part) given: a shaded point
 * finds it once for its shadow rays, its mirror ray and its transmitted ray. */
ray ray_spawn_hit_sized(const scene_prim *p, const hit *h, vec3 dir, real m);
/* Shadow rays: from h->point toward a target point, or toward a distant
 * light (the shadow rays' tmin, the offset over |dir|, and tmax =
 * HUGE_VAL). */
ray ray_spawn_hit_to(const scene_prim *p, const hit *h, vec3 target);
ray ray_spawn_hit_shadow(const scene_prim *p, const hit *h, vec3 dir);

/* The shadow rays of one shaded point share their start: the hit point
 * (h->point, or the lifted point of isect_shadow_point in a copy of the
 * hit), its geometric normal and the offset of ray_spawn_hit_to, computed
 * once (the magnitude is not cheap for a transformed primitive).
 * ray_shadow_to and ray_shadow_along give exactly the rays of
 * ray_spawn_hit_to and ray_spawn_hit_shadow. */
typedef struct shadow_start {
    vec3 point, normal;
    real offset;
} shadow_start;
shadow_start ray_shadow_start(const scene_prim *p, const hit *h);
shadow_start ray_shadow_start_sized(const hit *h, real m);   /* m as ray_spawn_hit_sized's */
ray ray_shadow_to(const shadow_start *st, vec3 target);
/* The origin of ray_shadow_to(st, target) for every target whose
 * vec_dot(target - st->point, st->normal), rounded, is >= 0 when
 * vec_dot(toward, st->normal) is, < 0 when it is: spawn_origin decides by
 * that sign alone. */
vec3 ray_shadow_origin(const shadow_start *st, vec3 toward);
ray ray_shadow_along(const shadow_start *st, vec3 dir);
/* ray_shadow_along with length = vec_length(dir) given, the same ray. */
ray ray_shadow_along_sized(const shadow_start *st, vec3 dir, real length);

#endif
