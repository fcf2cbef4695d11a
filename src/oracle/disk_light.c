/*
 * disk_light.c - family `disk_light` (spec/analytic.md (section `area_lights`), [ORACLE-DISK]):
 * a distributed disk light parallel to a Lambert floor.  On the axis the
 * light is closed for every falloff, E/A 2 pi h (G(sqrt(h^2+a^2)) - G(h))
 * (linear: E/A 2 pi h ln((sqrt(h^2+a^2)+d0)/(h+d0)); inverse_square, d0 = 0:
 * E/A 2 pi (1 - h/sqrt(h^2+a^2))).  Off the axis, inverse_square with d0 = 0
 * is the solid angle of the disk in complete and incomplete elliptic
 * integrals (Paxton 1959); the other falloffs have no closed form and use
 * the contour integral around the rim, by adaptive Gauss-Kronrod.
 */
#include "oracle/area_family.h"

static const area_kind kind = {"disk_light", LIGHT_DISK, 0};

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

const oracle_family oracle_disk_light = {
    "disk_light", "a disk light over a Lambert floor, on and off axis: Paxton's elliptic form or the exact contour integral", 1, accepts, radiance, tolerance,
};
