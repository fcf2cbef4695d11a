/*
 * verify.c - see verify.h.  The render and the exact image are made for
 * the same oracle_view (size, k x k camera grid, depth), so the two are
 * compared at the very points the tracer samples; the family's tolerance
 * is asked for the light samples the render used.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "render/render.h"
#include "verify/verify.h"
#include "io/atomic.h"
#include "io/fileio.h"

static void copy_text(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src ? src : "");
}

oracle_view verify_view(const scene_model *s, const verify_opts *o)
{
    oracle_view v;
    v.scene = s;
    v.width = o && o->width > 0 ? o->width : s->image.width;
    v.height = o && o->height > 0 ? o->height : s->image.height;
    v.samples = o && o->samples > 0 ? o->samples : s->image.samples;
    v.max_depth = o && o->max_depth > 0 ? o->max_depth : s->image.max_depth;
    return v;
}

/* "a, b, c": the names of every family, for the unknown-family message. */
static void family_names(char *out, size_t size)
{
    int count;
    const oracle_family *const *all = oracle_families(&count);
    size_t used = 0;
    out[0] = '\0';
    for (int i = 0; i < count && used < size; i++) {
        int n = snprintf(out + used, size - used, "%s%s", i ? ", " : "", all[i]->name);
        used += n > 0 ? (size_t)n : 0;
    }
}

const oracle_family *verify_family(const scene_model *s, const oracle_view *v, int *status, char *why,
                                   size_t why_size)
{
    if (!s->oracle) {
        *status = STATUS_DATA;
        snprintf(why, why_size, "the scene has no `oracle NAME` statement, so there is no exact image to "
                 "compare with (the analytic scenes are in scenes/analytic/)");
        return NULL;
    }
    const oracle_family *f = oracle_find(s->oracle);
    if (!f) {
        char names[384];
        family_names(names, sizeof names);
        *status = STATUS_FAIL;
        snprintf(why, why_size, "no oracle family is called '%s' (known: %s)", s->oracle, names);
        return NULL;
    }
    why[0] = '\0';
    if (!f->accepts(v, why, why_size)) {
        *status = STATUS_FAIL;
        if (!why[0])
            snprintf(why, why_size, "%s: the family refused the scene", f->name);
        return NULL;
    }
    *status = STATUS_OK;
    return f;
}

void verify_exact_free(verify_exact *e)
{
    img_free(&e->image);
    free(e->excluded);
    e->excluded = NULL;
    e->excluded_count = 0;
}

int verify_exact_build(const oracle_family *f, const oracle_view *v, verify_exact *e)
{
    memset(e, 0, sizeof *e);
    e->family = f;
    e->view = *v;
    e->excluded = calloc((size_t)v->width * (size_t)v->height, 1);
    double start = render_clock();
    int status = e->excluded ? oracle_image(f, v, &e->image, e->excluded, &e->excluded_count) : STATUS_NO_MEMORY;
    if (status != STATUS_OK) {
        verify_exact_free(e);
        return status;
    }
    e->seconds = render_clock() - start;
    return STATUS_OK;
}

const char *verify_exact_error(int status)
{
    return status == STATUS_OK   ? NULL
           : status == STATUS_FAIL ? VERIFY_INEXACT " (a point's exact value came out negative or not finite)"
                                   : "out of memory building the exact image";
}

int verify_tolerance_usable(double tolerance)
{
    return isfinite(tolerance) && tolerance >= 0;
}

int verify_tolerance_decisive(double tolerance)
{
    return verify_tolerance_usable(tolerance) && tolerance < VERIFY_DECISIVE_BELOW;
}

void verify_result_error(verify_result *r, const char *path, int status, const char *reason)
{
    if (r->scene != path)
        copy_text(r->scene, sizeof r->scene, path);
    r->verdict = status == STATUS_FAIL ? VERIFY_REFUSED : VERIFY_ERROR;
    r->status = status;
    if (r->reason != reason)
        copy_text(r->reason, sizeof r->reason, reason);
}

static long rays_of(const trace_stats *t)
{
    return t->camera_rays + t->shadow_rays + t->reflection_rays + t->refraction_rays + t->tir_rays;
}

static void judge(verify_result *r)
{
    const image_metrics *m = &r->metrics;
    r->verdict = VERIFY_PASS;
    r->status = STATUS_OK;
    if (m->compared == 0)
        copy_text(r->reason, sizeof r->reason, "every pixel was excluded: nothing was compared");
    else if (m->over > 0)
        snprintf(r->reason, sizeof r->reason, "%ld pixel%s over the relative tolerance %.3g", m->over,
                 m->over == 1 ? "" : "s", r->tolerance);
    else
        return;
    r->verdict = VERIFY_FAIL;
    r->status = STATUS_FAIL;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Renders runs times (the image is the same every time: the samples are a
 * pure function of the pixel), keeps the first image and the median time. */
static int timed_render(const scene_model *s, const render_opts *ro, int runs, img_buf *img, render_stats *st,
                        double *seconds)
{
    double times[VERIFY_RUNS_MAX];
    runs = runs < 1 ? 1 : runs > VERIFY_RUNS_MAX ? VERIFY_RUNS_MAX : runs;
    for (int i = 0; i < runs; i++) {
        img_buf again = {0};
        render_stats st_again;
        double start = render_clock();
        int status = render_image(s, ro, i == 0 ? img : &again, i == 0 ? st : &st_again);
        times[i] = render_clock() - start;
        img_free(&again);
        if (status != STATUS_OK) {
            img_free(img);
            return status;
        }
    }
    qsort(times, (size_t)runs, sizeof times[0], by_value);
    *seconds = runs % 2 ? times[runs / 2] : 0.5 * (times[runs / 2 - 1] + times[runs / 2]);
    return STATUS_OK;
}

int verify_render_compare(const scene_model *s, const verify_opts *o, const verify_exact *e, verify_result *r)
{
    render_opts ro;
    memset(&ro, 0, sizeof ro);
    ro.width = e->view.width;
    ro.height = e->view.height;
    ro.samples = e->view.samples;
    ro.max_depth = e->view.max_depth;
    ro.light_samples = o ? o->light_samples : 0;
    ro.cancel = o ? o->cancel : NULL;
    ro.cancel_ctx = o ? o->cancel_user : NULL;
    img_buf img = {0};
    render_stats st;
    memset(&st, 0, sizeof st);
    int status = timed_render(s, &ro, o ? o->runs : 1, &img, &st, &r->render_seconds);
    r->oracle_seconds = e->seconds;
    if (status != STATUS_OK) {
        verify_result_error(r, r->scene, status, status == STATUS_NO_MEMORY ? "out of memory while rendering"
                                                 : status == STATUS_CANCELLED ? "interrupted"
                                                                              : "the render was stopped");
        return status;
    }
    r->rays = rays_of(&st.trace);
    r->tolerance = e->family->tolerance(&e->view, ro.light_samples);
    if (!verify_tolerance_usable(r->tolerance)) {
        img_free(&img);
        char why[sizeof r->reason];
        snprintf(why, sizeof why, "%s (its error bound, relative, is %.3g)", VERIFY_INEXACT, r->tolerance);
        verify_result_error(r, r->scene, STATUS_FAIL, why);
        return r->status;
    }
    metrics_compare(&img, &e->image, e->excluded, r->tolerance, &r->metrics);
    img_free(&img);
    r->measured = 1;
    judge(r);
    if (r->verdict == VERIFY_PASS && !verify_tolerance_decisive(r->tolerance)) {
        char why[sizeof r->reason];
        snprintf(why, sizeof why, "%s (it is %.3g here: use more light samples)", VERIFY_UNBOUNDED, r->tolerance);
        verify_result_error(r, r->scene, STATUS_FAIL, why);
    }
    return r->status;
}

/* Fills r's identity and view, finds the family.  Returns r->status
 * (0 when the scene can be checked, with *f set). */
static int prepare(const scene_model *s, const char *path, const verify_opts *o, verify_result *r,
                   const oracle_family **f)
{
    memset(r, 0, sizeof *r);
    copy_text(r->scene, sizeof r->scene, path);
    copy_text(r->family, sizeof r->family, s->oracle);
    oracle_view v = verify_view(s, o);
    r->width = v.width;
    r->height = v.height;
    r->samples = v.samples;
    r->max_depth = v.max_depth;
    r->light_samples = o ? o->light_samples : 0;
    r->metrics.psnr = HUGE_VAL;
    int status;
    *f = verify_family(s, &v, &status, r->reason, sizeof r->reason);
    if (!*f) {
        verify_result_error(r, path, status, r->reason);
        return status;
    }
    r->sampled = (*f)->sampled;
    return STATUS_OK;
}

int verify_scene(const scene_model *s, const char *path, const verify_opts *o, verify_result *r)
{
    const oracle_family *f;
    if (prepare(s, path, o, r, &f) != STATUS_OK)
        return r->status;
    verify_exact e;
    oracle_view v = verify_view(s, o);
    int status = verify_exact_build(f, &v, &e);
    if (status != STATUS_OK) {
        verify_result_error(r, path, status, verify_exact_error(status));
        return r->status;
    }
    verify_render_compare(s, o, &e, r);
    verify_exact_free(&e);
    return r->status;
}

/* ---- Sweeps ---- */

const char *verify_sweep_name(verify_sweep_kind kind)
{
    return kind == VERIFY_SWEEP_PIXEL ? "pixel-samples" : "samples";
}

double verify_sweep_n(const verify_sweep *sw, int step)
{
    double v = sw->values[step];
    return sw->kind == VERIFY_SWEEP_PIXEL ? v * v : v;
}

/* One whole number of a sweep list at *p, moved past it. */
static int sweep_value(const char **p, int max, int *out, char *why, size_t n)
{
    char *end;
    long v = strtol(*p, &end, 10);
    if (end == *p || v < 1 || v > max || (*end && (*end != ',' || !end[1]))) {
        snprintf(why, n, "sweep values are whole numbers from 1 to %d, separated by commas ('%s')", max, *p);
        return 0;
    }
    *out = (int)v;
    *p = *end ? end + 1 : end;
    return 1;
}

int verify_sweep_parse(const char *text, int max, verify_sweep *sw, char *why, size_t why_size)
{
    const char *eq = strchr(text, '=');
    size_t len = eq ? (size_t)(eq - text) : 0;
    memset(sw, 0, sizeof *sw);
    if (eq && len == 7 && strncmp(text, "samples", len) == 0)
        sw->kind = VERIFY_SWEEP_LIGHT;
    else if (eq && len == 13 && strncmp(text, "pixel-samples", len) == 0)
        sw->kind = VERIFY_SWEEP_PIXEL;
    else {
        snprintf(why, why_size, "--sweep takes samples=N,N,... or pixel-samples=K,K,..., not '%s'", text);
        return 0;
    }
    const char *p = eq + 1;
    while (*p) {
        if (sw->count == VERIFY_SWEEP_MAX) {
            snprintf(why, why_size, "a sweep has at most %d steps", VERIFY_SWEEP_MAX);
            return 0;
        }
        if (!sweep_value(&p, max, &sw->values[sw->count++], why, why_size))
            return 0;
    }
    if (sw->count == 0)
        snprintf(why, why_size, "--sweep %s lists no values", text);
    return sw->count > 0;
}

/* Step i's options: o with the swept setting replaced. */
static verify_opts step_opts(const verify_opts *o, const verify_sweep *sw, int i)
{
    verify_opts so;
    memset(&so, 0, sizeof so);
    if (o)
        so = *o;
    if (sw->kind == VERIFY_SWEEP_PIXEL)
        so.samples = sw->values[i];
    else
        so.light_samples = sw->values[i];
    return so;
}

int verify_sweep_run(const scene_model *s, const char *path, const verify_opts *o, const verify_sweep *sw,
                     verify_result *steps, int *ran)
{
    verify_exact e;
    int have_exact = 0, worst = STATUS_OK;
    *ran = 0;
    for (int i = 0; i < sw->count; i++) {
        verify_opts so = step_opts(o, sw, i);
        const oracle_family *f;
        *ran = i + 1;
        if (prepare(s, path, &so, &steps[i], &f) != STATUS_OK)
            return status_worse(worst, steps[i].status);
        if (have_exact && sw->kind == VERIFY_SWEEP_PIXEL) {
            verify_exact_free(&e);
            have_exact = 0;
        }
        oracle_view v = verify_view(s, &so);
        int status = have_exact ? STATUS_OK : verify_exact_build(f, &v, &e);
        if (status != STATUS_OK) {
            verify_result_error(&steps[i], path, status, verify_exact_error(status));
            return status_worse(worst, status);
        }
        have_exact = 1;
        int step = verify_render_compare(s, &so, &e, &steps[i]);
        /* A step whose bound carries no verdict still measures the error
         * the sweep is for; it does not fail the sweep. */
        if (!(steps[i].measured && steps[i].verdict == VERIFY_REFUSED))
            worst = status_worse(worst, step);
    }
    if (have_exact)
        verify_exact_free(&e);
    return worst;
}

/* The steps above the round-off floor: their N (or seconds) and RMS. */
static int fit_points(const verify_sweep *sw, const verify_result *steps, int count, int by_time, double *x,
                      double *y)
{
    int m = 0;
    for (int i = 0; i < count && i < VERIFY_SWEEP_MAX; i++) {
        const verify_result *r = &steps[i];
        if (!r->measured)
            continue;
        if (!(r->metrics.rms > VERIFY_ROUNDOFF * r->metrics.peak))
            continue;
        x[m] = by_time ? r->render_seconds : verify_sweep_n(sw, i);
        y[m++] = r->metrics.rms;
    }
    return m;
}

static void order_of(const verify_sweep *sw, const verify_result *steps, int count, int by_time, verify_order *o)
{
    double x[VERIFY_SWEEP_MAX] = {0}, y[VERIFY_SWEEP_MAX] = {0};
    int m = fit_points(sw, steps, count, by_time, x, y);
    fit_loglog(x, y, m, &o->line);
    int rendered = 0;
    for (int i = 0; i < count; i++)
        rendered += steps[i].measured;
    o->meaningful = 0;
    if (rendered == 0)
        snprintf(o->note, sizeof o->note, "not meaningful: no step was rendered");
    else if (m == 0)
        snprintf(o->note, sizeof o->note, "not meaningful: the error is at round-off (RMS <= %g x peak) at every "
                 "step, as for an exact (deterministic) scene", VERIFY_ROUNDOFF);
    else if (m < 3)
        snprintf(o->note, sizeof o->note, "not meaningful: only %d step%s above round-off (3 needed)", m,
                 m == 1 ? "" : "s");
    else if (!isfinite(o->line.slope))
        snprintf(o->note, sizeof o->note, "not meaningful: every step has the same %s",
                 by_time ? "time" : "N");
    else {
        o->meaningful = 1;
        snprintf(o->note, sizeof o->note, "fitted to %d steps", m);
    }
}

void verify_sweep_orders(const verify_sweep *sw, const verify_result *steps, int count, verify_order *vs_n,
                         verify_order *vs_time)
{
    order_of(sw, steps, count, 0, vs_n);
    order_of(sw, steps, count, 1, vs_time);
}

/*
 * Stratified jittered sampling of a smooth integrand over a 2-D domain has
 * variance O(N^-2), an RMS error of order N^-1; a discontinuity crossing
 * the domain (a shadow edge across the light) leaves O(N^-3/2), order
 * N^-3/4 (Mitchell, "Consequences of stratified sampling in graphics",
 * SIGGRAPH 1996).  Averaging k^2 independent such estimates per pixel
 * divides the RMS by k: order (k^2)^-1/2.
 */
const char *verify_expected_order(const verify_result *r, const verify_sweep *sw)
{
    if (!r->measured)
        return "unknown: the scene was not checked";
    if (!r->sampled)
        return "none: exact at every step (deterministic family)";
    if (sw->kind == VERIFY_SWEEP_PIXEL)
        return "-0.5 (k*k independent light estimates averaged)";
    return "-1 (stratified, smooth light); -0.75 where a shadow edge crosses the light";
}

/* ---- JSON and TSV ---- */

/* The two-character escape of c, or 0 when it has none. */
static char short_escape(unsigned char c)
{
    switch (c) {
    case '"': return '"';
    case '\\': return '\\';
    case '\b': return 'b';
    case '\f': return 'f';
    case '\n': return 'n';
    case '\r': return 'r';
    case '\t': return 't';
    default: return 0;
    }
}

void verify_json_string(FILE *fp, const char *s)
{
    fputc('"', fp);
    for (const unsigned char *p = (const unsigned char *)(s ? s : ""); *p; p++) {
        char e = short_escape(*p);
        if (e)
            fprintf(fp, "\\%c", e);
        else if (*p < 0x20 || *p == 0x7f)
            fprintf(fp, "\\u%04x", *p);
        else
            fputc(*p, fp);
    }
    fputc('"', fp);
}

void verify_json_number(FILE *fp, double v)
{
    if (isfinite(v))
        fprintf(fp, "%.17g", v);
    else
        fputs("null", fp);
}

/* ", "key": " then the value's writer is called by the caller. */
static void json_key(FILE *fp, const char *key, int first)
{
    fputs(first ? "" : ", ", fp);
    verify_json_string(fp, key);
    fputs(": ", fp);
}

static void json_num(FILE *fp, const char *key, double v)
{
    json_key(fp, key, 0);
    verify_json_number(fp, v);
}

static void json_long(FILE *fp, const char *key, long v)
{
    json_key(fp, key, 0);
    fprintf(fp, "%ld", v);
}

void verify_json_metrics(FILE *fp, const image_metrics *m, double tolerance)
{
    json_key(fp, "compared", 1);
    fprintf(fp, "%ld", m->compared);
    json_long(fp, "excluded", m->excluded);
    json_num(fp, "max_abs", m->max_abs);
    json_num(fp, "rms", m->rms);
    json_num(fp, "max_rel", m->max_rel);
    json_num(fp, "psnr", m->psnr);
    json_num(fp, "peak", m->peak);
    json_long(fp, "over", m->over);
    json_num(fp, "tolerance", tolerance);
    json_key(fp, "worst", 0);
    fprintf(fp, "[%d, %d]", m->worst_x, m->worst_y);
    json_long(fp, "nonfinite", m->nonfinite);
    json_key(fp, "first_nonfinite", 0);
    if (m->nonfinite)
        fprintf(fp, "[%d, %d]", m->nonfinite_x, m->nonfinite_y);
    else
        fputs("null", fp);
}

static const char *verdict_name(verify_verdict v)
{
    static const char *const names[] = {"pass", "fail", "refused", "error"};
    return names[v];
}

void verify_json_result(FILE *fp, const verify_result *r)
{
    fputc('{', fp);
    json_key(fp, "scene", 1);
    verify_json_string(fp, r->scene);
    json_key(fp, "family", 0);
    if (r->family[0])
        verify_json_string(fp, r->family);
    else
        fputs("null", fp);
    json_key(fp, "verdict", 0);
    verify_json_string(fp, verdict_name(r->verdict));
    json_long(fp, "status", status_exit_code(r->status));
    json_key(fp, "reason", 0);
    if (r->verdict == VERIFY_PASS)
        fputs("null", fp);
    else
        verify_json_string(fp, r->reason);
    if (r->measured) {
        json_key(fp, "sampled", 0);
        fputs(r->sampled ? "true" : "false", fp);
        json_long(fp, "width", r->width);
        json_long(fp, "height", r->height);
        json_long(fp, "samples", r->samples);
        json_long(fp, "max_depth", r->max_depth);
        json_long(fp, "light_samples", r->light_samples);
        json_long(fp, "pixels", (long)r->width * r->height);
        fputs(", ", fp);
        verify_json_metrics(fp, &r->metrics, r->tolerance);
        json_num(fp, "render_seconds", r->render_seconds);
        json_num(fp, "oracle_seconds", r->oracle_seconds);
        json_long(fp, "rays", r->rays);
    }
    fputc('}', fp);
}

void verify_json_results(FILE *fp, const verify_result *r, int count)
{
    fputc('[', fp);
    for (int i = 0; i < count; i++) {
        fputs(i ? ",\n " : "", fp);
        verify_json_result(fp, &r[i]);
    }
    fputs("]\n", fp);
}

static void json_order(FILE *fp, const char *key, const verify_order *o)
{
    json_key(fp, key, 0);
    fputc('{', fp);
    json_key(fp, "slope", 1);
    verify_json_number(fp, o->line.slope);
    json_num(fp, "slope_se", o->line.slope_se);
    json_num(fp, "r2", o->line.r2);
    json_long(fp, "points", o->line.points);
    json_key(fp, "meaningful", 0);
    fputs(o->meaningful ? "true" : "false", fp);
    json_key(fp, "note", 0);
    verify_json_string(fp, o->note);
    fputc('}', fp);
}

void verify_json_sweep(FILE *fp, const verify_sweep *sw, const verify_result *steps, int count,
                       const verify_order *vs_n, const verify_order *vs_time)
{
    fputc('{', fp);
    json_key(fp, "scene", 1);
    verify_json_string(fp, count > 0 ? steps[0].scene : "");
    json_key(fp, "sweep", 0);
    verify_json_string(fp, verify_sweep_name(sw->kind));
    json_key(fp, "expected_order", 0);
    verify_json_string(fp, count > 0 ? verify_expected_order(&steps[0], sw) : "");
    json_key(fp, "steps", 0);
    fputc('[', fp);
    for (int i = 0; i < count; i++) {
        fputs(i ? ",\n  " : "\n  ", fp);
        fprintf(fp, "{\"value\": %d, \"n\": ", sw->values[i]);
        verify_json_number(fp, verify_sweep_n(sw, i));
        fputs(", \"result\": ", fp);
        verify_json_result(fp, &steps[i]);
        fputc('}', fp);
    }
    fputc(']', fp);
    json_order(fp, "order_vs_n", vs_n);
    json_order(fp, "order_vs_seconds", vs_time);
    fputc('}', fp);
}

void verify_tsv_header(FILE *fp)
{
    fputs("scene\tfamily\tsweep\tvalue\tn\tlight_samples\tpixel_samples\twidth\theight\tpixels\texcluded\t"
          "max_abs\trms\tmax_rel\tpsnr\tover\ttolerance\trender_seconds\toracle_seconds\trays\tverdict\n",
          fp);
}

/* A TSV field may not hold a tab or a line break: those become spaces. */
static void tsv_text(FILE *fp, const char *s)
{
    for (; *s; s++)
        fputc(*s == '\t' || *s == '\n' || *s == '\r' ? ' ' : *s, fp);
}

static void tsv_step(FILE *fp, const verify_sweep *sw, const verify_result *r, int i)
{
    const image_metrics *m = &r->metrics;
    tsv_text(fp, r->scene);
    fputc('\t', fp);
    tsv_text(fp, r->family[0] ? r->family : "-");
    fprintf(fp, "\t%s\t%d\t%.17g\t%d\t%d\t%d\t%d\t%ld\t%ld", verify_sweep_name(sw->kind), sw->values[i],
            verify_sweep_n(sw, i), r->light_samples, r->samples, r->width, r->height, (long)r->width * r->height,
            m->excluded);
    fprintf(fp, "\t%.9e\t%.9e\t%.9e\t%.6f\t%ld\t%.9g\t%.6f\t%.6f\t%ld\t%s\n", m->max_abs, m->rms, m->max_rel,
            isfinite(m->psnr) ? m->psnr : INFINITY, m->over, r->tolerance, r->render_seconds, r->oracle_seconds,
            r->rays, verdict_name(r->verdict));
}

static void tsv_order(FILE *fp, const verify_result *r, const verify_sweep *sw, const char *against,
                      const verify_order *o)
{
    fputs("# fit\t", fp);
    tsv_text(fp, r->scene);
    fputc('\t', fp);
    tsv_text(fp, r->family[0] ? r->family : "-");
    fprintf(fp, "\t%s\t%s\t%.6f\t%.6f\t%d\t%.6f\t%d\t", verify_sweep_name(sw->kind), against, o->line.slope,
            o->line.slope_se, o->line.points, o->line.r2, o->meaningful);
    tsv_text(fp, verify_expected_order(r, sw));
    fputc('\t', fp);
    tsv_text(fp, o->note);
    fputc('\n', fp);
}

void verify_tsv_sweep(FILE *fp, const verify_sweep *sw, const verify_result *steps, int count,
                      const verify_order *vs_n, const verify_order *vs_time)
{
    for (int i = 0; i < count; i++)
        if (steps[i].measured)
            tsv_step(fp, sw, &steps[i], i);
    if (count > 0 && steps[0].measured) {
        tsv_order(fp, &steps[0], sw, "n", vs_n);
        tsv_order(fp, &steps[0], sw, "seconds", vs_time);
    }
}

/* ---- Error maps ---- */

/* Inverse of the sRGB encoding (IEC 61966-2-1): display value to linear. */
static double srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

rgb verify_map_colour(double e, int style)
{
    /* Stops in display values, luminance rising: black, purple, red,
     * orange, yellow, white. */
    static const double stops[][4] = {
        {0.0, 0.0, 0.0, 0.0},  {0.2, 0.30, 0.05, 0.45}, {0.45, 0.85, 0.15, 0.15},
        {0.7, 1.0, 0.55, 0.05}, {0.9, 1.0, 0.95, 0.25}, {1.0, 1.0, 1.0, 1.0},
    };
    e = isfinite(e) ? fmin(fmax(e, 0), 1) : 1;
    if (style == VERIFY_MAP_GREY)
        return vec_splat(e);
    int i = 1;
    while (i < 5 && e > stops[i][0])
        i++;
    double w = (e - stops[i - 1][0]) / (stops[i][0] - stops[i - 1][0]);
    return vec_make(stops[i - 1][1] + w * (stops[i][1] - stops[i - 1][1]),
                    stops[i - 1][2] + w * (stops[i][2] - stops[i - 1][2]),
                    stops[i - 1][3] + w * (stops[i][3] - stops[i - 1][3]));
}

static int excluded_at(const unsigned char *mask, size_t p)
{
    return mask && mask[p];
}

/* max over channels |a - b| at pixel p. */
static double pixel_error(const img_buf *a, const img_buf *b, size_t p)
{
    double e = 0;
    for (int c = 0; c < 3; c++)
        e = fmax(e, fabs(a->rgb[3 * p + c] - b->rgb[3 * p + c]));
    return e;
}

static int same_size(const img_buf *a, const img_buf *b)
{
    return a->width == b->width && a->height == b->height && a->rgb && b->rgb;
}

int verify_abs_diff(const img_buf *a, const img_buf *b, const unsigned char *mask, img_buf *out)
{
    if (!same_size(a, b))
        return STATUS_INTERNAL;
    int status = img_create(out, a->width, a->height);
    size_t n = (size_t)a->width * (size_t)a->height;
    for (size_t p = 0; status == STATUS_OK && p < n; p++)
        for (int c = 0; c < 3; c++)
            out->rgb[3 * p + c] = excluded_at(mask, p) ? 0
                                  : !metrics_pixel_finite(a, b, p) ? VERIFY_MAP_NONFINITE
                                                                   : fabs(a->rgb[3 * p + c] - b->rgb[3 * p + c]);
    return status;
}

int verify_diff_map(const img_buf *a, const img_buf *b, const unsigned char *mask, int style, img_buf *out)
{
    if (!same_size(a, b))
        return STATUS_INTERNAL;
    int status = img_create(out, a->width, a->height);
    if (status != STATUS_OK)
        return status;
    size_t n = (size_t)a->width * (size_t)a->height;
    double max_abs = 0;
    for (size_t p = 0; p < n; p++)
        if (!excluded_at(mask, p) && metrics_pixel_finite(a, b, p))
            max_abs = fmax(max_abs, pixel_error(a, b, p));
    for (size_t p = 0; p < n; p++) {
        rgb c = excluded_at(mask, p)                ? vec_make(0, 0.5, 0.5)
                : !metrics_pixel_finite(a, b, p) ? vec_make(0, 1, 0)
                                                  : verify_map_colour(max_abs > 0 ? pixel_error(a, b, p) / max_abs : 0,
                                                                      style);
        out->rgb[3 * p] = srgb_to_linear(c.x);
        out->rgb[3 * p + 1] = srgb_to_linear(c.y);
        out->rgb[3 * p + 2] = srgb_to_linear(c.z);
    }
    return STATUS_OK;
}

/* ---- Masks ---- */

static int has_extension(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    if (n <= e || path[n - e - 1] != '.')
        return 0;
    for (size_t i = 0; i < e; i++)
        if ((path[n - e + i] | 0x20) != ext[i])
            return 0;
    return 1;
}

/* The PGM bytes into fp: header, then one byte per pixel. */
typedef struct pgm_image {
    const unsigned char *mask;
    int width, height;
} pgm_image;

static int pgm_fill(FILE *fp, void *ctx)
{
    const pgm_image *g = ctx;
    if (fprintf(fp, "P5\n%d %d\n255\n", g->width, g->height) < 0)
        return STATUS_IO;
    size_t n = (size_t)g->width * (size_t)g->height;
    for (size_t p = 0; p < n; p++)
        if (fputc(g->mask[p] ? 255 : 0, fp) == EOF)
            return STATUS_IO;
    return STATUS_OK;
}

static int pgm_write(const char *path, const unsigned char *mask, int width, int height, char *err, size_t errlen)
{
    pgm_image g = {mask, width, height};
    char why[1024];
    int status = file_write_atomic(path, pgm_fill, &g, why, sizeof why);
    return status == STATUS_OK ? status : img_error(err, errlen, status, "%s", why);
}

int verify_mask_write(const char *path, const unsigned char *mask, int width, int height, char *err,
                      size_t errlen)
{
    if (has_extension(path, "pgm"))
        return pgm_write(path, mask, width, height, err, errlen);
    img_buf img;
    int status = img_create(&img, width, height);
    if (status != STATUS_OK)
        return img_error(err, errlen, status, "cannot make a %dx%d mask", width, height);
    size_t n = (size_t)width * (size_t)height;
    for (size_t p = 0; p < 3 * n; p++)
        img.rgb[p] = mask[p / 3] ? 1 : 0;
    status = img_write(path, &img, NULL, err, errlen);
    img_free(&img);
    return status;
}

/* One whole number of a PGM header, after white space and # comments. */
static int pgm_number(FILE *fp, long *out)
{
    int c = fgetc(fp);
    for (;;) {
        if (c == '#')
            while (c != '\n' && c != EOF)
                c = fgetc(fp);
        else if (c == ' ' || c == '\t' || c == '\n' || c == '\r')
            c = fgetc(fp);
        else
            break;
    }
    long v = 0;
    int digits = 0;
    for (; c >= '0' && c <= '9' && v < 100000000; c = fgetc(fp), digits++)
        v = 10 * v + (c - '0');
    *out = v;
    return digits > 0 && (c == ' ' || c == '\t' || c == '\n' || c == '\r');
}

static int pgm_read(FILE *fp, int width, int height, unsigned char *mask, char *err, size_t errlen)
{
    long w, h, maxval;
    if (fgetc(fp) != 'P' || fgetc(fp) != '5' || !pgm_number(fp, &w) || !pgm_number(fp, &h) ||
        !pgm_number(fp, &maxval) || maxval < 1 || maxval > 255)
        return img_error(err, errlen, STATUS_DATA, "not a binary 8-bit PGM (P5, maxval up to 255)");
    if (w != width || h != height)
        return img_error(err, errlen, STATUS_DATA, "the mask is %ldx%ld, the images %dx%d", w, h, width, height);
    size_t n = (size_t)width * (size_t)height;
    for (size_t p = 0; p < n; p++) {
        int c = fgetc(fp);
        if (c == EOF)
            return img_error(err, errlen, STATUS_DATA, "the PGM ends after %zu of %zu pixels", p, n);
        /* A byte between would be a mark to one reader and not to another
         * (kit_check.c once took any non-zero byte): none is read. */
        if (c != 0 && c != maxval)
            return img_error(err, errlen, STATUS_DATA, MASK_NOT_BINARY " (pixel (%zu, %zu) is %d; maxval %ld)",
                             p % (size_t)width, p / (size_t)width, c, maxval);
        mask[p] = c == maxval;
    }
    return STATUS_OK;
}

/* A mask image's value: 0 black, 1 white, -1 neither (a band finer than
 * any 16-bit step, for the rounding of decoding). */
static int mask_level(double v)
{
    return v <= 1e-6 && v >= 0 ? 0 : v >= 1 - 1e-6 && v <= 1 + 1e-6 ? 1 : -1;
}

static int mask_from_image(const char *path, int width, int height, unsigned char *mask, char *err,
                           size_t errlen)
{
    img_buf img;
    /* The size is refused on the header, before any pixel is decoded. */
    img_read_opts o = img_read_opts_default();
    o.width = width;
    o.height = height;
    int status = img_read(path, &o, &img, err, errlen);
    if (status != STATUS_OK)
        return status;
    size_t n = (size_t)width * (size_t)height;
    for (size_t p = 0; status == STATUS_OK && p < n; p++) {
        const double *v = &img.rgb[3 * p];
        int level = mask_level(v[0]);
        if (level < 0 || mask_level(v[1]) != level || mask_level(v[2]) != level)
            status = img_error(err, errlen, STATUS_DATA, MASK_NOT_BINARY " (pixel (%zu, %zu) is %g %g %g)",
                               p % (size_t)width, p / (size_t)width, v[0], v[1], v[2]);
        mask[p] = level == 1;
    }
    img_free(&img);
    return status;
}

int verify_mask_read(const char *path, int width, int height, unsigned char **mask, char *err, size_t errlen)
{
    *mask = malloc((size_t)width * (size_t)height);
    if (!*mask)
        return img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    int status;
    if (has_extension(path, "pgm")) {
        char why[1024];
        FILE *fp = file_fopen_read(path, &status, why, sizeof why);
        status = fp ? pgm_read(fp, width, height, *mask, err, errlen) : img_error(err, errlen, status, "%s", why);
        if (fp)
            fclose(fp);
    } else {
        status = mask_from_image(path, width, height, *mask, err, errlen);
    }
    if (status != STATUS_OK) {
        free(*mask);
        *mask = NULL;
    }
    return status;
}
