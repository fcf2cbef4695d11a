/* pfmvar.c - how many floats of a PFM differ from its first (diff_render.sh). */
#include <stdio.h>
#include <string.h>
/* prints how many floats of a PFM differ from the first one (0: a flat image) */
int main(int c, char **v) { FILE *f = fopen(v[1], "rb"); if (!f) return 1; char l[64]; int n = 0, w, h;
  while (n < 3 && fgets(l, sizeof l, f)) { if (n == 1) sscanf(l, "%d %d", &w, &h); n++; }
  float first, x; long d = 0; if (fread(&first, 4, 1, f) != 1) return 1;
  while (fread(&x, 4, 1, f) == 1) d += memcmp(&x, &first, 4) != 0; printf("%ld\n", d); return 0; }
