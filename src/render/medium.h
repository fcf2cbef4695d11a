/*
 * medium.h - the medium stack of a ray (trace.h's medium_stack): the
 * transparent solids it is inside, innermost last, each with its ior.
 * A solid pushed past MEDIUM_MAX is counted in trace_stats.medium_overflow
 * and the render refuses the image ([REL-MEDIUM-1]).
 */
#ifndef REFRAY_MEDIUM_H
#define REFRAY_MEDIUM_H

#include "render/trace.h"

/* The ior of the innermost solid, 1 (air) when the stack is empty. */
real medium_top_ior(const medium_stack *media);
/* Puts solid on top; a full stack counts an overflow in st instead. */
void medium_push(medium_stack *media, int solid, real ior, trace_stats *st);
/* Takes solid off wherever it is (solids may overlap); absent: nothing. */
void medium_remove(medium_stack *media, int solid);
/* The index of solid in the stack, the innermost match; -1 when absent. */
int medium_find(const medium_stack *media, int solid);

/* Identity of the solid a primitive is, what the stack holds (sphere, box,
 * closed cylinder or cone, torus, closed mesh: its index), or -1 for a
 * sheet (plane, disk, lone triangle, open cylinder or cone, a mesh that is
 * not closed), which has no inside. */
int medium_solid_id(const scene_model *s, int prim);

#endif
