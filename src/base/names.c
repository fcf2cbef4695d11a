/*
 * names.c - see names.h.  Separate chaining through two int arrays: a
 * bucket's chain runs newest to oldest, so the newest entry is always the
 * head of its chain and removing it (scopes end newest first) is O(1).
 * The table doubles when it holds two entries per bucket on average.
 */
#include <string.h>
#include "base/names.h"

/* FNV-1a over the name's bytes. */
static unsigned hash(const char *s)
{
    unsigned h = 2166136261u;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 16777619u;
    return h;
}

void name_index_init(name_index *x, name_of_fn name_of, const void *ctx, const mem *m)
{
    memset(x, 0, sizeof *x);
    x->name_of = name_of;
    x->ctx = ctx;
    x->mem = mem_pick(m);
}

void name_index_free(name_index *x)
{
    mem_free(&x->mem, x->heads, (size_t)x->bucket_count * sizeof *x->heads);
    mem_free(&x->mem, x->next, (size_t)x->entry_cap * sizeof *x->next);
    name_index_init(x, x->name_of, x->ctx, &x->mem);
}

/* Relinks every named entry below limit into buckets of count heads. */
static int rebuild(name_index *x, int buckets, int limit)
{
    int *heads = mem_alloc(&x->mem, (size_t)buckets * sizeof *heads);
    if (!heads)
        return 0;
    for (int b = 0; b < buckets; b++)
        heads[b] = -1;
    mem_free(&x->mem, x->heads, (size_t)x->bucket_count * sizeof *x->heads);
    x->heads = heads;
    x->bucket_count = buckets;
    for (int i = 0; i < limit; i++) {
        const char *name = x->name_of(x->ctx, i);
        if (!name || x->next[i] == -2)
            continue;
        unsigned b = hash(name) & (unsigned)(buckets - 1);
        x->next[i] = heads[b];
        heads[b] = i;
    }
    return 1;
}

int name_index_add(name_index *x, int entry)
{
    const char *name = x->name_of(x->ctx, entry);
    if (!name)
        return 1;
    if (entry >= x->entry_cap) {
        int cap = x->entry_cap ? x->entry_cap : 16;
        while (cap <= entry)
            cap *= 2;
        int *next = mem_resize_array(&x->mem, x->next, (size_t)x->entry_cap, (size_t)cap, sizeof *next);
        if (!next)
            return 0;
        /* -2: not linked (an entry without a name, or one removed). */
        for (int i = x->entry_cap; i < cap; i++)
            next[i] = -2;
        x->next = next;
        x->entry_cap = cap;
    }
    if (x->count + 1 > 2 * x->bucket_count && !rebuild(x, x->bucket_count ? 2 * x->bucket_count : 64, entry))
        return 0;
    unsigned b = hash(name) & (unsigned)(x->bucket_count - 1);
    x->next[entry] = x->heads[b];
    x->heads[b] = entry;
    x->count++;
    return 1;
}

/* strcmp(a, b) == 0 without the library call: the names of a scene are
 * short (loop variables, materials), and a find is nearly always a hit,
 * so the call, not the bytes, was most of a comparison's cost. */
static int same_name(const char *a, const char *b)
{
    while (*a && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

int name_index_find(name_index *x, const char *name)
{
    if (!x->bucket_count)
        return -1;
    for (int i = x->heads[hash(name) & (unsigned)(x->bucket_count - 1)]; i >= 0; i = x->next[i]) {
        x->comparisons++;
        if (same_name(x->name_of(x->ctx, i), name))
            return i;
    }
    return -1;
}

void name_index_remove(name_index *x, int entry)
{
    const char *name = entry < x->entry_cap && x->next[entry] != -2 ? x->name_of(x->ctx, entry) : NULL;
    if (!name)
        return;
    unsigned b = hash(name) & (unsigned)(x->bucket_count - 1);
    /* The newest entry heads its bucket's chain. */
    if (x->heads[b] == entry)
        x->heads[b] = x->next[entry];
    x->next[entry] = -2;
    x->count--;
}
