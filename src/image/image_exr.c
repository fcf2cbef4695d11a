/*
 * image_exr.c - OpenEXR through the OpenEXRCore C API of OpenEXR 3.1
 * (compiled only with EXR=1).
 *
 * Written files: one scanline part, channels B, G, R (EXR sorts them),
 * HALF by default or FLOAT on request, ZIP compression (lossless), data
 * and display window 0..w-1 x 0..h-1.  The half conversion is ours
 * (img_half_from_double: straight from double, ties to even, clamped at
 * 65504 instead of overflowing); we hand the library data already of the
 * channel's type, so it only packs and compresses.
 *
 * All I/O goes through our own stream callbacks on the caller's FILE: the
 * caller keeps the atomic temp-and-rename scheme and sees every failed
 * write (the library would otherwise open the file itself).
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>
#include <openexr.h>
#include "image/codec.h"

/* The user data of both stream directions. */
typedef struct exr_stream {
    FILE *fp;
    off_t base;      /* writing: file offset of the EXR's first byte */
    int saved_errno; /* errno of the first failed I/O call, 0 if none */
    char msg[200];   /* first message of the library's error callback */
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
    if (s->saved_errno)
        return img_error(err, errlen, STATUS_IO, "%s error: %s", what, strerror(s->saved_errno));
    if (s->msg[0])
        return img_error(err, errlen, code, "OpenEXR: %s", s->msg);
    return img_error(err, errlen, code, "OpenEXR: %s", exr_get_default_error_message(rv));
}

/* ---- Writing ---- */

/* pwrite-like on the stream: the library writes the header and chunks in
 * order, then seeks back to fill the chunk offset table. */
static int64_t stream_write(exr_const_context_t ctxt, void *ud, const void *buf, uint64_t sz,
                            uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    exr_stream *s = ud;
    (void)ctxt;
    (void)error_cb;
    if (fseeko(s->fp, s->base + (off_t)offset, SEEK_SET) != 0 || fwrite(buf, 1, sz, s->fp) != sz) {
        if (!s->saved_errno)
            s->saved_errno = errno ? errno : EIO;
        return -1;
    }
    return (int64_t)sz;
}

/* The three planes R, G, B of the image in the channel type, each
 * width*height values of elem bytes, top row first. */
typedef struct exr_planes {
    unsigned char *plane[3];
    int elem;  /* 2 (half) or 4 (float) */
    int ptype; /* EXR_PIXEL_HALF or EXR_PIXEL_FLOAT */
} exr_planes;

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

static int fill_planes(exr_planes *pl, const img_buf *img, int use_float, img_write_stats *st)
{
    size_t n = (size_t)img->width * (size_t)img->height;
    pl->elem = use_float ? 4 : 2;
    pl->ptype = use_float ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF;
    for (int c = 0; c < 3; c++)
        pl->plane[c] = malloc(n * (size_t)pl->elem);
    if (!pl->plane[0] || !pl->plane[1] || !pl->plane[2])
        return -1;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            store_value(pl, c, i, img->rgb[3 * i + (size_t)c], st);
    return 0;
}

/* 0, 1, 2 for the channels R, G, B, else -1. */
static int rgb_index(const char *name)
{
    if (!name || !name[0] || name[1])
        return -1;
    return name[0] == 'R' ? 0 : name[0] == 'G' ? 1 : name[0] == 'B' ? 2 : -1;
}

/* Points the encoder's channels at the rows of the chunk starting at y. */
static void aim_encoder(exr_encode_pipeline_t *enc, const exr_planes *pl, int width, int y)
{
    for (int i = 0; i < enc->channel_count; i++) {
        exr_coding_channel_info_t *ch = &enc->channels[i];
        int c = rgb_index(ch->channel_name);
        ch->encode_from_ptr = c < 0 ? NULL : pl->plane[c] + (size_t)y * (size_t)width * (size_t)pl->elem;
        ch->user_pixel_stride = pl->elem;
        ch->user_line_stride = pl->elem * width;
        ch->user_data_type = (uint16_t)pl->ptype;
        ch->user_bytes_per_element = (int16_t)pl->elem;
    }
}

static exr_result_t write_chunks(exr_context_t ctx, int part, const img_buf *img,
                                 const exr_planes *pl)
{
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int32_t lines = 0;
    int started = 0;
    exr_result_t rv = exr_get_scanlines_per_chunk(ctx, part, &lines);
    for (int y = 0; rv == EXR_ERR_SUCCESS && y < img->height; y += lines) {
        exr_chunk_info_t ci;
        rv = exr_write_scanline_chunk_info(ctx, part, y, &ci);
        if (rv == EXR_ERR_SUCCESS)
            rv = started ? exr_encoding_update(ctx, part, &ci, &enc)
                         : exr_encoding_initialize(ctx, part, &ci, &enc);
        if (rv != EXR_ERR_SUCCESS)
            break;
        aim_encoder(&enc, pl, img->width, y);
        if (!started++)
            rv = exr_encoding_choose_default_routines(ctx, part, &enc);
        if (rv == EXR_ERR_SUCCESS)
            rv = exr_encoding_run(ctx, part, &enc);
    }
    if (started)
        exr_encoding_destroy(ctx, &enc);
    return rv;
}

/* Part, required attributes, channels, header. */
static exr_result_t define_part(exr_context_t ctx, const img_buf *img, int ptype, int *part)
{
    static const char *const names[3] = {"R", "G", "B"};
    exr_result_t rv = exr_add_part(ctx, "rgb", EXR_STORAGE_SCANLINE, part);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_initialize_required_attr_simple(ctx, *part, img->width, img->height,
                                                 EXR_COMPRESSION_ZIP);
    for (int c = 0; c < 3 && rv == EXR_ERR_SUCCESS; c++)
        rv = exr_add_channel(ctx, *part, names[c], (exr_pixel_type_t)ptype,
                             EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_write_header(ctx);
    return rv;
}

static exr_result_t encode_exr(exr_stream *s, const img_buf *img, const exr_planes *pl)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    int part = 0;
    init.user_data = s;
    init.write_fn = stream_write;
    init.error_handler_fn = on_exr_error;
    exr_result_t rv = exr_start_write(&ctx, "image.exr", EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv == EXR_ERR_SUCCESS)
        rv = define_part(ctx, img, pl->ptype, &part);
    if (rv == EXR_ERR_SUCCESS)
        rv = write_chunks(ctx, part, img, pl);
    /* exr_finish writes the chunk offset table, so its result counts. */
    exr_result_t fin = ctx ? exr_finish(&ctx) : EXR_ERR_SUCCESS;
    return rv != EXR_ERR_SUCCESS ? rv : fin;
}

int img_exr_write(FILE *fp, const img_buf *img, const img_write_opts *o, img_write_stats *st,
                  char *err, size_t errlen)
{
    exr_stream s = {fp, 0, 0, ""};
    exr_planes pl = {{NULL, NULL, NULL}, 0, 0};
    int rc = STATUS_OK;
    s.base = ftello(fp);
    if (s.base < 0)
        rc = img_error(err, errlen, STATUS_IO, "EXR needs a seekable file: %s", strerror(errno));
    else if (fill_planes(&pl, img, o->exr_float, st) != 0)
        rc = img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    else {
        exr_result_t rv = encode_exr(&s, img, &pl);
        if (rv != EXR_ERR_SUCCESS || s.saved_errno)
            rc = exr_failure(&s, rv, STATUS_IO, "write", err, errlen);
    }
    for (int c = 0; c < 3; c++)
        free(pl.plane[c]);
    return rc;
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

/* The decoded image as three float planes of the data window. */
typedef struct exr_target {
    float *plane[3];
    int width, height;
    int min_y; /* data window top, so that chunk rows map to plane rows */
} exr_target;

/* Points the decoder's R, G, B channels at the chunk's rows as floats
 * (the library converts half and uint); other channels are skipped. */
static void aim_decoder(exr_decode_pipeline_t *dec, const exr_target *t, int start_y)
{
    for (int i = 0; i < dec->channel_count; i++) {
        exr_coding_channel_info_t *ch = &dec->channels[i];
        int c = rgb_index(ch->channel_name);
        size_t row = (size_t)(start_y - t->min_y);
        ch->decode_to_ptr = c < 0 ? NULL : (uint8_t *)(t->plane[c] + row * (size_t)t->width);
        ch->user_pixel_stride = 4;
        ch->user_line_stride = 4 * t->width;
        ch->user_data_type = EXR_PIXEL_FLOAT;
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

/* The first part must be a scanline image with full-resolution R, G, B. */
static int check_layout(exr_const_context_t ctx, exr_target *t, char *err, size_t errlen)
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
    t->width = dw.max.x - dw.min.x + 1;
    t->height = dw.max.y - dw.min.y + 1;
    t->min_y = dw.min.y;
    if (t->width < 1 || t->height < 1 || t->width > IMG_MAX_PIXELS / t->height)
        return img_error(err, errlen, STATUS_DATA, "bad data window");
    return STATUS_OK;
}

static void copy_planes(const exr_target *t, img_buf *out)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            out->rgb[3 * i + (size_t)c] = t->plane[c][i];
}

/* Decodes the first part into *out once the context is open. */
static int decode_exr(exr_const_context_t ctx, exr_stream *s, img_buf *out, char *err,
                      size_t errlen)
{
    exr_target t = {{NULL, NULL, NULL}, 0, 0, 0};
    int rc = check_layout(ctx, &t, err, errlen);
    for (int c = 0; rc == STATUS_OK && c < 3; c++)
        if (!(t.plane[c] = calloc((size_t)t.width * (size_t)t.height, sizeof(float))))
            rc = img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    if (rc == STATUS_OK) {
        exr_result_t rv = read_chunks(ctx, &t);
        if (rv != EXR_ERR_SUCCESS)
            rc = exr_failure(s, rv, STATUS_DATA, "read", err, errlen);
    }
    if (rc == STATUS_OK && (rc = img_create(out, t.width, t.height)) != STATUS_OK)
        rc = img_error(err, errlen, rc, "out of memory");
    if (rc == STATUS_OK)
        copy_planes(&t, out);
    for (int c = 0; c < 3; c++)
        free(t.plane[c]);
    return rc;
}

int img_exr_read(FILE *fp, img_buf *out, char *err, size_t errlen)
{
    exr_stream s = {fp, 0, 0, ""};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    init.user_data = &s;
    init.read_fn = stream_read;
    init.size_fn = stream_size;
    init.error_handler_fn = on_exr_error;
    exr_result_t rv = exr_start_read(&ctx, "image.exr", &init);
    int rc = rv == EXR_ERR_SUCCESS ? decode_exr(ctx, &s, out, err, errlen)
                                   : exr_failure(&s, rv, STATUS_DATA, "read", err, errlen);
    if (ctx)
        exr_finish(&ctx);
    return rc;
}
