/*
 * hash.h - FNV-1a, 64 bits (Fowler, Noll, Vo; offset basis 14695981039346656037,
 * prime 1099511628211): a fingerprint of bytes for telling inputs apart, not
 * a defence against anyone crafting a collision.
 */
#ifndef REFRAY_HASH_H
#define REFRAY_HASH_H

#include <stddef.h>
#include <stdint.h>

#define HASH_FNV_START 0xcbf29ce484222325ULL

/* h extended by the n bytes at p. */
static inline uint64_t hash_bytes(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 0x100000001b3ULL;
    return h;
}

/* h extended by v as 8 little-endian bytes, whatever the host's order. */
static inline uint64_t hash_u64(uint64_t h, uint64_t v)
{
    unsigned char b[8];
    for (int i = 0; i < 8; i++)
        b[i] = (unsigned char)(v >> (8 * i));
    return hash_bytes(h, b, sizeof b);
}

#endif
