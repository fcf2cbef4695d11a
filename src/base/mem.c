/*
 * mem.c - the allocator hook (mem.h) and the C library's allocator behind
 * it: the one file of the core that calls malloc, realloc and free.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "base/mem.h"

static void *libc_alloc(void *user, size_t size)
{
    (void)user;
    return malloc(size);
}

static void *libc_resize(void *user, void *p, size_t old_size, size_t new_size)
{
    (void)user;
    (void)old_size;
    return realloc(p, new_size);
}

static void libc_release(void *user, void *p, size_t size)
{
    (void)user;
    (void)size;
    free(p);
}

mem mem_pick(const mem *m)
{
    if (m && m->alloc)
        return *m;
    mem libc = {libc_alloc, libc_resize, libc_release, NULL};
    return libc;
}

void *mem_alloc(const mem *m, size_t size)
{
    mem a = mem_pick(m);
    return a.alloc(a.user, size ? size : 1);
}

void *mem_calloc(const mem *m, size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    size_t bytes = count * size > 0 ? count * size : 1;
    void *p = mem_alloc(m, bytes);
    if (p)
        memset(p, 0, bytes);
    return p;
}

void *mem_resize(const mem *m, void *p, size_t old_size, size_t new_size)
{
    mem a = mem_pick(m);
    if (!p)
        return mem_alloc(m, new_size);
    old_size = old_size ? old_size : 1;
    new_size = new_size ? new_size : 1;
    if (a.resize)
        return a.resize(a.user, p, old_size, new_size);
    void *q = a.alloc(a.user, new_size);
    if (!q)
        return NULL;
    memcpy(q, p, old_size < new_size ? old_size : new_size);
    a.release(a.user, p, old_size);
    return q;
}

void *mem_resize_array(const mem *m, void *p, size_t old_count, size_t new_count, size_t size)
{
    if (size && new_count > SIZE_MAX / size)
        return NULL;
    return mem_resize(m, p, old_count * size, new_count * size);
}

void mem_free(const mem *m, void *p, size_t size)
{
    if (!p)
        return;
    mem a = mem_pick(m);
    a.release(a.user, p, size ? size : 1);
}

char *mem_strndup(const mem *m, const char *text, size_t len)
{
    char *s = len < SIZE_MAX ? mem_alloc(m, len + 1) : NULL;
    if (s) {
        memcpy(s, text, len);
        s[len] = '\0';
    }
    return s;
}

char *mem_strdup(const mem *m, const char *s)
{
    return mem_strndup(m, s, strlen(s));
}

void mem_free_string(const mem *m, char *s)
{
    if (s)
        mem_free(m, s, strlen(s) + 1);
}
