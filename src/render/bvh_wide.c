/*
 * bvh_wide.c - the binary tree collapsed to 4-wide nodes (bvh.h,
 * bvh_wide_node) for the nearest walk (bvh.c).
 *
 * Each wide node stands for an inner node of the binary tree; its slots
 * are that node's children, each inner child replaced by its own two
 * children: two to four slots, in depth-first order.  The boxes are the
 * binary nodes' own, copied bit for bit, so a slot's slab test is the
 * binary walk's test of that node.  Leaving out the test of an inner
 * child before its children changes no hit: a child's box lies inside its
 * parent's and the slab test is monotone in the box (bvh.c,
 * root_decides_nothing), and the nearest hit does not depend on which
 * nodes are entered or in what order ([BVH-TIE-ORDER-1]).
 * Nodes are laid out in depth-first order (a node, then its subtrees), so
 * a walk going down reads nearby memory.
 */
#include <stdint.h>
#include <string.h>
#include "render/bvh.h"
#include "render/slab_pair.h"

#ifdef SLAB_PAIR_SSE2
enum { WIDE_ALIGN = 64 };

/* The surface area of n's box, up to a factor 2: the chance a ray through
 * its parent meets it. */
static real box_area(const bvh_node *n)
{
    vec3 e = vec_sub(n->hi, n->lo);
    return e.x * (e.y + e.z) + e.y * e.z;
}

/* The slots of binary inner node n's wide node in kids[], their number
 * returned: its two children, then, while fewer than four, the inner
 * slot of the largest box replaced by its own two children in its place
 * (so the slots stay in depth-first order).  Full nodes make the tree
 * shallow: opening only grandchildren left half the nodes of the sphere
 * grids with two slots (two leaves). */
static int wide_kids(const bvh *b, int n, int kids[4])
{
    int slots = 2;
    kids[0] = b->nodes[n].first;
    kids[1] = kids[0] + 1;
    while (slots < 4) {
        int open = -1;
        for (int j = 0; j < slots; j++)
            if (b->nodes[kids[j]].count == 0 &&
                (open < 0 || box_area(&b->nodes[kids[j]]) > box_area(&b->nodes[kids[open]])))
                open = j;
        if (open < 0)
            break;
        int first = b->nodes[kids[open]].first;
        for (int j = slots; j > open + 1; j--)
            kids[j] = kids[j - 1];
        kids[open] = first;
        kids[open + 1] = first + 1;
        slots++;
    }
    return slots;
}

/* The wide nodes needed below binary inner node n (itself included). */
static int wide_count_below(const bvh *b, int n)
{
    int kids[4], slots = wide_kids(b, n, kids), total = 1;
    for (int j = 0; j < slots; j++)
        if (b->nodes[kids[j]].count == 0)
            total += wide_count_below(b, kids[j]);
    return total;
}

/* Slot j of w from binary node n; an inner n's wide node is made next, at
 * *next. */
static void wide_fill(bvh *b, int n, int *next);

static void wide_slot(bvh *b, bvh_wide_node *w, int j, int n, int *next)
{
    const bvh_node *nd = &b->nodes[n];
    const real lo[3] = {nd->lo.x, nd->lo.y, nd->lo.z}, hi[3] = {nd->hi.x, nd->hi.y, nd->hi.z};
    for (int k = 0; k < 3; k++) {
        w->lo[k][j] = lo[k];
        w->hi[k][j] = hi[k];
    }
    w->count[j] = nd->count;
    if (nd->count > 0) {
        w->first[j] = nd->first;
        return;
    }
    w->first[j] = *next;
    wide_fill(b, n, next);
}

static void wide_fill(bvh *b, int n, int *next)
{
    int at = (*next)++;
    bvh_wide_node *w = &b->wide[at];
    int kids[4], slots = wide_kids(b, n, kids);
    memset(w, 0, sizeof *w);
    for (int j = slots; j < 4; j++)
        for (int k = 0; k < 3; k++) {
            w->lo[k][j] = INFINITY;
            w->hi[k][j] = -INFINITY;
        }
    w->slots = slots;
    /* w is filled before the subtrees (they move *next on); it stays at
     * b->wide[at], the array is not grown. */
    for (int j = 0; j < slots; j++)
        wide_slot(b, &b->wide[at], j, kids[j], next);
}

void bvh_wide_build(bvh *b)
{
    if (b->node_count < 3 || b->nodes[0].count > 0)
        return;
    int count = wide_count_below(b, 0);
    size_t bytes = (size_t)count * sizeof *b->wide + WIDE_ALIGN;
    void *block = mem_alloc(&b->mem, bytes);
    if (!block)
        return;
    b->wide_block = block;
    b->wide_block_bytes = bytes;
    b->wide = (bvh_wide_node *)(void *)((char *)block + (WIDE_ALIGN - (uintptr_t)block % WIDE_ALIGN) % WIDE_ALIGN);
    b->wide_count = count;
    int next = 0;
    wide_fill(b, 0, &next);
}
#else
/* Without the pair test the nearest walk reads the binary tree alone. */
void bvh_wide_build(bvh *b)
{
    (void)b;
}
#endif
