/*
 * camera.h - primary rays.  Image coordinates are continuous: x from 0 at
 * the left edge to width at the right, y from 0 at the top to height at the
 * bottom, so pixel (i, j) covers [i, i+1) x [j, j+1) and its centre is
 * (i + 0.5, j + 0.5).
 */
#ifndef REFRAY_CAMERA_H
#define REFRAY_CAMERA_H

#include "render/ray.h"
#include "scene/scene.h"

/*
 * The half-width of a perspective camera's screen at distance 1,
 * tan(fov/2); 0 for an orthographic camera, whose rays do not read it.
 * Made once per image (a tracer keeps it: tracer.camera_half), not per
 * camera ray.
 */
real camera_half(const scene_camera *cam);

/*
 * The camera ray through image point (x, y) of a width x height image.
 * Perspective: from the eye, through the point of a screen at distance 1
 * whose half-width is half, which must be camera_half(cam).  Orthographic:
 * parallel to forward, from the point of a width-wide rectangle centred on
 * the eye.
 */
ray camera_ray(const scene_camera *cam, real half, int width, int height, real x, real y);

#endif
