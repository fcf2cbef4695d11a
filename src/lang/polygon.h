/*
 * polygon.h - cutting a polygon face of a mesh file into triangles.
 *
 * A face c0 c1 ... c(n-1) of n >= 3 corners is triangulated on its plane by
 * ear clipping (spec/language.md, section 8, [MESH-POLY-1]): the plane is
 * the one of the polygon's Newell normal, the corners are projected by
 * dropping the normal's largest axis (exact: no coordinate is rounded), and
 * an ear (a corner that turns the polygon's way and whose triangle with its
 * two neighbours holds no other corner) is cut off until three corners are
 * left.  Corners that add no area (at the place of the one before, or the
 * tip of a spike out and back) are left out first ([MESH-POLY-2]); a
 * polygon through one place twice gets a stricter ear test ([MESH-POLY-3]);
 * the tests are scale-free ([MESH-POLY-4]).  The triangles keep the
 * polygon's winding, cover its region exactly when it does not cross
 * itself (convex or not, touching itself or not), and use only its own
 * edges and diagonals, so a corner lying on an edge (a T-junction seen from
 * the neighbour) stays a corner of some triangle.
 *
 * What is found on the way comes back as flags: no area (every corner on
 * one line, or fewer than 3 places once the repeats are out: the face
 * gives no triangle), not planar (a corner farther than POLYGON_PLANAR_TOL
 * of the polygon's size from its plane), fanned (the polygon crosses
 * itself, so no ear was left, or over the work budget: cut as the fan
 * (c0, ck, ck+1) instead).
 */
#ifndef REFRAY_POLYGON_H
#define REFRAY_POLYGON_H

#include "base/mem.h"
#include "base/vec.h"

/* A corner is off the plane when farther than this times the largest side
 * of the polygon's bounding box: well above the rounding of coordinates
 * written with 6 decimals on faces down to 1/100 of a unit. */
#define POLYGON_PLANAR_TOL 1e-4

enum {
    POLYGON_NO_AREA = 1,
    POLYGON_NONPLANAR = 2,
    POLYGON_FANNED = 4
};

/* Scratch space reused from one polygon to the next, and the ear-clipping
 * budget of a whole mesh: each corner tested against an ear costs one step;
 * when the steps run out, later non-convex polygons are fanned, so a hostile
 * file of huge polygons cannot take quadratic time. */
typedef struct polygon_work {
    double *x, *y;     /* projected corners */
    int *next, *prev;  /* the corners still in the polygon, as a ring */
    int *aux;          /* sorted corners, then the ring's corners marked */
    int cap;           /* corners of room: the five arrays are one block */
    long budget;       /* steps left */
    mem mem;
} polygon_work;

/* Empty scratch with the default budget (2^26 steps, a fraction of a
 * second), allocating from m (NULL: the C library). */
void polygon_work_init(polygon_work *w, const mem *m);
void polygon_work_free(polygon_work *w);

/*
 * Triangulates the n corners at[0..n-1] (positions).  Writes at most n - 2
 * triangles to out as corner numbers (0..n-1) and returns how many, or -1
 * when out of memory.  *flags gets the POLYGON_* flags above.  n == 3 is
 * taken as it is (a triangle with no area is the caller's to find).
 */
int polygon_triangulate(const vec3 *at, int n, polygon_work *w, int (*out)[3], int *flags);

#endif
