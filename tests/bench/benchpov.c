/*
 * benchpov.c - `make bench-pov` (spec/performance.md): refray against
 * POV-Ray 3.7 on the same scenes, CPU time of the whole process, side by
 * side, and whether the two images agree (so a speed-up cannot come from
 * doing less work).
 *
 *   bench-pov [-r RUNS] [-o DIR] --refray PROG [--povray PROG] SCENE[@WxH[xK]]...
 *
 * For each scene (size and pixel grid optionally overridden): refray
 * renders it once in this process (its image, its ray count and the
 * export's scale), the export writes DIR/NAME.pov, then RUNS pairs of
 * renders run as child processes, refray (`PROG render ... -o NAME.pfm`)
 * and POV-Ray (`+WT1 -A`, the options of make difftest), the order
 * alternating from pair to pair.  A process's CPU time is its user plus
 * system time from getrusage (threads included).  Printed per scene: the
 * median of each, the median of the pairs' ratios, both ray counts and the
 * ratio per ray (the median ratio times POV-Ray's rays over refray's), and
 * the comparison of the last POV-Ray picture with refray's image by make
 * difftest's rule (tests/difftest/run.c): pixels over 1 step of 1/65535,
 * sorted into edge pixels (the ray tree changes within 1/8 pixel) and
 * interior ones, and the largest difference in steps.
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include "../difftest/dt.h"
#include "io/scene_file.h"
#include "render/render.h"

enum { PATH_LEN = 1024, RUNS_MAX = 15, ARGS_MAX = 24 };

typedef struct entry {
    char path[PATH_LEN];
    char name[256];
    int width, height, samples;   /* 0: the scene's own */
} entry;

typedef struct options {
    int runs;
    const char *dir, *refray, *povray;
} options;

/* CPU seconds of every child waited for so far (POSIX getrusage): the
 * difference over one wait is that child's. */
static double children_cpu(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_CHILDREN, &ru) != 0)
        return 0;
    return (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec + (double)ru.ru_stime.tv_sec +
           1e-6 * (double)ru.ru_stime.tv_usec;
}

/* Runs argv in dir (NULL: here) with stdout and stderr to log; returns its
 * CPU seconds (user + system), or -1 when it failed. */
static double run_timed(char *const argv[], const char *dir, const char *log)
{
    pid_t pid = dt_spawn(argv, dir, log);
    if (pid < 0)
        return -1;
    int status;
    double before = children_cpu();
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    return children_cpu() - before;
}

/* POV-Ray's ray count from its statistics in log: camera, reflected and
 * refracted rays ("Rays:") plus shadow rays ("Shadow Ray Tests:"); -1
 * when they are missing. */
static long pov_rays(const char *log)
{
    char line[512];
    long rays = -1, shadow = -1;
    FILE *f = fopen(log, "r");
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "Rays:", 5) == 0)
            rays = atol(line + 5);
        else if (strncmp(line, "Shadow Ray Tests:", 17) == 0)
            shadow = atol(line + 17);
    }
    fclose(f);
    return rays < 0 || shadow < 0 ? -1 : rays + shadow;
}

/* The mean of |ours - pov| over every pixel and channel, relative to the
 * mean of pov: the agreement of two images that differ by sampling noise. */
static double mean_difference(const img_buf *ours, const img_buf *pov)
{
    double diff = 0, sum = 0;
    for (size_t i = 0; i < 3 * (size_t)ours->width * ours->height; i++) {
        diff += fabs(ours->rgb[i] - pov->rgb[i]);
        sum += pov->rgb[i];
    }
    return sum > 0 ? diff / sum : diff;
}

/* SCENE[@WxH[xK]] into e; the name is the file's base name without .scene. */
static int parse_entry(const char *arg, entry *e)
{
    memset(e, 0, sizeof *e);
    const char *at = strchr(arg, '@');
    size_t len = at ? (size_t)(at - arg) : strlen(arg);
    if (len == 0 || len >= sizeof e->path)
        return -1;
    memcpy(e->path, arg, len);
    e->path[len] = 0;
    if (at && sscanf(at + 1, "%dx%dx%d", &e->width, &e->height, &e->samples) < 2)
        return -1;
    const char *base = strrchr(e->path, '/');
    base = base ? base + 1 : e->path;
    snprintf(e->name, sizeof e->name, "%.200s", base);
    char *dot = strstr(e->name, ".scene");
    if (dot)
        *dot = 0;
    return 0;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof v[0], by_value);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static long total_rays(const trace_stats *t)
{
    return t->camera_rays + t->shadow_rays + t->reflection_rays + t->refraction_rays + t->tir_rays;
}

/* The refray and POV-Ray command lines of e (buffers in nums). */
static void command_lines(const options *o, const entry *e, const scene_model *s, char nums[8][PATH_LEN],
                          char *rf[ARGS_MAX], char *pov[ARGS_MAX])
{
    int width, height, n = 0;
    pov_render_size(s, &width, &height);
    snprintf(nums[0], PATH_LEN, "%d", s->image.width);
    snprintf(nums[1], PATH_LEN, "%d", s->image.height);
    snprintf(nums[2], PATH_LEN, "%d", s->image.samples);
    snprintf(nums[3], PATH_LEN, "+I%.200s.pov", e->name);
    snprintf(nums[4], PATH_LEN, "+O%.200s.png", e->name);
    snprintf(nums[5], PATH_LEN, "+W%d", width);
    snprintf(nums[6], PATH_LEN, "+H%d", height);
    snprintf(nums[7], PATH_LEN, "%.700s/%.200s.pfm", o->dir, e->name);
    const char *r[] = {o->refray, "render", e->path, "-o", nums[7], "-q", "-W", "--width", nums[0],
                       "--height", nums[1], "--samples", nums[2], NULL};
    const char *p[] = {o->povray, nums[3], nums[4], nums[5], nums[6], "-A", "-D", "-V", "+WT1", "+FN16",
                       "File_Gamma=1.0", "Output_Alpha=off", NULL};
    for (n = 0; r[n]; n++)
        rf[n] = (char *)r[n];
    rf[n] = NULL;
    for (n = 0; p[n]; n++)
        pov[n] = (char *)p[n];
    pov[n] = NULL;
}

/* Times o->runs pairs; fills the medians; returns 0, or -1 when a run failed. */
static int time_pairs(const options *o, const entry *e, const scene_model *s, double *rf_s, double *pov_s,
                      double *ratio)
{
    char nums[8][PATH_LEN], log[PATH_LEN];
    char *rf[ARGS_MAX], *pov[ARGS_MAX];
    double a[RUNS_MAX], b[RUNS_MAX], q[RUNS_MAX];
    command_lines(o, e, s, nums, rf, pov);
    for (int i = 0; i < o->runs; i++) {
        for (int k = 0; k < 2; k++) {
            if ((k == 0) == (i % 2 == 0)) {
                snprintf(log, sizeof log, "%.700s/%.200s.refray.log", o->dir, e->name);
                a[i] = run_timed(rf, NULL, log);
            } else {
                snprintf(log, sizeof log, "%.200s.log", e->name);
                b[i] = run_timed(pov, o->dir, log);
            }
        }
        if (a[i] < 0 || b[i] < 0) {
            fprintf(stderr, "bench-pov: %s: a render failed (logs in %s/)\n", e->path, o->dir);
            return -1;
        }
        q[i] = a[i] / b[i];
    }
    *rf_s = median(a, o->runs);
    *pov_s = median(b, o->runs);
    *ratio = median(q, o->runs);
    return 0;
}

/* One scene: load, render here, export, time, compare, print one row. */
static int bench_one(const options *o, const entry *e)
{
    int status, k;
    char pov_path[PATH_LEN], log[PATH_LEN], err[600];
    scene_model *s = scene_file_load(e->path, NULL, stderr, 0, &status);
    if (!s)
        return -1;
    if (e->width > 0) {
        s->image.width = e->width;
        s->image.height = e->height;
    }
    if (e->samples > 0)
        s->image.samples = e->samples;
    img_buf ours, pov;
    render_stats st;
    dt_config c = {o->dir, o->povray, 1, 0.125, 0, 1, stderr, NULL};
    dt_result r;
    pov_opts po;
    pov_notes notes;
    double rf_s, pov_s, ratio;
    int failed = -1;
    memset(&r, 0, sizeof r);
    memset(&po, 0, sizeof po);
    if (render_image(s, NULL, &ours, &st) != STATUS_OK)
        goto done_scene;
    r.scale = po.scale = dt_scale(s, &ours);
    po.source = e->name;
    snprintf(pov_path, sizeof pov_path, "%.700s/%.200s.pov", o->dir, e->name);
    if (pov_export_file(s, &po, pov_path, &notes, err, sizeof err) != 0) {
        fprintf(stderr, "bench-pov: %s: export failed: %s\n", e->path, err);
        goto done_image;
    }
    if (time_pairs(o, e, s, &rf_s, &pov_s, &ratio) != 0)
        goto done_image;
    k = s->image.samples;
    if (dt_read_pov(&c, e->name, k, r.scale, &pov, &r) != 0) {
        fprintf(stderr, "bench-pov: %s: %s\n", e->path, r.why);
        goto done_image;
    }
    r.pixels = s->image.width * s->image.height;
    dt_compare(&c, s, &ours, &pov, &r);
    double mean = mean_difference(&ours, &pov);
    img_free(&pov);
    snprintf(log, sizeof log, "%.700s/%.200s.log", o->dir, e->name);
    long rf_rays = total_rays(&st.trace), pv_rays = pov_rays(log);
    /* The ray counts are the same in every run, so the per-ray ratio is
     * the paired median scaled by them (0 when a count is missing). */
    double per_ray = rf_rays > 0 && pv_rays > 0 ? ratio * (double)pv_rays / (double)rf_rays : 0;
    printf("| %s | %dx%d, %dx%d | %ld | %ld | %.2f | %.2f | **%.2f** | %.2f | %d / %d / %d, %.0f | %.2g%% | %d |\n",
           e->path, s->image.width, s->image.height, k, k, rf_rays, pv_rays, rf_s, pov_s, ratio, per_ray,
           r.pixels - r.edge - r.interior, r.edge, r.interior, r.max_steps, 100 * mean, notes.count);
    fflush(stdout);
    failed = 0;
done_image:
    img_free(&ours);
done_scene:
    scene_free(s);
    return failed;
}

int main(int argc, char **argv)
{
    options o = {3, "build/bench-pov", NULL, "povray"};
    int i = 1, failures = 0;
    for (; i + 1 < argc && argv[i][0] == '-'; i += 2) {
        if (strcmp(argv[i], "-r") == 0)
            o.runs = atoi(argv[i + 1]);
        else if (strcmp(argv[i], "-o") == 0)
            o.dir = argv[i + 1];
        else if (strcmp(argv[i], "--refray") == 0)
            o.refray = argv[i + 1];
        else if (strcmp(argv[i], "--povray") == 0)
            o.povray = argv[i + 1];
        else
            break;
    }
    if (o.runs < 1 || o.runs > RUNS_MAX || !o.refray || i >= argc) {
        fprintf(stderr, "usage: bench-pov [-r RUNS (1-%d)] [-o DIR] --refray PROG [--povray PROG] "
                        "SCENE[@WxH[xK]]...\n", RUNS_MAX);
        return 64;
    }
    if (mkdir(o.dir, 0755) != 0 && errno != EEXIST) {
        perror(o.dir);
        return 74;
    }
    printf("CPU seconds (user + system) of the whole process, median of %d paired runs; POV-Ray 3.7 +WT1 -A.\n"
           "Rays: refray's total; POV-Ray's rays plus shadow ray tests.  Pixels: within 1 step of 1/65535 / "
           "edge / interior over it, largest difference in steps.\nMean: mean |refray - POV-Ray| over mean "
           "POV-Ray.  Approx.: approximations the export lists (refray export --to pov).\n"
           "Per ray: the ratio of CPU time per ray, (refray s / refray rays) / (POV-Ray s / POV-Ray rays).\n\n",
           o.runs);
    printf("| scene | size, grid | refray rays | POV-Ray rays | refray s | POV-Ray s | refray / POV-Ray | per ray "
           "| pixels | mean | approx. |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (; i < argc; i++) {
        entry e;
        if (parse_entry(argv[i], &e) != 0) {
            fprintf(stderr, "bench-pov: bad scene argument '%s' (SCENE[@WxH[xK]])\n", argv[i]);
            return 64;
        }
        failures += bench_one(&o, &e) != 0;
    }
    return failures ? 1 : 0;
}
