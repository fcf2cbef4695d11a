/*
 * cli_alloc.c - see cli_alloc.h.
 */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS, madvise */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include "cli/cli_alloc.h"

#if defined(MAP_ANONYMOUS) && defined(MADV_HUGEPAGE)
#define HAVE_HUGE 1
#else
#define HAVE_HUGE 0
#endif

/* Huge pages need 2 MB alignment; the mapping is made that much larger and
 * the ends trimmed. */
#define HUGE_PAGE ((size_t)2 << 20)

static int is_big(size_t size) { return HAVE_HUGE && size >= CLI_ALLOC_BIG; }

static size_t mapped_size(size_t size) { return (size + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE; }

void *cli_alloc(void *user, size_t size)
{
    (void)user;
    if (!is_big(size))
        return malloc(size);
#if HAVE_HUGE
    size_t want = mapped_size(size);
    if (want < size || want + HUGE_PAGE < want)
        return NULL;
    char *raw = mmap(NULL, want + HUGE_PAGE, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED)
        return NULL;
    size_t lead = (HUGE_PAGE - (size_t)((uintptr_t)raw % HUGE_PAGE)) % HUGE_PAGE;
    if (lead > 0)
        munmap(raw, lead);
    if (HUGE_PAGE - lead > 0)
        munmap(raw + lead + want, HUGE_PAGE - lead);
    /* Only advice: without huge pages the block still works. */
    madvise(raw + lead, want, MADV_HUGEPAGE);
    return raw + lead;
#else
    return NULL;
#endif
}

void cli_release(void *user, void *p, size_t size)
{
    (void)user;
    if (!p)
        return;
    if (!is_big(size)) {
        free(p);
        return;
    }
#if HAVE_HUGE
    munmap(p, mapped_size(size));
#endif
}

void *cli_resize(void *user, void *p, size_t old_size, size_t new_size)
{
    if (!is_big(old_size) && !is_big(new_size))
        return realloc(p, new_size);
    if (is_big(old_size) && is_big(new_size) && mapped_size(new_size) == mapped_size(old_size))
        return p;
    void *q = cli_alloc(user, new_size);
    if (!q)
        return NULL;
    memcpy(q, p, old_size < new_size ? old_size : new_size);
    cli_release(user, p, old_size);
    return q;
}

const rf_allocator *cli_allocator(void)
{
    static const rf_allocator a = {cli_alloc, cli_resize, cli_release, NULL};
    return &a;
}
