/*
 * fnv_doubles.h - FNV-1a over the bytes of n doubles: the attack
 * harnesses that print an image's hash so that two builds (the new
 * library and an older one) can be compared line by line.
 */
#ifndef REFRAY_FNV_DOUBLES_H
#define REFRAY_FNV_DOUBLES_H

#include <stddef.h>

static unsigned long long fnv(const double *p, size_t n)
{
    unsigned long long h = 1469598103934665603ull;
    const unsigned char *b = (const unsigned char *)p;
    for (size_t i = 0; i < n * sizeof *p; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

#endif
