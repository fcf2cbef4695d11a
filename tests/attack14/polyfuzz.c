/* polyfuzz.c - random simple polygons as one OBJ face, rendered by refray,
 * each pixel judged by an even-odd point-in-polygon test of its centre.
 *
 *   polyfuzz REFRAY DIR SEED COUNT [EXTRA]    (EXTRA 0: extra corners on edges
 *   only; 1: repeated corners only; 2: star-shaped polygons of 5 to 44 corners,
 *   one in each of n equal sectors, at random radii, instead; default both; POLYFUZZ_REVERSE set:
 *   each face written clockwise)
 *
 * The scene is tests/attack14/poly.scene's (ambient 0.5 x Kd 1, background
 * 0, orthographic, 64 x 64 over [-1, 5]^2): a pixel is 0.5 exactly when its
 * centre is inside the polygon.  The polygons are rectilinear (random
 * columns of random heights over a base, a "skyline", so simple by
 * construction) with corners on a grid of 1/4 that no pixel centre meets;
 * some get extra corners on their edges and repeated corners, which
 * [MESH-POLY-1] and the face rules of spec/language.md 8 accept.  Prints
 * each polygon whose picture has a wrong pixel; exit 1 when one has. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

enum { W = 64, MAXC = 256 };

static unsigned long long rng;
static unsigned rnd(unsigned n)
{
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return (unsigned)(rng >> 33) % n;
}

static int inside(const double *x, const double *y, int n, double px, double py)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((y[i] > py) != (y[j] > py) && px < (x[j] - x[i]) * (py - y[i]) / (y[j] - y[i]) + x[i])
            in = !in;
    return in;
}

static int read_pfm(const char *path, float *px)
{
    FILE *f = fopen(path, "rb");
    int w, h;
    double s;
    if (!f || fscanf(f, "PF %d %d %lf", &w, &h, &s) != 3 || w != W || h != W || fgetc(f) == EOF ||
        fread(px, sizeof(float), 3 * W * W, f) != 3 * W * W) {
        if (f)
            fclose(f);
        return -1;
    }
    fclose(f);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 5 && argc != 6)
        return 2;
    rng = strtoull(argv[3], NULL, 10);
    int count = atoi(argv[4]), failures = 0, mode = argc > 5 ? atoi(argv[5]) : -1;
    char obj[4096], scn[4096], pfm[4096], cmd[16384];
    snprintf(obj, sizeof obj, "%s/p.obj", argv[2]);
    snprintf(scn, sizeof scn, "%s/p.scene", argv[2]);
    snprintf(pfm, sizeof pfm, "%s/p.pfm", argv[2]);
    FILE *s = fopen(scn, "w");
    fprintf(s, "image { width 64 height 64 samples 1 background [0, 0, 0] }\n"
               "camera { orthographic eye [2, 2, 10] look_at [2, 2, 0] up [0, 1, 0] width 6 }\n"
               "ambient { color [0.5, 0.5, 0.5] }\nmaterial m { Kd 1 Ks 0 }\n"
               "mesh { file \"p.obj\" material m }\n");
    fclose(s);
    for (int k = 0; k < count; k++) {
        /* A skyline: columns 0..c-1 of width 4/c, heights h[i] in quarters. */
        double x[MAXC], y[MAXC];
        int n = 0, c = 2 + (int)rnd(7);
        double cw = 4.0 / c;
        x[n] = 0, y[n++] = 0;
        x[n] = 4, y[n++] = 0;
        int h[16];
        for (int i = 0; i < c; i++)
            h[i] = 1 + (int)rnd(16);
        for (int i = c - 1; i >= 0; i--) {
            double hx = (i + 1) * cw, lx = i * cw, hy = h[i] * 0.25;
            if (i == c - 1 || h[i] != h[i + 1])
                x[n] = hx, y[n++] = hy;
            if (i == 0 || h[i] != h[i - 1])
                x[n] = lx, y[n++] = hy;
        }
        /* the column edges at multiples of 4/c: keep them off pixel centres by snapping to quarters */
        for (int i = 0; i < n; i++)
            x[i] = (double)(long)(x[i] * 4 + 0.5) / 4;
        if (mode == 2) {
            /* a star-shaped polygon about (2, 2): corner i at an angle in the i-th of n
             * equal sectors (so no gap reaches pi and the polygon is simple), radius random */
            n = 5 + (int)rnd(40);
            for (int i = 0; i < n; i++) {
                double a = (i + 0.9 * rnd(1000000) / 1000000) * (6.283185307179586 / n);
                double r = 0.2 + rnd(1000000) * (2.6 / 1000000);
                x[i] = 2 + r * cos(a);
                y[i] = 2 + r * sin(a);
            }
        }
        /* extra corners: on an edge (its midpoint, snapped), or a corner repeated */
        int extra = mode == 2 ? 0 : (int)rnd(4);
        for (int e = 0; e < extra && n < MAXC - 2; e++) {
            int at = (int)rnd((unsigned)n), kind = mode < 0 ? (int)rnd(2) : mode, nx = (at + 1) % n;
            double cx = x[at], cy = y[at];
            if (kind == 0) {
                cx = (double)(long)((x[at] + x[nx]) * 2 + 0.5) / 4;
                cy = (double)(long)((y[at] + y[nx]) * 2 + 0.5) / 4;
                /* only a corner strictly inside an edge: snapping may land it on an end */
                if ((cx == x[at] && cy == y[at]) || (cx == x[nx] && cy == y[nx]))
                    continue;
            }
            memmove(x + at + 2, x + at + 1, (size_t)(n - at - 1) * sizeof *x);
            memmove(y + at + 2, y + at + 1, (size_t)(n - at - 1) * sizeof *y);
            x[at + 1] = cx, y[at + 1] = cy;
            n++;
        }
        FILE *o = fopen(obj, "w");
        for (int i = 0; i < n; i++)
            fprintf(o, "v %.17g %.17g 0\n", x[i], y[i]);
        fprintf(o, "f");
        for (int i = 0; i < n; i++)
            fprintf(o, " %d", getenv("POLYFUZZ_REVERSE") ? n - i : i + 1);
        fprintf(o, "\n");
        fclose(o);
        snprintf(cmd, sizeof cmd, "'%s' render '%s' -q -W -o '%s' 2>/dev/null", argv[1], scn, pfm);
        static float px[3 * W * W];
        remove(pfm);
        if (system(cmd) != 0 || read_pfm(pfm, px) != 0) {
            printf("polygon %d: refray failed\n", k);
            failures++;
            continue;
        }
        int wrong = 0;
        for (int j = 0; j < W; j++)
            for (int i = 0; i < W; i++) {
                /* PFM rows run from the bottom */
                double cx = -1 + (i + 0.5) * 6.0 / W, cy = 5 - (j + 0.5) * 6.0 / W;
                float want = inside(x, y, n, cx, cy) ? 0.5f : 0.0f;
                wrong += px[3 * ((W - 1 - j) * W + i)] != want;
            }
        if (wrong) {
            failures++;
            printf("polygon %d (%d corners): %d pixels wrong: f", k, n, wrong);
            for (int i = 0; i < n; i++)
                printf(" (%g %g)", x[i], y[i]);
            printf("\n");
        }
    }
    printf("%d of %d polygons wrong\n", failures, count);
    return failures ? 1 : 0;
}
