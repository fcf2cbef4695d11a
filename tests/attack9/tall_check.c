/*
 * tall_check.c - the analytic image of ortho_tall_glass.scene and
 * ortho_tall_torus.scene (1 x 16384 pixels).  The camera looks down -y from
 * y = s = 2^500; image row y (from the top) starts at z = sy (s/2) h,
 * sy = 1 - 2 (y + 1/2)/h, and meets the floor there head-on.  The light
 * (power E = 1e4, falloff none) is at (0, s, 0), so the floor's value is
 * E (N.L) T with N.L = s / hypot(s, z) and T the shadow's transmission:
 * 1 where z < 0 (nothing between), and for z > 8s t^2 = 0.25 for the
 * glass ball (two crossings), 0 for the opaque torus: there the shadow ray
 * passes within s (3s/4)/z < s/8 of the ball's centre line y = s, z
 * in [s/4, 3s/4], so through the ball (radius s/4 about (0, s, s/2)) and
 * through both sides of the torus's tube (radius s/8 about the circle of
 * radius s/4 about (0, s, s/2) in the plane x = 0).  Rows with z in
 * [0, 8s] are left out.  Prints the rows that differ by more than 1e-4 relative,
 * and how many; exit 1 if any.
 * Build: cc -std=c99 -o /tmp/tall_check tests/attack9/tall_check.c -lm
 * Run:   /tmp/tall_check OUT.pfm glass|torus
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    FILE *f = argc > 2 ? fopen(argv[1], "rb") : NULL;
    int w, h, glass = argc > 2 && strcmp(argv[2], "glass") == 0;
    double scale, s = ldexp(1, 500);
    char kind[3];
    if (!f || fscanf(f, "%2s %d %d %lf", kind, &w, &h, &scale) != 4 || fgetc(f) != '\n' || w != 1)
        return 2;
    int bad = 0, first = -1, last = -1;
    for (int row = 0; row < h; row++) { /* PFM: bottom row first */
        float rgb[3];
        if (fread(rgb, sizeof rgb[0], 3, f) != 3)
            return 2;
        int y = h - 1 - row;
        double sy = 1 - 2 * (y + 0.5) / h, z = sy * (s / 2) * h;
        if (z >= 0 && z <= 8 * s)
            continue;
        double through = z < 0 ? 1 : glass ? 0.25 : 0;
        double want = 1e4 * (s / hypot(s, z)) * through;
        if (fabs(rgb[0] - want) > 1e-4 * (want > 1 ? want : 1)) {
            if (bad++ < 3)
                printf("row %d (z = 2^%.4f): %.6g, expected %.6g\n", y, log2(fabs(z)), rgb[0], want);
            first = first < 0 ? y : first;
            last = y;
        }
    }
    printf("%d rows wrong (image rows %d .. %d from the top)\n", bad, last, first);
    return bad > 0;
}
