/*
 * gen.h - random scenes as text, one statement per line, from a seed.
 *
 * Two profiles share the generator:
 *   DTGEN_EXACT  what `refray export --to pov` maps exactly (spec/
 *                crosscheck.md): spheres, boxes, cylinders, cones and tori
 *                (closed and open), disks, triangles, planes, OBJ meshes
 *                with and without normals, transforms with mirroring, both
 *                cameras (also inside solids), point lights with falloff
 *                none or linear with d0 > 0, distant lights, ambient, grey
 *                Ks, glass spheres with Ks + t = 1 apart from every other
 *                surface; for `make difftest` (tests/difftest/difftest.c),
 *                which still drops any scene whose export lists an
 *                approximation.
 *   DTGEN_ANY    everything the language has, in small images, with lone
 *                primitives and cameras inside solids often: for the
 *                shortcuts-on/off test (tests/check_shortcuts.c).
 * The same seed and profile give the same text on every machine: the
 * numbers come from the counter-based sampler (base/sampler.h) and are
 * printed with 17 digits.
 */
#ifndef REFRAY_DIFFTEST_GEN_H
#define REFRAY_DIFFTEST_GEN_H

#include <stddef.h>
#include <stdint.h>

enum { DTGEN_TEXT_MAX = 16384, DTGEN_STMT_MAX = 40 };

typedef enum dtgen_profile { DTGEN_EXACT, DTGEN_ANY } dtgen_profile;

typedef struct dtgen_scene {
    char text[DTGEN_TEXT_MAX];
    size_t len;
    int count;                         /* statements: 0 is `image`, 1 is `camera` */
    size_t start[DTGEN_STMT_MAX + 1];  /* statement i is text[start[i] .. start[i + 1]) */
} dtgen_scene;

/* Fills out with the scene of seed in profile.  OBJ files are named
 * obj_dir/NAME.obj (obj_dir as the scene will be read: relative to the
 * scene file's directory, or absolute). */
void dtgen_make(dtgen_scene *out, uint64_t seed, dtgen_profile profile, const char *obj_dir);

/* The scene of dtgen_make moved as a whole to offset + scale x (every
 * point, length, light and the camera; the objects by a trailing `scale`
 * and `translate`): the same scene far from the origin or tiny, for the
 * shortcuts-on/off test at extreme magnitudes.  Scale 1 and offset 0 give
 * dtgen_make's text. */
void dtgen_make_placed(dtgen_scene *out, uint64_t seed, dtgen_profile profile, const char *obj_dir, double scale,
                       const double offset[3]);

/* The statements i with keep[i] != 0 (statements 0 and 1 always) into buf
 * (size bytes, NUL-terminated); returns the length, or 0 when it does not
 * fit. */
size_t dtgen_subset(const dtgen_scene *s, const unsigned char *keep, char *buf, size_t size);

#endif
