/* What flattening (flatten.c) will make of an object, counted from the
 * scene's tree before anything is made: so that a world too big for the
 * memory budget is refused at the object that makes it so, rather than
 * found out by running out of memory. A union of two copies of itself,
 * twenty times over, is a scene of 150 bytes and a million objects; the
 * tree shares its subtrees, so each is counted once (memoised by node) and
 * the count takes as long as the scene's text, not as the world. */
#ifndef HST_WORLD_ESTIMATE_H
#define HST_WORLD_ESTIMATE_H

#include "world.h"

typedef struct WorldEstimate WorldEstimate;

/* NULL when out of memory. */
WorldEstimate *world_estimate_new(void);
/* The bytes the world and its hierarchy will take for `o` and everything
 * under it (polygons, points, outlines, normals, uvs, planes, a material
 * per object, and the hierarchy's share per polygon), and its polygons; as
 * doubles, which hold any count a tree of 200 levels can make. Returns 0,
 * or -1 when out of memory. */
int world_estimate_object(WorldEstimate *e, const SceneObject *o, double *bytes, double *polygons);
void world_estimate_free(WorldEstimate *e);

#endif
