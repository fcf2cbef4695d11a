/*
 * check.c - the rules a scene's records obey, stated once for every front
 * end: the scene language (lower_*.c) and JSON scenes (load_json.c) call
 * the same functions, so a value refused in one form is refused in the
 * other with the same message.
 *
 * A rule reports at the span of the offending field, which it asks of the
 * front end (check_at) only when it reports: locating a value in a JSON
 * text walks the text, which must not happen once per field of a large
 * scene.
 */
#include <float.h>
#include <limits.h>
#include <math.h>
#include "scene/loader.h"

src_span check_span(const check_at *at, int field)
{
    return at->span(at->ctx, field);
}

int check_range(loader *L, const check_at *at, int field, const char *what, double x, double lo, int lo_open,
                double hi, int hi_open)
{
    int ok = (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
    if (ok)
        return 1;
    if (isinf(hi))
        diag_report(&L->diag, DIAG_ERROR, check_span(at, field), "%s must be %s %g, got %.17g", what,
                    lo_open ? ">" : ">=", lo, x);
    else
        diag_report(&L->diag, DIAG_ERROR, check_span(at, field), "%s must be in %c%g, %g%c, got %.17g", what,
                    lo_open ? '(' : '[', lo, hi, hi_open ? ')' : ']', x);
    return 0;
}

int check_color(loader *L, const check_at *at, int field, const char *what, rgb c, double lo, double hi)
{
    const char *channel[3] = {"red", "green", "blue"};
    double v[3] = {(double)c.x, (double)c.y, (double)c.z};
    for (int i = 0; i < 3; i++) {
        if (v[i] >= lo && v[i] <= hi)
            continue;
        if (isinf(hi))
            diag_report(&L->diag, DIAG_ERROR, check_span(at, field), "%s must be >= %g, got %.17g (%s)", what, lo,
                        v[i], channel[i]);
        else
            diag_report(&L->diag, DIAG_ERROR, check_span(at, field), "%s must be in [%g, %g], got %.17g (%s)",
                        what, lo, hi, v[i], channel[i]);
        return 0;
    }
    return 1;
}

int check_whole(loader *L, const check_at *at, int field, double x, long lo, long hi, const char *limit_flag,
                long *out)
{
    const char *name = keyword_name((keyword_id)field);
    /* Every such count is stored in an int (the image's size, samples and
     * depth, a light's samples): a host's rf_limits above INT_MAX must not
     * let 3e9 wrap to a negative width. */
    if (hi > INT_MAX)
        hi = INT_MAX;
    if (x != floor(x)) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, field), "%s must be a whole number, got %.17g", name, x);
        return 0;
    }
    if (x < (double)lo) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, field), "%s must be at least %ld, got %.17g", name, lo, x);
        return 0;
    }
    if (x > (double)hi) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, field), "%s of %.17g is over the limit of %ld%s%s%s", name,
                    x, hi, limit_flag ? " (raise it with " : "", limit_flag ? limit_flag : "", limit_flag ? ")" : "");
        return 0;
    }
    *out = (long)x;
    return 1;
}

/* |v| within 1e-9 of 1: what the loader leaves in every normal it stores. */
int check_is_unit(vec3 v)
{
    return vec_is_finite(v) && fabs(vec_length(v) - 1) < 1e-9;
}

int check_unit(loader *L, const check_at *at, int field, const char *what, vec3 v)
{
    if (check_is_unit(v))
        return 1;
    diag_report(&L->diag, DIAG_ERROR, check_span(at, field),
                "%s must be a unit vector (length 1 within 1e-9), got length %.17g", what, (double)vec_length(v));
    return 0;
}

int check_image(loader *L, const check_at *at, const double size[4], rgb background, scene_image_spec *im)
{
    const scene_limits *lim = L->limits;
    long w = im->width, h = im->height, k = im->samples, depth = im->max_depth;
    int ok = check_whole(L, at, KW_WIDTH, size[0], 1, lim->max_width, "--max-width", &w);
    ok &= check_whole(L, at, KW_HEIGHT, size[1], 1, lim->max_height, "--max-height", &h);
    ok &= check_whole(L, at, KW_SAMPLES, size[2], 1, lim->max_samples, "--max-samples", &k);
    /* A library caller's limits may say more than the ceiling: it holds. */
    int at_ceiling = lim->max_depth >= SCENE_DEPTH_CEILING;
    long depth_limit = at_ceiling ? SCENE_DEPTH_CEILING : lim->max_depth;
    if (!check_whole(L, at, KW_MAX_DEPTH, size[3], 1, depth_limit, at_ceiling ? NULL : "--max-depth-limit", &depth)) {
        ok = 0;
        if (at_ceiling && size[3] > SCENE_DEPTH_CEILING)
            diag_report(&L->diag, DIAG_NOTE, check_span(at, KW_MAX_DEPTH),
                        "%d is the ceiling: the tracer recurses once a bounce, and its C stack is sized for that "
                        "many (spec/reliability.md, [REL-STACK-1])",
                        (int)SCENE_DEPTH_CEILING);
    }
    ok &= check_color(L, at, KW_BACKGROUND, "background", background, 0, HUGE_VAL);
    if (ok && (double)w * (double)h > (double)lim->max_pixels) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, CHECK_BLOCK),
                    "%ld x %ld pixels is over the limit of %ld (--max-pixels)", w, h, lim->max_pixels);
        ok = 0;
    }
    im->width = (int)w;
    im->height = (int)h;
    im->samples = (int)k;
    im->max_depth = (int)depth;
    im->background = background;
    return ok;
}

/* forward = look_at - eye; right = forward x up; true_up = right x forward.
 * When look_at - eye overflows, half of each gives the same direction.
 * A zero view and a zero up are both reported; parallel only when neither. */
int check_camera_basis(loader *L, const check_at *at, scene_camera *cam)
{
    vec3 view = vec_sub(cam->look_at, cam->eye), up;
    if (!vec_is_finite(view))
        view = vec_sub(vec_scale(cam->look_at, 0.5), vec_scale(cam->eye, 0.5));
    int ok = loader_unit(view, &cam->forward);
    if (!ok)
        diag_report(&L->diag, DIAG_ERROR, check_span(at, KW_LOOK_AT),
                    "look_at must differ from eye (the view direction has zero length)");
    if (vec_length(cam->up) == 0) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, KW_UP), "up must not be a zero-length vector");
        return 0;
    }
    if (!ok)
        return 0;
    loader_unit(cam->up, &up);
    vec3 side = vec_cross(cam->forward, up);
    if (vec_length(side) < 1e-9) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, KW_UP),
                    "up is parallel to the view direction (look_at - eye)");
        return 0;
    }
    cam->right = vec_normalize(side);
    cam->true_up = vec_normalize(vec_cross(cam->right, cam->forward));
    return 1;
}

int check_camera_ranges(loader *L, const check_at *at, scene_camera *cam)
{
    cam->width_where = check_span(at, KW_WIDTH);
    int ok = check_range(L, at, KW_FOV, "fov", cam->fov, 0, 1, 180, 1);
    ok &= check_range(L, at, KW_WIDTH, "width", cam->width, 0, 1, HUGE_VAL, 0);
    return ok && check_camera_extent(L, at, cam);
}

int check_camera(loader *L, const check_at *at, scene_camera *cam)
{
    int ok = check_camera_ranges(L, at, cam);
    return check_camera_basis(L, at, cam) && ok;
}

int check_ambient(loader *L, const check_at *at, rgb color)
{
    return check_color(L, at, KW_COLOR, "ambient color", color, 0, HUGE_VAL);
}

int check_light(loader *L, const check_at *at, const scene_light *light)
{
    int ok = check_color(L, at, KW_POWER, "power", light->power, 0, HUGE_VAL);
    if (light->kind != LIGHT_DISTANT)
        ok &= check_range(L, at, KW_D0, "d0", light->d0, 0, 0, HUGE_VAL, 0);
    /* A distributed light's shape is checked with the shape (its spans). */
    return light->kind == LIGHT_POINT ? check_light_extent(L, at, light) && ok : ok;
}

int check_light_samples(loader *L, const check_at *at, double x, int *out)
{
    long samples = *out;
    int ok = check_whole(L, at, KW_SAMPLES, x, 1, L->limits->max_light_samples, "--max-light-samples", &samples);
    *out = (int)samples;
    return ok;
}

int check_rectangle(loader *L, const check_at *at, scene_light *light)
{
    /* The normal from the edges' directions: their cross product itself
     * could overflow for long edges. */
    vec3 corner = light->position, u = light->edge_u, v = light->edge_v, du, dv;
    vec3 far = vec_add(vec_add(corner, u), v);
    if (!loader_unit(u, &du) || !loader_unit(v, &dv) || !(vec_length(vec_cross(du, dv)) > 4 * DBL_EPSILON) ||
        !loader_unit(vec_cross(du, dv), &light->normal)) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, CHECK_RECT_EDGES),
                    "the rectangle's edges are parallel or zero: it has no area");
        return 0;
    }
    if (!vec_is_finite(far) || !vec_is_finite(vec_add(corner, u)) || !vec_is_finite(vec_add(corner, v))) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, CHECK_RECT_EXTENT),
                    "the rectangle reaches beyond the largest number (about 1.8e308)");
        return 0;
    }
    return check_light_extent(L, at, light);
}

int check_material(loader *L, const check_at *at, const scene_material *m)
{
    int ok = check_color(L, at, KW_KD, "Kd", m->kd, 0, 1);
    ok &= check_color(L, at, KW_KS, "Ks", m->ks, 0, 1);
    ok &= check_range(L, at, KW_N, "n", m->n, 0, 0, HUGE_VAL, 0);
    ok &= check_range(L, at, KW_T, "t", m->t, 0, 0, 1, 0);
    ok &= check_range(L, at, KW_IOR, "ior", m->ior, 0, 1, HUGE_VAL, 0);
    return ok;
}

int check_radius(loader *L, const check_at *at, double radius)
{
    return check_range(L, at, KW_RADIUS, "radius", radius, 0, 1, HUGE_VAL, 0);
}

int check_box(loader *L, const check_at *at, vec3 a, vec3 b, scene_prim *prim)
{
    if (a.x == b.x || a.y == b.y || a.z == b.z) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, KW_TO),
                    "the box is flat: from and to must differ along every axis");
        return 0;
    }
    prim->u.box.lo = vec_min(a, b);
    prim->u.box.hi = vec_max(a, b);
    return 1;
}

int check_ends(loader *L, const check_at *at, vec3 from, vec3 to)
{
    if (from.x != to.x || from.y != to.y || from.z != to.z)
        return 1;
    diag_report(&L->diag, DIAG_ERROR, check_span(at, KW_TO),
                "from and to must differ (they are the centres of the two ends)");
    return 0;
}

int check_cone_radii(loader *L, const check_at *at, const double radius[2])
{
    for (int i = 0; i < 2; i++) {
        if (!(radius[i] >= 0)) {
            diag_report(&L->diag, DIAG_ERROR, check_span(at, CHECK_CONE_RADIUS0 + i),
                        "a cone's radii must be >= 0, got %.17g", radius[i]);
            return 0;
        }
    }
    if (radius[0] == 0 && radius[1] == 0) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, KW_RADII), "a cone needs a radius > 0 at one end at least");
        return 0;
    }
    return 1;
}

/* A ring torus: 0 < minor < major (a horn or spindle torus would cross
 * itself, and its inside would no longer be the tube's). */
int check_torus(loader *L, const check_at *at, double major, double minor)
{
    int ok = check_range(L, at, KW_MAJOR, "major", major, 0, 1, HUGE_VAL, 0);
    ok &= check_range(L, at, KW_MINOR, "minor", minor, 0, 1, HUGE_VAL, 0);
    if (ok && !(minor < major)) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, KW_MINOR),
                    "minor must be less than major (a ring torus), got minor %.17g and major %.17g", minor, major);
        ok = 0;
    } else if (ok && !(minor >= major * TORUS_THINNEST)) {
        /* [LANG-TORUS-2] The quartic, of coefficients of order 1, must
         * resolve a tube whose signal is of order (minor/major)^2: past
         * 2^-22 roots were lost and hits reported off the surface, and the
         * BVH's box test then changed the image (spec/numerics.md 2.15). */
        diag_report(&L->diag, DIAG_ERROR, check_span(at, KW_MINOR),
                    "minor must be at least major / 65536 (2^-16): a thinner tube is beyond what the torus's hit "
                    "test resolves, got minor %.17g and major %.17g (ratio %.3g)", minor, major, minor / major);
        ok = 0;
    }
    return ok;
}

int check_invert(loader *L, const check_at *at, const xform *to_world, xform *to_local)
{
    if (xform_invert(to_world, to_local))
        return 1;
    diag_report(&L->diag, DIAG_ERROR, check_span(at, CHECK_TRANSFORM),
                "these transforms cannot be undone (the matrix is singular)");
    return 0;
}

static int xform_finite(const xform *a)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (!isfinite(a->m[i][j]))
                return 0;
    return 1;
}

static int triangle_in_range(const scene_prim *prim)
{
    const vec3 *q = prim->u.triangle.p, *n = prim->u.triangle.n;
    int ok = vec_is_finite(q[0]) && vec_is_finite(q[1]) && vec_is_finite(q[2]) &&
             vec_is_finite(vec_sub(q[1], q[0])) && vec_is_finite(vec_sub(q[2], q[0])) &&
             vec_is_finite(vec_sub(q[2], q[1]));
    return ok && (!n ||
                  (check_is_unit(n[0]) && check_is_unit(n[1]) && check_is_unit(n[2])));
}

/* Placement can push a finite shape past the largest double, or leave a
 * normal that cannot be made unit: the scene keeps no such number. */
static int in_range(const scene_prim *prim)
{
    int ok = 1;
    switch (prim->kind) {
    case PRIM_SPHERE: ok = vec_is_finite(prim->u.sphere.center) && isfinite(prim->u.sphere.radius); break;
    case PRIM_PLANE: ok = vec_is_finite(prim->u.plane.point) && check_is_unit(prim->u.plane.normal); break;
    case PRIM_TRIANGLE: ok = triangle_in_range(prim); break;
    case PRIM_DISK:
        ok = vec_is_finite(prim->u.disk.center) && check_is_unit(prim->u.disk.normal) &&
             isfinite(prim->u.disk.radius);
        break;
    case PRIM_BOX: ok = vec_is_finite(prim->u.box.lo) && vec_is_finite(prim->u.box.hi); break;
    case PRIM_CYLINDER:
    case PRIM_CONE:
    case PRIM_TORUS: ok = lower_quadric_in_range(prim); break;
    case PRIM_MESH: break; /* checked triangle by triangle (lower_mesh.c) */
    }
    return ok && (!prim->frame || (xform_finite(&prim->frame->to_world) && xform_finite(&prim->frame->to_local)));
}

/* A transform can take a positive size below the smallest double: the
 * shape is then gone, and the hit tests' preconditions (a sphere's and a
 * disk's radius > 0, a cone's r0 > 0 || r1 > 0: intersect_shapes.h,
 * intersect.c) would not hold.  The cylinder's and torus's are in
 * lower_quadric_in_range. */
static int size_kept(const scene_prim *prim)
{
    switch (prim->kind) {
    case PRIM_SPHERE: return prim->u.sphere.radius > 0;
    case PRIM_DISK: return prim->u.disk.radius > 0;
    case PRIM_CONE: return prim->u.cone.radius[0] > 0 || prim->u.cone.radius[1] > 0;
    default: return 1;
    }
}

/* A triangle has no area when its edges are parallel to rounding error:
 * the sine of the angle between them is at most 4 epsilon (computed on the
 * edges' directions, so the size of the triangle does not matter). */
int check_degenerate(vec3 a, vec3 b, vec3 c)
{
    vec3 e1, e2;
    if (!loader_unit(vec_sub(b, a), &e1) || !loader_unit(vec_sub(c, a), &e2))
        return 1;
    return !(vec_length(vec_cross(e1, e2)) > 4 * DBL_EPSILON);
}

int check_placed(loader *L, const check_at *at, const scene_prim *prim)
{
    if (!in_range(prim)) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, CHECK_BLOCK),
                    "this %s is out of range: a coordinate or size passes the largest number (about 1.8e308)",
                    scene_prim_name(prim->kind));
        return 0;
    }
    if (!size_kept(prim)) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, CHECK_BLOCK),
                    "this %s's size is 0 after its transforms: it passes below the smallest number "
                    "(about 4.9e-324)",
                    scene_prim_name(prim->kind));
        return 0;
    }
    const vec3 *q = prim->u.triangle.p;
    if (prim->kind == PRIM_TRIANGLE && check_degenerate(q[0], q[1], q[2])) {
        diag_report(&L->diag, DIAG_ERROR, check_span(at, KW_VERTICES),
                    "degenerate triangle: its corners are on one line (no area)");
        return 0;
    }
    return check_prim_extent(L, at, prim);
}

static src_span fixed_span(const void *ctx, int field)
{
    (void)field;
    return *(const src_span *)ctx;
}

check_at check_at_fixed(const src_span *span)
{
    check_at at;
    at.span = fixed_span;
    at.ctx = span;
    return at;
}

static int ends_in_range(vec3 from, vec3 to)
{
    vec3 d = vec_sub(to, from);
    return vec_is_finite(from) && vec_is_finite(to) && vec_is_finite(d) && vec_length(d) > 0;
}

int lower_quadric_in_range(const scene_prim *prim)
{
    switch (prim->kind) {
    case PRIM_CYLINDER:
        return ends_in_range(prim->u.cylinder.from, prim->u.cylinder.to) && isfinite(prim->u.cylinder.radius) &&
               prim->u.cylinder.radius > 0;
    case PRIM_CONE:
        return ends_in_range(prim->u.cone.from, prim->u.cone.to) && isfinite(prim->u.cone.radius[0]) &&
               isfinite(prim->u.cone.radius[1]);
    default:
        return vec_is_finite(prim->u.torus.center) && fabs(vec_length(prim->u.torus.axis) - 1) < 1e-9 &&
               isfinite(prim->u.torus.major) && prim->u.torus.minor > 0 &&
               prim->u.torus.minor < prim->u.torus.major;
    }
}
