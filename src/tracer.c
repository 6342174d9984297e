/* Nearest-hit queries through the grid, and the planes beside it. */
#include "tracer.h"

#include <stdlib.h>
#include <string.h>

#include "intersect.h"

int trace_context_init(TraceContext *ctx, const World *w, const Grid *g, const struct ShadowMethod *shadow, Quality q)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->world = w;
    ctx->grid = g;
    ctx->shadow = shadow;
    ctx->quality = q;
    ctx->stamp = calloc((size_t)(w->npolygons > 0 ? w->npolygons : 1), sizeof(uint32_t));
    return ctx->stamp ? 0 : -1;
}

void trace_context_free(TraceContext *ctx)
{
    free(ctx->stamp);
    ctx->stamp = NULL;
}

int trace_nearest(TraceContext *ctx, Vec3 org, Vec3 dir, double tmax, const Hit *from, Hit *hit)
{
    const World *w = ctx->world;
    const Grid *g = ctx->grid;
    double tmin = trace_min_distance(org);
    hit->kind = HIT_NONE;

    /* Planes first: they bound the grid walk, and on an exact tie (a box
     * resting on a plane) the plane wins, as it does in POV-Ray, whose
     * bounding tree meets the infinite plane before the finite object. */
    double plane_t = tmax;
    int plane = -1;
    for (int i = 0; i < w->nplanes; i++) {
        if (from && from->kind == HIT_PLANE && from->index == i)
            continue;
        ctx->stats.plane_tests++;
        double t = intersect_plane(&w->planes[i], org, dir);
        if (t > tmin && t < plane_t) {
            plane_t = t;
            plane = i;
        }
    }

    double best = HUGE_VAL;
    GridWalk walk;
    if (w->npolygons > 0 && grid_walk_begin(g, org, dir, 0.0, plane_t, &walk)) {
        uint32_t id = trace_new_segment(ctx);
        int exclude = (from && from->kind == HIT_POLYGON) ? from->index : -1;
        if (exclude >= 0)
            ctx->stamp[exclude] = id;
        do {
            ctx->stats.cells_visited++;
            int c = grid_cell_index(g, walk.cell);
            for (uint32_t k = g->cell_start[c]; k < g->cell_start[c + 1]; k++) {
                uint32_t pi = g->items[k];
                if (!bucket_admit(ctx, id, pi))
                    continue;
                ctx->stats.polygon_tests++;
                double t = intersect_polygon(w, &w->polygons[pi], org, dir);
                if (t > tmin && t < best && t < plane_t) {
                    best = t;
                    hit->kind = HIT_POLYGON;
                    hit->index = (int)pi;
                }
            }
            /* A hit inside this cell cannot be beaten by later cells. */
            if (best <= grid_walk_exit(&walk))
                break;
            if (best < walk.t_end)
                walk.t_end = best;
        } while (grid_walk_next(g, &walk));
    }
    if (hit->kind == HIT_NONE) {
        if (plane < 0)
            return 0;
        hit->kind = HIT_PLANE;
        hit->index = plane;
        best = plane_t;
    } else {
        ctx->stats.polygon_hits++;
    }
    hit->t = best;
    hit->point = v3_madd(org, dir, best);
    return 1;
}
