/*
 * cli_alloc.h - the refray program's allocator for scenes and renders.
 *
 * Blocks of CLI_ALLOC_BIG bytes or more (a big scene's primitive array, its
 * BVH) are mapped on their own and, where the kernel offers it
 * (madvise(MADV_HUGEPAGE), Linux), backed by 2 MB pages: a 100 000-sphere
 * scene then takes a few dozen page faults for those arrays instead of
 * about ten thousand, which were a fifth of its load and build time
 * (spec/performance.md).  Smaller blocks are malloc's.  Thread-safe, no
 * state.
 */
#ifndef REFRAY_CLI_ALLOC_H
#define REFRAY_CLI_ALLOC_H

#include <stddef.h>
#include "refray.h"

#define CLI_ALLOC_BIG ((size_t)4 << 20)

const rf_allocator *cli_allocator(void);

void *cli_alloc(void *user, size_t size);
void *cli_resize(void *user, void *p, size_t old_size, size_t new_size);
void cli_release(void *user, void *p, size_t size);

#endif
