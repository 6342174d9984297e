/* The bounding box POV-Ray keeps on an object (ObjectBase::BBox), which
 * min_extent and max_extent report: a corner and lengths in single
 * precision (BBOX_VAL), made from a minimum and maximum by
 * Make_BBox_from_min_max and carried through each transform by
 * Recompute_BBox (bbox.cpp): the box around its eight corners moved, held
 * within BOUND_HUGE. Written anew from reading them. */
#include "grammar.h"

#define BOUND_HUGE 2.0e10 /* POV-Ray's BOUND_HUGE */

void gram_extent_from_min_max(SceneObject *o, const double min[3], const double max[3])
{
    for (int i = 0; i < 3; i++) {
        o->extent_lower[i] = (float)min[i];
        o->extent_lengths[i] = (float)(max[i] - min[i]);
    }
    o->has_extent = 1;
}

void gram_extent_min_max(const SceneObject *o, double min[3], double max[3])
{
    for (int i = 0; i < 3; i++) {
        min[i] = o->extent_lower[i];
        max[i] = min[i] + o->extent_lengths[i];
    }
}

void gram_extent_transform(SceneObject *o, const Transform *t)
{
    if (!o->has_extent)
        return;
    double mins[3] = { BOUND_HUGE, BOUND_HUGE, BOUND_HUGE }, maxs[3] = { -BOUND_HUGE, -BOUND_HUGE, -BOUND_HUGE };
    for (int k = 1; k <= 8; k++) {
        Vec3 c = v3(o->extent_lower[0], o->extent_lower[1], o->extent_lower[2]);
        c.x += (k & 1) ? (double)o->extent_lengths[0] : 0.0;
        c.y += (k & 2) ? (double)o->extent_lengths[1] : 0.0;
        c.z += (k & 4) ? (double)o->extent_lengths[2] : 0.0;
        c = transform_point(t, c);
        const double v[3] = { c.x, c.y, c.z };
        for (int i = 0; i < 3; i++) {
            if (v[i] < mins[i])
                mins[i] = v[i];
            if (v[i] > maxs[i])
                maxs[i] = v[i];
        }
    }
    for (int i = 0; i < 3; i++) {
        if (mins[i] < -BOUND_HUGE / 2)
            mins[i] = -BOUND_HUGE / 2;
        if (maxs[i] > BOUND_HUGE / 2)
            maxs[i] = BOUND_HUGE / 2;
    }
    gram_extent_from_min_max(o, mins, maxs);
}
