/*
 * refray.h - the public API of librefray.a.
 *
 * Load a scene (scene_load, scene_load_text: diagnostics to a stream, an
 * exit-code status, limits), render it (render_image, with progress and
 * cancellation through a callback), write or read images (img_write,
 * img_read) and compare them (metrics_compare).  Everything is reentrant:
 * there is no global state, so scenes may be loaded and rendered in
 * parallel by different threads, each with its own objects.
 *
 *   #include <refray/refray.h>      cc ... -lrefray -lOpenEXRCore -lpng -lm
 *
 * (-lOpenEXRCore and -lpng only when the library was built with EXR=1 and
 * PNG=1, the defaults.)  The headers below are installed next to this one.
 */
#ifndef REFRAY_REFRAY_H
#define REFRAY_REFRAY_H

#include "scene/scene.h"
#include "render/render.h"
#include "image/image_file.h"
#include "image/metrics.h"

#define REFRAY_API_VERSION 1

#endif
