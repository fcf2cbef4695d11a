/*
 * conform.c - see conform.h.  A scene's working directory holds the
 * renderer's standard output and error (stdout.txt, stderr.txt) and the
 * directory it runs in (run/), where {out} points; it is removed after
 * the scene unless kept.
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "io/fileio.h"
#include "io/filewrite.h"
#include "base/status.h"
#include "base/text.h"
#include "image/adjust.h"
#include "io/image_io.h"
#include "verify/conform.h"
#include "verify/verify.h"

/* conform_expand returns CONFORM_NO_INPUT or a status: they must differ. */
typedef char no_input_is_no_status[(int)CONFORM_NO_INPUT >= (int)STATUS_COUNT ? 1 : -1];

const char *const conform_placeholders[] = {
    "scene", "json", "pov", "out", "width", "height", "samples", "name", "scale", NULL,
};

const char *conform_outcome_name(conform_outcome o)
{
    static const char *const names[] = {
        "pass", "over", "crashed", "exit", "timeout", "no_output", "unreadable",
        "size", "nonfinite", "no_input", "error", "interrupted",
    };
    return o >= CONFORM_PASS && o <= CONFORM_INTERRUPTED ? names[o] : "error";
}

int conform_downsample_of(const conform_adjust *a, const manifest_scene *s)
{
    return a->downsample == CONFORM_FROM_MANIFEST ? s->samples : a->downsample;
}

double conform_scale_of(const conform_adjust *a, const manifest_scene *s)
{
    return a->scale == CONFORM_FROM_MANIFEST ? 1.0 / s->png16_scale : a->scale;
}

/* ---- Placeholders ---- */

char *conform_shell_quote(const char *s)
{
    size_t quotes = 0;
    for (const char *p = s; *p; p++)
        quotes += *p == '\'';
    char *out = malloc(strlen(s) + 3 * quotes + 3);
    if (!out)
        return NULL;
    char *o = out;
    *o++ = '\'';
    for (const char *p = s; *p; p++) {
        if (*p == '\'') {
            memcpy(o, "'\\''", 4); /* close, an escaped quote, reopen */
            o += 4;
        } else {
            *o++ = *p;
        }
    }
    *o++ = '\'';
    *o = '\0';
    return out;
}

/* The var whose name is text[0..len), or NULL. */
static const conform_var *find_var(const conform_var *vars, int count, const char *text, size_t len)
{
    for (int i = 0; i < count; i++)
        if (strlen(vars[i].name) == len && strncmp(vars[i].name, text, len) == 0)
            return &vars[i];
    return NULL;
}

/* Appends n bytes to the growing buffer *buf (used, cap); 0 or -1. */
static int append(char **buf, size_t *used, size_t *cap, const char *s, size_t n)
{
    if (*used + n + 1 > *cap) {
        size_t want = 2 * (*used + n + 1);
        char *grown = realloc(*buf, want);
        if (!grown)
            return -1;
        *buf = grown;
        *cap = want;
    }
    memcpy(*buf + *used, s, n);
    *used += n;
    (*buf)[*used] = '\0';
    return 0;
}

int conform_expand(const char *tmpl, const conform_var *vars, int count, char **out, char *why,
                   size_t why_size)
{
    char *buf = NULL;
    size_t used = 0, cap = 0;
    int failed = append(&buf, &used, &cap, "", 0);
    for (const char *p = tmpl; *p && !failed;) {
        const char *close = *p == '{' ? strchr(p, '}') : NULL;
        const conform_var *v = close ? find_var(vars, count, p + 1, (size_t)(close - p - 1)) : NULL;
        if (!v) {
            failed = append(&buf, &used, &cap, p, 1);
            p++;
            continue;
        }
        if (!v->value) {
            snprintf(why, why_size, "the command needs {%s}, which this kit does not have for the scene: %s",
                     v->name, v->missing ? v->missing : "not written");
            free(buf);
            return CONFORM_NO_INPUT;
        }
        char *q = conform_shell_quote(v->value);
        failed = !q || append(&buf, &used, &cap, q, strlen(q));
        free(q);
        p = close + 1;
    }
    if (failed) {
        free(buf);
        snprintf(why, why_size, "out of memory");
        return STATUS_NO_MEMORY;
    }
    *out = buf;
    return 0;
}

int conform_template_ok(const char *tmpl, char *why, size_t why_size)
{
    if (strstr(tmpl, "{out}"))
        return 1;
    snprintf(why, why_size, "the command must write its image to {out} (placeholders: {scene} {json} {pov} "
             "{out} {width} {height} {samples} {name} {scale})");
    return 0;
}

/* ---- Judging a picture ---- */

static void set(conform_result *r, conform_outcome o, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static void set(conform_result *r, conform_outcome o, const char *fmt, ...)
{
    va_list ap;
    r->outcome = o;
    va_start(ap, fmt);
    vsnprintf(r->reason, sizeof r->reason, fmt, ap);
    va_end(ap);
}

/* The PNG bit depth of the file at path (byte 24 of the IHDR), 0 if not a PNG. */
static int png_bit_depth(const char *path)
{
    unsigned char head[25];
    char why[512];
    int status;
    FILE *f = file_fopen_read(path, &status, why, sizeof why);
    size_t n = f ? fread(head, 1, sizeof head, f) : 0;
    if (f)
        fclose(f);
    return n == sizeof head && memcmp(head, "\x89PNG", 4) == 0 ? head[24] : 0;
}

/* Up to 6 names of what the renderer left beside {out}, for the reason
 * when {out} is not there (an extension added, another name chosen). */
static void left_beside(const char *out_path, char *buf, size_t size)
{
    char *dir = file_dirname(NULL, out_path);
    DIR *d = dir ? opendir(dir) : NULL;
    struct dirent *e;
    size_t used = 0;
    int shown = 0;
    buf[0] = '\0';
    while (d && (e = readdir(d)) != NULL && used + 1 < size) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        int n = snprintf(buf + used, size - used, "%s%s", shown ? ", " : "", shown < 6 ? e->d_name : "...");
        used += n > 0 ? (size_t)n : 0;
        if (++shown > 6)
            break;
    }
    if (d)
        closedir(d);
    free(dir);
}

/* Whether every finite value of img is a binary16 value: 0, a subnormal
 * half (a multiple of 2^-24 below 2^-14), or a normal one of at most 11
 * significant bits up to 65504.  A failing picture that is so was most
 * likely written as half floats, whose relative step (up to 2^-11) is
 * coarser than a kit's tolerance: the verdict says so, as it does for an
 * 8-bit PNG (attack 14, finding 6). */
static int on_half_grid(const img_buf *img)
{
    size_t n = 3 * (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++) {
        double v = fabs(img->rgb[i]);
        if (!isfinite(v) || v == 0)
            continue;
        if (v > 65504)
            return 0;
        double units = v < 0x1p-14 ? ldexp(v, 24) : ldexp(v, 10 - ilogb(v));
        if (units != floor(units))
            return 0;
    }
    return 1;
}

/* Reads the picture and brings it to the exact image's size and units;
 * *half: the file's values were all half floats (before averaging and
 * scaling, which move them off the grid). */
static int read_picture(const char *out_path, const manifest_scene *s, img_buf *img, int *half, conform_result *r)
{
    char err[600];
    struct stat sb;
    if (stat(out_path, &sb) != 0) {
        char beside[200];
        left_beside(out_path, beside, sizeof beside);
        set(r, CONFORM_NO_OUTPUT, "the renderer exited 0 but wrote nothing at {out}%s%s%s", beside[0] ? " (its "
            "directory holds: " : "", beside, beside[0] ? ")" : "");
        return -1;
    }
    /* A FIFO would block the read for ever, a device never end. */
    if (!S_ISREG(sb.st_mode)) {
        set(r, CONFORM_UNREADABLE, "{out} is not a regular file");
        return -1;
    }
    /* The size is judged on the header, before anything is decoded: a
     * renderer's output is input like any other ([REL-IMAGE-1]). */
    img_buf raw;
    int k = r->downsample, width, height;
    img_read_opts o = img_read_opts_default();
    int status = img_read_size(out_path, &o, &width, &height, err, sizeof err);
    if (status == STATUS_OK && (width != k * s->width || height != k * s->height)) {
        set(r, CONFORM_SIZE, "its image is %dx%d; expected %dx%d (the exact image's %dx%d times --downsample %d)",
            width, height, k * s->width, k * s->height, s->width, s->height, k);
        return -1;
    }
    o.width = width;
    o.height = height;
    if (status == STATUS_OK)
        status = img_read(out_path, &o, &raw, err, sizeof err);
    if (status != STATUS_OK) {
        set(r, CONFORM_UNREADABLE, "its output is not a readable image: %s", err);
        return -1;
    }
    *half = on_half_grid(&raw);
    status = k == 1 ? STATUS_OK : img_downsample(&raw, k, img);
    if (k == 1)
        *img = raw;
    else
        img_free(&raw);
    if (status != STATUS_OK) {
        set(r, CONFORM_ERROR, "out of memory averaging the image");
        return -1;
    }
    img_scale(img, r->scale);
    return 0;
}

/* "3 channel values of its image are", "1 channel value ... is". */
static const char *values_are(long n)
{
    return n == 1 ? "channel value of its image is" : "channel values of its image are";
}

/* The reason of a picture over its tolerance, with the worst pixel. */
static void over_reason(const img_buf *img, const img_buf *exact, const char *out_path, int half, conform_result *r)
{
    const image_metrics *m = &r->metrics;
    if (m->compared == 0) {
        set(r, CONFORM_OVER, "every pixel is masked: nothing was compared");
        return;
    }
    const double *a = img_pixel(img, m->worst_x, m->worst_y), *b = img_pixel(exact, m->worst_x, m->worst_y);
    int depth = png_bit_depth(out_path);
    const char *coarse = depth && depth < 16 ? "; the output is a PNG of fewer than 16 bits, too coarse for the tolerance"
                         : half && r->relative < 0x1p-11
                             ? "; every value of the output is a half float (11 significant bits, a relative step up "
                               "to 4.9e-4), too coarse for the tolerance: write 32-bit floats (refray: --exr-float)"
                             : "";
    set(r, CONFORM_OVER,
        "%ld of %ld pixels over |out - exact| <= %.3g |exact| + %.3g; largest error at (%d, %d): "
        "out (%.6g, %.6g, %.6g), exact (%.6g, %.6g, %.6g)%s",
        m->over, m->compared, r->relative, r->absolute, m->worst_x, m->worst_y, a[0], a[1], a[2], b[0], b[1], b[2],
        coarse);
}

/* [KIT-RULE-1] judges only the pixels the mask leaves: a NaN or an
 * infinity there fails the picture, one in a pixel the mask excludes is
 * noted and not judged (a renderer may well write NaN on the silhouettes
 * and terminators a kit masks). */
static void judge(const img_buf *img, const img_buf *exact, const unsigned char *mask, const manifest_scene *s,
                  const char *out_path, int half, conform_result *r)
{
    long bad, masked;
    conform_count_nonfinite(img, mask, &bad, &masked);
    if (masked > 0)
        snprintf(r->note, sizeof r->note, "%ld %s NaN or infinite in pixels the mask excludes: not judged", masked,
                 values_are(masked));
    if (bad > 0) {
        set(r, CONFORM_NONFINITE, "%ld %s NaN or infinite", bad, values_are(bad));
        return;
    }
    r->compared = 1;
    int quantized = conform_picture_quantized(out_path);
    r->absolute = conform_absolute(s, quantized);
    if (conform_rule(img, exact, mask, s, quantized, &r->metrics))
        set(r, CONFORM_PASS, "%s", "");
    else
        over_reason(img, exact, out_path, half, r);
}

void conform_judge(const char *kit_dir, const manifest_scene *s, const char *out_path, const conform_adjust *a,
                   conform_result *r)
{
    img_buf img, exact;
    unsigned char *mask;
    char why[600];
    r->relative = s->relative;
    r->absolute = conform_absolute(s, conform_picture_quantized(out_path));
    r->downsample = conform_downsample_of(a, s);
    r->scale = conform_scale_of(a, s);
    int half;
    if (read_picture(out_path, s, &img, &half, r) != 0)
        return;
    int status = conform_kit_read(kit_dir, s, &exact, &mask, why, sizeof why);
    if (status == STATUS_OK) {
        judge(&img, &exact, mask, s, out_path, half, r);
        img_free(&exact);
        free(mask);
    } else {
        set(r, CONFORM_ERROR, "the kit is damaged: %s", why);
    }
    img_free(&img);
}

/* ---- Running a scene ---- */

/* "exited with status 3", "killed by SIGSEGV", with the shell's 128 + n. */
static void outcome_of_process(const conform_run *run, conform_result *r)
{
    char sig[32];
    const proc_result *p = &r->proc;
    if (p->stopped)
        set(r, CONFORM_INTERRUPTED, "interrupted: the renderer was stopped");
    else if (p->timed_out)
        set(r, CONFORM_TIMEOUT, "no result within --timeout %g s: its process group was killed", run->timeout);
    else if (p->signaled)
        set(r, CONFORM_CRASHED, "the renderer was killed by %s", proc_signal_name(p->term_signal, sig, sizeof sig));
    else if (p->exit_code > 128 && p->exit_code < 128 + 65)
        set(r, CONFORM_CRASHED, "the renderer was killed by %s (its shell's status %d)",
            proc_signal_name(p->exit_code - 128, sig, sizeof sig), p->exit_code);
    else if (p->exit_code != 0)
        set(r, CONFORM_EXIT, "the renderer exited with status %d%s", p->exit_code,
            p->exit_code == 127 ? " (command not found: the command runs in a fresh directory, so name programs "
                                  "and scripts by absolute path)" : "");
}

/* The last lines of the renderer's standard error, cleaned. */
static void read_tail(const char *path, conform_result *r)
{
    char buf[4 * CONFORM_TAIL_BYTES], why[512];
    int status;
    FILE *f = file_fopen_read(path, &status, why, sizeof why);
    r->stderr_tail[0] = '\0';
    if (!f)
        return;
    size_t n = 0;
    if (fseek(f, 0, SEEK_END) == 0) {
        long size = ftell(f);
        long from = size > (long)sizeof buf ? size - (long)sizeof buf : 0;
        if (fseek(f, from, SEEK_SET) == 0)
            n = fread(buf, 1, sizeof buf, f);
    }
    fclose(f);
    size_t start = text_tail(buf, n, CONFORM_TAIL_LINES, CONFORM_TAIL_BYTES);
    text_clean(buf + start, n - start, r->stderr_tail, sizeof r->stderr_tail);
}

/* Fills vars for scene s; paths are malloc'd into owned[]. */
static int fill_vars(const conform_run *run, const manifest_scene *s, const char *out, conform_var *vars,
                     char owned[][64], char **paths)
{
    static const manifest_file inputs[3] = {MANIFEST_FILE_SCENE, MANIFEST_FILE_JSON, MANIFEST_FILE_POV};
    int k = conform_downsample_of(&run->adjust, s);
    for (int i = 0; i < 3; i++) {
        const char *rel = s->files[inputs[i]];
        paths[i] = rel[0] ? file_join(NULL, run->kit_dir, rel) : NULL;
        if (rel[0] && !paths[i])
            return -1;
        vars[i].name = conform_placeholders[i];
        vars[i].value = paths[i];
        vars[i].missing = s->missing[inputs[i]];
    }
    snprintf(owned[0], 64, "%d", k * s->width);
    snprintf(owned[1], 64, "%d", k * s->height);
    snprintf(owned[2], 64, "%d", s->samples);
    snprintf(owned[3], 64, "%.17g", s->png16_scale);
    const char *values[6] = {out, owned[0], owned[1], owned[2], s->name, owned[3]};
    for (int i = 3; i < 9; i++) {
        vars[i].name = conform_placeholders[i];
        vars[i].value = values[i - 3];
        vars[i].missing = NULL;
    }
    return 0;
}

/* Makes the scene's working directory and its run/ inside. */
static char *make_workdir(const conform_run *run, const manifest_scene *s, conform_result *r)
{
    size_t n = strlen(run->tmp_root) + strlen(s->name) + 40;
    char *dir = malloc(n), why[512];
    if (dir)
        snprintf(dir, n, "%s/refray-conform-%s-XXXXXX", run->tmp_root, s->name);
    if (!dir || !mkdtemp(dir)) {
        set(r, CONFORM_ERROR, "cannot make a working directory in %s: %s", run->tmp_root,
            dir ? strerror(errno) : "out of memory");
        free(dir);
        return NULL;
    }
    char *inner = file_join(NULL, dir, "run");
    if (!inner || file_make_dirs(inner, why, sizeof why) != 0) {
        set(r, CONFORM_ERROR, "cannot make a working directory: %s", inner ? why : "out of memory");
        file_remove_tree(dir, why, sizeof why);
        free(dir);
        dir = NULL;
    }
    free(inner);
    return dir;
}

/* Expands and runs the command in dir; the picture is judged after. */
static void run_in(const conform_run *run, const manifest_scene *s, const char *dir, conform_result *r)
{
    char name[MANIFEST_NAME_LEN + 8], why[1024], owned[4][64];
    char *paths[3] = {NULL, NULL, NULL}, *cmd = NULL;
    conform_var vars[9];
    snprintf(name, sizeof name, "run/%s.%s", s->name, run->format);
    char *out = file_join(NULL, dir, name), *cwd = file_join(NULL, dir, "run");
    char *err_path = file_join(NULL, dir, "stderr.txt"), *out_log = file_join(NULL, dir, "stdout.txt");
    int status = out && cwd && err_path && out_log && fill_vars(run, s, out, vars, owned, paths) == 0
                     ? conform_expand(run->command, vars, 9, &cmd, why, sizeof why)
                     : STATUS_NO_MEMORY;
    proc_opts po = {cwd, out_log, err_path, run->timeout, run->stop};
    if (status == CONFORM_NO_INPUT)
        set(r, CONFORM_NO_INPUT, "%s", why);
    else if (status != 0)
        set(r, CONFORM_ERROR, "out of memory");
    else if (proc_run_shell(cmd, &po, &r->proc, why, sizeof why) != 0)
        set(r, CONFORM_ERROR, "%s", why);
    else {
        r->ran = 1;
        read_tail(err_path, r);
        outcome_of_process(run, r);
        if (r->outcome == CONFORM_PASS)
            conform_judge(run->kit_dir, s, out, &run->adjust, r);
    }
    for (int i = 0; i < 3; i++)
        free(paths[i]);
    free(cmd);
    free(out);
    free(cwd);
    free(err_path);
    free(out_log);
}

void conform_run_scene(const conform_run *run, const manifest_scene *s, conform_result *r)
{
    memset(r, 0, sizeof *r);
    r->scene = s;
    r->relative = s->relative;
    r->absolute = conform_absolute(s, strcmp(run->format, "png") == 0);
    r->downsample = conform_downsample_of(&run->adjust, s);
    r->scale = conform_scale_of(&run->adjust, s);
    char *dir = make_workdir(run, s, r);
    if (!dir)
        return;
    run_in(run, s, dir, r);
    char why[512];
    if (run->keep)
        snprintf(r->workdir, sizeof r->workdir, "%s", dir);
    else
        file_remove_tree(dir, why, sizeof why);
    free(dir);
}
