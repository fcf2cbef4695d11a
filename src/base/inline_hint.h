/*
 * inline_hint.h - the inlining hints the hot paths use, in one place.
 *
 * Each is a hint about where code goes, never about what it computes (the
 * build has -ffp-contract=off, so the same operations give the same bits
 * inlined or called); each use says why it is there (spec/performance.md
 * has the figures).  gcc and clang (which defines __GNUC__) know the
 * attributes; Frama-C need not see them.
 */
#ifndef REFRAY_INLINE_HINT_H
#define REFRAY_INLINE_HINT_H

#if defined(__GNUC__) && !defined(__FRAMAC__)
#define HINT_IN_LINE __attribute__((always_inline))
#define HINT_OUT_OF_LINE __attribute__((noinline))
#define HINT_FLATTEN __attribute__((flatten))
#else
#define HINT_IN_LINE
#define HINT_OUT_OF_LINE
#define HINT_FLATTEN
#endif

#endif
