/* POV-Ray 3.7's blob (source/backend/shape/blob.cpp): the surface where a
 * sum of component fields equals the threshold. Each component's field is
 * strength * (1 - r^2/R^2)^2 within its radius R (r: the distance to a
 * sphere's centre, an ellipsoid's in its own space, a cylinder's axis
 * between its ends, or a hemisphere's centre at either end); a ray meets
 * the surface where, between consecutive boundaries of the components it
 * passes through, the quartic sum of their fields less the threshold has
 * a root, found by POV-Ray's own solver (polynomial_solver.h, the poly
 * shapes' too). Kept in blob space and reached through the shape's
 * transform, as POV-Ray's Trans. */
#ifndef HST_BLOB_H
#define HST_BLOB_H

#include "scene.h"
#include "shape.h"

/* A component as POV-Ray's Blob_Element after Make_Blob: a cylinder is
 * three of them (the cylinder, its base and apex hemispheres). */
typedef enum { BLOB_SPHERE, BLOB_ELLIPSOID, BLOB_CYLINDER, BLOB_BASE_HEMISPHERE, BLOB_APEX_HEMISPHERE } BlobElementKind;

typedef struct {
    BlobElementKind kind;
    Vec3 center;        /* sphere, ellipsoid */
    double radius2;     /* R^2 */
    double len;         /* cylinder and hemispheres: the axis's length in their own space */
    double c[3];        /* the field: c0 r^4 + c1 r^2 + c2 */
    int placed;         /* reached through `to_element` (all but the sphere) */
    Transform to_element; /* the element's own space to blob space */
} BlobElement;

typedef struct Blob {
    double threshold;
    int nelements;
    BlobElement *elements; /* in POV-Ray's order: the components last written first */
} Blob;

/* The blob of a scene object's components (POV-Ray's Make_Blob), or NULL
 * when out of memory. */
Blob *blob_make(const SceneBlobComponent *components, int n, double threshold);
void blob_free(Blob *b);

/* The Shape interface (shape.h) for SHAPE_BLOB. */
void blob_bounds(const Shape *s, Vec3 *lo, Vec3 *hi);
int blob_intersect_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);
int blob_inside(const Shape *s, Vec3 p);
Vec3 blob_normal(const Shape *s, Vec3 p);

#endif
