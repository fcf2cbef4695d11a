/*
 * verify.h - a render checked against its exact image (spec/verify.md).
 *
 * The library side of `refray verify`, `refray oracle` and `refray
 * compare`: the scene's family found and asked whether it accepts the
 * scene, the exact image built at the tracer's sample points, the render
 * timed and compared, sweeps over the light or pixel samples with the
 * convergence order fitted, and the JSON, error-map and mask files.  The
 * command-line driver only parses options and prints.
 *
 * Statuses are those of base/status.h: STATUS_OK pass, STATUS_FAIL a check
 * failed (an error over the tolerance, a refused scene, an unknown family),
 * STATUS_DATA a bad scene (no `oracle` statement included), STATUS_NO_INPUT
 * a missing file, STATUS_NO_MEMORY.  A run over many scenes exits with the
 * largest exit code it met ([VERIFY-EXIT-1]): 70 > 66 > 65 > 1 > 0
 * (status_worse); the JSON's "status" is that exit code.
 */
#ifndef REFRAY_VERIFY_H
#define REFRAY_VERIFY_H

#include <stddef.h>
#include <float.h>
#include <stdio.h>
#include "verify/fit.h"
#include "io/image_io.h"
#include "image/metrics.h"
#include "oracle/oracle.h"
#include "scene/scene.h"

/* Overrides of the scene's image settings; 0 keeps the scene's own. */
typedef struct verify_opts {
    int width, height;
    int samples;        /* k of the k x k camera grid */
    int max_depth;
    int light_samples;  /* samples of every distributed light */
    int runs;           /* renders timed, the median reported; 0 or 1: one */
    int (*cancel)(void *user); /* stops a render (render_opts.cancel); NULL: never */
    void *cancel_user;
} verify_opts;

/* Most renders --runs may ask for. */
enum { VERIFY_RUNS_MAX = 99 };

typedef enum verify_verdict {
    VERIFY_PASS,        /* every compared pixel within the tolerance */
    VERIFY_FAIL,        /* some pixel over it, or no pixel left to compare */
    VERIFY_REFUSED,     /* unknown family, or the family refused the scene */
    VERIFY_ERROR        /* the scene could not be loaded, has no oracle, out of memory */
} verify_verdict;

/* One render compared with its exact image. */
typedef struct verify_result {
    char scene[512];          /* the path as given (cut if longer) */
    char family[64];          /* the scene's `oracle` name, "" when none */
    verify_verdict verdict;
    int status;               /* this scene's status (see the top) */
    char reason[512];         /* why, for REFUSED, ERROR and a FAIL with no pixels */
    int width, height, samples, max_depth;
    int light_samples;        /* the override, 0 for each light's own */
    int sampled;              /* the family converges with the light samples */
    image_metrics metrics;    /* valid when measured */
    int measured;             /* the render was compared: PASS, FAIL, or REFUSED
                                 for a bound of VERIFY_DECISIVE_BELOW or more
                                 (VERIFY_UNBOUNDED) */
    double tolerance;         /* relative, the family's for this render */
    double render_seconds;    /* wall time of render_image, BVH build included
                                 (the median of opts.runs renders) */
    double oracle_seconds;    /* wall time of oracle_image */
    long rays;                /* every ray traced: camera, shadow, reflected, refracted */
} verify_result;

/* An exact image and its excluded pixels. */
typedef struct verify_exact {
    const oracle_family *family;
    oracle_view view;
    img_buf image;
    unsigned char *excluded;  /* width*height flags */
    long excluded_count;
    double seconds;
} verify_exact;

/* The view a render with options o makes of s (the overrides applied). */
oracle_view verify_view(const scene_model *s, const verify_opts *o);

/*
 * The family of s, if it accepts view v.  Returns it, or NULL with the
 * reason in why and *status STATUS_DATA (no `oracle` statement) or STATUS_FAIL (no family of
 * that name, or the family refused the scene: its own reason).
 */
/* The reason every tool gives for a scene whose exact image the oracle
 * cannot vouch for (spec/verify.md, "Refusals"). */
#define VERIFY_INEXACT "the oracle cannot give this scene's image to the stated accuracy"

/* A verdict must reject an image scaled by any s with |1 - s| >= 1/2: half
 * the light and less (black too), and 3/2 and more (a lost or doubled
 * factor of 2, the smallest factor by which a radiometric formula slips).
 * s times the exact image is within a relative bound tol at every pixel
 * exactly when |1 - s| <= tol, so the bound must be below 1/2
 * (spec/verify.md, [VERIFY-UNBOUNDED-2]). */
#define VERIFY_DECISIVE_BELOW 0.5

/* The reason of a render judged against a relative bound of 1/2 or more:
 * every value in [(1 - tol) exact, (1 + tol) exact] is within it, half the
 * image too, so it is not passed (spec/verify.md, [VERIFY-UNBOUNDED-2]). */
#define VERIFY_UNBOUNDED "a relative error bound of 1/2 or more cannot tell the image from one of half its light"

/* 1 when a usable tolerance can carry a verdict: below VERIFY_DECISIVE_BELOW. */
int verify_tolerance_decisive(double tolerance);

/* The message for verify_exact_build's status (0: none). */
const char *verify_exact_error(int status);

/* 1 when a relative tolerance is a bound at all: finite and not negative.
 * (A bound of 1/2 or more is honest for a render of few light samples, and
 * a sweep measures its error, but no verdict rests on it: VERIFY_UNBOUNDED.) */
int verify_tolerance_usable(double tolerance);

const oracle_family *verify_family(const scene_model *s, const oracle_view *v, int *status, char *why,
                                   size_t why_size);

/* Builds (and times) the exact image of f for v into e.  Returns 0,
 * STATUS_NO_MEMORY (out of memory) or STATUS_FAIL (the family gave a point
 * a non-finite or negative radiance: VERIFY_INEXACT); e is then empty.
 * Free e with verify_exact_free. */
int verify_exact_build(const oracle_family *f, const oracle_view *v, verify_exact *e);
void verify_exact_free(verify_exact *e);

/*
 * Renders s with options o, compares the render with e (built for the same
 * view) at the family's tolerance for o->light_samples, and fills r's
 * metrics, timings, rays and verdict.  r->scene is left as it is.
 * Returns r->status.
 */
int verify_render_compare(const scene_model *s, const verify_opts *o, const verify_exact *e, verify_result *r);

/*
 * The whole check of one loaded scene: family, exact image, render,
 * comparison.  path names the scene in r.  Returns r->status.
 */
int verify_scene(const scene_model *s, const char *path, const verify_opts *o, verify_result *r);

/* r for a scene that could not be loaded or checked: verdict ERROR. */
void verify_result_error(verify_result *r, const char *path, int status, const char *reason);

/* ---- Sweeps: error against cost ---- */

typedef enum verify_sweep_kind {
    VERIFY_SWEEP_LIGHT,   /* samples=...: light samples per distributed light */
    VERIFY_SWEEP_PIXEL    /* pixel-samples=...: k of the k x k camera grid */
} verify_sweep_kind;

/* Largest number of steps a sweep takes. */
enum { VERIFY_SWEEP_MAX = 64 };

typedef struct verify_sweep {
    verify_sweep_kind kind;
    int values[VERIFY_SWEEP_MAX];
    int count;
} verify_sweep;

/*
 * Parses "samples=1,2,4" or "pixel-samples=1,2,3" into sw (values are
 * whole numbers from 1 to max, at most VERIFY_SWEEP_MAX of them).  Returns
 * 1, or 0 with the reason in why.
 */
int verify_sweep_parse(const char *text, int max, verify_sweep *sw, char *why, size_t why_size);

/* "samples" or "pixel-samples". */
const char *verify_sweep_name(verify_sweep_kind kind);

/* The cost N of a step: the light samples, or k*k camera rays per pixel. */
double verify_sweep_n(const verify_sweep *sw, int step);

/*
 * Runs every step of sw on s: steps[i] is the check of s with o and the
 * swept setting replaced by sw->values[i] (the exact image is built once
 * for a light sweep, once per k for a pixel sweep).  Returns the largest
 * status of the steps; steps past a failed exact image (out of memory) or a refused
 * scene are not run (steps[0] then holds the reason and *ran is 1).
 */
int verify_sweep_run(const scene_model *s, const char *path, const verify_opts *o, const verify_sweep *sw,
                     verify_result *steps, int *ran);

/* A convergence order, with whether it means anything. */
typedef struct verify_order {
    fit_line line;
    int meaningful;      /* 0: the note says why the slope is not an order */
    char note[160];
} verify_order;

/*
 * The orders of a sweep: RMS error against N (verify_sweep_n) and against
 * render seconds, fitted in log-log ([VERIFY-FIT-1]).  Steps whose RMS is at
 * the round-off floor (<= VERIFY_ROUNDOFF x the reference's peak) are left
 * out; with fewer than 3 steps left the slope is marked not meaningful
 * ([VERIFY-FIT-2]): a deterministic scene's error is round-off at every N,
 * and a slope through round-off would be noise.
 */
#define VERIFY_ROUNDOFF 1e-10
void verify_sweep_orders(const verify_sweep *sw, const verify_result *steps, int count, verify_order *vs_n,
                         verify_order *vs_time);

/* The order stratified light sampling should show, as text for reports. */
const char *verify_expected_order(const verify_result *r, const verify_sweep *sw);

/* ---- Output ---- */

/* s as a JSON string, quotes included: ", \ and control bytes escaped
 * (\n, \t, ... or \u00XX); other bytes (UTF-8 included) as they are. */
void verify_json_string(FILE *fp, const char *s);

/* v as a JSON number with 17 significant digits; null when not finite
 * (JSON has no infinity: an exact match has PSNR +inf, written null). */
void verify_json_number(FILE *fp, double v);

/* The metrics of a comparison as JSON object members (no braces), e.g.
 * "max_abs": 0.1, "rms": ..., "over": 1 ... */
void verify_json_metrics(FILE *fp, const image_metrics *m, double tolerance);

/* One result as a JSON object. */
void verify_json_result(FILE *fp, const verify_result *r);

/* Results as a JSON array, one object per line, and a final newline. */
void verify_json_results(FILE *fp, const verify_result *r, int count);

/* A sweep of one scene as a JSON object: steps and both orders. */
void verify_json_sweep(FILE *fp, const verify_sweep *sw, const verify_result *steps, int count,
                       const verify_order *vs_n, const verify_order *vs_time);

/* The TSV header line of sweeps (spec/verify.md, [VERIFY-TSV-1]). */
void verify_tsv_header(FILE *fp);

/* One TSV row per step, then one "# fit" comment line per order. */
void verify_tsv_sweep(FILE *fp, const verify_sweep *sw, const verify_result *steps, int count,
                      const verify_order *vs_n, const verify_order *vs_time);

/* ---- Error maps and masks ---- */

enum { VERIFY_MAP_COLOUR = 0, VERIFY_MAP_GREY = 1 };

/* What a raw map holds where A or B is not finite: the largest double,
 * which the writers store as the largest value of the file's number type
 * (a map never holds a NaN, and 0 would read as "no error"). */
#define VERIFY_MAP_NONFINITE DBL_MAX

/*
 * The error map of a against b: e = max over channels |a - b| / max_abs,
 * (max_abs over the pixels not excluded; e = 0 everywhere when it is 0),
 * shown as a grey level or on the false-colour scale black - purple - red -
 * orange - yellow - white ([VERIFY-MAP-1]); excluded pixels (mask non-zero,
 * mask may be NULL) are teal; a pixel where a or b is not finite is pure
 * green, off the scale, and takes no part in max_abs ([REL-NONFINITE-1]).  The colours are display (sRGB-encoded)
 * values; out holds them made linear, so that an 8-bit PNG written with the
 * default options stores exactly these display colours.  Returns 0 or
 * STATUS_NO_MEMORY / STATUS_INTERNAL (sizes differ).
 */
int verify_diff_map(const img_buf *a, const img_buf *b, const unsigned char *mask, int style, img_buf *out);

/* The display colour of e in [0, 1] on the scale of style. */
rgb verify_map_colour(double e, int style);

/* |a - b| per channel (excluded pixels 0; VERIFY_MAP_NONFINITE where a or
 * b is not finite): the raw error, for EXR/PFM maps. */
int verify_abs_diff(const img_buf *a, const img_buf *b, const unsigned char *mask, img_buf *out);

/*
 * Writes a width x height mask (non-zero = excluded) to path: .pgm as a
 * binary 8-bit PGM (P5; 255 excluded, 0 compared), atomically; any image
 * extension through img_write (white excluded, black compared).  Returns
 * 0 or an IMG_ code with the reason in err.
 */
int verify_mask_write(const char *path, const unsigned char *mask, int width, int height, char *err,
                      size_t errlen);

/* The reason of a mask with a value other than black and white. */
#define MASK_NOT_BINARY "a mask is black (0: judged) or white (maxval, 255: excluded) only, nothing between"

/*
 * Reads a mask of width x height from path (.pgm: binary P5, maxval <= 255;
 * others through img_read): a pixel is excluded when it is white (maxval;
 * 1 in every channel), judged when black (0), and any other value is
 * refused (STATUS_DATA, MASK_NOT_BINARY), so that no reader can take a
 * grey byte another way (spec/verify.md [VERIFY-MASK-1]).  *mask is
 * malloc'd.  Returns 0, or an IMG_ code with the reason in err (STATUS_DATA
 * for a size other than width x height).
 */
int verify_mask_read(const char *path, int width, int height, unsigned char **mask, char *err, size_t errlen);

#endif
