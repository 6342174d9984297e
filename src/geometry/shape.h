/* Analytic shapes: POV-Ray's curved primitives kept as what they are (a
 * sphere stays a centre and a radius, never triangles), with POV-Ray 3.7's
 * own intersection arithmetic, tolerances, normals, inside tests, uv
 * coordinates and bounds, so that a ray meets a shape where POV-Ray's does.
 *
 * Every query answers along a ray org + t dir (dir need not be unit: t is
 * in units of dir, as the polygon tests'). The ray leaving a shape's own
 * surface is not told which shape it left: as in POV-Ray, each shape's
 * depth tolerance alone keeps a ray from meeting the surface it starts on. */
#ifndef HST_SHAPE_H
#define HST_SHAPE_H

#include "transform.h"
#include "vecmath.h"

/* SHAPE_BOX and SHAPE_PLANE are POV-Ray's box and plane as parts of CSG
 * objects (csg.h), where their inside matters; elsewhere a box is six
 * polygons and a plane an InfinitePlane (world.h). */
typedef enum {
    SHAPE_SPHERE, SHAPE_DISC, SHAPE_CONE, SHAPE_TORUS, SHAPE_CSG, SHAPE_BOX, SHAPE_PLANE, SHAPE_GLYPH, SHAPE_BLOB,
    SHAPE_QUADRIC, /* quadric.h */
    SHAPE_POLY,    /* poly.h: poly, cubic, quartic */
    SHAPE_SUPERELLIPSOID, /* superellipsoid.h */
    SHAPE_LATHE,   /* lathe.h */
    SHAPE_SOR,     /* sor.h */
    SHAPE_PRISM,   /* prism.h */
} ShapeKind;

/* A CSG object's operation (csg.h), after POV-Ray's rewriting: a
 * difference is an intersection whose later parts are inverted, and an
 * inverted CSG object the other operation over inverted parts. UNION is
 * a union inside a CSG object or clipped (a top-level union is
 * flattened); CLIP an object clipped_by others: its first part, the
 * others its clipping solids; BOUND an object bounded_by others where
 * POV-Ray keeps the bound (a poly, a quadric without bounds of its own):
 * its first part, the others its bounding solids (csg.h). */
typedef enum { CSG_UNION, CSG_INTERSECTION, CSG_MERGE, CSG_CLIP, CSG_BOUND } CsgOp;

/* Which part of a shape a crossing is on, where the normal depends on it:
 * a cone's or cylinder's side, its cap (the wide end, +z in its own space)
 * or its base (POV-Ray's SIDE_HIT, CAP_HIT, BASE_HIT). */
enum { SHAPE_SIDE = 0, SHAPE_CAP = 1, SHAPE_BASE = 2 };

/* A box's sides as a crossing's part (POV-Ray's SIDE_X_0 ... SIDE_Z_1;
 * 0: none decided, POV-Ray's own initial value). */
enum { BOX_SIDE_X0 = 1, BOX_SIDE_X1, BOX_SIDE_Y0, BOX_SIDE_Y1, BOX_SIDE_Z0, BOX_SIDE_Z1 };

/* The most surfaces one ray can cross on one shape: four on a torus, one
 * per line and two per curve of a glyph's outline (text.h), the sum of its
 * parts' on a CSG object, which the world's build keeps within this
 * (Shape.max_hits): room for a text of some 60 letters as a CSG part (a
 * buffer of 96 KiB on the stack where one is kept). */
#define SHAPE_MAX_HITS 4096
/* The most crossings one test of a shape found numerically from the
 * ray's origin reports (poly, superellipsoid, lathe, sor: shape.c casts
 * the ray again past each, with a buffer of this many); a lathe or sor of
 * more segments keeps its nearest crossings. */
#define SHAPE_NUMERIC_MAX_HITS 256

typedef struct Shape Shape;
struct Blob;
struct SplineSegment; /* scene.h: a lathe's segment */
struct SorSegment;    /* scene.h: a sor's segment */
struct PrismSegment;  /* scene.h: a prism's segment */

/* One crossing of a shape's surface: where, and whether the ray enters
 * the solid there (for CSG and the interiors a ray is inside). */
typedef struct {
    double t;
    int entering;
    int part;             /* SHAPE_SIDE, SHAPE_CAP, SHAPE_BASE */
    /* The primitive crossed: the shape itself (NULL), or a CSG object's
     * part, whose material, normal and uv the crossing has. */
    const Shape *leaf;
} ShapeHit;

struct Shape {
    ShapeKind kind;
    int material;         /* World.materials */
    /* 1: a part of a CSG object, reached through it alone (World.shapes
     * past nshapes), never an item of the hierarchy */
    int is_part;
    /* How many shapes this one and its parts take in World.shapes: 1 for
     * a primitive; a CSG object's parts follow it, each with its own
     * parts after it, so that the next sibling is `subtree` further. */
    int subtree;
    int max_hits;         /* the most crossings one ray can have with it */
    int inverse;          /* POV-Ray's inverse: inside and outside swapped */
    /* 0: the parameters are in world space (POV-Ray keeps a sphere's centre
     * and radius through translations, rotations and uniform scales);
     * 1: they are in the shape's own space, reached through to_world's
     * inverse (POV-Ray's Trans: its ellipsoid, and every shape whose
     * parameters cannot absorb a transform). */
    int transformed;
    /* The shape's own space to world: every transform written on it and
     * its unions, whether or not its parameters absorbed them (POV-Ray's
     * UV_Trans, which places uv coordinates, collects them all). */
    Transform to_world;
    union {
        struct {
            Vec3 center;          /* in world space, or in its own where transformed */
            double radius;
            Vec3 own_center;      /* as written: in its own space */
        } sphere;
        /* A disc is the unit disc of the z = 0 plane of its own space
         * (POV-Ray's Compute_Coordinate_Transform places it), between the
         * squared radii. */
        struct {
            double inner2, outer2;
            Vec3 normal;          /* world space, unit */
        } disc;
        /* A cone is x^2 + y^2 = z^2 for dist <= z <= 1 in its own space, a
         * cylinder x^2 + y^2 = 1 for 0 <= z <= 1 (POV-Ray's canonical
         * cone), capped unless open. */
        struct {
            int cylinder, closed;
            double dist;
        } cone;
        /* A torus about the y axis of its own space: the circle of radius
         * minor swept around the circle of radius major. sturm: the scene
         * asked for POV-Ray's Sturm solver (polynomial_solver.h). */
        struct {
            double major, minor;
            int sturm;
        } torus;
        /* A blob (blob.h), in its own space; its components are the
         * world's (World.blobs). sturm: POV-Ray's Sturm solver always. */
        struct {
            const struct Blob *blob;
            int sturm;
        } blob;
        /* A box between its corners lo <= hi, in world space or in its own
         * where transformed (POV-Ray's bounds, moved and scaled with the
         * box until a rotation or matrix gives it a transform). */
        struct {
            Vec3 lo, hi;
        } box;
        /* A plane's solid: dot(p, normal) + distance < EPSILON (POV-Ray's
         * Normal_Vector and Distance, the negated d of plane { N, d };
         * inverse negates both, as Plane::Invert), in world space or its
         * own where transformed. */
        struct {
            Vec3 normal;
            double distance;
        } plane;
        /* A glyph of a text object (text.h), in its own space. */
        struct {
            const struct SceneGlyph *glyph;
            double depth;
        } glyph;
        /* A quadric's coefficients in world space, inverse applied, and
         * its bounds (quadric.h) */
        struct {
            Vec3 square, mixed, terms;
            double constant;
        } quadric;
        /* A poly's coefficients in POV-Ray's order of terms (poly.h), in
         * its own space; sturm: POV-Ray's Sturm solver asked for */
        struct {
            int order;
            const double *coeffs;
            int sturm;
        } poly;
        /* A superellipsoid in its own space: POV-Ray's Power x and z,
         * 2/e and 2/n of superellipsoid { <e, n> } */
        struct {
            double ex, ez;
        } superellipsoid;
        /* A lathe in its own space: its spline's segments (the scene's),
         * their kind (SplineKind) and its overall bounding cylinder */
        struct {
            int spline;
            int nsegments;
            const struct SplineSegment *segments;
            double radius1, radius2, height1, height2;
            int sturm;
        } lathe;
        /* A sor in its own space: its segments (the scene's), its
         * bounding cylinder, its discs' squared radii */
        struct {
            int nsegments;
            const struct SorSegment *segments;
            double radius1, radius2, height1, height2, base2, cap2;
            int open, sturm;
        } sor;
        /* A prism in its own space: its segments and rectangles (the
         * scene's, scene.h), its spline (SplineKind), its heights */
        struct {
            int spline, conic;
            int nsegments;
            const struct PrismSegment *segments;
            double height1, height2;
            double u1, u2, v1, v2, x1, x2, y1, y2;
            int open, sturm, degenerate;
        } prism;
        /* A CSG object: nparts parts, the first at `parts` (the next at
         * parts + parts->subtree ...), set once World.shapes is final. */
        struct {
            CsgOp op;
            int nparts;
            int first_part;   /* while building: the first part's index among the parts */
            const Shape *parts;
        } csg;
    } u;
    Vec3 bbox_min, bbox_max; /* world space */
};

/* A ray as the analytic shapes' tests make it unit (crossings and
 * sphere_all in shape.c), worked out once for a ray tested against many
 * spheres: POV-Ray's rays are unit, so the tests run along u = dir / |dir|,
 * and a sphere's along u made unit again (|u| may round off 1). */
typedef struct {
    Vec3 org;
    double len;  /* |dir| */
    double ulen; /* |u|, u = dir / len as crossings() makes it */
    Vec3 uu;     /* u / ulen, as sphere_all makes it */
} ShapeRay;
static inline void shape_ray_init(ShapeRay *r, Vec3 org, Vec3 dir)
{
    r->org = org;
    r->len = v3_length(dir);
    Vec3 u = r->len == 1.0 ? dir : v3_scale(dir, 1.0 / r->len);
    /* u is dir itself where len is 1: its length is len (the same sum) */
    r->ulen = r->len == 1.0 ? r->len : v3_length(u);
    r->uu = r->ulen == 1.0 ? u : v3_scale(u, 1.0 / r->ulen);
}

/* ---- the sphere's test: sphere_all's (shape.c), inline here for the
 * tests that meet many spheres along one ray ---- */

#define SHAPE_SPHERE_DEPTH_TOLERANCE 1.0e-6 /* spheres.cpp's DEPTH_TOLERANCE */
#define SHAPE_MAX_DISTANCE 1.0e7            /* POV-Ray's MAX_DISTANCE */

/* POV-Ray's Sphere::Intersect for a unit direction: the two crossings of
 * the line, or 0 when it misses, grazes (half chord squared within EPSILON)
 * or starts outside moving away. */
static inline int shape_sphere_roots(Vec3 org, Vec3 unit_dir, Vec3 center, double radius2, double *t1, double *t2)
{
    Vec3 oc = v3_sub(center, org);
    double oc2 = v3_dot(oc, oc);
    double closest = v3_dot(oc, unit_dir);
    if (oc2 >= radius2 && closest < POV_EPSILON)
        return 0;
    double half_chord2 = radius2 - oc2 + closest * closest;
    if (!(half_chord2 > POV_EPSILON))
        return 0;
    double half_chord = sqrt(half_chord2);
    *t1 = closest - half_chord;
    *t2 = closest + half_chord;
    return 1;
}

/* sphere_all's test in the sphere's own space from o along u, which is
 * d / len (len = |d| > 0): the two crossings' t along d in t[0] (entering)
 * and t[1] (leaving); returns which of them count, as bits (1: t[0], 2:
 * t[1]). sphere_all's own, and shape_sphere_crossings', so that both do the
 * same arithmetic. */
static inline unsigned shape_sphere_unit_crossings(const Shape *s, Vec3 o, Vec3 u, double len, double tmax,
                                                   double t[2])
{
    double r = s->u.sphere.radius, t1, t2;
    if (!shape_sphere_roots(o, u, s->u.sphere.center, r * r, &t1, &t2))
        return 0;
    unsigned kept = 0;
    const double depth[2] = { t1, t2 };
    for (int k = 0; k < 2; k++) {
        if (!(depth[k] > SHAPE_SPHERE_DEPTH_TOLERANCE && depth[k] < SHAPE_MAX_DISTANCE))
            continue;
        t[k] = len == 1.0 ? depth[k] : depth[k] / len;
        if (t[k] < tmax)
            kept |= 1u << k;
    }
    return kept;
}

/* shape_intersect_all for an untransformed sphere (kind SHAPE_SPHERE,
 * !transformed; its box not tested) along r: the t of its crossings,
 * nearest first, into t; returns how many (0 to 2). The same arithmetic,
 * bit for bit (tests/test_bvh.c compares them), without the frame every
 * shape's test needs: the fast path of the tests that meet many spheres
 * along one ray (shadow rays through a light buffer's cell, nearest hits). */
static inline int shape_sphere_crossings(const Shape *s, const ShapeRay *r, double tmax, double t[2])
{
    /* crossings(): the unit direction u and the limit along it */
    if (!(r->len > 0.0))
        return 0;
    double ulimit = r->len == 1.0 ? tmax : tmax * r->len;
    /* sphere_all(s, org, u, ulimit), s untransformed: its own ray is r's */
    if (!(r->ulen > 0.0))
        return 0;
    double ut[2];
    unsigned kept = shape_sphere_unit_crossings(s, r->org, r->uu, r->ulen, ulimit, ut);
    int n = 0;
    for (int k = 0; k < 2; k++)
        if (kept & (1u << k)) /* crossings() divides back to t along dir */
            t[n++] = r->len == 1.0 ? ut[k] : ut[k] / r->len;
    return n;
}

/* Fills s's bounds from its parameters and transform (POV-Ray's
 * Compute_BBox, carried through the transform as Recompute_BBox does). */
void shape_compute_bounds(Shape *s);

/* Every crossing of s by the ray at t in (0, tmax) that POV-Ray's
 * All_Intersections would report (its depth tolerance and MAX_DISTANCE
 * applied), nearest first, into hits (room for s->max_hits, at most
 * SHAPE_MAX_HITS); returns how many. */
int shape_intersect_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);

/* The nearest of them (its part, and the primitive it is on, in *hit), or
 * -1 when there is none before tmax. */
double shape_nearest(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hit);

/* Is the world point inside the solid (POV-Ray's Inside, inverse
 * included)? */
int shape_inside(const Shape *s, Vec3 p);

/* The outward surface normal at world point p on part `part` of s
 * (POV-Ray's Normal; not turned toward any ray), of unit length up to
 * POV-Ray's own rounding. */
Vec3 shape_normal(const Shape *s, Vec3 p, int part);

/* POV-Ray's UVCoord at world point p on s, as (u, v, 0). */
Vec3 shape_uv(const Shape *s, Vec3 p);


/* Puts n crossings in order of distance, nearest first, those at one
 * distance in the order given (stable: a CSG object's earlier part
 * first); POV-Ray takes the nearest of its intersection stack. */
void shape_hits_sort(ShapeHit *hits, int n);

/* Where a crossing at distance d goes among the *n crossings in hits
 * (room for s->max_hits): the next slot (*n grows), or, the list full, the
 * farthest one's if d is nearer; -1 where it is not kept. */
int shape_hit_slot(const Shape *s, ShapeHit *hits, int *n, double d);

/* Does the ray come near s's bounds for some t in [0, tmax]? A
 * conservative rejection before the exact test. */
int shape_box_hit(const Shape *s, Vec3 org, Vec3 dir, double tmax);

#endif
