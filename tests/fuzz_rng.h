/*
 * fuzz_rng.h - the random numbers of the attack harnesses (tests/attack22,
 * tests/attack23: standalone programs, one per run, so one sequence per
 * program is enough): splitmix64 with the library's own finaliser, so a
 * seed names the same cases in each.  Set `rng` to the seed first.
 */
#ifndef REFRAY_FUZZ_RNG_H
#define REFRAY_FUZZ_RNG_H

#include <stdint.h>
#include "base/sampler.h"

static uint64_t rng = 1;

static uint64_t R64(void)
{
    uint64_t z = sampler_mix(rng);
    rng += SAMPLER_GAMMA;
    return z;
}

/* A double in [0, 1). */
static double U(void) { return (R64() >> 11) * 0x1p-53; }

#endif
