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
 * The camera ray through image point (x, y) of a width x height image.
 * Perspective: from the eye, through the point of a screen at distance 1
 * whose half-width is tan(fov/2).  Orthographic: parallel to forward, from
 * the point of a width-wide rectangle centred on the eye.
 */
ray camera_ray(const scene_camera *cam, int width, int height, real x, real y);

#endif
