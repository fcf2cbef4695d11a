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

/* HINT_IN_LINE_EXTERN: a function of external linkage that the link-time
 * optimiser inlines into its callers in other files.  gcc takes
 * always_inline only beside `inline` (the header's declaration has none, so
 * the definition stays an external one); clang, which builds without LTO
 * here, takes it alone, and with `inline` would warn of the static helpers
 * such a definition calls (-Wstatic-in-inline). */
#if defined(__GNUC__) && !defined(__FRAMAC__)
#define HINT_IN_LINE __attribute__((always_inline))
#define HINT_OUT_OF_LINE __attribute__((noinline))
#define HINT_FLATTEN __attribute__((flatten))
#if defined(__clang__)
#define HINT_IN_LINE_EXTERN __attribute__((always_inline))
#else
#define HINT_IN_LINE_EXTERN __attribute__((always_inline)) inline
#endif
#else
#define HINT_IN_LINE
#define HINT_OUT_OF_LINE
#define HINT_FLATTEN
#define HINT_IN_LINE_EXTERN
#endif

#endif
