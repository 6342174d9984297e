/* Camera rays, made exactly as POV-Ray 3.7 makes them for each of its
 * camera types but the mesh camera (its TracePixel::CreateCameraRay). */
#ifndef HST_CAMERA_H
#define HST_CAMERA_H

#include "world.h"

/* The camera ray through the centre of pixel (x, y) of a width x height
 * image, row 0 at the top. Returns 0 when the camera traces no ray there
 * (outside the fisheye's circle, below the omnimax's dome): POV-Ray gives
 * such a pixel black, fully transparent. */
int camera_ray(const Camera *cam, int width, int height, int x, int y, Vec3 *org, Vec3 *dir);
/* The same through pixel coordinates that need not be whole (the samples of
 * anti-aliasing): camera_ray's ray for whole ones. */
int camera_ray_at(const Camera *cam, int width, int height, double x, double y, Vec3 *org, Vec3 *dir);
/* Whether every camera ray starts at the camera's location (all types but
 * orthographic and cylinders 3 and 4). */
int camera_has_one_origin(const Camera *cam);

#endif
