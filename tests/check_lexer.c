/* Tests of the scanner (grammar/scene.l) through its reentrant interface:
 * token kinds, values, messages of bad tokens and byte locations.  The
 * lexical rules are those of spec/language.md, section "Lexical rules";
 * the statement IDs cited are from there.  Expected values are written out
 * by hand from the input text. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "lang/keywords.h"
#include "lang/parse.h"
#include "scene.tab.h"
#include "scene.lex.h"

enum { MAX_TOKENS = 64 };

typedef struct lexed {
    int token;
    SCN_STYPE value;
    src_span loc;
    const char *message;   /* scan_message after a BAD_* token */
} lexed;

typedef struct lex_run {
    arena arena;
    source_set sources;
    diag diag;
    parse_ctx ctx;
    lexed tokens[MAX_TOKENS];
    int count;             /* tokens before end of input */
} lex_run;

/* Scans len bytes of text to the end; run must be released with lex_done. */
static void lex_bytes(lex_run *run, const char *text, size_t len)
{
    yyscan_t scanner;
    memset(run, 0, sizeof *run);
    arena_init(&run->arena, NULL);
    source_set_init(&run->sources, NULL);
    ck_assert_int_eq(source_set_add(&run->sources, "t.scene", text, len, src_span_none()), 0);
    diag_init(&run->diag, &run->sources, NULL, NULL);
    run->ctx.arena = &run->arena;
    run->ctx.diag = &run->diag;
    run->ctx.sources = &run->sources;
    ck_assert_int_eq(scn_lex_init_extra(&run->ctx, &scanner), 0);
    YY_BUFFER_STATE buffer = scn__scan_bytes(run->sources.files[0]->text, (int)len, scanner);
    ck_assert_ptr_nonnull(buffer);
    for (;;) {
        lexed *t = &run->tokens[run->count];
        run->ctx.scan_message = NULL;
        t->token = scn_lex(&t->value, &t->loc, scanner);
        t->message = run->ctx.scan_message;
        if (t->token == 0)
            break;
        ck_assert_int_lt(++run->count, MAX_TOKENS);
    }
    scn__delete_buffer(buffer, scanner);
    scn_lex_destroy(scanner);
}

static void lex(lex_run *run, const char *text)
{
    lex_bytes(run, text, strlen(text));
}

static void lex_done(lex_run *run)
{
    source_set_free(&run->sources);
    arena_free(&run->arena);
}

static void assert_kinds(const lex_run *run, const int *kinds, int count)
{
    ck_assert_int_eq(run->count, count);
    for (int i = 0; i < count; i++)
        ck_assert_msg(run->tokens[i].token == kinds[i], "token %d is %d, expected %d", i, run->tokens[i].token,
                      kinds[i]);
}

/* [LANG-LEX-NUM-1] digits, an optional fraction, an optional exponent;
 * a leading '.' is allowed. */
START_TEST(test_scan_numbers_with_decimals_and_exponents)
{
    static const struct {
        const char *text;
        double value;
    } cases[] = {
        {"0", 0}, {"42", 42}, {"007", 7}, {"2.5", 2.5}, {".5", 0.5}, {"1e3", 1000},
        {"1E3", 1000}, {"1.5e-2", 0.015}, {"2e+2", 200}, {"6.25E1", 62.5}, {".25e1", 2.5},
        {"123456789012", 123456789012.0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        lex_run run;
        lex(&run, cases[i].text);
        ck_assert_msg(run.count == 1 && run.tokens[0].token == NUMBER, "'%s' is not one number", cases[i].text);
        ck_assert_near(run.tokens[0].value.number, cases[i].value, 0.0);
        lex_done(&run);
    }
}
END_TEST

/* 1e400 still scans as a number (infinite): the evaluator refuses it with a
 * location ([LANG-EXPR-FINITE-1]), not the scanner. */
START_TEST(test_scan_number_out_of_range_is_a_number)
{
    lex_run run;
    lex(&run, "1e400");
    ck_assert_int_eq(run.count, 1);
    ck_assert_int_eq(run.tokens[0].token, NUMBER);
    ck_assert(isinf(run.tokens[0].value.number));
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-NUM-2] a number glued to letters, a second '.', a missing
 * exponent or a missing fraction digit is one malformed-number token. */
START_TEST(test_scan_malformed_numbers)
{
    static const struct {
        const char *text;
        size_t length;          /* bytes of the bad token */
        const char *message;    /* NULL: no detail */
    } cases[] = {
        {"12abc", 5, NULL},
        {"1.5e", 4, "exponent without digits"},
        {"1.5ex", 5, NULL},
        {"1e5x", 4, NULL},
        {"1.2.3", 5, NULL},
        {"1.x", 3, NULL},
        {"1e", 2, "exponent without digits"},
        {"1e+", 3, "exponent without digits"},
        {"7E-", 3, "exponent without digits"},
        {"1. ", 2, "no digit after '.'"},
        {"3.]", 2, "no digit after '.'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        lex_run run;
        lex(&run, cases[i].text);
        ck_assert_msg(run.count >= 1 && run.tokens[0].token == BAD_NUMBER, "'%s' is not a bad number",
                      cases[i].text);
        ck_assert_uint_eq(run.tokens[0].loc.begin, 0);
        ck_assert_uint_eq(run.tokens[0].loc.end, cases[i].length);
        if (cases[i].message)
            ck_assert_str_eq(run.tokens[0].message, cases[i].message);
        else
            ck_assert_ptr_null(run.tokens[0].message);
        lex_done(&run);
    }
}
END_TEST

/* [LANG-LEX-RANGE-1] `0..4` is three tokens: 0, .., 4. */
START_TEST(test_scan_range_dots)
{
    static const int kinds[] = {NUMBER, DOTDOT, NUMBER};
    const char *texts[] = {"0..4", "0 .. 4", "0.. 4", "0 ..4"};
    for (int i = 0; i < 4; i++) {
        lex_run run;
        lex(&run, texts[i]);
        assert_kinds(&run, kinds, 3);
        ck_assert_near(run.tokens[0].value.number, 0, 0);
        ck_assert_near(run.tokens[2].value.number, 4, 0);
        lex_done(&run);
    }
    /* Names and a decimal on either side. */
    lex_run run;
    static const int names[] = {NAME, DOTDOT, NAME, NUMBER, DOTDOT, NUMBER};
    lex(&run, "a..b 1.5..2.5");
    assert_kinds(&run, names, 6);
    ck_assert_near(run.tokens[3].value.number, 1.5, 0);
    ck_assert_near(run.tokens[5].value.number, 2.5, 0);
    lex_done(&run);
    /* Three dots: the number 0, then .., then .4 (a loop bound of 0.4). */
    static const int three[] = {NUMBER, DOTDOT, NUMBER};
    lex(&run, "0...4");
    assert_kinds(&run, three, 3);
    ck_assert_near(run.tokens[2].value.number, 0.4, 0);
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-DOT-1] a '.' that is no part of a number or of '..'. */
START_TEST(test_scan_lone_dot)
{
    lex_run run;
    lex(&run, "a . b");
    ck_assert_int_eq(run.count, 3);
    ck_assert_int_eq(run.tokens[1].token, BAD_CHAR);
    ck_assert_str_eq(run.tokens[1].message, "unexpected '.' (numbers need a digit before and after '.')");
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-STR-1] strings: quotes dropped, \" \\ \n \t resolved, any
 * other escaped byte stands for itself; bytes >= 0x80 are kept. */
START_TEST(test_scan_strings_and_escapes)
{
    static const struct {
        const char *text, *value;
    } cases[] = {
        {"\"a b\"", "a b"},
        {"\"\"", ""},
        {"\"say \\\"hi\\\"\"", "say \"hi\""},
        {"\"back\\\\slash\"", "back\\slash"},
        {"\"n\\nt\\t\"", "n\nt\t"},
        {"\"\\q\\.\"", "q."},
        {"\"caf\xc3\xa9.obj\"", "caf\xc3\xa9.obj"},
        {"\"# not a comment\"", "# not a comment"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        lex_run run;
        lex(&run, cases[i].text);
        ck_assert_msg(run.count == 1 && run.tokens[0].token == STRING, "%s is not one string", cases[i].text);
        ck_assert_str_eq(run.tokens[0].value.text, cases[i].value);
        ck_assert_uint_eq(run.tokens[0].loc.end, strlen(cases[i].text));
        lex_done(&run);
    }
}
END_TEST

/* [LANG-LEX-STR-2] a string ends on its line; a NUL byte is refused. */
START_TEST(test_scan_bad_strings)
{
    static const char unterminated[] = "unterminated string (a string ends on its line)";
    const char *texts[] = {"\"abc", "\"abc\ndef\"", "\"abc\\", "\"a\\\"", "\"abc\r\n\""};
    for (int i = 0; i < 5; i++) {
        lex_run run;
        lex(&run, texts[i]);
        ck_assert_int_ge(run.count, 1);
        ck_assert_int_eq(run.tokens[0].token, BAD_STRING);
        ck_assert_str_eq(run.tokens[0].message, unterminated);
        ck_assert_uint_eq(run.tokens[0].loc.begin, 0);
        lex_done(&run);
    }
    lex_run run;
    lex_bytes(&run, "\"a\0b\"", 5);
    ck_assert_int_eq(run.count, 1);
    ck_assert_int_eq(run.tokens[0].token, BAD_STRING);
    ck_assert_str_eq(run.tokens[0].message, "NUL byte in a string");
    ck_assert_uint_eq(run.tokens[0].loc.end, 5);
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-COMMENT-1] '#' to the end of the line; any byte may be in a
 * comment, NUL and non-ASCII ones included. */
START_TEST(test_scan_comments)
{
    static const char text[] = "# head\n1 # tail \xff\x01\0 x\n2#\n#";
    lex_run run;
    static const int kinds[] = {NUMBER, NUMBER};
    lex_bytes(&run, text, sizeof text - 1);
    assert_kinds(&run, kinds, 2);
    ck_assert_near(run.tokens[0].value.number, 1, 0);
    ck_assert_near(run.tokens[1].value.number, 2, 0);
    ck_assert_uint_eq(run.tokens[0].loc.begin, 7);
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-LINES-1] LF, CRLF and a lone CR each end one line. */
START_TEST(test_scan_line_endings)
{
    lex_run run;
    lex(&run, "a\r\nb\rc\nd\r\r\ne # c\rf");
    ck_assert_int_eq(run.count, 6);
    const int lines[] = {1, 2, 3, 4, 6, 7};
    for (int i = 0; i < 6; i++) {
        int line, col;
        ck_assert_int_eq(run.tokens[i].token, NAME);
        source_line_col(run.sources.files[0], run.tokens[i].loc.begin, &line, &col);
        ck_assert_msg(line == lines[i] && col == 1, "token %d at %d:%d, expected %d:1", i, line, col, lines[i]);
    }
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-BYTES-1] outside strings and comments: NUL, control bytes and
 * bytes >= 0x80 are refused one by one, each with its own message. */
START_TEST(test_scan_bad_bytes)
{
    static const struct {
        const char *text;
        size_t len;
        const char *message;
    } cases[] = {
        {"a\0b", 3, "NUL byte in the scene text"},
        {"a\xc3\xa9", 3, "non-ASCII byte outside a string or comment (names and numbers are ASCII)"},
        {"a\x01", 2, "invalid character"},
        {"a@", 2, "invalid character"},
        {"a$", 2, "invalid character"},
        {"a;", 2, "invalid character"},
        {"a\x7f", 2, "invalid character"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        lex_run run;
        lex_bytes(&run, cases[i].text, cases[i].len);
        ck_assert_int_ge(run.count, 2);
        ck_assert_int_eq(run.tokens[0].token, NAME);
        ck_assert_int_eq(run.tokens[1].token, BAD_CHAR);
        ck_assert_str_eq(run.tokens[1].message, cases[i].message);
        ck_assert_uint_eq(run.tokens[1].loc.begin, 1);
        ck_assert_uint_eq(run.tokens[1].loc.end, 2);
        lex_done(&run);
    }
}
END_TEST

/* [LANG-LEX-BYTES-2] a UTF-8 byte-order mark is skipped at the very start
 * of a file and refused anywhere else. */
START_TEST(test_scan_byte_order_mark)
{
    lex_run run;
    lex(&run, "\xEF\xBB\xBFsphere \xEF\xBB\xBF");
    ck_assert_int_eq(run.count, 2);
    ck_assert_int_eq(run.tokens[0].token, KEYWORD);
    ck_assert_uint_eq(run.tokens[0].loc.begin, 3);
    ck_assert_int_eq(run.tokens[1].token, BAD_CHAR);
    ck_assert_uint_eq(run.tokens[1].loc.begin, 10);
    ck_assert_str_eq(run.tokens[1].message, "non-ASCII byte outside a string or comment (names and numbers are ASCII)");
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-BLANK-1] space, tab, form feed and vertical tab separate tokens. */
START_TEST(test_scan_blanks)
{
    lex_run run;
    static const int kinds[] = {NAME, NAME, NAME, NAME, NAME};
    lex(&run, "a b\tc\fd\ve");
    assert_kinds(&run, kinds, 5);
    ck_assert_uint_eq(run.tokens[4].loc.begin, 8);
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-WORD-1] a word is a reserved word exactly as the table spells
 * it (case matters); other words are names.  [LANG-LEX-WORD-2] a function
 * name is reserved only where it is called (before '(', blanks allowed);
 * another word glued to '(' is a call of an unknown function. */
START_TEST(test_scan_keywords_versus_names)
{
    lex_run run;
    lex(&run, "material m { Kd kd n N } sphere spheres Sphere sqrt sqrt( sqrt\t(x foo( foo (x _a1 let in material");
    static const int kinds[] = {MATERIAL, NAME, '{', KEYWORD, NAME, KEYWORD, NAME, '}', KEYWORD, NAME, NAME, NAME,
                                FUNC, '(', FUNC, '(', NAME, CALLNAME, '(', NAME, '(', NAME, NAME, LET, IN, MATERIAL};
    assert_kinds(&run, kinds, 26);
    ck_assert_int_eq(run.tokens[3].value.id, KW_KD);
    ck_assert_int_eq(run.tokens[5].value.id, KW_N);
    ck_assert_int_eq(run.tokens[8].value.id, KW_SPHERE);
    ck_assert_str_eq(run.tokens[11].value.text, "sqrt");
    ck_assert_int_eq(run.tokens[12].value.id, KW_SQRT);
    ck_assert_int_eq(run.tokens[14].value.id, KW_SQRT);
    ck_assert_str_eq(run.tokens[9].value.text, "spheres");
    ck_assert_str_eq(run.tokens[17].value.text, "foo");
    ck_assert_str_eq(run.tokens[22].value.text, "_a1");
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-WORD-3] a property word is a keyword only where a property may
 * start: in a block body, once the property before has all its values and
 * no operator waits for an operand.  Everywhere else it is a name. */
START_TEST(test_scan_property_words_in_context)
{
    static const struct {
        const char *text;
        int at;        /* the token checked */
        int kind;      /* KEYWORD or NAME */
    } cases[] = {
        {"let width = 4", 1, NAME},
        {"for t in 0 .. 3 { }", 1, NAME},
        {"for i in 0 .. n { }", 5, NAME},
        {"material n { }", 1, NAME},
        {"oracle width", 1, NAME},
        {"sphere { radius 1 }", 2, KEYWORD},
        {"sphere { radius width / 2 }", 3, NAME},
        {"sphere { radius 2 * radius }", 5, NAME},
        {"sphere { radius 1 center [radius, 0, 0] }", 4, KEYWORD},
        {"sphere { radius 1 center [radius, 0, 0] }", 6, NAME},
        {"sphere { radius (scale) }", 4, NAME},
        {"sphere { radius sqrt(scale) }", 5, NAME},
        {"sphere { radius sqrt(scale) scale 2 }", 7, KEYWORD},
        {"sphere { radius -scale }", 4, NAME},
        {"sphere { radius 1 -scale }", 5, NAME},
        {"sphere { radius r scale 2 }", 4, KEYWORD},
        {"camera { orthographic width width }", 3, KEYWORD},
        {"camera { orthographic width width }", 4, NAME},
        {"triangle { vertices a scale c }", 4, NAME},
        {"triangle { vertices a b c scale 2 }", 6, KEYWORD},
        {"distributed_light { disk c n r power 1 }", 4, NAME},
        {"distributed_light { disk c n r power 1 }", 6, KEYWORD},
        {"sphere { material { n 2 } radius 1 }", 4, KEYWORD},
        {"sphere { material { n 2 } radius 1 }", 7, KEYWORD},
        {"sphere { material m radius 1 }", 4, KEYWORD},
        {"material glass { t 1 }", 3, KEYWORD},
        {"for i in 0 .. 1 { sphere { radius i } }", 9, KEYWORD},
        {"for i in 0 .. 1 { radius }", 7, NAME},
        {"cone { radii 1 0 open }", 5, KEYWORD},
        {"cone { radii a open }", 4, NAME},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        lex_run run;
        lex(&run, cases[i].text);
        ck_assert_msg(cases[i].at < run.count, "%s: %d tokens", cases[i].text, run.count);
        ck_assert_msg(run.tokens[cases[i].at].token == cases[i].kind, "%s: token %d is %d, expected %d",
                      cases[i].text, cases[i].at, run.tokens[cases[i].at].token, cases[i].kind);
        lex_done(&run);
    }
}
END_TEST

/* Every word of the keyword table scans as its own class (a function when
 * called, a property where a property may start: in a block body). */
START_TEST(test_scan_every_keyword)
{
    static const int statements[] = {LET, FOR, IN, INCLUDE, ORACLE, MATERIAL};
    for (int i = 0; i < KEYWORD_COUNT; i++) {
        const keyword_info *info = keyword_get((keyword_id)i);
        char text[64];
        int property = info->cls == KWC_PROPERTY;
        snprintf(text, sizeof text, "%s%s%s", property ? "box { " : "", info->name,
                 info->cls == KWC_FUNCTION ? "(" : "");
        lex_run run;
        lex(&run, text);
        int at = property ? 2 : 0;
        ck_assert_int_eq(run.count, property ? 3 : info->cls == KWC_FUNCTION ? 2 : 1);
        if (info->cls == KWC_STATEMENT) {
            ck_assert_int_eq(run.tokens[0].token, statements[i]);
        } else {
            ck_assert_int_eq(run.tokens[at].token, info->cls == KWC_FUNCTION ? FUNC : KEYWORD);
            ck_assert_int_eq(run.tokens[at].value.id, i);
        }
        ck_assert_int_eq(keyword_lookup(info->name, strlen(info->name)), i);
        lex_done(&run);
    }
    ck_assert_int_eq(keyword_lookup("spherex", 6), KW_SPHERE);
    ck_assert_int_eq(keyword_lookup("spherex", 7), -1);
}
END_TEST

START_TEST(test_scan_punctuation)
{
    lex_run run;
    lex(&run, "{[(,=+-*/^)]}");
    static const int kinds[] = {'{', '[', '(', ',', '=', '+', '-', '*', '/', '^', ')', ']', '}'};
    assert_kinds(&run, kinds, 13);
    for (int i = 0; i < 13; i++) {
        ck_assert_uint_eq(run.tokens[i].loc.begin, (size_t)i);
        ck_assert_uint_eq(run.tokens[i].loc.end, (size_t)i + 1);
    }
    lex_done(&run);
}
END_TEST

/* [LANG-LEX-LOC-1] spans are byte offsets; columns count bytes from 1 (a
 * tab is one column). */
START_TEST(test_scan_locations_and_columns)
{
    lex_run run;
    lex(&run, "let  x\t= 12.5\n  sphere { radius \"r\" }");
    ck_assert_int_eq(run.count, 9);
    const size_t begins[] = {0, 5, 7, 9, 16, 23, 25, 32, 36};
    const size_t ends[] = {3, 6, 8, 13, 22, 24, 31, 35, 37};
    const int cols[] = {1, 6, 8, 10, 3, 10, 12, 19, 23};
    for (int i = 0; i < 9; i++) {
        int line, col;
        ck_assert_uint_eq(run.tokens[i].loc.begin, begins[i]);
        ck_assert_uint_eq(run.tokens[i].loc.end, ends[i]);
        ck_assert_int_eq(run.tokens[i].loc.file, 0);
        source_line_col(run.sources.files[0], run.tokens[i].loc.begin, &line, &col);
        ck_assert_int_eq(line, i < 4 ? 1 : 2);
        ck_assert_int_eq(col, cols[i]);
    }
    lex_done(&run);
}
END_TEST

/* End of input is placed after the last non-blank byte. */
START_TEST(test_scan_end_location)
{
    lex_run run;
    lex(&run, "a {\n  b\n\n \t\r\n");
    ck_assert_int_eq(run.count, 3);
    ck_assert_int_eq(run.tokens[3].token, 0);
    ck_assert_uint_eq(run.tokens[3].loc.begin, 7);
    ck_assert_uint_eq(run.tokens[3].loc.end, 7);
    lex_done(&run);
    lex(&run, "");
    ck_assert_int_eq(run.count, 0);
    ck_assert_uint_eq(run.tokens[0].loc.begin, 0);
    lex_done(&run);
}
END_TEST

/* The bracket stack behind "(to close '{' at line 3)": a closer takes
 * effect at the next token, and closes the innermost matching opener. */
START_TEST(test_scan_bracket_stack)
{
    lex_run run;
    lex(&run, "{ [ ( ) ]");
    ck_assert_int_eq(run.count, 5);
    /* Past the end every pending closer has been applied: one '{' left. */
    ck_assert_int_eq(run.ctx.bracket_depth, 1);
    lex_done(&run);
    lex(&run, "{ [ }");
    ck_assert_int_eq(run.ctx.bracket_depth, 0);
    lex_done(&run);
    lex(&run, "{ ) ]");
    ck_assert_int_eq(run.ctx.bracket_depth, 1);
    ck_assert_uint_eq(run.ctx.brackets[0].begin, 0);
    lex_done(&run);
}
END_TEST

/* Tokens far longer than flex's 16 kB buffer: a comment, a name, a string,
 * a number, and 20 kB of blanks between a function word and its '('. */
START_TEST(test_scan_long_tokens)
{
    enum { LONG = 100000 };
    char *text = malloc(LONG + 64);
    ck_assert_ptr_nonnull(text);
    static const struct {
        char first, fill;
        int token;
    } cases[] = {{'#', 'x', 0}, {'a', 'b', NAME}, {'"', 's', BAD_STRING}, {'1', '2', NUMBER}};
    for (int i = 0; i < 4; i++) {
        lex_run run;
        text[0] = cases[i].first;
        memset(text + 1, cases[i].fill, LONG - 1);
        lex_bytes(&run, text, LONG);
        ck_assert_int_eq(run.count, cases[i].token ? 1 : 0);
        if (cases[i].token) {
            ck_assert_int_eq(run.tokens[0].token, cases[i].token);
            ck_assert_uint_eq(run.tokens[0].loc.end, LONG);
        }
        lex_done(&run);
    }
    memcpy(text, "sqrt", 4);
    memset(text + 4, ' ', 20000);
    memcpy(text + 20004, "(2)", 4);
    lex_run run;
    lex(&run, text);
    ck_assert_int_eq(run.count, 4);
    ck_assert_int_eq(run.tokens[0].token, FUNC);
    ck_assert_int_eq(run.tokens[1].token, '(');
    ck_assert_uint_eq(run.tokens[1].loc.begin, 20004);
    lex_done(&run);
    free(text);
}
END_TEST

Suite *suite_lexer(void)
{
    Suite *s = suite_create("lexer");
    TCase *tc = tcase_create("lexer");
    tcase_add_test(tc, test_scan_numbers_with_decimals_and_exponents);
    tcase_add_test(tc, test_scan_number_out_of_range_is_a_number);
    tcase_add_test(tc, test_scan_malformed_numbers);
    tcase_add_test(tc, test_scan_range_dots);
    tcase_add_test(tc, test_scan_lone_dot);
    tcase_add_test(tc, test_scan_strings_and_escapes);
    tcase_add_test(tc, test_scan_bad_strings);
    tcase_add_test(tc, test_scan_comments);
    tcase_add_test(tc, test_scan_line_endings);
    tcase_add_test(tc, test_scan_bad_bytes);
    tcase_add_test(tc, test_scan_blanks);
    tcase_add_test(tc, test_scan_byte_order_mark);
    tcase_add_test(tc, test_scan_keywords_versus_names);
    tcase_add_test(tc, test_scan_property_words_in_context);
    tcase_add_test(tc, test_scan_every_keyword);
    tcase_add_test(tc, test_scan_punctuation);
    tcase_add_test(tc, test_scan_locations_and_columns);
    tcase_add_test(tc, test_scan_end_location);
    tcase_add_test(tc, test_scan_bracket_stack);
    tcase_add_test(tc, test_scan_long_tokens);
    suite_add_tcase(s, tc);
    return s;
}
