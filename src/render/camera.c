/*
 * camera.c - see camera.h.
 */
#include "render/camera.h"

ray camera_ray(const scene_camera *cam, int width, int height, real x, real y)
{
    real aspect = (real)height / (real)width;
    real sx = 2.0 * x / width - 1.0;   /* -1 at the left edge, +1 at the right */
    real sy = 1.0 - 2.0 * y / height;  /* +1 at the top, -1 at the bottom */
    ray r;
    r.tmin = 0.0;
    r.tmax = HUGE_VAL;
    if (cam->kind == CAMERA_ORTHOGRAPHIC) {
        real half = 0.5 * cam->width;
        r.origin = vec_add(cam->eye, vec_add(vec_scale(cam->right, sx * half), vec_scale(cam->true_up, sy * half * aspect)));
        r.dir = cam->forward;
    } else {
        real half = tan(0.5 * cam->fov * (REAL_PI / 180));
        vec3 d = vec_add(cam->forward, vec_add(vec_scale(cam->right, sx * half), vec_scale(cam->true_up, sy * half * aspect)));
        r.origin = cam->eye;
        r.dir = vec_normalize(d);
    }
    return r;
}
