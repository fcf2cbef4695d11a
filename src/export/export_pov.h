/*
 * export_pov.h - a refray scene as POV-Ray 3.7 SDL (`refray export --to
 * pov`), so that POV-Ray can be checked against refray's oracle
 * (spec/crosscheck.md has the mapping, construct by construct).
 *
 * What maps exactly: the camera (perspective and orthographic; POV-Ray is
 * left-handed, so every point and direction has its z negated, a mirror
 * that keeps the picture), the image size and k x k pixel grid (rendered at
 * k times the size and box-filtered back), ambient, Lambert and Phong terms
 * (phong Ks, phong_size n is Ks (V.R)^n), mirror reflection, the (1 - t)
 * body weight and t-weighted transmission (transmit t), refraction into
 * solids (interior ior), tinted unbent shadows, point and distant lights
 * with falloff none, `linear` with d0 > 0 (POV-Ray's fading
 * 2/(1 + d/d0) times E/(2 d0) is E/(d + d0)), max_depth as max_trace_level.
 * What is approximated is written as a comment in the SDL and returned in
 * pov_notes; what cannot be approximated usefully is refused.
 */
#ifndef REFRAY_EXPORT_POV_H
#define REFRAY_EXPORT_POV_H

#include <stddef.h>
#include <stdio.h>
#include "export/export_pov_far.h"
#include "scene/scene.h"

enum { POV_NOTE_MAX = 24, POV_NOTE_LEN = 320 };

/* What an export could not map exactly. */
typedef struct pov_notes {
    int refused;                           /* 1: the scene cannot be exported */
    char reason[POV_NOTE_LEN];             /* why, when refused */
    int count;                             /* approximations found (may pass POV_NOTE_MAX) */
    char text[POV_NOTE_MAX][POV_NOTE_LEN]; /* the first POV_NOTE_MAX of them, one line each */
} pov_notes;

typedef struct pov_opts {
    /* 0 (default): each distributed light becomes its `samples` point
     * sources at the centres of its cells, which is the seed's model with
     * refray's jitter left out.  1: one POV-Ray area_light per light, which
     * averages visibility apart from shading (approximate in penumbrae). */
    int area_lights;
    const char *source;  /* the scene's path for the header comment, or NULL */
    /* > 0: every light, the ambient light and the background are
     * multiplied by scale, and so is the whole image (it is linear in
     * them jointly); a power of two keeps every value exact.  It lets an
     * image brighter than 1 fit a 16-bit file.  0 means 1. */
    double scale;
    /* 1: surfaces that pass rays straight on keep ior 1, so POV-Ray does
     * not count those passes as trace levels (spec/crosscheck.md,
     * [XCHK-MAP-LEVEL-1]); 0 (default): each gets its own ior
     * 1 + j POV_NUDGE, which POV-Ray counts as refray does. */
    int plain_sheets;
    /* 1: refray's image to compare with is rendered with
     * render_opts.facet_shadows (shadow rays of smooth meshes from the
     * facet, as POV-Ray), so [XCHK-MAP-MESH-3] is not listed. */
    int facet_shadows;
} pov_opts;

/* The largest max_trace_level POV-Ray 3.7 accepts (it clamps to it). */
#define POV_MAX_TRACE_LEVEL 256

/* Fade distances that stand in for d0 = 0, relative to the scene's size:
 * E/(d + D) and E/(d^2 + D^2) differ from E/d and E/d^2 by about D/d and
 * (D/d)^2 relative. */
#define POV_LINEAR_FADE 1e-9
#define POV_SQUARE_FADE 1e-5

/* The step between the iors of straight-passing surfaces: 2^-22, two
 * float steps at 1 (POV-Ray keeps iors as floats and continues a ray
 * unbent and uncounted when the ratio is within 1e-10 of 1).  The j-th such
 * surface gets 1 + (1 + j mod POV_NUDGE_CYCLE) POV_NUDGE. */
#define POV_NUDGE (1.0 / 4194304.0)
#define POV_NUDGE_CYCLE 1024

/*
 * Finds what cannot be mapped: fills notes (cleared first) and returns 1
 * when s can be exported, 0 when it is refused (the reason in notes).
 */
int pov_export_check(const scene_model *s, const pov_opts *o, pov_notes *notes);

/*
 * Writes s as SDL to fp: a header comment that names the povray options
 * the render needs and how to read the image back (`// pov-args:`,
 * `// pov-downsample:` and `// pov-scale:` lines, read by
 * tests/crosscheck.sh) and lists the approximations, then the scene.
 * Returns 0; STATUS_DATA when refused (nothing written); or
 * STATUS_IO when a write to fp failed.  notes as pov_export_check.
 */
int pov_export_write(const scene_model *s, const pov_opts *o, FILE *fp, pov_notes *notes);

/*
 * The same into path through the atomic writer (io/atomic.h): path holds
 * the whole export or is left as it was.  Returns as
 * pov_export_write, with a one-line reason in err (errlen bytes; err may be
 * NULL only when errlen is 0) for an I/O error.
 */
int pov_export_file(const scene_model *s, const pov_opts *o, const char *path, pov_notes *notes, char *err,
                    size_t errlen);

#endif
