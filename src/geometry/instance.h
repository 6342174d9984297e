/* Instances: a mesh placed many times (an LDraw part, a copied declared
 * object) is kept once, as a prototype in its own space, and each
 * placement is an instance (world.h). A polygon is named by one id:
 * 0 .. npolygons - 1 the world's own polygons, then each instance's
 * polygons in turn (Instance.first_id + k for its prototype's polygon k),
 * up to World.nids. Hits, the shadow ray's blockers and its own surface
 * carry ids, so a cache or an exclusion names an instance's polygon as it
 * names a world polygon.
 *
 * A ray meets an instance's polygons in the prototype's space: its origin
 * and direction carried there by the inverse transform (instance_ray), the
 * same t on both sides (the map is affine and the direction is not
 * normalised), tested by the polygon tests of intersect.h. Every query that
 * meets an instance's polygon (the hierarchy's walks, the cache's one
 * polygon) makes the local ray by instance_ray alone, so they all meet it
 * at the same t, bit for bit: their decisions stay the shadow ray's. */
#ifndef HST_INSTANCE_H
#define HST_INSTANCE_H

#include <stdint.h>

#include "world.h"

/* The instance holding polygon id `id` (>= npolygons), by bisection over
 * the instances' first ids (ascending). */
static inline int instance_of_id(const World *w, int id)
{
    int lo = 0, hi = w->ninstances - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (w->instances[mid].first_id <= id)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/* Whether instance i holds polygon id. */
static inline int instance_holds(const World *w, int i, int id)
{
    return i >= 0 && i < w->ninstances && id >= w->instances[i].first_id &&
           id < w->instances[i].first_id + w->prototypes[w->instances[i].prototype].npolygons;
}

/* The polygon record of id (an instance's: its prototype's, in the
 * prototype's space), and its instance (-1: a world polygon). `hint`: an
 * instance that may hold it (a walk's, a hit's), tried before the search;
 * anything else (-1) is fine. */
static inline const Polygon *world_polygon_hinted(const World *w, int id, int hint, int *instance)
{
    if (id < w->npolygons) {
        *instance = -1;
        return &w->polygons[id];
    }
    int i = instance_holds(w, hint, id) ? hint : instance_of_id(w, id);
    const Instance *in = &w->instances[i];
    *instance = i;
    return &w->polygons[w->prototypes[in->prototype].first_polygon + (id - in->first_id)];
}

static inline const Polygon *world_polygon_of_id(const World *w, int id, int *instance)
{
    return world_polygon_hinted(w, id, -1, instance);
}

/* The id of an instance's prototype polygon pi (an index in World.polygons). */
static inline int instance_polygon_id(const World *w, const Instance *in, uint32_t pi)
{
    return in->first_id + (int)(pi - (uint32_t)w->prototypes[in->prototype].first_polygon);
}

/* The world material of an instance's polygon. */
static inline int instance_material(const World *w, const Instance *in, const Polygon *p)
{
    return w->instance_materials[in->first_material + p->material];
}

/* The material of polygon id; `hint` as world_polygon_hinted's. */
static inline int world_polygon_material_hinted(const World *w, int id, int hint)
{
    if (id < w->npolygons)
        return w->polygons[id].material;
    int i;
    const Polygon *p = world_polygon_hinted(w, id, hint, &i);
    return instance_material(w, &w->instances[i], p);
}

static inline int world_polygon_material(const World *w, int id)
{
    return world_polygon_material_hinted(w, id, -1);
}

/* The polygon the uv coordinates of id's hits are read from, or -1: an
 * instance's materials read none (flatten.c instances no mesh whose
 * materials read uv). */
static inline int world_uv_polygon(const World *w, int id)
{
    return id < w->npolygons ? id : -1;
}

/* The ray org + t dir in the instance's space: the same t on both sides.
 * inverse_transform_point's and _direction's arithmetic, inline: every
 * walk that enters an instance makes it. */
static inline void instance_ray(const Instance *in, Vec3 org, Vec3 dir, Vec3 *lorg, Vec3 *ldir)
{
    const double(*m)[4] = in->to_world.inv;
    if (in->permutation) {
        /* a signed permutation: the products by 0 and 1 the matrix's
         * arithmetic would make add nothing (but the sign of a zero) */
        const double o[3] = { org.x, org.y, org.z }, d[3] = { dir.x, dir.y, dir.z };
        const int *a = in->axis;
        const double *s = in->sign;
        *lorg = v3(s[0] * o[a[0]] + m[3][0], s[1] * o[a[1]] + m[3][1], s[2] * o[a[2]] + m[3][2]);
        *ldir = v3(s[0] * d[a[0]], s[1] * d[a[1]], s[2] * d[a[2]]);
        return;
    }
    *lorg = v3(org.x * m[0][0] + org.y * m[1][0] + org.z * m[2][0] + m[3][0],
               org.x * m[0][1] + org.y * m[1][1] + org.z * m[2][1] + m[3][1],
               org.x * m[0][2] + org.y * m[1][2] + org.z * m[2][2] + m[3][2]);
    *ldir = v3(dir.x * m[0][0] + dir.y * m[1][0] + dir.z * m[2][0], dir.x * m[0][1] + dir.y * m[1][1] + dir.z * m[2][1],
               dir.x * m[0][2] + dir.y * m[1][2] + dir.z * m[2][2]);
}

/* The inverses of the components of ldir (instance_ray's direction of a
 * ray whose own direction has inverses winv): 1 / ldir, bit for bit. For
 * a signed permutation, ldir's components are the ray's, signed
 * (instance_ray), and 1 / (s d) is s (1 / d), zeros included: no division. */
static inline void instance_inverse_dir(const Instance *in, const double winv[3], Vec3 ldir, double linv[3])
{
    const double l[3] = { ldir.x, ldir.y, ldir.z };
    for (int i = 0; i < 3; i++)
        linv[i] = in->permutation ? in->sign[i] * winv[in->axis[i]] : 1.0 / l[i];
}

/* Polygon id's exact test against org + t dir (intersect_polygon's answer;
 * an instance's in its space, on instance_ray's ray); `hint` as
 * world_polygon_hinted's. */
double world_polygon_hit(const World *w, int id, int hint, Vec3 org, Vec3 dir);

/* Polygon id's plane in world space: for a world polygon the polygon
 * itself; for an instance's, *scratch with the normal and d carried to
 * world space (its other fields the prototype's: for plane tests only).
 * `hint` as world_polygon_hinted's. */
const Polygon *world_polygon_plane(const World *w, int id, int hint, Polygon *scratch);

/* The shading normal (smooth normals interpolated) of polygon id at the
 * world point x, in world space, unit; `hint` as world_polygon_hinted's. */
Vec3 world_polygon_shading_normal(const World *w, int id, int hint, Vec3 x);

#endif
