/*
 * kit.h - the conformance kit (`refray kit -o DIR`, spec/conformance.md):
 * every analytic scene given, with its exact image, mask, exports and one
 * manifest, in a directory another renderer's author can use without
 * refray.
 *
 * Layout of DIR:
 *   README.md                    one page: how to render and check
 *   manifest.json                manifest.h
 *   scenes/NAME/NAME.scene       the scene as written
 *   scenes/NAME/NAME.json        the scene as JSON (when the build exports it)
 *   scenes/NAME/NAME.pov         POV-Ray 3.7 SDL, lights scaled by png16_scale
 *   scenes/NAME/NAME.exact.exr   the exact image, 32-bit float (EXR=1 builds)
 *   scenes/NAME/NAME.exact.pfm   the same, PFM
 *   scenes/NAME/NAME.mask.pgm    excluded pixels, 255 (binary 8-bit PGM)
 *   scenes/NAME/NAME.mask.png    the same, 8-bit PNG (PNG=1 builds)
 * NAME is the scene file's name without ".scene".
 */
#ifndef REFRAY_KIT_H
#define REFRAY_KIT_H

#include <stddef.h>
#include <stdio.h>
#include "scene/scene.h"
#include "verify/manifest.h"

typedef struct kit_opts {
    scene_limits limits;      /* for loading the scenes */
    int warnings;          /* print the scenes' warnings */
    FILE *diag;            /* the scenes' diagnostics */
    const char *version;   /* refray's version, for the manifest and README */
    int (*cancel)(void *user); /* asked between scenes: non-zero stops the build,
                                  STATUS_CANCELLED, nothing left; NULL: never */
    void *cancel_user;
    const char *const *read_dirs; /* [REL-READ-1] NULL-ended directories a scene's
                                     include and mesh files may come from beside
                                     the scene's own tree; NULL: none */
} kit_opts;

/*
 * Builds the kit of the count scenes in dir.  It is built in a new
 * directory next to dir and renamed onto it when complete, so dir is
 * either the whole new kit or left as it was.  dir may be missing (its
 * parents are made), empty, or an earlier kit (one with a manifest.json),
 * which is replaced; anything else is refused.  On success *out holds the
 * manifest (free with manifest_free).
 *
 * Returns STATUS_OK; STATUS_USAGE (no JSON in this build, dir not a kit,
 * two scenes of one name); STATUS_DATA (a bad scene, one without an
 * `oracle` the family accepts, one that reads other files);
 * STATUS_NO_INPUT (a missing scene); STATUS_IO; STATUS_NO_MEMORY; with the
 * reason in why (a scene's own diagnostics go to o->diag).
 */
int kit_build(const char *dir, const char *const *scenes, int count, const kit_opts *o, manifest *out, char *why,
              size_t why_size);

/* Writes the kit's README.md for m into path, atomically; STATUS_OK or the
 * status of file_write_atomic with the reason in why. */
int kit_readme_write(const char *path, const manifest *m, char *why, size_t why_size);

#endif
