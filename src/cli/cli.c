/*
 * cli.c - command dispatch, help and version.
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "refray.h"
#include "cli/cli.h"
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"

static const char usage_text[] =
    "usage: refray COMMAND [OPTIONS] [FILE...]\n"
    "\n"
    "A verified reference ray tracer for hand-written .scene files.\n"
    "\n"
    "commands:\n"
    "  check FILE...        parse and validate scenes, print a one-line summary each\n"
    "  render SCENE -o OUT  render to OUT (.png .exr .pfm .ppm, chosen by extension);\n"
    "                       --jobs N, --tile I/N, --region, --checkpoint DIR for big ones\n"
    "  merge TILE... -o OUT put the tiles of one render together (spec/scaling.md)\n"
    "  export SCENE --to pov|json  write the scene as POV-Ray SDL or as JSON\n"
    "                       (spec/json.md; -o OUT, else stdout)\n"
    "  verify SCENE...      render analytic scenes and compare with their exact images\n"
    "  oracle SCENE -o OUT  write the exact image of an analytic scene (.exr .pfm)\n"
    "  compare A B          compare image A with the reference B, --diff MAP for a map\n"
    "  kit -o DIR           write the conformance kit: scenes, exact images, manifest\n"
    "  conform --cmd CMD    run another renderer over a kit and check every image\n"
    "\n"
    "options of every command that reads scenes:\n"
    "  -W, --no-warnings          do not print warnings\n"
    "  --max-width N, --max-height N, --max-pixels N, --max-samples N,\n"
    "  --max-light-samples N, --max-depth-limit N, --max-loop N,\n"
    "  --max-include-depth N, --max-file-size BYTES, --max-mesh-triangles N,\n"
    "  --max-primitives N, --max-errors N, --max-ray-tree N,\n"
    "  --max-input-size BYTES, --max-memory MIB\n"
    "                             raise or lower the input limits\n"
    "  --allow-read DIR           let include and mesh files come from DIR too\n"
    "                             (by default only from the scene's directory tree)\n"
    "\n"
    "  refray --help | -h         this text\n"
    "  refray --version           the version\n"
    "  refray --features          the optional parts built in (png exr json)\n"
    "  refray COMMAND --help      the options of one command\n"
    "\n"
    "exit codes: 0 ok, 1 a check failed, 64 usage, 65 bad scene, 66 missing input,\n"
    "70 out of memory, 74 I/O error, 128 + N stopped by signal N (130 SIGINT,\n"
    "143 SIGTERM, 129 SIGHUP).  The language: spec/language.md;\n"
    "limits, signals and output files: spec/reliability.md.\n";

/* One line naming the optional parts this build has, so scripts can ask
 * (`refray --features | grep -qw json`). */
static int cli_features(void)
{
    const char *parts[3];
    int n = 0;
#ifdef REFRAY_HAVE_PNG
    parts[n++] = "png";
#endif
#ifdef REFRAY_HAVE_EXR
    parts[n++] = "exr";
#endif
    if (scene_json_available())
        parts[n++] = "json";
    for (int i = 0; i < n; i++)
        printf("%s%s", i ? " " : "", parts[i]);
    printf("\n");
    return STATUS_OK;
}

int cli_main(int argc, char **argv)
{
    cli_signal_install();
    if (argc < 2)
        return cli_usage_error("no command given");
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        fputs(usage_text, stdout);
        return STATUS_OK;
    }
    if (strcmp(cmd, "--version") == 0) {
        printf("refray %s\n", rf_version());
        return STATUS_OK;
    }
    if (strcmp(cmd, "--features") == 0)
        return cli_features();
    if (strcmp(cmd, "check") == 0)
        return cli_check(argc - 1, argv + 1);
    if (strcmp(cmd, "render") == 0)
        return cli_render(argc - 1, argv + 1);
    if (strcmp(cmd, "export") == 0)
        return cli_export(argc - 1, argv + 1);
    if (strcmp(cmd, "verify") == 0)
        return cli_verify(argc - 1, argv + 1);
    if (strcmp(cmd, "oracle") == 0)
        return cli_oracle(argc - 1, argv + 1);
    if (strcmp(cmd, "compare") == 0)
        return cli_compare(argc - 1, argv + 1);
    if (strcmp(cmd, "kit") == 0)
        return cli_kit(argc - 1, argv + 1);
    if (strcmp(cmd, "conform") == 0)
        return cli_conform(argc - 1, argv + 1);
    if (strcmp(cmd, "merge") == 0)
        return cli_merge(argc - 1, argv + 1);
    return cli_usage_error("unknown command '%s'", cmd);
}
