/*
 * cli_verify.c - `refray verify SCENE...`: each analytic scene rendered and
 * compared with its exact image, one table row (or JSON object) per scene;
 * with --sweep, each scene rendered at rising cost with the convergence
 * order fitted.  The exit code is the largest any scene gave (verify.h).
 * With --jobs N the scenes are checked on N worker processes (io/pool.h),
 * each scene on one, and printed in the order given, as without.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/pool.h"
#include "io/scene_file.h"
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "io/atomic.h"
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
    "  --jobs N               check N scenes at a time, each in a worker process of\n"
    "                         its own (default 1; 0: one per processor); the same\n"
    "                         output, but the render times are taken side by side\n"
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
    int jobs;
} verify_args;


/* 1: consumed, 0: error (reported), -1: not a verify option. */
static int verify_option(void *args, int argc, char **argv, int *i)
{
    verify_args *a = args;
    const char *opt = argv[*i];
    if (strcmp(opt, "--json") == 0)
        return a->json = 1;
    if (strcmp(opt, "--sweep") == 0)
        return cli_take_value(argc, argv, i, &a->sweep_text);
    if (strcmp(opt, "--tsv") == 0)
        return cli_take_value(argc, argv, i, &a->tsv_path);
    if (strcmp(opt, "--runs") == 0)
        return cli_int_value(argc, argv, i, VERIFY_RUNS_MAX, &a->view.runs);
    if (strcmp(opt, "--jobs") == 0) {
        const char *v;
        long jobs;
        if (!cli_take_value(argc, argv, i, &v) || !cli_parse_long(opt, v, 0, 256, &jobs))
            return 0;
        a->jobs = jobs ? (int)jobs : pool_cpu_count();
        return 1;
    }
    return cli_view_option(&a->view, 1, argc, argv, i);
}

/* The sweep is parsed after every option, so that a limit given after
 * --sweep still bounds its values. */
static int finish_args(verify_args *a)
{
    if (a->path_count == 0)
        return cli_usage_error("verify: no scene given");
    if (a->tsv_path && !a->sweep_text)
        return cli_usage_error("verify: --tsv needs --sweep");
    const verify_opts *v = &a->view;
    int status = cli_check_sizes(v->width, v->height, v->samples, v->light_samples, v->max_depth, &a->scene.limits);
    if (status != 0 || !a->sweep_text)
        return status;
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

static int verify_operand(void *args, const char *arg)
{
    verify_args *a = args;
    a->paths[a->path_count++] = arg;
    return 0;
}

static int parse_args(verify_args *a, int argc, char **argv)
{
    int status = cli_parse_command("verify", verify_help, argc, argv, &a->scene, verify_operand, verify_option, a);
    return status != 0 ? status : finish_args(a);
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

static const char *verdict_word(verify_verdict v)
{
    static const char *const words[] = {"pass", "FAIL", "REFUSED", "ERROR"};
    return words[v];
}

static void print_row(const verify_result *r, int w)
{
    printf("%-*s  %-*s", w, r->scene, family_width(), r->family[0] ? r->family : "-");
    if (r->measured) {
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
    printf("  %s\n", verdict_word(r->verdict));
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
    scene_model *s = cli_load_scene(&a->scene, path, &status);
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
    if (!r->measured) {
        printf("    %s\n", r->reason);
        return;
    }
    printf("  %7s %10s %10s %10s %10s %6s %9s %9s %12s  %s\n", "value", "N", "max abs", "RMS", "max rel", "over",
           "tolerance", "render s", "rays", "verdict");
    for (int i = 0; i < count; i++) {
        const image_metrics *m = &steps[i].metrics;
        printf("  %7d %10.0f %10.3e %10.3e %10.3e %6ld %9.2e %9.3f %12ld  %s\n", sw->values[i],
               verify_sweep_n(sw, i), m->max_abs, m->rms, m->max_rel, m->over, steps[i].tolerance,
               steps[i].render_seconds, steps[i].rays, verdict_word(steps[i].verdict));
    }
    print_order("N:", vs_n);
    print_order("seconds:", vs_time);
    printf("  expected order vs N: %s\n", verify_expected_order(r, sw));
}

/* Runs one scene's check or sweep into steps; returns its status. */
static int check_scene(const verify_args *a, int k, verify_result *steps, int *ran)
{
    const char *path = a->paths[k];
    int status;
    scene_model *s = load(a, path, &steps[0]);
    *ran = 1;
    if (!s)
        return steps[0].status;
    if (a->sweep_text) {
        status = verify_sweep_run(s, path, &a->view, &a->sweep, steps, ran);
    } else {
        verify_scene(s, path, &a->view, &steps[0]);
        status = steps[0].status;
    }
    scene_free(s);
    return status;
}

/* ---- The run: each scene checked, then printed in the order given ---- */

typedef struct verify_outcome {
    int status, ran;
    verify_result *steps;    /* ran of them; NULL until the scene is done */
} verify_outcome;

typedef struct verify_run {
    const verify_args *a;
    verify_outcome *out;
    verify_result *results;  /* a plain check's rows, for the JSON array */
    int printed;             /* scenes printed so far */
    int worst;
    int width;               /* of the scene column */
    FILE *tsv;
    int first_json;
} verify_run;

static void print_sweep_scene(verify_run *v, const verify_result *steps, int ran)
{
    const verify_args *a = v->a;
    verify_order vs_n, vs_time;
    verify_sweep_orders(&a->sweep, steps, ran, &vs_n, &vs_time);
    if (v->tsv)
        verify_tsv_sweep(v->tsv, &a->sweep, steps, ran, &vs_n, &vs_time);
    if (a->json) {
        fputs(v->first_json ? "[" : ",\n ", stdout);
        verify_json_sweep(stdout, &a->sweep, steps, ran, &vs_n, &vs_time);
        v->first_json = 0;
    } else {
        print_sweep(&a->sweep, steps, ran, &vs_n, &vs_time);
    }
}

/* Prints every finished scene whose turn has come. */
static void print_ready(verify_run *v)
{
    for (; v->printed < v->a->path_count && v->out[v->printed].steps; v->printed++) {
        verify_outcome *o = &v->out[v->printed];
        v->worst = status_worse(v->worst, o->status);
        if (v->a->sweep_text) {
            print_sweep_scene(v, o->steps, o->ran);
        } else {
            v->results[v->printed] = o->steps[0];
            if (!v->a->json)
                print_row(&o->steps[0], v->width);
        }
        fflush(stdout);
        free(o->steps);
        o->steps = NULL;
    }
}

/* Keeps scene k's outcome: status, steps[0 .. ran). */
static int keep(verify_run *v, int k, int status, const verify_result *steps, int ran)
{
    verify_outcome *o = &v->out[k];
    o->steps = malloc((size_t)ran * sizeof *o->steps);
    if (!o->steps) {
        fputs("refray: error: out of memory\n", stderr);
        return STATUS_NO_MEMORY;
    }
    memcpy(o->steps, steps, (size_t)ran * sizeof *steps);
    o->status = status;
    o->ran = ran;
    print_ready(v);
    return STATUS_OK;
}

/* A worker's scene: the status, the count, the steps, in one message. */
static int work(void *ctx, int k, pool_link *link)
{
    const verify_run *v = ctx;
    verify_result *steps = malloc(VERIFY_SWEEP_MAX * sizeof *steps + 2 * sizeof(int));
    int ran = 0, head[2];
    if (!steps)
        return STATUS_NO_MEMORY;
    head[0] = check_scene(v->a, k, steps, &ran);
    head[1] = ran;
    unsigned char *msg = (unsigned char *)steps;
    memmove(msg + sizeof head, steps, (size_t)ran * sizeof *steps);
    memcpy(msg, head, sizeof head);
    int sent = pool_send(link, msg, sizeof head + (size_t)ran * sizeof *steps);
    free(steps);
    return sent == 0 ? STATUS_OK : STATUS_CANCELLED;
}

static int message(void *ctx, int k, const void *data, size_t len)
{
    int head[2];
    memcpy(head, data, sizeof head);
    if (head[1] < 1 || head[1] > VERIFY_SWEEP_MAX || len != sizeof head + (size_t)head[1] * sizeof(verify_result))
        return STATUS_INTERNAL;
    verify_result *steps = malloc((size_t)head[1] * sizeof *steps);
    if (!steps)
        return STATUS_NO_MEMORY;
    memcpy(steps, (const unsigned char *)data + sizeof head, (size_t)head[1] * sizeof *steps);
    int rc = keep(ctx, k, head[0], steps, head[1]);
    free(steps);
    return rc;
}

static int run_scenes(verify_run *v, verify_result *steps)
{
    const verify_args *a = v->a;
    if (a->jobs > 1) {
        pool_ops ops = {work, NULL, message, NULL, v};
        pool_failure fail;
        char why[300];
        int rc = pool_run(a->jobs, a->path_count, &ops, cli_signal_flag(), &fail, why, sizeof why);
        if (rc != STATUS_OK && rc != STATUS_CANCELLED)
            cli_error("verify: %s", why[0] ? why : status_string(rc));
        return rc;
    }
    for (int k = 0; k < a->path_count; k++) {
        if (cli_signal_cancel(NULL))
            return STATUS_CANCELLED;
        int ran = 0, status = check_scene(a, k, steps, &ran);
        int rc = keep(v, k, status, steps, ran);
        if (rc != STATUS_OK)
            return rc;
    }
    return STATUS_OK;
}

/* The TSV goes through the atomic writer: it is at its path whole, or
 * not at all (a missing scene, a bad one, a signal: nothing), as every
 * output of every command ([REL-OUT-1]). */
static int finish_tsv(file_out *tsv, const char *path, int worst)
{
    char why[1024];
    /* A check that failed (exit 1) is a result worth keeping; an error is not. */
    if (worst != STATUS_OK && worst != STATUS_FAIL) {
        file_out_abort(tsv);
        cli_note("", "'%s' not written", path);
        return worst;
    }
    int status = file_out_commit(tsv, why, sizeof why);
    if (status != STATUS_OK && status != STATUS_CANCELLED)
        cli_error("%s", why);
    return status_worse(worst, status);
}

static int verify_all(const verify_args *a, verify_result *steps)
{
    verify_run v;
    file_out tsv;
    char why[1024];
    cancel_poll cancel = cancel_poll_make(cli_signal_cancel, NULL);
    memset(&v, 0, sizeof v);
    v.a = a;
    v.width = name_width(a);
    v.first_json = 1;
    v.out = calloc((size_t)a->path_count, sizeof *v.out);
    v.results = malloc((size_t)a->path_count * sizeof *v.results);
    if (!v.out || !v.results) {
        free(v.out);
        free(v.results);
        cli_error("out of memory");
        return STATUS_NO_MEMORY;
    }
    if (a->tsv_path && file_out_open(&tsv, a->tsv_path, &cancel, why, sizeof why) != STATUS_OK) {
        cli_error("%s", why);
        free(v.out);
        free(v.results);
        return STATUS_IO;
    }
    v.tsv = a->tsv_path ? tsv.fp : NULL;
    if (v.tsv)
        verify_tsv_header(v.tsv);
    if (!a->json && !a->sweep_text)
        print_header(v.width);
    int status = run_scenes(&v, steps);
    for (int k = 0; k < a->path_count; k++)
        free(v.out[k].steps);
    if (status == STATUS_OK && cli_signal_cancel(NULL))
        status = STATUS_CANCELLED;
    if (status == STATUS_OK && !a->sweep_text && a->json)
        verify_json_results(stdout, v.results, a->path_count);
    else if (status == STATUS_OK && !a->sweep_text)
        print_totals(v.results, a->path_count);
    else if (status == STATUS_OK && a->json)
        fputs(v.first_json ? "[]\n" : "]\n", stdout);
    status = status_worse(v.worst, status);
    if (a->tsv_path)
        status = finish_tsv(&tsv, a->tsv_path, status);
    free(v.out);
    free(v.results);
    return status;
}

/* In cli_stability.c: `verify --stability SCENE` is the stability tool. */
int cli_verify(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--stability") == 0)
            return cli_stability(argc, argv);
    verify_args a;
    memset(&a, 0, sizeof a);
    a.jobs = 1;
    cli_scene_opts_init(&a.scene);
    cli_signal_cooperate(1);
    a.view.cancel = cli_signal_cancel;
    a.paths = malloc((size_t)(argc > 0 ? argc : 1) * sizeof *a.paths);
    verify_result *results = malloc((size_t)(argc > VERIFY_SWEEP_MAX ? argc : VERIFY_SWEEP_MAX) * sizeof *results);
    int status = a.paths && results ? parse_args(&a, argc, argv) : STATUS_NO_MEMORY;
    if (status == STATUS_NO_MEMORY)
        cli_error("out of memory");
    else if (status < 0)
        status = STATUS_OK;
    else if (status == 0)
        status = verify_all(&a, results);
    free(results);
    free(a.paths);
    return status;
}
