/*
 * image_exr.c - OpenEXR through the OpenEXRCore C API of OpenEXR 3.1
 * (compiled only with EXR=1).
 *
 * Written files: one scanline part, channels B, G, R (EXR sorts them),
 * HALF by default or FLOAT on request, ZIP compression (lossless), data
 * and display window 0..w-1 x 0..h-1.  A tile (image/tile.h) differs in
 * three ways: the display window is the whole image and the data window
 * the tile's region; six UINT channels f64hi.R .. f64lo.B hold the high
 * and low 32 bits of each value's IEEE double, so a merge gets back
 * exactly the doubles a whole render has; and the string attribute
 * refrayKey holds the render's fingerprint (16 hex digits) and the int
 * refrayTile the layout's version, 1.  The half conversion is ours
 * (img_half_from_double: straight from double, ties to even, clamped at
 * 65504 instead of overflowing); we hand the library data already of the
 * channel's type, so it only packs and compresses.
 *
 * All I/O goes through our own stream callbacks on the caller's FILE: the
 * caller keeps the atomic temp-and-rename scheme and sees every failed
 * write (the library would otherwise open the file itself).  The library
 * writes the chunk offset table last, at the front: a stream that cannot
 * seek (a pipe) gets the file built in memory first and then written in
 * one go, so `render -o - --format exr` works.
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>
#include <openexr.h>
#include "image/codec.h"
#include "image/tile.h"

/* The user data of both stream directions. */
typedef struct exr_stream {
    FILE *fp;
    off_t base;      /* writing: file offset of the EXR's first byte; -1: into memory */
    int saved_errno; /* errno of the first failed I/O call, 0 if none */
    char msg[200];   /* first message of the library's error callback */
    unsigned char *buf; /* writing into memory: the file so far, from mem */
    size_t len, cap;
    const mem *mem;
    int out_of_memory;
} exr_stream;

/* The library reports errors through this callback (by default it prints
 * to stderr); we keep the first message for err. */
static void on_exr_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    void *ud = NULL;
    (void)code;
    if (exr_get_user_data(ctxt, &ud) == EXR_ERR_SUCCESS && ud) {
        exr_stream *s = ud;
        if (!s->msg[0])
            snprintf(s->msg, sizeof s->msg, "%s", msg ? msg : "unknown error");
    }
}

/* The reason for err: the operating system's word if a read or write
 * failed, else the library's message, else its generic text for rv. */
static int exr_failure(const exr_stream *s, exr_result_t rv, int code, const char *what, char *err,
                       size_t errlen)
{
    if (s->out_of_memory || rv == EXR_ERR_OUT_OF_MEMORY)
        return img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    if (s->saved_errno)
        return img_error(err, errlen, STATUS_IO, "%s error: %s", what, strerror(s->saved_errno));
    if (s->msg[0])
        return img_error(err, errlen, code, "OpenEXR: %s", s->msg);
    return img_error(err, errlen, code, "OpenEXR: %s", exr_get_default_error_message(rv));
}

/* ---- Writing ---- */

/* pwrite-like into the memory image of the file. */
static int64_t memory_write(exr_stream *s, const void *buf, uint64_t sz, uint64_t offset)
{
    if (offset > SIZE_MAX - sz) {
        s->out_of_memory = 1;
        return -1;
    }
    size_t end = (size_t)(offset + sz);
    if (end > s->cap) {
        size_t cap = s->cap ? s->cap : 1 << 16;
        while (cap < end)
            cap = cap > SIZE_MAX / 2 ? end : 2 * cap;
        unsigned char *grown = mem_resize(s->mem, s->buf, s->cap, cap);
        if (!grown) {
            s->out_of_memory = 1;
            return -1;
        }
        memset(grown + s->cap, 0, cap - s->cap);
        s->buf = grown;
        s->cap = cap;
    }
    memcpy(s->buf + offset, buf, sz);
    if (end > s->len)
        s->len = end;
    return (int64_t)sz;
}

/* pwrite-like on the stream: the library writes the header and chunks in
 * order, then seeks back to fill the chunk offset table. */
static int64_t stream_write(exr_const_context_t ctxt, void *ud, const void *buf, uint64_t sz,
                            uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    exr_stream *s = ud;
    (void)ctxt;
    (void)error_cb;
    if (s->base < 0)
        return memory_write(s, buf, sz, offset);
    if (fseeko(s->fp, s->base + (off_t)offset, SEEK_SET) != 0 || fwrite(buf, 1, sz, s->fp) != sz) {
        if (!s->saved_errno)
            s->saved_errno = errno ? errno : EIO;
        return -1;
    }
    return (int64_t)sz;
}

/* The channels refray writes and reads, in slots: R, G, B, then a
 * tile's exact doubles (their high words, then their low words). */
enum { RGB_SLOTS = 3, SLOT_COUNT = 9 };
static const char *const slot_names[SLOT_COUNT] = {"R", "G", "B", "f64hi.R", "f64hi.G", "f64hi.B",
                                                   "f64lo.R", "f64lo.G", "f64lo.B"};

/* The slot of a channel name, or -1. */
static int slot_index(const char *name)
{
    for (int i = 0; name && i < SLOT_COUNT; i++)
        if (strcmp(name, slot_names[i]) == 0)
            return i;
    return -1;
}

/* The planes of the image in the channel types, each width*height values,
 * top row first: R, G, B of elem bytes, the double words as uint32.  A
 * NULL plane is a channel not written. */
typedef struct exr_planes {
    unsigned char *plane[SLOT_COUNT];
    int elem;  /* R, G, B: 2 (half) or 4 (float) */
    int ptype; /* R, G, B: EXR_PIXEL_HALF or EXR_PIXEL_FLOAT */
    size_t bytes[SLOT_COUNT]; /* of each plane, from the image's allocator */
} exr_planes;

static int slot_elem(const exr_planes *pl, int slot)
{
    return slot < RGB_SLOTS ? pl->elem : 4;
}

static int slot_type(const exr_planes *pl, int slot)
{
    return slot < RGB_SLOTS ? pl->ptype : EXR_PIXEL_UINT;
}

/* What the header says beyond the channels. */
typedef struct exr_layout {
    int width, height;                 /* the planes: the data window's size */
    exr_attr_box2i_t display, data;
    const char *key;                   /* refrayKey of a tile, NULL for an image */
} exr_layout;

static void store_value(exr_planes *pl, int c, size_t i, double v, img_write_stats *st)
{
    int clamped;
    v = img_sanitize(v, st);
    if (pl->ptype == EXR_PIXEL_HALF) {
        uint16_t h = img_half_from_double(v, &clamped);
        memcpy(pl->plane[c] + 2 * i, &h, 2);
    } else {
        float f = img_float_from_double(v, &clamped);
        memcpy(pl->plane[c] + 4 * i, &f, 4);
    }
    st->clamped += (size_t)clamped;
}

/* The double's bits into the high and low word planes of channel c. */
static void store_exact(exr_planes *pl, int c, size_t i, double v)
{
    uint64_t bits;
    uint32_t hi, lo;
    memcpy(&bits, &v, sizeof bits);
    hi = (uint32_t)(bits >> 32);
    lo = (uint32_t)(bits & 0xffffffffu);
    memcpy(pl->plane[RGB_SLOTS + c] + 4 * i, &hi, 4);
    memcpy(pl->plane[2 * RGB_SLOTS + c] + 4 * i, &lo, 4);
}

/* The planes of img; with exact, the double words too. */
static int fill_planes(exr_planes *pl, const img_buf *img, int use_float, int exact, img_write_stats *st)
{
    size_t n = (size_t)img->width * (size_t)img->height;
    int slots = exact ? SLOT_COUNT : RGB_SLOTS;
    pl->elem = use_float ? 4 : 2;
    pl->ptype = use_float ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF;
    for (int c = 0; c < slots; c++) {
        pl->bytes[c] = n * (size_t)slot_elem(pl, c);
        if (!(pl->plane[c] = mem_alloc(&img->mem, pl->bytes[c])))
            return -1;
    }
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            store_value(pl, c, i, img->rgb[3 * i + (size_t)c], st);
            if (exact)
                store_exact(pl, c, i, img->rgb[3 * i + (size_t)c]);
        }
    return 0;
}

/* 0, 1, 2 for the channels R, G, B, else -1. */
static int rgb_index(const char *name)
{
    int c = slot_index(name);
    return c < RGB_SLOTS ? c : -1;
}

/* Points the encoder's channels at row `row` of their planes, where the
 * chunk starts. */
static void aim_encoder(exr_encode_pipeline_t *enc, const exr_planes *pl, int width, int row)
{
    for (int i = 0; i < enc->channel_count; i++) {
        exr_coding_channel_info_t *ch = &enc->channels[i];
        int c = slot_index(ch->channel_name), elem = c < 0 ? 4 : slot_elem(pl, c);
        ch->encode_from_ptr = c < 0 ? NULL : pl->plane[c] + (size_t)row * (size_t)width * (size_t)elem;
        ch->user_pixel_stride = elem;
        ch->user_line_stride = elem * width;
        ch->user_data_type = (uint16_t)(c < 0 ? EXR_PIXEL_UINT : slot_type(pl, c));
        ch->user_bytes_per_element = (int16_t)elem;
    }
}

static exr_result_t write_chunks(exr_context_t ctx, int part, const exr_layout *lay, const exr_planes *pl,
                                 const img_buf *img, const img_write_opts *o, int *cancelled)
{
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int32_t lines = 0;
    int started = 0;
    exr_result_t rv = exr_get_scanlines_per_chunk(ctx, part, &lines);
    for (int y = lay->data.min.y; rv == EXR_ERR_SUCCESS && y <= lay->data.max.y; y += lines) {
        exr_chunk_info_t ci;
        rv = exr_write_scanline_chunk_info(ctx, part, y, &ci);
        if (rv == EXR_ERR_SUCCESS)
            rv = started ? exr_encoding_update(ctx, part, &ci, &enc)
                         : exr_encoding_initialize(ctx, part, &ci, &enc);
        if (rv != EXR_ERR_SUCCESS)
            break;
        if ((*cancelled = img_row_cancelled(o, img)) != 0)
            break;
        aim_encoder(&enc, pl, lay->width, y - lay->data.min.y);
        if (!started++)
            rv = exr_encoding_choose_default_routines(ctx, part, &enc);
        if (rv == EXR_ERR_SUCCESS)
            rv = exr_encoding_run(ctx, part, &enc);
    }
    if (started)
        exr_encoding_destroy(ctx, &enc);
    return rv;
}

/* Part, required attributes (the defaults of
 * exr_initialize_required_attr_simple but the windows), channels, a
 * tile's attributes, header. */
static exr_result_t define_part(exr_context_t ctx, const exr_layout *lay, const exr_planes *pl, int *part)
{
    exr_attr_v2f_t centre = {{{0.0f, 0.0f}}};
    exr_result_t rv = exr_add_part(ctx, "rgb", EXR_STORAGE_SCANLINE, part);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_initialize_required_attr(ctx, *part, &lay->display, &lay->data, 1.0f, &centre, 1.0f,
                                          EXR_LINEORDER_INCREASING_Y, EXR_COMPRESSION_ZIP);
    for (int c = 0; c < SLOT_COUNT && rv == EXR_ERR_SUCCESS; c++)
        if (pl->plane[c])
            rv = exr_add_channel(ctx, *part, slot_names[c], (exr_pixel_type_t)slot_type(pl, c),
                                 c < RGB_SLOTS ? EXR_PERCEPTUALLY_LOGARITHMIC : EXR_PERCEPTUALLY_LINEAR, 1, 1);
    if (rv == EXR_ERR_SUCCESS && lay->key)
        rv = exr_attr_set_string(ctx, *part, "refrayKey", lay->key);
    if (rv == EXR_ERR_SUCCESS && lay->key)
        rv = exr_attr_set_int(ctx, *part, "refrayTile", 1);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_write_header(ctx);
    return rv;
}

static exr_result_t encode_exr(exr_stream *s, const exr_layout *lay, const exr_planes *pl, const img_buf *img,
                               const img_write_opts *o, int *cancelled)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    int part = 0;
    init.user_data = s;
    init.write_fn = stream_write;
    init.error_handler_fn = on_exr_error;
    exr_result_t rv = exr_start_write(&ctx, "image.exr", EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv == EXR_ERR_SUCCESS)
        rv = define_part(ctx, lay, pl, &part);
    if (rv == EXR_ERR_SUCCESS)
        rv = write_chunks(ctx, part, lay, pl, img, o, cancelled);
    /* exr_finish writes the chunk offset table, so its result counts. */
    exr_result_t fin = ctx ? exr_finish(&ctx) : EXR_ERR_SUCCESS;
    return rv != EXR_ERR_SUCCESS ? rv : fin;
}

static exr_attr_box2i_t box(int x0, int y0, int x1, int y1)
{
    exr_attr_box2i_t b;
    b.min.x = x0;
    b.min.y = y0;
    b.max.x = x1 - 1;
    b.max.y = y1 - 1;
    return b;
}

/* img laid out as lay says; exact: with the double words. */
static int write_exr(FILE *fp, const img_buf *img, const exr_layout *lay, int exact, const img_write_opts *o,
                     img_write_stats *st, char *err, size_t errlen)
{
    exr_stream s;
    exr_planes pl;
    int rc = STATUS_OK, cancelled = 0;
    memset(&s, 0, sizeof s);
    memset(&pl, 0, sizeof pl);
    s.fp = fp;
    s.mem = &img->mem;
    /* A stream without a position (a pipe) gets the file from memory. */
    s.base = ftello(fp);
    if (fill_planes(&pl, img, o->exr_float, exact, st) != 0)
        rc = img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    else {
        exr_result_t rv = encode_exr(&s, lay, &pl, img, o, &cancelled);
        if (cancelled)
            rc = img_error(err, errlen, STATUS_CANCELLED, "interrupted");
        else if (rv != EXR_ERR_SUCCESS || s.saved_errno || s.out_of_memory)
            rc = exr_failure(&s, rv, STATUS_IO, "write", err, errlen);
        else if (s.base < 0 && fwrite(s.buf, 1, s.len, fp) != s.len)
            rc = img_error(err, errlen, STATUS_IO, "write error: %s", strerror(errno));
    }
    for (int c = 0; c < SLOT_COUNT; c++)
        mem_free(&img->mem, pl.plane[c], pl.bytes[c]);
    mem_free(&img->mem, s.buf, s.cap);
    return rc;
}

int img_exr_write(FILE *fp, const img_buf *img, const img_write_opts *o, img_write_stats *st,
                  char *err, size_t errlen)
{
    exr_layout lay;
    lay.width = img->width;
    lay.height = img->height;
    lay.display = lay.data = box(0, 0, img->width, img->height);
    lay.key = NULL;
    return write_exr(fp, img, &lay, 0, o, st, err, errlen);
}

int img_exr_write_tile(FILE *fp, const tile_info *t, const img_buf *img, const img_write_opts *o,
                       img_write_stats *st, char *err, size_t errlen)
{
    char key[17];
    exr_layout lay;
    tile_key_text(t->key, key);
    lay.width = img->width;
    lay.height = img->height;
    lay.display = box(0, 0, t->width, t->height);
    lay.data = box(t->region.x0, t->region.y0, t->region.x1, t->region.y1);
    lay.key = key;
    return write_exr(fp, img, &lay, 1, o, st, err, errlen);
}

/* ---- Reading ---- */

static int64_t stream_read(exr_const_context_t ctxt, void *ud, void *buf, uint64_t sz,
                           uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    exr_stream *s = ud;
    unsigned char *p = buf;
    uint64_t done = 0;
    (void)ctxt;
    (void)error_cb;
    while (done < sz) {
        ssize_t n = pread(fileno(s->fp), p + done, sz - done, (off_t)(offset + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            if (!s->saved_errno)
                s->saved_errno = errno;
            return -1;
        }
        if (n == 0)
            break; /* end of file: the library judges the short read */
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

static int64_t stream_size(exr_const_context_t ctxt, void *ud)
{
    exr_stream *s = ud;
    struct stat sb;
    (void)ctxt;
    return fstat(fileno(s->fp), &sb) == 0 && S_ISREG(sb.st_mode) ? (int64_t)sb.st_size : -1;
}

/* The decoded planes of the data window, 4 bytes a value: R, G, B as
 * floats, a tile's double words as uint32.  NULL planes are not decoded. */
typedef struct exr_target {
    unsigned char *plane[SLOT_COUNT];
    int width, height;
    int min_y; /* data window top, so that chunk rows map to plane rows */
} exr_target;

/* Points the decoder's wanted channels at the chunk's rows (the library
 * converts half and uint to float); other channels are skipped. */
static void aim_decoder(exr_decode_pipeline_t *dec, const exr_target *t, int start_y)
{
    for (int i = 0; i < dec->channel_count; i++) {
        exr_coding_channel_info_t *ch = &dec->channels[i];
        int c = slot_index(ch->channel_name);
        size_t row = (size_t)(start_y - t->min_y);
        ch->decode_to_ptr = c < 0 || !t->plane[c] ? NULL : t->plane[c] + 4 * row * (size_t)t->width;
        ch->user_pixel_stride = 4;
        ch->user_line_stride = 4 * t->width;
        ch->user_data_type = c >= RGB_SLOTS ? EXR_PIXEL_UINT : EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
    }
}

static exr_result_t read_chunks(exr_const_context_t ctx, const exr_target *t)
{
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    int32_t lines = 0;
    int started = 0;
    exr_result_t rv = exr_get_scanlines_per_chunk(ctx, 0, &lines);
    for (int y = t->min_y; rv == EXR_ERR_SUCCESS && y < t->min_y + t->height; y += lines) {
        exr_chunk_info_t ci;
        rv = exr_read_scanline_chunk_info(ctx, 0, y, &ci);
        if (rv == EXR_ERR_SUCCESS)
            rv = started ? exr_decoding_update(ctx, 0, &ci, &dec)
                         : exr_decoding_initialize(ctx, 0, &ci, &dec);
        if (rv != EXR_ERR_SUCCESS)
            break;
        aim_decoder(&dec, t, ci.start_y);
        if (!started++)
            rv = exr_decoding_choose_default_routines(ctx, 0, &dec);
        if (rv == EXR_ERR_SUCCESS)
            rv = exr_decoding_run(ctx, 0, &dec);
    }
    if (started)
        exr_decoding_destroy(ctx, &dec);
    return rv;
}

/* The first part must be a scanline image with full-resolution R, G, B,
 * of a size o accepts. */
static int check_layout(exr_const_context_t ctx, const img_read_opts *o, exr_target *t, char *err, size_t errlen)
{
    exr_storage_t storage;
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *chl = NULL;
    int found = 0;
    if (exr_get_storage(ctx, 0, &storage) || storage != EXR_STORAGE_SCANLINE)
        return img_error(err, errlen, STATUS_DATA, "only scanline OpenEXR files are supported");
    if (exr_get_data_window(ctx, 0, &dw) || exr_get_channels(ctx, 0, &chl) || !chl)
        return img_error(err, errlen, STATUS_DATA, "OpenEXR header lacks a data window or channels");
    for (int i = 0; i < chl->num_channels; i++) {
        const exr_attr_chlist_entry_t *e = &chl->entries[i];
        int c = rgb_index(e->name.str);
        if (c >= 0 && (e->x_sampling != 1 || e->y_sampling != 1))
            return img_error(err, errlen, STATUS_DATA, "subsampled channel %s", e->name.str);
        found |= c >= 0 ? 1 << c : 0;
    }
    if (found != 7)
        return img_error(err, errlen, STATUS_DATA, "the file has no R, G and B channels");
    long width = (long)dw.max.x - dw.min.x + 1, height = (long)dw.max.y - dw.min.y + 1;
    int rc = img_check_header(width, height, o, err, errlen);
    t->width = (int)width;
    t->height = (int)height;
    t->min_y = dw.min.y;
    return rc;
}

static void copy_planes(const exr_target *t, img_buf *out)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            float f;
            memcpy(&f, t->plane[c] + 4 * i, 4);
            out->rgb[3 * i + (size_t)c] = f;
        }
}

/* Decodes the slots [from, to) of the first part into new planes of t
 * (the caller frees them) and makes *out of the data window's size. */
static int decode_planes(exr_const_context_t ctx, exr_stream *s, exr_target *t, int from, int to, img_buf *out,
                         char *err, size_t errlen)
{
    int rc = STATUS_OK;
    for (int c = from; rc == STATUS_OK && c < to; c++)
        if (!(t->plane[c] = calloc((size_t)t->width * (size_t)t->height, 4)))
            rc = img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    if (rc == STATUS_OK) {
        exr_result_t rv = read_chunks(ctx, t);
        if (rv != EXR_ERR_SUCCESS)
            rc = exr_failure(s, rv, STATUS_DATA, "read", err, errlen);
    }
    if (rc == STATUS_OK && (rc = img_create(out, t->width, t->height)) != STATUS_OK)
        rc = img_error(err, errlen, rc, "out of memory");
    return rc;
}

static void free_planes(exr_target *t)
{
    for (int c = 0; c < SLOT_COUNT; c++)
        free(t->plane[c]);
}

/* Decodes the first part into *out once the context is open (info: unused,
 * the shape of read_exr's decode). */
static int decode_exr(exr_const_context_t ctx, exr_stream *s, const img_read_opts *o, tile_info *info,
                      img_buf *out, char *err, size_t errlen)
{
    exr_target t;
    (void)info;
    memset(&t, 0, sizeof t);
    int rc = check_layout(ctx, o, &t, err, errlen);
    if (rc == STATUS_OK && o->header_only) {
        out->width = t.width;
        out->height = t.height;
        return STATUS_OK;
    }
    if (rc == STATUS_OK)
        rc = decode_planes(ctx, s, &t, 0, RGB_SLOTS, out, err, errlen);
    if (rc == STATUS_OK)
        copy_planes(&t, out);
    free_planes(&t);
    return rc;
}

/* ---- Reading tiles ---- */

/* The tile's attributes and windows into *info; the data window's size
 * and top into t.  The whole image is held to o's --max-pixels before
 * anything is allocated: a merge makes an image of that size. */
static int tile_header(exr_const_context_t ctx, const img_read_opts *o, tile_info *info, exr_target *t, char *err,
                       size_t errlen)
{
    exr_storage_t storage;
    exr_attr_box2i_t disp, dw;
    const char *key = NULL;
    int32_t len = 0, version = 0;
    if (exr_attr_get_string(ctx, 0, "refrayKey", &len, &key) || !key ||
        exr_attr_get_int(ctx, 0, "refrayTile", &version))
        return img_error(err, errlen, STATUS_DATA, "not a refray tile (no refrayKey and refrayTile attributes)");
    char text[17];
    snprintf(text, sizeof text, "%.*s", len > 16 ? 16 : (int)len, key);
    if (version != 1 || len != 16 || !tile_key_parse(text, &info->key))
        return img_error(err, errlen, STATUS_DATA, "a refray tile of another version (refrayTile %d)", (int)version);
    if (exr_get_storage(ctx, 0, &storage) || storage != EXR_STORAGE_SCANLINE ||
        exr_get_display_window(ctx, 0, &disp) || exr_get_data_window(ctx, 0, &dw) || disp.min.x || disp.min.y ||
        dw.max.x == INT32_MAX || dw.max.y == INT32_MAX)
        return img_error(err, errlen, STATUS_DATA, "a refray tile with a damaged header");
    /* The whole image against --max-pixels, in long: a header may claim
     * a window up to INT_MAX. */
    int rc = img_check_header((long)disp.max.x + 1, (long)disp.max.y + 1, o, err, errlen);
    if (rc != STATUS_OK)
        return rc;
    info->width = disp.max.x + 1;
    info->height = disp.max.y + 1;
    info->region.x0 = dw.min.x;
    info->region.y0 = dw.min.y;
    info->region.x1 = dw.max.x + 1;
    info->region.y1 = dw.max.y + 1;
    char why[200];
    if (!tile_info_valid(info, img_max_pixels(o), why, sizeof why))
        return img_error(err, errlen, STATUS_DATA, "a refray tile with a bad header: %s", why);
    t->width = info->region.x1 - info->region.x0;
    t->height = info->region.y1 - info->region.y0;
    t->min_y = dw.min.y;
    return STATUS_OK;
}

/* Every double word channel is there, as full-resolution UINT. */
static int tile_channels(exr_const_context_t ctx, char *err, size_t errlen)
{
    const exr_attr_chlist_t *chl = NULL;
    int found = 0;
    if (exr_get_channels(ctx, 0, &chl) || !chl)
        return img_error(err, errlen, STATUS_DATA, "a refray tile without channels");
    for (int i = 0; i < chl->num_channels; i++) {
        const exr_attr_chlist_entry_t *e = &chl->entries[i];
        int c = slot_index(e->name.str);
        if (c >= RGB_SLOTS && e->pixel_type == EXR_PIXEL_UINT && e->x_sampling == 1 && e->y_sampling == 1)
            found |= 1 << c;
    }
    if (found != ((1 << SLOT_COUNT) - 1) - ((1 << RGB_SLOTS) - 1))
        return img_error(err, errlen, STATUS_DATA, "a refray tile without its exact f64hi/f64lo channels");
    return STATUS_OK;
}

static void join_words(const exr_target *t, img_buf *out)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            uint32_t hi, lo;
            memcpy(&hi, t->plane[RGB_SLOTS + c] + 4 * i, 4);
            memcpy(&lo, t->plane[2 * RGB_SLOTS + c] + 4 * i, 4);
            uint64_t bits = (uint64_t)hi << 32 | lo;
            memcpy(&out->rgb[3 * i + (size_t)c], &bits, sizeof bits);
        }
}

static int decode_tile(exr_const_context_t ctx, exr_stream *s, const img_read_opts *o, tile_info *info,
                       img_buf *out, char *err, size_t errlen)
{
    exr_target t;
    memset(&t, 0, sizeof t);
    int rc = tile_header(ctx, o, info, &t, err, errlen);
    if (rc == STATUS_OK)
        rc = tile_channels(ctx, err, errlen);
    if (rc != STATUS_OK || !out)
        return rc;
    rc = decode_planes(ctx, s, &t, RGB_SLOTS, SLOT_COUNT, out, err, errlen);
    if (rc == STATUS_OK)
        join_words(&t, out);
    free_planes(&t);
    return rc;
}

/* Reads the OpenEXR file fp through decode, which sees the open context:
 * a plain image or a tile.  Returns decode's status, or the open's. */
static int read_exr(FILE *fp,
                    int (*decode)(exr_const_context_t ctx, exr_stream *s, const img_read_opts *o, tile_info *info,
                                  img_buf *out, char *err, size_t errlen),
                    const img_read_opts *o, tile_info *info, img_buf *out, char *err, size_t errlen)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    exr_stream s;
    memset(&s, 0, sizeof s);
    s.fp = fp;
    init.user_data = &s;
    init.read_fn = stream_read;
    init.size_fn = stream_size;
    init.error_handler_fn = on_exr_error;
    exr_result_t rv = exr_start_read(&ctx, "image.exr", &init);
    int rc = rv == EXR_ERR_SUCCESS ? decode(ctx, &s, o, info, out, err, errlen)
                                   : exr_failure(&s, rv, STATUS_DATA, "read", err, errlen);
    if (ctx)
        exr_finish(&ctx);
    return rc;
}

int img_exr_read(FILE *fp, const img_read_opts *o, img_buf *out, char *err, size_t errlen)
{
    return read_exr(fp, decode_exr, o, NULL, out, err, errlen);
}

int img_exr_read_tile(FILE *fp, const img_read_opts *o, tile_info *info, img_buf *out, char *err, size_t errlen)
{
    return read_exr(fp, decode_tile, o, info, out, err, errlen);
}
