/*
 * names.h - finding a name among many in constant expected time: an index
 * over entries 0, 1, 2, ... of a caller's array (constants in scope,
 * materials), hashed by name ([REL-COMPLEXITY-1] of spec/reliability.md:
 * a load does O(1) expected name comparisons per lookup, so a scene of N
 * definitions loads in O(N), where a list made it O(N^2)).
 *
 * The index does not hold the names: name_of(ctx, i) gives entry i's (or
 * NULL for an entry that has none).  Entries are added in increasing order
 * and removed newest first, as scopes are; among entries of one name the
 * newest is found, so an inner binding hides an outer one.
 */
#ifndef REFRAY_NAMES_H
#define REFRAY_NAMES_H

#include "base/mem.h"

typedef const char *(*name_of_fn)(const void *ctx, int entry);

typedef struct name_index {
    int *heads;          /* per bucket: its newest entry, -1 when empty */
    int *next;           /* per entry: the next older entry of its bucket */
    int bucket_count;    /* a power of two, or 0 before the first add */
    int entry_cap;       /* entries next can hold */
    int count;           /* entries linked */
    long comparisons;    /* names compared by every find so far */
    name_of_fn name_of;
    const void *ctx;
    mem mem;
} name_index;

/* An empty index over the entries named by name_of(ctx, i); memory from m
 * (NULL: the C library). */
void name_index_init(name_index *x, name_of_fn name_of, const void *ctx, const mem *m);
void name_index_free(name_index *x);

/* Links entry (greater than every entry linked before) under its name.
 * Returns 1, or 0 when out of memory (the index is unchanged then). */
int name_index_add(name_index *x, int entry);

/* The newest entry named name, or -1. */
int name_index_find(name_index *x, const char *name);

/* Unlinks entry, which must be the newest one linked. */
void name_index_remove(name_index *x, int entry);

#endif
