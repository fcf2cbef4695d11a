/* polyjudge.c - renders each OBJ file given (one face, z = 0, corners
 * inside [-1, 5]^2) through tests/attack14/poly.scene's setting (ambient
 * 0.5 x Kd 1, background 0, orthographic 64 x 64 over [-1, 5]^2), and
 * judges each pixel by the even-odd rule at its centre: 0.5 inside, 0
 * outside (a bridge walked both ways cancels, so a keyhole's hole is out).
 *
 *   polyjudge REFRAY DIR FILE.obj...
 *
 * Prints the wrong pixels of each file; exit 1 when one has any. */
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

static int read_face(const char *path)
{
    static double vx[MAXC], vy[MAXC];
    FILE *f = fopen(path, "r");
    char line[64];
    int nv = 0, n = 0, c;
    if (!f)
        return -1;
    while (fscanf(f, "%63s", line) == 1) {
        if (strcmp(line, "v") == 0 && nv < MAXC) {
            double z;
            if (fscanf(f, "%lf %lf %lf", &vx[nv], &vy[nv], &z) != 3)
                break;
            nv++;
        } else if (strcmp(line, "f") == 0) {
            int k;
            while (n < MAXC && fscanf(f, "%d", &k) == 1) {
                x[n] = vx[k - 1], y[n] = vy[k - 1], n++;
                while ((c = fgetc(f)) != EOF && c != ' ' && c != '\n' && c != '\t')
                    ;
            }
        } else
            while ((c = fgetc(f)) != EOF && c != '\n')
                ;
    }
    fclose(f);
    return n;
}

int main(int argc, char **argv)
{
    static float px[3 * W * W];
    int bad = 0;
    if (argc < 4)
        return 2;
    for (int a = 3; a < argc; a++) {
        char scn[4096], pfm[4096], cmd[16384];
        int n = read_face(argv[a]), wrong = 0, w, h;
        double s;
        snprintf(scn, sizeof scn, "%s/j.scene", argv[2]);
        snprintf(pfm, sizeof pfm, "%s/j.pfm", argv[2]);
        FILE *o = fopen(scn, "w");
        fprintf(o, "image { width 64 height 64 samples 1 background [0, 0, 0] }\n"
                   "camera { orthographic eye [2, 2, 10] look_at [2, 2, 0] up [0, 1, 0] width 6 }\n"
                   "ambient { color [0.5, 0.5, 0.5] }\nmaterial m { Kd 1 Ks 0 }\n"
                   "mesh { file \"%s\" material m }\n", argv[a]);
        fclose(o);
        remove(pfm);
        snprintf(cmd, sizeof cmd, "'%s' render '%s' -q --allow-read / -o '%s'", argv[1], scn, pfm);
        FILE *f = system(cmd) == 0 ? fopen(pfm, "rb") : NULL;
        if (n < 3 || !f || fscanf(f, "PF %d %d %lf", &w, &h, &s) != 3 || w != W || h != W || fgetc(f) == EOF ||
            fread(px, sizeof(float), 3 * W * W, f) != 3 * W * W) {
            printf("%s: refray failed or no face\n", argv[a]);
            bad = 1;
            if (f)
                fclose(f);
            continue;
        }
        fclose(f);
        for (int j = 0; j < W; j++)
            for (int i = 0; i < W; i++) {
                double cx = -1 + (i + 0.5) * 6.0 / W, cy = 5 - (j + 0.5) * 6.0 / W;
                float want = inside(n, cx, cy) ? 0.5f : 0.0f;
                wrong += px[3 * ((W - 1 - j) * W + i)] != want;
            }
        printf("%s: %d corners, %d pixels wrong\n", argv[a], n, wrong);
        bad |= wrong != 0;
    }
    return bad;
}
