/*
 * cli_stability.c - `refray stability SCENE` (also reached as `refray
 * verify --stability SCENE`): render SCENE here in double and in the long
 * double twin refray-ld, compare the two images, report where and by how
 * much they differ (spec/numerics.md, "The stability tool").
 *
 * The twin is found by --ld PATH, else $REFRAY_LD, else where `make
 * install` puts it (../libexec/refray/refray-ld from this program), else as
 * refray-ld next to this program (where `make` puts it).  It is run as
 *   refray-ld verify --stability --raw-dump TMP [the same options] SCENE
 * and hands its image back through TMP, a raw dump (stability.h).
 */
#include <errno.h>
#include <limits.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "io/scene_file.h"
#include "cli/cli_args.h"
#include "io/atomic.h"
#include "io/fileio.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"
#include "io/image_io.h"
#include "verify/stability.h"

extern char **environ;

/* The command's entry; cli.c (refray stability) and cli_verify.c (refray
 * verify --stability) declare it where they call it, as cli.c does for
 * cli_export, since cli.h is not this file's. */
int cli_stability(int argc, char **argv);

static const char stability_help[] =
    "usage: refray stability SCENE [OPTIONS]\n"
    "       refray verify --stability SCENE [OPTIONS]\n"
    "Renders SCENE in double and in long double (the twin program refray-ld,\n"
    "built by `make`, installed by `make install`) and reports how much the\n"
    "two pictures differ: the largest absolute and relative difference and\n"
    "where, and how many pixels differ by how much.  Exit status 0 when no pixel differs by more\n"
    "than the threshold, 1 when some does.\n"
    "options:\n"
    "  --threshold REL       relative difference that counts as unstable (1e-9)\n"
    "  --map OUT             write the differences as an image: per pixel and\n"
    "                        channel (17 + log10 rel) / 17, 0 where identical\n"
    "                        (linear; .pfm or .exr keep it exactly)\n"
    "  --ld PATH             the long double program (default: $REFRAY_LD, or\n"
    "                        the installed or built refray-ld)\n"
    "  --width W --height H --samples K --max-depth D --light-samples N\n"
    "  --no-shortcuts        as for `refray render`\n"
    "and -W and the input limits of `refray --help`.\n";

typedef struct stab_args {
    cli_scene_opts scene;
    render_opts render;
    const char *input, *map, *ld, *raw_dump;
    double threshold;
    int argc;
    char **argv;
} stab_args;

/* 1: consumed, 0: error (reported), -1: not an option of this command. */
static int stab_option(void *args, int argc, char **argv, int *i)
{
    stab_args *a = args;
    const char *opt = argv[*i], *v;
    int sized = cli_render_option(&a->render, argc, argv, i);
    if (sized >= 0)
        return sized;
    if (strcmp(opt, "--threshold") == 0)
        return cli_take_value(argc, argv, i, &v) && cli_parse_double(opt, v, &a->threshold);
    if (strcmp(opt, "--map") == 0)
        return cli_take_value(argc, argv, i, &a->map);
    if (strcmp(opt, "--ld") == 0)
        return cli_take_value(argc, argv, i, &a->ld);
    if (strcmp(opt, "--raw-dump") == 0)
        return cli_take_value(argc, argv, i, &a->raw_dump);
    if (strcmp(opt, "--stability") == 0 || strcmp(opt, "-q") == 0 || strcmp(opt, "--quiet") == 0)
        return 1;
    return -1;
}

/* 0: go on; -1: help printed; else the usage exit code. */
static int parse_args(stab_args *a, int argc, char **argv)
{
    int status = cli_parse_one_scene("stability", stability_help, argc, argv, &a->scene, &a->input, stab_option, a);
    if (status != 0)
        return status;
    if ((status = cli_check_render_sizes(&a->render, &a->scene.limits)) != 0)
        return status;
    if (!(a->threshold > 0))
        return cli_usage_error("stability: --threshold must be > 0");
    return 0;
}

/* The twin's path into buf: --ld, $REFRAY_LD, or where the build and
 * `make install` put it: LIBEXEC_TWIN relative to this program (an
 * installed refray), else refray-ld beside it (the build directory).
 * -1 when even the candidates cannot be named. */
#define LIBEXEC_TWIN "../libexec/refray/refray-ld"
static int find_twin(const stab_args *a, char *buf, size_t len)
{
    const char *env = getenv("REFRAY_LD");
    if (a->ld || (env && *env)) {
        snprintf(buf, len, "%s", a->ld ? a->ld : env);
        return 0;
    }
    char self[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0)
        return -1;
    self[n] = '\0';
    char *slash = strrchr(self, '/');
    int dir = slash ? (int)(slash - self) + 1 : 0;
    if ((size_t)snprintf(buf, len, "%.*s%s", dir, self, LIBEXEC_TWIN) < len && access(buf, X_OK) == 0)
        return 0;
    return (size_t)snprintf(buf, len, "%.*srefray-ld", dir, self) < len ? 0 : -1;
}

/* The twin's argv: verify --stability --raw-dump TMP, then ours without
 * the options only this side uses. */
static char **twin_argv(const stab_args *a, const char *twin, const char *tmp)
{
    char **v = calloc((size_t)a->argc + 6, sizeof *v);
    int n = 0;
    if (!v)
        return NULL;
    v[n++] = (char *)twin;
    v[n++] = (char *)"verify";
    v[n++] = (char *)"--stability";
    v[n++] = (char *)"--raw-dump";
    v[n++] = (char *)tmp;
    for (int i = 1; i < a->argc; i++) {
        const char *s = a->argv[i];
        if (strcmp(s, "--map") == 0 || strcmp(s, "--ld") == 0 || strcmp(s, "--threshold") == 0) {
            i++;
            continue;
        }
        if (strcmp(s, "--stability") != 0)
            v[n++] = a->argv[i];
    }
    v[n++] = (char *)"-W";
    return v;
}

/* Runs the twin; its image comes back through a temporary file. */
static int run_twin(const stab_args *a, stab_image *out)
{
    char twin[PATH_MAX], tmp[] = "/tmp/refray-stability-XXXXXX", err[128];
    /* A missing helper is missing input (66), not an internal error. */
    if (find_twin(a, twin, sizeof twin) != 0 || access(twin, X_OK) != 0) {
        cli_error("the long double program '%s' is missing (`make` builds it, `make install` installs it); "
                  "or name it with --ld", twin);
        return STATUS_NO_INPUT;
    }
    int fd = mkstemp(tmp);
    if (fd < 0) {
        cli_error("cannot create a temporary file: %s", strerror(errno));
        return STATUS_IO;
    }
    close(fd);
    char **argv = twin_argv(a, twin, tmp);
    pid_t pid;
    int wstatus = 0, status = STATUS_INTERNAL;
    if (argv && posix_spawn(&pid, twin, NULL, NULL, argv, environ) == 0 && waitpid(pid, &wstatus, 0) == pid) {
        if (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0) {
            char why[512];
            FILE *f = file_fopen_read(tmp, &status, why, sizeof why);
            status = f && stability_read_raw(f, out, err, sizeof err) == 0 ? STATUS_OK : STATUS_INTERNAL;
            if (status != STATUS_OK)
                cli_error("reading the long double image: %s", f ? err : why);
            if (f)
                fclose(f);
        } else {
            cli_error("the long double program failed (%s %d)",
                    WIFEXITED(wstatus) ? "exit status" : "signal",
                    WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : WTERMSIG(wstatus));
            status = WIFEXITED(wstatus) && WEXITSTATUS(wstatus) != 0 ? status_from_exit_code(WEXITSTATUS(wstatus)) : STATUS_INTERNAL;
        }
    } else {
        cli_error("cannot run '%s'", twin);
    }
    free(argv);
    unlink(tmp);
    return status;
}

/* The private half: render in this build's precision, dump raw. */
static int fill_raw(FILE *f, void *img)
{
    return stability_write_raw(f, img) == 0 ? STATUS_OK : STATUS_IO;
}

static int dump_raw(const stab_args *a, const scene_model *scene)
{
    stab_image img;
    char why[1024];
    int status = stability_render(scene, &a->render, &img);
    if (status != STATUS_OK)
        return status;
    status = file_write_atomic(a->raw_dump, fill_raw, &img, why, sizeof why);
    stability_free(&img);
    if (status != STATUS_OK)
        cli_error("%s", why);
    return status;
}

static void print_report(const stab_args *a, const stab_image *d, const stab_image *ld, const stab_report *r)
{
    static const char *const bands[STAB_BANDS] = {"identical", "below 1e-15", "1e-15 .. 1e-12",
                                                  "1e-12 .. 1e-9", "1e-9 .. 1e-6", "1e-6 and more"};
    printf("stability: %s, %dx%d pixels, double against long double (%d-bit significand)\n", a->input, d->width,
           d->height, LDBL_MANT_DIG);
    if (r->rel_x < 0)
        printf("  the two images are identical\n");
    else
        printf("  largest difference: %.3Lg absolute at (%d, %d); %.3Lg relative at (%d, %d)\n", r->max_abs,
               r->abs_x, r->abs_y, r->max_rel, r->rel_x, r->rel_y);
    printf("  pixels by their largest relative difference:\n");
    for (int b = 0; b < STAB_BANDS; b++)
        printf("    %-16s %ld\n", bands[b], r->band[b]);
    printf("  pixels beyond %g: %ld of %ld: %s\n", a->threshold, r->beyond, r->pixels,
           r->beyond ? "UNSTABLE" : "stable");
    printf("  non-finite values: %ld in double, %ld in long double\n", d->nonfinite, ld->nonfinite);
}

static int write_map(const char *path, const img_buf *map)
{
    img_write_opts o = img_write_opts_default();
    char err[512];
    o.linear_png = 1;
    if (img_write(path, map, &o, err, sizeof err) != 0) {
        cli_error("%s", err);
        return STATUS_IO;
    }
    return STATUS_OK;
}

static int compare(const stab_args *a, const scene_model *scene)
{
    stab_image d, ld;
    stab_report r;
    img_buf map = {0};
    int status = stability_render(scene, &a->render, &d);
    if (status != STATUS_OK)
        return status;
    if ((status = run_twin(a, &ld)) != STATUS_OK) {
        stability_free(&d);
        return status;
    }
    if (stability_compare(&d, &ld, a->threshold, &r, a->map ? &map : NULL) != 0) {
        cli_error("the two renders differ in size, or out of memory");
        status = STATUS_INTERNAL;
    } else {
        print_report(a, &d, &ld, &r);
        status = a->map ? write_map(a->map, &map) : STATUS_OK;
        if (status == STATUS_OK && (r.beyond > 0 || d.nonfinite > 0 || ld.nonfinite > 0))
            status = STATUS_FAIL;
    }
    if (a->map)
        img_free(&map);
    stability_free(&d);
    stability_free(&ld);
    return status;
}

int cli_stability(int argc, char **argv)
{
    stab_args a;
    memset(&a, 0, sizeof a);
    cli_scene_opts_init(&a.scene);
    a.threshold = 1e-9;
    a.argc = argc;
    a.argv = argv;
    int status = parse_args(&a, argc, argv);
    if (status != 0)
        return status < 0 ? STATUS_OK : status;
    a.render.max_tree_rays = a.scene.limits.max_ray_tree;
    if (!a.raw_dump && sizeof(real) > sizeof(double))
        return cli_usage_error("stability: this is the long double program; run refray, the double one");
    cli_signal_cooperate(1);
    a.render.cancel = cli_signal_cancel;
    scene_model *scene = cli_load_scene(&a.scene, a.input, &status);
    if (!scene)
        return status;
    status = a.raw_dump ? dump_raw(&a, scene) : compare(&a, scene);
    if (status == STATUS_DATA)
        cli_error("a ray tree passed --max-ray-tree %ld; nothing compared",
                a.scene.limits.max_ray_tree);
    scene_free(scene);
    return status;
}
