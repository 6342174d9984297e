/* Camera rays, made exactly as POV-Ray 3.7 makes them for its perspective
 * and orthographic cameras. */
#ifndef HST_CAMERA_H
#define HST_CAMERA_H

#include "world.h"

/* The camera ray through the centre of pixel (x, y) of a width x height
 * image, row 0 at the top. */
void camera_ray(const Camera *cam, int width, int height, int x, int y, Vec3 *org, Vec3 *dir);
/* The same through pixel coordinates that need not be whole (the samples of
 * anti-aliasing): camera_ray's ray for whole ones. */
void camera_ray_at(const Camera *cam, int width, int height, double x, double y, Vec3 *org, Vec3 *dir);

#endif
