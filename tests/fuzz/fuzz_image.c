/*
 * fuzz_image.c - libFuzzer harness over the image readers (PNG, EXR, PFM,
 * PPM), the files `compare` and `--mask` read from users.  The first byte
 * picks the format, the rest is the file.  `make fuzz FUZZ_TARGET=image`.
 *
 * The pixel limit is lowered so that a header claiming a large but legal
 * image costs little: the fuzzer looks for crashes, leaks, undefined
 * behaviour and headers that slip past the limit ([REL-IMAGE-1]), which
 * the size check below catches.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "image/image_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

enum { FUZZ_MAX_PIXELS = 1 << 16 };

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const img_format formats[4] = {IMG_FORMAT_PNG, IMG_FORMAT_EXR, IMG_FORMAT_PFM, IMG_FORMAT_PPM};
    if (size < 1)
        return 0;
    img_format fmt = formats[data[0] % 4];
    if (!img_format_available(fmt))
        return 0;
    FILE *fp = fmemopen((void *)(data + 1), size - 1, "rb");
    if (!fp)
        return 0;
    img_read_opts o = img_read_opts_default();
    o.max_pixels = FUZZ_MAX_PIXELS;
    img_buf img;
    char err[256];
    int status = img_read_stream(fp, fmt, &o, &img, err, sizeof err);
    fclose(fp);
    if (status == 0) {
        if ((long)img.width * img.height > FUZZ_MAX_PIXELS)
            __builtin_trap(); /* the limit is judged on the header */
        img_free(&img);
    }
    return 0;
}
