/*
 * metrics.c - see metrics.h.
 */
#include <math.h>
#include "image/metrics.h"

static double peak_of(const img_buf *b, const unsigned char *excluded)
{
    double peak = 0;
    size_t n = (size_t)b->width * (size_t)b->height;
    for (size_t p = 0; p < n; p++)
        for (int c = 0; c < 3 && !(excluded && excluded[p]); c++)
            peak = fmax(peak, fabs(b->rgb[3 * p + c]));
    return peak;
}

void metrics_compare(const img_buf *a, const img_buf *b, const unsigned char *excluded, double tol,
                     image_metrics *m)
{
    size_t n = (size_t)b->width * (size_t)b->height;
    double sum2 = 0;
    m->peak = peak_of(b, excluded);
    double floor_value = 1e-12 * m->peak;
    m->max_abs = m->max_rel = 0;
    m->over = m->compared = m->excluded = 0;
    m->worst_x = m->worst_y = 0;
    for (size_t p = 0; p < n; p++) {
        if (excluded && excluded[p]) {
            m->excluded++;
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
            over |= !(err <= tol * fmax(fabs(ref), floor_value));
            sum2 += err * err;
        }
        m->over += over;
        m->compared++;
    }
    m->rms = m->compared ? sqrt(sum2 / (3.0 * (double)m->compared)) : 0;
    m->psnr = m->rms > 0 ? 20 * log10((m->peak > 0 ? m->peak : 1) / m->rms) : HUGE_VAL;
}
