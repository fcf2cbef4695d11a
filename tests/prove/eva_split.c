/*
 * eva_split.c - Eva's driver for saturating_div and scale_indices
 * (src/render/shade.c), the two helpers eva_shade.c uses through their
 * contracts.  Both work binade by binade, a relation between two inputs an
 * analysis of intervals loses over the whole range, so the domain is split
 * into the boxes of boxes.h (BOX(2^k, 2^(k+1)) for k = -1074 .. 1022, each
 * without its upper end, then BOX(2^1023, DBL_MAX); tests/prove/prove.sh
 * writes it): the divisor s of
 * saturating_div in each box (the dividend anywhere in [0, DBL_MAX]); the
 * larger index of scale_indices in each box, the other anywhere below it,
 * both ways round.  The boxes cover each precondition.  The file includes
 * shade.c because both helpers are static.
 */
#include "eva.h"
#include "render/shade.c"

volatile real eva_split_real;

static void binade(real lo, real hi)
{
    real s1, s2;
    hi = binade_top(hi);
    eva_split_real = saturating_div(any(0, DBL_MAX), any(lo, hi));
    eva_split_real = scale_indices(any(lo, hi), any(0x1p-1074, hi), &s1, &s2);
    eva_split_real = s1 + s2;
    eva_split_real = scale_indices(any(0x1p-1074, hi), any(lo, hi), &s1, &s2);
    eva_split_real = s1 + s2;
}

void eva_split(void)
{
#define BOX(lo, hi) binade(lo, hi);
#include "boxes.h"
#undef BOX
}
