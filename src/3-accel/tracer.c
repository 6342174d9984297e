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
        int most = 1;
        for (int i = 0; i < volumes->nlights; i++)
            if (volumes->light[i].count > most)
                most = volumes->light[i].count;
        ctx->sp_stamp = calloc((size_t)(volumes->npolygons > 0 ? volumes->npolygons : 1), sizeof(uint32_t));
        ctx->bucket = malloc(sizeof(uint32_t) * (size_t)most);
        /* A 3DDDA walk visits at most one cell per boundary crossed. */
        ctx->segment_cells_cap = g->n[0] + g->n[1] + g->n[2] + 3;
        ctx->segment_cells = malloc(sizeof(uint32_t) * (size_t)ctx->segment_cells_cap);
        ctx->states = calloc((size_t)nl * STATE_DEPTH, sizeof(LightState));
        if (!ctx->sp_stamp || !ctx->bucket || !ctx->segment_cells || !ctx->states)
            return -1;
        ctx->state_capacity = STATE_DEPTH;
    }
    return 0;
}

void trace_context_free(TraceContext *ctx)
{
    free(ctx->stamp);
    free(ctx->light_cache);
    free(ctx->bucket);
    free(ctx->segment_cells);
    free(ctx->sp_stamp);
    free(ctx->states);
    ctx->stamp = NULL;
    ctx->light_cache = NULL;
    ctx->bucket = NULL;
    ctx->segment_cells = NULL;
    ctx->sp_stamp = NULL;
    ctx->states = NULL;
}

int trace_fill_shadow_bucket(TraceContext *ctx, int light, int limit)
{
    return trace_fill_shadow_bucket_in(ctx, light, ctx->segment_cells, ctx->segment_ncells, limit);
}

uint32_t trace_shadow_registrations(const TraceContext *ctx, int light)
{
    return trace_shadow_registrations_in(ctx, light, ctx->segment_cells, ctx->segment_ncells);
}

int trace_fill_shadow_bucket_in(TraceContext *ctx, int light, const uint32_t *cells, int ncells, int limit)
{
    const LightVolumes *lv = &ctx->volumes->light[light];
    if (!lv->cell_start)
        return 0;
    uint32_t id = stamp_next(ctx->sp_stamp, ctx->volumes->npolygons, &ctx->sp_id);
    int n = 0;
    for (int k = 0; k < ncells; k++) {
        uint32_t c = cells[k];
        for (uint32_t j = lv->cell_start[c]; j < lv->cell_start[c + 1]; j++) {
            uint32_t s = lv->items[j];
            if (ctx->sp_stamp[s] == id)
                continue;
            ctx->sp_stamp[s] = id;
            ctx->bucket[n++] = s;
        }
        if (n > limit)
            break; /* too many to count: the caller fires the shadow ray */
    }
    ctx->stats.shadow_bucket_polygons += (uint64_t)n;
    return n;
}

uint32_t trace_shadow_registrations_in(const TraceContext *ctx, int light, const uint32_t *cells, int ncells)
{
    const LightVolumes *lv = &ctx->volumes->light[light];
    if (!lv->cell_start)
        return 0;
    uint32_t n = 0;
    for (int k = 0; k < ncells; k++) {
        uint32_t c = cells[k];
        n += lv->cell_start[c + 1] - lv->cell_start[c];
    }
    return n;
}

/* The uncached part of trace_point_touches_other. */
static int touches_other(TraceContext *ctx, const Hit *hit, double tol)
{
    const World *w = ctx->world;
    const Grid *g = ctx->grid;
    if (hit->kind == HIT_POLYGON && polygon_classify_point(w, &w->polygons[hit->index], hit->point, tol) < 0)
        return 1; /* on its own polygon's border: on the neighbours' too */
    /* Every cell within tol of the point (usually one). */
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = grid_cell_coord(g, v3_comp(hit->point, a) - tol, a);
        hi[a] = grid_cell_coord(g, v3_comp(hit->point, a) + tol, a);
    }
    uint32_t id = trace_new_segment(ctx);
    if (hit->kind == HIT_POLYGON)
        ctx->stamp[hit->index] = id;
    for (int z = lo[2]; z <= hi[2]; z++)
        for (int y = lo[1]; y <= hi[1]; y++)
            for (int x = lo[0]; x <= hi[0]; x++) {
                int c[3] = { x, y, z };
                int ci = grid_cell_index(g, c);
                for (uint32_t k = g->cell_start[ci]; k < g->cell_start[ci + 1]; k++) {
                    uint32_t pi = g->items[k];
                    if (!bucket_admit(ctx, id, pi))
                        continue;
                    const Polygon *p = &w->polygons[pi];
                    if (fabs(v3_dot(p->normal, hit->point) - p->d) <= tol && polygon_classify_point(w, p, hit->point, tol) != 0)
                        return 1;
                }
            }
    return 0;
}

int trace_point_touches_other(TraceContext *ctx, const Hit *hit, double tol)
{
    if (ctx->touch_valid && ctx->touch_kind == (int)hit->kind && ctx->touch_index == hit->index &&
        ctx->touch_point.x == hit->point.x && ctx->touch_point.y == hit->point.y && ctx->touch_point.z == hit->point.z)
        return ctx->touch_result;
    ctx->touch_valid = 1;
    ctx->touch_kind = (int)hit->kind;
    ctx->touch_index = hit->index;
    ctx->touch_point = hit->point;
    ctx->touch_result = touches_other(ctx, hit, tol);
    return ctx->touch_result;
}

static int inside_box(const ShadowVolumes *sv, Vec3 p)
{
    return p.x >= sv->box_min.x && p.x <= sv->box_max.x && p.y >= sv->box_min.y && p.y <= sv->box_max.y &&
           p.z >= sv->box_min.z && p.z <= sv->box_max.z;
}

static int material_hidden(const Material *m, unsigned hide)
{
    return ((hide & HIDE_NO_IMAGE) && m->no_image) || ((hide & HIDE_NO_REFLECTION) && m->no_reflection);
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
        if (ctx->hide && material_hidden(&w->materials[w->planes[i].material], ctx->hide))
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
    int gather = ctx->volumes != NULL, overflow = 0;
    if (gather)
        ctx->segment_ncells = 0;
    if ((w->npolygons > 0 || gather) && grid_walk_begin(g, org, dir, 0.0, plane_t, &walk)) {
        uint32_t id = trace_new_segment(ctx);
        RayFrame frame = ray_frame(org, dir);
        int exclude = (from && from->kind == HIT_POLYGON) ? from->index : -1;
        if (exclude >= 0)
            ctx->stamp[exclude] = id;
        do {
            ctx->stats.cells_visited++;
            int c = grid_cell_index(g, walk.cell);
            if (gather) {
                if (ctx->segment_ncells < ctx->segment_cells_cap)
                    ctx->segment_cells[ctx->segment_ncells++] = (uint32_t)c;
                else
                    overflow = 1; /* cannot happen with 3DDDA; distrust the bucket if it did */
            }
            for (uint32_t k = g->cell_start[c]; k < g->cell_start[c + 1]; k++) {
                uint32_t pi = g->items[k];
                if (!bucket_admit(ctx, id, pi))
                    continue;
                if (ctx->hide && material_hidden(&w->materials[w->polygons[pi].material], ctx->hide))
                    continue;
                ctx->stats.polygon_tests++;
                /* Only hits before the best so far are looked at. */
                double t = intersect_polygon_in(w, &w->polygons[pi], &frame, best < plane_t ? best : plane_t);
                if (t > tmin) {
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
        ctx->segment_in_box = !overflow && inside_box(ctx->volumes, hit->point) && inside_box(ctx->volumes, org);
    return 1;
}
