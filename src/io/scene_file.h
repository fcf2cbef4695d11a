/*
 * scene_file.h - scenes that live in files: the resolver that reads
 * `include` and `mesh` files from the file system, the choice between the
 * scene language and JSON by the file's name, and loading a scene file
 * with its diagnostics printed to a stream.  The core (scene.h) reads
 * nothing itself; this is where the file system comes in.
 */
#ifndef REFRAY_SCENE_FILE_H
#define REFRAY_SCENE_FILE_H

#include <stdio.h>
#include "base/names.h"
#include "scene/scene.h"

/* The file resolver's state: the size limit, the allocator of what it
 * reads (the load's), and the identities of the files it has delivered,
 * so that a file is read once per load ([REL-INPUT-1]). */
typedef struct scene_file_reader {
    long max_bytes;     /* per file (--max-file-size); < 0: no limit */
    mem mem;
    char **delivered;   /* identities given with their text so far */
    int delivered_count, delivered_cap;
    name_index index;   /* over delivered */
    char **roots;       /* real paths of the directories files may come
                           from ([REL-READ-1]) */
    int root_count, root_cap;
    int anywhere;       /* 1: read anywhere, roots unused (the host's
                           explicit choice, scene_file_reader_anywhere) */
} scene_file_reader;

/* A reader for one load; must not move until scene_file_reader_free.
 * It starts confined to no directory at all ([REL-READ-1]): it reads
 * nothing until scene_file_reader_confine gives it its directories or
 * scene_file_reader_anywhere lets it read anywhere, so a caller that
 * forgets to choose gets an error, not an unconfined load. */
void scene_file_reader_init(scene_file_reader *f, long max_bytes, const mem *m);
void scene_file_reader_free(scene_file_reader *f);

/* Lets f read any file the process can: the library's default, a host's
 * choice (rf_load_options.read_confined 0); never the program's. */
void scene_file_reader_anywhere(scene_file_reader *f);

/*
 * Confines f to the directory tree of scene_path and of each of dirs (a
 * NULL-terminated list; NULL: none) ([REL-READ-1]): a file is read only
 * when its real path (every symbolic link resolved; for a file that does
 * not exist, its directory's) lies in one of them; otherwise the fetch
 * fails with STATUS_DATA and a reason naming the real path and the
 * --allow-read option.  A directory that does not resolve is left out.
 * STATUS_OK or STATUS_NO_MEMORY.
 */
int scene_file_reader_confine(scene_file_reader *f, const char *scene_path, const char *const *dirs);

/*
 * A resolver over the file system: `name` is read relative to the
 * directory of the including file's path (as written, not resolved), only
 * if it is a regular file of at most max_bytes; its identity is its real
 * path (realpath), so an include cycle is found under any spelling.  A
 * file delivered before is answered as `known`, not read again.
 */
scene_resolver scene_file_resolver(scene_file_reader *files);

/* Whether path names a JSON scene (spec/json.md): it ends in ".json", in
 * any case.  Every loader below reads such a file as JSON. */
int scene_file_is_json(const char *path);

/* root in the format its path names: scene_load_json_source for a JSON
 * scene, else scene_load_source. */
scene_model *scene_file_load_source(const scene_source *root, const scene_load_opts *o, int *status);

/*
 * Reads the scene file path and loads it with o (NULL: the defaults); when
 * o has no resolver, includes and meshes come from files (with o's
 * --max-file-size), confined to path's directory tree ([REL-READ-1]).  A file that cannot be read is reported through
 * o->sink without a location, and *status is file_read_all's
 * (STATUS_NO_INPUT, STATUS_DATA over the size limit, STATUS_IO,
 * STATUS_NO_MEMORY).  Otherwise as scene_file_load_source.
 */
scene_model *scene_file_load_with(const char *path, const scene_load_opts *o, int *status);

/* scene_file_load_with whose file resolver (when o has none) is confined
 * to path's directory tree and those of read_dirs (scene_file_reader_confine;
 * read_dirs NULL: none besides path's). */
scene_model *scene_file_load_confined(const char *path, const scene_load_opts *o, const char *const *read_dirs,
                                      int *status);

/* scene_file_load_with whose file resolver reads anywhere: only for a
 * library host that did not ask for confinement (rf_load_options). */
scene_model *scene_file_load_anywhere(const char *path, const scene_load_opts *o, int *status);

/*
 * The short forms the program and the tests use: the default options but
 * limits (NULL: the defaults) and warnings, diagnostics printed to diag_out
 * (NULL: none), includes and meshes from files in path's directory tree.
 * scene_file_load_text takes the root's text from memory; path names it in
 * messages and is where its includes are looked for (and its tree).
 */
scene_model *scene_file_load(const char *path, const scene_limits *limits, FILE *diag_out, int warnings,
                             int *status);
scene_model *scene_file_load_text(const char *path, const char *text, size_t len, const scene_limits *limits,
                                  FILE *diag_out, int warnings, int *status);

/* scene_file_load_text whose files may also come from the trees of
 * read_dirs (NULL-terminated; NULL: none), as --allow-read gives the
 * program: a generated scene naming meshes kept elsewhere. */
scene_model *scene_file_load_text_confined(const char *path, const char *text, size_t len,
                                           const scene_limits *limits, FILE *diag_out, int warnings,
                                           const char *const *read_dirs, int *status);

#endif
