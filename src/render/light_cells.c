/*
 * light_cells.c - see light_cells.h.
 */
#include <math.h>
#include <string.h>
#include "render/light_cells.h"

/* Spawn offsets are a few ulps of the point's magnitudes (intersect.h,
 * SPAWN_REL, SPAWN_ABS): far below this share of a cell's edge, so the
 * slack covers them wherever the check passes. */
#define LIGHT_CELLS_OFFSET_SHARE 0x1p-6

static int has_point_light(const scene_model *s)
{
    for (int i = 0; i < s->light_count; i++)
        if (s->lights[i].kind == LIGHT_POINT)
            return 1;
    return 0;
}

int light_cells_init(light_cells *c, const tracer *t, real width, const mem *m)
{
    memset(c, 0, sizeof *c);
    c->mem = mem_pick(m);
    if (!t->bundles || t->accel.nodes == NULL || !has_point_light(t->scene) || !(width > 0))
        return 1;
    c->lo = t->accel.nodes[0].lo;
    c->width = width;
    c->inv_width = 1 / width;
    for (int i = 0; i < LIGHT_CELLS_RECENT; i++)
        c->last[i].light = -1;
    c->slack = 0.5 * width + LIGHT_CELLS_OFFSET_SHARE * width;
    c->slot = mem_alloc(&c->mem, LIGHT_CELLS_SLOTS * sizeof *c->slot);
    c->pool = mem_alloc(&c->mem, LIGHT_CELLS_POOL * sizeof *c->pool);
    if (!c->slot || !c->pool) {
        light_cells_free(c);
        return 0;
    }
    for (int i = 0; i < LIGHT_CELLS_SLOTS; i++)
        c->slot[i].light = -1;
    return 1;
}

void light_cells_free(light_cells *c)
{
    if (c->slot)
        mem_free(&c->mem, c->slot, LIGHT_CELLS_SLOTS * sizeof *c->slot);
    if (c->pool)
        mem_free(&c->mem, c->pool, LIGHT_CELLS_POOL * sizeof *c->pool);
    c->slot = NULL;
    c->pool = NULL;
}

/* The cell along one axis and its centre; 0 when the index would pass
 * 2^30 cells from the corner (or p is not finite). */
static int cell_of(real p, real lo, real width, real inv_width, int *cell, real *centre)
{
    real q = (p - lo) * inv_width;
    if (!(fabs(q) < 0x1p30))
        return 0;
    real f = (real)(long)q;   /* floor without the call: exact below 2^52 */
    f -= f > q;
    *centre = lo + (f + 0.5) * width;
    *cell = (int)f;
    return 1;
}

/* The slot of (light, cell): its own, or the free one where it would go;
 * NULL when the table is full along the probe. */
static light_cell_key *find_slot(light_cells *c, int light, const int cell[3])
{
    /* Multiplicative hashing (the table's size a power of 2): the top bits
     * of the sum of the coordinates times odd constants. */
    uint64_t h = (uint64_t)(unsigned)cell[0] * 0x9E3779B97F4A7C15u + (uint64_t)(unsigned)cell[1] * 0xC2B2AE3D27D4EB4Fu +
                 (uint64_t)(unsigned)cell[2] * 0x165667B19E3779F9u + (uint64_t)(unsigned)light * 0x27D4EB2F165667C5u;
    h >>= 64 - LIGHT_CELLS_SLOT_BITS;
    for (int probe = 0; probe < 32; probe++) {
        light_cell_key *k = &c->slot[(h + (uint64_t)probe) & (LIGHT_CELLS_SLOTS - 1)];
        if (k->light < 0 || (k->light == light && k->cell[0] == cell[0] && k->cell[1] == cell[1] &&
                             k->cell[2] == cell[2]))
            return k;
    }
    return NULL;
}

bvh_bundle *light_cells_bundle(light_cells *c, const tracer *t, int light, const shadow_start *from,
                               bvh_stats *stats)
{
    if (!c || !c->slot)
        return NULL;
    const real p[3] = {from->point.x, from->point.y, from->point.z}, lo[3] = {c->lo.x, c->lo.y, c->lo.z};
    real centre[3], far = 0;
    int cell[3];
    for (int a = 0; a < 3; a++) {
        if (!cell_of(p[a], lo[a], c->width, c->inv_width, &cell[a], &centre[a]))
            return NULL;
        real d = fabs(p[a] - centre[a]);
        far = d > far ? d : far;
    }
    /* [SHADE-SHORTCUT-BUNDLE-2] The origin lies within far + offset N of
     * the centre, each term rounded here by a few ulps at most: the factor
     * and the term of the magnitudes cover them. */
    real reach = (far + from->offset * vec_sum_abs(from->normal)) * (1 + 0x1p-40) +
                 0x1p-48 * (vec_max_abs(from->point) + c->slack);
    if (!(reach <= c->slack))
        return NULL;
    for (int i = 0; i < LIGHT_CELLS_RECENT; i++) {
        const light_cell_key *r = &c->last[i];
        if (r->light == light && r->cell[0] == cell[0] && r->cell[1] == cell[1] && r->cell[2] == cell[2])
            return &c->pool[r->bundle];
    }
    light_cell_key *k = find_slot(c, light, cell);
    if (!k)
        return NULL;
    if (k->light < 0) {
        if (c->pool_used == LIGHT_CELLS_POOL)
            return NULL;
        bvh_bundle_rays rays;
        rays.apex = vec_make(centre[0], centre[1], centre[2]);
        rays.slack = c->slack;
        rays.lo = t->scene->lights[light].position;
        rays.hi = rays.lo;
        rays.exact = 0;
        rays.origin = rays.apex;
        bvh_bundle_make(&t->accel, &rays, &c->pool[c->pool_used], stats);
        k->light = light;
        memcpy(k->cell, cell, sizeof k->cell);
        k->bundle = c->pool_used++;
    }
    c->last[c->last_next] = *k;
    c->last_next = (c->last_next + 1) % LIGHT_CELLS_RECENT;
    return &c->pool[k->bundle];
}
