/*
 * run.c - one scene through refray and POV-Ray (see dt.h).
 *
 * The comparison follows spec/crosscheck.md: the export scales every light,
 * the ambient light and the background by a power of two S that puts
 * refray's peak sample in (0.4, 0.8] ([XCHK-RUN-SCALE-1]), POV-Ray writes a linear
 * 16-bit PNG, and its values divided by S are refray's to within half a
 * step of 1/65535 of full scale plus POV-Ray's single-precision colours.
 * A scene with a k x k pixel grid is rendered by POV-Ray at k times the
 * size and averaged back ([XCHK-RUN-SIZE-1]).
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "dt.h"
#include "io/image_io.h"
#include "io/scene_file.h"
#include "render/camera.h"
#include "render/render.h"

enum { PATH_LEN = 1024 };

static void fail(dt_result *r, const char *fmt, const char *what)
{
    r->verdict = DT_FAILED;
    snprintf(r->why, sizeof r->why, fmt, what);
}

/* The power of two that takes peak into (0.4, 0.8]; 1 for a black image. */
static double scale_for(double peak)
{
    double s = 1;
    if (!(peak > 0) || !isfinite(peak))
        return 1;
    while (peak * s > 0.8)
        s *= 0.5;
    while (peak * s <= 0.4)
        s *= 2;
    return s;
}

static double peak_of(const img_buf *img)
{
    double peak = 0;
    for (size_t i = 0; i < 3 * (size_t)img->width * img->height; i++)
        peak = fmax(peak, img->rgb[i]);
    return peak;
}

/* The peak of what POV-Ray will write: with a k x k grid, each of its
 * pixels is one of refray's sub-samples, which can be brighter than their
 * average (a 16-bit file clips at 1).  Rendered once at k times the size,
 * one ray per pixel, at the same points up to rounding. */
static double sample_peak(const scene_model *s, const img_buf *ours)
{
    int k = s->image.samples;
    render_opts o;
    img_buf fine;
    if (k == 1)
        return peak_of(ours);
    memset(&o, 0, sizeof o);
    o.width = k * s->image.width;
    o.height = k * s->image.height;
    o.samples = 1;
    o.facet_shadows = 1;
    if (render_image(s, &o, &fine, NULL) != STATUS_OK)
        return peak_of(ours) * k * k;
    double peak = peak_of(&fine);
    img_free(&fine);
    return peak;
}

double dt_scale(const scene_model *s, const img_buf *ours)
{
    return scale_for(sample_peak(s, ours));
}

pid_t dt_spawn(char *const argv[], const char *dir, const char *log)
{
    pid_t pid = fork();
    if (pid != 0)
        return pid;
    if (dir && chdir(dir) != 0)
        _exit(126);
    int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        dup2(fd, 1);
        dup2(fd, 2);
        close(fd);
    }
    execvp(argv[0], argv);
    _exit(127);
}

/* Runs POV-Ray on name.pov inside the work directory (Debian's povray.conf
 * lets it read and write only there and in /tmp), output name.png, log
 * name.log.  Returns 0 when it exited 0 within the timeout. */
static int run_povray(const dt_config *c, const char *name, int width, int height)
{
    char in[PATH_LEN], out[PATH_LEN], log[PATH_LEN], w[32], h[32];
    snprintf(in, sizeof in, "+I%s.pov", name);
    snprintf(out, sizeof out, "+O%s.png", name);
    snprintf(log, sizeof log, "%s.log", name);
    snprintf(w, sizeof w, "+W%d", width);
    snprintf(h, sizeof h, "+H%d", height);
    const char *args[] = {c->povray, in, out, w, h, "-A", "-D", "-V", "+WT1", "+FN16", "File_Gamma=1.0",
                          "Output_Alpha=off", NULL};
    pid_t pid = dt_spawn((char *const *)args, c->work_dir, log);
    if (pid < 0)
        return -1;
    struct timespec nap = {0, 20000000};
    for (long waited = 0;; waited += 20) {
        int status;
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid)
            return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
        if (done < 0 && errno != EINTR)
            return -1;
        if (waited > 1000L * c->timeout) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return -1;
        }
        nanosleep(&nap, NULL);
    }
}

int dt_read_pov(const dt_config *c, const char *name, int k, double scale, img_buf *out, dt_result *r)
{
    char path[PATH_LEN], err[512];
    img_buf raw;
    snprintf(path, sizeof path, "%s/%s.png", c->work_dir, name);
    if (img_read(path, NULL, &raw, err, sizeof err) != 0) {
        fail(r, "cannot read POV-Ray's picture: %.250s", err);
        return -1;
    }
    if (raw.width % k || raw.height % k || img_create(out, raw.width / k, raw.height / k) != 0) {
        img_free(&raw);
        fail(r, "POV-Ray's picture %.250s has the wrong size", path);
        return -1;
    }
    for (int y = 0; y < out->height; y++)
        for (int x = 0; x < out->width; x++)
            for (int ch = 0; ch < 3; ch++) {
                double sum = 0;
                for (int j = 0; j < k; j++)
                    for (int i = 0; i < k; i++)
                        sum += img_pixel(&raw, k * x + i, k * y + j)[ch];
                img_pixel(out, x, y)[ch] = sum / (k * k) / scale;
            }
    img_free(&raw);
    return 0;
}

/* The ray tree's hash for the camera ray through image point (x, y). */
static uint64_t path_at(const tracer *t, double x, double y)
{
    trace_stats st;
    const scene_model *s = t->scene;
    memset(&st, 0, sizeof st);
    st.record_path = 1;
    ray r = camera_ray(&s->camera, camera_half(&s->camera), s->image.width, s->image.height, x, y);
    medium_stack media = t->eye_media;
    if (s->camera.kind == CAMERA_ORTHOGRAPHIC)
        trace_media_at(t, r.origin, &media, &st);
    (void)trace_ray(t, &r, 1, &media, 0, &st);
    return st.path;
}

/* Whether the ray tree of one of pixel (i, j)'s camera rays changes within
 * radius (in POV-Ray pixels, 1/k of refray's) of the ray's point. */
static int is_edge(const tracer *t, int i, int j, double radius)
{
    int k = t->scene->image.samples;
    for (int b = 0; b < k; b++)
        for (int a = 0; a < k; a++) {
            double x = i + (a + 0.5) / k, y = j + (b + 0.5) / k;
            uint64_t centre = path_at(t, x, y);
            for (int n = 0; n < 12; n++) {
                double rho = (n < 8 ? radius : 0.5 * radius) / k;
                double angle = n < 8 ? n * (REAL_PI / 4) : (n - 8) * (REAL_PI / 2) + REAL_PI / 4;
                if (path_at(t, x + rho * cos(angle), y + rho * sin(angle)) != centre)
                    return 1;
            }
        }
    return 0;
}

void dt_compare(const dt_config *c, const scene_model *s, const img_buf *ours, const img_buf *pov, dt_result *r)
{
    tracer t;
    int have_tracer = tracer_init(&t, s, 0, 0);
    double step = 1.0 / 65535 / r->scale;
    for (int y = 0; y < ours->height; y++)
        for (int x = 0; x < ours->width; x++) {
            int worst_c = 0;
            double worst = 0;
            for (int ch = 0; ch < 3; ch++) {
                double d = fabs(img_pixel(ours, x, y)[ch] - img_pixel(pov, x, y)[ch]);
                if (d > worst || ch == 0) {
                    worst = d;
                    worst_c = ch;
                }
            }
            r->max_steps = fmax(r->max_steps, worst / step);
            if (!(worst > c->tol_steps * step))
                continue;
            if (have_tracer && is_edge(&t, x, y, c->edge_radius)) {
                r->edge++;
                continue;
            }
            r->interior++;
            if (worst > r->worst_interior) {
                r->worst_interior = worst;
                r->worst_x = x;
                r->worst_y = y;
                r->worst_c = worst_c;
                r->refray_value = img_pixel(ours, x, y)[worst_c];
                r->pov_value = img_pixel(pov, x, y)[worst_c];
            }
        }
    if (have_tracer)
        tracer_free(&t);
    r->verdict = r->interior > 0 ? DT_INTERIOR : r->edge > 0 ? DT_EDGE_ONLY : DT_AGREE;
}

/* Exports at r->scale, renders with POV-Ray and compares with ours. */
static void against_pov(const dt_config *c, const char *name, const scene_model *s, const img_buf *ours, dt_result *r)
{
    char path[PATH_LEN], err[600];
    pov_opts o;
    pov_notes notes;
    img_buf pov;
    int width, height, k = pov_render_size(s, &width, &height);
    memset(&o, 0, sizeof o);
    o.facet_shadows = 1;
    o.scale = r->scale;
    o.source = name;
    snprintf(path, sizeof path, "%s/%s.pov", c->work_dir, name);
    if (pov_export_file(s, &o, path, &notes, err, sizeof err) != 0) {
        fail(r, "export failed: %.250s", err);
        return;
    }
    if (run_povray(c, name, width, height) != 0) {
        fail(r, "POV-Ray failed or timed out (see %.250s.log)", name);
        return;
    }
    if (dt_read_pov(c, name, k, r->scale, &pov, r) != 0)
        return;
    dt_compare(c, s, ours, &pov, r);
    img_free(&pov);
}

dt_verdict dt_run(const dt_config *c, const char *name, const char *text, dt_result *r)
{
    char path[PATH_LEN];
    int status;
    pov_opts o;
    pov_notes notes;
    img_buf ours;
    render_opts ro;
    memset(r, 0, sizeof *r);
    memset(&o, 0, sizeof o);
    memset(&ro, 0, sizeof ro);
    /* [XCHK-MAP-MESH-3] Smooth meshes' shadow rays from the facet, as
     * POV-Ray's: compared as the seed has them, not listed. */
    o.facet_shadows = ro.facet_shadows = 1;
    snprintf(path, sizeof path, "%s/%s.scene", c->work_dir, name);
    scene_model *s = scene_file_load_text_confined(path, text, strlen(text), NULL, c->diag, 0, c->read_dirs,
                                                   &status);
    if (!s) {
        fail(r, "%.250s does not load", name);
        return r->verdict;
    }
    r->pixels = s->image.width * s->image.height;
    int exportable = pov_export_check(s, &o, &notes);
    r->notes = notes.count;
    if (!exportable || notes.count > 0)
        snprintf(r->why, sizeof r->why, "%s", notes.refused ? notes.reason : notes.text[0]);
    if (!exportable || (notes.count > 0 && !c->approximations)) {
        r->verdict = DT_DISCARDED;
    } else if (render_image(s, &ro, &ours, NULL) != STATUS_OK) {
        fail(r, "refray could not render %.250s", name);
    } else {
        r->scale = dt_scale(s, &ours);
        against_pov(c, name, s, &ours, r);
        img_free(&ours);
    }
    scene_free(s);
    return r->verdict;
}
