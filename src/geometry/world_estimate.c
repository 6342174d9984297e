/* Counting what a flattening will make (world_estimate.h). */
#include "world_estimate.h"

#include <stdlib.h>

#include "planar_shapes.h"
#include "ptr_map.h"

/* The hierarchy's build (bvh.c) per polygon: its primitive, packed copy and
 * share of the nodes, measured on unions of boxes (tests/hostile.sh's
 * union-doublings scenes). */
#define HIERARCHY_BYTES_PER_POLYGON 96.0

/* What each union counted (a union is what copies share): its bytes and
 * polygons at the index the map gives it. */
struct WorldEstimate {
    PtrMap counted;
    double *bytes, *polygons;
    int n, cap;
};

WorldEstimate *world_estimate_new(void)
{
    return calloc(1, sizeof(WorldEstimate));
}

void world_estimate_free(WorldEstimate *e)
{
    if (e) {
        ptr_map_free(&e->counted);
        free(e->bytes);
        free(e->polygons);
    }
    free(e);
}

static int remember(WorldEstimate *e, const SceneObject *o, double bytes, double polygons)
{
    if (e->n == e->cap) {
        int cap = e->cap ? 2 * e->cap : 256;
        double *nb = realloc(e->bytes, sizeof *nb * (size_t)cap);
        if (!nb)
            return -1;
        e->bytes = nb;
        double *np = realloc(e->polygons, sizeof *np * (size_t)cap);
        if (!np)
            return -1;
        e->polygons = np;
        e->cap = cap;
    }
    if (ptr_map_put(&e->counted, o, e->n))
        return -1;
    e->bytes[e->n] = bytes;
    e->polygons[e->n] = polygons;
    e->n++;
    return 0;
}

/* One object that is no union: what flatten_object and the flatten_* of
 * its kind add (a material, then the kind's polygons and their lists). */
static void leaf(const SceneObject *o, double *bytes, double *polygons)
{
    const double poly = sizeof(Polygon), vec = sizeof(Vec3);
    double n = 0.0, b = sizeof(Material);
    switch (o->kind) {
    case OBJ_POLYGON:
        n = 1.0;
        b += poly + vec * o->u.polygon.npoints + (sizeof(int) + sizeof(OutlineBox)) * (o->u.polygon.noutlines + 1.0);
        break;
    case OBJ_TRIANGLE:
        n = 1.0;
        b += poly + 3.0 * vec * (o->u.triangle.has_normals ? 2.0 : 1.0);
        break;
    case OBJ_MESH:
        n = o->u.mesh.nfaces;
        b += sizeof(Material) * (double)o->u.mesh.ntextures +
             n * (poly + 3.0 * vec * (1.0 + (o->u.mesh.nnormals > 0) + (o->u.mesh.nuvs > 0)));
        break;
    case OBJ_BOX:
        n = 6.0;
        b += 6.0 * (poly + 4.0 * vec + 2.0 * sizeof(int));
        break;
    case OBJ_PLANE:
        b += sizeof(InfinitePlane);
        break;
    case OBJ_SPHERE:
    case OBJ_DISC:
    case OBJ_CONE:
    case OBJ_TORUS:
    case OBJ_QUADRIC:
    case OBJ_POLY:
    case OBJ_SUPERELLIPSOID:
    case OBJ_LATHE:
    case OBJ_SOR:
    case OBJ_PRISM:
    case OBJ_GLYPH:
    case OBJ_BLOB:
        b += sizeof(Shape) + HIERARCHY_BYTES_PER_POLYGON; /* an item of the shapes' own hierarchy */
        break;
    case OBJ_UNION:
    case OBJ_INTERSECTION:
    case OBJ_DIFFERENCE:
    case OBJ_MERGE:
        break;
    case OBJ_HEIGHT_FIELD: case OBJ_BICUBIC_PATCH: {
        double points = 0.0;
        if (o->kind == OBJ_HEIGHT_FIELD)
            height_field_count(o, &n, &points);
        else
            bicubic_patch_count(o, &n, &points);
        b += n * (poly + 2.0 * sizeof(int) + sizeof(OutlineBox)) + points * vec;
        break;
    }
    }
    *bytes = b + n * HIERARCHY_BYTES_PER_POLYGON;
    *polygons = n;
}

int world_estimate_object(WorldEstimate *e, const SceneObject *o, double *bytes, double *polygons)
{
    int k = ptr_map_get(&e->counted, o);
    if (k >= 0) {
        *bytes = e->bytes[k];
        *polygons = e->polygons[k];
        return 0;
    }
    double b = 0.0, n = 0.0;
    if (scene_object_has_children(o->kind)) {
        /* the parser keeps unions 200 levels deep at most (SceneObject.depth) */
        for (int i = 0; i < o->u.csg.nchildren; i++) {
            double cb, cn;
            if (world_estimate_object(e, o->u.csg.children[i], &cb, &cn))
                return -1;
            b += cb;
            n += cn;
        }
    } else {
        leaf(o, &b, &n);
    }
    if (o->kind != OBJ_UNION && scene_object_has_children(o->kind))
        b += sizeof(Shape) + sizeof(Material) + HIERARCHY_BYTES_PER_POLYGON; /* the CSG object's own node */
    for (int i = 0; i < o->nclips; i++) { /* clipped_by: its solids, and a node over them */
        double cb, cn;
        if (world_estimate_object(e, o->clips[i], &cb, &cn))
            return -1;
        b += cb + sizeof(Shape) + sizeof(Material);
    }
    *bytes = b;
    *polygons = n;
    /* a union is what copies share; an object of another kind costs no more to count again */
    return scene_object_has_children(o->kind) ? remember(e, o, b, n) : 0;
}
