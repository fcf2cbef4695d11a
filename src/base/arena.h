/*
 * arena.h - a bump allocator for everything one parse builds (syntax nodes,
 * strings) and for what a scene keeps out of line (frames).  Freed in one
 * call, so error recovery in the parser cannot leak; blocks never move, so
 * a pointer into one stays valid until arena_free.
 */
#ifndef REFRAY_ARENA_H
#define REFRAY_ARENA_H

#include <stddef.h>
#include "base/mem.h"

typedef struct arena_block arena_block;

typedef struct arena {
    arena_block *head;
    mem mem;          /* where the blocks come from */
    size_t bytes;     /* held in blocks (a load's memory estimate counts them) */
    size_t first, last; /* block sizes: the first, doubling up to last */
} arena;

/* An empty arena whose blocks come from m (NULL: the C library), 16 KiB each. */
void arena_init(arena *a, const mem *m);
/* The same with blocks of first bytes doubling up to last, for an owner
 * that may need only a few bytes (a zeroed arena: a block per request). */
void arena_init_growing(arena *a, const mem *m, size_t first, size_t last);
void arena_free(arena *a);
/* Zeroed memory aligned for any object; NULL when out of memory. */
void *arena_alloc(arena *a, size_t size);
/* A NUL-terminated copy of text[0..len); NULL when out of memory. */
char *arena_strndup(arena *a, const char *text, size_t len);

#endif
