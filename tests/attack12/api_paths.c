/*
 * api_paths.c - rf_scene_load_file on paths that are not regular scene
 * files: a directory, a FIFO nobody writes, /dev/zero, /dev/null, a
 * /proc file, a missing file, and a .json of each.  Each call runs under
 * alarm(10): a hang is killed by SIGALRM.  Prints the status of each.
 *
 *   api_paths DIR     (a scratch directory: the FIFO is made in it)
 */
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <refray.h>

static void try(const char *path)
{
    rf_load_options o;
    rf_scene *s = NULL;
    rf_load_options_init(&o);
    alarm(10);
    rf_status st = rf_scene_load_file(path, &o, &s);
    alarm(0);
    printf("%-40s %s\n", path, rf_status_string(st));
    rf_scene_free(s);
}

int main(int argc, char **argv)
{
    char fifo[4096], fifo_json[4096];
    if (argc != 2)
        return 2;
    snprintf(fifo, sizeof fifo, "%s/fifo.scene", argv[1]);
    snprintf(fifo_json, sizeof fifo_json, "%s/fifo.json", argv[1]);
    unlink(fifo);
    unlink(fifo_json);
    if (mkfifo(fifo, 0600) != 0 || mkfifo(fifo_json, 0600) != 0)
        return 2;
    try(argv[1]);
    try(fifo);
    try(fifo_json);
    try("/dev/zero");
    try("/dev/null");
    try("/proc/self/status");
    try("/nonexistent/x.scene");
    unlink(fifo);
    unlink(fifo_json);
    return 0;
}
