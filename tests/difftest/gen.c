/*
 * gen.c - see gen.h.  Every statement is one line; the objects sit in a
 * box of a few units around the origin so that they shadow, reflect and
 * contain one another, and the camera looks at that box from outside or
 * from inside a solid.  Each primitive is written at its own origin and
 * moved by `translate` (after `scale`, with mirroring, and `rotate`), so
 * its bounding ball is known: the EXACT profile uses it to keep every
 * transparent sphere apart from all other surfaces (which also keeps
 * transparent solids from overlapping: POV-Ray and refray differ where a
 * ray leaves a solid that is not the last one it entered, and where a
 * shadow ray leaves glass next to another surface, spec/crosscheck.md).
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "base/sampler.h"
#include "gen.h"

enum { LINE_MAX_LEN = 1024, BALL_MAX = 16, PLANE_MAX = 2 };

/* EXACT: transparent spheres stay this far from every other surface
 * (POV-Ray's SHADOW_TOLERANCE where surfaces meet, [XCHK-MAP-SHADOW-2]). */
#define CLEAR_GAP 0.05

/* A bounding ball: every point of the primitive's bounding box (what the
 * export tests for all but untransformed spheres) is within r of c. */
typedef struct ball {
    double c[3], r;
    int clear;       /* a transparent sphere */
    int solid;       /* a solid whose centre is inside it: a place for the camera */
} ball;

typedef struct gen {
    uint64_t key, counter;
    dtgen_profile profile;
    const char *obj_dir;
    int depth;
    char line[DTGEN_STMT_MAX][LINE_MAX_LEN];
    int lines;
    ball balls[BALL_MAX];    /* the bounded primitives so far */
    int nballs;
    double plane_point[PLANE_MAX][3], plane_normal[PLANE_MAX][3];
    int planes;
    /* dtgen_make_placed: the whole scene moved to offset + scale x */
    int placed;
    double scale, offset[3];
} gen;

static double uniform(gen *g)
{
    return sampler_uniform(sampler_key(g->key, g->counter++));
}

static double range(gen *g, double lo, double hi)
{
    return lo + (hi - lo) * uniform(g);
}

static int pick(gen *g, int n)
{
    int k = (int)(uniform(g) * n);
    return k < n ? k : n - 1;
}

static int chance(gen *g, double p)
{
    return uniform(g) < p;
}

static int exact(const gen *g)
{
    return g->profile == DTGEN_EXACT;
}

/* Appends to the statement being written (the last line). */
static void put(gen *g, const char *fmt, ...)
{
    char *line = g->line[g->lines - 1];
    size_t len = strlen(line);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line + len, LINE_MAX_LEN - len, fmt, ap);
    va_end(ap);
}

/* Starts a statement; returns 0 when the scene is full. */
static int begin(gen *g)
{
    if (g->lines == DTGEN_STMT_MAX)
        return 0;
    g->line[g->lines++][0] = '\0';
    return 1;
}

static void put_vec(gen *g, const double v[3])
{
    put(g, "[%.17g, %.17g, %.17g]", v[0], v[1], v[2]);
}

/* A point of the scene as placed (dtgen_make_placed). */
static void put_point(gen *g, const double v[3])
{
    double p[3];
    for (int i = 0; i < 3; i++)
        p[i] = g->placed ? g->offset[i] + g->scale * v[i] : v[i];
    put_vec(g, p);
}

/* A length of the scene as placed. */
static double placed_length(const gen *g, double x)
{
    return g->placed ? g->scale * x : x;
}

static void random_point(gen *g, double half, double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = range(g, -half, half);
}

/* A unit vector, uniform on the sphere. */
static void random_direction(gen *g, double out[3])
{
    double len;
    do {
        random_point(g, 1, out);
        len = sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
    } while (len < 0.1 || len > 1);
    for (int i = 0; i < 3; i++)
        out[i] /= len;
}

static void put_colour(gen *g, double lo, double hi)
{
    if (chance(g, 0.3))
        put(g, "%.17g", range(g, lo, hi));
    else
        put(g, "[%.17g, %.17g, %.17g]", range(g, lo, hi), range(g, lo, hi), range(g, lo, hi));
}

/* ---- Materials ---- */

/* What a primitive is, for its material. */
typedef struct shape_use {
    int solid;        /* sphere, box, mesh */
    int sphere;
    int normals;      /* a mesh with vertex normals */
} shape_use;

/* Chooses t first (placement depends on it). */
static double choose_t(gen *g, const shape_use *u)
{
    if (exact(g)) {
        /* Transparent sheets get nudged iors, and transparent boxes and
         * meshes meet POV-Ray's SHADOW_TOLERANCE at their edges: the
         * export lists both as approximations. */
        if (!u->sphere)
            return 0;
        return chance(g, 0.35) ? range(g, 0.2, 0.95) : 0;
    }
    switch (pick(g, 5)) {
    case 0: return 1;
    case 1: return range(g, 0.05, 0.95);
    default: return 0;
    }
}

static void put_material(gen *g, const shape_use *u, double t)
{
    double ks = 0;
    put(g, " material { Kd ");
    put_colour(g, 0, 1);
    if (exact(g)) {
        /* Glass with Ks + t = 1: POV-Ray weights total internal reflection
         * by 1, refray by Ks + t ([XCHK-MAP-TIR-1]). */
        if (t > 0)
            ks = 1 - t;
        else if (!(u->normals && g->depth > 1) && chance(g, 0.5))
            ks = range(g, 0.05, 0.8);
        if (ks > 0)
            put(g, " Ks %.17g n %.17g", ks, range(g, 1, 200));
        if (t > 0)
            put(g, " t %.17g ior %.17g", t, chance(g, 0.15) ? range(g, 0.7, 0.9) : range(g, 1.1, 2.0));
    } else {
        static const double n[] = {0, 1, 30, 1e4};
        static const double ior[] = {1, 1.5, 0.7, 2.4};
        if (chance(g, 0.5)) {
            put(g, " Ks ");
            put_colour(g, 0, 1);
        }
        put(g, " n %.17g t %.17g ior %.17g", n[pick(g, 4)], t, ior[pick(g, 4)]);
    }
    put(g, " }");
}

/* ---- Primitives ---- */

/* scale (possibly mirroring), rotate, then translate to c.  Returns the
 * largest |scale| (the factor on the bounding radius). */
static double put_transforms(gen *g, const double c[3])
{
    double most = 1;
    if (chance(g, 0.35)) {
        double s[3];
        int uniform_scale = chance(g, 0.4);
        s[0] = range(g, 0.5, 1.5);
        for (int i = 0; i < 3; i++) {
            if (i > 0)
                s[i] = uniform_scale ? s[0] : range(g, 0.5, 1.5);
            most = fmax(most, s[i]);
        }
        for (int i = 0; i < 3; i++)
            if (chance(g, 0.25))
                s[i] = -s[i];
        put(g, " scale ");
        put_vec(g, s);
    }
    if (chance(g, 0.4)) {
        double a[3];
        random_point(g, 180, a);
        put(g, " rotate ");
        put_vec(g, a);
    }
    put(g, " translate ");
    put_vec(g, c);
    return most;
}

static double distance(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static double plane_offset(const gen *g, int k, const double c[3])
{
    const double *q = g->plane_point[k], *n = g->plane_normal[k];
    return fabs(n[0] * (c[0] - q[0]) + n[1] * (c[1] - q[1]) + n[2] * (c[2] - q[2]));
}

/* Whether a ball (c, r) would come near a transparent sphere, or, when it
 * is one (clear), near anything (EXACT only). */
static int too_near(const gen *g, const double c[3], double r, int clear)
{
    if (!exact(g))
        return 0;
    for (int i = 0; i < g->nballs; i++)
        if ((clear || g->balls[i].clear) && distance(c, g->balls[i].c) < r + g->balls[i].r + CLEAR_GAP)
            return 1;
    for (int k = 0; clear && k < g->planes; k++)
        if (plane_offset(g, k, c) < r + CLEAR_GAP)
            return 1;
    return 0;
}

/* Where a primitive with bounding radius r goes: a point in the scene box
 * that keeps it apart from the transparent spheres (*t = 0 when a
 * transparent one finds no such place). */
static void place(gen *g, double r, double *t, double c[3])
{
    double half = exact(g) ? 2 : 1.5;
    for (int tries = 0; tries < 30; tries++) {
        random_point(g, half, c);
        if (!too_near(g, c, r, *t > 0))
            return;
    }
    *t = 0;
}

static void remember(gen *g, const double c[3], double r, int clear, int solid)
{
    if (g->nballs == BALL_MAX)
        return;
    ball *b = &g->balls[g->nballs++];
    memcpy(b->c, c, sizeof b->c);
    b->r = r;
    b->clear = clear;
    b->solid = solid;
}

typedef struct mesh_file {
    const char *name;
    double radius;     /* of a ball about the OBJ's origin that holds it */
    int normals, centred;
} mesh_file;

static const mesh_file meshes[] = {
    {"tetrahedron", 1.0, 0, 0},
    {"cube", 1.7320508075688772, 1, 1},
    {"icosahedron_smooth", 1.9021130325903071, 1, 1},
};

/* The kinds put_solid makes. */
enum { SOLID_SPHERE, SOLID_BOX, SOLID_MESH, SOLID_CYLINDER, SOLID_CONE, SOLID_TORUS };

/* A cylinder, cone or torus about the y axis at the origin (open now and
 * then: a sheet); returns the radius of a ball about the origin that
 * holds it. */
static double put_quadric(gen *g, int kind, int open)
{
    double h = range(g, 0.3, 1), r = range(g, 0.3, 1), r1 = chance(g, 0.3) ? 0 : range(g, 0.1, 1);
    if (kind == SOLID_CYLINDER)
        put(g, "cylinder { from [0, %.17g, 0] to [0, %.17g, 0] radius %.17g%s", -h, h, r, open ? " open" : "");
    else if (kind == SOLID_CONE)
        put(g, "cone { from [0, %.17g, 0] to [0, %.17g, 0] radii %.17g %.17g%s", -h, h, r, r1, open ? " open" : "");
    else
        put(g, "torus { major %.17g minor %.17g", r + 0.3, r1 > 0 ? 0.9 * fmin(r1, r) : 0.5 * r);
    if (kind == SOLID_TORUS)
        return r + 0.3 + 0.9 * r;
    return sqrt(h * h + r * r);
}

static void put_solid(gen *g, int kind)
{
    shape_use u = {1, kind == SOLID_SPHERE, 0};
    double c[3], local_r = 0, t, reach;
    const mesh_file *m = NULL;
    double half[3] = {range(g, 0.3, 1.1), range(g, 0.3, 1.1), range(g, 0.3, 1.1)};
    double radius = range(g, 0.4, 1.3), size = range(g, 0.4, 0.9);
    int open = (kind == SOLID_CYLINDER || kind == SOLID_CONE) && chance(g, 0.3);
    u.solid = !open;
    if (kind == SOLID_SPHERE) {
        local_r = radius;
    } else if (kind == SOLID_BOX) {
        local_r = sqrt(half[0] * half[0] + half[1] * half[1] + half[2] * half[2]);
    } else if (kind == SOLID_MESH) {
        m = &meshes[pick(g, 3)];
        u.normals = m->normals;
        local_r = m->radius * size;
    }
    t = choose_t(g, &u);
    /* The shape's own words first, then its place, which needs its size:
     * a transparent sphere gets no scale, so the export tests its own
     * ball; any other shape its bounding box, which lies within sqrt(3) of
     * the ball scaled by at most 1.5. */
    if (kind == SOLID_SPHERE)
        put(g, "sphere { radius %.17g", radius);
    else if (kind == SOLID_BOX)
        put(g, "box { from [%.17g, %.17g, %.17g] to [%.17g, %.17g, %.17g]", -half[0], -half[1], -half[2], half[0],
            half[1], half[2]);
    else if (kind == SOLID_MESH)
        put(g, "mesh { file \"%s/%s.obj\" scale %.17g", g->obj_dir, m->name, size);
    else
        local_r = put_quadric(g, kind, open);
    reach = kind == SOLID_SPHERE && t > 0 ? local_r : 1.7320508075688772 * 1.5 * local_r;
    place(g, reach, &t, c);
    if (kind == SOLID_SPHERE && !(t > 0))
        reach = 1.7320508075688772 * 1.5 * local_r;
    put_material(g, &u, t);
    if (kind == SOLID_SPHERE && t > 0 && exact(g))
        put(g, " translate ");
    if (kind == SOLID_SPHERE && t > 0 && exact(g))
        put_vec(g, c);
    else
        put_transforms(g, c);
    put(g, " }");
    remember(g, c, reach, kind == SOLID_SPHERE && t > 0,
             !open && kind != SOLID_TORUS && (m == NULL || m->centred));
}

/* Whether the plane through q with normal n cuts or nears a transparent
 * sphere (EXACT only). */
static int plane_too_near(const gen *g, const double q[3], const double n[3])
{
    for (int i = 0; exact(g) && i < g->nballs; i++) {
        const double *c = g->balls[i].c;
        if (g->balls[i].clear &&
            fabs(n[0] * (c[0] - q[0]) + n[1] * (c[1] - q[1]) + n[2] * (c[2] - q[2])) < g->balls[i].r + CLEAR_GAP)
            return 1;
    }
    return 0;
}

/* A floor below the objects half the time, else any plane; apart from
 * the transparent spheres. */
static void put_plane(gen *g, const shape_use *u, double t)
{
    double q[3], n[3];
    int tries = 0;
    do {
        random_point(g, 2, q);
        random_direction(g, n);
        if (chance(g, 0.5)) {
            n[0] = n[2] = q[0] = q[2] = 0;
            n[1] = 1;
            q[1] = range(g, -3, -1.5);
        }
    } while (plane_too_near(g, q, n) && ++tries < 30);
    if (g->planes < PLANE_MAX) {
        memcpy(g->plane_point[g->planes], q, sizeof q);
        memcpy(g->plane_normal[g->planes++], n, sizeof n);
    }
    put(g, "plane { point ");
    put_vec(g, q);
    put(g, " normal ");
    put_vec(g, n);
    put_material(g, u, t);
    put(g, " }");
}

static void put_sheet(gen *g, int kind)
{
    shape_use u = {0, 0, 0};
    double t = choose_t(g, &u), c[3], n[3], radius = range(g, 0.3, 1.5);
    /* disk: radius; triangle: corners within sqrt(3) 0.8 of its origin;
     * either scaled by at most 1.5, inside a box sqrt(3) wider */
    double reach = 1.7320508075688772 * 1.5 * (kind == 0 ? radius : 1.3856406460551018);
    if (kind == 2) {
        put_plane(g, &u, t);
        return;
    }
    place(g, reach, &t, c);
    remember(g, c, reach, 0, 0);
    random_direction(g, n);
    if (kind == 0) {
        put(g, "disk { normal ");
        put_vec(g, n);
        put(g, " radius %.17g", radius);
    } else {
        double a[3], b[3], d[3], ab[3], ad[3], cr[3];
        do {
            random_point(g, 0.8, a);
            random_point(g, 0.8, b);
            random_point(g, 0.8, d);
            for (int i = 0; i < 3; i++) {
                ab[i] = b[i] - a[i];
                ad[i] = d[i] - a[i];
            }
            cr[0] = ab[1] * ad[2] - ab[2] * ad[1];
            cr[1] = ab[2] * ad[0] - ab[0] * ad[2];
            cr[2] = ab[0] * ad[1] - ab[1] * ad[0];
        } while (sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) < 0.2);
        put(g, "triangle { vertices ");
        put_vec(g, a);
        put(g, " ");
        put_vec(g, b);
        put(g, " ");
        put_vec(g, d);
    }
    put_material(g, &u, t);
    put_transforms(g, c);
    put(g, " }");
}

static void put_primitive(gen *g, int planes_left)
{
    int kind = pick(g, planes_left > 0 ? 8 : 7);
    if (!begin(g))
        return;
    if (kind < 3)
        put_solid(g, kind);                   /* sphere, box, mesh */
    else if (kind == 3)
        put_solid(g, SOLID_SPHERE);
    else if (kind == 4)
        put_solid(g, SOLID_CYLINDER + pick(g, 3));
    else
        put_sheet(g, kind - 5);               /* disk, triangle, plane */
}

/* ---- Lights ---- */

/* The centre of a solid that holds it, or NULL. */
static const double *inside_point(gen *g)
{
    int found[BALL_MAX], n = 0;
    for (int i = 0; i < g->nballs; i++)
        if (g->balls[i].solid)
            found[n++] = i;
    return n > 0 ? g->balls[found[pick(g, n)]].c : NULL;
}

static void put_point_light(gen *g)
{
    double p[3];
    const double *in = chance(g, 0.1) ? inside_point(g) : NULL;
    if (in)
        memcpy(p, in, sizeof p);
    else
        random_point(g, 5, p);
    put(g, "point_light { position ");
    put_point(g, p);
    put(g, " power ");
    int kind = pick(g, exact(g) ? 2 : 4);
    put_colour(g, kind == 0 ? 0.5 : 3, kind == 0 ? 2 : 12);
    if (kind == 0)
        put(g, " falloff none }");
    else if (kind == 1)
        put(g, " d0 %.17g falloff linear }", placed_length(g, range(g, 0.5, 5)));
    else if (kind == 2)
        put(g, " falloff linear }");
    else
        put(g, " d0 %.17g falloff inverse_square }", placed_length(g, chance(g, 0.5) ? 0 : range(g, 0.5, 2)));
}

static void put_distant_light(gen *g)
{
    double d[3];
    random_direction(g, d);
    if (chance(g, 0.8))
        d[1] = -fabs(d[1]);   /* mostly from above */
    put(g, "distant_light { direction ");
    put_vec(g, d);
    put(g, " power ");
    put_colour(g, 0.3, 1.5);
    put(g, " }");
}

static void put_distributed_light(gen *g)
{
    double c[3], n[3];
    random_point(g, 4, c);
    random_direction(g, n);
    if (g->placed) {
        /* Draws in statements of their own (the unplaced branch draws two
         * in one argument list, in the compiler's order): a placed scene
         * need not repeat an unplaced one's numbers. */
        if (chance(g, 0.5)) {
            double u = range(g, 0.2, 1), v = range(g, 0.2, 1);
            put(g, "distributed_light { rectangle ");
            put_point(g, c);
            put(g, " [%.17g, 0, 0] [0, 0, %.17g]", placed_length(g, u), placed_length(g, v));
        } else {
            put(g, "distributed_light { disk ");
            put_point(g, c);
            put(g, " [%.17g, %.17g, %.17g] %.17g", n[0], n[1], n[2], placed_length(g, range(g, 0.1, 0.8)));
        }
    } else if (chance(g, 0.5))
        put(g, "distributed_light { rectangle [%.17g, %.17g, %.17g] [%.17g, 0, 0] [0, 0, %.17g]", c[0], c[1], c[2],
            range(g, 0.2, 1), range(g, 0.2, 1));
    else
        put(g, "distributed_light { disk [%.17g, %.17g, %.17g] [%.17g, %.17g, %.17g] %.17g", c[0], c[1], c[2], n[0],
            n[1], n[2], range(g, 0.1, 0.8));
    put(g, " samples %d power %.17g falloff %s }", 1 + pick(g, 4), range(g, 2, 10),
        chance(g, 0.5) ? "linear" : "none");
}

static void put_lights(gen *g)
{
    static const double weights[] = {0.1, 0.5, 0.3, 0.1};
    double u = uniform(g);
    int count = 0;
    while (count < 3 && u > weights[count])
        u -= weights[count++];
    for (int i = 0; i < count && begin(g); i++) {
        int kind = pick(g, exact(g) ? 2 : 3);
        if (kind == 0)
            put_point_light(g);
        else if (kind == 1)
            put_distant_light(g);
        else
            put_distributed_light(g);
    }
    if (chance(g, 0.4) && begin(g)) {
        put(g, "ambient { color ");
        put_colour(g, 0.05, 0.3);
        put(g, " }");
    }
}

/* ---- Image and camera ---- */

static void put_image(gen *g)
{
    begin(g);
    if (exact(g))
        put(g, "image { width 64 height 48 samples %d max_depth %d background ", chance(g, 0.15) ? 2 : 1,
            g->depth);
    else
        put(g, "image { width 8 height 6 samples %d max_depth %d background ", 1 + pick(g, 2), g->depth);
    if (chance(g, 0.5))
        put(g, "0 }");
    else {
        put_colour(g, 0, 0.4);
        put(g, " }");
    }
}

static void put_camera(gen *g)
{
    double eye[3], at[3], dir[3];
    const double *in = chance(g, exact(g) ? 0.15 : 0.3) ? inside_point(g) : NULL;
    int ortho = chance(g, 0.3);
    begin(g);
    if (in) {
        memcpy(eye, in, sizeof eye);
        random_direction(g, dir);
        for (int i = 0; i < 3; i++)
            at[i] = eye[i] + dir[i];
    } else {
        double dist = ortho ? range(g, 5, 9) : range(g, 3, 7);
        random_point(g, 1, at);
        random_direction(g, dir);
        for (int i = 0; i < 3; i++)
            eye[i] = at[i] + dist * dir[i];
    }
    put(g, "camera { %s eye ", ortho ? "orthographic" : "perspective");
    put_point(g, eye);
    put(g, " look_at ");
    put_point(g, at);
    put(g, fabs(dir[1]) > 0.95 ? " up [0, 0, 1]" : " up [0, 1, 0]");
    if (ortho)
        put(g, " width %.17g }", placed_length(g, range(g, 3, 6)));
    else
        put(g, " fov %.17g }", range(g, 35, 75));
}

/* ---- The scene ---- */

static void assemble(const gen *g, dtgen_scene *out)
{
    out->len = 0;
    out->count = 0;
    for (int i = 0; i < g->lines; i++) {
        int n = snprintf(out->text + out->len, sizeof out->text - out->len, "%s\n", g->line[i]);
        if (n < 0 || out->len + (size_t)n >= sizeof out->text)
            break;
        out->start[out->count++] = out->len;
        out->len += (size_t)n;
    }
    out->start[out->count] = out->len;
}

/* A primitive's statement (every one ends in its transforms and " }"): the
 * placement's scale and translation go last, so its local shape is scaled
 * and moved with the rest. */
static void place_primitive(gen *g, char *line)
{
    static const char *const kinds[] = {"sphere ", "box ", "mesh ", "cylinder ", "cone ", "torus ",
                                        "disk ", "triangle ", "plane "};
    size_t len = strlen(line);
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        if (strncmp(line, kinds[k], strlen(kinds[k])) != 0 || len < 2)
            continue;
        snprintf(line + len - 2, LINE_MAX_LEN - (len - 2), " scale %.17g translate [%.17g, %.17g, %.17g] }",
                 g->scale, g->offset[0], g->offset[1], g->offset[2]);
        return;
    }
}

void dtgen_make(dtgen_scene *out, uint64_t seed, dtgen_profile profile, const char *obj_dir)
{
    static const double origin[3] = {0, 0, 0};
    dtgen_make_placed(out, seed, profile, obj_dir, 1, origin);
}

void dtgen_make_placed(dtgen_scene *out, uint64_t seed, dtgen_profile profile, const char *obj_dir, double scale,
                       const double offset[3])
{
    static gen g;   /* 40 kB of lines: not on the stack of a forked test */
    memset(&g, 0, sizeof g);
    g.placed = scale != 1 || offset[0] != 0 || offset[1] != 0 || offset[2] != 0;
    g.scale = scale;
    memcpy(g.offset, offset, sizeof g.offset);
    g.key = sampler_key(0x64696666u, seed);
    g.profile = profile;
    g.obj_dir = obj_dir;
    g.depth = 1 + pick(&g, exact(&g) ? 8 : 5);
    /* image and camera first in the text, but the camera may sit in a
     * solid: the primitives are drawn first, into lines 2.. */
    g.lines = 2;
    int prims = exact(&g) ? 1 + pick(&g, 6) : (chance(&g, 0.45) ? 1 : 2 + pick(&g, 3));
    for (int i = 0; i < prims; i++)
        put_primitive(&g, PLANE_MAX - g.planes);
    put_lights(&g);
    int lines = g.lines;
    g.lines = 0;
    put_image(&g);
    put_camera(&g);
    g.lines = lines;
    for (int i = 2; i < g.lines && g.placed; i++)
        place_primitive(&g, g.line[i]);
    assemble(&g, out);
}

size_t dtgen_subset(const dtgen_scene *s, const unsigned char *keep, char *buf, size_t size)
{
    size_t len = 0;
    for (int i = 0; i < s->count; i++) {
        size_t n = s->start[i + 1] - s->start[i];
        if (i >= 2 && !keep[i])
            continue;
        if (len + n + 1 > size)
            return 0;
        memcpy(buf + len, s->text + s->start[i], n);
        len += n;
    }
    buf[len] = '\0';
    return len;
}
