/* Camera rays (camera.h). */
#include "camera.h"

void camera_ray_at(const Camera *cam, int width, int height, double x, double y, Vec3 *org, Vec3 *dir)
{
    /* POV-Ray's CreateCameraRay: x += 0.5, y -= 0.5, then
     * x0 = x/width - 0.5 and y0 = ((height-1) - y)/height - 0.5. */
    double px = x + 0.5, py = y - 0.5;
    double x0 = px / width - 0.5;
    double y0 = ((height - 1) - py) / height - 0.5;
    if (cam->kind == CAMERA_ORTHOGRAPHIC) {
        *org = v3_add(cam->location, v3_add(v3_scale(cam->right, x0), v3_scale(cam->up, y0)));
        *dir = v3_normalize(cam->direction);
        return;
    }
    *org = cam->location;
    *dir = v3_normalize(v3_add(cam->direction, v3_add(v3_scale(cam->right, x0), v3_scale(cam->up, y0))));
}

void camera_ray(const Camera *cam, int width, int height, int x, int y, Vec3 *org, Vec3 *dir)
{
    camera_ray_at(cam, width, height, x, y, org, dir);
}
