/* api_write_cancel.c - rf_image_write cancelled at its 1st, 2nd, ... poll,
 * for every format.  refray.h: "non-zero stops the write with
 * RF_ERR_CANCELLED, and nothing is left at the path"; a file that was there
 * before stays as it was (atomic write).  Checked: the status, the old
 * file's bytes, and no temporary left in the directory.
 * usage: api_write_cancel DIR    (an empty directory)
 * Exit 1 on a breach, 0 when all hold. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <string.h>
#include <refray.h>

struct stop { int calls, at; };

static int cancel(void *user)
{
    struct stop *s = user;
    return ++s->calls == s->at;
}

static int entries(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL)
        n += e->d_name[0] != '.' || (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0);
    if (d)
        closedir(d);
    return n;
}

int main(int argc, char **argv)
{
    if (argc != 2)
        return 2;
    rf_image *img;
    if (rf_image_create(300, 200, NULL, &img) != RF_OK)
        return 2;
    double *p = rf_image_pixels(img);
    for (int i = 0; i < 300 * 200 * 3; i++)
        p[i] = (i % 97) / 50.0;
    static const char *ext[] = {"png", "exr", "pfm", "ppm"};
    int bad = 0;
    for (int f = 0; f < 4; f++) {
        char path[4096];
        snprintf(path, sizeof path, "%s/out.%s", argv[1], ext[f]);
        FILE *old = fopen(path, "w");
        fputs("old", old);
        fclose(old);
        for (int at = 1; at <= 400; at++) {
            struct stop s = {0, at};
            rf_write_options o;
            rf_write_options_init(&o);
            o.cancel = cancel;
            o.user = &s;
            char msg[256] = "";
            rf_status st = rf_image_write(img, path, &o, NULL, msg, sizeof msg);
            char got[8] = "";
            FILE *fp = fopen(path, "r");
            size_t n = fp ? fread(got, 1, sizeof got - 1, fp) : 0;
            got[n] = 0;
            if (fp)
                fclose(fp);
            int left = entries(argv[1]);
            if (st == RF_OK) {
                printf("%s: written at the %d-th poll (%d polls in a whole write)\n", ext[f], at, s.calls);
                break;
            }
            if (st != RF_ERR_CANCELLED || strcmp(got, "old") != 0 || left != 1) {
                printf("%s: cancelled at poll %d: %s (%s), old file %s, %d entries in the directory\n", ext[f], at,
                       rf_status_string(st), msg, strcmp(got, "old") == 0 ? "kept" : "changed", left);
                bad = 1;
                break;
            }
        }
        remove(path);
    }
    rf_image_free(img);
    return bad;
}
