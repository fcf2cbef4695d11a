/*
 * memcheck.h - an allocator for the tests of the allocator hook: it counts
 * the bytes and blocks live, keeps each block's size in a header to check
 * that every release names the size the block was made with, and fails on
 * request (after a number of calls, or past a number of live bytes).
 */
#ifndef REFRAY_MEMCHECK_H
#define REFRAY_MEMCHECK_H

#include <stdlib.h>
#include <string.h>

typedef struct memcheck {
    size_t live;          /* bytes allocated and not yet released */
    size_t peak;
    long blocks;          /* blocks live */
    long calls;           /* allocations and growing resizes so far */
    long fail_after;      /* calls that succeed before every later one fails; < 0: never */
    size_t max_live;      /* a call that would pass this many live bytes fails; 0: no cap */
    long failures;        /* calls refused */
    long bad_sizes;       /* releases or resizes that named a wrong size */
} memcheck;

typedef union memcheck_header {
    size_t size;
    long double align;
} memcheck_header;

static inline void memcheck_init(memcheck *c)
{
    memset(c, 0, sizeof *c);
    c->fail_after = -1;
}

static inline int memcheck_refuse(memcheck *c, size_t more)
{
    long call = c->calls++;
    if ((c->fail_after >= 0 && call >= c->fail_after) || (c->max_live && c->live + more > c->max_live)) {
        c->failures++;
        return 1;
    }
    return 0;
}

static inline void memcheck_count(memcheck *c, long double_blocks, size_t add, size_t sub)
{
    c->blocks += double_blocks;
    c->live = c->live + add - sub;
    if (c->live > c->peak)
        c->peak = c->live;
}

static inline void *memcheck_alloc(void *user, size_t size)
{
    memcheck *c = user;
    if (size == 0 || memcheck_refuse(c, size))
        return NULL;
    memcheck_header *h = malloc(sizeof *h + size);
    if (!h)
        return NULL;
    h->size = size;
    memcheck_count(c, 1, size, 0);
    return h + 1;
}

static inline void *memcheck_resize(void *user, void *p, size_t old_size, size_t new_size)
{
    memcheck *c = user;
    memcheck_header *h = (memcheck_header *)p - 1;
    if (h->size != old_size)
        c->bad_sizes++;
    if (new_size > old_size && memcheck_refuse(c, new_size - old_size))
        return NULL;
    memcheck_header *moved = realloc(h, sizeof *h + new_size);
    if (!moved)
        return NULL;
    moved->size = new_size;
    memcheck_count(c, 0, new_size, old_size);
    return moved + 1;
}

static inline void memcheck_release(void *user, void *p, size_t size)
{
    memcheck *c = user;
    memcheck_header *h = (memcheck_header *)p - 1;
    if (h->size != size)
        c->bad_sizes++;
    memcheck_count(c, -1, 0, h->size);
    free(h);
}

#endif
