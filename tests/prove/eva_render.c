/*
 * eva_render.c - Eva's driver for the ray spawn functions
 * (src/render/intersect.c, included: they are static), the camera ray
 * (src/render/camera.c) and the light samples (src/render/lightsample.c).
 * Each call covers its function's precondition with a box (a relation
 * between two inputs, such as x <= width, is covered by the wider box of
 * each).  A unit direction is vec_normalize's box, 4 a component; where
 * the code divides by its length (shadow_tmin) the box is split six ways:
 * one component at least 1/8 in magnitude (vec_normalize's bound), of
 * either sign.  vec_length and vec_normalize are used through their
 * contracts, checked by eva_vec.c.
 *
 * Two entry points.  eva_render: the helpers and the light samples, with
 * every non-finite double an alarm.  eva_rays: the functions that return a
 * ray, whose tmax is +Inf by design (ray.h: HUGE_VAL, an open interval), so
 * that run treats only NaN as an alarm; the finiteness of every other field
 * is a clause of their contracts, which the run checks, and every double
 * they compute goes into a helper whose precondition asks it finite.  The
 * helpers are taken by their contracts there.
 */
#include "eva.h"
#include "render/intersect.c"
#include "render/camera.c"
#include "render/lightsample.h"

volatile real eva_render_real;
volatile vec3 eva_render_vec;
volatile ray eva_render_ray;
volatile light_grid eva_render_grid;

static vec3 any_point(void) { return any_vec(-DBL_MAX, DBL_MAX); }
static real any_offset(void) { return any(SPAWN_ABS, 0x1p983); }

/* A unit direction whose component axis is at least 1/8 in magnitude. */
static vec3 long_dir(int axis, real sign)
{
    vec3 v = any_dir();
    real m = sign > 0 ? any(0.125, 4) : any(-4, -0.125);
    return axis == 0 ? vec_make(m, v.y, v.z) : axis == 1 ? vec_make(v.x, m, v.z) : vec_make(v.x, v.y, m);
}

static void spawn_helpers(void)
{
    eva_render_real = spawn_offset(any_point(), any(0, DBL_MAX));
    eva_render_vec = spawn_origin(any_point(), any_dir(), any_vec(-0x1p1020, 0x1p1020), any_offset());
    for (int axis = 0; axis < 3; axis++)
        for (int sign = -1; sign <= 1; sign += 2)
            eva_render_real = shadow_tmin(any_offset(), long_dir(axis, sign));
    int w = Frama_C_int_interval(1, 1000000000), h = Frama_C_int_interval(1, 1000000000);
    scene_camera cam;
    cam.right = any_dir();
    cam.true_up = any_dir();
    real sx = 2.0 * any(0, 1e9) / w - 1.0, sy = 1.0 - 2.0 * any(0, 1e9) / h;
    eva_render_vec = screen_offset(&cam, any(0, 0x1p54), (real)h / (real)w, sx, sy);
    /* An orthographic camera's half width, above the perspective's 2^54. */
    eva_render_vec = screen_offset(&cam, any(0x1.0000000000001p54, 0x1p499), (real)h / (real)w, sx, sy);
}

/* Shadow rays toward a point (a light's, within 2^503) from a hit within
 * 2^1019: spawn_to_by's precondition.  unit_toward is used by its
 * contract, checked binade by binade by eva_toward.c. */
static void spawns_to(void)
{
    eva_render_ray = spawn_to_by(any_vec(-0x1p1019, 0x1p1019), any_dir(), any_vec(-0x1p503, 0x1p503), any_offset());
    eva_render_ray = ray_spawn_to(any_vec(-0x1p1019, 0x1p1019), any_dir(), any_vec(-0x1p503, 0x1p503));
    shadow_start st;
    st.point = any_vec(-0x1p1019, 0x1p1019);
    st.normal = any_dir();
    st.offset = any_offset();
    eva_render_ray = ray_shadow_to(&st, any_vec(-0x1p503, 0x1p503));
}

/* From a hit: eva_hits, a run of its own, with isect_part_magnitude by its
 * contract (p is not read), which passes +Inf past DBL_MAX by design
 * (spawn_offset caps it): NaN is the alarm there, as in eva_rays, and the
 * finiteness of each field a clause; spawn_offset and spawn_origin are
 * analysed, so the origin keeps its bound. */
/* ray_spawn_hit (mirror and refracted rays) on each of its paths: a
 * primitive that is neither a box nor a closed mesh (the hit point
 * anywhere), a box without a local frame and a closed mesh of one
 * triangle (their corners within the extent, [LANG-EXTENT-1], the hit
 * within 2^1019 as the contract asks).  A box with a local frame is not
 * driven: validation does not bound its matrices (spec/proofs.md). */
static void spawn_hits(void)
{
    scene_prim p;
    hit h;
    h.part = 0;
    h.normal = any_dir();
    p.kind = PRIM_SPHERE;
    h.point = any_point();
    eva_render_ray = ray_spawn_hit(&p, &h, any_dir());
    p.kind = PRIM_BOX;
    p.frame = NULL;
    p.u.box.lo = any_vec(-0x1p500, 0x1p500);
    p.u.box.hi = any_vec(-0x1p500, 0x1p500);
    h.point = any_vec(-0x1p1019, 0x1p1019);
    eva_render_ray = ray_spawn_hit(&p, &h, any_dir());
    static vec3 corners[3];
    static int tri[1][3] = {{0, 1, 2}};
    for (int i = 0; i < 3; i++)
        corners[i] = any_vec(-0x1p500, 0x1p500);
    p.kind = PRIM_MESH;
    p.frame = NULL;
    p.u.mesh.positions = corners;
    p.u.mesh.position_count = 3;
    p.u.mesh.tri = tri;
    p.u.mesh.tri_count = 1;
    p.u.mesh.tri_normal = 0;
    p.u.mesh.normals = 0;
    p.u.mesh.closed = Frama_C_int_interval(0, 1);
    eva_render_ray = ray_spawn_hit(&p, &h, any_dir());
}

void eva_hits(void)
{
    scene_prim p;
    hit h;
    h.point = any_vec(-0x1p1019, 0x1p1019);
    h.normal = any_dir();
    h.part = 0;
    eva_render_ray = ray_spawn_hit_to(&p, &h, any_vec(-0x1p503, 0x1p503));
    h.point = any_point();
    shadow_start st = ray_shadow_start(&p, &h);
    eva_render_real = st.offset;
    for (int axis = 0; axis < 3; axis++)
        for (int sign = -1; sign <= 1; sign += 2)
            eva_render_ray = ray_spawn_hit_shadow(&p, &h, long_dir(axis, sign));
    spawn_hits();
}

static void spawns(void)
{
    eva_render_ray = spawn_by(any_point(), any_dir(), any_dir(), any_offset(), 0);
    eva_render_ray = spawn(any_point(), any_dir(), any_dir(), any(0, DBL_MAX), 0);
    eva_render_ray = ray_spawn(any_point(), any_dir(), any_dir());
    shadow_start st;
    st.point = any_point();
    st.normal = any_dir();
    st.offset = any_offset();
    for (int axis = 0; axis < 3; axis++) {
        for (int sign = -1; sign <= 1; sign += 2) {
            vec3 dir = long_dir(axis, sign);
            eva_render_ray = spawn_by(any_point(), any_dir(), dir, any_offset(), 1);
            eva_render_ray = spawn(any_point(), any_dir(), dir, any(0, DBL_MAX), 1);
            eva_render_ray = ray_shadow_along(&st, dir);
        }
    }
}

static void camera(void)
{
    scene_camera cam;
    cam.kind = CAMERA_PERSPECTIVE;
    cam.eye = any_point();
    cam.forward = any_dir();
    cam.right = any_dir();
    cam.true_up = any_dir();
    cam.fov = any(0x1p-1074, 0x1.67fffffffffffp+7);   /* (0, 180): the double below 180 */
    cam.width = 0;
    int w = Frama_C_int_interval(1, 1000000000), h = Frama_C_int_interval(1, 1000000000);
    eva_render_ray = camera_ray(&cam, camera_half(&cam), w, h, any(0, 1e9), any(0, 1e9));
    /* Orthographic: eye and width within the scene's extent (2^500). */
    cam.kind = CAMERA_ORTHOGRAPHIC;
    cam.eye = any_vec(-0x1p500, 0x1p500);
    cam.width = any(0x1p-1074, 0x1p500);
    eva_render_ray = camera_ray(&cam, camera_half(&cam), w, h, any(0, 1e9), any(0, 1e9));
}

static void lights(void)
{
    light_grid g = light_grid_for(Frama_C_int_interval(1, 1000000000));
    eva_render_grid = g;
    double s, t;
    g.rows = Frama_C_int_interval(1, 1000000000);
    g.cols = Frama_C_int_interval(1, 1000000000);
    light_cell_point(g, Frama_C_int_interval(0, 1000000000), any(0, 0x1.fffffffffffffp-1),
                     any(0, 0x1.fffffffffffffp-1), &s, &t);
    eva_render_real = s + t;
    vec3 t1, t2;
    light_frame(any_dir(), &t1, &t2);
    eva_render_vec = t1;
    eva_render_vec = t2;
}

void eva_render(void)
{
    spawn_helpers();
    spawns_to();
    lights();
}

void eva_rays(void)
{
    spawns();
    camera();
}

/*
 * light_concentric divides b by a where |a| > |b| (and a by b otherwise):
 * a ratio of at most 1 that the boxes of a and b in [-1, 1] lose.  So
 * s and t (a = 2s - 1, b = 2t - 1) are split into the boxes of
 * concentric.h (tests/prove/prove.sh writes it): s = 1/2 (a = 0), and
 * 1/2 -+ [2^-(m+1), 2^-m], where a lies in one binade; the doubles of
 * [0, 1] nearest 1/2 are 1/2 - 2^-54 and 1/2 + 2^-53, so m up to 53 below
 * and 52 above cover them all.  Every pair of boxes is one call: a ratio
 * of two binades is finite.
 */
static void concentric_row(real slo, real shi)
{
    double x, y;
#define CBOX(lo, hi)                                            \
    light_concentric(any(slo, shi), any(lo, hi), &x, &y);       \
    eva_render_real = x + y;
#include "concentric.h"
#undef CBOX
}

void eva_concentric(void)
{
#define CBOX(lo, hi) concentric_row(lo, hi);
#include "concentric.h"
#undef CBOX
}
