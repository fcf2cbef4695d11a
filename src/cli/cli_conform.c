/*
 * cli_conform.c - `refray conform --cmd CMD`: another renderer run over a
 * conformance kit, every picture checked (verify/conform.h,
 * spec/conformance.md).
 *
 * The renderers run in their own process groups, so Ctrl-C reaches only
 * refray; its signal flag (cli_signal.h) stops the run, which kills the
 * renderer's group, and nothing half done is written.  The library sees
 * only a pointer to the flag.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "io/fileio.h"
#include "io/filewrite.h"
#include "base/suggest.h"
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"
#include "io/image_io.h"
#include "verify/conform_report.h"

static const char conform_help[] =
    "usage: refray conform --cmd 'CMD' [OPTIONS]\n"
    "Runs another renderer over a conformance kit (`refray kit`, `make kit`): CMD once\n"
    "per scene through /bin/sh -c, in a fresh directory, then checks the image it wrote\n"
    "against the exact image under the manifest's tolerance and mask.\n"
    "placeholders in CMD (replaced by shell-quoted values: do not quote them again):\n"
    "  {scene} {json} {pov}  the kit's scene files (absolute paths)\n"
    "  {out}                 where to write the image (.exr, .pfm or .png by --format)\n"
    "  {width} {height}      the size to write: the exact image's times --downsample\n"
    "  {samples}             k: the k x k sample points of a pixel\n"
    "  {name} {scale}        the scene's name; its png16_scale\n"
    "options:\n"
    "  --kit DIR             the kit (default build/kit)\n"
    "  --format exr|pfm|png  the format CMD writes (default exr; png: 16-bit, linear)\n"
    "  --timeout SECONDS     per scene (default 60); the process group is then killed\n"
    "  --downsample K        average K x K blocks first; 'manifest': each scene's samples\n"
    "  --scale S             multiply the image by S; 'manifest': by 1 / png16_scale\n"
    "  --only NAME...        only these scenes (names, or NAME,NAME)\n"
    "  --json                one JSON object on stdout instead of the table\n"
    "  --tap                 TAP version 13 on stdout instead of the table\n"
    "  --junit FILE          also write JUnit XML (atomically)\n"
    "  --markdown FILE       also write the table as Markdown (atomically)\n"
    "  --keep                keep each scene's working directory (printed)\n"
    "exit: 0 every scene passed; 1 some failed; 64 usage; 65 a malformed manifest, or\n"
    "one its kit contradicts; 66 no kit, or a file of it missing; 74 a report or working\n"
    "directory could not be written; 130 stopped.\n";

typedef struct conform_args {
    const char *kit, *cmd, *format, *junit, *markdown;
    conform_adjust adjust;
    double timeout;
    int json, tap, keep;
    const char **only;
    int only_count;
} conform_args;

/* --only takes the arguments up to the next option, each NAME or NAME,NAME. */
static int only_value(conform_args *a, int argc, char **argv, int *i)
{
    int start = a->only_count;
    while (*i + 1 < argc && argv[*i + 1][0] != '-') {
        char *list = argv[++*i];
        for (char *name = strtok(list, ","); name; name = strtok(NULL, ","))
            a->only[a->only_count++] = name;
    }
    if (a->only_count > start)
        return 1;
    cli_usage_error("--only needs at least one scene name");
    return 0;
}

/* 1 consumed, 0 error reported, -1 not an option of conform. */
static int conform_option(conform_args *a, int argc, char **argv, int *i)
{
    const char *opt = argv[*i], *v;
    if (strcmp(opt, "--cmd") == 0)
        return cli_take_value(argc, argv, i, &a->cmd);
    if (strcmp(opt, "--kit") == 0)
        return cli_take_value(argc, argv, i, &a->kit);
    if (strcmp(opt, "--format") == 0)
        return cli_take_value(argc, argv, i, &a->format);
    if (strcmp(opt, "--junit") == 0)
        return cli_take_value(argc, argv, i, &a->junit);
    if (strcmp(opt, "--markdown") == 0)
        return cli_take_value(argc, argv, i, &a->markdown);
    if (strcmp(opt, "--downsample") == 0 || strcmp(opt, "--scale") == 0)
        return cli_adjust_option(&a->adjust, argc, argv, i);
    if (strcmp(opt, "--only") == 0)
        return only_value(a, argc, argv, i);
    if (strcmp(opt, "--json") == 0)
        return a->json = 1;
    if (strcmp(opt, "--tap") == 0)
        return a->tap = 1;
    if (strcmp(opt, "--keep") == 0)
        return a->keep = 1;
    if (strcmp(opt, "--timeout") != 0)
        return -1;
    if (!cli_take_value(argc, argv, i, &v) || !cli_parse_double(opt, v, &a->timeout))
        return 0;
    if (a->timeout > 0 && a->timeout <= 1e6)
        return 1;
    cli_usage_error("--timeout takes seconds, more than 0 and at most 1e6, not '%s'", v);
    return 0;
}

/* The format's extension, checked against this build. */
static int check_format(const conform_args *a)
{
    if (strcmp(a->format, "exr") != 0 && strcmp(a->format, "pfm") != 0 && strcmp(a->format, "png") != 0)
        return cli_usage_error("conform: --format is exr, pfm or png, not '%s'", a->format);
    char probe[8];
    snprintf(probe, sizeof probe, "x.%s", a->format);
    if (!img_format_available(img_format_from_path(probe)))
        return cli_usage_error("conform: this refray cannot read .%s files (built without %s); use --format pfm",
                               a->format, strcmp(a->format, "exr") == 0 ? "OpenEXR" : "libpng");
    return 0;
}

/* Stats the directory part of path (".": none) into st; 0 when it cannot. */
static int dir_stat(const char *path, struct stat *st)
{
    const char *slash = strrchr(path, '/');
    char dir[4096];
    if (!slash)
        return stat(".", st) == 0;
    size_t n = slash == path ? 1 : (size_t)(slash - path);
    if (n >= sizeof dir)
        return 0;
    memcpy(dir, path, n);
    dir[n] = '\0';
    return stat(dir, st) == 0;
}

/* Whether paths p and q name one file: the same existing file, or the
 * same last name in the same directory.  Two reports renamed onto one
 * path would leave only the last. */
static int same_file(const char *p, const char *q)
{
    struct stat a, b;
    if (strcmp(p, q) == 0)
        return 1;
    if (stat(p, &a) == 0 && stat(q, &b) == 0)
        return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
    const char *pn = strrchr(p, '/'), *qn = strrchr(q, '/');
    pn = pn ? pn + 1 : p;
    qn = qn ? qn + 1 : q;
    return strcmp(pn, qn) == 0 && dir_stat(p, &a) && dir_stat(q, &b) && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

/* 0: go on; -1: help printed; else the usage exit code. */
static int parse_args(conform_args *a, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(conform_help, stdout);
            return -1;
        }
        int r = conform_option(a, argc, argv, &i);
        if (r == 0)
            return STATUS_USAGE;
        if (r < 0)
            return cli_usage_error("conform: unknown %s '%s'", argv[i][0] == '-' ? "option" : "argument", argv[i]);
    }
    char why[256];
    if (!a->cmd)
        return cli_usage_error("conform: no renderer given (--cmd 'CMD ... {out}')");
    if (!conform_template_ok(a->cmd, why, sizeof why))
        return cli_usage_error("conform: %s", why);
    if (a->json && a->tap)
        return cli_usage_error("conform: --json and --tap both write stdout: choose one");
    if (a->junit && a->markdown && same_file(a->junit, a->markdown))
        return cli_usage_error("conform: --junit and --markdown name one file, '%s': give each its own", a->markdown);
    return check_format(a);
}

/* The kit's manifest: STATUS_OK, or the status after the message. */
static int load_kit(const conform_args *a, char **kit_dir, manifest *m)
{
    char why[1024];
    if (!manifest_supported(why, sizeof why))
        return cli_usage_error("conform: %s", why);
    char *path = file_join(NULL, a->kit, "manifest.json");
    if (!path || access(path, F_OK) != 0) {
        cli_error("conform: no kit at '%s' (no manifest.json); make one with `make kit` "
                "or `refray kit -o DIR`, and name it with --kit DIR", a->kit);
        free(path);
        return STATUS_NO_INPUT;
    }
    int status = manifest_read(path, m, why, sizeof why);
    free(path);
    if (status != 0) {
        cli_error("conform: %s", why);
        return status;
    }
    /* Absolute, so the renderer may change directory and still find it. */
    *kit_dir = file_absolute(NULL, a->kit);
    if (!*kit_dir) {
        manifest_free(m);
        cli_error("conform: cannot resolve '%s'", a->kit);
        return STATUS_NO_INPUT;
    }
    return 0;
}

/* The scenes to run, in manifest order; an unknown --only name is an error. */
static int select_scenes(const conform_args *a, const manifest *m, const manifest_scene **out, int *count)
{
    const char **names = malloc((size_t)m->scene_count * sizeof *names + 1);
    if (!names)
        return STATUS_NO_MEMORY;
    for (int i = 0; i < m->scene_count; i++)
        names[i] = m->scenes[i].name;
    for (int k = 0; k < a->only_count; k++) {
        if (manifest_find(m, a->only[k]))
            continue;
        const char *near = suggest_nearest(a->only[k], strlen(a->only[k]), names, m->scene_count);
        free(names);
        return cli_usage_error("conform: the kit has no scene '%s'%s%s%s", a->only[k], near ? "; did you mean '" : "",
                               near ? near : "", near ? "'?" : "");
    }
    free(names);
    *count = 0;
    for (int i = 0; i < m->scene_count; i++) {
        int chosen = a->only_count == 0;
        for (int k = 0; k < a->only_count && !chosen; k++)
            chosen = strcmp(a->only[k], m->scenes[i].name) == 0;
        if (chosen)
            out[(*count)++] = &m->scenes[i];
    }
    return 0;
}

/* [KIT-MASK-1] The kit's files of each chosen scene, read and checked
 * against the manifest before any renderer runs: a manifest its kit
 * contradicts is refused (65) as a malformed one is, not found out scene by
 * scene after the renders.  STATUS_OK, or the status after the message. */
static int check_kit(const conform_args *a, const char *kit_dir, const manifest_scene **scenes, int count)
{
    for (int i = 0; i < count; i++) {
        img_buf exact;
        unsigned char *mask;
        char why[1024];
        int status = conform_kit_read(kit_dir, scenes[i], &exact, &mask, why, sizeof why);
        if (status != STATUS_OK) {
            cli_error("conform: %s/manifest.json: scene '%s': %s", a->kit, scenes[i]->name, why);
            return status;
        }
        img_free(&exact);
        free(mask);
    }
    return STATUS_OK;
}

/* The report files, --junit then --markdown: fp NULL when not asked. */
enum { REPORT_FILES = 2 };

/* [CONF-REPORT-3] Each report file's temporary is made beside it before
 * the first render, so a path that cannot be written fails at once, not
 * after every scene has run.  STATUS_OK, or the writer's status after the
 * message (nothing left open). */
static int open_reports(const conform_args *a, file_out out[REPORT_FILES])
{
    const char *paths[REPORT_FILES] = {a->junit, a->markdown};
    memset(out, 0, REPORT_FILES * sizeof *out);
    for (int k = 0; k < REPORT_FILES; k++) {
        char why[600];
        int status = paths[k] ? file_out_open(&out[k], paths[k], NULL, why, sizeof why) : STATUS_OK;
        if (status != STATUS_OK) {
            cli_error("conform: %s", why);
            for (int j = 0; j < k; j++)
                if (out[j].fp)
                    file_out_abort(&out[j]);
            memset(out, 0, REPORT_FILES * sizeof *out);
            return status;
        }
    }
    return STATUS_OK;
}

/* Fills and renames the report files (rep NULL: abandons them, leaving
 * every path as it was).  STATUS_OK or STATUS_IO. */
static int close_reports(file_out out[REPORT_FILES], const conform_report *rep)
{
    int (*const write[REPORT_FILES])(FILE *, const conform_report *) = {conform_junit_write, conform_markdown_write};
    int status = STATUS_OK;
    for (int k = 0; k < REPORT_FILES; k++) {
        char why[600];
        if (!out[k].fp)
            continue;
        if (!rep || status != STATUS_OK || write[k](out[k].fp, rep) != 0) {
            if (rep && status == STATUS_OK)
                cli_error("conform: cannot write '%s': write error", out[k].path);
            file_out_abort(&out[k]);
            status = rep ? STATUS_IO : status;
        } else if (file_out_commit(&out[k], why, sizeof why) != STATUS_OK) {
            cli_error("conform: %s", why);
            status = STATUS_IO;
        }
    }
    return status;
}

/* Runs the scenes, streaming the table or TAP; returns how many ran. */
static int run_all(const conform_args *a, const conform_run *run, const manifest_scene **scenes, int count,
                   conform_result *results)
{
    cli_signal_cooperate(1);
    if (a->tap)
        conform_tap_plan(stdout, count);
    else if (!a->json)
        conform_text_header(stdout);
    int ran = 0;
    for (int i = 0; i < count && !cli_signal_cancel(NULL); i++) {
        conform_run_scene(run, scenes[i], &results[i]);
        ran++;
        if (a->tap)
            conform_tap_row(stdout, i + 1, &results[i]);
        else if (!a->json)
            conform_text_row(stdout, &results[i]);
    }
    return ran;
}

/* STATUS_OK all passed, STATUS_FAIL some failed (exit 1), STATUS_IO (74)
 * when refray itself could not run one. */
static int verdict_status(const conform_report *rep)
{
    int status = 0;
    for (int i = 0; i < rep->count; i++) {
        conform_outcome o = rep->results[i].outcome;
        if (o == CONFORM_ERROR)
            status = STATUS_IO;
        else if (o != CONFORM_PASS && status == 0)
            status = STATUS_FAIL;
    }
    return status;
}

static int run_kit(const conform_args *a, const char *kit_dir, const manifest *m)
{
    const manifest_scene **scenes = calloc((size_t)m->scene_count + 1, sizeof *scenes);
    conform_result *results = calloc((size_t)m->scene_count + 1, sizeof *results);
    int count = 0, status = scenes && results ? select_scenes(a, m, scenes, &count) : STATUS_NO_MEMORY;
    const char *tmp = getenv("TMPDIR");
    file_out reports[REPORT_FILES];
    if (status == 0)
        status = check_kit(a, kit_dir, scenes, count);
    if (status == 0)
        status = open_reports(a, reports);
    else
        memset(reports, 0, sizeof reports);
    conform_run run = {kit_dir, a->cmd, a->format, a->adjust, a->timeout, a->keep,
                       tmp && tmp[0] == '/' ? tmp : "/tmp", cli_signal_flag()};
    double start = render_clock();
    int ran = status == 0 ? run_all(a, &run, scenes, count, results) : 0;
    conform_report rep = {kit_dir, a->cmd, results, ran, render_clock() - start};
    if (status == 0 && count == 0) {
        cli_error("conform: the kit has no scenes: nothing was checked");
        status = STATUS_FAIL;
    } else if (status == 0 && cli_signal_cancel(NULL)) {
        fprintf(stderr, "refray: conform: stopped after %d of %d scenes; no report written\n", ran, count);
        status = STATUS_CANCELLED;
    } else if (status == 0) {
        if (a->json && conform_json_write(stdout, &rep) != 0)
            status = STATUS_IO;
        else if (!a->json && !a->tap)
            conform_text_summary(stdout, &rep);
        if (status == 0)
            status = close_reports(reports, &rep);
        if (status == 0)
            status = verdict_status(&rep);
    }
    close_reports(reports, NULL);
    free(scenes);
    free(results);
    return status;
}

int cli_conform(int argc, char **argv)
{
    conform_args a;
    memset(&a, 0, sizeof a);
    a.kit = "build/kit";
    a.format = "exr";
    a.timeout = 60;
    a.adjust.downsample = 1;
    a.adjust.scale = 1;
    /* --only's names: at most one per argument and comma. */
    size_t names = (size_t)argc + 1;
    for (int i = 0; i < argc; i++)
        for (const char *p = argv[i]; *p; p++)
            names += *p == ',';
    a.only = calloc(names, sizeof *a.only);
    if (!a.only)
        return STATUS_NO_MEMORY;
    int status = parse_args(&a, argc, argv);
    manifest m;
    char *kit_dir = NULL;
    if (status == 0)
        status = load_kit(&a, &kit_dir, &m);
    if (status == 0) {
        status = run_kit(&a, kit_dir, &m);
        manifest_free(&m);
    }
    free(kit_dir);
    free(a.only);
    return status < 0 ? STATUS_OK : status;
}
