/*
 * apex_check.c - the analytic image of cone_apex_subnormal.scene: every
 * camera ray goes down the axis of the cone (radius 1 - y/2 about the y
 * axis) and meets the side next to the apex at azimuth phi of its pixel
 * centre, where the outward normal is (cos phi, 1/2, sin phi)/sqrt(5/4);
 * the value is ambient 0.1 x Kd 0.8 + Kd 0.8 x max(0, n . L), L the unit
 * vector toward the light (-1, 1, -0.5)/1.5.  Prints the largest
 * difference from a rendered 32 x 24 PFM; exit 1 past 1e-6.
 * Build: cc -std=c99 -o /tmp/apex_check tests/attack8/apex_check.c -lm
 */
#include <math.h>
#include <stdio.h>

int main(int argc, char **argv)
{
    FILE *f = argc > 1 ? fopen(argv[1], "rb") : NULL;
    int w, h;
    double scale;
    char kind[3];
    if (!f || fscanf(f, "%2s %d %d %lf", kind, &w, &h, &scale) != 4 || fgetc(f) != '\n' || w != 32 || h != 24)
        return 2;
    double worst = 0, L[3] = {-1 / 1.5, 1 / 1.5, -0.5 / 1.5};
    /* PFM rows run bottom to top, and the camera's up is -z: stored row k
     * (bottom first) is at world z = (1/2 - (k + 1/2)/h) h/w widths,
     * column x at world x = ((x + 1/2)/w - 1/2) widths. */
    for (int row = 0; row < h; row++) {
        for (int x = 0; x < w; x++) {
            float rgb[3];
            if (fread(rgb, sizeof rgb[0], 3, f) != 3)
                return 2;
            double u = (x + 0.5) / w - 0.5, v = (0.5 - (row + 0.5) / h) * h / w;
            double r = hypot(u, v), n[3] = {u / r, 0.5, v / r}, nn = sqrt(1.25);
            double lambert = (n[0] * L[0] + n[1] * L[1] + n[2] * L[2]) / nn;
            double want = 0.08 + 0.8 * (lambert > 0 ? lambert : 0);
            double d = fabs(rgb[0] - want);
            worst = d > worst ? d : worst;
        }
    }
    printf("largest difference from the analytic value: %.3g\n", worst);
    return worst > 1e-6;
}
