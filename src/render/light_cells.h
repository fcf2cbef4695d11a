/*
 * light_cells.h - bundles of shadow rays toward point lights, shared by the
 * shaded points of a cell (spec/shading.md, [SHADE-SHORTCUT-BUNDLE-2]).
 *
 * Every shadow ray toward a point light ends at the light.  A regular grid
 * of cubes over the tree's root box (one cell of margin around it) gives
 * each cell, per point light, one bundle (bvh_bundle_make) whose apex is
 * the cell's centre and whose slack covers every point of the cell plus
 * the largest spawn offset allowed; a shadow ray whose start is checked to
 * lie within that slack walks only the bundle's nodes.  The bundles are
 * made lazily, at a cell's first shadow ray, into a pool of fixed size:
 * when it is full, or a point falls outside the check, the plain walk.
 *
 * The cache belongs to the caller's per-render state (the renderer), not
 * to the tracer, which stays read-only while shading.
 */
#ifndef REFRAY_LIGHT_CELLS_H
#define REFRAY_LIGHT_CELLS_H

#include "render/trace.h"

/* The bundles a render keeps (a fixed pool; the table of cells has twice
 * as many slots, so a probe ends soon). */
enum { LIGHT_CELLS_RECENT = 4, LIGHT_CELLS_POOL = 32768, LIGHT_CELLS_SLOT_BITS = 16, LIGHT_CELLS_SLOTS = 1 << LIGHT_CELLS_SLOT_BITS };

typedef struct light_cell_key {
    int light, cell[3];   /* light -1: a free slot */
    int bundle;           /* its index in pool */
} light_cell_key;

struct light_cells {
    vec3 lo;              /* a corner of the grid (the tree's root box's) */
    real width;           /* a cell's edge */
    real inv_width;       /* 1 / width, rounded: picks the cell, which the
                             check then confirms */
    real slack;           /* half the edge plus the spawn offsets allowed */
    light_cell_key *slot; /* LIGHT_CELLS_SLOTS, NULL: no cache */
    bvh_bundle *pool;     /* LIGHT_CELLS_POOL */
    int pool_used;
    light_cell_key last[LIGHT_CELLS_RECENT];  /* the cells asked for last,
                             in turn: the next shaded point mostly lies in
                             one of them (the camera ray's, the mirrored
                             ray's); light -1: none */
    int last_next;
    mem mem;
};

/* Sets up the grid for t's point lights with cells of edge width; nothing
 * is allocated (and every query answers NULL) when the scene has no point
 * light, t's bundles are off, or the tree is empty.  Returns 1, or 0 when out of memory (then *c is
 * empty too). */
int light_cells_init(light_cells *c, const tracer *t, real width, const mem *m);
void light_cells_free(light_cells *c);

/* The bundle of point light `light` for the cell holding from->point, made
 * now if it was not; NULL (walk the whole tree) when c is NULL or empty,
 * the point's start is not surely within the cell's slack, or the pool is
 * full. */
bvh_bundle *light_cells_bundle(light_cells *c, const tracer *t, int light, const shadow_start *from,
                               bvh_stats *stats);

#endif
