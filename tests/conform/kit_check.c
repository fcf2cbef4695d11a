/*
 * kit_check.c - checks a picture against one scene of a refray conformance
 * kit without refray: one C99 file, no library, PFM pictures and the PGM
 * mask only.  It is the rule of spec/conformance.md [KIT-RULE-1] written
 * out, for a renderer's author who wants to read it or port it:
 *
 *     cc -std=c99 -O2 -o kit_check kit_check.c -lm
 *     kit_check EXACT.pfm MASK.pgm RELATIVE ABSOLUTE MINE.pfm
 *
 * EXACT.pfm and MASK.pgm are the scene's files in the kit; RELATIVE and
 * ABSOLUTE are its manifest's "tolerance" numbers "relative" and
 * "absolute" (a float picture's; "absolute_png" is a PNG's).  A channel fails when
 * |mine - exact| > RELATIVE * |exact| + ABSOLUTE, or when it is not a
 * number; masked pixels (mask byte 255) are skipped.  Prints
 * "N of M pixels over"; exit 0 when none is over and at least one pixel
 * was compared, 1 when some are, 2 when a file cannot be read (a mask
 * byte other than 0 and 255 included), a
 * tolerance is not a finite number >= 0, or the two carry no verdict:
 * RELATIVE * PEAK + ABSOLUTE is not below PEAK / 2, PEAK the largest
 * |exact| of the compared pixels, so that a picture of half the light
 * (or black) would pass (spec/verify.md [VERIFY-UNBOUNDED-3]), or ABSOLUTE
 * is more than PEAK / 16384, so that black would pass wherever the exact
 * image is dimmer than it ([VERIFY-UNBOUNDED-4]).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct picture {
    long width, height;
    float *rgb;         /* 3 per pixel, rows from the top */
} picture;

static int is_white(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* A PFM header token as refray reads one ([KIT-PFM-1]): white space and
 * '#' comments (to the end of the line) skipped, then the non-white bytes,
 * the white byte after them consumed.  A token that does not fit size - 1
 * bytes is refused, not cut: refray refuses it, and a cut token could read
 * as another number. */
static int token(FILE *f, char *buf, size_t size)
{
    int c = fgetc(f);
    for (;;) {
        while (is_white(c))
            c = fgetc(f);
        if (c != '#')
            break;
        while (c != EOF && c != '\n')
            c = fgetc(f);
    }
    size_t n = 0;
    for (; c != EOF && !is_white(c); c = fgetc(f)) {
        if (n + 1 >= size)
            return 0;
        buf[n++] = (char)c;
    }
    buf[n] = '\0';
    return n > 0;
}

/* A width or height: the whole token a decimal number in [1, INT_MAX]. */
static long dimension(const char *s)
{
    char *end;
    long v = strtol(s, &end, 10);
    return end != s && *end == '\0' && v >= 1 && v <= 2147483647L ? v : -1;
}

static int little_endian_host(void)
{
    unsigned one = 1;
    unsigned char first;
    memcpy(&first, &one, 1);
    return first == 1;
}

/* PFM's pixel data are the file's last bytes: between the header's last
 * token with its separator and them there may be only the LF of a CR LF
 * (the separator read was the CR: a header from a writer in text mode),
 * else the file's size does not fit its header and it is refused, never
 * read some bytes off (a white-space byte first in the pixels must not
 * pass for a separator).  A stream that cannot seek is read as it comes. */
static int seek_raster(FILE *f, size_t raster)
{
    long here = ftell(f), end;
    if (here < 0 || fseek(f, 0, SEEK_END) != 0 || (end = ftell(f)) < 0) {
        clearerr(f);
        return here < 0 || fseek(f, here, SEEK_SET) == 0;
    }
    if (end < here || (size_t)(end - here) < raster)
        return 0;
    size_t extra = (size_t)(end - here) - raster;
    if (extra == 0)
        return fseek(f, here, SEEK_SET) == 0;
    return extra == 1 && here > 0 && fseek(f, here - 1, SEEK_SET) == 0 && fgetc(f) == '\r' && fgetc(f) == '\n';
}

/* PF (colour) or Pf (grey) of either byte order; PFM stores rows from the
 * bottom, so they are turned over here. */
static int read_pfm(const char *path, picture *p)
{
    /* refray's token sizes: a longer token is refused by both. */
    char kind[4], w[24], h[24], scale[64], *end = scale;
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    int ok = token(f, kind, sizeof kind) && (strcmp(kind, "PF") == 0 || strcmp(kind, "Pf") == 0) &&
             token(f, w, sizeof w) && token(f, h, sizeof h) && token(f, scale, sizeof scale);
    /* The scale as refray reads it ([KIT-PFM-1]): a finite non-zero
     * number, the token read whole; its sign is the byte order. */
    double sc = ok ? strtod(scale, &end) : 0;
    ok = ok && sc != 0 && isfinite(sc) && *end == '\0';
    p->width = ok ? dimension(w) : -1;
    p->height = ok ? dimension(h) : -1;
    /* At most 2^26 pixels, refray's default --max-pixels: a 65536 x 65536
     * header on a short file must not wrap a 32-bit size_t or ask for
     * 51 GB before the file is found short. */
    if (p->width < 1 || p->height < 1 || p->width > (64L * 1024 * 1024) / p->height) {
        fclose(f);
        return 0;
    }
    int channels = kind[1] == 'F' ? 3 : 1;
    int swap = (sc < 0) != little_endian_host();
    size_t pixels = (size_t)p->width * (size_t)p->height;
    if (!seek_raster(f, 4 * (size_t)channels * pixels)) {
        fclose(f);
        return 0;
    }
    p->rgb = malloc(3 * pixels * sizeof *p->rgb);
    for (long row = p->height - 1; p->rgb && row >= 0; row--) {
        for (long x = 0; x < p->width; x++) {
            float v[3];
            for (int c = 0; c < channels; c++) {
                unsigned char b[4];
                if (fread(b, 1, 4, f) != 4) {
                    fclose(f);
                    free(p->rgb);
                    return 0;
                }
                if (swap) {
                    unsigned char t = b[0];
                    b[0] = b[3], b[3] = t, t = b[1], b[1] = b[2], b[2] = t;
                }
                memcpy(&v[c], b, 4);
            }
            for (int c = 0; c < 3; c++)
                p->rgb[3 * ((size_t)row * (size_t)p->width + (size_t)x) + (size_t)c] = v[channels == 3 ? c : 0];
        }
    }
    fclose(f);
    return p->rgb != NULL;
}

/* One whole number of the mask's header as refray reads it (verify.c's
 * pgm_number): space, tab, CR and LF and '#' comments before it, at most
 * the digits that keep it under 10^9, and one of those four white bytes
 * after it, consumed. */
static int pgm_number(FILE *f, long *out)
{
    int c = fgetc(f);
    for (;;) {
        if (c == '#')
            while (c != '\n' && c != EOF)
                c = fgetc(f);
        else if (c == ' ' || c == '\t' || c == '\n' || c == '\r')
            c = fgetc(f);
        else
            break;
    }
    long v = 0;
    int digits = 0;
    for (; c >= '0' && c <= '9' && v < 100000000; c = fgetc(f), digits++)
        v = 10 * v + (c - '0');
    *out = v;
    return digits > 0 && (c == ' ' || c == '\t' || c == '\n' || c == '\r');
}

/* The kit's mask: a binary PGM of the image's size whose bytes are 0 (the
 * pixel is judged) or maxval (255: skipped), nothing between, so that no
 * reader can take a grey byte another way (spec/verify.md
 * [VERIFY-MASK-1]); "P5" its first two bytes.  NULL with *why set when
 * it is not. */
static unsigned char *read_pgm(const char *path, long width, long height, const char **why)
{
    FILE *f = fopen(path, "rb");
    *why = "cannot be opened";
    if (!f)
        return NULL;
    unsigned char *mask = NULL;
    long w = 0, h = 0, top = 0;
    *why = "is not a binary PGM of the image's size";
    if (fgetc(f) == 'P' && fgetc(f) == '5' && pgm_number(f, &w) && pgm_number(f, &h) && pgm_number(f, &top) &&
        w == width && h == height && top >= 1 && top < 256) {
        size_t n = (size_t)width * (size_t)height;
        mask = malloc(n);
        if (mask && fread(mask, 1, n, f) != n) {
            free(mask);
            mask = NULL;
        }
        for (size_t p = 0; mask && p < n; p++)
            if (mask[p] != 0 && mask[p] != top) {
                *why = "holds a byte other than 0 and its maxval (255): a mask is black or white only";
                free(mask);
                mask = NULL;
            }
    }
    fclose(f);
    return mask;
}

/* A tolerance: the whole argument a finite number >= 0.  An infinite one
 * would pass any finite picture, and a misspelt one read as 0 would fail
 * every pixel for no reason the user could see. */
static int tolerance(const char *arg, double *out)
{
    char *end;
    *out = strtod(arg, &end);
    return end != arg && *end == '\0' && *out >= 0 && *out <= 1e300;
}

int main(int argc, char **argv)
{
    picture exact, mine;
    if (argc != 6) {
        fputs("usage: kit_check EXACT.pfm MASK.pgm RELATIVE ABSOLUTE MINE.pfm\n", stderr);
        return 2;
    }
    double rel, abs_tol;
    if (!tolerance(argv[3], &rel) || !tolerance(argv[4], &abs_tol)) {
        fprintf(stderr, "kit_check: RELATIVE and ABSOLUTE must be finite numbers >= 0, not '%s' '%s'\n", argv[3],
                argv[4]);
        return 2;
    }
    int have_exact = read_pfm(argv[1], &exact);
    if (!have_exact || !read_pfm(argv[5], &mine)) {
        if (have_exact)
            free(exact.rgb);
        fprintf(stderr, "kit_check: cannot read %s or %s as PFM\n", argv[1], argv[5]);
        return 2;
    }
    if (mine.width != exact.width || mine.height != exact.height) {
        printf("the image is %ldx%ld, the exact image %ldx%ld\n", mine.width, mine.height, exact.width,
               exact.height);
        free(exact.rgb);
        free(mine.rgb);
        return 1;
    }
    const char *why;
    unsigned char *mask = read_pgm(argv[2], exact.width, exact.height, &why);
    if (!mask) {
        fprintf(stderr, "kit_check: %s %s (%ldx%ld)\n", argv[2], why, exact.width, exact.height);
        free(exact.rgb);
        free(mine.rgb);
        return 2;
    }
    /* A picture of half the light errs by exact / 2: it must fail at the
     * peak, where that is largest. */
    double peak = 0;
    for (size_t p = 0; p < (size_t)exact.width * (size_t)exact.height; p++)
        for (int c = 0; c < 3 && !mask[p]; c++)
            peak = fmax(peak, fabs(exact.rgb[3 * p + (size_t)c]));
    int status = 0;
    if (!(rel * peak + abs_tol < peak / 2)) {
        fprintf(stderr, "kit_check: RELATIVE %g and ABSOLUTE %g pass a picture of half the light of the exact "
                "image (its peak is %g): no verdict\n", rel, abs_tol, peak);
        status = 2;
    } else if (!(abs_tol <= peak / 16384)) {
        /* An ABSOLUTE checked at the peak alone passes black wherever the
         * exact image is dimmer than it (spec/verify.md
         * [VERIFY-UNBOUNDED-4]); the kit's own is below 2^-14 of the peak. */
        fprintf(stderr, "kit_check: ABSOLUTE %g passes black wherever the exact image is dimmer than that: it "
                "must be at most 2^-14 of its peak %g\n", abs_tol, peak);
        status = 2;
    }
    if (status) {
        free(mask);
        free(exact.rgb);
        free(mine.rgb);
        return 2;
    }
    long over = 0, compared = 0;
    for (size_t p = 0; p < (size_t)exact.width * (size_t)exact.height; p++) {
        if (mask[p])
            continue;
        compared++;
        int bad = 0;
        for (int c = 0; c < 3; c++) {
            double e = exact.rgb[3 * p + (size_t)c], m = mine.rgb[3 * p + (size_t)c];
            /* "not <=" so that a NaN fails too */
            bad |= !(fabs(m - e) <= rel * fabs(e) + abs_tol);
        }
        over += bad;
    }
    printf("%ld of %ld pixels over\n", over, compared);
    free(mask);
    free(exact.rgb);
    free(mine.rgb);
    return over == 0 && compared > 0 ? 0 : 1;
}
