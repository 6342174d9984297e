/* Instances' polygons seen from world space (instance.h). */
#include "instance.h"

#include "intersect.h"

double world_polygon_hit(const World *w, int id, int hint, Vec3 org, Vec3 dir)
{
    int i;
    const Polygon *p = world_polygon_hinted(w, id, hint, &i);
    if (i < 0)
        return intersect_polygon(w, p, org, dir);
    Vec3 lorg, ldir;
    instance_ray(&w->instances[i], org, dir, &lorg, &ldir);
    return intersect_polygon(w, p, lorg, ldir);
}

const Polygon *world_polygon_plane(const World *w, int id, int hint, Polygon *scratch)
{
    int i;
    const Polygon *p = world_polygon_hinted(w, id, hint, &i);
    if (i < 0)
        return p;
    /* transform_normal's and transform_point's arithmetic, inline: a
     * shadow ray asks this of every polygon it meets */
    const double(*inv)[4] = w->instances[i].to_world.inv, (*m)[4] = w->instances[i].to_world.m;
    const Vec3 n = p->normal, q = w->points[p->first_point];
    *scratch = *p;
    scratch->normal = v3_normalize(v3(n.x * inv[0][0] + n.y * inv[0][1] + n.z * inv[0][2],
                                      n.x * inv[1][0] + n.y * inv[1][1] + n.z * inv[1][2],
                                      n.x * inv[2][0] + n.y * inv[2][1] + n.z * inv[2][2]));
    scratch->d = v3_dot(scratch->normal, v3(q.x * m[0][0] + q.y * m[1][0] + q.z * m[2][0] + m[3][0],
                                            q.x * m[0][1] + q.y * m[1][1] + q.z * m[2][1] + m[3][1],
                                            q.x * m[0][2] + q.y * m[1][2] + q.z * m[2][2] + m[3][2]));
    return scratch;
}

Vec3 world_polygon_shading_normal(const World *w, int id, int hint, Vec3 x)
{
    int i;
    const Polygon *p = world_polygon_hinted(w, id, hint, &i);
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
