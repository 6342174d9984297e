/* --shadows light-buffer: each point light's light buffer (light_buffer.h)
 * decides its shadows; what it cannot (area lights' samples, parallel
 * lights, a cell the memory budget left unbuilt) the shadow ray with the
 * light's last blocker tried first decides, as the cache method does. Its
 * decisions are the shadow ray's, exactly: lit where no candidate is
 * nearer the light than the point, shadow where a proved cover is, else
 * the shadow ray's own polygon test against the candidates the point's
 * side of their planes does not rule out.
 *
 * hst hands its point lights' decisions here where no volumes pay
 * (shadow_hst_prepare.c): the light buffer is hst's sub-scheme in light
 * space. */
#include "shadow.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "light_buffer.h"

/* The cells' memory. */
#define LB_BUDGET_DEFAULT ((size_t)256 << 20)

/* The light's buffer for q, or NULL: q is an area light's sample (its
 * source is not the light itself) or the light has none. */
static LightBuffer *buffer_for(const ShadowContext *ctx, const ShadowQuery *q)
{
    const LightBuffers *lbs = ctx->light_buffers;
    if (!lbs || !lbs->light[q->light] || q->source != &ctx->tracer->world->lights[q->light])
        return NULL;
    return lbs->light[q->light];
}

/* Time spent building cells, counted whole rather than sampled (shadow_decide.h). */
static void count_build(ShadowContext *ctx, double seconds)
{
    if (seconds > 0.0) {
        ctx->stats.light_buffer_build_ns += (uint64_t)(seconds * 1e9);
        ctx->stats.shadow_seconds += seconds;
        ctx->untimed_seconds += seconds;
    }
}

/* Does the remembered cell m hold spot, and is it still the buffer's cell
 * there? (a split cell is remembered only where the budget left its child
 * unbuilt: it is looked up again) */
static inline int memo_holds(const LbMemo *m, const LbSpot *spot)
{
    if (!m->cell || m->face != spot->face)
        return 0;
    int shift = 2 * (LB_LEVELS - 1 - m->cell->level);
    return (spot->iu >> shift) == m->i && (spot->iv >> shift) == m->j && !m->cell->child;
}

/* The cell at spot: one of the thread's last ones for the light while it
 * still holds the spot (neighbouring points mostly share a cell), else
 * the buffer's. */
static const LbCell *cell_at_spot(ShadowContext *ctx, LightBuffer *lb, const ShadowQuery *q, const LbSpot *spot)
{
    _Static_assert(LB_MEMO_CELLS == 2, "the last cell and the one before");
    LbMemo *m = &ctx->light_buffer_memo[LB_MEMO_CELLS * (2 * q->light + shadow_query_secondary(q))];
    if (memo_holds(&m[0], spot))
        return m[0].cell;
    if (memo_holds(&m[1], spot)) {
        LbMemo x = m[1];
        m[1] = m[0];
        m[0] = x;
        return x.cell;
    }
    double built;
    const LbCell *c = light_buffer_cell(ctx->light_buffers, lb, spot, &built);
    count_build(ctx, built);
    if (c) {
        int shift = 2 * (LB_LEVELS - 1 - c->level);
        m[1] = m[0];
        m[0] = (LbMemo){ c, spot->face, spot->iu >> shift, spot->iv >> shift };
    }
    return c;
}

/* The infinite planes' part of q's decision (shadow_planes_test's
 * answer, exactly) for a point light with a buffer: an opaque plane the
 * light is clear of blocks the shadow ray where the point lies on its
 * other side. The shadow ray computes t = (d - n.P) / (n.D) and asks
 * tmin < t < dist. Where the point and the light are on opposite sides,
 * exactly, t = dist |s_P| / (|s_P| + |s_L|) (s: signed distances from the
 * plane), and dist >= |s_P| + |s_L|: t is at least |s_P| past the point
 * and at least |s_L| short of the light; on one side, t < 0 (the point
 * nearer the plane) or t - dist = dist |s_L| / (|s_P| - |s_L|) >= |s_L|.
 * With |n.D| >= 1e-6, the computed t's relative error is below 1e-9 (the
 * dot products' rounding, some 2^-52, over 1e-6), and its absolute error
 * from n.P's below 1e-10 (|P| + |d|); |s_P| >= 1e-6 (1 + |P| + |d|) and
 * |s_L| >= 1e-6 (|s_P| + dist) keep every end of the segment (tmin is
 * 1e-9 (1 + |P|)) far beyond those errors: the side test gives the shadow
 * ray's answer. Elsewhere, and for planes without a side
 * (LightBuffer.plane_side), the shadow ray's own plane test decides. */
static int buffer_planes_test(ShadowContext *ctx, const LightBuffer *lb, const ShadowQuery *q, RGB *light)
{
    const World *w = ctx->tracer->world;
    for (int i = 0; i < w->nplanes; i++) {
        /* the point's own plane, which shadow_plane_test passes over */
        if (q->surface->kind == HIT_PLANE && q->surface->index == i)
            continue;
        double s_light = lb->plane_side[i];
        if (s_light != 0.0) {
            const InfinitePlane *pl = &w->planes[i];
            double num = pl->d - v3_dot(pl->normal, q->point);
            double cosine = v3_dot(pl->normal, q->to_light);
            if (fabs(cosine) >= 1e-6 && fabs(num) >= 1e-6 * (1.0 + v3_max_abs(q->point) + fabs(pl->d)) &&
                fabs(s_light) >= 1e-6 * (fabs(num) + q->distance)) {
                /* num is -s_P: opposite sides where it has s_L's sign */
                if ((num > 0.0) == (s_light > 0.0)) {
                    light->r = light->g = light->b = 0.0;
                    return 1;
                }
                continue;
            }
        }
        if (shadow_plane_test(ctx, q, i, trace_min_distance(q->point), light))
            return 1;
    }
    return 0;
}

/* Where q falls in its light's buffer lb (NULL: none): the spot and its
 * cell (NULL: none, the shadow ray decides). */
typedef struct {
    LbSpot spot;
    const LbCell *cell;
} BufferPlace;

static BufferPlace buffer_place(ShadowContext *ctx, LightBuffer *lb, const ShadowQuery *q)
{
    BufferPlace at = { { 0, 0, 0, 0.0, 0.0 }, NULL };
    if (lb && light_buffer_spot(v3_neg(q->to_light), &at.spot))
        at.cell = cell_at_spot(ctx, lb, q, &at.spot);
    return at;
}

/* The curved objects' part of q's decision (shadow_shapes_test's answer,
 * bit for bit) by its cell's list of them: every object the shadow ray
 * can cross is listed (light_buffer.h), so none listed nearer than the
 * point crossed means none crossed at all, and an opaque surface crossed
 * blocks the light whatever else the ray meets. See-through ones crossed,
 * and no opaque one, are folded in the order the shadow ray's walk folds
 * them (shadow_shape_fold); more of them than LB_FOLD_MAX, the walk
 * itself folds them. For a world with curved objects only (the caller
 * asks). */
#define LB_FOLD_MAX 16
static int buffer_objects_test(ShadowContext *ctx, const BufferPlace *at, const ShadowQuery *q, RGB *light)
{
    const LbCell *cell = at->cell;
    const LightBuffers *lbs = ctx->light_buffers;
    if (!cell || !lbs->bvh->shapes || v3_max_abs(q->point) > lbs->object_reach)
        return shadow_shapes_test(ctx, q, light);
    /* the near bounds are floats rounded down: the limit is rounded up */
    const float limit = (float)((q->distance * (1.0 + 1e-9) + lbs->margin) * (1.0 + 0x1p-22));
    const float u = (float)at->spot.u, v = (float)at->spot.v;
    /* the see-through ones crossed, by their rank; a sphere tested by the
     * fast test with its crossings (n > 0), which the fold need not find
     * again */
    struct {
        uint32_t shape;
        int n;
        double t[2];
    } fold[LB_FOLD_MAX];
    int nfold = 0, too_many = 0;
    ShadowSphereRay sr; /* made at its first sphere (no more set here: this runs at every decision) */
    sr.made = 0;
    sr.n = 0;
    for (uint32_t k = 0; k < cell->nobjects && cell->object[k].near <= limit; k++) {
        const LbObject *o = &cell->object[k];
        if (u < o->u0 || u > o->u1 || v < o->v0 || v > o->v1)
            continue;
        const Shape *s = &lbs->world->shapes[o->shape];
        ShapeCrossing c = shadow_sphere_fast(s) ? shadow_sphere_crossing(ctx, q, s, &sr)
                                                : shadow_shape_crossing(ctx, q, (int)o->shape, &sr);
        if (c == SHAPE_CROSSED_OPAQUE) {
            light->r = light->g = light->b = 0.0;
            return 1;
        }
        if (c == SHAPE_CROSSED_SEE_THROUGH) {
            if (nfold == LB_FOLD_MAX) {
                too_many = 1;
                continue;
            }
            /* insertion by rank */
            uint32_t r = lbs->object_rank[o->shape];
            int j = nfold++;
            for (; j > 0 && lbs->object_rank[fold[j - 1].shape] > r; j--)
                fold[j] = fold[j - 1];
            fold[j].shape = o->shape;
            fold[j].n = shadow_sphere_fast(&lbs->world->shapes[o->shape]) ? sr.n : 0;
            for (int h = 0; h < fold[j].n; h++)
                fold[j].t[h] = sr.t[h];
        }
    }
    if (too_many)
        return shadow_shapes_test(ctx, q, light);
    for (int j = 0; j < nfold; j++)
        if (fold[j].n > 0 ? shadow_sphere_fold(ctx, q, (int)fold[j].shape, fold[j].t, fold[j].n, light)
                          : shadow_shape_fold(ctx, q, (int)fold[j].shape, light))
            return 1;
    return 0;
}

/* q's decision at its place in the buffer (no cell: the cache's test),
 * planes and objects aside. */
static int buffer_polygons_test(ShadowContext *ctx, const BufferPlace *at, const ShadowQuery *q, RGB *light)
{
    const LbCell *cell = at->cell;
    const LbSpot spot = at->spot;
    if (!cell)
        return shadow_cache_polygons_test(ctx, q, light);
    LightBuffers *lbs = ctx->light_buffers;
    int own = q->surface->kind == HIT_POLYGON ? q->surface->index : -1;
    if (cell->cover >= 0 && q->distance > cell->cover_beyond && cell->cover != own) {
        light->r = light->g = light->b = 0.0;
        ctx->last_scheme = SCHEME_BUFFER_COVER;
        ctx->stats.shadow_schemes[SCHEME_BUFFER_COVER]++;
        ctx->stats.shadow_blocked++;
        return 1;
    }
    /* the candidates' near bounds are floats rounded down: the limit is
     * rounded up */
    const double limit_d = q->distance * (1.0 + 1e-9) + lbs->margin;
    const float limit = (float)(limit_d * (1.0 + 0x1p-22)); /* float's rounding is below 2^-24 */
    if (cell->n == 0 || !(cell->block[0].near[0] < limit)) {
        /* no candidate nearer the light than the point: lit at once, as
         * the walk below would find */
        ctx->last_scheme = SCHEME_BUFFER_LIT;
        ctx->stats.shadow_schemes[SCHEME_BUFFER_LIT]++;
        ctx->light_cache[q->light].lit_last = 1;
        return 0;
    }
    const LbPoint point = lb_point(q->point, q->distance);
    const float u = (float)spot.u, v = (float)spot.v;
    /* an instance's own polygon is left out by its instance's walk */
    const uint32_t own_item = own >= 0 && own < lbs->world->npolygons ? lbs->item_of[own] : UINT32_MAX;
    const uint32_t nblocks = (cell->n + LB_BLOCK - 1) / LB_BLOCK;
    uint32_t looked = 0, tests = 0;
    int blocked = 0, walking = 0, cache_hit = 0, crossed_opaque = 0;
    /* The candidates the point needs, by the blocks' footprints and near
     * bounds, its own polygon and the side of their planes, each tested as
     * it is found. */
    ShadowListWalk lw;
    const LbScan scan = lb_scan(limit, u, v, &point);
    for (uint32_t b = 0; b < nblocks && !blocked && cell->block[b].near[0] < limit; b++) {
        looked += LB_BLOCK;
        for (unsigned mask = lb_block_mask(cell, b, &scan); mask && !blocked; mask &= mask - 1) {
            uint32_t i = b * LB_BLOCK + (uint32_t)__builtin_ctz(mask);
            /* the point's own polygon: the shadow ray starts on it (passed over) */
            if (cell->item[i] == own_item)
                continue;
            const LbShape *shape = &cell->shapes[cell->shape_at[i]];
            int where = lb_shape_classify(shape, u, v);
            if (where == LB_OUTSIDE)
                continue;
            const LbPlane plane = lb_plane_at(cell, i);
            int crossed = where == LB_INSIDE && lb_candidate_crossed(&plane, &point, q->to_light, lbs->cover_margin);
            if (crossed && shape->opaque) {
                /* an opaque polygon proved crossed: no light */
                ctx->last_blocker = (int)lbs->bvh->items[cell->item[i]];
                crossed_opaque = blocked = 1;
                break;
            }
            if (!walking) {
                walking = 1;
                /* the light's last opaque blocker first (the cache method's
                 * rule), now that some candidate may block: neighbouring
                 * points in a shadow no cover proves are mostly blocked by
                 * one polygon */
                if (shadow_cached_blocker_hits(ctx, q)) {
                    cache_hit = blocked = 1;
                    break;
                }
                ctx->last_blocker = -1;
                shadow_list_begin(&lw, ctx, q);
                /* the cell lists no polygon edge-on to the light
                 * (gather_from_hierarchy asks the shadow ray's rule, of
                 * this light, which is q's source: buffer_for) */
                lw.sides_known = 1;
            }
            tests++;
            blocked = crossed ? shadow_list_meet_crossed(&lw, lbs->bvh->items[cell->item[i]])
                              : shadow_list_meet_item(&lw, lbs->bvh, cell->item[i]);
        }
    }
    if (blocked)
        light->r = light->g = light->b = 0.0;
    else if (walking)
        blocked = shadow_list_end(&lw, light);
    ctx->last_scheme = cache_hit ? SCHEME_CACHE_HIT : walking || crossed_opaque ? SCHEME_BUFFER_LIST : SCHEME_BUFFER_LIT;
    ctx->stats.shadow_schemes[ctx->last_scheme]++;
    ctx->stats.shadow_blocked += (uint64_t)blocked;
    if (blocked && !cache_hit)
        shadow_cache_remember(ctx, q, light);
    ctx->light_cache[q->light].lit_last = !blocked;
    ctx->stats.light_buffer_scanned += looked;
    ctx->stats.light_buffer_candidates += tests;
    return blocked;
}

/* shadow_planes_test's part by the buffer: the planes by their sides,
 * then, unless one blocks, the objects by q's cell (which *at is left
 * holding, for the polygons' part). */
static int buffer_surfaces_test(ShadowContext *ctx, LightBuffer *lb, const ShadowQuery *q, RGB *light,
                                BufferPlace *at)
{
    if (!lb) {
        *at = buffer_place(ctx, NULL, q);
        return shadow_planes_test(ctx, q, light);
    }
    if (buffer_planes_test(ctx, lb, q, light))
        return 1;
    *at = buffer_place(ctx, lb, q);
    /* (asked here, not in the test: a world without curved objects, most
     * polygon scenes, then makes no call at every decision) */
    return ctx->light_buffers->world->nshapes > 0 && buffer_objects_test(ctx, at, q, light);
}

static inline int buffer_decide(ShadowContext *ctx, const ShadowQuery *q, RGB *light, int *surfaces_blocked)
{
    BufferPlace at;
    *surfaces_blocked = buffer_surfaces_test(ctx, buffer_for(ctx, q), q, light, &at);
    return *surfaces_blocked || buffer_polygons_test(ctx, &at, q, light);
}

int shadow_light_buffer_decide(ShadowContext *ctx, const ShadowQuery *q, RGB *light, int *surfaces_blocked)
{
    return buffer_decide(ctx, q, light, surfaces_blocked);
}

/* The planes' and objects' part, then, unless they block, the buffer's
 * polygon part, which counts its own scheme. */
static void light_buffer_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    light->r = light->g = light->b = 1.0;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    int surfaces_blocked;
    if (buffer_decide(ctx, q, light, &surfaces_blocked) && surfaces_blocked) {
        ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
        ctx->stats.shadow_blocked++;
    }
}

int shadow_light_buffer_prepare(const ShadowMethod *self, const ShadowSetup *s, ShadowPrepared *out, char *err,
                                int errlen)
{
    (void)self;
    if (!s->shadows_on)
        return 0;
    out->light_buffers = calloc(1, sizeof *out->light_buffers);
    if (!out->light_buffers ||
        light_buffers_init(out->light_buffers, s->world, s->bvh, grid_tolerance(s->grid), LB_BUDGET_DEFAULT)) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    return 0;
}

const ShadowMethod shadow_light_buffer_method = {
    .name = "light-buffer",
    .summary = "each point light's light buffer (Haines and Greenberg 1986): a direction cube whose cells list "
               "the candidate occluders, built as points ask",
    .prepare = shadow_light_buffer_prepare,
    .test = light_buffer_test,
    .instances = 1,
};
