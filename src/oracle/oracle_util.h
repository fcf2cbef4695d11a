/*
 * oracle_util.h - what the local-shading and shadow families share
 * (ambient, lambert_sphere, plane_point, phong_plane, phong_sphere,
 * sphere_shadow, transparent_shadow, stacked_sheets; spec/analytic.md, one section per family).
 *
 * Everything here is written from the model's definition (spec/shading.md)
 * and from plain geometry, never from the tracer's
 * code: lines are met by planes and spheres through the distance of a line
 * from a point, the Phong lobe through V.R = 2(N.L)(N.V) - L.V without
 * forming R, the falloffs from their formulas.  Nothing here keeps state.
 *
 * Margins.  A sample point whose answer a rounding error of the tracer could
 * flip is ORACLE_AMBIGUOUS, never guessed:
 *   ORACLE_EDGE_MARGIN  relative distance (to a radius, or to the length
 *                       scale of the scene) from a silhouette, a shadow
 *                       boundary or the rim of a disk;
 *   ORACLE_COS_MARGIN   |N.L| near 0 (the terminator: the side is decided
 *                       by rounding and a near-zero cosine has no relative
 *                       accuracy), |N.D| near 0 (a ray along a plane),
 *                       |V.R| near 0 for a lobe exponent below 1 (where
 *                       max(0, V.R)^n jumps or has an infinite slope).
 * Both are a million times wider than the tracer's rounding (about 1e-15
 * relative) and narrow enough that the pixels they exclude are a handful.
 */
#ifndef REFRAY_ORACLE_UTIL_H
#define REFRAY_ORACLE_UTIL_H

#include "oracle/oracle.h"
#include "oracle/oracle_geom.h"

#define ORACLE_EXACT_TOLERANCE 1e-9
/* The constant of the view's rounding floor (spec/verify.md,
 * [ORACLE-VIEW-ROUNDING-1]). */
#define ORACLE_VIEW_ROUNDING_K 256
/* The most the floor may loosen a verdict, whatever the view
 * ([ORACLE-VIEW-ROUNDING-2]). */
#define ORACLE_VIEW_ROUNDING_MAX 1e-3
/* The render's offset of a secondary ray's origin, relative to the hit's
 * coordinates (spec/numerics.md, [NUM-SPAWN-1]: 2^-42), and the shading's
 * relative change per unit of that offset over the distance to what the
 * ray samples, with margin ([ORACLE-VIEW-ROUNDING-3]). */
#define ORACLE_SPAWN_REL 0x1p-42
#define ORACLE_SPAWN_K 8
/* The same per unit of that offset over the smallest radius of curvature
 * a secondary ray may meet, the normal there turning by offset / radius
 * ([ORACLE-VIEW-ROUNDING-4]). */
#define ORACLE_SPAWN_CURVE_K 32
#define ORACLE_EDGE_MARGIN 1e-6
#define ORACLE_COS_MARGIN 1e-6

/* The tolerance of every deterministic family: 1e-9 relative (issue 4), or
 * the rounding of the view's rays where that is larger (an eye or geometry
 * far away for the picture's width: [ORACLE-VIEW-ROUNDING-1]), read from
 * the eye and the geometry, never from look_at. */
double oracle_tolerance_exact(const oracle_view *v, int light_samples);

/* E/(d+d0), E/(d+d0)^2 or E (slides 15-16), straight from the formula. */
rgb oracle_falloff(rgb power, double d, double d0, scene_falloff falloff);

/* A light as seen from a point p. */
typedef struct oracle_light_at {
    const scene_light *light;
    vec3 l;             /* unit, from p toward the light */
    double dist;        /* to a point light; HUGE_VAL for a distant light */
    rgb intensity;      /* E after the falloff */
} oracle_light_at;

/* Fills *out for a point or distant light seen from p; returns 0 for a
 * distributed light or a point light at p (callers refuse both). */
int oracle_light_toward(const scene_light *light, vec3 p, oracle_light_at *out);

/* The fraction S of light la that reaches p (1, 0, t^2, ...); sets
 * *ambiguous when p lies within the margin of a shadow boundary. */
typedef double (*oracle_shadow_fn)(const void *ctx, vec3 p, const oracle_light_at *la, int *ambiguous);

typedef struct oracle_shading {
    rgb body;           /* Kd*Ia + sum Kd*I*S*(N.L) */
    rgb highlight;      /* sum Ks*I*S*max(0, V.R)^n */
} oracle_shading;

/*
 * The direct light at p with unit normal n facing the viewer v: ambient
 * plus every point and distant light with N.L > 0, each scaled by shadow()
 * (NULL: nothing is in the way).  Returns ORACLE_AMBIGUOUS when some light
 * with power has |N.L| within ORACLE_COS_MARGIN, when a lobe with n < 1 has
 * |V.R| within it, or when shadow() says so.
 */
oracle_status oracle_shade_direct(const scene_model *s, const scene_material *m, vec3 p, vec3 n, vec3 v,
                                  oracle_shadow_fn shadow, const void *ctx, oracle_shading *out);

/* (1 - t)*body + highlight: the local colour (slide 37). */
rgb oracle_shade_local(const scene_material *m, const oracle_shading *sh);

/* max(0, c)^n with c = V.R clamped to 1; 0 when ambiguous (see above). */
double oracle_phong_lobe(double c, double n, int *ambiguous);

/* Where a line o + s d (d unit) passes a sphere of centre c, radius r. */
typedef struct oracle_chord {
    double along;       /* (c - o).d: the parameter of the point nearest c */
    double off;         /* distance of the line from c */
    double half;        /* sqrt(r^2 - off^2): half the chord; 0 on a miss */
    vec3 q;             /* (c - o) - along*d: from that nearest point to c, negated */
} oracle_chord;

typedef enum oracle_chord_kind {
    ORACLE_CHORD_MISS,
    ORACLE_CHORD_HIT,   /* crossings at along -/+ half */
    ORACLE_CHORD_GRAZE  /* within ORACLE_EDGE_MARGIN*r of the outline */
} oracle_chord_kind;

oracle_chord_kind oracle_line_sphere(vec3 o, vec3 d, vec3 c, double r, oracle_chord *out);

/* The outward unit normal at the entry (far = 0) or exit (far = 1) of a
 * chord of a sphere of radius r: (-q -/+ half*d)/r, solved without the
 * crossing point. */
vec3 oracle_chord_normal(const oracle_chord *ch, vec3 d, double r, int far);

/* The entry point *p, outward normal *n and toward-viewer *v of the view
 * ray through (x, y) on the sphere prim; the kind of its chord (*p, *n, *v
 * are set for ORACLE_CHORD_HIT only).  The caller has checked that the view
 * ray's origin is outside the sphere. */
oracle_chord_kind oracle_view_sphere(const oracle_view *v, double x, double y, const scene_prim *sphere, vec3 *p,
                                     vec3 *n, vec3 *toward_viewer);

/* The same for a plane prim (any camera): returns 1 with *p, *n (the
 * plane's normal turned toward the viewer) and *v set when the view ray
 * meets the plane ahead, 0 when it does not, -1 (ambiguous) when the ray
 * runs within ORACLE_COS_MARGIN of parallel to the plane or starts within
 * ORACLE_EDGE_MARGIN scene scales of it. */
int oracle_view_plane(const oracle_view *v, double x, double y, const scene_prim *plane, vec3 *p, vec3 *n,
                      vec3 *toward_viewer);

/* The direct shading (oracle_shade_direct, nothing in the way) of what the
 * view ray through (x, y) meets on the scene's one primitive, a sphere or
 * a plane: ORACLE_EXACT with *seen 1 and *sh set, or with *seen 0 and *out
 * the background where the ray misses it; ORACLE_AMBIGUOUS where it grazes
 * or the shading is not exact. */
oracle_status oracle_view_shade(const oracle_view *v, double x, double y, oracle_shading *sh, rgb *out, int *seen);

/* The radiance of a matte sphere or plane alone (families lambert_sphere
 * and plane_point): the body of oracle_view_shade's shading. */
oracle_status oracle_view_lambert(const oracle_view *v, double x, double y, rgb *out);

/* The radiance of a Phong sphere or plane alone (families phong_sphere and
 * phong_plane): body and highlight of oracle_view_shade's shading, plus
 * Ks times the background that the mirror direction sees when max_depth
 * lets a reflection ray leave. */
oracle_status oracle_view_phong(const oracle_view *v, double x, double y, rgb *out);

/* Where the Phong lobe of a distant light peaks on a sphere seen along v
 * (unit, toward the viewer): N = normalize(l + v), the point c + r N. */
vec3 oracle_phong_sphere_peak(vec3 c, double r, vec3 l, vec3 v);

/* Distance from c to the path p -> light of la (a segment for a point
 * light, a half-line for a distant one). */
double oracle_path_distance(vec3 p, const oracle_light_at *la, vec3 c);

/* The parameter s where o + s d meets the plane through p0 with normal n;
 * returns 0 (s untouched) when |n.d| <= ORACLE_COS_MARGIN |n||d|. */
int oracle_line_plane(vec3 o, vec3 d, vec3 p0, vec3 n, double *s);

/* The continuous image point (x, y) whose view ray passes through the
 * world point p: the inverse of oracle_view_ray.  Returns 0 when p is not
 * in front of a perspective eye. */
int oracle_image_point(const oracle_view *v, vec3 p, double *x, double *y);

/* The point of the plane (p0, n) where a perspective eye sees the mirror
 * image of light: the eye -> mirror-light line crossing the plane.  Eye
 * and light must be on the same side, off the plane. */
vec3 oracle_mirror_point(vec3 p0, vec3 n, vec3 eye, vec3 light);

/* The same for an orthographic camera of unit forward f (V = -f for all
 * points): the point whose direction to the light is the mirror of V. */
vec3 oracle_mirror_point_ortho(vec3 p0, vec3 n, vec3 f, vec3 light);

/* The largest coordinate magnitude of the scene's eye, primitives and
 * point lights (at least 1): the length scale of absolute margins.  Not
 * look_at, which names a direction only (a far one made every margin
 * huge: [ORACLE-VIEW-ROUNDING-2]). */
double oracle_scene_scale(const scene_model *s);

/* The material of primitive i. */
const scene_material *oracle_material(const scene_model *s, int prim);

/* 1 when every light is a point or distant light, else refuses with
 * "FAMILY: light N is distributed (...)". */
int oracle_accept_lights(const scene_model *s, const char *family, char *why, size_t n);

/* 1 when every primitive is stored without a transform (spheres under
 * similarities, planes and disks always are), else refuses. */
int oracle_accept_untransformed(const scene_model *s, const char *family, char *why, size_t n);

/* 1 when material m has Ks = 0 and t = 0, else refuses naming what. */
int oracle_accept_matte(const scene_material *m, const char *family, const char *what, char *why, size_t n);

/* 1 when every point light is more than ORACLE_EDGE_MARGIN radii outside
 * the sphere (c, r), else refuses. */
int oracle_accept_lights_outside(const scene_model *s, vec3 c, double r, const char *family, char *why, size_t n);

/* 1 when the camera is orthographic and the sphere lies wholly in front
 * of its image plane ((c - eye).forward > r), else refuses. */
int oracle_accept_ortho_in_front(const scene_model *s, vec3 c, double r, const char *family, char *why, size_t n);

/*
 * A sphere over a plane (sphere_shadow, transparent_shadow): what the view
 * ray through (x, y) meets first, solved from the chord of the sphere and
 * the line/plane formula.  out->ray, out->chord and out->plane_s (when the
 * ray is not parallel to the plane, out->plane_ok) are always filled.
 */
typedef enum oracle_sees {
    ORACLE_SEES_NOTHING,
    ORACLE_SEES_SPHERE,     /* entry at chord.along - chord.half */
    ORACLE_SEES_PLANE,      /* at plane_s */
    ORACLE_SEES_AMBIGUOUS   /* grazes the sphere, runs along the plane, starts on it */
} oracle_sees;

typedef struct oracle_pair_view {
    oracle_ray ray;
    oracle_chord chord;
    int plane_ok;           /* 0: within ORACLE_COS_MARGIN of parallel */
    double plane_s;
} oracle_pair_view;

oracle_sees oracle_view_sphere_plane(const oracle_view *v, double x, double y, const scene_prim *sphere,
                                     const scene_prim *plane, oracle_pair_view *out);

/* The plane's point at parameter s of the ray, with the normal turned
 * toward the ray's origin. */
void oracle_plane_hit(const scene_prim *plane, const oracle_ray *ray, double s, vec3 *p, vec3 *n);

/*
 * 1 when the scene is one sphere and one plane, untransformed, the sphere
 * strictly on one side of the plane, every light on that side (point lights
 * outside the sphere and off the plane, distant lights shining toward the
 * plane from that side) and the eye on that side outside the sphere (an
 * orthographic image plane clear of the sphere); *sphere and *plane are the
 * indices.  Else refuses with the reason.  Under these assumptions nothing
 * shadows the sphere where N.L > 0: a segment between two points of an open
 * half-space stays in it.
 */
int oracle_accept_sphere_plane(const scene_model *s, const char *family, int *sphere, int *plane, char *why,
                               size_t n);

/* 1 when every point light and the eye lie more than ORACLE_EDGE_MARGIN
 * scene scales off the plane prim, else refuses. */
int oracle_accept_off_plane(const scene_model *s, const scene_prim *plane, const char *family, char *why, size_t n);

#endif
