/*
 * disk_occluded.c - family `disk_occluded` (spec/analytic.md (section `area_lights`),
 * [ORACLE-OCCLUDED]): a distributed disk light, an opaque Lambert disk
 * parallel to it between it and a Lambert floor.  From a floor point the
 * occluder hides the central projection of itself onto the light's plane, a
 * disk of radius b h/h_o; the light is the exact integral over the light disk
 * minus that disk (on the axis an annulus in closed form; off it the contour
 * integral along the two boundary arcs, split at the circles' crossings).
 * The occluder's top is lit by the whole light (nothing lies between); its
 * underside sees no light (N.L < 0), only ambient.
 */
#include "oracle/area_family.h"

static const area_kind kind = {"disk_occluded", LIGHT_DISK, 1};

static int accepts(const oracle_view *v, char *why, size_t why_size)
{
    area_setup s;
    return area_setup_read(v, &kind, &s, why, why_size);
}

static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    return area_radiance(v, &kind, x, y, out);
}

static double tolerance(const oracle_view *v, int light_samples)
{
    return area_tolerance(v, &kind, light_samples);
}

const oracle_family oracle_disk_occluded = {
    "disk_occluded", "a disk light partly hidden by a parallel opaque disk: the exact integral over light minus shadow", 1, accepts, radiance, tolerance,
};
