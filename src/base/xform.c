/*
 * xform.c - 3x4 affine transforms: composition, inversion, application.
 *
 * A transform is p' = L p + T with L the 3x3 block m[i][0..2] and T the
 * column m[i][3].  Everything is a small pure function on values; nothing
 * here allocates or keeps state.
 */
#include <float.h>
#include "base/xform.h"

/* Relative tolerance of xform_is_similarity: L^T L must equal s^2 I to this
 * fraction of s^2.  Rotations built from sin/cos and composed a few times
 * are orthogonal to about 1e-15; 1e-12 accepts those and nothing that would
 * turn a sphere into a visibly different ellipsoid. */
#define SIMILARITY_TOL 1e-12

/* Hadamard's bound |det L| <= product of the row lengths is an equality for
 * orthogonal rows; a ratio below this means the rows are dependent to within
 * rounding and the inverse would be noise. */
#define SINGULAR_RATIO (64.0 * DBL_EPSILON)

/* The identity, +0 off the diagonal: made by every primitive's load, so a
 * copy of a constant rather than twelve choices. */
static const xform identity = {{{1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}}};

xform xform_identity(void)
{
    return identity;
}

xform xform_translate(vec3 t)
{
    xform a = xform_identity();
    a.m[0][3] = t.x;
    a.m[1][3] = t.y;
    a.m[2][3] = t.z;
    return a;
}

xform xform_scale(vec3 s)
{
    xform a = xform_identity();
    a.m[0][0] = s.x;
    a.m[1][1] = s.y;
    a.m[2][2] = s.z;
    return a;
}

/*
 * sin and cos of an angle in degrees, exact at multiples of 90 degrees.
 * The angle is reduced to q*90 + r with |r| <= 45 (fmod is exact), so
 * sin(r), cos(r) are evaluated on a small argument and the quadrant is
 * applied by swapping and negating: r == 0 gives exact 0 and 1.
 */
static void sincos_degrees(double degrees, double *s, double *c)
{
    static const double pi = 3.14159265358979323846;
    if (!isfinite(degrees)) {
        *s = *c = NAN;
        return;
    }
    double a = fmod(degrees, 360.0);
    double q = floor(a / 90.0 + 0.5);
    double r = (a - 90.0 * q) * (pi / 180.0);
    double sr = sin(r), cr = cos(r);
    int quadrant = ((int)q % 4 + 4) % 4;
    switch (quadrant) {
    case 0: *s = sr; *c = cr; break;
    case 1: *s = cr; *c = -sr; break;   /* sin(90+r) = cos r, cos(90+r) = -sin r */
    case 2: *s = -sr; *c = -cr; break;
    default: *s = -cr; *c = sr; break;  /* sin(270+r) = -cos r, cos(270+r) = sin r */
    }
}

/* A rotation about one axis (0 x, 1 y, 2 z) by the right-hand rule: the
 * other two axes u, v = (axis+1)%3, (axis+2)%3 turn u toward v. */
static xform rotate_axis(int axis, double degrees)
{
    double s, c;
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    xform a = xform_identity();
    sincos_degrees(degrees, &s, &c);
    a.m[u][u] = c;
    a.m[u][v] = -s;
    a.m[v][u] = s;
    a.m[v][v] = c;
    return a;
}

xform xform_rotate_xyz(vec3 degrees)
{
    xform rx = rotate_axis(0, degrees.x), ry = rotate_axis(1, degrees.y);
    xform rz = rotate_axis(2, degrees.z);
    xform yx = xform_compose(&ry, &rx);
    return xform_compose(&rz, &yx);
}

/* (A o B) p = A_L (B_L p + B_T) + A_T: linear parts multiply, the
 * translation is B's moved by A. */
xform xform_compose(const xform *after, const xform *before)
{
    xform c;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++) {
            double sum = j == 3 ? after->m[i][3] : 0.0;
            for (int k = 0; k < 3; k++)
                sum += after->m[i][k] * before->m[k][j];
            c.m[i][j] = sum;
        }
    }
    return c;
}

static double row_length(const xform *a, int i)
{
    return vec_length(vec_make(a->m[i][0], a->m[i][1], a->m[i][2]));
}

/* The power of two e with the row's largest entry in [1, 2) after scaling by
 * 2^-e (0 for a zero row): an exact scaling that keeps the products below
 * from overflowing or underflowing whatever the transform's scale. */
static int row_exponent(const xform *a, int i)
{
    double m = fmax(fabs(a->m[i][0]), fmax(fabs(a->m[i][1]), fabs(a->m[i][2])));
    int e = 0;
    if (m > 0.0)
        (void)frexp(m, &e);
    return e - 1;
}

/* m = D^-1 a's linear part, row i divided by 2^e[i] (row_exponent). */
static void scale_rows(const xform *a, xform *m, int e[3])
{
    *m = *a;
    for (int i = 0; i < 3; i++) {
        e[i] = row_exponent(a, i);
        for (int j = 0; j < 3; j++)
            m->m[i][j] = ldexp(a->m[i][j], -e[i]);
    }
}

/*
 * The inverse of p' = L p + T is p = L^-1 p' - L^-1 T.  Write L = D M with
 * D = diag(2^e_i) scaling row i of L to M's row (largest entry in [1, 2)):
 * then L^-1 = M^-1 D^-1, and M^-1 is the adjugate of M over det M: entry
 * (j,i) is the cofactor of (i,j), which with cyclic indices is a 2x2
 * determinant and needs no sign.  The scaling is exact, so the result is the
 * plain adjugate formula's to the bit whenever that one neither overflows nor
 * underflows, and it also inverts `scale 2^400` or `scale 1e-300`, whose
 * determinant alone is out of range.  Returns 0 (and leaves *inverse alone)
 * when L is singular: det M is 0, the rows are dependent to rounding
 * (SINGULAR_RATIO), or an entry of the inverse overflows.
 */
/* Whether a is the identity to the bit (+0 off the diagonal). */
static int exact_identity(const xform *a)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (a->m[i][j] != identity.m[i][j] || signbit(a->m[i][j]))
                return 0;
    return 1;
}

int xform_invert(const xform *a, xform *inverse)
{
    xform r, m;
    double cof[3][3];
    int e[3];
    /* Every untransformed primitive (each of the 100 000 spheres of a big
     * scene) comes here with the identity: its inverse is what the steps
     * below give for it, the identity with translations -(0 + 0 + 0) = -0. */
    if (exact_identity(a)) {
        *inverse = *a;
        for (int i = 0; i < 3; i++)
            inverse->m[i][3] = -0.0;
        return 1;
    }
    scale_rows(a, &m, e);
    for (int i = 0; i < 3; i++) {
        int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; j++) {
            int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            cof[i][j] = m.m[i1][j1] * m.m[i2][j2] - m.m[i1][j2] * m.m[i2][j1];
        }
    }
    double det = m.m[0][0] * cof[0][0] + m.m[0][1] * cof[0][1] + m.m[0][2] * cof[0][2];
    double bound = row_length(&m, 0) * row_length(&m, 1) * row_length(&m, 2);
    if (det == 0.0 || !isfinite(det) || !(fabs(det) > SINGULAR_RATIO * bound))
        return 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[i][j] = ldexp(cof[j][i] / det, -e[j]);
    for (int i = 0; i < 3; i++) {
        r.m[i][3] = -(r.m[i][0] * a->m[0][3] + r.m[i][1] * a->m[1][3] + r.m[i][2] * a->m[2][3]);
        for (int j = 0; j < 4; j++)
            if (!isfinite(r.m[i][j]))
                return 0;
    }
    *inverse = r;
    return 1;
}

vec3 xform_point(const xform *a, vec3 p)
{
    return vec_make(a->m[0][0] * p.x + a->m[0][1] * p.y + a->m[0][2] * p.z + a->m[0][3],
                    a->m[1][0] * p.x + a->m[1][1] * p.y + a->m[1][2] * p.z + a->m[1][3],
                    a->m[2][0] * p.x + a->m[2][1] * p.y + a->m[2][2] * p.z + a->m[2][3]);
}

vec3 xform_vector(const xform *a, vec3 v)
{
    return vec_make(a->m[0][0] * v.x + a->m[0][1] * v.y + a->m[0][2] * v.z,
                    a->m[1][0] * v.x + a->m[1][1] * v.y + a->m[1][2] * v.z,
                    a->m[2][0] * v.x + a->m[2][1] * v.y + a->m[2][2] * v.z);
}

/* n' = (L^-1)^T n keeps n' . (L t) = n . t = 0 for every tangent t.  The
 * result is not normalised. */
vec3 xform_normal(const xform *inverse, vec3 n)
{
    const double (*m)[4] = inverse->m;
    return vec_make(m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z,
                    m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
                    m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z);
}

/* Exact comparison: rotations by multiples of 90 degrees and scale 1 give
 * exact entries, so a transform that ends up at the identity is one. */
int xform_is_identity(const xform *a)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (a->m[i][j] != identity.m[i][j])
                return 0;
    return 1;
}

/*
 * L = s R with R a rotation (det +1) and s > 0 exactly when L^T L = s^2 I
 * and det L > 0.  s^2 is taken as trace(L^T L)/3; every entry of L^T L must
 * match s^2 I to SIMILARITY_TOL * s^2.  Reflections are refused, so a mirror
 * keeps its local frame (correct, merely slower).
 */
int xform_is_similarity(const xform *a, double *scale)
{
    /* Work on M = L / 2^e with e the largest row exponent (exact): L^T L
     * would overflow or underflow for a scale beyond 2^+-511, M^T M never. */
    xform m;
    int e[3];
    scale_rows(a, &m, e);
    int top = e[0] > e[1] ? (e[0] > e[2] ? e[0] : e[2]) : (e[1] > e[2] ? e[1] : e[2]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m.m[i][j] = ldexp(a->m[i][j], -top);
    double g[3][3], s2 = 0.0;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            g[i][j] = m.m[0][i] * m.m[0][j] + m.m[1][i] * m.m[1][j] + m.m[2][i] * m.m[2][j];
        }
        s2 += g[i][i] / 3.0;
    }
    if (!(s2 > 0.0) || !isfinite(s2))
        return 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (!(fabs(g[i][j] - (i == j ? s2 : 0.0)) <= SIMILARITY_TOL * s2))
                return 0;
    double det = m.m[0][0] * (m.m[1][1] * m.m[2][2] - m.m[1][2] * m.m[2][1])
               - m.m[0][1] * (m.m[1][0] * m.m[2][2] - m.m[1][2] * m.m[2][0])
               + m.m[0][2] * (m.m[1][0] * m.m[2][1] - m.m[1][1] * m.m[2][0]);
    if (!(det > 0.0))
        return 0;
    if (scale)
        *scale = ldexp(sqrt(s2), top);
    return 1;
}
