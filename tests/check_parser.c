/* Tests of the grammar (grammar/scene.y) through parse_file: the shapes of
 * statements, operator precedence and associativity written as
 * S-expressions, juxtaposed property values, and syntax errors with their
 * exact wording and recovery.  IDs are those of spec/language.md. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/diag_print.h"
#include "testlib.h"
#include "lang/keywords.h"
#include "lang/parse.h"

typedef struct parsed {
    arena arena;
    source_set sources;
    diag diag;
    char *messages;        /* everything the parse printed */
    size_t size;
    ast *root;
} parsed;

static void parse_bytes(parsed *p, const char *text, size_t len)
{
    memset(p, 0, sizeof *p);
    arena_init(&p->arena, NULL);
    source_set_init(&p->sources, NULL);
    ck_assert_int_eq(source_set_add(&p->sources, "t.scene", text, len, src_span_none()), 0);
    FILE *out = open_memstream(&p->messages, &p->size);
    ck_assert_ptr_nonnull(out);
    diag_init(&p->diag, &p->sources, out ? diag_print : NULL, out);
    p->root = parse_file(&p->arena, &p->diag, &p->sources, 0);
    fclose(out);
    ck_assert_ptr_nonnull(p->root);
}

static void parse_text(parsed *p, const char *text)
{
    parse_bytes(p, text, strlen(text));
}

static void parsed_done(parsed *p)
{
    free(p->messages);
    source_set_free(&p->sources);
    arena_free(&p->arena);
}

static const ast *child(const ast *node, int i)
{
    ck_assert_int_lt(i, node->count);
    const ast *k = node->first;
    while (i-- > 0)
        k = k->next;
    return k;
}

/* The first line of what was printed, without the trailing newline. */
static const char *first_line(parsed *p)
{
    char *nl = p->messages ? strchr(p->messages, '\n') : NULL;
    if (nl)
        *nl = '\0';
    return p->messages ? p->messages : "";
}

/* An expression tree as an S-expression: (op a b), (neg a), [a b c],
 * f(a b) for built-in and unknown calls, "s" for strings. */
static void sexpr(const ast *n, char *buf, size_t size)
{
    size_t used = strlen(buf);
    char *at = buf + used;
    size_t left = size - used;
    switch (n->kind) {
    case AST_NUMBER: snprintf(at, left, "%g", n->number); return;
    case AST_NAME: snprintf(at, left, "%s", n->text); return;
    case AST_STRING: snprintf(at, left, "\"%s\"", n->text); return;
    case AST_NEGATE: snprintf(at, left, "(neg "); break;
    case AST_BINARY: snprintf(at, left, "(%c ", n->op); break;
    case AST_VECTOR: snprintf(at, left, "["); break;
    case AST_CALL:
        snprintf(at, left, "%s%s(", n->keyword >= 0 ? keyword_name((keyword_id)n->keyword) : n->text,
                 n->keyword >= 0 ? "" : "?");
        break;
    default: snprintf(at, left, "<%d>", (int)n->kind); return;
    }
    for (const ast *k = n->first; k; k = k->next) {
        sexpr(k, buf, size);
        if (k->next)
            strncat(buf, " ", size - strlen(buf) - 1);
    }
    strncat(buf, n->kind == AST_VECTOR ? "]" : n->kind == AST_CALL ? ")" : ")", size - strlen(buf) - 1);
}

/* The value of `let x = EXPR` as an S-expression. */
static void expr_shape(const char *expr, char *buf, size_t size)
{
    char text[256];
    parsed p;
    snprintf(text, sizeof text, "let x = %s", expr);
    parse_text(&p, text);
    ck_assert_msg(p.diag.errors == 0, "'%s': %s", expr, first_line(&p));
    ck_assert_int_eq(p.root->count, 1);
    buf[0] = '\0';
    sexpr(child(p.root, 0)->first, buf, size);
    parsed_done(&p);
}

/* The statements of the issue's example, in order and in shape. */
START_TEST(test_parse_file_issue_example)
{
    static const char text[] =
        "# a glass ball over a red floor\n"
        "let r = 1.5\n"
        "image  { width 640  height 480  samples 2  max_depth 8  background [0.05, 0.05, 0.1] }\n"
        "camera { perspective  eye [0, 1, -5]  look_at [0, r, 0]  up [0, 1, 0]  fov 45 }\n"
        "ambient       { color [0.2, 0.2, 0.2] }\n"
        "point_light   { position [5, 10, -5]  power 60  d0 1  falloff linear }\n"
        "distant_light { direction [-1, -1, 1]  power [0.8, 0.8, 0.7] }\n"
        "distributed_light { rectangle [-1, 4, -1] [2, 0, 0] [0, 0, 2]  power 40  samples 16 }\n"
        "material glass { Kd 0  Ks 0.1  n 200  t 0.9  ior 1.5 }\n"
        "material red   { Kd [0.8, 0.1, 0.1]  Ks 0.3  n 40 }\n"
        "sphere { center [0, r, 0]  radius r  material glass }\n"
        "plane  { point [0, 0, 0]  normal [0, 1, 0]  material red }\n"
        "for i in 0 .. 4 { sphere { center [i - 2, 0.3, 2]  radius 0.3  material red  translate [0, 0, 1] } }\n"
        "include \"lamps.scene\"\n";
    static const struct {
        ast_kind kind;
        int keyword;
        const char *text;
        int count;      /* properties, or children */
    } want[] = {
        {AST_LET, -1, "r", 1},
        {AST_BLOCK, KW_IMAGE, NULL, 5},
        {AST_BLOCK, KW_CAMERA, NULL, 5},
        {AST_BLOCK, KW_AMBIENT, NULL, 1},
        {AST_BLOCK, KW_POINT_LIGHT, NULL, 4},
        {AST_BLOCK, KW_DISTANT_LIGHT, NULL, 2},
        {AST_BLOCK, KW_DISTRIBUTED_LIGHT, NULL, 3},
        {AST_BLOCK, KW_MATERIAL, "glass", 5},
        {AST_BLOCK, KW_MATERIAL, "red", 3},
        {AST_BLOCK, KW_SPHERE, NULL, 3},
        {AST_BLOCK, KW_PLANE, NULL, 3},
        {AST_FOR, -1, "i", 3},
        {AST_INCLUDE, -1, "lamps.scene", 0},
    };
    parsed p;
    parse_text(&p, text);
    ck_assert_int_eq(p.diag.errors, 0);
    ck_assert_int_eq(p.root->count, 13);
    for (int i = 0; i < 13; i++) {
        const ast *s = child(p.root, i);
        ck_assert_int_eq(s->kind, want[i].kind);
        ck_assert_int_eq(s->keyword, want[i].keyword);
        if (want[i].text)
            ck_assert_str_eq(s->text, want[i].text);
        ck_assert_int_eq(s->count, want[i].count);
    }
    /* camera: `perspective` has no value, `look_at` one vector naming r. */
    const ast *camera = child(p.root, 2);
    ck_assert_int_eq(child(camera, 0)->keyword, KW_PERSPECTIVE);
    ck_assert_int_eq(child(camera, 0)->count, 0);
    ck_assert_int_eq(child(camera, 2)->keyword, KW_LOOK_AT);
    ck_assert_int_eq(child(child(camera, 2), 0)->kind, AST_VECTOR);
    /* rectangle takes three juxtaposed vectors. */
    const ast *rect = child(child(p.root, 6), 0);
    ck_assert_int_eq(rect->keyword, KW_RECTANGLE);
    ck_assert_int_eq(rect->count, 3);
    /* `falloff linear` and `material glass` keep bare names. */
    ck_assert_int_eq(child(child(child(p.root, 4), 3), 0)->kind, AST_NAME);
    ck_assert_str_eq(child(child(child(p.root, 9), 2), 0)->text, "glass");
    /* for: from, to, then the body's one statement. */
    const ast *loop = child(p.root, 11);
    ck_assert_int_eq(child(loop, 0)->number, 0);
    ck_assert_int_eq(child(loop, 1)->number, 4);
    ck_assert_int_eq(child(loop, 2)->kind, AST_BLOCK);
    ck_assert_int_eq(child(child(loop, 2), 0)->keyword, KW_SPHERE);
    ck_assert_int_eq(child(child(child(loop, 2), 0), 3)->keyword, KW_TRANSLATE);
    parsed_done(&p);
}
END_TEST

/* [LANG-EXPR-PREC-1] precedence from loosest: + -, then * /, then unary
 * minus, then ^ (right associative); + - * / are left associative. */
START_TEST(test_parse_file_precedence)
{
    static const struct {
        const char *expr, *shape;
    } cases[] = {
        {"-2^2", "(neg (^ 2 2))"},
        {"2^-1", "(^ 2 (neg 1))"},
        {"-2^-2", "(neg (^ 2 (neg 2)))"},
        {"2^3^2", "(^ 2 (^ 3 2))"},
        {"1-2-3", "(- (- 1 2) 3)"},
        {"1+2*3", "(+ 1 (* 2 3))"},
        {"(1+2)*3", "(* (+ 1 2) 3)"},
        {"8/2/2", "(/ (/ 8 2) 2)"},
        {"8/2*2", "(* (/ 8 2) 2)"},
        {"-a*b", "(* (neg a) b)"},
        {"a*-b", "(* a (neg b))"},
        {"a - -b", "(- a (neg b))"},
        {"+a", "a"},
        {"--a", "(neg (neg a))"},
        {"2*-3^2", "(* 2 (neg (^ 3 2)))"},
        {"(2^3)^2", "(^ (^ 2 3) 2)"},
        {"[1, a+b, -c]", "[1 (+ a b) (neg c)]"},
        {"[1,2,3]*2 - v", "(- (* [1 2 3] 2) v)"},
        {"sqrt(x)^2", "(^ sqrt(x) 2)"},
        {"max(1, min(2, 3))", "max(1 min(2 3))"},
        {"dot(a, b) + 1", "(+ dot(a b) 1)"},
        {"cross (a, b)", "cross(a b)"},
        {"foo(1, 2)", "foo?(1 2)"},
        {"pi / 2", "(/ pi 2)"},
        {"\"a.obj\"", "\"a.obj\""},
        {"1e3", "1000"},
        {"(((7)))", "7"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char shape[256];
        expr_shape(cases[i].expr, shape, sizeof shape);
        ck_assert_msg(strcmp(shape, cases[i].shape) == 0, "'%s' parsed as %s, expected %s", cases[i].expr, shape,
                      cases[i].shape);
    }
}
END_TEST

/* [LANG-PROP-JUXT-1] a property's values follow it side by side; a value
 * after the first may not begin with a sign, so `a -b` is a - b. */
START_TEST(test_parse_file_juxtaposed_values)
{
    static const struct {
        const char *text;
        int values;
        const char *first, *second;
    } cases[] = {
        {"sphere { radius a -b }", 1, "(- a b)", NULL},
        {"sphere { radius a - b }", 1, "(- a b)", NULL},
        {"sphere { radius a +b }", 1, "(+ a b)", NULL},
        {"sphere { radius -a }", 1, "(neg a)", NULL},
        {"sphere { radius 2 * 3 4 }", 2, "(* 2 3)", "4"},
        {"sphere { radius 1 (2) }", 2, "1", "2"},
        {"sphere { translate [1,0,0] -[0,1,0] }", 1, "(- [1 0 0] [0 1 0])", NULL},
        {"triangle { vertices a b c }", 3, "a", "b"},
        {"distributed_light { rectangle [0,4,0] [1,0,0] [0,0,1] }", 3, "[0 4 0]", "[1 0 0]"},
        {"distributed_light { disk c nrm 2^-1 }", 3, "c", "nrm"},
        /* [LANG-LEX-WORD-3] `n` is a property word, but disk still waits for values */
        {"distributed_light { disk c n 2^-1 }", 3, "c", "n"},
        {"material m { n n  t t }", 1, "n", NULL},
        {"sphere { radius sqrt (2) }", 1, "sqrt(2)", NULL},
        {"sphere { radius foo (2) }", 2, "foo", "2"},
        {"sphere { radius 1 center [0,0,0] }", 1, "1", NULL},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        parsed p;
        char a[128] = "", b[128] = "";
        parse_text(&p, cases[i].text);
        ck_assert_msg(p.diag.errors == 0, "%s: %s", cases[i].text, first_line(&p));
        const ast *prop = child(child(p.root, 0), 0);
        ck_assert_int_eq(prop->kind, AST_PROPERTY);
        ck_assert_msg(prop->count == cases[i].values, "%s: %d values", cases[i].text, prop->count);
        sexpr(child(prop, 0), a, sizeof a);
        ck_assert_str_eq(a, cases[i].first);
        if (cases[i].second) {
            sexpr(child(prop, 1), b, sizeof b);
            ck_assert_str_eq(b, cases[i].second);
        }
        parsed_done(&p);
    }
}
END_TEST

/* Vectors keep the components as written (checked later); calls keep
 * their arguments and the function's id. */
START_TEST(test_parse_file_vectors_and_calls)
{
    parsed p;
    parse_text(&p, "let a = []\nlet b = [1, 2]\nlet c = max()\nlet d = atan2(1, 2)\nlet e = zz()");
    ck_assert_int_eq(p.diag.errors, 0);
    const ast *a = child(p.root, 0)->first, *b = child(p.root, 1)->first;
    const ast *c = child(p.root, 2)->first, *d = child(p.root, 3)->first, *e = child(p.root, 4)->first;
    ck_assert_int_eq(a->kind, AST_VECTOR);
    ck_assert_int_eq(a->count, 0);
    ck_assert_int_eq(b->kind, AST_VECTOR);
    ck_assert_int_eq(b->count, 2);
    ck_assert_int_eq(c->kind, AST_CALL);
    ck_assert_int_eq(c->keyword, KW_MAX);
    ck_assert_int_eq(c->count, 0);
    ck_assert_int_eq(d->keyword, KW_ATAN2);
    ck_assert_int_eq(d->count, 2);
    ck_assert_int_eq(e->keyword, -1);
    ck_assert_str_eq(e->text, "zz");
    ck_assert_int_eq(e->count, 0);
    parsed_done(&p);
}
END_TEST

/* [LANG-MAT-INLINE-1] `material { ... }` inside a primitive is a property
 * holding a material block. */
START_TEST(test_parse_file_inline_material)
{
    parsed p;
    parse_text(&p, "sphere { radius 1 material { Kd [1, 0, 0] Ks 0.5 } }");
    ck_assert_int_eq(p.diag.errors, 0);
    const ast *prop = child(child(p.root, 0), 1);
    ck_assert_int_eq(prop->kind, AST_PROPERTY);
    ck_assert_int_eq(prop->keyword, KW_MATERIAL);
    ck_assert_int_eq(prop->count, 1);
    const ast *block = child(prop, 0);
    ck_assert_int_eq(block->kind, AST_BLOCK);
    ck_assert_int_eq(block->keyword, KW_MATERIAL);
    ck_assert_ptr_null(block->text);
    ck_assert_int_eq(block->count, 2);
    ck_assert_int_eq(child(block, 0)->keyword, KW_KD);
    ck_assert_int_eq(child(block, 1)->keyword, KW_KS);
    parsed_done(&p);
}
END_TEST

/* Statement heads: the name of a let/for/material, the path of include. */
START_TEST(test_parse_file_statement_heads)
{
    parsed p;
    parse_text(&p, "let  width = 2\nmaterial  m {}\noracle two_spheres\ninclude \"a b.scene\"\nlet floor = 1");
    ck_assert_int_eq(p.diag.errors, 0);
    const ast *let = child(p.root, 0), *mat = child(p.root, 1), *oracle = child(p.root, 2);
    const ast *inc = child(p.root, 3), *floor_let = child(p.root, 4);
    /* [LANG-LEX-WORD-3] a property word after let is a name. */
    ck_assert_int_eq(let->kind, AST_LET);
    ck_assert_int_eq(let->keyword, -1);
    ck_assert_str_eq(let->text, "width");
    ck_assert_uint_eq(let->head.begin, 5);
    ck_assert_uint_eq(let->head.end, 10);
    ck_assert_uint_eq(let->span.begin, 0);
    ck_assert_uint_eq(let->span.end, 14);
    ck_assert_str_eq(mat->text, "m");
    ck_assert_uint_eq(mat->head.begin, 25);
    ck_assert_int_eq(oracle->kind, AST_ORACLE);
    ck_assert_str_eq(oracle->text, "two_spheres");
    ck_assert_int_eq(inc->kind, AST_INCLUDE);
    ck_assert_str_eq(inc->text, "a b.scene");
    /* [LANG-LEX-WORD-2] a function name not called is a plain name. */
    ck_assert_int_eq(floor_let->keyword, -1);
    ck_assert_str_eq(floor_let->text, "floor");
    parsed_done(&p);
}
END_TEST

/* An operator node is located at its operator; a property at its word. */
START_TEST(test_parse_file_spans)
{
    parsed p;
    parse_text(&p, "sphere { radius 1 +  2 }");
    const ast *prop = child(child(p.root, 0), 0), *sum = child(prop, 0);
    ck_assert_uint_eq(prop->head.begin, 9);
    ck_assert_uint_eq(prop->head.end, 15);
    ck_assert_uint_eq(prop->span.end, 22);
    ck_assert_int_eq(sum->kind, AST_BINARY);
    ck_assert_uint_eq(sum->head.begin, 18);
    ck_assert_uint_eq(sum->head.end, 19);
    ck_assert_uint_eq(sum->span.begin, 16);
    ck_assert_uint_eq(sum->span.end, 22);
    parsed_done(&p);
}
END_TEST

/* [LANG-DIAG-SYNTAX-1] a syntax error says what was found and what was
 * expected, names the bracket a closer would close, and suggests the
 * nearest word for a misspelt statement or property. */
START_TEST(test_parse_file_syntax_messages)
{
    static const struct {
        const char *text, *message;
    } cases[] = {
        {"sphere { radius 1", "t.scene:1:18: error: unexpected end of file, expecting a value, an operator, "
                              "a property or '}' (to close '{' at line 1)"},
        {"sphere { center [1, 2, 3 }", "t.scene:1:26: error: unexpected '}', expecting an operator, ',' or ']' "
                                       "(to close '[' at line 1)"},
        {"sphere radius 1", "t.scene:1:8: error: unexpected name 'radius', expecting '{'"},
        {"spher { }", "t.scene:1:1: error: unknown statement 'spher'; did you mean 'sphere'?"},
        {"xyzzy { }", "t.scene:1:1: error: unexpected name 'xyzzy', expecting a statement or end of file"},
        {"sphere { radus 1 }", "t.scene:1:10: error: unknown property 'radus' in sphere; did you mean 'radius'?"},
        {"material m { colr 1 }",
         "t.scene:1:14: error: unknown property 'colr' in material (it takes Kd, Ks, n, t, ior)"},
        {"sphere { material { kd 1 } }",
         "t.scene:1:21: error: unknown property 'kd' in material; did you mean 'Kd'?"},
        {"let = 3", "t.scene:1:5: error: unexpected '=', expecting a name"},
        {"let x 3", "t.scene:1:7: error: unexpected number 3, expecting '='"},
        {"for i 0 .. 3 {}", "t.scene:1:7: error: unexpected number 0, expecting 'in'"},
        {"for i in 0 3 {}", "t.scene:1:12: error: unexpected number 3, expecting an operator or '..'"},
        {"include foo", "t.scene:1:9: error: file names are strings: write \"foo\""},
        {"oracle \"x\"", "t.scene:1:8: error: unexpected string \"x\", expecting a name"},
        {"}", "t.scene:1:1: error: unexpected '}', expecting a statement or end of file"},
        {"sphere { let x = 1 }", "t.scene:1:10: error: unexpected 'let', expecting a property or '}' "
                                 "(to close '{' at line 1)"},
        {"let x = (1 + 2", "t.scene:1:15: error: unexpected end of file, expecting an operator or ')' "
                           "(to close '(' at line 1)"},
        {"let x = 1 ..", "t.scene:1:11: error: unexpected '..', expecting an operator, a statement or end of file"},
        {"let x = max(1,)", "t.scene:1:15: error: unexpected ')', expecting a value"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        parsed p;
        parse_text(&p, cases[i].text);
        ck_assert_int_ge(p.diag.errors, 1);
        ck_assert_str_eq(first_line(&p), cases[i].message);
        parsed_done(&p);
    }
}
END_TEST

/* [LANG-DIAG-RECOVER-1] after a syntax error the parser goes on at the
 * next property or statement: one run reports every error. */
START_TEST(test_parse_file_recovers_from_errors)
{
    static const char text[] =
        "sphere { radius 1 } @\n"
        "sphere { radius $ }\n"
        "sphere { center [1, 2,, 3] }\n"
        "plane { nromal [0, 1, 0] }\n"
        "sphere { radius 2 }\n";
    parsed p;
    parse_text(&p, text);
    ck_assert_int_eq(p.diag.errors, 4);
    ck_assert_ptr_nonnull(strstr(p.messages, "t.scene:1:21: error: invalid character '@'\n"));
    ck_assert_ptr_nonnull(strstr(p.messages, "t.scene:2:17: error: invalid character '$'\n"));
    ck_assert_ptr_nonnull(strstr(p.messages, "t.scene:3:23: error: unexpected ',', expecting a value\n"));
    ck_assert_ptr_nonnull(
        strstr(p.messages, "t.scene:4:9: error: unknown property 'nromal' in plane; did you mean 'normal'?\n"));
    /* The statements around the errors are kept, the last one whole. */
    const ast *last = p.root->last;
    ck_assert_int_eq(last->keyword, KW_SPHERE);
    ck_assert_int_eq(child(last, 0)->keyword, KW_RADIUS);
    parsed_done(&p);
}
END_TEST

/* [LANG-LIMIT-NEST-1] past 10000 open brackets or pending operators the
 * parse stops with one error (a bad scene, not an out-of-memory). */
START_TEST(test_parse_file_nesting_limit)
{
    enum { DEPTH = 20000 };
    char *text = malloc(DEPTH + 16);
    ck_assert_ptr_nonnull(text);
    strcpy(text, "let x = ");
    memset(text + 8, '[', DEPTH);
    text[8 + DEPTH] = '\0';
    parsed p;
    parse_text(&p, text);
    ck_assert_int_eq(p.diag.errors, 1);
    ck_assert_ptr_nonnull(strstr(first_line(&p), "error: nesting too deep (more than 10000 open brackets or operators)"));
    ck_assert_int_eq(p.root->count, 0);
    parsed_done(&p);
    free(text);
}
END_TEST

/* Deep but legal: 2000 nested parentheses. */
START_TEST(test_parse_file_deep_parentheses)
{
    enum { DEPTH = 2000 };
    char *text = malloc(2 * DEPTH + 16);
    ck_assert_ptr_nonnull(text);
    strcpy(text, "let x = ");
    memset(text + 8, '(', DEPTH);
    text[8 + DEPTH] = '1';
    memset(text + 9 + DEPTH, ')', DEPTH);
    text[9 + 2 * DEPTH] = '\0';
    parsed p;
    parse_text(&p, text);
    ck_assert_int_eq(p.diag.errors, 0);
    ck_assert_int_eq(child(p.root, 0)->first->kind, AST_NUMBER);
    parsed_done(&p);
    free(text);
}
END_TEST

/* Two parses share nothing: a second file parsed while the first tree is
 * alive leaves the first intact (no global state in scanner or parser). */
START_TEST(test_parse_file_two_files)
{
    parsed p;
    parse_text(&p, "let a = 1");
    free(p.messages);
    ck_assert_int_eq(source_set_add(&p.sources, "u.scene", "sphere { radius }\nlet b = (", 27, src_span_none()), 1);
    FILE *out = open_memstream(&p.messages, &p.size);
    p.diag.sink = diag_print;
    p.diag.sink_user = out;
    ast *second = parse_file(&p.arena, &p.diag, &p.sources, 1);
    fclose(out);
    ck_assert_ptr_nonnull(second);
    ck_assert_int_eq(p.diag.errors, 1);
    ck_assert_str_eq(first_line(&p), "u.scene:2:10: error: unexpected end of file, expecting a value");
    ck_assert_int_eq(p.root->count, 1);
    ck_assert_str_eq(child(p.root, 0)->text, "a");
    ck_assert_int_eq(child(p.root, 0)->span.file, 0);
    ck_assert_int_eq(child(second, 0)->span.file, 1);
    parsed_done(&p);
}
END_TEST

Suite *suite_parser(void)
{
    Suite *s = suite_create("parser");
    TCase *tc = tcase_create("parser");
    tcase_add_test(tc, test_parse_file_issue_example);
    tcase_add_test(tc, test_parse_file_precedence);
    tcase_add_test(tc, test_parse_file_juxtaposed_values);
    tcase_add_test(tc, test_parse_file_vectors_and_calls);
    tcase_add_test(tc, test_parse_file_inline_material);
    tcase_add_test(tc, test_parse_file_statement_heads);
    tcase_add_test(tc, test_parse_file_spans);
    tcase_add_test(tc, test_parse_file_syntax_messages);
    tcase_add_test(tc, test_parse_file_recovers_from_errors);
    tcase_add_test(tc, test_parse_file_nesting_limit);
    tcase_add_test(tc, test_parse_file_deep_parentheses);
    tcase_add_test(tc, test_parse_file_two_files);
    suite_add_tcase(s, tc);
    return s;
}
