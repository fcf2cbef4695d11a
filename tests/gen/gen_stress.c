/*
 * gen_stress.c - the stress scenes of scenes/stress/ whose numbers are
 * computed (critical angles, a Phong lobe 1e-3 rad off its peak, a
 * refracted path's target) and the OBJ meshes the watertightness cases
 * sweep (spec/numerics.md, section 3):
 *
 *     build/gen_stress [ROOT]                  (make fixtures)
 *
 * The output is committed; tests/test_stability.c re-derives every property
 * in long double from the loaded scene, so a number written here only has
 * to be close.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "gen.h"

#define DIR "scenes/stress/"

/* "[x, y, z]" with the shortest decimals. */
static const char *vec_text(const double v[3], char *buf, size_t size)
{
    char a[GEN_REPR_MAX], b[GEN_REPR_MAX], c[GEN_REPR_MAX];
    snprintf(buf, size, "[%s, %s, %s]", gen_repr(v[0], a), gen_repr(v[1], b), gen_repr(v[2], c));
    return buf;
}

static double dot(const double a[3], const double b[3])
{
    return 0.0 + a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void unit(const double v[3], double out[3])
{
    double n = sqrt(dot(v, v));
    for (int i = 0; i < 3; i++)
        out[i] = v[i] / n;
}

static void along(const double p[3], double t, const double d[3], double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = p[i] + t * d[i];
}

/* Camera inside a glass box (ior 1.5) looking up at its top face y = 0 at
 * theta = theta_c + sign 1e-12 from the face normal. */
static void critical(const char *root, const char *name, int sign)
{
    double th = asin(1 / 1.5) + sign * 1e-12;
    double d[3] = {sin(th), cos(th), 0.0}, eye[3] = {0.0, -1.0, 0.0}, at[3];
    along(eye, 1, d, at);
    char e[128], l[128];
    FILE *f = gen_open(root, name);
    fprintf(f, "# Stress: incidence 1e-12 rad %s the critical angle asin(1/1.5), from\n"
               "# inside a glass box (ior 1.5, t 1, Kd 0) through its top face.  Written by\n"
               "# tests/gen/gen_stress.c.\n"
               "# Must hold: the camera ray %s.\n",
            sign < 0 ? "below" : "above",
            sign < 0 ? "refracts: the ray leaves just above the face and sees the background, pixel = t * 0.5 = 0.5"
                     : "is totally reflected, and so at every later face: the ray is trapped until max_depth and "
                       "the pixel is the local colour 0");
    fprintf(f, "image  { width 1 height 1 background 0.5 max_depth 6 }\n"
               "camera { perspective eye %s look_at %s up [0, 0, 1] fov 1 }\n"
               "box { from [-10, -10, -10] to [10, 0, 10] material { Kd 0 t 1 ior 1.5 } }\n",
            vec_text(eye, e, sizeof e), vec_text(at, l, sizeof l));
    gen_close(f, name);
}

/* Rodrigues' rotation of v about the unit axis k. */
static void rot(const double v[3], const double k[3], double ang, double out[3])
{
    double c = cos(ang), s = sin(ang), kv = dot(k, v);
    double kxv[3] = {k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
    for (int i = 0; i < 3; i++)
        out[i] = v[i] * c + kxv[i] * s + k[i] * kv * (1 - c);
}

/* A plane through the origin with a generic normal, viewed along it; the
 * light's mirror direction R is 1e-3 rad from V, so the lobe with n = 1e6
 * is about exp(-0.5). */
static void phong_off(const char *root)
{
    const char *name = DIR "phong_n1e6_off.scene";
    const double raw[3] = {1, 2, 3};
    double n[3], axis[3], r[3], l[3], eye[3];
    unit(raw, n);
    double across[3] = {n[1] * 1 - n[2] * 0, n[2] * 0.3 - n[0] * 1, n[0] * 0 - n[1] * 0.3};
    unit(across, axis);
    rot(n, axis, 1e-3, r); /* R, the mirror of L about N */
    for (int i = 0; i < 3; i++) {
        l[i] = 2 * dot(n, r) * n[i] - r[i];
        eye[i] = 10 * n[i];
    }
    double towards[3] = {-l[0], -l[1], -l[2]};
    char e[128], d[128];
    FILE *f = gen_open(root, name);
    fprintf(f, "# Stress: Phong exponent 1e6, 1e-3 rad off the peak, in a frame along no\n"
               "# axis (normal [1, 2, 3]).  The lobe is cos^1e6(1e-3) = exp(-0.5): an error of\n"
               "# one ulp in V.R is an error of 1e6 ulps in the lobe.  Written by\n"
               "# tests/gen/gen_stress.c.\n"
               "# Must hold: the pixel is Kd*Ia + Kd*E*(N.L) + Ks*E*(V.R)^n with N, L, V from\n"
               "# the loaded scene, to 1e-9 relative (spec/numerics.md has the measured error).\n"
               "image  { width 1 height 1 background 0 }\n"
               "camera { orthographic eye %s look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
               "ambient { color 0.1 }\n"
               "distant_light { direction %s power 1 }\n"
               "plane { point [0, 0, 0] normal [1, 2, 3] material { Kd 0.25 Ks 0.5 n 1e6 } }\n",
            vec_text(eye, e, sizeof e), vec_text(towards, d, sizeof d));
    gen_close(f, name);
}

/* Camera inside box A (ior 1.5, z in [-1, 0]) looking at the shared face
 * z = 0 with sin(theta) = 0.7: A -> air would be total internal reflection
 * (0.7 > 1/1.5) but A -> B (ior 1.4) refracts to sin = 0.75.  The ray then
 * leaves B through its side x = 1 into air; a small target ball sits 10
 * units along that exit ray. */
static void touching_inside(const char *root)
{
    const char *name = DIR "touching_glass_camera_inside.scene";
    double s1 = 0.7, eye[3] = {-0.5, 0.0, -0.5}, p1[3], p2[3], target[3], at[3];
    double d1[3] = {s1, 0.0, sqrt(1 - s1 * s1)};
    along(eye, -eye[2] / d1[2], d1, p1);
    double s2 = 1.5 * s1 / 1.4;
    double d2[3] = {s2, 0.0, sqrt(1 - s2 * s2)};
    along(p1, (1 - p1[0]) / d2[0], d2, p2);
    double sz = 1.4 * d2[2]; /* leaving through x = 1: the part along the face (z) scales by 1.4/1 */
    double d3[3] = {sqrt(1 - sz * sz), 0.0, sz};
    along(p2, 10, d3, target);
    along(eye, 1, d1, at);
    char e[128], l[128], t[128];
    FILE *f = gen_open(root, name);
    fprintf(f, "# Stress: the camera inside glass box A (ior 1.5) that touches box B (ior 1.4)\n"
               "# along the face z = 0.  The camera ray meets the shared face at sin = 0.7:\n"
               "# it must bend 1.5 -> 1.4 (to sin 0.75), not 1.5 -> air (total internal\n"
               "# reflection) nor through an air gap.  It then leaves B through the face\n"
               "# x = 1 and travels to a small red ball placed on the exit ray computed by\n"
               "# Snell's law (tests/gen/gen_stress.c).\n"
               "# Must hold: the pixel is the ball's ambient colour [1, 0, 0] exactly (every\n"
               "# crossing has t = 1 and Kd 0).\n"
               "image  { width 1 height 1 background 0.5 max_depth 6 }\n"
               "camera { perspective eye %s look_at %s up [0, 1, 0] fov 1 }\n"
               "ambient { color 1 }\n"
               "box { from [-1, -1, -1] to [1, 1, 0] material { Kd 0 t 1 ior 1.5 } }\n"
               "box { from [-1, -1, 0] to [1, 1, 1] material { Kd 0 t 1 ior 1.4 } }\n"
               "sphere { center %s radius 0.2 material { Kd [1, 0, 0] } }\n",
            vec_text(eye, e, sizeof e), vec_text(at, l, sizeof l), vec_text(target, t, sizeof t));
    gen_close(f, name);
}

/* d unit, n unit facing against d: the refracted unit vector (the paths
 * here have no total internal reflection). */
static void refract(const double d[3], const double n[3], double n1, double n2, double out[3])
{
    double c = -dot(d, n), eta = n1 / n2, k = 1 - eta * eta * (1 - c * c), t[3];
    for (int i = 0; i < 3; i++)
        t[i] = eta * d[i] + (eta * c - sqrt(k)) * n[i];
    unit(t, out);
}

/* o inside the sphere of radius r at the origin: the exit point along d. */
static void sphere_exit(const double o[3], const double d[3], double r, double out[3])
{
    double b = dot(o, d), c = dot(o, o) - r * r;
    along(o, -b + sqrt(b * b - c), d, out);
}

/* The inward normal at p on a sphere about the origin. */
static void inward(const double p[3], double out[3])
{
    unit(p, out);
    for (int i = 0; i < 3; i++)
        out[i] = -out[i];
}

/* Camera inside glass ball A (radius 1, ior 1.3) inside glass ball B
 * (radius 2, ior 1.6), both centred at the origin.  Leaving A the ray goes
 * 1.3 -> 1.6 (into B, not into air); leaving B, 1.6 -> 1. */
static void nested_inside(const char *root)
{
    const char *name = DIR "camera_inside_nested_glass.scene";
    const double eye[3] = {0.6, 0.1, 0.0}, raw[3] = {0.3, 0.2, 1.0};
    double d1[3], p1[3], n1[3], d2[3], p2[3], n2[3], d3[3], target[3], at[3];
    unit(raw, d1);
    sphere_exit(eye, d1, 1.0, p1);
    inward(p1, n1);
    refract(d1, n1, 1.3, 1.6, d2);
    sphere_exit(p1, d2, 2.0, p2);
    inward(p2, n2);
    refract(d2, n2, 1.6, 1.0, d3);
    along(p2, 10, d3, target);
    along(eye, 1, d1, at);
    char e[128], l[128], t[128];
    FILE *f = gen_open(root, name);
    fprintf(f, "# Stress: the camera inside a glass ball (ior 1.3) that is itself inside a\n"
               "# larger glass ball (ior 1.6).  The camera ray starts with both on its\n"
               "# medium stack: leaving the inner ball it bends 1.3 -> 1.6, leaving the outer\n"
               "# one 1.6 -> 1.  A small red ball sits on the exit ray computed by Snell's\n"
               "# law (tests/gen/gen_stress.c).\n"
               "# Must hold: the pixel is the red ball's ambient colour [1, 0, 0] exactly.\n"
               "image  { width 1 height 1 background 0.5 max_depth 6 }\n"
               "camera { perspective eye %s look_at %s up [0, 1, 0] fov 1 }\n"
               "ambient { color 1 }\n"
               "sphere { center [0, 0, 0] radius 2 material { Kd 0 t 1 ior 1.6 } }\n"
               "sphere { center [0, 0, 0] radius 1 material { Kd 0 t 1 ior 1.3 } }\n"
               "sphere { center %s radius 0.2 material { Kd [1, 0, 0] } }\n",
            vec_text(eye, e, sizeof e), vec_text(at, l, sizeof l), vec_text(target, t, sizeof t));
    gen_close(f, name);
}

static void write_obj(const char *root, const char *name, const double (*v)[3], int nv, const int (*t)[3], int nt,
                      const char *comment)
{
    FILE *f = gen_open(root, name);
    fprintf(f, "# %s\n# Written by tests/gen/gen_stress.c.\n", comment);
    for (int k = 0; k < nv; k++) {
        fputs("v", f);
        for (int c = 0; c < 3; c++) {
            fputc(' ', f);
            gen_put(f, v[k][c]);
        }
        fputc('\n', f);
    }
    for (int k = 0; k < nt; k++)
        fprintf(f, "f %d %d %d\n", t[k][0] + 1, t[k][1] + 1, t[k][2] + 1);
    gen_close(f, name);
}

/* Icosphere of level 3: 642 vertices, 1280 triangles. */
enum { ICO_VERTS = 642, ICO_TRIS = 1280, ICO_EDGES = 1920 };

typedef struct ico {
    double v[ICO_VERTS][3];
    int nv;
    int t[ICO_TRIS][3], nt;
    int edge[ICO_EDGES][3], ne; /* this level's midpoints: lower, upper corner, vertex */
} ico;

/* The midpoint vertex of edge a-b, made on first use (in this order, as
 * the faces ask for them). */
static int midpoint(ico *s, int a, int b)
{
    int lo = a < b ? a : b, hi = a < b ? b : a;
    for (int k = 0; k < s->ne; k++)
        if (s->edge[k][0] == lo && s->edge[k][1] == hi)
            return s->edge[k][2];
    double m[3];
    for (int i = 0; i < 3; i++)
        m[i] = (s->v[a][i] + s->v[b][i]) / 2;
    unit(m, s->v[s->nv]);
    int e[3] = {lo, hi, s->nv++};
    memcpy(s->edge[s->ne++], e, sizeof e);
    return e[2];
}

static void icosphere(ico *s, int levels)
{
    double g = (1 + sqrt(5)) / 2;
    const double start[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                                 {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    static const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (s->nv = 0; s->nv < 12; s->nv++)
        unit(start[s->nv], s->v[s->nv]);
    memcpy(s->t, faces, sizeof faces);
    s->nt = 20;
    static int next[ICO_TRIS][3];
    for (int level = 0; level < levels; level++) {
        int n = 0;
        s->ne = 0;
        for (int k = 0; k < s->nt; k++) {
            int a = s->t[k][0], b = s->t[k][1], c = s->t[k][2];
            int ab = midpoint(s, a, b), bc = midpoint(s, b, c), ca = midpoint(s, c, a);
            const int cut[4][3] = {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}};
            memcpy(next[n], cut, sizeof cut);
            n += 4;
        }
        memcpy(s->t, next, (size_t)n * sizeof next[0]);
        s->nt = n;
    }
}

static void meshes(const char *root)
{
    static ico s;
    icosphere(&s, 3);
    write_obj(root, DIR "geosphere.obj", (const double(*)[3])s.v, s.nv, (const int(*)[3])s.t, s.nt,
              "A closed icosphere of 1280 triangles (radius 1), for the watertightness sweep.");
    double h = 1e-8;
    const double strip[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, h, 0}, {0, h, 0}};
    const int halves[2][3] = {{0, 1, 2}, {0, 2, 3}};
    write_obj(root, DIR "thin_strip.obj", strip, 4, halves, 2,
              "A 1 x 1e-8 rectangle cut along its diagonal: two triangles of aspect 1e8.");
    enum { N = 64 };
    double fan[N + 2][3] = {{0.0, 0.0, 0.0}};
    int wedges[N][3];
    for (int k = 0; k <= N; k++) {
        fan[k + 1][0] = cos(k * 1e-8);
        fan[k + 1][1] = sin(k * 1e-8);
        fan[k + 1][2] = 0.0;
    }
    for (int k = 1; k <= N; k++) {
        const int w[3] = {0, k, k + 1};
        memcpy(wedges[k - 1], w, sizeof w);
    }
    write_obj(root, DIR "thin_fan.obj", (const double(*)[3])fan, N + 2, (const int(*)[3])wedges, N,
              "A fan of 64 triangles 1e-8 rad wide around the origin (aspect 1e8).");
}

int main(int argc, char **argv)
{
    const char *root = gen_root(argc, argv, "gen_stress [ROOT]");
    critical(root, DIR "critical_below.scene", -1);
    critical(root, DIR "critical_above.scene", +1);
    phong_off(root);
    touching_inside(root);
    nested_inside(root);
    meshes(root);
    return 0;
}
