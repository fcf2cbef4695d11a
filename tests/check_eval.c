/* Tests of constant expressions (src/lang/eval.c): every built-in function with
 * a value worked out by hand, vector arithmetic, and every error with its
 * exact message and column.  Expressions are parsed as `let x = EXPR`, so a
 * column is 9 plus the offset inside EXPR.  IDs: spec/language.md. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/diag_print.h"
#include "testlib.h"
#include "lang/eval.h"
#include "lang/parse.h"

#define PI 3.14159265358979323846

typedef struct evaluated {
    arena arena;
    source_set sources;
    diag diag;
    char *messages;
    size_t size;
    value v;
    int ok;
} evaluated;

/* Parses `let x = EXPR` and evaluates EXPR in e (NULL: no constants). */
static void eval_text(evaluated *r, const char *expr, const env *e)
{
    char text[4096];
    env empty;
    env_init(&empty, NULL);
    memset(r, 0, sizeof *r);
    snprintf(text, sizeof text, "let x = %s", expr);
    arena_init(&r->arena, NULL);
    source_set_init(&r->sources, NULL);
    ck_assert_int_eq(source_set_add(&r->sources, "t.scene", text, strlen(text), src_span_none()), 0);
    FILE *out = open_memstream(&r->messages, &r->size);
    diag_init(&r->diag, &r->sources, out ? diag_print : NULL, out);
    ast *root = parse_file(&r->arena, &r->diag, &r->sources, 0);
    ck_assert_ptr_nonnull(root);
    ck_assert_int_eq(r->diag.errors, 0);
    r->ok = eval_expr(e ? e : &empty, &r->diag, root->first->first, &r->v);
    fclose(out);
}

static void eval_done(evaluated *r)
{
    free(r->messages);
    source_set_free(&r->sources);
    arena_free(&r->arena);
}

static const char *first_line(evaluated *r)
{
    char *nl = r->messages ? strchr(r->messages, '\n') : NULL;
    if (nl)
        *nl = '\0';
    return r->messages ? r->messages : "";
}

static double eval_number(const char *expr)
{
    evaluated r;
    eval_text(&r, expr, NULL);
    ck_assert_msg(r.ok, "%s: %s", expr, first_line(&r));
    ck_assert_msg(r.v.kind == VAL_NUMBER, "%s is not a number", expr);
    double x = r.v.number;
    eval_done(&r);
    return x;
}

static vec3 eval_vector(const char *expr)
{
    evaluated r;
    eval_text(&r, expr, NULL);
    ck_assert_msg(r.ok, "%s: %s", expr, first_line(&r));
    ck_assert_msg(r.v.kind == VAL_VECTOR, "%s is not a vector", expr);
    vec3 v = r.v.vector;
    eval_done(&r);
    return v;
}

/* [LANG-FN-1] every function, radians in and out of the trigonometric
 * ones.  Values are the textbook ones (sin 30 degrees = 1/2, ...). */
START_TEST(test_eval_expr_functions)
{
    static const struct {
        const char *expr;
        double value, tol;
    } cases[] = {
        {"pi", PI, 0},
        {"sqrt(16)", 4, 0},
        {"sqrt(2)", 1.4142135623730951, 0},
        {"sqrt(0)", 0, 0},
        {"sin(pi/6)", 0.5, 1e-15},
        {"sin(-pi/2)", -1, 0},
        {"cos(pi/3)", 0.5, 1e-15},
        {"cos(0)", 1, 0},
        {"tan(pi/4)", 1, 1e-15},
        {"asin(1)", PI / 2, 1e-15},
        {"asin(-0.5)", -PI / 6, 1e-15},
        {"acos(0)", PI / 2, 1e-15},
        {"acos(1)", 0, 0},
        {"acos(-1)", PI, 1e-15},
        {"atan2(1, 1)", PI / 4, 1e-15},   /* atan2(y, x) */
        {"atan2(1, 0)", PI / 2, 1e-15},
        {"atan2(0, -1)", PI, 1e-15},
        {"atan2(-1, 0)", -PI / 2, 1e-15},
        {"pow(2, 10)", 1024, 0},
        {"pow(4, 0.5)", 2, 0},
        {"pow(-2, 3)", -8, 0},
        {"abs(-3)", 3, 0},
        {"abs(2.5)", 2.5, 0},
        {"min(2, 3)", 2, 0},
        {"min(-1, -2)", -2, 0},
        {"max(2, 3)", 3, 0},
        {"exp(0)", 1, 0},
        {"exp(1)", 2.718281828459045, 1e-15},
        {"log(1)", 0, 0},
        {"log(10)", 2.302585092994046, 1e-15},
        {"log(exp(2))", 2, 1e-15},
        {"floor(2.7)", 2, 0},
        {"floor(-1.5)", -2, 0},
        {"floor(3)", 3, 0},
        {"radians(180)", PI, 1e-15},
        {"radians(90)", PI / 2, 1e-15},
        {"degrees(pi)", 180, 1e-13},
        {"degrees(1)", 57.29577951308232, 1e-13},
        {"dot([1, 2, 3], [4, 5, 6])", 32, 0},
        {"dot([1, 0, 0], [0, 1, 0])", 0, 0},
        {"length([3, 4, 12])", 13, 0},
        {"length([0, -5, 0])", 5, 0},
        {"length([0, 0, 0])", 0, 0},
        {"sqrt (9)", 3, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double x = eval_number(cases[i].expr);
        ck_assert_msg(fabs(x - cases[i].value) <= cases[i].tol, "%s = %.17g, expected %.17g", cases[i].expr, x,
                      cases[i].value);
    }
}
END_TEST

START_TEST(test_eval_expr_vector_functions)
{
    ck_assert_vec_near(eval_vector("cross([1, 0, 0], [0, 1, 0])"), vec_make(0, 0, 1), 0);
    ck_assert_vec_near(eval_vector("cross([0, 1, 0], [1, 0, 0])"), vec_make(0, 0, -1), 0);
    /* (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4) */
    ck_assert_vec_near(eval_vector("cross([1, 2, 3], [4, 5, 6])"), vec_make(-3, 6, -3), 0);
    ck_assert_vec_near(eval_vector("normalize([3, 0, 4])"), vec_make(0.6, 0, 0.8), 1e-16);
    ck_assert_vec_near(eval_vector("normalize([0, -2, 0])"), vec_make(0, -1, 0), 0);
    ck_assert_vec_near(eval_vector("normalize([1e-300, 0, 0])"), vec_make(1, 0, 0), 0);
}
END_TEST

/* [LANG-EXPR-VEC-1] vector + and -, number * vector (either side),
 * vector / number, unary minus. */
START_TEST(test_eval_expr_vector_arithmetic)
{
    ck_assert_vec_near(eval_vector("[1, 2, 3] + [4, 5, 6]"), vec_make(5, 7, 9), 0);
    ck_assert_vec_near(eval_vector("[1, 2, 3] - [4, 5, 6]"), vec_make(-3, -3, -3), 0);
    ck_assert_vec_near(eval_vector("2 * [1, 2, 3]"), vec_make(2, 4, 6), 0);
    ck_assert_vec_near(eval_vector("[1, 2, 3] * 2"), vec_make(2, 4, 6), 0);
    ck_assert_vec_near(eval_vector("[2, 4, 6] / 2"), vec_make(1, 2, 3), 0);
    ck_assert_vec_near(eval_vector("-[1, -2, 3]"), vec_make(-1, 2, -3), 0);
    ck_assert_vec_near(eval_vector("([1, 0, 0] + [0, 1, 0]) * 0.5"), vec_make(0.5, 0.5, 0), 0);
    ck_assert_vec_near(eval_vector("[1 + 1, 2 * 3, -4]"), vec_make(2, 6, -4), 0);
    ck_assert_vec_near(eval_vector("[1, 1, 1] * length([3, 4, 0]) - [5, 5, 5]"), vec_make(0, 0, 0), 0);
}
END_TEST

/* [LANG-EXPR-PREC-1] as computed values. */
START_TEST(test_eval_expr_arithmetic)
{
    ck_assert_near(eval_number("1 + 2 * 3"), 7, 0);
    ck_assert_near(eval_number("-2^2"), -4, 0);
    ck_assert_near(eval_number("2^-1"), 0.5, 0);
    ck_assert_near(eval_number("2^3^2"), 512, 0);
    ck_assert_near(eval_number("(2^3)^2"), 64, 0);
    ck_assert_near(eval_number("7 / 2"), 3.5, 0);
    ck_assert_near(eval_number("1 - 2 - 3"), -4, 0);
    ck_assert_near(eval_number("0^0"), 1, 0);
    ck_assert_near(eval_number("1e308"), 1e308, 0);
    ck_assert_near(eval_number("-1e308 * 1"), -1e308, 0);
    ck_assert_near(eval_number("4.9e-324"), 4.9e-324, 0);
}
END_TEST

/* Strings pass through (for `mesh { file ... }`). */
START_TEST(test_eval_expr_string)
{
    evaluated r;
    eval_text(&r, "\"dir/a.obj\"", NULL);
    ck_assert(r.ok);
    ck_assert_int_eq(r.v.kind, VAL_STRING);
    ck_assert_str_eq(r.v.text, "dir/a.obj");
    eval_done(&r);
}
END_TEST

/* [LANG-EXPR-ERR-1] [LANG-EXPR-FINITE-1] every evaluation error, at the
 * operator, the call, the argument or the literal at fault. */
START_TEST(test_eval_expr_errors)
{
    static const struct {
        const char *expr, *message;
    } cases[] = {
        {"1/0", "t.scene:1:10: error: division by zero"},
        {"[1, 2, 3] / 0", "t.scene:1:19: error: division by zero"},
        {"sqrt(-1)", "t.scene:1:9: error: sqrt of a negative number (argument -1)"},
        {"asin(2)", "t.scene:1:9: error: asin outside [-1, 1] (argument 2)"},
        {"acos(-1.5)", "t.scene:1:9: error: acos outside [-1, 1] (argument -1.5)"},
        {"log(0)", "t.scene:1:9: error: log of a number <= 0 (argument 0)"},
        {"log(-1)", "t.scene:1:9: error: log of a number <= 0 (argument -1)"},
        {"(-8)^(1/3)", "t.scene:1:13: error: -8 ^ 0.333333 is not a real number"},
        {"pow(-8, 1/3)", "t.scene:1:9: error: pow(-8, 0.333333) is not a real number"},
        {"0^-1", "t.scene:1:10: error: the result is not a finite number"},
        {"1e400", "t.scene:1:9: error: number out of range (the largest is about 1.8e308)"},
        {"1e308 * 10", "t.scene:1:15: error: the result is not a finite number"},
        {"exp(1000)", "t.scene:1:9: error: the result is not a finite number"},
        {"[1e308, 0, 0] + [1e308, 0, 0]", "t.scene:1:23: error: the result is not a finite number"},
        {"normalize([0, 0, 0])", "t.scene:1:19: error: cannot normalize a zero-length vector"},
        {"[1, 2, 3] * [1, 2, 3]", "t.scene:1:19: error: cannot apply '*' to a vector and a vector "
                                  "(use dot() or cross() to multiply vectors)"},
        {"1 + [1, 2, 3]", "t.scene:1:11: error: cannot apply '+' to a number and a vector"},
        {"[1, 2, 3] - 1", "t.scene:1:19: error: cannot apply '-' to a vector and a number"},
        {"2 / [1, 2, 3]", "t.scene:1:11: error: cannot apply '/' to a number and a vector"},
        {"\"a\" + 1", "t.scene:1:13: error: cannot apply '+' to a string"},
        {"-\"a\"", "t.scene:1:9: error: cannot negate a string"},
        {"sqrt([1, 2, 3])", "t.scene:1:14: error: sqrt expects a number here, not a vector"},
        {"dot(1, [1, 2, 3])", "t.scene:1:13: error: dot expects a vector here, not a number"},
        {"sqrt(1, 2)", "t.scene:1:9: error: sqrt takes 1 argument, got 2"},
        {"atan2(1)", "t.scene:1:9: error: atan2 takes 2 arguments, got 1"},
        {"max()", "t.scene:1:9: error: max takes 2 arguments, got 0"},
        {"sqr(2)", "t.scene:1:9: error: unknown function 'sqr'; did you mean 'sqrt'?"},
        {"frobnicate(2)", "t.scene:1:9: error: unknown function 'frobnicate'"},
        {"[1, 2]", "t.scene:1:9: error: a vector has 3 components, this one has 2"},
        {"[1, 2, 3, 4]", "t.scene:1:9: error: a vector has 3 components, this one has 4"},
        {"[1, [1, 2, 3], 3]", "t.scene:1:13: error: a vector component must be a number, not a vector"},
        {"q", "t.scene:1:9: error: unknown constant 'q'"},
        {"p", "t.scene:1:9: error: unknown constant 'p'; did you mean 'pi'?"},
        {"1 + sqrt", "t.scene:1:13: error: unknown constant 'sqrt'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        evaluated r;
        eval_text(&r, cases[i].expr, NULL);
        ck_assert_msg(!r.ok, "%s evaluated", cases[i].expr);
        ck_assert_int_eq(r.diag.errors, 1);
        ck_assert_str_eq(first_line(&r), cases[i].message);
        eval_done(&r);
    }
}
END_TEST

/* [LANG-LIMIT-EXPR-1] at most 1000 operators, calls or vectors nested. */
START_TEST(test_eval_expr_depth_limit)
{
    char text[4096];
    evaluated r;
    /* 1000 minus signs: 1000 nested negations, just allowed. */
    memset(text, '-', 1000);
    strcpy(text + 1000, "1");
    ck_assert_near(eval_number(text), 1, 0);
    memset(text, '-', 1001);
    strcpy(text + 1001, "1");
    eval_text(&r, text, NULL);
    ck_assert(!r.ok);
    ck_assert_str_eq(first_line(&r), "t.scene:1:1010: error: expression nested too deep (more than 1000 operators, "
                                     "calls or vectors inside each other)");
    eval_done(&r);
    /* A long flat sum nests to the left just the same. */
    size_t n = 0;
    for (int i = 0; i < 1500; i++)
        n += (size_t)sprintf(text + n, "1+");
    strcpy(text + n, "1");
    eval_text(&r, text, NULL);
    ck_assert(!r.ok);
    ck_assert_int_eq(r.diag.errors, 1);
    eval_done(&r);
}
END_TEST

/* [LANG-LET-1] constants: the innermost binding of a name wins; a scope
 * is dropped by restoring the count at its start. */
START_TEST(test_env_bind_find_restore)
{
    env e;
    value one = {VAL_NUMBER, 1, {0, 0, 0}, NULL, {-1, 0, 0}};
    value two = {VAL_NUMBER, 2, {0, 0, 0}, NULL, {-1, 0, 0}};
    env_init(&e, NULL);
    ck_assert_ptr_null(env_find(&e, "r"));
    ck_assert(env_bind(&e, "r", one, src_span_none()));
    int mark = e.count;
    for (int i = 0; i < 40; i++)   /* past the first growth */
        ck_assert(env_bind(&e, i % 2 ? "r" : "radius2", two, src_span_none()));
    ck_assert_near(env_find(&e, "r")->value.number, 2, 0);
    env_restore(&e, mark);
    ck_assert_int_eq(e.count, 1);
    ck_assert_near(env_find(&e, "r")->value.number, 1, 0);
    ck_assert_ptr_null(env_find(&e, "radius2"));
    ck_assert_str_eq(env_suggest(&e, "rr"), "r");
    ck_assert_str_eq(env_suggest(&e, "pj"), "pi");
    ck_assert_ptr_null(env_suggest(&e, "zzzz"));
    env_free(&e);
    ck_assert_int_eq(e.count, 0);
}
END_TEST

START_TEST(test_eval_expr_uses_constants)
{
    env e;
    value r = {VAL_NUMBER, 2, {0, 0, 0}, NULL, {-1, 0, 0}};
    value c = {VAL_VECTOR, 0, {1, 2, 3}, NULL, {-1, 0, 0}};
    env_init(&e, NULL);
    ck_assert(env_bind(&e, "r", r, src_span_none()));
    ck_assert(env_bind(&e, "c", c, src_span_none()));
    evaluated x;
    eval_text(&x, "r * pi", &e);
    ck_assert(x.ok);
    ck_assert_near(x.v.number, 2 * PI, 0);
    eval_done(&x);
    eval_text(&x, "c + [r, r, r]", &e);
    ck_assert(x.ok);
    ck_assert_vec_near(x.v.vector, vec_make(3, 4, 5), 0);
    /* The value carries the span of where it is used, not of its let. */
    ck_assert_uint_eq(x.v.span.begin, 8);
    eval_done(&x);
    eval_text(&x, "rr", &e);
    ck_assert(!x.ok);
    ck_assert_str_eq(first_line(&x), "t.scene:1:9: error: unknown constant 'rr'; did you mean 'r'?");
    eval_done(&x);
    env_free(&e);
}
END_TEST

START_TEST(test_value_kind_name)
{
    ck_assert_str_eq(value_kind_name(VAL_NUMBER), "number");
    ck_assert_str_eq(value_kind_name(VAL_VECTOR), "vector");
    ck_assert_str_eq(value_kind_name(VAL_STRING), "string");
}
END_TEST

Suite *suite_eval(void)
{
    Suite *s = suite_create("eval");
    TCase *tc = tcase_create("eval");
    tcase_add_test(tc, test_eval_expr_functions);
    tcase_add_test(tc, test_eval_expr_vector_functions);
    tcase_add_test(tc, test_eval_expr_vector_arithmetic);
    tcase_add_test(tc, test_eval_expr_arithmetic);
    tcase_add_test(tc, test_eval_expr_string);
    tcase_add_test(tc, test_eval_expr_errors);
    tcase_add_test(tc, test_eval_expr_depth_limit);
    tcase_add_test(tc, test_env_bind_find_restore);
    tcase_add_test(tc, test_eval_expr_uses_constants);
    tcase_add_test(tc, test_value_kind_name);
    suite_add_tcase(s, tc);
    return s;
}
