/*
 * stability.c - see stability.h.  Nothing here knows which `real` the other
 * program used: a raw dump says so in its header, and every value travels
 * as a hex float, which both strtold and printf("%La") take exactly.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "verify/stability.h"
#include "render/trace.h"

#define RAW_MAGIC "refray-raw"
#define RAW_VERSION 1

const char *stability_real_name(void)
{
    return sizeof(real) == sizeof(double) ? "double" : "long-double";
}

void stability_free(stab_image *img)
{
    free(img->rgb);
    img->rgb = NULL;
    img->width = img->height = 0;
}

static int alloc_image(stab_image *img, int width, int height)
{
    memset(img, 0, sizeof *img);
    if (width < 1 || height < 1 || (size_t)width > ((size_t)-1 / 3 / sizeof(long double)) / (size_t)height)
        return -1;
    img->rgb = malloc(3 * (size_t)width * (size_t)height * sizeof *img->rgb);
    if (!img->rgb)
        return -1;
    img->width = width;
    img->height = height;
    return 0;
}

/* The pixels of render_image, from render_pixel, kept in real. */
static int render_rows(const tracer *t, int k, stab_image *out, trace_stats *st)
{
    for (int j = 0; j < out->height; j++)
        for (int i = 0; i < out->width; i++) {
            rgb c = render_pixel(t, out->width, out->height, k, i, j, st);
            long double *px = &out->rgb[3 * ((size_t)j * (size_t)out->width + (size_t)i)];
            px[0] = c.x;
            px[1] = c.y;
            px[2] = c.z;
            if (cancel_stopped(st->cancel))
                return STATUS_CANCELLED;
            if (st->tree_overflow || st->medium_overflow > 0)
                return STATUS_DATA;
        }
    return STATUS_OK;
}

int stability_render(const scene_model *scene, const render_opts *opts, stab_image *out)
{
    tracer t;
    trace_stats st;
    int width = opts && opts->width > 0 ? opts->width : scene->image.width;
    int height = opts && opts->height > 0 ? opts->height : scene->image.height;
    int k = opts && opts->samples > 0 ? opts->samples : scene->image.samples;
    cancel_poll cancel = cancel_poll_make(opts ? opts->cancel : NULL, opts ? opts->cancel_ctx : NULL);
    memset(&st, 0, sizeof st);
    st.cancel = &cancel;
    if (alloc_image(out, width, height) != 0)
        return STATUS_NO_MEMORY;
    int status = tracer_build(&t, scene, opts ? opts->max_depth : 0, opts ? opts->light_samples : 0, &cancel);
    if (status != STATUS_OK) {
        stability_free(out);
        return status;
    }
    t.max_tree_rays = opts ? opts->max_tree_rays : 0;
    if (opts && opts->no_shortcuts)
        tracer_no_shortcuts(&t);
    status = render_rows(&t, k, out, &st);
    tracer_free(&t);
    out->long_double = sizeof(real) > sizeof(double);
    out->nonfinite = st.nonfinite;
    if (status != STATUS_OK)
        stability_free(out);
    return status;
}

int stability_write_raw(FILE *f, const stab_image *img)
{
    size_t n = 3 * (size_t)img->width * (size_t)img->height;
    if (fprintf(f, "%s %d %d %d %s %ld\n", RAW_MAGIC, RAW_VERSION, img->width, img->height,
                img->long_double ? "long-double" : "double", img->nonfinite) < 0)
        return -1;
    for (size_t i = 0; i < n; i += 3)
        if (fprintf(f, "%La %La %La\n", img->rgb[i], img->rgb[i + 1], img->rgb[i + 2]) < 0)
            return -1;
    return fflush(f) == 0 ? 0 : -1;
}

static int raw_error(char *err, size_t errlen, const char *what)
{
    snprintf(err, errlen, "%s", what);
    return -1;
}

/* One value: a hex float (or any strtold number) up to a blank or newline. */
static int read_value(FILE *f, long double *out)
{
    char buf[64];
    if (fscanf(f, "%63s", buf) != 1)
        return -1;
    char *end;
    errno = 0;
    *out = strtold(buf, &end);
    return *end == '\0' && end != buf ? 0 : -1;
}

int stability_read_raw(FILE *f, stab_image *out, char *err, size_t errlen)
{
    char magic[16], kind[16];
    int version, width, height;
    long nonfinite;
    memset(out, 0, sizeof *out);
    if (fscanf(f, "%15s %d %d %d %15s %ld", magic, &version, &width, &height, kind, &nonfinite) != 6 ||
        strcmp(magic, RAW_MAGIC) != 0)
        return raw_error(err, errlen, "not a refray raw dump");
    if (version != RAW_VERSION)
        return raw_error(err, errlen, "raw dump of an unknown version");
    if (strcmp(kind, "double") != 0 && strcmp(kind, "long-double") != 0)
        return raw_error(err, errlen, "raw dump of an unknown floating type");
    if (alloc_image(out, width, height) != 0)
        return raw_error(err, errlen, "raw dump too large or empty");
    out->long_double = strcmp(kind, "long-double") == 0;
    out->nonfinite = nonfinite;
    for (size_t i = 0; i < 3 * (size_t)width * (size_t)height; i++) {
        if (read_value(f, &out->rgb[i]) != 0) {
            stability_free(out);
            return raw_error(err, errlen, "raw dump truncated or malformed");
        }
    }
    return 0;
}

static long double rel_diff(long double a, long double b)
{
    long double d = fabsl(a - b), m = fmaxl(fabsl(a), fabsl(b));
    return d == 0 ? 0 : d / m;
}

/* The band of a pixel's largest relative difference (stab_report.band). */
static int band_of(long double rel)
{
    static const long double edges[STAB_BANDS - 2] = {1e-15L, 1e-12L, 1e-9L, 1e-6L};
    if (rel == 0)
        return 0;
    int b = 1;
    while (b - 1 < STAB_BANDS - 2 && rel >= edges[b - 1])
        b++;
    return b;
}

static double map_value(long double rel)
{
    if (rel == 0)
        return 0;
    long double v = (17 + log10l(rel)) / 17;
    return v < 0 ? 0 : v > 1 ? 1 : (double)v;
}

static void note_pixel(stab_report *r, const long double *pa, const long double *pb, int i, int j,
                       long double threshold, double *map_px)
{
    long double worst = 0;
    for (int c = 0; c < 3; c++) {
        long double abs_d = fabsl(pa[c] - pb[c]), rel = rel_diff(pa[c], pb[c]);
        if (abs_d > r->max_abs) {
            r->max_abs = abs_d;
            r->abs_x = i;
            r->abs_y = j;
        }
        if (rel > r->max_rel) {
            r->max_rel = rel;
            r->rel_x = i;
            r->rel_y = j;
        }
        worst = rel > worst ? rel : worst;
        if (map_px)
            map_px[c] = map_value(rel);
    }
    r->beyond += worst > threshold;
    r->band[band_of(worst)]++;
}

int stability_compare(const stab_image *a, const stab_image *b, long double threshold, stab_report *r,
                      img_buf *map)
{
    memset(r, 0, sizeof *r);
    r->abs_x = r->abs_y = r->rel_x = r->rel_y = -1;
    if (a->width != b->width || a->height != b->height)
        return -1;
    if (map && img_create(map, a->width, a->height) != 0)
        return -1;
    r->pixels = (long)a->width * a->height;
    for (int j = 0; j < a->height; j++)
        for (int i = 0; i < a->width; i++) {
            size_t at = 3 * ((size_t)j * (size_t)a->width + (size_t)i);
            note_pixel(r, &a->rgb[at], &b->rgb[at], i, j, threshold, map ? img_pixel(map, i, j) : NULL);
        }
    return 0;
}
