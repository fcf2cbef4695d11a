/*
 * tile_fuzz.c - attack 24: attack 23's beam_fuzz.c with the camera's runs
 * as 2-D tiles (the render's own tiling and random tiles).  Otherwise:
 * [BVH-BEAM-1] hit by hit.  For each scene file
 * given, its tracer's tree (renderer_init) is walked by runs of rays that
 * share an origin: the camera's own runs (camera_ray of every pixel, runs
 * of 1 .. 32 pixels starting anywhere in the row, k x k samples), and
 * random runs (an origin at the eye, at a part's box corner or face
 * centre, or anywhere in the scene's box; 1 .. 256 directions in a cone
 * of spread 0 .. 1 about a random direction or about an axis, some
 * components exactly 0 or tiny).  Each run is pruned with the render's
 * cap (64) and with caps 2, 3, 1024 and 8192; every ray's hit by
 * bvh_beam_intersect on each pruned tree is compared with
 * bvh_intersect_ties on the whole tree: met, t, prim, part, point,
 * normal, tmax and the tie count, to the bit.  A difference prints
 * DEFECT and exits 1.
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/tilef \
 *      tests/attack24/tile_fuzz.c build/librefray-internal.a -ljansson -lm
 *   /tmp/tilef SEED RUNS FILE.scene...
 */
#define BEAM_FUZZ_TILES 1
#include "../attack23/beam_fuzz.c"
