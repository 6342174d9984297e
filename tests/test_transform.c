/* Vector and transform maths, against values worked out by hand with
 * POV-Ray's conventions (left-handed, rotations in degrees x then y then z). */
#include <math.h>

#include "tap.h"
#include "transform.h"

static int near(Vec3 a, Vec3 b, double eps)
{
    return fabs(a.x - b.x) <= eps && fabs(a.y - b.y) <= eps && fabs(a.z - b.z) <= eps;
}

int main(void)
{
    Vec3 a = v3(1, 2, 3), b = v3(-2, 0.5, 4);
    tap_ok(v3_dot(a, b) == -2 + 1 + 12, "dot product");
    Vec3 c = v3_cross(v3(1, 0, 0), v3(0, 1, 0));
    tap_ok(near(c, v3(0, 0, 1), 0), "x cross y is z");
    tap_ok(fabs(v3_length(v3_normalize(b)) - 1.0) < 1e-15, "normalize gives unit length");

    Transform t;
    transform_identity(&t);
    tap_ok(transform_is_identity(&t), "identity is identity");
    transform_translate(&t, v3(1, 2, 3));
    tap_ok(near(transform_point(&t, v3(0, 0, 0)), v3(1, 2, 3), 0), "translate moves points");
    tap_ok(near(transform_direction(&t, v3(0, 0, 1)), v3(0, 0, 1), 0), "translate leaves directions");

    /* POV-Ray: rotate <0,90,0> takes +x to -z (left-handed, clockwise looking down +y). */
    transform_identity(&t);
    transform_rotate(&t, v3(0, 90, 0));
    tap_ok(near(transform_point(&t, v3(1, 0, 0)), v3(0, 0, -1), 1e-15), "rotate y 90 takes +x to -z");
    transform_identity(&t);
    transform_rotate(&t, v3(90, 0, 0));
    tap_ok(near(transform_point(&t, v3(0, 1, 0)), v3(0, 0, 1), 1e-15), "rotate x 90 takes +y to +z");
    transform_identity(&t);
    transform_rotate(&t, v3(0, 0, 90));
    tap_ok(near(transform_point(&t, v3(1, 0, 0)), v3(0, 1, 0), 1e-15), "rotate z 90 takes +x to +y");

    /* Order matters: scale then translate differs from translate then scale. */
    Transform st, ts;
    transform_identity(&st);
    transform_scale(&st, v3(2, 2, 2));
    transform_translate(&st, v3(1, 0, 0));
    transform_identity(&ts);
    transform_translate(&ts, v3(1, 0, 0));
    transform_scale(&ts, v3(2, 2, 2));
    tap_ok(near(transform_point(&st, v3(1, 0, 0)), v3(3, 0, 0), 0), "scale then translate");
    tap_ok(near(transform_point(&ts, v3(1, 0, 0)), v3(4, 0, 0), 0), "translate then scale");

    /* Inverse undoes forward for a mixed transform. */
    Transform m;
    transform_identity(&m);
    transform_scale(&m, v3(2, 3, 0.5));
    transform_rotate(&m, v3(10, 20, 30));
    transform_translate(&m, v3(-4, 5, 6));
    Vec3 p = v3(0.3, -1.7, 2.2);
    tap_ok(near(inverse_transform_point(&m, transform_point(&m, p)), p, 1e-12), "inverse undoes a mixed transform");

    /* Normals stay perpendicular to transformed surfaces under non-uniform scale. */
    Transform s;
    transform_identity(&s);
    transform_scale(&s, v3(1, 4, 1));
    Vec3 tangent = transform_direction(&s, v3(1, -1, 0));
    Vec3 normal = transform_normal(&s, v3(1, 1, 0));
    tap_ok(fabs(v3_dot(tangent, normal)) < 1e-15, "normals transform with the inverse transpose");

    /* matrix <...> is POV-Ray's row-vector layout; a singular one is refused. */
    double shear[12] = { 1, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0 };
    transform_identity(&m);
    tap_ok(transform_matrix(&m, shear), "matrix keyword accepts a shear");
    tap_ok(near(transform_point(&m, v3(0, 1, 0)), v3(1, 1, 0), 0), "shear maps y into x as POV-Ray's matrix does");
    double singular[12] = { 1, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0 };
    tap_ok(!transform_matrix(&m, singular), "a singular matrix is refused");
    return tap_done();
}
