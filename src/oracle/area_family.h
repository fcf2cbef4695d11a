/*
 * area_family.h - what the area-light families (rect_light, disk_light,
 * disk_occluded) share: reading and checking their scenes, the geometry of
 * a camera ray's hit solved directly, the exact light at the hit
 * (area_light.h), and the tolerance of a sampled render
 * (spec/analytic.md (section `area_lights`), "Tolerance").
 *
 * The scenes: one Lambert floor (a plane, Ks = 0, t = 0), one distributed
 * light parallel to it, and for disk_occluded one opaque Lambert disk
 * parallel to both, strictly between them.  Nothing else.
 */
#ifndef REFRAY_AREA_FAMILY_H
#define REFRAY_AREA_FAMILY_H

#include "oracle/oracle.h"

typedef struct area_setup {
    const char *family;         /* for messages */
    const scene_model *scene;
    const scene_light *light;
    const scene_prim *floor;       /* the plane */
    const scene_prim *occluder;    /* the disk, or NULL */
    vec3 n, e1, e2;             /* the floor's unit normal and two unit tangents */
    double area;                /* of the light */
} area_setup;

/* The family's description of the light and whether it has an occluder. */
typedef struct area_kind {
    const char *family;
    scene_light_kind light;        /* LIGHT_RECTANGLE or LIGHT_DISK */
    int occluded;
} area_kind;

/* Reads v's scene as a scene of kind; 1, or 0 with the reason in why. */
int area_setup_read(const oracle_view *v, const area_kind *kind, area_setup *s, char *why, size_t why_size);

/* The exact radiance at image point (x, y) (oracle_family.radiance). */
oracle_status area_radiance(const oracle_view *v, const area_kind *kind, double x, double y, rgb *out);

/* The largest relative error a render with light_samples (0: the light's
 * own) may show at any pixel, by the bound of the spec's "Tolerance". */
double area_tolerance(const oracle_view *v, const area_kind *kind, int light_samples);

/* Bernstein's bound: the t with 2 exp(-t^2 / (2 (var + range t / 3))) =
 * delta, for a sum of independent zero-mean terms of total variance var,
 * each at most range in size (spec "Tolerance").  Exposed for the tests. */
double area_bernstein(double var, double range, double delta);

#endif
