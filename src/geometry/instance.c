/* Instances' polygons seen from world space (instance.h). */
#include "instance.h"

#include "intersect.h"

double world_polygon_hit(const World *w, int id, Vec3 org, Vec3 dir)
{
    int i;
    const Polygon *p = world_polygon_of_id(w, id, &i);
    if (i < 0)
        return intersect_polygon(w, p, org, dir);
    Vec3 lorg, ldir;
    instance_ray(&w->instances[i], org, dir, &lorg, &ldir);
    return intersect_polygon(w, p, lorg, ldir);
}

const Polygon *world_polygon_plane(const World *w, int id, Polygon *scratch)
{
    int i;
    const Polygon *p = world_polygon_of_id(w, id, &i);
    if (i < 0)
        return p;
    const Transform *t = &w->instances[i].to_world;
    *scratch = *p;
    scratch->normal = v3_normalize(transform_normal(t, p->normal));
    scratch->d = v3_dot(scratch->normal, transform_point(t, w->points[p->first_point]));
    return scratch;
}

Vec3 world_polygon_shading_normal(const World *w, int id, Vec3 x)
{
    int i;
    const Polygon *p = world_polygon_of_id(w, id, &i);
    if (i < 0)
        return polygon_shading_normal(w, p, x);
    const Transform *t = &w->instances[i].to_world;
    if (p->smooth_normals < 0)
        return v3_normalize(transform_normal(t, p->normal));
    /* Interpolated in the prototype's space, then carried out (inverse
     * transpose) and made unit: what flattening, which carries each vertex
     * normal out before interpolating, gives up to rounding. */
    Vec3 local = polygon_shading_normal(w, p, inverse_transform_point(t, x));
    return v3_normalize(transform_normal(t, local));
}
