/*
 * mem.h - the allocator every allocation of the library goes through.
 *
 * A host can hand the library its own allocator (a fixed arena, a counting
 * wrapper, a pool); a zeroed mem means the C library's malloc, realloc and
 * free.  Objects that outlive a call (a scene, an image, a BVH) keep a copy
 * of the mem they were made with and free through it.
 *
 * The contract, for both sides:
 *   - alloc(user, size) returns memory aligned for any object, or NULL;
 *     size is never 0 (the helpers below ask for 1 byte instead).
 *   - resize(user, p, old_size, new_size) returns a block holding the
 *     first min(old_size, new_size) bytes of p (p itself or a new one, p
 *     then released), or NULL with p untouched.  resize may be NULL: the
 *     library then allocates, copies and releases.
 *   - release(user, p, size) frees p; size is exactly the size p was last
 *     allocated or resized to (so an arena or a counter needs no header).
 * The library never frees memory it did not allocate through the same mem.
 */
#ifndef REFRAY_MEM_H
#define REFRAY_MEM_H

#include <stddef.h>

typedef struct mem {
    void *(*alloc)(void *user, size_t size);
    void *(*resize)(void *user, void *p, size_t old_size, size_t new_size);
    void (*release)(void *user, void *p, size_t size);
    void *user;
} mem;

/* *m, or the C library's allocator when m is NULL or has no alloc. */
mem mem_pick(const mem *m);

/* size bytes (1 when size is 0), or NULL. */
void *mem_alloc(const mem *m, size_t size);
/* count * size zeroed bytes, or NULL (also when the product overflows). */
void *mem_calloc(const mem *m, size_t count, size_t size);
/* p grown or shrunk from old_size to new_size bytes; p NULL allocates.
 * NULL when out of memory, p then untouched. */
void *mem_resize(const mem *m, void *p, size_t old_size, size_t new_size);
/* The same for arrays of count elements of size bytes, overflow-checked. */
void *mem_resize_array(const mem *m, void *p, size_t old_count, size_t new_count, size_t size);
/* Frees p (NULL is fine) of size bytes. */
void mem_free(const mem *m, void *p, size_t size);

/* A copy of text[0..len) with a NUL after it (free with len + 1 bytes). */
char *mem_strndup(const mem *m, const char *text, size_t len);
/* A copy of s (free with strlen(s) + 1 bytes). */
char *mem_strdup(const mem *m, const char *s);
/* Frees a string made by mem_strdup or mem_strndup (NULL is fine). */
void mem_free_string(const mem *m, char *s);


#endif
