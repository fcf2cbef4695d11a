/*
 * source.c - file texts and byte-offset spans (see source.h).
 */
#include <stdlib.h>
#include <string.h>
#include "base/source.h"

src_span src_span_none(void)
{
    src_span s = {-1, 0, 0};
    return s;
}

/* The smallest span covering both; a located span wins over an unlocated one. */
src_span src_span_join(src_span a, src_span b)
{
    if (a.file < 0)
        return b;
    if (b.file < 0 || b.file != a.file)
        return a;
    a.begin = a.begin < b.begin ? a.begin : b.begin;
    a.end = a.end > b.end ? a.end : b.end;
    return a;
}

void source_set_init(source_set *set)
{
    set->files = NULL;
    set->count = 0;
    set->cap = 0;
}

static void source_file_free(source_file *f)
{
    free(f->path);
    free(f->text);
    free(f->line_start);
    free(f);
}

void source_set_free(source_set *set)
{
    for (int i = 0; i < set->count; i++)
        source_file_free(set->files[i]);
    free(set->files);
    source_set_init(set);
}

/* Records where every line starts; "\n", "\r\n" and a lone "\r" all end a line. */
static int index_lines(source_file *f)
{
    size_t cap = 64, count = 0;
    size_t *starts = malloc(cap * sizeof *starts);
    if (!starts)
        return 0;
    starts[count++] = 0;
    for (size_t i = 0; i < f->len; i++) {
        int ends = f->text[i] == '\n' || (f->text[i] == '\r' && (i + 1 >= f->len || f->text[i + 1] != '\n'));
        if (!ends)
            continue;
        if (count == cap) {
            size_t *grown = realloc(starts, 2 * cap * sizeof *starts);
            if (!grown) {
                free(starts);
                return 0;
            }
            starts = grown;
            cap *= 2;
        }
        starts[count++] = i + 1;
    }
    f->line_start = starts;
    f->line_count = count;
    return 1;
}

static int grow_set(source_set *set)
{
    if (set->count < set->cap)
        return 1;
    int cap = set->cap ? 2 * set->cap : 8;
    source_file **files = realloc(set->files, (size_t)cap * sizeof *files);
    if (!files)
        return 0;
    set->files = files;
    set->cap = cap;
    return 1;
}

int source_set_add(source_set *set, const char *path, const char *text, size_t len,
                   src_span included_from)
{
    source_file *f = calloc(1, sizeof *f);
    if (!f || !grow_set(set))
        goto fail;
    f->path = malloc(strlen(path) + 1);
    f->text = malloc(len + 1);
    if (!f->path || !f->text)
        goto fail;
    strcpy(f->path, path);
    memcpy(f->text, text, len);
    f->text[len] = '\0';
    f->len = len;
    f->included_from = included_from;
    if (!index_lines(f))
        goto fail;
    set->files[set->count] = f;
    return set->count++;
fail:
    if (f)
        source_file_free(f);
    return -1;
}

int source_set_adopt(source_set *set, const char *path, char *text, size_t len, src_span included_from)
{
    source_file *f = calloc(1, sizeof *f);
    if (!f || !grow_set(set) || !(f->path = malloc(strlen(path) + 1))) {
        free(f);
        free(text);
        return -1;
    }
    strcpy(f->path, path);
    f->text = text;
    f->len = len;
    f->included_from = included_from;
    set->files[set->count] = f;
    return set->count++;
}

void source_set_release(source_set *set, int file)
{
    source_file *f = set->files[file];
    free(f->text);
    free(f->line_start);
    f->text = NULL;
    f->len = 0;
    f->line_start = NULL;
    f->line_count = 0;
}

/* The line holding offset: its number from 0 and where it starts.  With
 * the index, a binary search for the last line starting at or before
 * offset; without (an adopted file), a scan from the start. */
static size_t line_index(const source_file *file, size_t offset, size_t *begin)
{
    if (!file->line_start) {
        size_t line = 0;
        *begin = 0;
        for (size_t i = 0; i < offset && i < file->len; i++) {
            char c = file->text[i];
            if (c == '\n' || (c == '\r' && (i + 1 >= file->len || file->text[i + 1] != '\n'))) {
                line++;
                *begin = i + 1;
            }
        }
        return line;
    }
    size_t lo = 0, hi = file->line_count;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (file->line_start[mid] <= offset)
            lo = mid;
        else
            hi = mid;
    }
    *begin = file->line_start[lo];
    return lo;
}

void source_line_col(const source_file *file, size_t offset, int *line, int *col)
{
    size_t begin, i = line_index(file, offset, &begin);
    *line = (int)i + 1;
    *col = (int)(offset - begin) + 1;
}

const char *source_line_text(const source_file *file, size_t offset, size_t *length)
{
    size_t begin;
    line_index(file, offset, &begin);
    size_t end = begin;
    while (end < file->len && file->text[end] != '\n' && file->text[end] != '\r')
        end++;
    *length = end - begin;
    return file->text + begin;
}
