/*
 * camera.c - see camera.h.
 */
#include "render/camera.h"

/*@ predicate is_screen_point(vec3 p, vec3 r, vec3 u, mreal half, mreal aspect, mreal sx, mreal sy) =
      p.x == r.x * (sx * half) + u.x * (sy * half * aspect) &&
      p.y == r.y * (sx * half) + u.y * (sy * half * aspect) &&
      p.z == r.z * (sx * half) + u.z * (sy * half * aspect);
*/

/* The point of the screen plane at (sx, sy): sx half along right, sy half
 * aspect along true_up, from the screen's centre. */
/*@ requires \valid_read(cam);
    requires vfinite(cam->right) && vbounded(cam->right, 4) && vfinite(cam->true_up) && vbounded(cam->true_up, 4);
    // half: tan(fov/2) <= 2^54 for a perspective camera, width/2 <= 2^499 for an
    // orthographic one (check_camera_extent: [LANG-EXTENT-1])
    requires \is_finite(half) && half >= 0 && DOUBLES(half <= 0x1p499);
    requires \is_finite(aspect) && aspect > 0 && DOUBLES(aspect <= 0x1p31);
    requires \is_finite(sx) && \is_finite(sy) && DOUBLES(\abs(sx) <= 0x1p32 && \abs(sy) <= 0x1p32);
    assigns \nothing;
    ensures \is_finite(\result.x) && \is_finite(\result.y) && \is_finite(\result.z);
    ensures DOUBLES(half <= 0x1p54 ==> -0x1p122 <= \result.x <= 0x1p122 && -0x1p122 <= \result.y <= 0x1p122 &&
                    -0x1p122 <= \result.z <= 0x1p122);
    ensures EXACT(is_screen_point(\result, cam->right, cam->true_up, half, aspect, sx, sy));
    ensures DOUBLES(-0x1p565 <= \result.x <= 0x1p565 && -0x1p565 <= \result.y <= 0x1p565 &&
                    -0x1p565 <= \result.z <= 0x1p565); */
static vec3 screen_offset(const scene_camera *cam, real half, real aspect, real sx, real sy)
{
    return vec_add(vec_scale(cam->right, sx * half), vec_scale(cam->true_up, sy * half * aspect));
}

/* The requires are camera_ray's (below); tan's contract (tests/prove/libm.c)
 * gives the bound: the argument is below pi/2 as rounded. */
/*@ requires \valid_read(cam);
    requires cam->kind == CAMERA_PERSPECTIVE || cam->kind == CAMERA_ORTHOGRAPHIC;
    requires cam->kind == CAMERA_PERSPECTIVE ==> \is_finite(cam->fov) && 0 < cam->fov < 180;
    assigns errno;   // tan's contract sets it for an infinite argument only
    ensures cam->kind == CAMERA_PERSPECTIVE ==> \is_finite(\result) && \result >= 0 && DOUBLES(\result <= 0x1p54);
    ensures EXACT(cam->kind == CAMERA_PERSPECTIVE ==> \result == \tan(0.5 * cam->fov * (REAL_PI / 180)));
    ensures cam->kind == CAMERA_ORTHOGRAPHIC ==> \result == 0; */
real camera_half(const scene_camera *cam)
{
    if (cam->kind != CAMERA_PERSPECTIVE)
        return 0.0;
    return tan(0.5 * cam->fov * (REAL_PI / 180));
}

/*
 * The contract (make prove, spec/proofs.md): the pinhole formula of
 * camera.h in exact arithmetic (the origin, and the direction: a unit
 * vector along the screen point, which is screen_offset's), a finite ray
 * with a unit direction (vec_normalize's bound, or the validated forward)
 * for the doubles.  The requires name what establishes them: the kind, a
 * finite eye and unit forward, right, true_up: [LANG-CAMERA-1],
 * [LANG-VALID-2] (check_camera_basis, src/scene/check.c: loader_unit,
 * vec_normalize); 0 < fov < 180, width > 0: [LANG-VALID-1]
 * (check_camera_ranges); width, height >= 1: [LANG-IMAGE-1] (check_image;
 * --max-width and --max-height may raise the 16384 to 10^9); x in
 * [0, width], y in [0, height]: render_pixel's i + (a + 0.5)/k.
 */
/*@ requires \valid_read(cam);
    requires cam->kind == CAMERA_PERSPECTIVE || cam->kind == CAMERA_ORTHOGRAPHIC;
    requires vfinite(cam->eye);
    requires vfinite(cam->forward) && vbounded(cam->forward, 4) && EXACT(vunit(cam->forward));
    requires vfinite(cam->right) && vbounded(cam->right, 4);
    requires vfinite(cam->true_up) && vbounded(cam->true_up, 4);
    requires cam->kind == CAMERA_PERSPECTIVE ==> \is_finite(cam->fov) && 0 < cam->fov < 180;
    // half: camera_half(cam), made once per image (its value, tan(fov/2), is
    // camera_half's ensures: stated here too, it left WP unable to prove the
    // assert on aspect below, out of memory)
    requires cam->kind == CAMERA_PERSPECTIVE ==> \is_finite(half) && half >= 0 && DOUBLES(half <= 0x1p54);
    requires cam->kind == CAMERA_ORTHOGRAPHIC ==> \is_finite(cam->width) && cam->width > 0;
    // the eye and the orthographic width within 2^500: check_camera_extent, [LANG-EXTENT-1]
    requires cam->kind == CAMERA_ORTHOGRAPHIC ==> DOUBLES(cam->width <= 0x1p500 && vbounded(cam->eye, 0x1p500));
    requires 1 <= width <= 1000000000 && 1 <= height <= 1000000000;
    // Eva takes x, y anywhere in [0, 10^9]: a box, wider than the relation
    requires \is_finite(x) && 0 <= x <= 1000000000 && \is_finite(y) && 0 <= y <= 1000000000;
    requires EXACT(x <= width && y <= height);
    assigns \nothing;
    ensures \result.tmin == 0 && DOUBLES(\is_plus_infinity(\result.tmax));
    ensures cam->kind == CAMERA_PERSPECTIVE ==> vfinite(\result.origin) && vfinite(\result.dir) &&
                                                DOUBLES(vbounded(\result.dir, 4));
    ensures EXACT(vzero(\result.dir) || vunit(\result.dir));
    ensures EXACT(cam->kind == CAMERA_PERSPECTIVE ==> veq(\result.origin, cam->eye));
    ensures EXACT(cam->kind == CAMERA_ORTHOGRAPHIC ==> veq(\result.dir, cam->forward));
    ensures cam->kind == CAMERA_ORTHOGRAPHIC ==> vfinite(\result.origin) && vfinite(\result.dir) &&
                                                 DOUBLES(vbounded(\result.dir, 4)); */
ray camera_ray(const scene_camera *cam, real half, int width, int height, real x, real y)
{
    real aspect = (real)height / (real)width;
    /*@ assert aspect > 0; */
    real sx = 2.0 * x / width - 1.0;   /* -1 at the left edge, +1 at the right */
    real sy = 1.0 - 2.0 * y / height;  /* +1 at the top, -1 at the bottom */
    ray r;
    r.tmin = 0.0;
    r.tmax = HUGE_VAL;
    if (cam->kind == CAMERA_ORTHOGRAPHIC) {
        r.origin = vec_add(cam->eye, screen_offset(cam, 0.5 * cam->width, aspect, sx, sy));
        r.dir = cam->forward;
    } else {
        vec3 d = vec_add(cam->forward, screen_offset(cam, half, aspect, sx, sy));
        r.origin = cam->eye;
        r.dir = vec_normalize(d);
    }
    return r;
}
