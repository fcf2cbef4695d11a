/*
 * rect_light.c - family `rect_light` (spec/analytic.md (section `area_lights`), [ORACLE-RECT]):
 * a distributed rectangle (or parallelogram) light parallel to a Lambert
 * floor.  The converged light at a floor point is (E/A) times the integral
 * over the light of falloff(d) N.L: for inverse_square with d0 = 0 the solid
 * angle of the rectangle, by the corner form atan(ab / (h sqrt(h^2+a^2+b^2)))
 * superposed over four corner rectangles (any foot point, under the light or
 * not); otherwise Green's contour integral of the closed radial integral
 * along the four edges, by adaptive Gauss-Kronrod (no elementary closed form:
 * for linear falloff the edge integral is a Clausen-type function).
 */
#include "oracle/area_family.h"

static const area_kind kind = {"rect_light", LIGHT_RECTANGLE, 0};

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

const oracle_family oracle_rect_light = {
    "rect_light", "a rectangle light over a Lambert floor: E/A times the integral of falloff*N.L (solid angle for inverse_square)", 1, accepts, radiance, tolerance,
};
