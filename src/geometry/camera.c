/* Camera rays (camera.h): POV-Ray 3.7's TracePixel::CreateCameraRay, type by
 * type, with its constants and its order of operations. */
#include <math.h>

#include "camera.h"

/* POV-Ray's own constants (configbase.h, configbackend.h), as written there:
 * M_PI / 180 computed here could differ from them in the last bit. */
#define POV_PI_180 0.01745329251994329576
#define POV_PI_360 0.00872664625997164788
#define POV_TWO_PI 6.283185307179586476925286766560
#define POV_PI_2 (M_PI / 2.0) /* exact: a halving */
#define POV_EPSILON 1.0e-10
#define POV_BOUND_HUGE 2.0e+10

/* POV-Ray's VLinComb3 and VLinComb2: a*A + b*B (+ c*C), left to right. */
static Vec3 lin3(double a, Vec3 A, double b, Vec3 B, double c, Vec3 C)
{
    return v3(a * A.x + b * B.x + c * C.x, a * A.y + b * B.y + c * C.y, a * A.z + b * B.z + c * C.z);
}

static Vec3 lin2(double a, Vec3 A, double b, Vec3 B)
{
    return v3(a * A.x + b * B.x, a * A.y + b * B.y, a * A.z + b * B.z);
}

/* v turned by `angle` radians about `axis`: POV-Ray's
 * Compute_Axis_Rotation_Transform matrix applied as MTransPoint does. */
static Vec3 rotate_about(Vec3 v, Vec3 axis, double angle)
{
    Vec3 a = v3_normalize(axis);
    double c = cos(angle), s = sin(angle);
    double m[3][3] = {
        { a.x * a.x + c * (1.0 - a.x * a.x), a.x * a.y * (1.0 - c) + a.z * s, a.x * a.z * (1.0 - c) - a.y * s },
        { a.x * a.y * (1.0 - c) - a.z * s, a.y * a.y + c * (1.0 - a.y * a.y), a.y * a.z * (1.0 - c) + a.x * s },
        { a.x * a.z * (1.0 - c) + a.y * s, a.y * a.z * (1.0 - c) - a.x * s, a.z * a.z + c * (1.0 - a.z * a.z) },
    };
    return v3(v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0], v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
              v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2]);
}

/* The angle around the axis of a point (x0, y0) at distance rad of the
 * centre, as the fisheye and omnimax cameras measure it. */
static double polar_angle(double x0, double y0, double rad)
{
    if (rad == 0.0)
        return 0.0;
    if (x0 < 0.0)
        return M_PI - asin(y0 / rad);
    return asin(y0 / rad);
}

int camera_has_one_origin(const Camera *cam)
{
    return cam->kind != CAMERA_ORTHOGRAPHIC && cam->kind != CAMERA_CYLINDER_3 && cam->kind != CAMERA_CYLINDER_4;
}

int camera_ray_at(const Camera *cam, int width, int height, double x, double y, Vec3 *org, Vec3 *dir)
{
    /* POV-Ray's CreateCameraRay: x += 0.5, y -= 0.5, then (for most types)
     * x0 = x/width - 0.5 and y0 = ((height-1) - y)/height - 0.5. */
    const double px = x + 0.5, py = y - 0.5;
    double x0 = px / width - 0.5;
    double y0 = ((height - 1) - py) / height - 0.5;
    Vec3 right = cam->right, up = cam->up, direction = cam->direction;
    const double right_len = v3_length(right), up_len = v3_length(up);
    /* SetupCamera: the aspect ratio each type uses, and which types work
     * with the unit vectors of the camera's frame */
    double aspect = right_len / up_len;
    int normalise = 1;
    switch (cam->kind) {
    case CAMERA_CYLINDER_1: case CAMERA_CYLINDER_3: aspect = up_len; break;
    case CAMERA_CYLINDER_2: case CAMERA_CYLINDER_4: aspect = right_len; break;
    case CAMERA_ULTRA_WIDE_ANGLE: aspect = up_len / right_len; break;
    case CAMERA_OMNIMAX: case CAMERA_FISHEYE: break;
    default: normalise = 0; break;
    }
    if (normalise) {
        right = v3_normalize(right);
        up = v3_normalize(up);
        direction = v3_normalize(direction);
    }
    *org = cam->location;

    switch (cam->kind) {
    case CAMERA_PERSPECTIVE:
        *dir = v3_normalize(v3_add(direction, v3_add(v3_scale(right, x0), v3_scale(up, y0))));
        return 1;
    case CAMERA_ORTHOGRAPHIC:
        *org = v3_add(cam->location, v3_add(v3_scale(right, x0), v3_scale(up, y0)));
        *dir = v3_normalize(direction);
        return 1;
    case CAMERA_FISHEYE:
    case CAMERA_OMNIMAX: {
        x0 = 2.0 * px / width - 1.0;
        y0 = 2.0 * ((height - 1) - py) / height - 1.0;
        if (cam->kind == CAMERA_FISHEYE) {
            x0 *= right_len;
            y0 *= up_len;
        } else if (aspect > 1.0) { /* the omnimax's frame on the dome */
            if (aspect > 1.283458) {
                x0 *= aspect / 1.283458;
                y0 = (y0 - 1.0) / 1.283458 + 1.0;
            } else {
                y0 = (y0 - 1.0) / aspect + 1.0;
            }
        } else {
            y0 /= aspect;
        }
        const double rad = sqrt(x0 * x0 + y0 * y0);
        if (rad > 1.0) /* outside the circle: no ray */
            return 0;
        const double phi = polar_angle(x0, y0, rad);
        const double theta = cam->kind == CAMERA_FISHEYE
                                 ? rad * cam->angle * POV_PI_360
                                 : 1.411269 * rad - 0.09439 * rad * rad * rad + 0.25674 * rad * rad * rad * rad * rad;
        const double cx = cos(phi), sx = sin(phi), cy = cos(theta), sy = sin(theta);
        /* the omnimax sees nothing below 45 degrees under its axis */
        if (cam->kind == CAMERA_OMNIMAX && sx * sy < tan(135.0 * POV_PI_180) * cy)
            return 0;
        *dir = v3_normalize(lin3(cx * sy, right, sx * sy, up, cy, direction));
        return 1;
    }
    case CAMERA_PANORAMIC: {
        x0 = (1.0 - px / width) * M_PI;
        y0 = POV_PI_2 * (2.0 * ((height - 1) - py) / height - 1.0);
        double ty;
        if (fabs(POV_PI_2 - fabs(y0)) < POV_EPSILON)
            ty = y0 > 0.0 ? POV_BOUND_HUGE : -POV_BOUND_HUGE;
        else
            ty = tan(y0);
        *dir = v3_normalize(lin3(cos(x0), right, ty, up, sin(x0), direction));
        return 1;
    }
    case CAMERA_ULTRA_WIDE_ANGLE:
        x0 *= cam->angle * POV_PI_180;
        y0 *= cam->angle * aspect * POV_PI_180;
        *dir = v3_normalize(lin3(sin(x0), right, sin(y0), up, cos(x0) * cos(y0), direction));
        return 1;
    case CAMERA_CYLINDER_1: /* axis along up */
        x0 *= cam->angle * POV_PI_180;
        y0 *= aspect;
        *dir = v3_normalize(lin3(sin(x0), right, y0, up, cos(x0), direction));
        return 1;
    case CAMERA_CYLINDER_2: /* axis along right */
        y0 *= cam->angle * POV_PI_180;
        x0 *= aspect;
        *dir = v3_normalize(lin3(x0, right, sin(y0), up, cos(y0), direction));
        return 1;
    case CAMERA_CYLINDER_3: /* axis along up, parallel rays along it */
        x0 *= cam->angle * POV_PI_180;
        y0 *= aspect;
        *dir = v3_normalize(lin2(sin(x0), right, cos(x0), direction));
        *org = lin2(1.0, cam->location, y0, up);
        return 1;
    case CAMERA_CYLINDER_4: /* axis along right, parallel rays along it */
        y0 *= cam->angle * POV_PI_180;
        x0 *= aspect;
        *dir = v3_normalize(lin2(sin(y0), up, cos(y0), direction));
        *org = lin2(1.0, cam->location, x0, right);
        return 1;
    case CAMERA_SPHERICAL: {
        /* latitude: direction turned about right; longitude: about up */
        y0 *= (cam->v_angle / 360) * POV_TWO_PI;
        x0 *= (cam->h_angle / 360) * POV_TWO_PI;
        Vec3 v = rotate_about(direction, right, -y0);
        *dir = v3_normalize(rotate_about(v, up, x0));
        return 1;
    }
    }
    return 0;
}

int camera_ray(const Camera *cam, int width, int height, int x, int y, Vec3 *org, Vec3 *dir)
{
    return camera_ray_at(cam, width, height, x, y, org, dir);
}
