/*
 * metrics.c - see metrics.h.
 */
#include <math.h>
#include "image/metrics.h"

int metrics_pixel_finite(const img_buf *a, const img_buf *b, size_t p)
{
    for (int c = 0; c < 3; c++)
        if (!isfinite(a->rgb[3 * p + c]) || !isfinite(b->rgb[3 * p + c]))
            return 0;
    return 1;
}

/* The largest |B| over the finite pixels compared. */
static double peak_of(const img_buf *a, const img_buf *b, const unsigned char *excluded)
{
    double peak = 0;
    size_t n = (size_t)b->width * (size_t)b->height;
    for (size_t p = 0; p < n; p++)
        for (int c = 0; c < 3 && !(excluded && excluded[p]) && metrics_pixel_finite(a, b, p); c++)
            peak = fmax(peak, fabs(b->rgb[3 * p + c]));
    return peak;
}

static void note_nonfinite(image_metrics *m, size_t p, int width)
{
    if (m->nonfinite++ == 0) {
        m->nonfinite_x = (int)(p % (size_t)width);
        m->nonfinite_y = (int)(p / (size_t)width);
    }
}

/* A channel is over when err > rel * max(|ref|, floor_frac * peak) + abs:
 * verify's rule with abs 0, the kit's with floor_frac 0. */
typedef struct over_rule {
    double rel, floor_frac, abs;
} over_rule;

static void compare(const img_buf *a, const img_buf *b, const unsigned char *excluded, over_rule rule,
                    image_metrics *m)
{
    size_t n = (size_t)b->width * (size_t)b->height;
    double sum2 = 0;
    m->peak = peak_of(a, b, excluded);
    double floor_value = 1e-12 * m->peak, over_floor = rule.floor_frac * m->peak;
    m->max_abs = m->max_rel = 0;
    m->over = m->compared = m->excluded = m->nonfinite = 0;
    m->worst_x = m->worst_y = 0;
    m->nonfinite_x = m->nonfinite_y = -1;
    for (size_t p = 0; p < n; p++) {
        if (excluded && excluded[p]) {
            m->excluded++;
            continue;
        }
        m->compared++;
        if (!metrics_pixel_finite(a, b, p)) {
            note_nonfinite(m, p, b->width);
            m->over++;
            continue;
        }
        int over = 0;
        for (int c = 0; c < 3; c++) {
            double ref = b->rgb[3 * p + c], err = fabs(a->rgb[3 * p + c] - ref);
            if (!(err <= m->max_abs)) {
                m->max_abs = err;
                m->worst_x = (int)(p % (size_t)b->width);
                m->worst_y = (int)(p / (size_t)b->width);
            }
            if (fabs(ref) > floor_value)
                m->max_rel = fmax(m->max_rel, err / fabs(ref));
            over |= !(err <= rule.rel * fmax(fabs(ref), over_floor) + rule.abs);
            sum2 += err * err;
        }
        m->over += over;
    }
    long finite = m->compared - m->nonfinite;
    m->rms = finite ? sqrt(sum2 / (3.0 * (double)finite)) : 0;
    m->psnr = m->rms > 0 ? 20 * log10((m->peak > 0 ? m->peak : 1) / m->rms) : HUGE_VAL;
}

void metrics_compare(const img_buf *a, const img_buf *b, const unsigned char *excluded, double tol,
                     image_metrics *m)
{
    over_rule rule = {tol, 1e-12, 0};
    compare(a, b, excluded, rule, m);
}

void metrics_compare_abs(const img_buf *a, const img_buf *b, const unsigned char *excluded, double rel,
                         double abs_tol, image_metrics *m)
{
    over_rule rule = {rel, 0, abs_tol};
    compare(a, b, excluded, rule, m);
}
