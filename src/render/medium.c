/*
 * medium.c - the medium stack of a ray: what the interface crossings push
 * and pop (interface.c) and where a camera ray starts (trace_media_at).
 */
#include <string.h>
#include "render/medium.h"

real medium_top_ior(const medium_stack *media)
{
    return media->count > 0 ? media->ior[media->count - 1] : 1.0;
}

void medium_push(medium_stack *media, int solid, real ior, trace_stats *st)
{
    if (media->count == MEDIUM_MAX) {
        st->medium_overflow++;
        return;
    }
    media->solid[media->count] = solid;
    media->ior[media->count++] = ior;
}

void medium_remove(medium_stack *media, int solid)
{
    for (int i = media->count - 1; i >= 0; i--) {
        if (media->solid[i] != solid)
            continue;
        /* The top, where a ray leaves the solid it is in, has nothing above
         * it to move down: no two calls of memmove for 0 bytes. */
        if (i < media->count - 1) {
            memmove(&media->solid[i], &media->solid[i + 1], (size_t)(media->count - 1 - i) * sizeof media->solid[0]);
            memmove(&media->ior[i], &media->ior[i + 1], (size_t)(media->count - 1 - i) * sizeof media->ior[0]);
        }
        media->count--;
        return;
    }
}

int medium_find(const medium_stack *media, int solid)
{
    for (int i = media->count - 1; i >= 0; i--)
        if (media->solid[i] == solid)
            return i;
    return -1;
}

int medium_solid_id(const scene_model *s, int prim)
{
    const scene_prim *p = &s->prims[prim];
    if (scene_prim_is_solid(p))
        return prim;
    if (p->kind == PRIM_MESH && p->u.mesh.closed)
        return prim;
    return -1;
}
