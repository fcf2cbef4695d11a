/*
 * check_conform.c - `refray conform` against fake renderers
 * (the scripts in tests/conform/fake/) that crash, hang, exit non-zero, write nothing,
 * garbage, a FIFO, the wrong size or NaN, and that are right (a copy of the exact
 * image; refray itself; a picture rendered twice as large and four times
 * as bright, taken back by --downsample and --scale); each with its verdict
 * and exit code, the reports, the command-line errors, and the expansion
 * of placeholders (spec/conformance.md).  A kit of three small scenes
 * (cli_testlib.h) is built once for the suite.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>
#include "io/fileio.h"
#include "io/filewrite.h"
#include "cli_testlib.h"
#include "io/image_io.h"
#include "verify/conform.h"
#include "verify/verify.h"

#ifndef REFRAY_HAVE_EXR
#define REFRAY_HAVE_EXR 0
#endif

static char kit_root[64];
static int kit_status = -1;

static void kit_setup(void)
{
    kit_status = cli_kit_setup(kit_root, sizeof kit_root);
}

static void kit_teardown(void)
{
    cli_kit_teardown(kit_root);
}

/* Valgrind runs refray and the shell under it: more time there. */
static double slow(void)
{
    const char *v = getenv("REFRAY_TEST_VALGRIND");
    return v && strcmp(v, "1") == 0 ? 20 : 1;
}

#if REFRAY_HAVE_JSON

/* The command line of a fake: absolute, since conform runs it in a fresh
 * directory. */
static const char *fake(char *buf, size_t size, const char *name)
{
    char cwd[256];
    ck_assert_ptr_nonnull(getcwd(cwd, sizeof cwd));
    snprintf(buf, size, "sh %s/tests/conform/fake/%s.sh {scene} {out} {width} {height}", cwd, name);
    return buf;
}

static void conform(cli_run *r, const char *cmd, const char *extra1, const char *extra2)
{
    char kit[128], timeout[32];
    ck_assert_msg(kit_status == 0, "`refray kit` failed (exit %d)", kit_status);
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    snprintf(timeout, sizeof timeout, "%g", 10 * slow());
    const char *args[] = {"conform", "--kit", kit, "--format", "pfm", "--json", "--only", "plane_point_linear",
                          "--timeout", timeout, "--cmd", cmd, extra1, extra2, NULL};
    cli_refray(r, args);
}

/* Asserts the one scene's outcome and that reason holds want. */
static void expect(const cli_run *r, int code, const char *outcome, const char *want)
{
    char pattern[64];
    snprintf(pattern, sizeof pattern, "\"outcome\": \"%s\"", outcome);
    ck_assert_msg(r->code == code, "exit %d, expected %d\nstdout %s\nstderr %s", r->code, code, r->out, r->err);
    ck_assert_msg(strstr(r->out, pattern) != NULL, "no %s in %s", pattern, r->out);
    ck_assert_msg(!want || strstr(r->out, want) != NULL, "no '%s' in %s", want, r->out);
}

/* [CONF-OUTCOME-1] One test per way a renderer can go wrong. */
START_TEST(test_conform_crash)
{
    char cmd[512];
    cli_run *r = malloc(sizeof *r);
    conform(r, fake(cmd, sizeof cmd, "crash"), NULL, NULL);
    expect(r, 1, "crashed", "SIGSEGV");
    ck_assert(strstr(r->out, "fake renderer: about to crash") != NULL); /* its stderr */
    free(r);
}
END_TEST

START_TEST(test_conform_hang)
{
    char cmd[512], kit[128];
    cli_run *r = malloc(sizeof *r);
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    const char *args[] = {"conform", "--kit", kit, "--format", "pfm", "--json", "--only", "plane_point_linear",
                          "--timeout", "0.3", "--cmd", fake(cmd, sizeof cmd, "hang"), NULL};
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    cli_refray(r, args);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    expect(r, 1, "timeout", "--timeout 0.3 s");
    ck_assert(strstr(r->out, "\"timed_out\": true") != NULL);
    ck_assert_msg(s < 10 * slow(), "conform took %g s for a 0.3 s limit", s);
    free(r);
}
END_TEST

START_TEST(test_conform_garbage)
{
    char cmd[512];
    cli_run *r = malloc(sizeof *r);
    conform(r, fake(cmd, sizeof cmd, "garbage"), NULL, NULL);
    expect(r, 1, "unreadable", "not a PFM file");
    free(r);
}
END_TEST

/* A FIFO at {out} would block a reader for ever: it is refused unread. */
START_TEST(test_conform_fifo)
{
    char cmd[512];
    cli_run *r = malloc(sizeof *r);
    conform(r, fake(cmd, sizeof cmd, "fifo"), NULL, NULL);
    expect(r, 1, "unreadable", "not a regular file");
    free(r);
}
END_TEST

START_TEST(test_conform_wrong_size)
{
    char cmd[512];
    cli_run *r = malloc(sizeof *r);
    conform(r, fake(cmd, sizeof cmd, "wrong_size"), NULL, NULL);
    expect(r, 1, "size", "its image is 97x72; expected 96x72");
    free(r);
}
END_TEST

START_TEST(test_conform_nothing)
{
    char cmd[512];
    cli_run *r = malloc(sizeof *r);
    conform(r, fake(cmd, sizeof cmd, "nothing"), NULL, NULL);
    expect(r, 1, "no_output", "wrote nothing at {out} (its directory holds: elsewhere.pfm)");
    free(r);
}
END_TEST

START_TEST(test_conform_nonzero_exit)
{
    char cmd[512];
    cli_run *r = malloc(sizeof *r);
    conform(r, fake(cmd, sizeof cmd, "fail"), NULL, NULL);
    expect(r, 1, "exit", "exited with status 3");
    ck_assert(strstr(r->out, "\"exit_status\": 3") && strstr(r->out, "fake renderer: cannot read /"));
    free(r);
}
END_TEST

START_TEST(test_conform_nan)
{
    char cmd[512];
    cli_run *r = malloc(sizeof *r);
    conform(r, fake(cmd, sizeof cmd, "nan"), NULL, NULL);
    expect(r, 1, "nonfinite", "1 channel value of its image is NaN");
    free(r);
}
END_TEST

/* A relative path to a program is the classic mistake: say why. */
START_TEST(test_conform_command_not_found)
{
    cli_run *r = malloc(sizeof *r);
    conform(r, "no-such-renderer-anywhere {scene} {out}", NULL, NULL);
    expect(r, 1, "exit", "status 127 (command not found");
    free(r);
}
END_TEST

START_TEST(test_conform_exact_copy_passes)
{
    char cmd[512];
    cli_run *r = malloc(sizeof *r);
    conform(r, fake(cmd, sizeof cmd, "exact"), NULL, NULL);
    expect(r, 0, "pass", "\"max_abs\": 0.0,");
    ck_assert(strstr(r->out, "\"passed\": 1") && strstr(r->out, "\"failed\": 0"));
    free(r);
}
END_TEST

/* refray's own render, as PFM, is within 1e-4 of its oracle everywhere. */
START_TEST(test_conform_refray_render_passes)
{
    char cmd[512], kit[128];
    cli_run *r = malloc(sizeof *r);
    const char *bin = cli_refray_bin();
    char cwd[256];
    ck_assert_ptr_nonnull(getcwd(cwd, sizeof cwd));
    snprintf(cmd, sizeof cmd, "%s%s%s render -q {scene} -o {out}", bin[0] == '/' ? "" : cwd,
             bin[0] == '/' ? "" : "/", bin);
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    const char *args[] = {"conform", "--kit", kit, "--format", "pfm", "--cmd", cmd, NULL};
    cli_refray(r, args);
    ck_assert_msg(r->code == 0, "exit %d\n%s\n%s", r->code, r->out, r->err);
    ck_assert_msg(strstr(r->out, "3 scenes: 3 passed, 0 failed") != NULL, "stdout: %s", r->out);
    free(r);
}
END_TEST

/* refray's own default EXR holds half floats, whose relative step (up to
 * 2^-11) is coarser than the kit's 1e-4: the verdict fails and says why,
 * as it does for an 8-bit PNG (attack 14, finding 6: no reason before);
 * the same render as 32-bit floats passes. */
START_TEST(test_conform_half_exr_says_why)
{
    if (!REFRAY_HAVE_EXR)
        return;
    char cmd[512], kit[128], cwd[256];
    cli_run *r = malloc(sizeof *r);
    const char *bin = cli_refray_bin();
    ck_assert_ptr_nonnull(getcwd(cwd, sizeof cwd));
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    for (int as_float = 0; as_float <= 1; as_float++) {
        snprintf(cmd, sizeof cmd, "%s%s%s render -q %s{scene} -o {out}", bin[0] == '/' ? "" : cwd,
                 bin[0] == '/' ? "" : "/", bin, as_float ? "--exr-float " : "");
        const char *args[] = {"conform", "--kit", kit, "--format", "exr", "--cmd", cmd, NULL};
        cli_refray(r, args);
        if (as_float) {
            ck_assert_msg(r->code == 0, "exit %d\n%s\n%s", r->code, r->out, r->err);
            ck_assert_ptr_null(strstr(r->out, "half float"));
        } else {
            ck_assert_msg(r->code != 0, "half floats passed a 1e-4 kit:\n%s", r->out);
            ck_assert_msg(strstr(r->out, "every value of the output is a half float") != NULL, "stdout: %s", r->out);
        }
    }
    free(r);
}
END_TEST

/* [KIT-ADJUST-1] A renderer that draws the exact image 2 x 2 larger and 4
 * times as bright passes with --downsample 2 --scale 0.25 (powers of two:
 * exact in float) and fails on its size without them. */
START_TEST(test_conform_downsample_and_scale)
{
    char kit[128], src[300], big[300], cmd[700], err[256];
    img_buf e, b;
    cli_run *r = malloc(sizeof *r);
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    cli_path(src, sizeof src, kit, "scenes/plane_point_linear/plane_point_linear.exact.pfm");
    ck_assert_int_eq(img_read(src, NULL, &e, err, sizeof err), 0);
    ck_assert_int_eq(img_create(&b, 2 * e.width, 2 * e.height), 0);
    for (int y = 0; y < b.height; y++)
        for (int x = 0; x < b.width; x++)
            for (int c = 0; c < 3; c++)
                img_pixel(&b, x, y)[c] = 4 * img_pixel(&e, x / 2, y / 2)[c];
    cli_path(big, sizeof big, kit_root, "big.pfm");
    ck_assert_int_eq(img_write(big, &b, NULL, err, sizeof err), 0);
    snprintf(cmd, sizeof cmd, "test {width}x{height} = 192x144 && cp '%s' {out}", big);
    conform(r, cmd, "--downsample", "2");
    expect(r, 1, "over", NULL);
    const char *args[] = {"conform", "--kit", kit, "--format", "pfm", "--json", "--only", "plane_point_linear",
                          "--downsample", "2", "--scale", "0.25", "--cmd", cmd, NULL};
    cli_refray(r, args);
    expect(r, 0, "pass", "\"max_abs\": 0.0,");
    snprintf(cmd, sizeof cmd, "cp '%s' {out}", big);
    conform(r, cmd, NULL, NULL);
    expect(r, 1, "size", "expected 96x72");
    img_free(&e);
    img_free(&b);
    free(r);
}
END_TEST

/* A scene the kit has no .pov for fails without running the command. */
START_TEST(test_conform_missing_input)
{
    char kit[128];
    cli_run *r = malloc(sizeof *r);
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    const char *args[] = {"conform", "--kit", kit, "--format", "pfm", "--json", "--only",
                          "sphere_shadow_two_lights", "--cmd", "touch {out}.ran; cp {pov} {out}", NULL};
    cli_refray(r, args);
    expect(r, 1, "no_input", "refused by the POV-Ray export");
    ck_assert(strstr(r->out, "\"exit_status\": null") != NULL);
    free(r);
}
END_TEST

/* [CONF-REPORT-1] TAP, JUnit and Markdown of a run where one scene of two
 * fails ({name} in shell syntax: it is quoted for the shell). */
START_TEST(test_conform_reports)
{
    char kit[128], cmd[700], junit[300], md[300], text[8192], why[256], exact[512];
    cli_run *r = malloc(sizeof *r);
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    snprintf(cmd, sizeof cmd, "case {name} in disk*) echo 'bad <&> \"x\"' >&2; exit 2;; esac; %s",
             fake(exact, sizeof exact, "exact"));
    cli_path(junit, sizeof junit, kit_root, "junit.xml");
    cli_path(md, sizeof md, kit_root, "table.md");
    const char *args[] = {"conform", "--kit", kit, "--format", "pfm", "--tap", "--only", "plane_point_linear",
                          "disk_light", "--junit", junit, "--markdown", md, "--cmd", cmd, NULL};
    cli_refray(r, args);
    ck_assert_int_eq(r->code, 1);
    static const char tap[] = "TAP version 13\n1..2\nok 1 - plane_point_linear\n"
                              "not ok 2 - disk_light # the renderer exited with status 2\n  ---\n";
    ck_assert_msg(strncmp(r->out, tap, strlen(tap)) == 0, "tap: %s", r->out);
    char *x;
    size_t n;
    ck_assert_int_eq(file_read_all(junit, -1, NULL, &x, &n, why, sizeof why), 0);
    ck_assert(strstr(x, "<testsuites name=\"refray conform\" tests=\"2\" failures=\"1\""));
    ck_assert(strstr(x, "name=\"plane_point_linear\" time=") && strstr(x, "<failure type=\"exit\""));
    ck_assert_msg(strstr(x, "<system-err>bad &lt;&amp;&gt; &quot;x&quot;\n</system-err>"), "junit: %s", x);
    free(x);
    ck_assert_int_eq(file_read_all(md, -1, NULL, &x, &n, why, sizeof why), 0);
    snprintf(text, sizeof text, "%s", x);
    free(x);
    ck_assert(strstr(text, "| scene | family | exact peak |") && strstr(text, "| disk_light | disk_light |"));
    /* A report that cannot be written: exit 74 and no file. */
    const char *bad[] = {"conform", "--kit", kit, "--format", "pfm", "--only", "plane_point_linear", "--junit",
                         "/nonexistent/dir/j.xml", "--cmd", cmd, NULL};
    cli_refray(r, bad);
    ck_assert_int_eq(r->code, 74);
    ck_assert(!cli_exists("/nonexistent/dir/j.xml"));
    free(r);
}
END_TEST

/* [CONF-REPORT-3] A report path that cannot be written is refused before
 * the first render: the renderer (which leaves a mark) never runs, exit
 * 74, the reason names the path, and no temporary is left.  Before: every
 * scene ran and the error came at the end. */
START_TEST(test_conform_report_path_checked_first)
{
    char kit[128], cmd[900], mark[300], exact[512], dir[300], bad_md[300];
    cli_run *r = malloc(sizeof *r);
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    cli_path(mark, sizeof mark, kit_root, "ran");
    snprintf(cmd, sizeof cmd, "touch %s; %s", mark, fake(exact, sizeof exact, "exact"));
    /* A directory at the --markdown path: not a file refray may replace. */
    cli_path(dir, sizeof dir, kit_root, "adir");
    ck_assert_int_eq(mkdir(dir, 0777), 0);
    snprintf(bad_md, sizeof bad_md, "%s", dir);
    const char *junit[] = {"conform", "--kit", kit, "--format", "pfm", "--only", "plane_point_linear", "--junit",
                           "/nonexistent/dir/j.xml", "--cmd", cmd, NULL};
    const char *md[] = {"conform", "--kit", kit, "--format", "pfm", "--tap", "--only", "plane_point_linear",
                        "--markdown", bad_md, "--cmd", cmd, NULL};
    const char *const *cases[] = {junit, md};
    const char *names[] = {"/nonexistent/dir/j.xml", bad_md};
    for (int i = 0; i < 2; i++) {
        cli_refray(r, cases[i]);
        ck_assert_msg(r->code == 74, "case %d: exit %d, stderr %s", i, r->code, r->err);
        ck_assert_msg(strstr(r->err, names[i]) != NULL, "case %d: stderr %s", i, r->err);
        ck_assert_msg(!cli_exists(mark), "case %d: the renderer ran before the report path was checked", i);
        ck_assert_msg(r->out[0] == '\0', "case %d: stdout %s", i, r->out);
    }
    /* The good path next to a bad one: neither is written, the good one's
     * temporary is gone. */
    char good[300];
    cli_path(good, sizeof good, kit_root, "good.xml");
    const char *both[] = {"conform", "--kit", kit, "--format", "pfm", "--only", "plane_point_linear", "--junit",
                          good, "--markdown", bad_md, "--cmd", cmd, NULL};
    cli_refray(r, both);
    ck_assert_int_eq(r->code, 74);
    ck_assert(!cli_exists(mark) && !cli_exists(good));
    char check[700];
    snprintf(check, sizeof check, "ls -a %s | grep -q refray-tmp", kit_root);
    ck_assert_msg(system(check) != 0, "a temporary was left in %s", kit_root);
    /* --junit and --markdown naming one file (also as ./NAME beside NAME):
     * both renamed onto it would leave only the Markdown; refused (64)
     * before the renderer runs.  Before: exit 1, the JUnit file lost. */
    char same[300], same_dot[310];
    cli_path(same, sizeof same, kit_root, "same.xml");
    snprintf(same_dot, sizeof same_dot, "%s/./same.xml", kit_root);
    const char *one[] = {"conform", "--kit", kit, "--format", "pfm", "--only", "plane_point_linear", "--junit",
                         same_dot, "--markdown", same, "--cmd", cmd, NULL};
    cli_refray(r, one);
    ck_assert_msg(r->code == 64, "one file: exit %d, stderr %s", r->code, r->err);
    ck_assert_msg(strstr(r->err, "--junit and --markdown name one file") != NULL, "%s", r->err);
    ck_assert(!cli_exists(mark) && !cli_exists(same));
    ck_assert_int_eq(rmdir(dir), 0);
    free(r);
}
END_TEST

START_TEST(test_conform_usage_errors)
{
    char kit[128], work[64], path[300], why[128];
    cli_run *r = malloc(sizeof *r);
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    const char *no_cmd[] = {"conform", "--kit", kit, NULL};
    const char *no_out[] = {"conform", "--kit", kit, "--cmd", "render {scene}", NULL};
    const char *unknown[] = {"conform", "--kit", kit, "--format", "pfm", "--cmd", "x {out}", "--only", "disk_lite",
                             NULL};
    const char *timeout[] = {"conform", "--kit", kit, "--cmd", "x {out}", "--timeout", "-1", NULL};
    const char *both[] = {"conform", "--kit", kit, "--cmd", "x {out}", "--json", "--tap", NULL};
    const char *format[] = {"conform", "--kit", kit, "--cmd", "x {out}", "--format", "tiff", NULL};
    /* More names than arguments: the list must not overrun (ASan watches). */
    const char *many[] = {"conform", "--kit", kit, "--format", "pfm", "--cmd", "x {out}", "--only",
                          "disk_light,a,b,c,d,e,f,g,h,i,j,k,l,m,n,o,p,q,r,s,t,u,v,w,x,y,z", NULL};
    const char *const *usage[] = {no_cmd, no_out, unknown, timeout, both, format, many};
    for (int i = 0; i < 7; i++) {
        cli_refray(r, usage[i]);
        ck_assert_msg(r->code == 64, "case %d: exit %d, stderr %s", i, r->code, r->err);
    }
    cli_refray(r, unknown);
    ck_assert_msg(strstr(r->err, "did you mean 'disk_light'") != NULL, "stderr: %s", r->err);
    cli_scratch(work, sizeof work, "nokit");
    const char *missing[] = {"conform", "--kit", work, "--format", "pfm", "--cmd", "x {out}", NULL};
    cli_refray(r, missing);
    ck_assert_int_eq(r->code, 66);
    ck_assert_int_eq(file_write_bytes(cli_path(path, sizeof path, work, "manifest.json"), "{", 1, why, sizeof why),
                     0);
    cli_refray(r, missing);
    ck_assert_int_eq(r->code, 65);
    cli_remove(work);
    free(r);
}
END_TEST

/* The over count of `refray compare --manifest` for image against the
 * suite kit's plane_point_linear. */
static long compare_over(const char *kit, const char *image)
{
    char mf[300];
    cli_run *r = malloc(sizeof *r);
    const char *args[] = {"compare", image, "--manifest", cli_path(mf, sizeof mf, kit, "manifest.json"), "--scene",
                          "plane_point_linear", "--json", NULL};
    cli_refray(r, args);
    const char *p = strstr(r->out, "\"over\": ");
    ck_assert_msg(p != NULL, "compare: %s %s", r->out, r->err);
    long over = strtol(p + 8, NULL, 10);
    free(r);
    return over;
}

/* [KIT-RULE-1] The rule is enough to check without refray: the kit's
 * stand-alone checker (tests/conform/kit_check.c, one C99 file without a
 * library, the worked example of spec/conformance.md) counts the same
 * pixels over as compare, on a picture 3e-4 too bright in its top half,
 * and passes the exact image itself. */
START_TEST(test_kit_check_agrees)
{
    const char *bin = getenv("KIT_CHECK_BIN");
    char kit[128], src[300], img[300], mask[300], mf[300], cmd[2048], err[256], want[64];
    img_buf e;
    ck_assert_msg(bin && access(bin, X_OK) == 0, "no kit_check at $KIT_CHECK_BIN (make test builds it)");
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    cli_path(src, sizeof src, kit, "scenes/plane_point_linear/plane_point_linear.exact.pfm");
    cli_path(mask, sizeof mask, kit, "scenes/plane_point_linear/plane_point_linear.mask.pgm");
    ck_assert_int_eq(img_read(src, NULL, &e, err, sizeof err), 0);
    for (int i = 0; i < 3 * e.width * e.height / 2; i++)
        e.rgb[i] *= 1 + 3e-4;
    ck_assert_int_eq(img_write(cli_path(img, sizeof img, kit_root, "bright.pfm"), &e, NULL, err, sizeof err), 0);
    long over = compare_over(kit, img);
    ck_assert_int_gt(over, 0);
    manifest m;
    ck_assert_int_eq(manifest_read(cli_path(mf, sizeof mf, kit, "manifest.json"), &m, err, sizeof err), 0);
    const manifest_scene *sc = manifest_find(&m, "plane_point_linear");
    ck_assert_ptr_nonnull(sc);
    snprintf(want, sizeof want, "%ld of %d pixels over", over, e.width * e.height);
    snprintf(cmd, sizeof cmd, "'%s' '%s' '%s' %.17g %.17g '%s' | grep -qx '%s'", bin, src, mask, sc->relative,
             sc->absolute, img, want);
    ck_assert_msg(system(cmd) == 0, "kit_check does not print '%s'", want);
    snprintf(cmd, sizeof cmd, "'%s' '%s' '%s' %.17g %.17g '%s' >/dev/null", bin, src, mask, sc->relative, sc->absolute,
             src);
    ck_assert_int_eq(system(cmd), 0);
    manifest_free(&m);
    img_free(&e);
}
END_TEST

/* kit_check's exit 2 for what it cannot judge: a tolerance that is not a
 * finite number >= 0 (an infinite one passed a picture of -1e30 everywhere,
 * a misspelt one was read as 0), and a PFM header of 65536 x 65536 pixels,
 * whose byte count wrapped around a 32-bit size_t into a small allocation
 * that the rows were then written past (make check M32=1). */
START_TEST(test_kit_check_refuses)
{
    const char *bin = getenv("KIT_CHECK_BIN");
    static const char *const tolerances[] = {"inf 0", "0 inf", "1e-4x 0", "abc 0", "1e-4 -1", "nan 0"};
    char kit[128], src[300], mask[300], big[300], cmd[2048];
    ck_assert_msg(bin && access(bin, X_OK) == 0, "no kit_check at $KIT_CHECK_BIN (make test builds it)");
    snprintf(kit, sizeof kit, "%s/kit", kit_root);
    ck_assert_int_eq(kit_status, 0);
    cli_path(src, sizeof src, kit, "scenes/plane_point_linear/plane_point_linear.exact.pfm");
    cli_path(mask, sizeof mask, kit, "scenes/plane_point_linear/plane_point_linear.mask.pgm");
    for (size_t i = 0; i < sizeof tolerances / sizeof tolerances[0]; i++) {
        snprintf(cmd, sizeof cmd, "'%s' '%s' '%s' %s '%s' >/dev/null 2>&1", bin, src, mask, tolerances[i], src);
        int st = system(cmd);
        ck_assert_msg(WIFEXITED(st) && WEXITSTATUS(st) == 2, "tolerance %s: status %d", tolerances[i], st);
    }
    FILE *f = fopen(cli_path(big, sizeof big, kit_root, "huge-header.pfm"), "wb");
    ck_assert_ptr_nonnull(f);
    fputs("PF\n65536 65536\n-1.0\n", f);
    for (int i = 0; i < 4096; i++)
        fputc(0, f);
    ck_assert_int_eq(fclose(f), 0);
    snprintf(cmd, sizeof cmd, "'%s' '%s' '%s' 1e-4 1e-5 '%s' >/dev/null 2>&1", bin, src, mask, big);
    int st = system(cmd);
    ck_assert_msg(WIFEXITED(st) && WEXITSTATUS(st) == 2, "a 65536 x 65536 header: status %d", st);
}
END_TEST

/* The pixels tests/conform/masked_sphere.scene's outline passes through
 * (worked in the scene's comment from its camera, not read from a kit). */
static const int masked_pixels[4][2] = {{4, 0}, {1, 3}, {7, 3}, {4, 6}};

/* A kit of tests/conform/masked_sphere.scene in a new directory work
 * (/tmp/refray-TAG-XXXXXX, 64 bytes): its path in kit, the exact image in exact and the mask, checked to mark
 * the four pixels above and no other. */
static void masked_kit(const char *tag, char work[64], char *kit, size_t size, img_buf *exact)
{
    char path[400], err[512];
    unsigned char *mask;
    cli_run *r = malloc(sizeof *r);
    cli_scratch(work, 64, tag);
    cli_path(kit, size, work, "kit");
    const char *args[] = {"kit", "-q", "-o", kit, "tests/conform/masked_sphere.scene", NULL};
    cli_refray(r, args);
    ck_assert_msg(r->code == 0, "refray kit: %s", r->err);
    free(r);
    cli_path(path, sizeof path, kit, "scenes/masked_sphere/masked_sphere.exact.pfm");
    ck_assert_int_eq(img_read(path, NULL, exact, err, sizeof err), 0);
    cli_path(path, sizeof path, kit, "scenes/masked_sphere/masked_sphere.mask.pgm");
    ck_assert_int_eq(verify_mask_read(path, exact->width, exact->height, &mask, err, sizeof err), 0);
    long marked = 0;
    for (int p = 0; p < exact->width * exact->height; p++)
        marked += mask[p] != 0;
    ck_assert_int_eq(marked, 4);
    for (int i = 0; i < 4; i++)
        ck_assert(mask[masked_pixels[i][1] * exact->width + masked_pixels[i][0]]);
    free(mask);
}

/* img as a PFM of its values as they are: refray's writers make NaN and
 * infinities finite ([REL-NONFINITE-1]); another renderer's need not.
 * The scale's sign says the host's byte order. */
static void write_raw_pfm(const char *path, const img_buf *img)
{
    unsigned one = 1;
    unsigned char little;
    memcpy(&little, &one, 1);
    FILE *f = fopen(path, "wb");
    ck_assert_ptr_nonnull(f);
    fprintf(f, "PF\n%d %d\n%s\n", img->width, img->height, little ? "-1.0" : "1.0");
    for (int y = img->height - 1; y >= 0; y--)
        for (int x = 0; x < img->width; x++)
            for (int c = 0; c < 3; c++) {
                float v = (float)img_pixel(img, x, y)[c];
                ck_assert_int_eq(fwrite(&v, sizeof v, 1, f), 1);
            }
    ck_assert_int_eq(fclose(f), 0);
}

/* The exit codes of the three judges for the picture at path against
 * scene name, the first of the kit: conform (its JSON in r), compare
 * --manifest and kit_check. */
static void three_judges_of(const char *kit, const char *name, const char *path, cli_run *r, int code[3])
{
    char cmd[2048], mf[400], exact[400], mask[400];
    const char *bin = getenv("KIT_CHECK_BIN");
    ck_assert_msg(bin && access(bin, X_OK) == 0, "no kit_check at $KIT_CHECK_BIN (make test builds it)");
    snprintf(cmd, sizeof cmd, "cp '%s' {out}", path);
    const char *conform_args[] = {"conform", "--kit", kit, "--format", "pfm", "--json", "--cmd", cmd, NULL};
    cli_refray(r, conform_args);
    code[0] = r->code;
    cli_run *c = malloc(sizeof *c);
    const char *compare_args[] = {"compare", path, "--manifest", cli_path(mf, sizeof mf, kit, "manifest.json"), NULL};
    cli_refray(c, compare_args);
    code[1] = c->code;
    free(c);
    snprintf(cmd, sizeof cmd, "scenes/%s/%s.exact.pfm", name, name);
    cli_path(exact, sizeof exact, kit, cmd);
    snprintf(cmd, sizeof cmd, "scenes/%s/%s.mask.pgm", name, name);
    cli_path(mask, sizeof mask, kit, cmd);
    manifest m;
    ck_assert_int_eq(manifest_read(mf, &m, cmd, sizeof cmd), 0);
    snprintf(cmd, sizeof cmd, "'%s' '%s' '%s' %.17g %.17g '%s' >/dev/null 2>&1", bin, exact, mask,
             m.scenes[0].relative, m.scenes[0].absolute, path);
    manifest_free(&m);
    int st = system(cmd);
    code[2] = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* three_judges_of the masked kit's scene. */
static void three_judges(const char *kit, const char *path, cli_run *r, int code[3])
{
    three_judges_of(kit, "masked_sphere", path, r, code);
}

/* [KIT-RULE-1] [CONF-MASKED-1] A NaN or an infinity in a pixel the mask
 * excludes is not judged, by any of the three judges: conform passes the
 * picture with a note of the values, compare --manifest and kit_check pass
 * it too.  One more NaN in a pixel the mask does not mark fails it in all
 * three.  Before, conform counted the non-finite values of the whole image
 * before it read the mask, and failed the first (attack 12, finding 4:
 * sh tests/attack12/conform_masked_nan.sh). */
START_TEST(test_conform_masked_nonfinite)
{
    char work[64], kit[128], path[300];
    img_buf e;
    int code[3];
    cli_run *r = malloc(sizeof *r);
    masked_kit("maskednan", work, kit, sizeof kit, &e);
    /* 3 + 3 + 1 values in three masked pixels. */
    for (int c = 0; c < 3; c++) {
        img_pixel(&e, 4, 0)[c] = NAN;
        img_pixel(&e, 1, 3)[c] = HUGE_VAL;
    }
    img_pixel(&e, 7, 3)[0] = NAN;
    write_raw_pfm(cli_path(path, sizeof path, work, "masked.pfm"), &e);
    three_judges(kit, path, r, code);
    ck_assert_msg(code[0] == 0 && code[1] == 0 && code[2] == 0, "conform %d, compare %d, kit_check %d\n%s", code[0],
                  code[1], code[2], r->out);
    ck_assert_msg(strstr(r->out, "\"note\": \"7 channel values of its image are NaN or infinite in pixels the mask "
                                 "excludes: not judged\"") && strstr(r->out, "\"compared\": 59,"), "%s", r->out);
    char cmd[400];
    snprintf(cmd, sizeof cmd, "cp '%s' {out}", path);
    const char *table[] = {"conform", "--kit", kit, "--format", "pfm", "--cmd", cmd, NULL};
    cli_refray(r, table);
    ck_assert_msg(r->code == 0 && strstr(r->out, "\n    note: 7 channel values") &&
                  strstr(r->out, "1 scene: 1 passed, 0 failed, 1 with a note"), "%s", r->out);
    const char *tap[] = {"conform", "--kit", kit, "--format", "pfm", "--tap", "--cmd", cmd, NULL};
    cli_refray(r, tap);
    ck_assert_msg(r->code == 0 && strstr(r->out, "ok 1 - masked_sphere\n# note: 7 channel values"), "%s", r->out);
    img_pixel(&e, 0, 0)[1] = NAN;
    write_raw_pfm(path, &e);
    three_judges(kit, path, r, code);
    ck_assert_msg(code[0] == 1 && code[1] == 1 && code[2] == 1, "conform %d, compare %d, kit_check %d\n%s", code[0],
                  code[1], code[2], r->out);
    expect(r, 1, "nonfinite", "1 channel value of its image is NaN or infinite");
    ck_assert_msg(strstr(r->out, "\"note\": \"7 channel values"), "%s", r->out);
    img_free(&e);
    cli_remove(work);
    free(r);
}
END_TEST

/* The masked kit's manifest with mask_pgm and mask_png kept or dropped
 * (pgm, png) and masked_pixels set to masked. */
static void edit_masked(const char *kit, int pgm, int png, long masked)
{
    char mf[400], why[512];
    manifest m;
    ck_assert_int_eq(manifest_read(cli_path(mf, sizeof mf, kit, "manifest.json"), &m, why, sizeof why), 0);
    manifest_scene *s = &m.scenes[0];
    char *keys[2] = {s->files[MANIFEST_FILE_MASK_PGM], s->files[MANIFEST_FILE_MASK_PNG]};
    int keep[2] = {pgm, png};
    for (int i = 0; i < 2; i++)
        if (!keep[i])
            keys[i][0] = '\0';
    s->masked = masked;
    ck_assert_int_eq(manifest_write(mf, &m, why, sizeof why), 0);
    manifest_free(&m);
}

/* conform and compare --manifest of the picture at path against the
 * masked kit: their exit codes, conform's output in r; the renderer's
 * command leaves ran beside path when it runs. */
static void conform_and_compare(const char *kit, const char *work, const char *path, cli_run *r, int code[2])
{
    char cmd[1024], mf[400], ran[300];
    snprintf(cmd, sizeof cmd, "touch '%s'; cp '%s' {out}", cli_path(ran, sizeof ran, work, "ran"), path);
    remove(ran);
    const char *conform_args[] = {"conform", "--kit", kit, "--format", "pfm", "--json", "--cmd", cmd, NULL};
    cli_refray(r, conform_args);
    code[0] = r->code;
    ck_assert_msg(r->code == 65 ? !cli_exists(ran) : cli_exists(ran), "conform %d: the renderer %s", r->code,
                  cli_exists(ran) ? "ran" : "did not run");
    cli_run *c = malloc(sizeof *c);
    const char *compare_args[] = {"compare", path, "--manifest", cli_path(mf, sizeof mf, kit, "manifest.json"), NULL};
    cli_refray(c, compare_args);
    code[1] = c->code;
    ck_assert_msg(c->code != 65 || strstr(c->err, "the manifest disagrees with its kit"), "%s", c->err);
    free(c);
}

/* [KIT-MASK-1] A manifest that lists its mask as PNG only (mask_pgm null,
 * which spec/conformance.md 2 allows for any file): conform and compare
 * read the PNG, and pass a picture that is the exact image with 0.5 in
 * the four masked pixels (where the exact image holds 0).  A manifest
 * whose masked_pixels is not what its mask marks, or that names masked
 * pixels and lists no mask, is refused (65) before any renderer runs.
 * Before, both read mask_pgm only: with it null they compared every pixel
 * and failed the picture, and masked_pixels was never read (attack 12,
 * finding 5: sh tests/attack12/conform_mask_png.sh). */
START_TEST(test_conform_mask_png_and_count)
{
    char work[64], kit[128], path[300];
    img_buf e;
    int code[2];
    cli_run *r = malloc(sizeof *r);
    masked_kit("maskpng", work, kit, sizeof kit, &e);
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 3; c++)
            img_pixel(&e, masked_pixels[i][0], masked_pixels[i][1])[c] = 0.5;
    write_raw_pfm(cli_path(path, sizeof path, work, "picture.pfm"), &e);
    edit_masked(kit, 0, 1, 4);
    conform_and_compare(kit, work, path, r, code);
    ck_assert_msg(code[0] == 0 && code[1] == 0, "PNG mask: conform %d, compare %d\n%s", code[0], code[1], r->out);
    ck_assert_msg(strstr(r->out, "\"excluded\": 4,"), "%s", r->out);
    edit_masked(kit, 0, 1, 3);
    conform_and_compare(kit, work, path, r, code);
    ck_assert_msg(code[0] == 65 && code[1] == 65, "3 of 4: conform %d, compare %d", code[0], code[1]);
    ck_assert_msg(strstr(r->err, "scene 'masked_sphere': 'masked_pixels' is 3, but its mask "
                                 "'scenes/masked_sphere/masked_sphere.mask.png' marks 4: the manifest disagrees "
                                 "with its kit"), "%s", r->err);
    edit_masked(kit, 0, 0, 4);
    conform_and_compare(kit, work, path, r, code);
    ck_assert_msg(code[0] == 65 && code[1] == 65, "no mask: conform %d, compare %d", code[0], code[1]);
    ck_assert_msg(strstr(r->err, "'masked_pixels' is 4, but it lists no mask"), "%s", r->err);
    edit_masked(kit, 0, 0, 0);
    conform_and_compare(kit, work, path, r, code);
    ck_assert_msg(code[0] == 1 && code[1] == 1, "no mask, none masked: conform %d, compare %d", code[0], code[1]);
    expect(r, 1, "over", "4 of 63 pixels over");
    img_free(&e);
    cli_remove(work);
    free(r);
}
END_TEST

/* The masked kit's manifest with png16_scale 2^-e and absolute (and
 * absolute_png) the step of a 16-bit PNG there, 2^e / 65535 (at most
 * what [KIT-TOL-1] allows, so that only [VERIFY-UNBOUNDED-3] is left to
 * refuse it). */
static void edit_scale(const char *kit, int e)
{
    char mf[400], why[512];
    manifest m;
    ck_assert_int_eq(manifest_read(cli_path(mf, sizeof mf, kit, "manifest.json"), &m, why, sizeof why), 0);
    m.scenes[0].png16_scale = ldexp(1, -e);
    m.scenes[0].absolute = m.scenes[0].absolute_png = ldexp(1, e) / 65535;
    ck_assert_int_eq(manifest_write(mf, &m, why, sizeof why), 0);
    manifest_free(&m);
}

/* [VERIFY-UNBOUNDED-3] The masked kit's exact image peaks at 0.87 (the
 * red of Kd 0.8 under ambient 0.1 and a distant light of 1, at a normal
 * near the light).  With png16_scale 2^-15 the absolute bound is 0.50:
 * above half the peak less its relative part, so a picture of half the
 * light, and a black one, would pass; conform, compare --manifest and
 * kit_check refuse the tolerance (65, 65, 2) and run nothing.  Before,
 * any absolute bound loaded, and conform passed an all-black picture
 * under absolute 10 (attack 12, finding 6: sh
 * tests/attack12/conform_abs_unbounded.sh).
 * [VERIFY-UNBOUNDED-4] At 2^-14 the absolute bound, 0.25, is below half the
 * peak but passes black wherever the exact image is below 0.25: more
 * than 2^-14 of the peak (0.87 / 16384 = 5.3e-5), the three refuse it too
 * (before, they failed the black picture and passed a picture black
 * below 0.4 under absolute 0.4, attack 13, finding 2).  At the kit's own
 * scale, 2^-1 (0.87 in (0.4, 0.8] x 2: absolute 2 / 65535 = 3.1e-5), the
 * three fail the black picture and pass the exact one. */
START_TEST(test_conform_absolute_bound_decides)
{
    char work[64], kit[128], path[300], black[300];
    img_buf e;
    int code[3];
    cli_run *r = malloc(sizeof *r);
    masked_kit("absbound", work, kit, sizeof kit, &e);
    for (int i = 0; i < 3 * e.width * e.height; i++)
        e.rgb[i] = 0;
    write_raw_pfm(cli_path(black, sizeof black, work, "black.pfm"), &e);
    cli_path(path, sizeof path, kit, "scenes/masked_sphere/masked_sphere.exact.pfm");
    edit_scale(kit, 15);
    three_judges(kit, black, r, code);
    ck_assert_msg(code[0] == 65 && code[1] == 65 && code[2] == 2, "2^-15: conform %d, compare %d, kit_check %d",
                  code[0], code[1], code[2]);
    ck_assert_msg(strstr(r->err, "scene 'masked_sphere': its tolerance, relative 0.0001 and absolute 0.5, passes a "
                                 "picture of half the light") && strstr(r->err, "[VERIFY-UNBOUNDED-3]"), "%s", r->err);
    ck_assert_msg(r->out[0] == '\0', "conform ran a scene: %s", r->out);
    three_judges(kit, path, r, code);
    ck_assert_msg(code[0] == 65 && code[1] == 65 && code[2] == 2, "2^-15, the exact image: %d %d %d", code[0],
                  code[1], code[2]);
    edit_scale(kit, 14);
    three_judges(kit, black, r, code);
    ck_assert_msg(code[0] == 65 && code[1] == 65 && code[2] == 2, "2^-14: conform %d, compare %d, kit_check %d",
                  code[0], code[1], code[2]);
    ck_assert_msg(strstr(r->err, "scene 'masked_sphere': its absolute tolerance 0.25 passes black wherever") &&
                  strstr(r->err, "[VERIFY-UNBOUNDED-4]"), "%s", r->err);
    ck_assert_msg(r->out[0] == '\0', "conform ran a scene: %s", r->out);
    three_judges(kit, path, r, code);
    ck_assert_msg(code[0] == 65 && code[1] == 65 && code[2] == 2, "2^-14, the exact image: %d %d %d", code[0],
                  code[1], code[2]);
    edit_scale(kit, 1);
    three_judges(kit, black, r, code);
    ck_assert_msg(code[0] == 1 && code[1] == 1 && code[2] == 1, "2^-1: conform %d, compare %d, kit_check %d",
                  code[0], code[1], code[2]);
    three_judges(kit, path, r, code);
    ck_assert_msg(code[0] == 0 && code[1] == 0 && code[2] == 0, "2^-1, the exact image: %d %d %d", code[0],
                  code[1], code[2]);
    img_free(&e);
    cli_remove(work);
    free(r);
}
END_TEST

/* [KIT-TOL-1] The kit of a scene with one bright spot (hdr_spot.scene:
 * peak 1084, most of the plane 0.012 .. 0.04) has png16_scale 2^-11,
 * whose 16-bit step 2048 / 65535 = 0.031 is above most of the image.  That
 * step is a PNG's absolute (absolute_png); a float picture, which holds
 * those values, is judged with 2^-20 of the peak (absolute).  A PFM whose
 * every value below 0.031 is black, most pixels 100 % off, fails the
 * three judges; the exact image passes them.  Before, absolute was the
 * step for every format and the three passed the black picture (attack
 * 15, finding 1: sh tests/attack15/conform_hdr_dark.sh). */
START_TEST(test_conform_float_absolute_is_not_the_png_step)
{
    char work[64], kit[128], path[400], dark[300], why[512];
    img_buf e;
    int code[3];
    cli_run *r = malloc(sizeof *r);
    cli_scratch(work, sizeof work, "hdrspot");
    cli_path(kit, sizeof kit, work, "kit");
    const char *args[] = {"kit", "-q", "-o", kit, "tests/conform/hdr_spot.scene", NULL};
    cli_refray(r, args);
    ck_assert_msg(r->code == 0, "refray kit: %s", r->err);
    manifest m;
    ck_assert_int_eq(manifest_read(cli_path(path, sizeof path, kit, "manifest.json"), &m, why, sizeof why), 0);
    const manifest_scene *s = &m.scenes[0];
    ck_assert(s->png16_scale == 0x1p-11 && s->absolute_png == 2048 / 65535.0);
    ck_assert_msg(s->peak > 1000 && s->absolute == 0x1p-20 * s->peak, "peak %g, absolute %g", s->peak, s->absolute);
    manifest_free(&m);
    cli_path(path, sizeof path, kit, "scenes/hdr_spot/hdr_spot.exact.pfm");
    ck_assert_int_eq(img_read(path, NULL, &e, why, sizeof why), 0);
    long dimmed = 0;
    for (int i = 0; i < 3 * e.width * e.height; i++)
        if (e.rgb[i] < 0.031) {
            e.rgb[i] = 0;
            dimmed++;
        }
    ck_assert_msg(dimmed > 3 * e.width * e.height / 2, "%ld values below 0.031", dimmed);
    write_raw_pfm(cli_path(dark, sizeof dark, work, "dark.pfm"), &e);
    three_judges_of(kit, "hdr_spot", dark, r, code);
    ck_assert_msg(code[0] == 1 && code[1] == 1 && code[2] == 1, "the dark picture: conform %d, compare %d, "
                  "kit_check %d", code[0], code[1], code[2]);
    three_judges_of(kit, "hdr_spot", path, r, code);
    ck_assert_msg(code[0] == 0 && code[1] == 0 && code[2] == 0, "the exact image: conform %d, compare %d, "
                  "kit_check %d", code[0], code[1], code[2]);
    img_free(&e);
    cli_remove(work);
    free(r);
}
END_TEST

/* Sets byte v at pixel (x, y) of the PGM at path (header "P5\nW H\n255\n",
 * as refray writes it). */
static void poke_pgm(const char *path, int x, int y, int width, int v)
{
    FILE *f = fopen(path, "r+b");
    ck_assert_ptr_nonnull(f);
    int c, lines = 0;
    long at = 0;
    while (lines < 3 && (c = fgetc(f)) != EOF)
        lines += c == '\n', at++;
    ck_assert_int_eq(lines, 3);
    ck_assert_int_eq(fseek(f, at + (long)y * width + x, SEEK_SET), 0);
    ck_assert_int_eq(fputc(v, f), v);
    ck_assert_int_eq(fclose(f), 0);
}

/* [VERIFY-MASK-1] A mask is black (0) or white (255) only: a byte between,
 * in a judged pixel (100) or a masked one (254), is refused by conform,
 * compare --manifest and kit_check (65, 65, 2) with the reason; so is a
 * grey pixel (0.5) of the PNG mask read where mask_pgm is null (conform
 * and compare; kit_check reads the PGM).  Before, kit_check took any
 * non-zero byte as a mark and the other two a byte over 127, so a byte
 * 100 in a pixel holding NaN passed kit_check and failed the others
 * (attack 13, finding 4: sh tests/attack13/mask_gray.sh). */
START_TEST(test_conform_mask_grey_refused)
{
    char work[64], kit[128], path[300], mask[400], png[400], err[512];
    img_buf e, m;
    int code[3];
    cli_run *r = malloc(sizeof *r);
    masked_kit("maskgrey", work, kit, sizeof kit, &e);
    cli_path(path, sizeof path, kit, "scenes/masked_sphere/masked_sphere.exact.pfm");
    cli_path(mask, sizeof mask, kit, "scenes/masked_sphere/masked_sphere.mask.pgm");
    three_judges(kit, path, r, code);
    ck_assert_msg(code[0] == 0 && code[1] == 0 && code[2] == 0, "as written: %d %d %d", code[0], code[1], code[2]);
    static const int grey[2][3] = {{0, 0, 100}, {4, 0, 254}};
    for (int i = 0; i < 2; i++) {
        poke_pgm(mask, grey[i][0], grey[i][1], e.width, grey[i][2]);
        three_judges(kit, path, r, code);
        ck_assert_msg(code[0] == 65 && code[1] == 65 && code[2] == 2, "byte %d: conform %d, compare %d, kit_check %d",
                      grey[i][2], code[0], code[1], code[2]);
        ck_assert_msg(strstr(r->err, MASK_NOT_BINARY) != NULL, "%s", r->err);
        poke_pgm(mask, grey[i][0], grey[i][1], e.width, i == 0 ? 0 : 255);
    }
    edit_masked(kit, 0, 1, 4);
    cli_path(png, sizeof png, kit, "scenes/masked_sphere/masked_sphere.mask.png");
    ck_assert_int_eq(img_read(png, NULL, &m, err, sizeof err), 0);
    for (int c = 0; c < 3; c++)
        img_pixel(&m, 2, 2)[c] = 0.5;
    ck_assert_int_eq(img_write(png, &m, NULL, err, sizeof err), 0);
    three_judges(kit, path, r, code);
    ck_assert_msg(code[0] == 65 && code[1] == 65, "PNG grey: conform %d, compare %d", code[0], code[1]);
    ck_assert_msg(strstr(r->err, MASK_NOT_BINARY) != NULL, "%s", r->err);
    img_free(&m);
    img_free(&e);
    cli_remove(work);
    free(r);
}
END_TEST

#else

/* conform reads the kit's manifest: a build without jansson says so. */
START_TEST(test_conform_needs_json)
{
    cli_run *r = malloc(sizeof *r);
    const char *args[] = {"conform", "--kit", "/tmp", "--format", "pfm", "--cmd", "x {out}", NULL};
    cli_refray(r, args);
    ck_assert_int_eq(r->code, 64);
    ck_assert_msg(strstr(r->err, "JSON") != NULL, "stderr: %s", r->err);
    free(r);
}
END_TEST

#endif

/* [CONF-CMD-1] Values survive the shell whatever they hold; braces that
 * are not placeholders stay; a missing file says why. */
START_TEST(test_conform_expand_quotes)
{
    static const char nasty[] = "a b'c\"d$HOME`x`\\e\nf;g*";
    conform_var vars[2] = {{"out", NULL, NULL}, {"x", nasty, NULL}};
    char work[64], path[300], why[256], *cmd = NULL;
    cli_scratch(work, sizeof work, "expand");
    vars[0].value = cli_path(path, sizeof path, work, "o u't");
    ck_assert_int_eq(conform_expand("printf %s {x} > {out}", vars, 2, &cmd, why, sizeof why), 0);
    proc_opts po = {work, NULL, NULL, 10 * slow(), NULL};
    proc_result pr;
    ck_assert_int_eq(proc_run_shell(cmd, &po, &pr, why, sizeof why), 0);
    ck_assert(pr.exited && pr.exit_code == 0);
    char *got;
    size_t n;
    ck_assert_int_eq(file_read_all(path, -1, NULL, &got, &n, why, sizeof why), 0);
    ck_assert_str_eq(got, nasty);
    free(got);
    free(cmd);
    ck_assert_int_eq(conform_expand("{y} ${HOME} {x {out", vars, 2, &cmd, why, sizeof why), 0);
    ck_assert_str_eq(cmd, "{y} ${HOME} {x {out");
    free(cmd);
    char *q = conform_shell_quote("it's");
    ck_assert_str_eq(q, "'it'\\''s'");
    free(q);
    conform_var none = {"json", NULL, "not exported"};
    ck_assert_int_eq(conform_expand("r {json}", &none, 1, &cmd, why, sizeof why), CONFORM_NO_INPUT);
    ck_assert_msg(strstr(why, "{json}") && strstr(why, "not exported"), "why: %s", why);
    ck_assert(conform_template_ok("r {scene} -o {out}", why, sizeof why));
    ck_assert(!conform_template_ok("r {scene}", why, sizeof why));
    cli_remove(work);
}
END_TEST

Suite *suite_conform(void)
{
    Suite *s = suite_create("conform");
    TCase *tc = tcase_create("conform");
    tcase_add_unchecked_fixture(tc, kit_setup, kit_teardown);
    tcase_set_timeout(tc, 20);
    tcase_add_test(tc, test_conform_expand_quotes);
#if REFRAY_HAVE_JSON
    tcase_add_test(tc, test_conform_crash);
    tcase_add_test(tc, test_conform_hang);
    tcase_add_test(tc, test_conform_garbage);
    tcase_add_test(tc, test_conform_wrong_size);
    tcase_add_test(tc, test_conform_fifo);
    tcase_add_test(tc, test_conform_nothing);
    tcase_add_test(tc, test_conform_nonzero_exit);
    tcase_add_test(tc, test_conform_nan);
    tcase_add_test(tc, test_conform_command_not_found);
    tcase_add_test(tc, test_conform_exact_copy_passes);
    tcase_add_test(tc, test_conform_refray_render_passes);
    tcase_add_test(tc, test_conform_half_exr_says_why);
    tcase_add_test(tc, test_conform_downsample_and_scale);
    tcase_add_test(tc, test_conform_missing_input);
    tcase_add_test(tc, test_conform_reports);
    tcase_add_test(tc, test_conform_usage_errors);
    tcase_add_test(tc, test_conform_report_path_checked_first);
    tcase_add_test(tc, test_kit_check_agrees);
    tcase_add_test(tc, test_kit_check_refuses);
    tcase_add_test(tc, test_conform_masked_nonfinite);
    tcase_add_test(tc, test_conform_mask_png_and_count);
    tcase_add_test(tc, test_conform_absolute_bound_decides);
    tcase_add_test(tc, test_conform_float_absolute_is_not_the_png_step);
    tcase_add_test(tc, test_conform_mask_grey_refused);
#else
    tcase_add_test(tc, test_conform_needs_json);
#endif
    suite_add_tcase(s, tc);
    return s;
}
