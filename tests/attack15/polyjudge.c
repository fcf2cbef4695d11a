/* polyjudge.c - judges refray's picture of one OBJ face (z = 0, corners
 * inside [-1, 5]^2) rendered through tests/attack14/poly.scene (ambient
 * 0.5 x Kd 1, background 0, orthographic 64 x 64 over [-1, 5]^2): each
 * pixel must be 0.5 where its centre is inside the face by the even-odd
 * rule (a bridge walked both ways cancels, so a keyhole's hole is out), 0
 * elsewhere.
 *
 *   polyjudge FACE.obj PICTURE.pfm
 *
 * Prints the count of wrong pixels; exit 1 when there is one, 2 when a file
 * cannot be read. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 64, MAXC = 200000 };

static double x[MAXC], y[MAXC];

static int inside(int n, double px, double py)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((y[i] > py) != (y[j] > py) && px < (x[j] - x[i]) * (py - y[i]) / (y[j] - y[i]) + x[i])
            in = !in;
    return in;
}

/* The corners of the file's face, in order, into x and y; their count. */
static int read_face(const char *path)
{
    static double vx[MAXC], vy[MAXC];
    FILE *f = fopen(path, "r");
    char word[64];
    int nv = 0, n = 0, c;
    if (!f)
        return -1;
    while (fscanf(f, "%63s", word) == 1) {
        double z;
        if (strcmp(word, "v") == 0 && nv < MAXC && fscanf(f, "%lf %lf %lf", &vx[nv], &vy[nv], &z) == 3) {
            nv++;
            continue;
        }
        if (strcmp(word, "f") == 0) {
            int k;
            while (n < MAXC && fscanf(f, "%d", &k) == 1 && k >= 1 && k <= nv) {
                x[n] = vx[k - 1], y[n] = vy[k - 1], n++;
                while ((c = fgetc(f)) != EOF && c != ' ' && c != '\n' && c != '\t')
                    ; /* a texture or normal index */
            }
            continue;
        }
        while ((c = fgetc(f)) != EOF && c != '\n')
            ;
    }
    fclose(f);
    return n;
}

int main(int argc, char **argv)
{
    static float px[3 * W * W];
    int w, h, n, wrong = 0;
    double scale;
    FILE *f;
    if (argc != 3 || (n = read_face(argv[1])) < 3 || !(f = fopen(argv[2], "rb")))
        return 2;
    int ok = fscanf(f, "PF %d %d %lf", &w, &h, &scale) == 3 && w == W && h == W && fgetc(f) != EOF &&
             fread(px, sizeof(float), 3 * W * W, f) == 3 * W * W;
    fclose(f);
    if (!ok)
        return 2;
    for (int j = 0; j < W; j++)
        for (int i = 0; i < W; i++) {
            /* PFM rows run from the bottom */
            double cx = -1 + (i + 0.5) * 6.0 / W, cy = 5 - (j + 0.5) * 6.0 / W;
            wrong += px[3 * ((W - 1 - j) * W + i)] != (inside(n, cx, cy) ? 0.5f : 0.0f);
        }
    printf("%d corners, %d pixels wrong\n", n, wrong);
    return wrong != 0;
}
