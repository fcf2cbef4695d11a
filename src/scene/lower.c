/*
 * lower.c - walks the statements of a scene in order: constants, loops,
 * includes and blocks.  Constants are bound when their `let` is reached, so
 * a name can be used only after it is defined; the same holds for materials.
 */
#include <limits.h>
#include <math.h>
#include <string.h>
#include "scene/loader.h"
#include "lang/parse.h"
#include "base/suggest.h"

static void note_first(loader *L, src_span first)
{
    diag_report(&L->diag, DIAG_NOTE, first, "first defined here");
}

static int lower_let(loader *L, const ast *node)
{
    if (node->keyword >= 0) {
        diag_report(&L->diag, DIAG_ERROR, node->head, "'%s' is a reserved word and cannot name a constant",
                    node->text);
        return 0;
    }
    if (strcmp(node->text, "pi") == 0) {
        diag_report(&L->diag, DIAG_ERROR, node->head, "'pi' is built in and cannot be redefined");
        return 0;
    }
    const binding *old = env_find(&L->env, node->text);
    if (old) {
        diag_report(&L->diag, DIAG_ERROR, node->head, "'%s' is already defined", node->text);
        note_first(L, old->where);
        return 0;
    }
    value v;
    if (!eval_expr(&L->env, &L->diag, node->first, &v))
        return 0;
    if (!env_bind(&L->env, node->text, v, node->head)) {
        loader_oom(L);
        return 0;
    }
    return 1;
}

static int loop_bound(loader *L, const ast *node, double *out)
{
    value v;
    if (!eval_expr(&L->env, &L->diag, node, &v))
        return 0;
    if (v.kind != VAL_NUMBER || v.number != floor(v.number)) {
        diag_report(&L->diag, DIAG_ERROR, node->span, "a loop bound must be a whole number");
        return 0;
    }
    *out = v.number;
    return 1;
}

/* The loop's iteration count is checked against the limits before the
 * first iteration runs, so `0 .. 1e12` is refused at once. */
static int loop_count(loader *L, const ast *node, double from, double to, long *count)
{
    double n = to >= from ? to - from + 1 : 0;
    long max = L->limits->max_loop_iterations;
    src_span range = src_span_join(node->first->span, node->first->next->span);
    if (n > (double)max) {
        diag_report(&L->diag, DIAG_ERROR, range, "this loop would run %.17g times, over the limit of %ld (--max-loop)",
                    n, max);
        return 0;
    }
    if ((double)L->loop_iterations + n > (double)max) {
        diag_report(&L->diag, DIAG_ERROR, range,
                    "this loop would bring the iterations of the scene to %.17g, over the limit of %ld (--max-loop)",
                    (double)L->loop_iterations + n, max);
        return 0;
    }
    if (n == 0)
        diag_report(&L->diag, DIAG_WARNING, node->first->span, "this loop runs 0 times (%.17g > %.17g)", from, to);
    *count = (long)n;
    return 1;
}

/* Enters one more level of loops and includes; 0 after the error when
 * that passes LOADER_MAX_NESTING. */
static int nest(loader *L, src_span at)
{
    if (L->nesting >= LOADER_MAX_NESTING) {
        diag_report(&L->diag, DIAG_ERROR, at, "nesting too deep: loops and includes nest more than %d deep in all",
                    LOADER_MAX_NESTING);
        L->too_deep = 1;
        return 0;
    }
    L->nesting++;
    return 1;
}

/* One pass of a loop body with the variable bound to x.  An error in the
 * body would repeat on every pass, so the loop stops at the first one, and
 * a note says which pass it was (unless the error limit hid the error). */
static int loop_pass(loader *L, const ast *node, double x)
{
    int mark = L->env.count, errors = L->diag.errors;
    value v = {VAL_NUMBER, x, {0, 0, 0}, NULL, node->head};
    if (!env_bind(&L->env, node->text, v, node->head)) {
        loader_oom(L);
        return 0;
    }
    int ok = lower_statements(L, node->first->next->next);
    env_restore(&L->env, mark);
    if (!ok && L->diag.errors > errors && !diag_too_many(&L->diag) && !L->too_deep)
        diag_report(&L->diag, DIAG_NOTE, node->head, "in the pass where %s = %.17g", node->text, x);
    return ok;
}

static int lower_for(loader *L, const ast *node)
{
    /* Zeroed, though read only where loop_bound set them: gcc -O3 cannot
     * see that through the `ok &=` below (maybe-uninitialized under
     * -Werror). */
    double from = 0, to = 0;
    long count;
    /* Both bounds are checked, so both errors are reported. */
    int ok = loop_bound(L, node->first, &from);
    ok &= loop_bound(L, node->first->next, &to);
    if (!ok)
        return 0;
    const binding *old = env_find(&L->env, node->text);
    if (old || strcmp(node->text, "pi") == 0) {
        diag_report(&L->diag, DIAG_ERROR, node->head, "loop variable '%s' hides a constant of the same name",
                    node->text);
        if (old)
            note_first(L, old->where);
        return 0;
    }
    if (!loop_count(L, node, from, to, &count))
        return 0;
    L->loop_iterations += count;
    if (count > 0 && !nest(L, node->head))
        return 0;
    for (long i = 0; i < count; i++)
        if (!loop_pass(L, node, from + (double)i)) {
            ok = 0;
            break;
        }
    L->nesting -= count > 0;
    return ok;
}

static int on_include_stack(const loader *L, const char *resolved)
{
    for (int i = 0; i < L->include_depth; i++)
        if (strcmp(L->include_stack[i], resolved) == 0)
            return 1;
    return 0;
}

/* The resolver is asked first; its failure is reported only when the
 * statement is not already wrong as a cycle or as too deep, in that order. */
static int lower_include(loader *L, const ast *node)
{
    char why[512], *identity = NULL;
    int file = loader_fetch(L, node->text, node->span, &identity, why, sizeof why);
    if (L->out_of_memory)
        return 0;
    int ok = 0;
    if (file >= 0 && on_include_stack(L, identity))
        diag_report(&L->diag, DIAG_ERROR, node->head, "include cycle: '%s' is already being read", node->text);
    else if (L->include_depth > L->limits->max_include_depth) /* the root file is not an include */
        diag_report(&L->diag, DIAG_ERROR, node->head, "includes nested more than %ld deep (--max-include-depth)",
                    L->limits->max_include_depth);
    else if (file < 0)
        diag_report(&L->diag, DIAG_ERROR, node->head, "%s", why);
    else if (nest(L, node->head)) {
        ok = loader_lower_file(L, file, identity);
        identity = NULL;
        L->nesting--;
    }
    mem_free_string(L->mem, identity);
    return ok;
}

static int lower_oracle(loader *L, const ast *node)
{
    scene_model *s = L->scene;
    if (s->oracle) {
        diag_report(&L->diag, DIAG_ERROR, node->head, "a scene names one oracle; '%s' is already named", s->oracle);
        return 0;
    }
    s->oracle = loader_strdup(L, node->text);
    if (!s->oracle)
        return 0;
    s->oracle_where = node->head;
    return 1;
}

static int lower_block(loader *L, const ast *node)
{
    switch (node->keyword) {
    case KW_MATERIAL: return lower_material_def(L, node);
    case KW_IMAGE: return lower_image(L, node);
    case KW_CAMERA: return lower_camera(L, node);
    case KW_AMBIENT: return lower_ambient(L, node);
    case KW_POINT_LIGHT:
    case KW_DISTANT_LIGHT:
    case KW_DISTRIBUTED_LIGHT: return lower_light(L, node);
    case KW_SPHERE:
    case KW_PLANE:
    case KW_TRIANGLE:
    case KW_DISK:
    case KW_BOX:
    case KW_CYLINDER:
    case KW_CONE:
    case KW_TORUS:
    case KW_MESH: return lower_primitive(L, node);
    default:
        diag_report(&L->diag, DIAG_ERROR, node->head, "'%s' is a property, not a statement",
                    keyword_name((keyword_id)node->keyword));
        return 0;
    }
}

static int lower_statement(loader *L, const ast *node)
{
    switch (node->kind) {
    case AST_LET: return lower_let(L, node);
    case AST_FOR: return lower_for(L, node);
    case AST_INCLUDE: return lower_include(L, node);
    case AST_ORACLE: return lower_oracle(L, node);
    default: return lower_block(L, node);
    }
}

/* Lowers every statement (to report as many errors as the limit allows);
 * returns 1 when all of them were valid. */
int lower_statements(loader *L, const ast *list)
{
    int ok = 1;
    for (const ast *node = list->first; node && !loader_stop(L); node = node->next)
        ok &= lower_statement(L, node);
    return ok && !loader_stop(L);
}

int loader_lower_file(loader *L, int file, char *identity)
{
    if (L->include_depth == L->include_cap) {
        int cap = L->include_cap ? 2 * L->include_cap : 8;
        char **stack = mem_resize_array(L->mem, L->include_stack, (size_t)L->include_cap, (size_t)cap,
                                        sizeof *stack);
        if (!stack) {
            mem_free_string(L->mem, identity);
            loader_oom(L);
            return 0;
        }
        L->include_stack = stack;
        L->include_cap = cap;
    }
    L->include_stack[L->include_depth++] = identity;
    /* Each file is parsed once per load; a loop that includes it again
     * lowers the same tree.  (L->files may move while the tree is
     * lowered: it is indexed afresh.) */
    if (!L->files[file].tree && !L->files[file].parse_failed) {
        int errors = L->diag.errors;
        ast *parsed = parse_file(&L->arena, &L->diag, &L->scene->sources, file);
        if (!parsed && !cancel_stopped(&L->cancel))
            loader_oom(L);
        L->files[file].tree = parsed;
        L->files[file].parse_failed = !parsed || L->diag.errors > errors;
    }
    ast *tree = L->files[file].parse_failed ? NULL : L->files[file].tree;
    const ast *includer = L->tree;
    L->tree = tree;
    int ok = tree && lower_statements(L, tree);
    L->tree = includer;
    /* Nested includes may have moved the stack: index it afresh. */
    mem_free_string(L->mem, L->include_stack[--L->include_depth]);
    return ok;
}
