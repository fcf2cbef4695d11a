/*
 * arena.c - chained blocks; a request larger than a block gets its own.
 */
#include <stdint.h>
#include <string.h>
#include "base/arena.h"

enum { BLOCK_BYTES = 16384 };

/* C99 has no max_align_t: a union of the widest scalar types stands in. */
typedef union arena_align {
    long double ld;
    long long ll;
    void *p;
    double d;
} arena_align;

struct arena_block {
    arena_block *next;
    size_t used, size;
    arena_align data[]; /* flexible array of the strictest alignment */
};

void arena_init(arena *a, const mem *m)
{
    arena_init_growing(a, m, BLOCK_BYTES, BLOCK_BYTES);
}

void arena_init_growing(arena *a, const mem *m, size_t first, size_t last)
{
    a->head = NULL;
    a->mem = mem_pick(m);
    a->bytes = 0;
    a->first = first;
    a->last = last;
}

/* The size of the next block: first, then twice the last one up to last. */
static size_t next_block(const arena *a)
{
    if (!a->head)
        return a->first;
    return a->head->size < a->last / 2 ? 2 * a->head->size : a->last;
}

void arena_free(arena *a)
{
    while (a->head) {
        arena_block *next = a->head->next;
        mem_free(&a->mem, a->head, sizeof *a->head + a->head->size);
        a->head = next;
    }
    a->bytes = 0;
}

static size_t round_up(size_t n)
{
    size_t align = sizeof(arena_align);
    return (n + align - 1) / align * align;
}

void *arena_alloc(arena *a, size_t size)
{
    if (size > SIZE_MAX / 2)
        return NULL;
    size = round_up(size ? size : 1);
    arena_block *b = a->head;
    if (!b || b->size - b->used < size) {
        size_t next = next_block(a), cap = size > next ? size : next;
        b = cap <= SIZE_MAX - sizeof *b ? mem_alloc(&a->mem, sizeof *b + cap) : NULL;
        if (!b)
            return NULL;
        b->used = 0;
        b->size = cap;
        a->bytes += sizeof *b + cap;
        b->next = a->head;
        a->head = b;
    }
    void *p = (char *)b->data + b->used;
    b->used += size;
    memset(p, 0, size);
    return p;
}

char *arena_strndup(arena *a, const char *text, size_t len)
{
    char *s = arena_alloc(a, len + 1);
    if (s) {
        memcpy(s, text, len);
        s[len] = '\0';
    }
    return s;
}
