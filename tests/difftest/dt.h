/*
 * dt.h - the parts of `make difftest` (spec/crosscheck.md, section 6):
 * one scene rendered by refray and by POV-Ray 3.7 and compared pixel by
 * pixel (run.c), a disagreeing scene shrunk to the fewest statements that
 * still disagree (shrink.c), and the campaign over many random scenes
 * (difftest.c).
 */
#ifndef REFRAY_DIFFTEST_DT_H
#define REFRAY_DIFFTEST_DT_H

#include <stdio.h>
#include <sys/types.h>
#include "export/export_pov.h"
#include "image/image.h"
#include "gen.h"

typedef struct dt_config {
    const char *work_dir;   /* where the .pov, .png and logs go (POV-Ray runs there) */
    const char *povray;     /* the program */
    double tol_steps;       /* a difference above this many 16-bit steps disagrees */
    double edge_radius;     /* in pixels of POV-Ray's render: see dt_run */
    int timeout;            /* seconds for one POV-Ray render */
    int approximations;     /* 1: compare a scene whose export lists approximations too */
    FILE *diag;             /* where a scene's load diagnostics go */
    const char *const *read_dirs; /* besides a scene's own tree, where its meshes may be read
                                     (NULL-terminated; NULL: none) [REL-READ-1] */
} dt_config;

typedef enum dt_verdict {
    DT_DISCARDED,   /* the export lists an approximation or refuses: not compared */
    DT_AGREE,       /* every pixel within the tolerance */
    DT_EDGE_ONLY,   /* every disagreeing pixel is an edge pixel */
    DT_INTERIOR,    /* some interior pixel disagrees: a finding */
    DT_FAILED       /* the scene did not load, or a renderer failed */
} dt_verdict;

typedef struct dt_result {
    dt_verdict verdict;
    char why[POV_NOTE_LEN];   /* discarded (or compared anyway): the first note; failed: the reason */
    int notes;                /* approximations the export lists */
    int pixels;
    int edge, interior;       /* disagreeing pixels of each kind */
    double worst_interior;    /* largest |refray - POV-Ray| over interior pixels, scene units */
    int worst_x, worst_y, worst_c;
    double refray_value, pov_value;  /* at the worst interior pixel and channel */
    double max_steps;         /* largest difference over all pixels, in 16-bit steps */
    double scale;             /* the export's --scale */
} dt_result;

/*
 * Loads text as the scene file name (in c->work_dir), drops it when the
 * export lists an approximation, renders it with refray, picks the scale
 * that puts the peak in (0.4, 0.8], exports and renders it with POV-Ray
 * (+FN16 -A +WT1, linear), and compares.  A disagreeing pixel is an edge
 * pixel when refray's ray tree (trace_stats.path) changes within
 * c->edge_radius of the centre of one of its camera rays (8 points on that
 * circle and 4 at half of it); else interior.  Fills r; returns its
 * verdict.
 */
dt_verdict dt_run(const dt_config *c, const char *name, const char *text, dt_result *r);

/* Starts argv[0] (found on PATH) with argv in dir (NULL: here), its output
 * and errors going to the file log (relative to dir); returns the child's
 * pid, or -1 when fork failed.  The child exits 126 when dir is not there,
 * 127 when the program cannot run. */
pid_t dt_spawn(char *const argv[], const char *dir, const char *log);

/* The export's scale for s: the power of two that puts the peak of what
 * POV-Ray will write (ours, or its sub-samples for a k x k grid) in
 * (0.4, 0.8] ([XCHK-RUN-SCALE-1]). */
double dt_scale(const scene_model *s, const img_buf *ours);

/* POV-Ray's picture c->work_dir/name.png, k x k blocks averaged, divided
 * by scale, into out (the scene's size).  Returns 0, or -1 with the
 * reason in r. */
int dt_read_pov(const dt_config *c, const char *name, int k, double scale, img_buf *out, dt_result *r);

/* Compares ours with pov pixel by pixel (r->scale set) and sorts the
 * disagreeing pixels into edge and interior ones as dt_run says; sets
 * r->verdict. */
void dt_compare(const dt_config *c, const scene_model *s, const img_buf *ours, const img_buf *pov, dt_result *r);

/*
 * Delta debugging over the statements of g (image and camera always
 * kept): keep[] starts all 1 and ends with the fewest statements found
 * whose scene still has an interior disagreement (1-minimal: removing any
 * one more loses it).  Returns the number of scenes tried.
 */
int dt_shrink(const dt_config *c, const char *name, const dtgen_scene *g, unsigned char *keep);

#endif
