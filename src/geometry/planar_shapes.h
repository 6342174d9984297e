/* The shapes POV-Ray 3.7 itself intersects as planar triangles and
 * polygons: height_field (two triangles a cell of its samples) and
 * bicubic_patch (its own subdivision's triangles, normals interpolated). Each builder turns the
 * description's object into world-space pieces handed to a PieceSink
 * (flatten.c adds them to the world), so every shadow method treats them as
 * the polygons they are; each counts its pieces beforehand for
 * world_estimate.c. */
#ifndef HST_PLANAR_SHAPES_H
#define HST_PLANAR_SHAPES_H

#include "scene.h"
#include "transform.h"
#include "vecmath.h"

/* A height field cell's shading data (a smooth one's): the unit world
 * normals at its corners (x, z), (x+1, z), (x, z+1), (x+1, z+1), then the
 * affine map from a world point to its place in the cell: fx = a_x . q +
 * b.x, fz = a_z . q + b.y, kept as the vectors a_x, a_z, b. */
#define CELL_NORMAL_VECTORS 7

typedef struct PieceSink PieceSink;
struct PieceSink {
    void *user;
    /* A triangle; normals: 3 vertex normals (world space, interpolated as
     * a smooth triangle's) or NULL for a flat one; uv: the texture's (u, v,
     * 0) at its corners or NULL. Returns 0, or -1 when out of memory. */
    int (*triangle)(PieceSink *s, const Vec3 v[3], const Vec3 *normals, const Vec3 *uv);
    /* A flat polygon of noutlines closed outlines (even-odd), as
     * World.polygons holds them. */
    int (*polygon)(PieceSink *s, const Vec3 *pts, int n, const int *starts, int noutlines);
    /* A convex polygon of a smooth height field's cell, shaded by `cell`. */
    int (*cell_polygon)(PieceSink *s, const Vec3 *pts, int n, const Vec3 cell[CELL_NORMAL_VECTORS]);
};

/* The pieces of o (its kind's), placed by to_world (object to world).
 * Return 0, or -1 when the sink fails. */
int height_field_pieces(const SceneObject *o, const Transform *to_world, PieceSink *sink);
int bicubic_patch_pieces(const SceneObject *o, const Transform *to_world, PieceSink *sink);

/* How many pieces, and points in all, the builder above makes of o at most
 * (world_estimate.c: before anything is built). */
void height_field_count(const SceneObject *o, double *pieces, double *points);
void bicubic_patch_count(const SceneObject *o, double *pieces, double *points);

/* The shading normal of a smooth height field's cell at q (a point of
 * it): its corner normals blended bilinearly by q's place in the cell
 * (POV-Ray's HField::Normal), or `flat` where they cancel out. */
Vec3 cell_normal_at(const Vec3 cell[CELL_NORMAL_VECTORS], Vec3 q, Vec3 flat);

#endif
