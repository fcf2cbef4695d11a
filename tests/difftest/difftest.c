/*
 * difftest.c - `make difftest`: random scenes rendered by refray and by
 * POV-Ray 3.7 and compared pixel by pixel (spec/crosscheck.md, section 6).
 *
 *   refray-difftest [-n N] [--seed S] [--first K] [-o DIR] [--obj-dir DIR]
 *                   [--povray PROG] [--tolerance STEPS] [--edge-radius PX]
 *                   [--timeout SECONDS] [--keep]
 *   refray-difftest --scene FILE [-o DIR] [the same options]
 *
 * --scene compares one scene file, approximations and all, and prints its
 * verdict, the export's first note and the worst interior pixel.
 * --regress DIR first compares every .scene file of DIR (the minimal
 * scenes of past findings, tests/difftest/regress/): each must export
 * exactly and have no interior disagreement.
 *
 * Scene i of seed S is tests/difftest/gen.c's DTGEN_EXACT scene of seed
 * S * 2^32 + i, for i = K .. K + N - 1, so a campaign and any one of its
 * scenes can be run again.  Each goes through dt_run (run.c).  A scene
 * with an interior disagreement is a finding: it is shrunk (shrink.c) and
 * written to DIR/finding-NAME.scene, with the full scene beside it as
 * DIR/finding-NAME-full.scene and POV-Ray's files in DIR/work/.  Scenes
 * that disagree only at edges are written unshrunk as DIR/edge-NAME.scene.
 * DIR/scenes.tsv has a line per scene, DIR/summary.txt the figures.
 * Exit status: 0 when no scene has an interior disagreement and none
 * failed, 1 otherwise, 64 for bad usage.
 */
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "dt.h"

enum { PATH_LEN = 1024 };

typedef struct options {
    long n, first;
    unsigned long seed;
    const char *out, *obj_dir, *scene, *regress;
    int keep;
    dt_config run;
} options;

typedef struct tally {
    long verdicts[5];
    long edge_pixels;
    double *steps;        /* per compared scene: its largest difference in steps */
    long compared;
    long discard_kinds[8];
} tally;

/* What an approximation note is about, for the summary. */
static const char *const discard_words[] = {
    "total internal reflection", "trace level", "SHADOW_TOLERANCE", "MAX_DISTANCE", "vertex normals",
    "not grey", "falloff", NULL,
};

static int usage(const char *why)
{
    fprintf(stderr, "difftest: %s\nusage: refray-difftest [-n N] [--seed S] [--first K] [-o DIR] [--obj-dir DIR] "
            "[--povray PROG] [--tolerance STEPS] [--edge-radius PX] [--timeout SECONDS] [--keep]\n"
            "       refray-difftest --scene FILE [-o DIR] [the same options]\n"
            "       (--regress DIR: first every DIR/*.scene)\n", why);
    return 64;
}

static int number(const char *text, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(text, &end);
    return errno == 0 && end != text && *end == '\0' && *out >= lo && *out <= hi;
}

static int parse(options *o, int argc, char **argv)
{
    o->n = 40;
    o->first = 0;
    o->seed = 1;
    o->out = "build/difftest";
    o->obj_dir = "tests/obj";
    o->scene = NULL;
    o->regress = NULL;
    o->keep = 0;
    o->run.povray = "povray";
    o->run.tol_steps = 1;
    o->run.edge_radius = 0.125;
    o->run.timeout = 300;
    o->run.approximations = 0;
    o->run.diag = stderr;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        double v;
        if (strcmp(a, "--keep") == 0) {
            o->keep = 1;
            continue;
        }
        if (i + 1 >= argc)
            return usage("an option is missing its value, or is unknown");
        const char *val = argv[++i];
        if (strcmp(a, "-o") == 0)
            o->out = val;
        else if (strcmp(a, "--obj-dir") == 0)
            o->obj_dir = val;
        else if (strcmp(a, "--povray") == 0)
            o->run.povray = val;
        else if (strcmp(a, "--scene") == 0)
            o->scene = val;
        else if (strcmp(a, "--regress") == 0)
            o->regress = val;
        else if (!number(val, 0, 1e9, &v))
            return usage("a number option has a bad value");
        else if (strcmp(a, "-n") == 0)
            o->n = (long)v;
        else if (strcmp(a, "--first") == 0)
            o->first = (long)v;
        else if (strcmp(a, "--seed") == 0)
            o->seed = (unsigned long)v;
        else if (strcmp(a, "--tolerance") == 0)
            o->run.tol_steps = v;
        else if (strcmp(a, "--edge-radius") == 0)
            o->run.edge_radius = v;
        else if (strcmp(a, "--timeout") == 0)
            o->run.timeout = (int)v;
        else
            return usage("unknown option");
    }
    return 0;
}

static int make_dir(const char *path)
{
    return mkdir(path, 0777) == 0 || errno == EEXIST ? 0 : -1;
}

/* The scenes are read as files of the work directory: their OBJ paths
 * must be absolute.  Returns 0 when out is too small or cwd unknown. */
static int absolute(const char *path, char *out, size_t size)
{
    char cwd[PATH_MAX];
    if (path[0] == '/')
        return snprintf(out, size, "%s", path) < (int)size;
    if (!getcwd(cwd, sizeof cwd))
        return 0;
    return snprintf(out, size, "%s/%s", cwd, path) < (int)size;
}

static void write_file(const char *path, const char *header, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "difftest: cannot write %s: %s\n", path, strerror(errno));
        return;
    }
    fprintf(f, "%s%s", header, text);
    fclose(f);
}

/* Removes name's files from the work directory. */
static void clean_work(const options *o, const char *name)
{
    static const char *const ext[] = {"pov", "png", "log"};
    char path[PATH_LEN];
    for (int i = 0; i < 3; i++) {
        snprintf(path, sizeof path, "%.700s/%.250s.%s", o->run.work_dir, name, ext[i]);
        remove(path);
    }
}

static const char *verdict_word(dt_verdict v)
{
    static const char *const words[] = {"discarded", "agree", "edge-only", "INTERIOR", "FAILED"};
    return words[v];
}

/* The header comment of a written scene: how to get it again, and what
 * disagreed. */
static void describe(char *buf, size_t size, const options *o, long i, const dt_result *r, const char *what)
{
    snprintf(buf, size,
             "# make difftest: %s; scene %ld of seed %lu (refray-difftest --seed %lu --first %ld -n 1)\n"
             "# %d pixels: %d interior and %d edge pixels disagree; worst interior pixel (%d, %d) channel %d: "
             "refray %.9g, POV-Ray %.9g (export --scale %.17g)\n",
             what, i, o->seed, o->seed, i, r->pixels, r->interior, r->edge, r->worst_x, r->worst_y, r->worst_c,
             r->refray_value, r->pov_value, r->scale);
}

/* A finding: shrink it, write both versions, run the shrunk one again so
 * its POV-Ray files stay in the work directory. */
static void report_finding(const options *o, long i, const char *name, const dtgen_scene *g, const dt_result *r)
{
    static char text[DTGEN_TEXT_MAX];
    unsigned char keep[DTGEN_STMT_MAX];
    char path[PATH_LEN], header[1024], shrunk_name[PATH_LEN];
    dt_result again;
    describe(header, sizeof header, o, i, r, "full scene");
    snprintf(path, sizeof path, "%s/finding-%s-full.scene", o->out, name);
    write_file(path, header, g->text);
    int tries = dt_shrink(&o->run, name, g, keep);
    dtgen_subset(g, keep, text, sizeof text);
    snprintf(shrunk_name, sizeof shrunk_name, "finding-%s", name);
    dt_run(&o->run, shrunk_name, text, &again);
    describe(header, sizeof header, o, i, &again, "shrunk");
    snprintf(path, sizeof path, "%s/finding-%s.scene", o->out, name);
    write_file(path, header, text);
    printf("difftest:   shrunk in %d tries to %s (%d interior pixels)\n", tries, path, again.interior);
}

static void count_discard(tally *t, const char *why)
{
    int k = 0;
    while (discard_words[k] && !strstr(why, discard_words[k]))
        k++;
    t->discard_kinds[k]++;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void summarise(const options *o, tally *t, double seconds)
{
    char path[PATH_LEN];
    double median = 0;
    if (t->compared > 0) {
        qsort(t->steps, (size_t)t->compared, sizeof *t->steps, compare_doubles);
        median = t->steps[t->compared / 2];
    }
    snprintf(path, sizeof path, "%s/summary.txt", o->out);
    FILE *files[2] = {stdout, fopen(path, "w")};
    for (int f = 0; f < 2 && files[f]; f++) {
        FILE *out = files[f];
        fprintf(out, "difftest: seed %lu, scenes %ld..%ld: %ld generated, %ld discarded (the export lists an "
                "approximation), %ld compared\n", o->seed, o->first, o->first + o->n - 1, o->n,
                t->verdicts[DT_DISCARDED], t->compared);
        fprintf(out, "difftest: %ld agree, %ld edge-only (%ld edge pixels), %ld with interior disagreements "
                "(findings), %ld failed\n", t->verdicts[DT_AGREE], t->verdicts[DT_EDGE_ONLY], t->edge_pixels,
                t->verdicts[DT_INTERIOR], t->verdicts[DT_FAILED]);
        fprintf(out, "difftest: median over compared scenes of the largest pixel difference: %.3g steps of "
                "1/65535 (tolerance %.3g steps, edge radius %.3g px)\n", median, o->run.tol_steps,
                o->run.edge_radius);
        fprintf(out, "difftest: discarded for:");
        for (int k = 0; discard_words[k] || k < 8; k++) {
            if (t->discard_kinds[k])
                fprintf(out, " %s %ld;", discard_words[k] ? discard_words[k] : "other", t->discard_kinds[k]);
            if (!discard_words[k])
                break;
        }
        fprintf(out, "\ndifftest: %.1f s in all\n", seconds);
        if (f == 1)
            fclose(out);
    }
}

static void one_scene(const options *o, long i, FILE *tsv, tally *t)
{
    static dtgen_scene g;
    char name[64], path[PATH_LEN], header[1024];
    dt_result r;
    snprintf(name, sizeof name, "s%lu-%ld", o->seed, i);
    dtgen_make(&g, ((uint64_t)o->seed << 32) | (uint64_t)i, DTGEN_EXACT, o->obj_dir);
    dt_verdict v = dt_run(&o->run, name, g.text, &r);
    t->verdicts[v]++;
    if (v == DT_DISCARDED)
        count_discard(t, r.why);
    if (v == DT_AGREE || v == DT_EDGE_ONLY || v == DT_INTERIOR)
        t->steps[t->compared++] = r.max_steps;
    t->edge_pixels += r.edge;
    fprintf(tsv, "%ld\t%s\t%s\t%d\t%d\t%.3g\t%.3g\t%s\n", i, name, verdict_word(v), r.edge, r.interior,
            r.worst_interior, r.max_steps, v == DT_DISCARDED || v == DT_FAILED ? r.why : "");
    fflush(tsv);
    if (v != DT_DISCARDED)
        printf("difftest: %s %s: %d edge, %d interior pixels; largest difference %.3g steps%s%s\n", name,
               verdict_word(v), r.edge, r.interior, r.max_steps, v == DT_FAILED ? "; " : "",
               v == DT_FAILED ? r.why : "");
    fflush(stdout);
    if (v == DT_EDGE_ONLY || v == DT_FAILED) {
        describe(header, sizeof header, o, i, &r, v == DT_FAILED ? "failed" : "edge pixels only");
        snprintf(path, sizeof path, "%s/%s-%s.scene", o->out, v == DT_FAILED ? "failed" : "edge", name);
        write_file(path, header, g.text);
    }
    if (v == DT_INTERIOR)
        report_finding(o, i, name, &g, &r);
    else if (!o->keep && v != DT_FAILED)
        clean_work(o, name);
}

/* Compares the scene file path (approximations too when the run's
 * config allows them) and prints the verdict; 1 when it is a failure:
 * an interior disagreement, a renderer failing, or a scene dropped. */
static int one_file(const options *o, const char *path)
{
    static char text[1 << 20];
    char name[PATH_LEN];
    dt_result r;
    FILE *f = fopen(path, "r");
    size_t len = f ? fread(text, 1, sizeof text - 1, f) : 0;
    if (!f || ferror(f) || len == sizeof text - 1) {
        fprintf(stderr, "difftest: cannot read %s (or it is over 1 MB)\n", path);
        if (f)
            fclose(f);
        return 1;
    }
    fclose(f);
    text[len] = '\0';
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    snprintf(name, sizeof name, "one-%.200s", base);
    dt_verdict v = dt_run(&o->run, name, text, &r);
    printf("difftest: %s: %s: %d edge, %d interior pixels of %d; largest difference %.3g steps\n", path,
           verdict_word(v), r.edge, r.interior, r.pixels, r.max_steps);
    if (r.interior > 0)
        printf("difftest: worst interior pixel (%d, %d) channel %d: refray %.9g, POV-Ray %.9g\n", r.worst_x,
               r.worst_y, r.worst_c, r.refray_value, r.pov_value);
    if (r.notes > 0 || v == DT_FAILED || v == DT_DISCARDED)
        printf("difftest: %d approximations listed by the export; the first: %s\n", r.notes, r.why);
    fflush(stdout);
    if (!o->keep && v != DT_INTERIOR && v != DT_FAILED)
        clean_work(o, name);
    return v == DT_INTERIOR || v == DT_FAILED || v == DT_DISCARDED;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every .scene file of o->regress, in name order; the number that failed. */
static int regressions(const options *o)
{
    char *names[256], path[PATH_LEN];
    int n = 0, failed = 0;
    DIR *dir = opendir(o->regress);
    if (!dir) {
        fprintf(stderr, "difftest: cannot read the directory %s\n", o->regress);
        return 1;
    }
    for (struct dirent *e = readdir(dir); e && n < 256; e = readdir(dir)) {
        size_t len = strlen(e->d_name);
        if (len > 6 && strcmp(e->d_name + len - 6, ".scene") == 0 && (names[n] = malloc(len + 1)) != NULL)
            memcpy(names[n++], e->d_name, len + 1);
    }
    closedir(dir);
    qsort(names, (size_t)n, sizeof names[0], by_name);
    for (int i = 0; i < n; i++) {
        snprintf(path, sizeof path, "%s/%s", o->regress, names[i]);
        failed += one_file(o, path);
        free(names[i]);
    }
    printf("difftest: %d regression scenes of %s, %d failed\n", n, o->regress, failed);
    return failed;
}

int main(int argc, char **argv)
{
    options o;
    tally t;
    char work[PATH_LEN], objs[PATH_MAX], path[PATH_LEN];
    int status = parse(&o, argc, argv);
    if (status != 0)
        return status;
    snprintf(work, sizeof work, "%s/work", o.out);
    o.run.work_dir = work;
    if (!absolute(o.obj_dir, objs, sizeof objs) || make_dir(o.out) != 0 || make_dir(work) != 0) {
        fprintf(stderr, "difftest: cannot set up %s with the OBJ files of %s: %s\n", o.out, o.obj_dir,
                strerror(errno));
        return 1;
    }
    o.obj_dir = objs;
    /* The generated scenes name the OBJ files where they are, outside the
     * work directory the scenes are written to. */
    const char *mesh_dirs[] = {objs, NULL};
    o.run.read_dirs = mesh_dirs;
    if (o.scene) {
        o.run.approximations = 1;
        return one_file(&o, o.scene);
    }
    int regressed = o.regress ? regressions(&o) : 0;
    /* The shrinking tries scenes that do not load (no primitive left): a
     * generated scene that does not load is a failure, run again with
     * --scene to see why. */
    FILE *null = fopen("/dev/null", "w");
    o.run.diag = null ? null : stderr;
    memset(&t, 0, sizeof t);
    t.steps = calloc((size_t)(o.n > 0 ? o.n : 1), sizeof *t.steps);
    snprintf(path, sizeof path, "%s/scenes.tsv", o.out);
    FILE *tsv = fopen(path, "w");
    if (!t.steps || !tsv) {
        fprintf(stderr, "difftest: cannot write %s\n", path);
        return 1;
    }
    fprintf(tsv, "index\tname\tverdict\tedge_px\tinterior_px\tworst_interior\tmax_steps\twhy\n");
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (long i = o.first; i < o.first + o.n; i++)
        one_scene(&o, i, tsv, &t);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    fclose(tsv);
    if (null)
        fclose(null);
    summarise(&o, &t, (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
    free(t.steps);
    return regressed > 0 || t.verdicts[DT_INTERIOR] > 0 || t.verdicts[DT_FAILED] > 0;
}
