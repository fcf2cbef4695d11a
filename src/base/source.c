/*
 * source.c - file texts and byte-offset spans (see source.h).
 */
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

void source_set_init(source_set *set, const mem *m)
{
    set->files = NULL;
    set->count = 0;
    set->cap = 0;
    set->mem = mem_pick(m);
}

static void source_file_free(const mem *m, source_file *f)
{
    mem_free_string(m, f->path);
    if (f->text && !f->lent)
        mem_free(m, f->text, f->len + 1);
    mem_free(m, f->line_start, f->line_cap * sizeof *f->line_start);
    mem_free(m, f, sizeof *f);
}

void source_set_free(source_set *set)
{
    mem m = set->mem;
    for (int i = 0; i < set->count; i++)
        source_file_free(&m, set->files[i]);
    mem_free(&m, set->files, (size_t)set->cap * sizeof *set->files);
    source_set_init(set, &m);
}

/* Records where every line starts; "\n", "\r\n" and a lone "\r" all end a line. */
static int index_lines(const mem *m, source_file *f)
{
    size_t cap = 64, count = 0;
    size_t *starts = mem_alloc(m, cap * sizeof *starts);
    if (!starts)
        return 0;
    starts[count++] = 0;
    for (size_t i = 0; i < f->len; i++) {
        int ends = f->text[i] == '\n' || (f->text[i] == '\r' && (i + 1 >= f->len || f->text[i + 1] != '\n'));
        if (!ends)
            continue;
        if (count == cap) {
            size_t *grown = mem_resize_array(m, starts, cap, 2 * cap, sizeof *starts);
            if (!grown) {
                mem_free(m, starts, cap * sizeof *starts);
                return 0;
            }
            starts = grown;
            cap *= 2;
        }
        starts[count++] = i + 1;
    }
    f->line_start = starts;
    f->line_count = count;
    f->line_cap = cap;
    return 1;
}

static int grow_set(source_set *set)
{
    if (set->count < set->cap)
        return 1;
    int cap = set->cap ? 2 * set->cap : 8;
    source_file **files = mem_resize_array(&set->mem, set->files, (size_t)set->cap, (size_t)cap, sizeof *files);
    if (!files)
        return 0;
    set->files = files;
    set->cap = cap;
    return 1;
}

int source_set_add(source_set *set, const char *path, const char *text, size_t len,
                   src_span included_from)
{
    source_file *f = mem_calloc(&set->mem, 1, sizeof *f);
    if (!f || !grow_set(set))
        goto fail;
    f->len = len;
    f->path = mem_strdup(&set->mem, path);
    f->text = mem_strndup(&set->mem, text, len);
    if (!f->path || !f->text)
        goto fail;
    f->included_from = included_from;
    if (!index_lines(&set->mem, f))
        goto fail;
    set->files[set->count] = f;
    return set->count++;
fail:
    if (f)
        source_file_free(&set->mem, f);
    return -1;
}

int source_set_lend(source_set *set, const char *path, const char *text, size_t len, src_span included_from)
{
    source_file *f = mem_calloc(&set->mem, 1, sizeof *f);
    if (!f || !grow_set(set) || !(f->path = mem_strdup(&set->mem, path))) {
        mem_free(&set->mem, f, sizeof *f);
        return -1;
    }
    /* Never written through: the set only reads a lent text. */
    f->text = (char *)(text ? text : "");
    f->len = len;
    f->lent = 1;
    f->included_from = included_from;
    set->files[set->count] = f;
    return set->count++;
}

void source_set_release(source_set *set, int file)
{
    source_file *f = set->files[file];
    if (f->text && !f->lent)
        mem_free(&set->mem, f->text, f->len + 1);
    mem_free(&set->mem, f->line_start, f->line_cap * sizeof *f->line_start);
    f->text = NULL;
    f->len = 0;
    f->line_start = NULL;
    f->line_count = f->line_cap = 0;
    f->lent = 0;
}

/* The line holding offset: its number from 0 and where it starts.  With
 * the index, a binary search for the last line starting at or before
 * offset; without (a lent file), a scan from the start. */
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
