/*
 * sampler.h - counter-based random numbers: a value is a pure function of
 * its key (pixel, camera sample, light, light sample, ray path), so a render
 * is bit-identical every time and needs no generator state.
 *
 * The mixer is the SplitMix64 finaliser (Steele, Lea, Flood, "Fast
 * splittable pseudorandom number generators", OOPSLA 2014), a bijection on
 * 64-bit words with good avalanche; keys are combined by mixing each word in
 * turn.
 */
#ifndef REFRAY_SAMPLER_H
#define REFRAY_SAMPLER_H

#include <stdint.h>

/* The finaliser's constants, named so that `refray export --to json`
 * writes the rule from the same numbers the sampler uses. */
#define SAMPLER_GAMMA 0x9e3779b97f4a7c15ULL
#define SAMPLER_MUL1 0xbf58476d1ce4e5b9ULL
#define SAMPLER_MUL2 0x94d049bb133111ebULL
#define SAMPLER_SHIFT1 30
#define SAMPLER_SHIFT2 27
#define SAMPLER_SHIFT3 31

static inline uint64_t sampler_mix(uint64_t z)
{
    z += SAMPLER_GAMMA;
    z = (z ^ (z >> SAMPLER_SHIFT1)) * SAMPLER_MUL1;
    z = (z ^ (z >> SAMPLER_SHIFT2)) * SAMPLER_MUL2;
    return z ^ (z >> SAMPLER_SHIFT3);
}

/* sampler_key with its counter already mixed (sampler_mix(counter)): the
 * counter's half depends on the counter alone, so a caller that extends
 * many keys by the same counters (the samples of a distributed light) can
 * mix those once. */
static inline uint64_t sampler_key_mixed(uint64_t key, uint64_t mixed_counter)
{
    return sampler_mix(key ^ mixed_counter);
}

/* A key extended by one more counter. */
static inline uint64_t sampler_key(uint64_t key, uint64_t counter)
{
    return sampler_key_mixed(key, sampler_mix(counter));
}

/* A double in [0, 1): the top 53 bits of the mixed key. */
static inline double sampler_uniform(uint64_t key)
{
    return (double)(sampler_mix(key) >> 11) * (1.0 / 9007199254740992.0);
}

#endif
