/*
 * eva_toward.c - Eva's driver for unit_toward (src/render/intersect.c,
 * included: it is static), a shadow ray's direction to / |to|.
 *
 * It divides each component of to by |to| (vec_length_fast, used by its
 * contract: between M/4 and 7M, M the largest component): a ratio an
 * analysis of intervals loses when M ranges over every double.  So the
 * domain is split as eva_vec.c splits it: M in one binade [2^k, 2^(k+1)),
 * taken by one component of one sign (largest_at), the other two in
 * [-2^(k+1), 2^(k+1)], for the BOX lines of boxes.h (tests/prove/prove.sh
 * writes them), and the zero vector.  In each box the quotients lie in
 * [-8, 8], and the boxes below 2^-1024 are where 1/|to| is infinite and the
 * components are divided instead.
 */
#include "eva.h"
#include "render/intersect.c"

volatile real eva_toward_real;
volatile vec3 eva_toward_vec;

static void toward(vec3 to)
{
    real d;
    eva_toward_vec = unit_toward(to, &d);
    eva_toward_real = d;
}

static void toward_binade(real lo, real hi)
{
    if (lo > 0x1p1022)
        return;   /* past the precondition */
    hi = lo == 0x1p1022 ? lo : binade_top(hi);
    for (int axis = 0; axis < 3; axis++) {
        toward(largest_at(axis, 1, lo, hi));
        toward(largest_at(axis, -1, lo, hi));
    }
}

void eva_toward(void)
{
    toward(vec_make(0, 0, 0));
#define BOX(lo, hi) toward_binade(lo, hi);
#include "boxes.h"
#undef BOX
}
