/* Counting what a flattening will make (world_estimate.h). */
#include "world_estimate.h"

#include <stdint.h>
#include <stdlib.h>

/* The hierarchy's build (bvh.c) per polygon: its primitive, packed copy and
 * share of the nodes, measured on unions of boxes (tests/hostile.sh's
 * union-doublings scenes). */
#define HIERARCHY_BYTES_PER_POLYGON 96.0

typedef struct {
    const SceneObject *key;
    double bytes, polygons;
} Slot;

struct WorldEstimate {
    Slot *slots;
    size_t nslots, used;
};

WorldEstimate *world_estimate_new(void)
{
    return calloc(1, sizeof(WorldEstimate));
}

void world_estimate_free(WorldEstimate *e)
{
    if (e)
        free(e->slots);
    free(e);
}

static size_t slot_of(const WorldEstimate *e, const SceneObject *o)
{
    uint64_t h = (uint64_t)(uintptr_t)o * 0x9E3779B97F4A7C15u;
    size_t j = (size_t)(h >> 17) & (e->nslots - 1);
    while (e->slots[j].key && e->slots[j].key != o)
        j = (j + 1) & (e->nslots - 1);
    return j;
}

static int remember(WorldEstimate *e, const SceneObject *o, double bytes, double polygons)
{
    if ((e->used + 1) * 2 > e->nslots) {
        size_t n = e->nslots ? e->nslots * 2 : 256;
        Slot *old = e->slots;
        size_t nold = e->nslots;
        e->slots = calloc(n, sizeof *e->slots);
        if (!e->slots) {
            e->slots = old;
            return -1;
        }
        e->nslots = n;
        for (size_t i = 0; i < nold; i++)
            if (old[i].key)
                e->slots[slot_of(e, old[i].key)] = old[i];
        free(old);
    }
    Slot *s = &e->slots[slot_of(e, o)];
    if (!s->key)
        e->used++;
    *s = (Slot){ o, bytes, polygons };
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
    case OBJ_UNION:
        break;
    }
    *bytes = b + n * HIERARCHY_BYTES_PER_POLYGON;
    *polygons = n;
}

int world_estimate_object(WorldEstimate *e, const SceneObject *o, double *bytes, double *polygons)
{
    if (e->nslots) {
        const Slot *s = &e->slots[slot_of(e, o)];
        if (s->key) {
            *bytes = s->bytes;
            *polygons = s->polygons;
            return 0;
        }
    }
    double b = 0.0, n = 0.0;
    if (o->kind == OBJ_UNION) {
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
    *bytes = b;
    *polygons = n;
    /* a union is what copies share; an object of another kind costs no more to count again */
    return o->kind == OBJ_UNION ? remember(e, o, b, n) : 0;
}
