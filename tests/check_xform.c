/* Tests of src/base/xform.c: composition order, inversion, normals, exact right
 * angles and the similarity test.  Expected values are worked out by hand
 * in the comments. */
#include <float.h>
#include "testlib.h"
#include "base/xform.h"

static int xform_equal(const xform *a, const xform *b, double tol)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (!(fabs(a->m[i][j] - b->m[i][j]) <= tol))
                return 0;
    return 1;
}

/* A fixed, well-conditioned but general transform: shear, non-uniform
 * scale, rotation, translation. */
static xform general_xform(void)
{
    xform r = xform_rotate_xyz(vec_make(17, -40, 123));
    xform s = xform_scale(vec_make(2, 0.5, -3));
    xform t = xform_translate(vec_make(1.5, -2, 7));
    xform sh = xform_identity();
    sh.m[0][1] = 0.7; /* x += 0.7 y */
    xform a = xform_compose(&s, &sh);
    xform b = xform_compose(&r, &a);
    return xform_compose(&t, &b);
}

START_TEST(test_xform_compose_applies_before_first)
{
    /* translate by (1,0,0) then scale by 2: the origin goes to (1,0,0)
     * and then to (2,0,0); the other order would give (1,0,0). */
    xform t = xform_translate(vec_make(1, 0, 0)), s = xform_scale(vec_make(2, 2, 2));
    xform st = xform_compose(&s, &t), ts = xform_compose(&t, &s);
    ck_assert_vec_near(xform_point(&st, vec_make(0, 0, 0)), vec_make(2, 0, 0), 0.0);
    ck_assert_vec_near(xform_point(&ts, vec_make(0, 0, 0)), vec_make(1, 0, 0), 0.0);
    ck_assert_vec_near(xform_point(&st, vec_make(0, 3, 0)), vec_make(2, 6, 0), 0.0);
    /* Vectors ignore the translation. */
    ck_assert_vec_near(xform_vector(&st, vec_make(1, 1, 1)), vec_make(2, 2, 2), 0.0);
}
END_TEST

START_TEST(test_xform_compose_matches_applying_in_turn)
{
    xform a = general_xform(), b = xform_rotate_xyz(vec_make(5, 6, 7));
    xform ab = xform_compose(&a, &b);
    vec3 p = vec_make(0.3, -1.2, 2.5);
    ck_assert_vec_near(xform_point(&ab, p), xform_point(&a, xform_point(&b, p)), 1e-13);
}
END_TEST

START_TEST(test_xform_invert_round_trip)
{
    xform a = general_xform(), inv;
    ck_assert(xform_invert(&a, &inv));
    xform left = xform_compose(&inv, &a), right = xform_compose(&a, &inv);
    xform id = xform_identity();
    ck_assert(xform_equal(&left, &id, 1e-14));
    ck_assert(xform_equal(&right, &id, 1e-14));
    vec3 p = vec_make(-4, 0.25, 9);
    ck_assert_vec_near(xform_point(&inv, xform_point(&a, p)), p, 1e-13);
}
END_TEST

START_TEST(test_xform_invert_by_hand)
{
    /* p' = 2p + (1,2,3) has inverse p = p'/2 - (0.5, 1, 1.5). */
    xform s = xform_scale(vec_make(2, 2, 2)), t = xform_translate(vec_make(1, 2, 3));
    xform a = xform_compose(&t, &s), inv;
    ck_assert(xform_invert(&a, &inv));
    ck_assert_near(inv.m[0][0], 0.5, 0.0);
    ck_assert_near(inv.m[1][1], 0.5, 0.0);
    ck_assert_vec_near(vec_make(inv.m[0][3], inv.m[1][3], inv.m[2][3]), vec_make(-0.5, -1, -1.5), 0.0);
}
END_TEST

START_TEST(test_xform_invert_identity)
{
    /* The identity (the shortcut for untransformed primitives) gives what
     * the adjugate formula gives: the identity, with translations
     * -(1 * 0 + 0 * 0 + 0 * 0) = -0; the same with a -0 off the diagonal,
     * which takes the general path. */
    xform id = xform_identity(), inv, minus = xform_identity(), inv2;
    memset(&inv, 0x55, sizeof inv);
    ck_assert(xform_invert(&id, &inv));
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            ck_assert(inv.m[i][j] == (i == j ? 1.0 : 0.0));
            ck_assert(!signbit(inv.m[i][j]));
        }
        ck_assert(inv.m[i][3] == 0.0 && signbit(inv.m[i][3]));
    }
    minus.m[0][1] = -0.0;
    ck_assert(xform_invert(&minus, &inv2));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            ck_assert(inv2.m[i][j] == inv.m[i][j]);
}
END_TEST

START_TEST(test_xform_invert_refuses_singular)
{
    xform inv = xform_identity(), keep = inv;
    xform flat = xform_scale(vec_make(1, 0, 1));
    ck_assert(!xform_invert(&flat, &inv));
    ck_assert(xform_equal(&inv, &keep, 0.0)); /* untouched on failure */
    /* Rows dependent to rounding: row 2 = row 0 + row 1 + 1e-17. */
    xform dep = xform_identity();
    dep.m[0][1] = 0.5;
    dep.m[2][0] = 1.0;
    dep.m[2][1] = 1.5;
    dep.m[2][2] = 1e-17;
    ck_assert(!xform_invert(&dep, &inv));
    xform nan = xform_identity();
    nan.m[1][1] = NAN;
    ck_assert(!xform_invert(&nan, &inv));
    /* A tiny but exact scale is fine. */
    xform tiny = xform_scale(vec_make(1e-200, 1, 1));
    ck_assert(xform_invert(&tiny, &inv));
    ck_assert_rel(inv.m[0][0], 1e200, 1e-15);
}
END_TEST

/* A uniform scale 2^k with a turn: the determinant s^3 (2^+-1200) is out of
 * range, the inverse is not.  The inverse of the scaled transform is the
 * unscaled inverse times 2^-k to the bit (powers of two are exact), and the
 * scaled transform is a similarity with scale exactly 2^k. */
START_TEST(test_xform_invert_huge_and_tiny_scales)
{
    static const int ks[] = {400, -400, 1000, -1000};
    xform r = xform_rotate_xyz(vec_make(17, -40, 123)), unscaled;
    ck_assert(xform_invert(&r, &unscaled));
    for (int i = 0; i < 4; i++) {
        xform s = xform_scale(vec_splat(ldexp(1.0, ks[i]))), a = xform_compose(&s, &r), inv;
        ck_assert_msg(xform_invert(&a, &inv), "scale 2^%d refused", ks[i]);
        for (int row = 0; row < 3; row++)
            for (int col = 0; col < 3; col++)
                ck_assert(inv.m[row][col] == ldexp(unscaled.m[row][col], -ks[i]));
        double scale = 0;
        ck_assert(xform_is_similarity(&a, &scale));
        ck_assert(scale == ldexp(1.0, ks[i]));
    }
}
END_TEST

START_TEST(test_xform_normal_stays_perpendicular)
{
    xform a = general_xform(), inv;
    ck_assert(xform_invert(&a, &inv));
    /* n is perpendicular to both tangents of the plane it belongs to. */
    vec3 n = vec_make(1, 2, -1), t1 = vec_make(1, 0, 1), t2 = vec_make(2, -1, 0);
    ck_assert_near(vec_dot(n, t1), 0.0, 0.0);
    ck_assert_near(vec_dot(n, t2), 0.0, 0.0);
    vec3 nw = vec_normalize(xform_normal(&inv, n));
    vec3 w1 = vec_normalize(xform_vector(&a, t1)), w2 = vec_normalize(xform_vector(&a, t2));
    ck_assert_near(vec_dot(nw, w1), 0.0, 1e-15);
    ck_assert_near(vec_dot(nw, w2), 0.0, 1e-15);
    /* Transforming the vector n itself would not be perpendicular. */
    vec3 wrong = vec_normalize(xform_vector(&a, n));
    ck_assert(fabs(vec_dot(wrong, w1)) > 1e-3);
}
END_TEST

START_TEST(test_xform_rotate_xyz_right_angles_exact)
{
    /* Right-hand rule: about z, x goes to y; about x, y goes to z; about y,
     * z goes to x.  Every entry must be exactly 0, 1 or -1. */
    xform rz = xform_rotate_xyz(vec_make(0, 0, 90));
    xform rx = xform_rotate_xyz(vec_make(90, 0, 0));
    xform ry = xform_rotate_xyz(vec_make(0, 90, 0));
    ck_assert_vec_near(xform_point(&rz, vec_make(1, 0, 0)), vec_make(0, 1, 0), 0.0);
    ck_assert_vec_near(xform_point(&rx, vec_make(0, 1, 0)), vec_make(0, 0, 1), 0.0);
    ck_assert_vec_near(xform_point(&ry, vec_make(0, 0, 1)), vec_make(1, 0, 0), 0.0);
    xform r = xform_rotate_xyz(vec_make(-270, 540, 3690)); /* x 90, y 180, z 90 */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            ck_assert(r.m[i][j] == 0.0 || fabs(r.m[i][j]) == 1.0);
    /* (0,1,0): x 90 -> (0,0,1); y 180 -> (0,0,-1); z 90 -> (0,0,-1). */
    ck_assert_vec_near(xform_point(&r, vec_make(0, 1, 0)), vec_make(0, 0, -1), 0.0);
    /* (1,0,0): x -> (1,0,0); y 180 -> (-1,0,0); z 90 -> (0,-1,0). */
    ck_assert_vec_near(xform_point(&r, vec_make(1, 0, 0)), vec_make(0, -1, 0), 0.0);
}
END_TEST

START_TEST(test_xform_rotate_xyz_order_and_general_angle)
{
    /* x first, then y: (0,1,0) -x90-> (0,0,1) -y90-> (1,0,0).  The
     * opposite order would give (0,1,0) -y90-> (0,1,0) -x90-> (0,0,1). */
    xform r = xform_rotate_xyz(vec_make(90, 90, 0));
    ck_assert_vec_near(xform_point(&r, vec_make(0, 1, 0)), vec_make(1, 0, 0), 0.0);
    /* 30 degrees about z: (cos 30, sin 30, 0) = (sqrt(3)/2, 1/2, 0). */
    xform r30 = xform_rotate_xyz(vec_make(0, 0, 30));
    ck_assert_vec_near(xform_point(&r30, vec_make(1, 0, 0)), vec_make(sqrt(3.0) / 2, 0.5, 0), 2e-16);
    /* -135 about x: y goes to (0, cos(-135), sin(-135)) = (0, -r, -r). */
    xform rm = xform_rotate_xyz(vec_make(-135, 0, 0));
    double h = sqrt(0.5);
    ck_assert_vec_near(xform_point(&rm, vec_make(0, 1, 0)), vec_make(0, -h, -h), 2e-16);
}
END_TEST

START_TEST(test_xform_is_identity)
{
    xform id = xform_identity();
    ck_assert(xform_is_identity(&id));
    xform full = xform_rotate_xyz(vec_make(360, -720, 90 * 4));
    ck_assert(xform_is_identity(&full));
    xform t = xform_translate(vec_make(0, 0, 1e-300));
    ck_assert(!xform_is_identity(&t));
}
END_TEST

START_TEST(test_xform_is_similarity)
{
    double s = 0.0;
    xform r = xform_rotate_xyz(vec_make(10, 20, 30));
    xform k = xform_scale(vec_make(3, 3, 3)), t = xform_translate(vec_make(5, 6, 7));
    xform rk = xform_compose(&r, &k), trk = xform_compose(&t, &rk);
    ck_assert(xform_is_similarity(&trk, &s));
    ck_assert_rel(s, 3.0, 1e-14);
    xform squash = xform_scale(vec_make(1, 1.000001, 1));
    ck_assert(!xform_is_similarity(&squash, &s));
    xform mirror = xform_scale(vec_make(-2, 2, 2));
    ck_assert(!xform_is_similarity(&mirror, &s));
    xform flat = xform_scale(vec_make(0, 0, 0));
    ck_assert(!xform_is_similarity(&flat, &s));
    /* A point reflection -I has det -1: not a rotation. */
    xform neg = xform_scale(vec_make(-1, -1, -1));
    ck_assert(!xform_is_similarity(&neg, &s));
    xform half_turn = xform_rotate_xyz(vec_make(0, 0, 180));
    ck_assert(xform_is_similarity(&half_turn, &s));
    ck_assert_near(s, 1.0, 0.0);
}
END_TEST

Suite *suite_xform(void)
{
    Suite *s = suite_create("xform");
    TCase *tc = tcase_create("xform");
    tcase_add_test(tc, test_xform_compose_applies_before_first);
    tcase_add_test(tc, test_xform_compose_matches_applying_in_turn);
    tcase_add_test(tc, test_xform_invert_round_trip);
    tcase_add_test(tc, test_xform_invert_by_hand);
    tcase_add_test(tc, test_xform_invert_identity);
    tcase_add_test(tc, test_xform_invert_refuses_singular);
    tcase_add_test(tc, test_xform_invert_huge_and_tiny_scales);
    tcase_add_test(tc, test_xform_normal_stays_perpendicular);
    tcase_add_test(tc, test_xform_rotate_xyz_right_angles_exact);
    tcase_add_test(tc, test_xform_rotate_xyz_order_and_general_angle);
    tcase_add_test(tc, test_xform_is_identity);
    tcase_add_test(tc, test_xform_is_similarity);
    suite_add_tcase(s, tc);
    return s;
}
