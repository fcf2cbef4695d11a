/*
 * conform.h - another renderer run over a conformance kit and checked
 * against its exact images (`refray conform`, spec/conformance.md).
 *
 * For each scene of the manifest the renderer's command line is expanded
 * (placeholders replaced by shell-quoted values) and run by /bin/sh in a
 * fresh directory with a time limit (io/proc.h); its picture is read,
 * brought to the exact image's terms (image/adjust.h) and judged by the
 * kit's rule (conform_rule, verify/conform_kit.h).  Whatever the renderer
 * does - crash, hang, exit non-zero, write nothing, garbage or the wrong
 * size - is a failed scene with a reason, never an error of ours.
 */
#ifndef REFRAY_CONFORM_H
#define REFRAY_CONFORM_H

#include <signal.h>
#include <stddef.h>
#include "io/proc.h"
#include "image/metrics.h"
#include "verify/conform_kit.h"
#include "verify/manifest.h"

/* The value of --downsample or --scale that says "each scene's own, from
 * the manifest": its samples k, or 1 / its png16_scale. */
#define CONFORM_FROM_MANIFEST 0

/* How a renderer's picture is brought to the exact image's terms. */
typedef struct conform_adjust {
    int downsample;   /* average k x k blocks: k >= 1, or CONFORM_FROM_MANIFEST */
    double scale;     /* multiply by it (> 0), or CONFORM_FROM_MANIFEST */
} conform_adjust;

/* The block size and factor a scene gets. */
int conform_downsample_of(const conform_adjust *a, const manifest_scene *s);
double conform_scale_of(const conform_adjust *a, const manifest_scene *s);

/* What became of one scene; CONFORM_PASS is the only pass. */
typedef enum conform_outcome {
    CONFORM_PASS,
    CONFORM_OVER,          /* some pixel over the tolerance, or none compared */
    CONFORM_CRASHED,       /* the renderer was killed by a signal */
    CONFORM_EXIT,          /* it exited with a non-zero status */
    CONFORM_TIMEOUT,       /* it ran past the time limit (its process group was killed) */
    CONFORM_NO_OUTPUT,     /* it exited 0 and wrote nothing at {out} */
    CONFORM_UNREADABLE,    /* what it wrote is not an image of the format */
    CONFORM_SIZE,          /* its image has the wrong size */
    CONFORM_NONFINITE,     /* its image holds NaN or infinity */
    CONFORM_NO_INPUT,      /* the kit lacks a file the command names (not run) */
    CONFORM_ERROR,         /* refray could not run it or read the kit */
    CONFORM_INTERRUPTED    /* stopped by the user */
} conform_outcome;

/* "pass", "over", "crashed", ...: the category in reports. */
const char *conform_outcome_name(conform_outcome o);

enum { CONFORM_TAIL_LINES = 20, CONFORM_TAIL_BYTES = 2000 };

typedef struct conform_result {
    const manifest_scene *scene;
    conform_outcome outcome;
    char reason[1024];
    char note[256];             /* what a pass or failure leaves unjudged ("": nothing) */
    int ran;                    /* the command was started; proc is valid */
    proc_result proc;
    int compared;               /* metrics are valid */
    image_metrics metrics;
    double relative, absolute;  /* the tolerance applied */
    int downsample;
    double scale;
    char stderr_tail[CONFORM_TAIL_BYTES + 8];  /* cleaned (base/text.h), "" when none */
    char workdir[512];          /* kept with --keep, else "" */
} conform_result;

/* One run over a kit. */
typedef struct conform_run {
    const char *kit_dir;        /* the kit (absolute, so the command may change directory) */
    const char *command;        /* with placeholders */
    const char *format;         /* the output's extension: "exr", "pfm" or "png" */
    conform_adjust adjust;
    double timeout;             /* seconds per scene; <= 0: none */
    int keep;                   /* keep each scene's working directory */
    const char *tmp_root;       /* where working directories are made ($TMPDIR, /tmp) */
    const volatile sig_atomic_t *stop;  /* set by the caller's signal handler; may be NULL */
} conform_run;

/* A placeholder's name and value; value NULL: not available, for the
 * reason in missing. */
typedef struct conform_var {
    const char *name;           /* without braces */
    const char *value;
    const char *missing;
} conform_var;

/* s in single quotes for /bin/sh ("'" becomes '\''), malloc'd. */
char *conform_shell_quote(const char *s);

/*
 * Replaces every {name} of tmpl whose name is one of vars[0..count) by
 * the shell-quoted value; other braces stay as written (so ${HOME} and
 * awk's { } pass through).  Returns 0 with *out malloc'd; CONFORM_NO_INPUT
 * as an int when a placeholder used has no value (the reason in why);
 * STATUS_NO_MEMORY when out of memory (conform.c checks that no status
 * equals CONFORM_NO_INPUT).
 */
int conform_expand(const char *tmpl, const conform_var *vars, int count, char **out, char *why,
                   size_t why_size);

/* The placeholders conform_run_scene fills, NULL-terminated. */
extern const char *const conform_placeholders[];

/* 1 when tmpl names {out}; else 0 with the reason. */
int conform_template_ok(const char *tmpl, char *why, size_t why_size);

/*
 * Checks the picture at out_path (written by the renderer) against scene
 * s of the kit in kit_dir: read, size, downsample, scale, finite values
 * of the pixels the mask leaves, tolerance.  Fills r's outcome, reason,
 * note, metrics and tolerance.
 */
void conform_judge(const char *kit_dir, const manifest_scene *s, const char *out_path, const conform_adjust *a,
                   conform_result *r);

/* Runs the command of run for scene s and judges its picture into r. */
void conform_run_scene(const conform_run *run, const manifest_scene *s, conform_result *r);

#endif
