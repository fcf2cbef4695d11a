/*
 * cli_verify.c - `refray verify SCENE...`: each analytic scene rendered and
 * compared with its exact image, one table row (or JSON object) per scene;
 * with --sweep, each scene rendered at rising cost with the convergence
 * order fitted.  The exit code is the largest any scene gave (verify.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/scene_file.h"
#include "cli/cli_args.h"
#include "cli/commands.h"

static const char verify_help[] =
    "usage: refray verify [OPTIONS] SCENE...\n"
    "Renders each analytic scene (one with `oracle NAME`) and compares the render\n"
    "with the exact image its oracle family computes at the same sample points.\n"
    "options:\n"
    "  --json                 a JSON array on stdout instead of the table\n"
    "  --width W --height H   override the image size (the exact image follows)\n"
    "  --samples K            K x K camera rays per pixel\n"
    "  --light-samples N      N point sources for every distributed light\n"
    "  --max-depth D          trace depth (1: camera rays only)\n"
    "  --sweep samples=N,N,...       render at each light-sample count, or\n"
    "  --sweep pixel-samples=K,K,... at each K x K camera grid; report error and\n"
    "                         time per step and the order fitted in log-log\n"
    "  --tsv FILE             with --sweep: every step as a TSV row (spec/verify.md)\n"
    "  --runs R               render R times, report the median time (default 1)\n"
    "and -W and the input limits of `refray --help`.\n"
    "table: pixels, excluded (ambiguous pixels, not compared), max abs, RMS and\n"
    "max rel error, PSNR (dB, peak = the exact image's largest value), over (pixels\n"
    "with a channel over tolerance x |exact|), tolerance (relative, the family's),\n"
    "render and oracle seconds, rays traced, verdict.\n"
    "exit: 0 every scene passed; 1 a scene missed its tolerance, was refused or\n"
    "names an unknown family; 65 a bad scene or one without `oracle`; 66 a\n"
    "missing scene; 70 out of memory.  The largest code met wins.\n";

typedef struct verify_args {
    cli_scene_opts scene;
    verify_opts view;
    int json;
    const char *sweep_text, *tsv_path;
    verify_sweep sweep;
    const char **paths;
    int path_count;
} verify_args;


/* 1: consumed, 0: error (reported), -1: not a verify option. */
static int verify_option(verify_args *a, int argc, char **argv, int *i)
{
    const char *opt = argv[*i];
    if (strcmp(opt, "--json") == 0)
        return a->json = 1;
    if (strcmp(opt, "--sweep") == 0)
        return cli_take_value(argc, argv, i, &a->sweep_text);
    if (strcmp(opt, "--tsv") == 0)
        return cli_take_value(argc, argv, i, &a->tsv_path);
    if (strcmp(opt, "--runs") == 0)
        return cli_int_value(argc, argv, i, VERIFY_RUNS_MAX, &a->view.runs);
    return cli_view_option(&a->view, &a->scene.limits, 1, argc, argv, i);
}

/* The sweep is parsed after every option, so that a limit given after
 * --sweep still bounds its values. */
static int finish_args(verify_args *a)
{
    if (a->path_count == 0)
        return cli_usage_error("verify: no scene given");
    if (a->tsv_path && !a->sweep_text)
        return cli_usage_error("verify: --tsv needs --sweep");
    if (!a->sweep_text)
        return 0;
    int pixel = strncmp(a->sweep_text, "pixel-", 6) == 0;
    if (pixel ? a->view.samples != 0 : a->view.light_samples != 0)
        return cli_usage_error("verify: --sweep %s and --%s both set the %s samples", a->sweep_text,
                               pixel ? "samples" : "light-samples", pixel ? "camera" : "light");
    char why[256];
    long max = pixel ? a->scene.limits.max_samples : a->scene.limits.max_light_samples;
    if (!verify_sweep_parse(a->sweep_text, (int)(max < 1000000000 ? max : 1000000000), &a->sweep, why, sizeof why))
        return cli_usage_error("verify: %s", why);
    return 0;
}

static int parse_args(verify_args *a, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(verify_help, stdout);
            return -1;
        }
        int used = cli_scene_opt(&a->scene, argc, argv, i);
        if (used < 0)
            return STATUS_USAGE;
        if (used > 0) {
            i += used - 1;
            continue;
        }
        if (argv[i][0] != '-' || !argv[i][1]) {
            a->paths[a->path_count++] = argv[i];
            continue;
        }
        int r = verify_option(a, argc, argv, &i);
        if (r == 0)
            return STATUS_USAGE;
        if (r < 0)
            return cli_usage_error("verify: unknown option '%s'", argv[i]);
    }
    return finish_args(a);
}

/* ---- The table ---- */

static int name_width(const verify_args *a)
{
    int w = 5;
    for (int i = 0; i < a->path_count; i++) {
        int n = (int)strlen(a->paths[i]);
        w = n > w ? n : w;
    }
    return w > 48 ? 48 : w;
}

/* The longest family name, so the family column never runs over. */
static int family_width(void)
{
    int count, w = 6;
    const oracle_family *const *all = oracle_families(&count);
    for (int i = 0; i < count; i++) {
        int n = (int)strlen(all[i]->name);
        w = n > w ? n : w;
    }
    return w;
}

static void print_header(int w)
{
    printf("%-*s  %-*s %7s %6s %10s %10s %10s %8s %6s %9s %9s %9s %12s  %s\n", w, "scene", family_width(), "family",
           "pixels", "excl", "max abs", "RMS", "max rel", "PSNR dB", "over", "tolerance", "render s", "oracle s", "rays",
           "verdict");
}

static void print_psnr(double psnr)
{
    if (psnr < 1e300)
        printf(" %8.2f", psnr);
    else
        printf(" %8s", "inf");
}

static void print_row(const verify_result *r, int w)
{
    static const char *const verdicts[] = {"pass", "FAIL", "REFUSED", "ERROR"};
    printf("%-*s  %-*s", w, r->scene, family_width(), r->family[0] ? r->family : "-");
    if (r->verdict == VERIFY_PASS || r->verdict == VERIFY_FAIL) {
        const image_metrics *m = &r->metrics;
        printf(" %7ld %6ld %10.3e %10.3e %10.3e", (long)r->width * r->height, m->excluded, m->max_abs, m->rms,
               m->max_rel);
        print_psnr(m->psnr);
        printf(" %6ld %9.2e %9.3f %9.3f %12ld", m->over, r->tolerance, r->render_seconds, r->oracle_seconds,
               r->rays);
    } else {
        printf(" %7s %6s %10s %10s %10s %8s %6s %9s %9s %9s %12s", "-", "-", "-", "-", "-", "-", "-", "-", "-", "-",
               "-");
    }
    printf("  %s\n", verdicts[r->verdict]);
    if (r->verdict == VERIFY_FAIL && r->metrics.compared > 0)
        printf("    %s; largest error at pixel (%d, %d)\n", r->reason, r->metrics.worst_x, r->metrics.worst_y);
    else if (r->verdict != VERIFY_PASS)
        printf("    %s\n", r->reason);
}

static void print_totals(const verify_result *r, int count)
{
    int n[4] = {0, 0, 0, 0};
    for (int i = 0; i < count; i++)
        n[r[i].verdict]++;
    printf("%d scene%s: %d passed, %d failed, %d refused, %d not checked\n", count, count == 1 ? "" : "s", n[0],
           n[1], n[2], n[3]);
}

/* ---- One scene ---- */

static const char *load_reason(int status)
{
    if (status == STATUS_NO_INPUT)
        return "cannot read the scene (see the message above)";
    if (status == STATUS_NO_MEMORY)
        return "out of memory loading the scene";
    return "not a valid scene (see the diagnostics above)";
}

/* Loads path; NULL with r filled as an error when it cannot be used. */
static scene_model *load(const verify_args *a, const char *path, verify_result *r)
{
    int status;
    memset(r, 0, sizeof *r);
    scene_model *s = scene_file_load(path, &a->scene.limits, stderr, a->scene.warnings, &status);
    if (!s) {
        verify_result_error(r, path, status, load_reason(status));
        return NULL;
    }
    oracle_view v = verify_view(s, &a->view);
    char why[256];
    if (!cli_view_fits(&v, &a->scene.limits, why, sizeof why)) {
        verify_result_error(r, path, STATUS_USAGE, why);
        scene_free(s);
        return NULL;
    }
    return s;
}

static int verify_all(const verify_args *a, verify_result *results)
{
    int worst = STATUS_OK, w = name_width(a);
    if (!a->json)
        print_header(w);
    for (int i = 0; i < a->path_count; i++) {
        scene_model *s = load(a, a->paths[i], &results[i]);
        if (s) {
            verify_scene(s, a->paths[i], &a->view, &results[i]);
            scene_free(s);
        }
        worst = status_worse(worst, results[i].status);
        if (!a->json) {
            print_row(&results[i], w);
            fflush(stdout);
        }
    }
    if (a->json)
        verify_json_results(stdout, results, a->path_count);
    else
        print_totals(results, a->path_count);
    return worst;
}

/* ---- Sweeps ---- */

static void print_order(const char *label, const verify_order *o)
{
    if (o->meaningful)
        printf("  order vs %-8s slope %.3f +- %.3f (%d steps, r2 %.4f)\n", label, o->line.slope,
               isfinite(o->line.slope_se) ? o->line.slope_se : 0.0, o->line.points, o->line.r2);
    else
        printf("  order vs %-8s %s\n", label, o->note);
}

static void print_sweep(const verify_sweep *sw, const verify_result *steps, int count, const verify_order *vs_n,
                        const verify_order *vs_time)
{
    const verify_result *r = &steps[0];
    printf("%s: family %s%s, sweep %s\n", r->scene, r->family[0] ? r->family : "-",
           r->sampled ? " (sampled)" : " (deterministic)", verify_sweep_name(sw->kind));
    if (r->verdict == VERIFY_REFUSED || r->verdict == VERIFY_ERROR) {
        printf("    %s\n", r->reason);
        return;
    }
    printf("  %7s %10s %10s %10s %10s %6s %9s %9s %12s  %s\n", "value", "N", "max abs", "RMS", "max rel", "over",
           "tolerance", "render s", "rays", "verdict");
    for (int i = 0; i < count; i++) {
        const image_metrics *m = &steps[i].metrics;
        printf("  %7d %10.0f %10.3e %10.3e %10.3e %6ld %9.2e %9.3f %12ld  %s\n", sw->values[i],
               verify_sweep_n(sw, i), m->max_abs, m->rms, m->max_rel, m->over, steps[i].tolerance,
               steps[i].render_seconds, steps[i].rays, steps[i].verdict == VERIFY_PASS ? "pass" : "FAIL");
    }
    print_order("N:", vs_n);
    print_order("seconds:", vs_time);
    printf("  expected order vs N: %s\n", verify_expected_order(r, sw));
}

/* Sweeps one scene; prints it; returns its worst status. */
static int sweep_one(const verify_args *a, const char *path, verify_result *steps, FILE *tsv, int *first_json)
{
    int ran = 0, status;
    scene_model *s = load(a, path, &steps[0]);
    if (s) {
        status = verify_sweep_run(s, path, &a->view, &a->sweep, steps, &ran);
        scene_free(s);
    } else {
        status = steps[0].status;
        ran = 1;
    }
    verify_order vs_n, vs_time;
    verify_sweep_orders(&a->sweep, steps, ran, &vs_n, &vs_time);
    if (tsv)
        verify_tsv_sweep(tsv, &a->sweep, steps, ran, &vs_n, &vs_time);
    if (a->json) {
        fputs(*first_json ? "[" : ",\n ", stdout);
        verify_json_sweep(stdout, &a->sweep, steps, ran, &vs_n, &vs_time);
        *first_json = 0;
    } else {
        print_sweep(&a->sweep, steps, ran, &vs_n, &vs_time);
    }
    fflush(stdout);
    return status;
}

static int close_tsv(FILE *tsv, const char *path)
{
    if (!tsv)
        return STATUS_OK;
    int bad = ferror(tsv);
    bad |= fclose(tsv) != 0;
    if (!bad)
        return STATUS_OK;
    fprintf(stderr, "refray: error: could not write '%s'\n", path);
    return STATUS_IO;
}

static int sweep_all(const verify_args *a, verify_result *steps)
{
    FILE *tsv = NULL;
    if (a->tsv_path && !(tsv = fopen(a->tsv_path, "w"))) {
        fprintf(stderr, "refray: error: cannot write '%s'\n", a->tsv_path);
        return STATUS_IO;
    }
    if (tsv)
        verify_tsv_header(tsv);
    int worst = STATUS_OK, first_json = 1;
    for (int i = 0; i < a->path_count; i++) {
        int status = sweep_one(a, a->paths[i], steps, tsv, &first_json);
        worst = status_worse(worst, status);
    }
    if (a->json)
        fputs(first_json ? "[]\n" : "]\n", stdout);
    int status = close_tsv(tsv, a->tsv_path);
    return status_worse(worst, status);
}

/* In cli_stability.c: `verify --stability SCENE` is the stability tool. */
int cli_verify(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--stability") == 0)
            return cli_stability(argc, argv);
    verify_args a;
    memset(&a, 0, sizeof a);
    cli_scene_opts_init(&a.scene);
    a.paths = malloc((size_t)(argc > 0 ? argc : 1) * sizeof *a.paths);
    verify_result *results = malloc((size_t)(argc > VERIFY_SWEEP_MAX ? argc : VERIFY_SWEEP_MAX) * sizeof *results);
    int status = a.paths && results ? parse_args(&a, argc, argv) : STATUS_NO_MEMORY;
    if (status == STATUS_NO_MEMORY)
        fputs("refray: error: out of memory\n", stderr);
    else if (status < 0)
        status = STATUS_OK;
    else if (status == 0)
        status = a.sweep_text ? sweep_all(&a, results) : verify_all(&a, results);
    free(results);
    free(a.paths);
    return status;
}
