/* Pixel shadow coherence: see shadow_coherence.h. */
#include "shadow_coherence.h"

#include <stdlib.h>
#include <string.h>

#include "intersect.h"
#include "shadow_bucket.h"
#include "shadow_volumes.h"

int pixel_coherence_init(PixelCoherence *pc, const World *w, const Grid *g)
{
    memset(pc, 0, sizeof *pc);
    int nl = w->nlights > 0 ? w->nlights : 1;
    pc->nlights = w->nlights;
    pc->left.state = calloc((size_t)nl, sizeof(LightState));
    pc->row_first.state = calloc((size_t)nl, sizeof(LightState));
    pc->cells_cap = g->n[0] + g->n[1] + g->n[2] + 3; /* a 3DDDA walk's most */
    pc->cells = malloc(sizeof(uint32_t) * (size_t)pc->cells_cap);
    pc->meets_cap = 64;
    pc->meets = malloc(sizeof(PolygonMeet) * (size_t)pc->meets_cap);
    if (!pc->left.state || !pc->row_first.state || !pc->cells || !pc->meets)
        return -1;
    return 0;
}

void pixel_coherence_free(PixelCoherence *pc)
{
    free(pc->left.state);
    free(pc->row_first.state);
    free(pc->cells);
    free(pc->meets);
    memset(pc, 0, sizeof *pc);
}

void pixel_coherence_begin(PixelCoherence *pc, int first_in_row, int first_row)
{
    pc->walked = 0;
    pc->have_hit = 0;
    if (first_in_row)
        pc->neighbour = !first_row && pc->row_first.valid ? &pc->row_first : NULL;
    else
        pc->neighbour = pc->left.valid ? &pc->left : NULL;
}

static void keep(PixelNeighbour *nb, const Hit *hit, const LightState *states, int nlights)
{
    nb->valid = hit != NULL && states != NULL;
    if (!nb->valid)
        return;
    nb->hit = *hit;
    memcpy(nb->state, states, sizeof(LightState) * (size_t)nlights);
}

void pixel_coherence_end(PixelCoherence *pc, const Hit *hit, const LightState *states, int first_in_row)
{
    keep(&pc->left, hit, states, pc->nlights);
    if (first_in_row)
        keep(&pc->row_first, hit, states, pc->nlights);
}

/* Does segment a-b (in p's plane) pass within tol of p's border? In p's
 * 2-D projection, against every edge. */
static int segments_near(double au, double av, double bu, double bv, double cu, double cv, double du, double dv,
                         double tol)
{
    /* Proper crossing: each segment's ends on opposite sides of the other. */
    double d1 = (du - cu) * (av - cv) - (dv - cv) * (au - cu), d2 = (du - cu) * (bv - cv) - (dv - cv) * (bu - cu);
    double d3 = (bu - au) * (cv - av) - (bv - av) * (cu - au), d4 = (bu - au) * (dv - av) - (bv - av) * (du - au);
    if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)))
        return 1;
    /* Otherwise the nearest approach is at an end point. */
    double t2 = tol * tol;
    return segment_distance2_2d(cu, cv, du, dv, au, av) <= t2 || segment_distance2_2d(cu, cv, du, dv, bu, bv) <= t2 ||
           segment_distance2_2d(au, av, bu, bv, cu, cv) <= t2 || segment_distance2_2d(au, av, bu, bv, du, dv) <= t2;
}

static int segment_crosses_border(const World *w, const Polygon *p, Vec3 a, Vec3 b, double tol)
{
    int iu = p->axis_u, iv = p->axis_v;
    double au = v3_comp(a, iu), av = v3_comp(a, iv), bu = v3_comp(b, iu), bv = v3_comp(b, iv);
    for (int k = 0; k < polygon_outline_count(p); k++) {
        int n;
        const Vec3 *pts = polygon_outline(w, p, k, &n);
        for (int i = 0; i < n; i++) {
            Vec3 c = pts[i], d = pts[i + 1 < n ? i + 1 : 0];
            if (segments_near(au, av, bu, bv, v3_comp(c, iu), v3_comp(c, iv), v3_comp(d, iu), v3_comp(d, iv), tol))
                return 1;
        }
    }
    return 0;
}

static int add_meet(PixelCoherence *pc, int polygon, MeetKind kind, double side)
{
    if (pc->nmeets == pc->meets_cap) {
        int cap = pc->meets_cap * 2;
        PolygonMeet *m = realloc(pc->meets, sizeof *m * (size_t)cap);
        if (!m)
            return 0;
        pc->meets = m;
        pc->meets_cap = cap;
    }
    PolygonMeet *m = &pc->meets[pc->nmeets++];
    m->polygon = polygon;
    m->kind = (int8_t)kind;
    m->side = side > 0.0 ? 1 : -1;
    return 1;
}

/* How the segment a -> b meets polygon p, neither end lying on p.
 * Returns 0 when too close to call. */
static int meet_polygon(PixelCoherence *pc, const World *w, int pi, Vec3 a, Vec3 b, double sa, double sb, double tol)
{
    const Polygon *p = &w->polygons[pi];
    int near_a = fabs(sa) <= tol, near_b = fabs(sb) <= tol;
    if (!near_a && !near_b) {
        if ((sa > 0.0) == (sb > 0.0))
            return 1;
        Vec3 x = v3_add(a, v3_scale(v3_sub(b, a), sa / (sa - sb)));
        int c = polygon_classify_point(w, p, x, tol);
        if (c < 0)
            return 0;
        return c == 0 || add_meet(pc, pi, MEET_CROSS, sa);
    }
    /* An end on (or within rounding of) p's plane: the segment leaves the
     * plane there, or runs in it. Its count changes nowhere if that end
     * lies clearly outside p; a shallow segment stays near the plane for a
     * while, so the margin grows with its length over its rise. */
    double margin = tol;
    if (!(near_a && near_b))
        margin += v3_length(v3_sub(b, a)) * 2.0 * tol / fabs(sb - sa);
    if (near_a && polygon_classify_point(w, p, a, margin) != 0)
        return 0;
    if (near_b && polygon_classify_point(w, p, b, margin) != 0)
        return 0;
    /* Running in the plane across p: fine unless p is bent (per light). */
    if (near_a && near_b && segment_crosses_border(w, p, a, b, tol))
        return add_meet(pc, pi, MEET_IN_PLANE, 1.0);
    return 1;
}

/* The polygons N and P2 lie on: only the other end decides. */
static int meet_own(PixelCoherence *pc, const World *w, int pi, MeetKind kind, Vec3 other, double tol)
{
    const Polygon *p = &w->polygons[pi];
    double s = v3_dot(p->normal, other) - p->d;
    if (fabs(s) > tol)
        return add_meet(pc, pi, kind, s);
    /* The segment runs in the plane: no cap is crossed, unless the other
     * end lies on this polygon too (then the whole segment does). It
     * leaves the polygon across its border, which matters if it is bent. */
    if (polygon_classify_point(w, p, other, tol) != 0)
        return 0;
    return add_meet(pc, pi, MEET_IN_PLANE, 1.0);
}

static int inside_box(const ShadowVolumes *sv, Vec3 p)
{
    return p.x >= sv->box_min.x && p.x <= sv->box_max.x && p.y >= sv->box_min.y && p.y <= sv->box_max.y &&
           p.z >= sv->box_min.z && p.z <= sv->box_max.z;
}

/* Walks N -> P2 through the grid: records the cells (for the shadow
 * buckets) and how every polygon in them meets the segment. */
static int walk(ShadowContext *ctx, PixelCoherence *pc, const Hit *from, const Hit *to)
{
    const World *w = ctx->tracer->world;
    const ShadowVolumes *sv = ctx->volumes;
    Vec3 a = from->point, b = to->point;
    pc->ncells = 0;
    pc->nmeets = 0;
    if (!inside_box(sv, a) || !inside_box(sv, b))
        return 0;
    double tol = sv->tolerance;
    int own_a = from->kind == HIT_POLYGON ? from->index : -1;
    int own_b = to->kind == HIT_POLYGON ? to->index : -1;
    if (own_a >= 0 && own_a == own_b) {
        /* Both on one polygon: the segment lies in it. */
    } else {
        if (own_a >= 0 && !meet_own(pc, w, own_a, MEET_START_CAP, b, tol))
            return 0;
        if (own_b >= 0 && !meet_own(pc, w, own_b, MEET_END_CAP, a, tol))
            return 0;
    }
    Vec3 d = v3_sub(b, a);
    double len = v3_length(d);
    if (len == 0.0)
        return 1;
    Vec3 dir = v3_scale(d, 1.0 / len);
    GridWalk gw;
    if (!grid_walk_begin(ctx->tracer->grid, a, dir, 0.0, len, &gw))
        return 1; /* cannot happen inside the box; nothing to count then */
    uint32_t id = trace_new_segment(ctx->tracer);
    if (own_a >= 0)
        ctx->tracer->stamp[own_a] = id;
    if (own_b >= 0)
        ctx->tracer->stamp[own_b] = id;
    const Grid *g = ctx->tracer->grid;
    do {
        ctx->tracer->stats.cells_visited++;
        int c = grid_cell_index(g, gw.cell);
        if (pc->ncells == pc->cells_cap)
            return 0;
        pc->cells[pc->ncells++] = (uint32_t)c;
        for (uint32_t k = g->cell_start[c]; k < g->cell_start[c + 1]; k++) {
            uint32_t pi = g->items[k];
            if (!bucket_admit(ctx->tracer, id, pi))
                continue;
            const Polygon *p = &w->polygons[pi];
            double sa = v3_dot(p->normal, a) - p->d, sb = v3_dot(p->normal, b) - p->d;
            if ((sa > tol && sb > tol) || (sa < -tol && sb < -tol))
                continue;
            if (!meet_polygon(pc, w, (int)pi, a, b, sa, sb, tol))
                return 0;
        }
    } while (grid_walk_next(g, &gw));
    return 1;
}

int pixel_coherence_count(ShadowContext *ctx, const ShadowQuery *q, double nth, uint32_t eye_registrations,
                          LightState *out)
{
    PixelCoherence *pc = ctx->coherence;
    const PixelNeighbour *nb = pc->neighbour;
    if (!nb || !nb->state[q->light].depth_known)
        return 0;
    if (!pc->walked)
        pc->walked = walk(ctx, pc, &nb->hit, q->surface) ? 1 : -1;
    if (pc->walked < 0)
        return -1;
    const LightVolumes *lv = &ctx->volumes->light[q->light];
    uint32_t registrations = shadow_bucket_registrations_in(ctx, q->light, pc->cells, pc->ncells);
    if (registrations + (uint32_t)pc->nmeets >= eye_registrations)
        return 0; /* counting from the eye is no dearer */

    const LightState *from = &nb->state[q->light];
    int opaque = from->depth_opaque, transparent = from->depth_transparent;
    for (int i = 0; i < pc->nmeets; i++) {
        const PolygonMeet *m = &pc->meets[i];
        const OccluderSide *o = &lv->occluder[m->polygon];
        if (!o->channel)
            continue;
        if (m->kind == MEET_IN_PLANE) {
            if (o->bent)
                return -1;
            continue;
        }
        int toward = m->side == o->light_side; /* the recorded point is on the light's side */
        int change;
        switch (m->kind) {
        case MEET_CROSS: change = toward ? 1 : -1; break;     /* from N's side across */
        case MEET_START_CAP: change = toward ? 0 : 1; break;  /* P2 behind N's polygon */
        default: change = toward ? 0 : -1; break;             /* N behind P2's polygon */
        }
        if (o->channel == 1)
            opaque += change;
        else
            transparent += change;
    }
    int n = shadow_bucket_fill_in(ctx, q->light, pc->cells, pc->ncells, shadow_bucket_limit(nth - pc->nmeets));
    if (n + pc->nmeets > nth)
        return 0;
    ctx->stats.shadow_volume_tests += (uint64_t)n;
    if (!shadow_bucket_crossings(ctx->volumes, ctx->bucket, n, nb->hit.point, q->point, &opaque, &transparent))
        return -1;
    if (opaque < 0 || transparent < 0)
        return -1; /* cannot happen with exact crossings: do not trust it */
    out->depth_known = 1;
    out->self = 0;
    out->depth_opaque = opaque;
    out->depth_transparent = transparent;
    out->condition = (int8_t)(opaque > 0 ? COND_BLOCKED : transparent > 0 ? COND_FILTERED : COND_LIT);
    ctx->stats.shadow_coherent++;
    return 1;
}
