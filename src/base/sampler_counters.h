/*
 * sampler_counters.h - sampler_mix of the small counters, as constants.
 * A distributed light's sample j extends the shading point's key by the
 * counters 2j and 2j + 1; their mixed halves are the same for every point
 * and every light, so one read-only table serves the whole program instead
 * of a copy per light (attack 18, finding 1: a copy per light cost 1 KiB
 * each and a scene of many point lights 4 times its memory).
 */
#ifndef REFRAY_SAMPLER_COUNTERS_H
#define REFRAY_SAMPLER_COUNTERS_H

#include <stdint.h>

enum { SAMPLER_MIXED_COUNTERS = 128 };

/* sampler_mix(c) for c = 0 .. SAMPLER_MIXED_COUNTERS - 1 (check_json_samples
 * recomputes each entry with sampler_mix). */
extern const uint64_t sampler_mixed_counter[SAMPLER_MIXED_COUNTERS];

#endif
