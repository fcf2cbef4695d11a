/*
 * conform_report.c - see conform_report.h.  Every text that comes from
 * outside (the renderer's standard error, file names) was cleaned to valid
 * UTF-8 without control characters (base/text.h) before it gets here, and
 * is escaped once more for the format at hand.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/status.h"
#include "verify/conform_report.h"

#ifndef REFRAY_HAVE_JSON
#define REFRAY_HAVE_JSON 0
#endif
#if REFRAY_HAVE_JSON
#include <jansson.h>
#endif

int conform_passed(const conform_report *rep)
{
    int n = 0;
    for (int i = 0; i < rep->count; i++)
        n += rep->results[i].outcome == CONFORM_PASS;
    return n;
}

const char *conform_short_reason(const conform_result *r, char *buf, size_t size)
{
    if (r->outcome == CONFORM_OVER && r->compared && r->metrics.compared > 0)
        snprintf(buf, size, "%ld of %ld pixels over the tolerance", r->metrics.over, r->metrics.compared);
    else if (r->outcome == CONFORM_PASS && r->note[0])
        snprintf(buf, size, "note: %s", r->note);
    else
        snprintf(buf, size, "%s", r->reason);
    return buf;
}

/* The renderer's standard error is shown where it may say why: after the
 * renderer itself failed, not under a picture that was merely wrong. */
static int show_stderr(const conform_result *r)
{
    return r->stderr_tail[0] && r->outcome != CONFORM_PASS && r->outcome != CONFORM_OVER &&
           r->outcome != CONFORM_NO_INPUT && r->outcome != CONFORM_ERROR;
}

static const char *verdict(const conform_result *r)
{
    return r->outcome == CONFORM_PASS ? "pass" : "FAIL";
}

/* ---- Text ---- */

void conform_text_header(FILE *fp)
{
    fprintf(fp, "%-30s %-18s %10s %10s %10s %13s %7s  %s\n", "scene", "family", "max abs", "RMS", "max rel", "over",
            "s", "verdict");
}

/* A metric as "%10.3e", or a dash when nothing was compared. */
static void metric(FILE *fp, int valid, double v)
{
    if (valid)
        fprintf(fp, " %10.3e", v);
    else
        fprintf(fp, " %10s", "-");
}

void conform_text_row(FILE *fp, const conform_result *r)
{
    const image_metrics *m = &r->metrics;
    char over[32] = "-", secs[16] = "-";
    if (r->compared)
        snprintf(over, sizeof over, "%ld/%ld", m->over, m->compared);
    if (r->ran)
        snprintf(secs, sizeof secs, "%.2f", r->proc.seconds);
    fprintf(fp, "%-30s %-18s", r->scene->name, r->scene->family);
    metric(fp, r->compared, m->max_abs);
    metric(fp, r->compared, m->rms);
    metric(fp, r->compared, m->max_rel);
    fprintf(fp, " %13s %7s  %s\n", over, secs, verdict(r));
    if (r->outcome != CONFORM_PASS)
        fprintf(fp, "    %s\n", r->reason);
    if (r->note[0])
        fprintf(fp, "    note: %s\n", r->note);
    if (show_stderr(r)) {
        fputs("    stderr (last lines):\n", fp);
        for (const char *p = r->stderr_tail; *p;) {
            const char *nl = strchr(p, '\n');
            int len = nl ? (int)(nl - p) : (int)strlen(p);
            fprintf(fp, "    | %.*s\n", len, p);
            p += len + (nl != NULL);
        }
    }
    if (r->workdir[0])
        fprintf(fp, "    kept: %s\n", r->workdir);
    fflush(fp);
}

void conform_text_summary(FILE *fp, const conform_report *rep)
{
    int passed = conform_passed(rep);
    int noted = 0;
    for (int i = 0; i < rep->count; i++)
        noted += rep->results[i].note[0] != '\0';
    fprintf(fp, "%d scene%s: %d passed, %d failed", rep->count, rep->count == 1 ? "" : "s", passed,
            rep->count - passed);
    if (noted)
        fprintf(fp, ", %d with a note (below the row)", noted);
    fprintf(fp, " (%.1f s)\n", rep->seconds);
}

/* ---- TAP ---- */

void conform_tap_plan(FILE *fp, int count)
{
    fprintf(fp, "TAP version 13\n1..%d\n", count);
}

/* s as a YAML (and JSON) double-quoted string. */
static void quoted(FILE *fp, const char *s)
{
    fputc('"', fp);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            fprintf(fp, "\\%c", *s);
        else if (*s == '\n')
            fputs("\\n", fp);
        else if (*s == '\t')
            fputs("\\t", fp);
        else
            fputc(*s, fp);
    }
    fputc('"', fp);
}

void conform_tap_row(FILE *fp, int number, const conform_result *r)
{
    char reason[sizeof ((conform_result *)0)->reason];
    /* A TAP description ends at '#': the short reason goes after one. */
    fprintf(fp, "%s %d - %s", r->outcome == CONFORM_PASS ? "ok" : "not ok", number, r->scene->name);
    if (r->outcome != CONFORM_PASS) {
        conform_short_reason(r, reason, sizeof reason);
        for (char *p = reason; *p; p++)
            *p = *p == '\n' ? ' ' : *p;
        fprintf(fp, " # %s", reason);
    }
    fputc('\n', fp);
    if (r->outcome != CONFORM_PASS) {
        fprintf(fp, "  ---\n  outcome: %s\n  family: %s\n  reason: ", conform_outcome_name(r->outcome),
                r->scene->family);
        quoted(fp, r->reason);
        if (r->compared)
            fprintf(fp, "\n  max_abs: %.6g\n  rms: %.6g\n  max_rel: %.6g\n  over: %ld\n  compared: %ld",
                    r->metrics.max_abs, r->metrics.rms, r->metrics.max_rel, r->metrics.over, r->metrics.compared);
        if (show_stderr(r)) {
            fputs("\n  stderr: ", fp);
            quoted(fp, r->stderr_tail);
        }
        fputs("\n  ...\n", fp);
    }
    /* After the YAML block, which must follow its test line. */
    if (r->note[0])
        fprintf(fp, "# note: %s\n", r->note);
    fflush(fp);
}

/* ---- JUnit XML ---- */

/* s with & < > " ' as entities (s is already free of control bytes). */
static void xml(FILE *fp, const char *s)
{
    for (; *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", fp); break;
        case '<': fputs("&lt;", fp); break;
        case '>': fputs("&gt;", fp); break;
        case '"': fputs("&quot;", fp); break;
        case '\'': fputs("&apos;", fp); break;
        default: fputc(*s, fp);
        }
    }
}

static void junit_case(FILE *fp, const conform_result *r)
{
    char reason[sizeof ((conform_result *)0)->reason];
    fputs("    <testcase classname=\"conform.", fp);
    xml(fp, r->scene->family);
    fputs("\" name=\"", fp);
    xml(fp, r->scene->name);
    fprintf(fp, "\" time=\"%.3f\"", r->ran ? r->proc.seconds : 0.0);
    if (r->outcome == CONFORM_PASS) {
        fputs("/>\n", fp);
        return;
    }
    /* JUnit's "error" is the harness's own trouble, a "failure" the tested thing's. */
    const char *tag = r->outcome == CONFORM_ERROR ? "error" : "failure";
    fprintf(fp, ">\n      <%s type=\"", tag);
    xml(fp, conform_outcome_name(r->outcome));
    fputs("\" message=\"", fp);
    xml(fp, conform_short_reason(r, reason, sizeof reason));
    fputs("\">", fp);
    xml(fp, r->reason);
    if (r->compared)
        fprintf(fp, "\nmax abs %.6g, RMS %.6g, max rel %.6g", r->metrics.max_abs, r->metrics.rms,
                r->metrics.max_rel);
    fprintf(fp, "</%s>\n", tag);
    if (show_stderr(r)) {
        fputs("      <system-err>", fp);
        xml(fp, r->stderr_tail);
        fputs("</system-err>\n", fp);
    }
    fputs("    </testcase>\n", fp);
}

int conform_junit_write(FILE *fp, const conform_report *rep)
{
    int errors = 0;
    for (int i = 0; i < rep->count; i++)
        errors += rep->results[i].outcome == CONFORM_ERROR;
    int failed = rep->count - conform_passed(rep) - errors;
    fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", fp);
    fprintf(fp, "<testsuites name=\"refray conform\" tests=\"%d\" failures=\"%d\" errors=\"%d\" time=\"%.3f\">\n",
            rep->count, failed, errors, rep->seconds);
    fprintf(fp, "  <testsuite name=\"refray conform\" tests=\"%d\" failures=\"%d\" errors=\"%d\" skipped=\"0\" "
            "time=\"%.3f\">\n", rep->count, failed, errors, rep->seconds);
    fputs("    <properties>\n      <property name=\"kit\" value=\"", fp);
    xml(fp, rep->kit_dir);
    fputs("\"/>\n      <property name=\"command\" value=\"", fp);
    xml(fp, rep->command);
    fputs("\"/>\n    </properties>\n", fp);
    for (int i = 0; i < rep->count; i++)
        junit_case(fp, &rep->results[i]);
    fputs("  </testsuite>\n</testsuites>\n", fp);
    return ferror(fp) ? STATUS_IO : STATUS_OK;
}

/* ---- Markdown ---- */

/* A table cell: '|' escaped, line breaks as spaces. */
static void cell(FILE *fp, const char *s)
{
    for (; *s; s++) {
        if (*s == '|')
            fputs("\\|", fp);
        else
            fputc(*s == '\n' ? ' ' : *s, fp);
    }
}

static void md_num(FILE *fp, int valid, double v)
{
    if (!valid)
        fputs(" - |", fp);
    else if (v == 0)
        fputs(" 0 |", fp);
    else
        fprintf(fp, " %.2e |", v);
}

int conform_markdown_write(FILE *fp, const conform_report *rep)
{
    char reason[sizeof ((conform_result *)0)->reason];
    fputs("| scene | family | exact peak | max abs | RMS | max rel | over / compared | s | verdict | reason |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n", fp);
    for (int i = 0; i < rep->count; i++) {
        const conform_result *r = &rep->results[i];
        fputs("| ", fp);
        cell(fp, r->scene->name);
        fputs(" | ", fp);
        cell(fp, r->scene->family);
        fprintf(fp, " | %.3g |", r->scene->peak);
        md_num(fp, r->compared, r->metrics.max_abs);
        md_num(fp, r->compared, r->metrics.rms);
        md_num(fp, r->compared, r->metrics.max_rel);
        if (r->compared)
            fprintf(fp, " %ld / %ld |", r->metrics.over, r->metrics.compared);
        else
            fputs(" - |", fp);
        if (r->ran)
            fprintf(fp, " %.2f |", r->proc.seconds);
        else
            fputs(" - |", fp);
        fprintf(fp, " %s | ", r->outcome == CONFORM_PASS ? "pass" : "fail");
        cell(fp, conform_short_reason(r, reason, sizeof reason));
        fputs(" |\n", fp);
    }
    return ferror(fp) ? STATUS_IO : STATUS_OK;
}

/* ---- JSON ---- */

#if REFRAY_HAVE_JSON

typedef struct jw {
    int failed;
} jw;

static void put(jw *w, json_t *o, const char *key, json_t *v)
{
    if (!v || json_object_set_new(o, key, v) != 0)
        w->failed = 1;
}

/* Strings here are clean UTF-8 already; NULL means JSON null. */
static json_t *str(const char *s)
{
    return s ? json_string(s) : json_null();
}

static json_t *num(double v)
{
    return isfinite(v) ? json_real(v) : json_null();
}

static void put_metrics(jw *w, json_t *o, const conform_result *r)
{
    const image_metrics *m = &r->metrics;
    int c = r->compared;
    json_t *worst = c ? json_pack("[ii]", m->worst_x, m->worst_y) : json_null();
    put(w, o, "compared", c ? json_integer(m->compared) : json_null());
    put(w, o, "excluded", c ? json_integer(m->excluded) : json_null());
    put(w, o, "max_abs", c ? num(m->max_abs) : json_null());
    put(w, o, "rms", c ? num(m->rms) : json_null());
    put(w, o, "max_rel", c ? num(m->max_rel) : json_null());
    put(w, o, "over", c ? json_integer(m->over) : json_null());
    put(w, o, "worst", worst);
}

static json_t *result_json(jw *w, const conform_result *r)
{
    json_t *o = json_object(), *tol = json_object();
    char sig[32];
    if (!o || !tol) {
        json_decref(o);
        json_decref(tol);
        return NULL;
    }
    put(w, o, "scene", str(r->scene->name));
    put(w, o, "family", str(r->scene->family));
    put(w, o, "verdict", str(r->outcome == CONFORM_PASS ? "pass" : "fail"));
    put(w, o, "outcome", str(conform_outcome_name(r->outcome)));
    put(w, o, "reason", str(r->outcome == CONFORM_PASS ? NULL : r->reason));
    put(w, o, "note", str(r->note[0] ? r->note : NULL));
    put(w, o, "exit_status", r->ran && r->proc.exited ? json_integer(r->proc.exit_code) : json_null());
    put(w, o, "signal", str(r->ran && r->proc.signaled ? proc_signal_name(r->proc.term_signal, sig, sizeof sig)
                                                       : NULL));
    put(w, o, "timed_out", json_boolean(r->ran && r->proc.timed_out));
    put(w, o, "seconds", r->ran ? num(r->proc.seconds) : json_null());
    put(w, o, "downsample", json_integer(r->downsample));
    put(w, o, "scale", num(r->scale));
    put(w, tol, "relative", num(r->relative));
    put(w, tol, "absolute", num(r->absolute));
    put(w, o, "tolerance", tol);
    put(w, o, "peak", num(r->scene->peak));
    put_metrics(w, o, r);
    put(w, o, "stderr", str(r->stderr_tail[0] ? r->stderr_tail : NULL));
    put(w, o, "workdir", str(r->workdir[0] ? r->workdir : NULL));
    return o;
}

int conform_json_write(FILE *fp, const conform_report *rep)
{
    jw w = {0};
    json_t *o = json_object(), *results = json_array();
    int passed = conform_passed(rep);
    if (o && results) {
        put(&w, o, "kit", str(rep->kit_dir));
        put(&w, o, "command", str(rep->command));
        put(&w, o, "scenes", json_integer(rep->count));
        put(&w, o, "passed", json_integer(passed));
        put(&w, o, "failed", json_integer(rep->count - passed));
        put(&w, o, "seconds", num(rep->seconds));
        for (int i = 0; i < rep->count; i++)
            if (json_array_append_new(results, result_json(&w, &rep->results[i])) != 0)
                w.failed = 1;
        put(&w, o, "results", results);
        results = NULL;
    }
    int status = !o || w.failed || json_dumpf(o, fp, JSON_INDENT(2) | JSON_REAL_PRECISION(17)) != 0 ||
                 fputc('\n', fp) == EOF;
    json_decref(o);
    json_decref(results);
    return status ? STATUS_IO : STATUS_OK;
}

#else

int conform_json_write(FILE *fp, const conform_report *rep)
{
    (void)fp;
    (void)rep;
    return STATUS_USAGE;
}

#endif
