/*
 * cli_progress.c - see cli_progress.h.
 */
#include <stdio.h>
#include <unistd.h>
#include "cli/cli_progress.h"
#include "render/render.h"

void cli_progress_init(cli_progress *p, int show, long base)
{
    p->show = show && isatty(2);
    p->start = render_clock();
    p->base = base;
    p->last = -1;
}

void cli_progress_show(cli_progress *p, long done, long total)
{
    int permille = total > 0 ? (int)(1000 * done / total) : 1000;
    if (!p->show || permille == p->last)
        return;
    p->last = permille;
    double elapsed = render_clock() - p->start;
    long fresh = done - p->base;
    double eta = fresh > 0 ? elapsed * (double)(total - done) / (double)fresh : 0;
    int width = 40, filled = (int)((long)width * done / total);
    fprintf(stderr, "\r[%-*.*s] %3d%%  %.1fs elapsed, ETA %.1fs ", width, filled,
            "########################################", permille / 10, elapsed, eta);
    if (done == total)
        fputc('\n', stderr);
    fflush(stderr);
}

const char *cli_progress_break(const cli_progress *p)
{
    return p->show && p->last >= 0 && p->last < 1000 ? "\n" : "";
}
