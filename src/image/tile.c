/*
 * tile.c - see tile.h.
 */
#include <stdio.h>
#include <string.h>
#include "image/tile.h"

void tile_band(int y0, int y1, int n, int i, int *band_y0, int *band_y1)
{
    long long rows = (long long)y1 - y0;
    *band_y0 = y0 + (int)(rows * i / n);
    *band_y1 = y0 + (int)(rows * (i + 1) / n);
}

int tile_info_valid(const tile_info *t, long max_pixels, char *why, size_t why_size)
{
    const tile_rect *r = &t->region;
    if (t->width < 1 || t->height < 1 || (double)t->width * t->height > (double)max_pixels) {
        snprintf(why, why_size, "the image size %dx%d is not one refray renders", t->width, t->height);
        return 0;
    }
    if (r->x0 < 0 || r->y0 < 0 || r->x1 > t->width || r->y1 > t->height || r->x0 >= r->x1 || r->y0 >= r->y1) {
        snprintf(why, why_size, "the region x %d..%d, y %d..%d is not inside the %dx%d image", r->x0, r->x1 - 1,
                 r->y0, r->y1 - 1, t->width, t->height);
        return 0;
    }
    return 1;
}

int tile_info_equal(const tile_info *a, const tile_info *b)
{
    const tile_rect *p = &a->region, *q = &b->region;
    return a->width == b->width && a->height == b->height && a->key == b->key && p->x0 == q->x0 &&
           p->y0 == q->y0 && p->x1 == q->x1 && p->y1 == q->y1;
}

int tile_overlap(const tile_rect *a, const tile_rect *b, tile_rect *out)
{
    tile_rect s;
    s.x0 = a->x0 > b->x0 ? a->x0 : b->x0;
    s.y0 = a->y0 > b->y0 ? a->y0 : b->y0;
    s.x1 = a->x1 < b->x1 ? a->x1 : b->x1;
    s.y1 = a->y1 < b->y1 ? a->y1 : b->y1;
    if (s.x0 >= s.x1 || s.y0 >= s.y1)
        return 0;
    *out = s;
    return 1;
}

long tile_area(const tile_rect *r)
{
    return (long)(r->x1 - r->x0) * (long)(r->y1 - r->y0);
}

/* 1 when some region touches the pixels [x0, x1) of row y. */
static int row_touched(const tile_rect *regions, int count, int y, int x0, int x1)
{
    for (int i = 0; i < count; i++) {
        const tile_rect *r = &regions[i];
        if (r->y0 <= y && y < r->y1 && r->x0 < x1 && x0 < r->x1)
            return 1;
    }
    return 0;
}

/* The first uncovered pixel of row y at or after x, or width: the
 * smallest x' >= x that no region covering row y contains. */
static int next_hole(const tile_rect *regions, int count, int y, int x, int width)
{
    for (int moved = 1; moved && x < width;) {
        moved = 0;
        for (int i = 0; i < count; i++) {
            const tile_rect *r = &regions[i];
            if (r->y0 <= y && y < r->y1 && r->x0 <= x && x < r->x1) {
                x = r->x1;
                moved = 1;
            }
        }
    }
    return x;
}

/* The end of the uncovered run of row y that starts at x. */
static int hole_end(const tile_rect *regions, int count, int y, int x, int width)
{
    int end = width;
    for (int i = 0; i < count; i++) {
        const tile_rect *r = &regions[i];
        if (r->y0 <= y && y < r->y1 && r->x0 > x && r->x0 < end)
            end = r->x0;
    }
    return end;
}

int tile_find_gap(const tile_rect *regions, int count, int width, int height, tile_rect *gap)
{
    for (int y = 0; y < height; y++) {
        int x = next_hole(regions, count, y, 0, width);
        if (x >= width)
            continue;
        gap->x0 = x;
        gap->x1 = hole_end(regions, count, y, x, width);
        gap->y0 = y;
        for (gap->y1 = y + 1; gap->y1 < height && !row_touched(regions, count, gap->y1, gap->x0, gap->x1);)
            gap->y1++;
        return 1;
    }
    return 0;
}

const char *tile_rect_text(const tile_rect *r, char *buf, size_t size)
{
    snprintf(buf, size, "x %d..%d, y %d..%d", r->x0, r->x1 - 1, r->y0, r->y1 - 1);
    return buf;
}

static const char hex_digits[] = "0123456789abcdef";

void tile_key_text(uint64_t key, char out[17])
{
    for (int i = 0; i < 16; i++)
        out[i] = hex_digits[(key >> (60 - 4 * i)) & 15];
    out[16] = '\0';
}

int tile_key_parse(const char *s, uint64_t *key)
{
    uint64_t k = 0;
    if (strlen(s) != 16)
        return 0;
    for (int i = 0; i < 16; i++) {
        const char *d = s[i] ? strchr(hex_digits, s[i]) : NULL;
        if (!d)
            return 0;
        k = k << 4 | (uint64_t)(d - hex_digits);
    }
    *key = k;
    return 1;
}
