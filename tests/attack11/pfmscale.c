/* pfmscale IN OUT K: writes the PFM IN with every value times K (a
 * "renderer" whose image is K times refray's).  Colour PFM ("PF") only. */
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 4)
        return 2;
    FILE *in = fopen(argv[1], "rb"), *out = fopen(argv[2], "wb");
    int w, h;
    double scale;
    float k = (float)atof(argv[3]), v;
    if (!in || !out || fscanf(in, "PF %d %d %lf", &w, &h, &scale) != 3 || fgetc(in) == EOF)
        return 2;
    fprintf(out, "PF\n%d %d\n%g\n", w, h, scale);
    for (long i = 0; i < 3L * w * h; i++) {
        if (fread(&v, sizeof v, 1, in) != 1)
            return 2;
        v *= k;
        fwrite(&v, sizeof v, 1, out);
    }
    return fclose(out) != 0;
}
