/* Affine transforms with POV-Ray's conventions: row vectors, a point p maps to
 * p * M, transforms compose in the order they are written, rotations are in
 * degrees about x, then y, then z in POV-Ray's left-handed frame. */
#ifndef HST_TRANSFORM_H
#define HST_TRANSFORM_H

#include "vecmath.h"

typedef struct {
    double m[4][4];   /* forward: object to world */
    double inv[4][4]; /* inverse: world to object */
} Transform;

void transform_identity(Transform *t);
void transform_translate(Transform *t, Vec3 v);
void transform_scale(Transform *t, Vec3 v);
void transform_rotate(Transform *t, Vec3 degrees);
/* POV-Ray's `matrix <m00,m01,m02, m10,m11,m12, m20,m21,m22, m30,m31,m32>`.
 * Returns 0 when the matrix is singular (and leaves t unchanged). */
int transform_matrix(Transform *t, const double v[12]);
/* t = t followed by u (u applied after t). */
void transform_compose(Transform *t, const Transform *u);
int transform_is_identity(const Transform *t);
/* 1 when t's linear part is a rotation (or mirror) times one scale factor:
 * rows orthogonal and of one length, to rounding. Such a transform keeps a
 * sphere a sphere. */
int transform_is_similarity(const Transform *t);
/* The scale factor of a similarity: the length of its linear part's rows. */
double transform_similarity_scale(const Transform *t);

/* t = the frame POV-Ray's Compute_Coordinate_Transform makes: its own
 * space scaled by (radius, radius, length), z turned to the unit vector
 * up, moved to origin. Discs, cones and cylinders are placed by it. */
void transform_coordinate_frame(Transform *t, Vec3 origin, Vec3 up, double radius, double length);
/* A cone's or cylinder's canonical frame (POV-Ray's Compute_Cone_Data and
 * Compute_Cylinder_Data): the wider end at z = 1, a cone's tip at the
 * origin and its narrower end at z = *dist (0 for a cylinder); ends of
 * radii within EPSILON, or a cone too slender to tell from one, make a
 * cylinder. base != apex. Returns 1 for a cylinder. */
int transform_cone_frame(Transform *frame, Vec3 base, double base_radius, Vec3 apex, double apex_radius,
                         double *dist);

Vec3 transform_point(const Transform *t, Vec3 p);
Vec3 transform_direction(const Transform *t, Vec3 d);
/* Normals transform with the inverse transpose. */
Vec3 transform_normal(const Transform *t, Vec3 n);
/* The other way (world normals into object space): n * M^T. */
Vec3 inverse_transform_normal(const Transform *t, Vec3 n);
Vec3 inverse_transform_point(const Transform *t, Vec3 p);
Vec3 inverse_transform_direction(const Transform *t, Vec3 d);

#endif
