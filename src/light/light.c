/* What every shadow method asks of a light (light.h). */
#include "light.h"

int light_side_of(const Polygon *p, const Light *l, double tol)
{
    if (l->kind == LIGHT_PARALLEL) {
        /* A direction: edge-on when within about 1e-12 rad of the plane. */
        double s = v3_dot(p->normal, l->direction);
        return s > 1e-12 ? 1 : s < -1e-12 ? -1 : 0;
    }
    double s = v3_dot(p->normal, l->location) - p->d;
    return s > tol ? 1 : s < -tol ? -1 : 0;
}
