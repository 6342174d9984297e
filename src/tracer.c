/* Nearest-hit queries through the grid, and the planes beside it. */
#include "tracer.h"

#include <stdlib.h>
#include <string.h>

#include "intersect.h"
#include "shadow.h"
#include "shadow_volumes.h"

/* Enough for max_trace_level reflections plus continued (same-ior) rays;
 * deeper points keep no state and their methods use the shadow ray. */
#define STATE_DEPTH 64

int trace_context_init(TraceContext *ctx, const World *w, const Grid *g, const struct ShadowMethod *shadow, Quality q,
                       const ShadowVolumes *volumes)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->world = w;
    ctx->grid = g;
    ctx->shadow = shadow;
    ctx->quality = q;
    ctx->last_blocker = -1;
    ctx->stamp = calloc((size_t)(w->npolygons > 0 ? w->npolygons : 1), sizeof(uint32_t));
    int nl = w->nlights > 0 ? w->nlights : 1;
    ctx->light_cache = malloc(sizeof(int) * (size_t)nl);
    if (!ctx->stamp || !ctx->light_cache)
        return -1;
    for (int i = 0; i < nl; i++)
        ctx->light_cache[i] = -1;
    if (volumes) {
        ctx->volumes = volumes;
        ctx->sp_stamp = calloc((size_t)(volumes->npolygons > 0 ? volumes->npolygons : 1), sizeof(uint32_t));
        ctx->bucket = calloc((size_t)nl, sizeof *ctx->bucket);
        ctx->bucket_n = calloc((size_t)nl, sizeof *ctx->bucket_n);
        ctx->states = calloc((size_t)nl * STATE_DEPTH, sizeof(LightState));
        if (!ctx->sp_stamp || !ctx->bucket || !ctx->bucket_n || !ctx->states)
            return -1;
        ctx->state_capacity = STATE_DEPTH;
        for (int i = 0; i < w->nlights; i++) {
            int n = volumes->light[i].count;
            ctx->bucket[i] = malloc(sizeof(uint32_t) * (size_t)(n > 0 ? n : 1));
            if (!ctx->bucket[i])
                return -1;
        }
    }
    return 0;
}

void trace_context_free(TraceContext *ctx)
{
    free(ctx->stamp);
    free(ctx->light_cache);
    if (ctx->bucket)
        for (int i = 0; i < ctx->world->nlights; i++)
            free(ctx->bucket[i]);
    free(ctx->bucket);
    free(ctx->bucket_n);
    free(ctx->sp_stamp);
    free(ctx->states);
    ctx->stamp = NULL;
    ctx->light_cache = NULL;
    ctx->bucket = NULL;
    ctx->bucket_n = NULL;
    ctx->sp_stamp = NULL;
    ctx->states = NULL;
}

/* The segment's shadow bucket: every shadow polygon registered in cell c,
 * per light, added once. */
static void gather_shadow_polygons(TraceContext *ctx, int c)
{
    const ShadowVolumes *sv = ctx->volumes;
    for (int li = 0; li < sv->nlights; li++) {
        const LightVolumes *lv = &sv->light[li];
        if (!lv->cell_start)
            continue;
        uint32_t k0 = lv->cell_start[c], k1 = lv->cell_start[c + 1];
        for (uint32_t k = k0; k < k1; k++) {
            uint32_t s = lv->items[k];
            if (ctx->sp_stamp[s] == ctx->sp_id)
                continue;
            ctx->sp_stamp[s] = ctx->sp_id;
            ctx->bucket[li][ctx->bucket_n[li]++] = s;
            ctx->stats.shadow_bucket_polygons++;
        }
    }
}

static void begin_shadow_bucket(TraceContext *ctx)
{
    if (++ctx->sp_id == 0) {
        for (int i = 0; i < ctx->volumes->npolygons; i++)
            ctx->sp_stamp[i] = 0;
        ctx->sp_id = 1;
    }
    for (int li = 0; li < ctx->world->nlights; li++)
        ctx->bucket_n[li] = 0;
    ctx->segment_in_box = 0;
}

static int inside_box(const ShadowVolumes *sv, Vec3 p)
{
    return p.x >= sv->box_min.x && p.x <= sv->box_max.x && p.y >= sv->box_min.y && p.y <= sv->box_max.y &&
           p.z >= sv->box_min.z && p.z <= sv->box_max.z;
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
    int gather = ctx->volumes != NULL;
    if (gather)
        begin_shadow_bucket(ctx);
    if ((w->npolygons > 0 || gather) && grid_walk_begin(g, org, dir, 0.0, plane_t, &walk)) {
        uint32_t id = trace_new_segment(ctx);
        int exclude = (from && from->kind == HIT_POLYGON) ? from->index : -1;
        if (exclude >= 0)
            ctx->stamp[exclude] = id;
        do {
            ctx->stats.cells_visited++;
            int c = grid_cell_index(g, walk.cell);
            if (gather)
                gather_shadow_polygons(ctx, c);
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
    /* The walk covered the whole segment only when its end is in the box. */
    if (gather)
        ctx->segment_in_box = inside_box(ctx->volumes, hit->point) && inside_box(ctx->volumes, org);
    return 1;
}
