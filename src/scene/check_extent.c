/*
 * check_extent.c - the scene's extent ([LANG-EXTENT-1], spec/language.md):
 * every coordinate and every size of a placed shape, a light and the
 * camera within 2^500, every non-zero size at least 2^-500.
 *
 * Why these bounds: the hit tests and the proved vec.h functions multiply
 * two coordinates, or two differences of coordinates, and sum a few such
 * products; vec.h requires every component <= 2^1022.  A difference of two
 * coordinates within 2^500 is within 2^501, a product of two within 2^1002
 * and a sum of three within 2^1004: 2^18 below the requirement, room for
 * the few further sums a test makes.  Squares and products of two sizes
 * of at least 2^-500 are at least 2^-1000, normal doubles (the least is
 * 2^-1022) with the same 2^22 of room, where the triangle test and the
 * quadrics lose their sign to underflow below.  Coordinates themselves
 * get no lower bound: a subnormal coordinate next to unit ones is only
 * rounded away, it is not squared on its own.
 */
#include <math.h>
#include "scene/loader.h"

#define EXTENT_MAX 0x1p500
#define EXTENT_MIN 0x1p-500

/* The first number out of the extent: what it is, and its value. */
typedef struct extent_fault {
    const char *what;
    double value;
    int coordinate; /* a coordinate, else a size */
} extent_fault;

static int coord_out(vec3 v, const char *what, extent_fault *f)
{
    double c[3] = {(double)v.x, (double)v.y, (double)v.z};
    for (int i = 0; i < 3; i++) {
        if (!(fabs(c[i]) <= EXTENT_MAX)) {
            f->what = what;
            f->value = c[i];
            f->coordinate = 1;
            return 1;
        }
    }
    return 0;
}

/* A zero size keeps the rule of its kind (a cone's radius may be 0, a
 * zero edge is a degenerate triangle): only non-zero ones are bounded. */
static int size_out(double s, const char *what, extent_fault *f)
{
    double a = fabs(s);
    if (a == 0 || (a >= EXTENT_MIN && a <= EXTENT_MAX))
        return 0;
    f->what = what;
    f->value = s;
    f->coordinate = 0;
    return 1;
}

/* The upper bound alone: for sizes nothing squares or multiplies (a
 * light's shape is only sampled, a linear map; the orthographic width
 * only spreads the rays' origins). */
static int big_out(double s, const char *what, extent_fault *f)
{
    return fabs(s) > EXTENT_MAX && size_out(s, what, f);
}

/* Ends within the extent, then the length between them (each component of
 * the difference within 2^501 once the ends are: vec_length is safe). */
static int segment_out(vec3 a, vec3 b, const char *ends, const char *length, extent_fault *f)
{
    return coord_out(a, ends, f) || coord_out(b, ends, f) || size_out((double)vec_length(vec_sub(b, a)), length, f);
}

static int triangle_out(const vec3 p[3], extent_fault *f)
{
    return coord_out(p[0], "vertex", f) || coord_out(p[1], "vertex", f) || coord_out(p[2], "vertex", f) ||
           size_out((double)vec_length(vec_sub(p[1], p[0])), "edge length", f) ||
           size_out((double)vec_length(vec_sub(p[2], p[1])), "edge length", f) ||
           size_out((double)vec_length(vec_sub(p[0], p[2])), "edge length", f);
}

static int box_out(vec3 lo, vec3 hi, extent_fault *f)
{
    return coord_out(lo, "corner", f) || coord_out(hi, "corner", f) || size_out((double)(hi.x - lo.x), "width", f) ||
           size_out((double)(hi.y - lo.y), "height", f) || size_out((double)(hi.z - lo.z), "depth", f);
}

/* A kept frame's matrix is not bounded by the local checks: a non-uniform
 * scale can make a shape of local size 2^499 wider than 2^1000 in the world,
 * where its hit tests' roots pass CROSSING_MAX and are dropped (a closed
 * cone then let light through its wall: tests/attack8, finding 5).  The
 * world box (the box around the images of the local box's eight corners,
 * scene_prim_world_box, the one the BVH bounds the shape by) holds the
 * shape, so that box within the extent keeps the shape within it.  A box
 * that is not finite went past every bound on the way. */
static int world_box_out(const scene_prim *p, extent_fault *f)
{
    vec3 lo, hi;
    if (!scene_prim_local_box(p, &lo, &hi))
        return 0;
    if (!scene_prim_world_box(p, &lo, &hi)) {
        f->what = "world box";
        f->value = INFINITY;
        f->coordinate = 1;
        return 1;
    }
    return coord_out(lo, "world box", f) || coord_out(hi, "world box", f);
}

static int prim_local_out(const scene_prim *p, extent_fault *f)
{
    switch (p->kind) {
    case PRIM_SPHERE: return coord_out(p->u.sphere.center, "center", f) || size_out(p->u.sphere.radius, "radius", f);
    case PRIM_PLANE: return coord_out(p->u.plane.point, "point", f);
    case PRIM_TRIANGLE: return triangle_out(p->u.triangle.p, f);
    case PRIM_DISK: return coord_out(p->u.disk.center, "center", f) || size_out(p->u.disk.radius, "radius", f);
    case PRIM_BOX: return box_out(p->u.box.lo, p->u.box.hi, f);
    case PRIM_CYLINDER:
        return segment_out(p->u.cylinder.from, p->u.cylinder.to, "end", "length", f) ||
               size_out(p->u.cylinder.radius, "radius", f);
    case PRIM_CONE:
        return segment_out(p->u.cone.from, p->u.cone.to, "end", "length", f) ||
               size_out(p->u.cone.radius[0], "radius", f) || size_out(p->u.cone.radius[1], "radius", f);
    case PRIM_TORUS:
        return coord_out(p->u.torus.center, "center", f) || size_out(p->u.torus.major, "major radius", f) ||
               size_out(p->u.torus.minor, "minor radius", f);
    case PRIM_MESH: break; /* triangle by triangle (check_mesh_extent) */
    }
    return 0;
}

/* A shape that keeps its frame is checked in that frame, by the world
 * position of the frame's origin (its translation) as a coordinate, and by
 * its world box. */
static int prim_out(const scene_prim *p, extent_fault *f)
{
    if (p->frame) {
        const xform *w = &p->frame->to_world;
        if (coord_out(vec_make(w->m[0][3], w->m[1][3], w->m[2][3]), "translation", f))
            return 1;
    }
    if (prim_local_out(p, f))
        return 1;
    return p->frame && world_box_out(p, f);
}

/* "<subject> <name> is outside the scene's extent: ..." (name may be ""). */
static void report(loader *L, src_span at, const char *subject, const char *name, const extent_fault *f)
{
    const char *space = name[0] ? " " : "";
    if (f->coordinate)
        diag_report(&L->diag, DIAG_ERROR, at,
                    "%s%s%s is outside the scene's extent: its %s has a coordinate of %.17g, beyond 2^500 (about "
                    "3.3e150)",
                    subject, space, name, f->what, f->value);
    else if (fabs(f->value) > 1)
        diag_report(&L->diag, DIAG_ERROR, at,
                    "%s%s%s is outside the scene's extent: its %s is %.17g, beyond 2^500 (about 3.3e150)", subject,
                    space, name, f->what, f->value);
    else
        diag_report(&L->diag, DIAG_ERROR, at,
                    "%s%s%s is outside the scene's extent: its %s is %.17g, below 2^-500 (about 3.1e-151), the "
                    "least non-zero size",
                    subject, space, name, f->what, f->value);
}

int check_prim_extent(loader *L, const check_at *at, const scene_prim *prim)
{
    extent_fault f;
    if (!prim_out(prim, &f))
        return 1;
    report(L, at->span(at->ctx, CHECK_BLOCK), "this", scene_prim_name(prim->kind), &f);
    return 0;
}

int check_face_extent(loader *L, src_span at, const vec3 p[3])
{
    extent_fault f;
    if (!triangle_out(p, &f))
        return 1;
    report(L, at, "this face", "", &f);
    return 0;
}

int check_camera_extent(loader *L, const check_at *at, const scene_camera *cam)
{
    extent_fault f;
    if (coord_out(cam->eye, "eye", &f)) {
        report(L, at->span(at->ctx, KW_EYE), "the camera", "", &f);
        return 0;
    }
    if (coord_out(cam->look_at, "look_at", &f)) {
        report(L, at->span(at->ctx, KW_LOOK_AT), "the camera", "", &f);
        return 0;
    }
    if (cam->kind == CAMERA_ORTHOGRAPHIC && big_out(cam->width, "width", &f)) {
        report(L, at->span(at->ctx, KW_WIDTH), "the camera", "", &f);
        return 0;
    }
    return 1;
}

/* In the order camera.c computes a ray's origin (screen_offset at sx, sy =
 * +-1, the values it takes at x = 0 and x = width), so a corner the check
 * passes is the origin's own bits. */
int scene_view_out(const scene_camera *cam, int width, int height, double *coordinate)
{
    extent_fault f;
    if (cam->kind != CAMERA_ORTHOGRAPHIC)
        return 0;
    real half = 0.5 * cam->width, aspect = (real)height / (real)width;
    for (int corner = 0; corner < 4; corner++) {
        real sx = corner & 1 ? 1.0 : -1.0, sy = corner & 2 ? 1.0 : -1.0;
        vec3 offset = vec_add(vec_scale(cam->right, sx * half), vec_scale(cam->true_up, sy * half * aspect));
        if (coord_out(vec_add(cam->eye, offset), "view", &f)) {
            *coordinate = f.value;
            return 1;
        }
    }
    return 0;
}

int scene_check_view(const scene_model *s, int width, int height, diag *d)
{
    double c;
    if (!scene_view_out(&s->camera, width, height, &c))
        return 1;
    diag_report(d, DIAG_ERROR, s->camera.width_where,
                "the camera is outside the scene's extent: its view on an image of %d x %d pixels (width %.17g, "
                "height %.17g) has a corner with a coordinate of %.17g, beyond 2^500 (about 3.3e150)",
                width, height, s->camera.width, s->camera.width * ((double)height / width), c);
    return 0;
}

int check_view_extent(loader *L, const scene_model *s)
{
    return scene_check_view(s, s->image.width, s->image.height, &L->diag);
}

int check_light_extent(loader *L, const check_at *at, const scene_light *light)
{
    extent_fault f;
    vec3 c = light->position, u = light->edge_u, v = light->edge_v;
    switch (light->kind) {
    case LIGHT_POINT:
        if (!coord_out(c, "position", &f))
            return 1;
        report(L, at->span(at->ctx, KW_POSITION), "this light", "", &f);
        return 0;
    case LIGHT_DISK:
        if (coord_out(c, "center", &f)) {
            report(L, at->span(at->ctx, KW_CENTER), "this light", "", &f);
            return 0;
        }
        if (big_out(light->radius, "radius", &f)) {
            report(L, at->span(at->ctx, KW_RADIUS), "this light", "", &f);
            return 0;
        }
        return 1;
    case LIGHT_RECTANGLE: /* its points are between its corners */
        if (coord_out(c, "corner", &f) || coord_out(vec_add(c, u), "corner", &f) ||
            coord_out(vec_add(c, v), "corner", &f) || coord_out(vec_add(vec_add(c, u), v), "corner", &f)) {
            report(L, at->span(at->ctx, CHECK_RECT_EXTENT), "this light", "", &f);
            return 0;
        }
        return 1;
    case LIGHT_DISTANT: break;
    }
    return 1;
}
