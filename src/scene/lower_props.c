/*
 * lower_props.c - reading a block's properties: which are allowed, how many
 * values each takes, and typed access with defaults.  Every error points at
 * the offending value, not at the block.
 */
#include <math.h>
#include <string.h>
#include "scene/loader.h"
#include "base/suggest.h"

static int is_transform(int kw)
{
    return kw == KW_TRANSLATE || kw == KW_ROTATE || kw == KW_SCALE;
}

static const char *block_name(const ast *block)
{
    return keyword_name((keyword_id)block->keyword);
}

/* A property this block does not take. */
static void report_foreign(loader *L, const ast *block, const ast *prop, const block_schema *schema)
{
    char list[256];
    schema_list(schema, list, sizeof list);
    diag_report(&L->diag, DIAG_ERROR, prop->head, "%s has no property '%s' (it takes %s)", block_name(block),
                keyword_name((keyword_id)prop->keyword), list);
}

/* `radius 1 radus 2` parses as three values of radius; when the first extra
 * value is a bare unknown name, it is really a misspelt property. */
static int report_misspelt_extra(loader *L, const ast *block, const ast *extra, const block_schema *schema)
{
    if (extra->kind != AST_NAME || env_find(&L->env, extra->text))
        return 0;
    const char *names[SCHEMA_MAX_PROPS];
    for (int i = 0; i < schema->prop_count; i++)
        names[i] = keyword_name(schema->props[i]);
    const char *hint = suggest_nearest(extra->text, strlen(extra->text), names, schema->prop_count);
    if (!hint)
        return 0;
    diag_report(&L->diag, DIAG_ERROR, extra->span, "unknown property '%s' in %s; did you mean '%s'?",
                extra->text, block_name(block), hint);
    return 1;
}

/* `rectangle c u -v` reads as the two values c and u - v: when values are
 * missing and one of them is a sum or difference, say so. */
static const char *sign_hint(const ast *prop)
{
    for (const ast *k = prop->first; k; k = k->next)
        if (k->kind == AST_BINARY && (k->op == '+' || k->op == '-'))
            return " (`a -b` is a subtraction; write `a (-b)` for two values)";
    return "";
}

/* `sphere { center radius 1 }`: a property word right after a property
 * that still waits for values is a name ([LANG-LEX-WORD-3]), so `radius`
 * became center's value.  When a value is such a word of this block and no
 * constant of that name exists, the property before it lost its value. */
static int report_swallowed(loader *L, const ast *prop, const block_schema *schema)
{
    if (prop->keyword == KW_MATERIAL || prop->keyword == KW_FALLOFF)
        return 0;   /* these take a bare name, which may be any word */
    for (const ast *k = prop->first; k; k = k->next) {
        int id = k->kind == AST_NAME ? keyword_lookup(k->text, strlen(k->text)) : -1;
        if (id < 0 || !schema_has(schema, (keyword_id)id) || env_find(&L->env, k->text))
            continue;
        diag_report(&L->diag, DIAG_ERROR, k->span,
                    "'%s' is missing a value: '%s' is read as its value here (a property word starts a "
                    "property only once the one before has all its values)",
                    keyword_name((keyword_id)prop->keyword), k->text);
        return 1;
    }
    return 0;
}

static int check_arity(loader *L, const ast *block, const ast *prop, const block_schema *schema)
{
    int arity = keyword_get((keyword_id)prop->keyword)->arity;
    if (report_swallowed(L, prop, schema))
        return 0;
    if (prop->count == arity)
        return 1;
    if (prop->count > arity) {
        const ast *extra = prop->first;
        for (int i = 0; i < arity; i++)
            extra = extra->next;
        if (report_misspelt_extra(L, block, extra, schema))
            return 0;
        diag_report(&L->diag, DIAG_ERROR, extra->span, "'%s' takes %d value%s, got %d",
                    keyword_name((keyword_id)prop->keyword), arity, arity == 1 ? "" : "s", prop->count);
    } else {
        diag_report(&L->diag, DIAG_ERROR, prop->span, "'%s' takes %d value%s, got %d%s",
                    keyword_name((keyword_id)prop->keyword), arity, arity == 1 ? "" : "s", prop->count,
                    sign_hint(prop));
    }
    return 0;
}

static int note_duplicate(loader *L, const ast *prop, const ast *first)
{
    int line, col;
    source_line_col(L->scene->sources.files[first->head.file], first->head.begin, &line, &col);
    diag_report(&L->diag, DIAG_ERROR, prop->head, "'%s' given twice (first at line %d)",
                keyword_name((keyword_id)prop->keyword), line);
    return 0;
}

static int collect_one(loader *L, const ast *block, const ast *prop, const block_schema *schema, props *out)
{
    if (!schema_has(schema, (keyword_id)prop->keyword)) {
        report_foreign(L, block, prop, schema);
        return 0;
    }
    if (!check_arity(L, block, prop, schema))
        return 0;
    if (is_transform(prop->keyword)) {
        if (out->xform_count == PROPS_MAX_XFORMS) {
            diag_report(&L->diag, DIAG_ERROR, prop->head, "more than %d transforms on one primitive",
                        PROPS_MAX_XFORMS);
            return 0;
        }
        out->xforms[out->xform_count++] = prop;
        return 1;
    }
    if (out->by_keyword[prop->keyword])
        return note_duplicate(L, prop, out->by_keyword[prop->keyword]);
    out->by_keyword[prop->keyword] = prop;
    return 1;
}

int props_collect(loader *L, const ast *block, props *out)
{
    /* xforms past xform_count is never read: not cleared (512 of the
     * struct's 1 160 bytes, cleared once per primitive before). */
    memset(out->by_keyword, 0, sizeof out->by_keyword);
    out->xform_count = 0;
    out->block = block;
    const block_schema *schema = schema_of((keyword_id)block->keyword);
    int ok = 1;
    for (const ast *prop = block->first; prop; prop = prop->next)
        ok &= collect_one(L, block, prop, schema, out);
    return ok;
}

src_span props_value_span(const props *p, keyword_id kw)
{
    const ast *prop = p->by_keyword[kw];
    if (!prop)
        return p->block->head;
    return prop->first ? prop->first->span : prop->span;
}

int props_require(loader *L, const props *p, keyword_id kw)
{
    if (p->by_keyword[kw])
        return 1;
    diag_report(&L->diag, DIAG_ERROR, p->block->head, "%s needs '%s'", block_name(p->block),
                keyword_name(kw));
    return 0;
}

int props_value_at(loader *L, const ast *node, value_kind kind, value *out)
{
    if (!eval_expr(&L->env, &L->diag, node, out))
        return 0;
    if (out->kind == kind)
        return 1;
    diag_report(&L->diag, DIAG_ERROR, node->span, "expected a %s, got a %s", value_kind_name(kind),
                value_kind_name(out->kind));
    return 0;
}

int props_number(loader *L, const props *p, keyword_id kw, double fallback, double *out)
{
    const ast *prop = p->by_keyword[kw];
    value v;
    *out = fallback;
    if (!prop)
        return 1;
    if (!props_value_at(L, prop->first, VAL_NUMBER, &v))
        return 0;
    *out = v.number;
    return 1;
}

int props_vector(loader *L, const props *p, keyword_id kw, vec3 fallback, vec3 *out)
{
    const ast *prop = p->by_keyword[kw];
    value v;
    *out = fallback;
    if (!prop)
        return 1;
    if (!props_value_at(L, prop->first, VAL_VECTOR, &v))
        return 0;
    *out = v.vector;
    return 1;
}

/* A colour is a vector [r, g, b], or one number meaning grey. */
int props_color(loader *L, const props *p, keyword_id kw, rgb fallback, rgb *out)
{
    const ast *prop = p->by_keyword[kw];
    value v;
    *out = fallback;
    if (!prop)
        return 1;
    if (!eval_expr(&L->env, &L->diag, prop->first, &v))
        return 0;
    if (v.kind == VAL_STRING) {
        diag_report(&L->diag, DIAG_ERROR, v.span, "expected a colour (a number or [r, g, b]), got a string");
        return 0;
    }
    *out = v.kind == VAL_NUMBER ? vec_splat(v.number) : v.vector;
    return 1;
}

static src_span props_field_span(const void *ctx, int field)
{
    const props *p = ctx;
    if (field >= KEYWORD_COUNT)
        return p->block->head;
    return props_value_span(p, (keyword_id)field);
}

check_at props_at(const props *p)
{
    check_at at;
    at.span = props_field_span;
    at.ctx = p;
    return at;
}

/* A bare word such as a material or falloff name: not looked up as a constant. */
int props_name(loader *L, const props *p, keyword_id kw, const char **out, src_span *where)
{
    const ast *prop = p->by_keyword[kw];
    *out = NULL;
    if (!prop)
        return 1;
    *where = prop->first->span;
    if (prop->first->kind != AST_NAME) {
        diag_report(&L->diag, DIAG_ERROR, prop->first->span, "expected a name after '%s'", keyword_name(kw));
        return 0;
    }
    *out = prop->first->text;
    return 1;
}

int props_string(loader *L, const props *p, keyword_id kw, const char **out, src_span *where)
{
    const ast *prop = p->by_keyword[kw];
    value v;
    *out = NULL;
    if (!prop)
        return 1;
    *where = prop->first->span;
    if (!props_value_at(L, prop->first, VAL_STRING, &v))
        return 0;
    *out = v.text;
    return 1;
}

int loader_unit(vec3 v, vec3 *out)
{
    double m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    if (!(m > 0) || !isfinite(m))
        return 0;
    *out = vec_normalize(vec_make(v.x / m, v.y / m, v.z / m));
    return 1;
}
