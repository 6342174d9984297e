/* The light buffer (light_buffer.h): cells built lazily by walking the
 * hierarchy with their pyramids, split where their lists are long.
 *
 * The bound behind "covers the cell". A cover is an opaque convex polygon
 * whose plane the cell's four (widened) corner rays from the light cross
 * at least cover_margin m away from the light's side of the plane, at an
 * angle of at least 1e-2 (|n.D| >= 1e-2 |D|), and whose every edge lies at
 * least m (in the plane) outside the convex quadrilateral those crossings
 * make. A point P of the cell farther from the light than the farthest
 * crossing plus m sends a shadow ray that, in exact arithmetic, crosses
 * the polygon at least m from every edge, at least m from P and from the
 * light. The watertight test (intersect.c) works in the ray's frame on
 * coordinates relative to P, below 2S in size (S: the scene's size, light
 * included); its products carry errors of a few 2^-53 S^2, and its plane
 * distance one of a few 2^-53 S. The edge function of an edge of length
 * e >= 2 sqrt(3) m (the polygon holds a disc of radius m) at a crossing
 * m away is at least e m 1e-2 / 2 = 1.7e-12 S^2 with m = 1e-5 S, some 10^4
 * times the error; the plane distance is at least m 1e-2 = 1e-7 S, far
 * from the test's "starts in the plane" band (1e-12 S) and from its tmin
 * (1e-9 S). So the test hits, and the ray is blocked: the shadow ray's
 * decision.
 *
 * The bound behind lb_candidate_passed. The point P lies on the light's
 * side of polygon p's plane by s_P > 6e-8 (|P|_1 + |d|) + 1e-12 dist (the
 * float plane's error is below 6e-8 (|P|_1 + |d|)), and the light by
 * s_L >= 1e-3 S. The shadow ray's test computes t = -s_P / (n.dir) (up to
 * sign conventions) with n.dir = (s_L - s_P) / dist exactly, rounded by a
 * few 2^-53. Its sign is certain unless |n.dir| is within that rounding,
 * and then |t| > s_P / 4e-16 > dist: no hit either way. Where P is nearer
 * the plane than the light t < 0; where farther, t exceeds dist by
 * s_L dist / (s_P - s_L), relatively at least 1e-3 S / 4S, while the
 * rounding of t is relatively 2^-51 dist / (s_P - s_L) < 1e-4 once
 * s_P - s_L > 1e-11 S, and t is beyond 10^3 dist below that. So the test
 * finds no hit in (tmin, dist): the polygon is passed over exactly.
 *
 * tests/test_agreement.c holds the light buffer to the shadow ray and a
 * long-double reference on random soups (shared edges, coplanar and
 * transparent polygons, lights in planes), its cells split at once too;
 * tests/shadows.sh runs --verify-shadows on every scene with every method. */
#include "light_buffer.h"

#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "intersect.h"
#include "light.h"

/* The cells' widening in the face's coordinates (which run from -1 to 1):
 * far above the rounding of a direction's coordinates (1e-16), far below a
 * finest cell (2 / LB_FINE). */
#define LB_WIDEN 1e-7
/* LB_COVER_ANGLE (light_buffer.h): the least |n.D| / |D| of a cover's corner rays */
#define LB_COVER_TRIES 16   /* candidates tried as a cell's cover, nearest first */
#define LB_COVER_POINTS 16  /* the most points of a polygon tried as a cover */
/* Footprints are also padded for the rounding of a point's direction to
 * float, where lb_block_mask compares them: 2^-24 of at most 2 (a face's
 * coordinates run from -1 to 1, and a point's lies within rounding of
 * that). */
#define LB_FLOAT_PAD 1e-6

static inline double comp(Vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }

static Vec3 from_face(int axis, double a, double b, double c)
{
    double v[3];
    v[axis] = a;
    v[(axis + 1) % 3] = b;
    v[(axis + 2) % 3] = c;
    return v3(v[0], v[1], v[2]);
}

/* A cell: its face, level and indices at that level. */
typedef struct {
    int face, level, i, j;
} CellAt;

static int cells_per_side(int level) { return LB_TOP << (2 * level); }

/* A cell's range in the face's coordinates, not widened. */
static void cell_range(const CellAt *at, double *u0, double *u1, double *v0, double *v1)
{
    double w = 2.0 / cells_per_side(at->level);
    *u0 = -1.0 + w * at->i;
    *u1 = -1.0 + w * (at->i + 1);
    *v0 = -1.0 + w * at->j;
    *v1 = -1.0 + w * (at->j + 1);
}

/* A cell's pyramid: four side planes through the light (outward unit
 * normals), and its widened corner directions. */
typedef struct {
    Vec3 normal[4];
    Vec3 corner[4];
} Pyramid;

static Pyramid pyramid_of(const CellAt *at)
{
    int axis = at->face / 2;
    double s = (at->face & 1) ? -1.0 : 1.0;
    double u0, u1, v0, v1;
    cell_range(at, &u0, &u1, &v0, &v1);
    u0 -= LB_WIDEN, v0 -= LB_WIDEN, u1 += LB_WIDEN, v1 += LB_WIDEN;
    Pyramid p;
    /* u >= u0: u0 s X_a - X_b <= 0, and so on (X from the light) */
    p.normal[0] = v3_normalize(from_face(axis, u0 * s, -1.0, 0.0));
    p.normal[1] = v3_normalize(from_face(axis, -u1 * s, 1.0, 0.0));
    p.normal[2] = v3_normalize(from_face(axis, v0 * s, 0.0, -1.0));
    p.normal[3] = v3_normalize(from_face(axis, -v1 * s, 0.0, 1.0));
    p.corner[0] = from_face(axis, s, u0, v0);
    p.corner[1] = from_face(axis, s, u1, v0);
    p.corner[2] = from_face(axis, s, u1, v1);
    p.corner[3] = from_face(axis, s, u0, v1);
    return p;
}

/* 1 when the box [lo, hi] lies wholly outside one of the pyramid's planes
 * by more than the margin. */
static int box_outside(const Pyramid *p, Vec3 at, Vec3 lo, Vec3 hi, double margin)
{
    for (int k = 0; k < 4; k++) {
        Vec3 n = p->normal[k];
        double m = (n.x > 0 ? lo.x - at.x : hi.x - at.x) * n.x + (n.y > 0 ? lo.y - at.y : hi.y - at.y) * n.y +
                   (n.z > 0 ? lo.z - at.z : hi.z - at.z) * n.z;
        if (m > margin)
            return 1;
    }
    return 0;
}

/* The points of polygon p: a triangle's three, or all its outlines'. */
static const Vec3 *polygon_points(const World *w, const Polygon *p, int *n)
{
    if (p->first_outline < 0) {
        *n = 3;
        return &w->points[p->first_point];
    }
    const int *start = &w->outline_start[p->first_outline];
    *n = start[p->noutlines] - start[0];
    return &w->points[start[0]];
}

/* 1 when every point of polygon p lies outside one of the pyramid's planes
 * by more than the margin. */
static int polygon_outside(const World *w, const Polygon *p, const Pyramid *pyr, Vec3 at, double margin)
{
    int n;
    const Vec3 *pts = polygon_points(w, p, &n);
    for (int k = 0; k < 4; k++) {
        int all = 1;
        for (int i = 0; i < n && all; i++)
            all = v3_dot(pyr->normal[k], v3_sub(pts[i], at)) > margin;
        if (all)
            return 1;
    }
    return 0;
}

static float round_up(double x)
{
    float f = (float)x;
    return (double)f < x ? nextafterf(f, INFINITY) : f;
}

static float round_down(double x)
{
    float f = (float)x;
    return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

/* A lower bound of the distance from the light to polygon p, in float
 * rounded down: the larger of its plane's and its box's distance, shrunk
 * by far more than their rounding. */
static float near_bound(const Polygon *p, Vec3 at)
{
    double plane = fabs(v3_dot(p->normal, at) - p->d);
    double dx = fmax(fmax(p->bbox_min.x - at.x, at.x - p->bbox_max.x), 0.0);
    double dy = fmax(fmax(p->bbox_min.y - at.y, at.y - p->bbox_max.y), 0.0);
    double dz = fmax(fmax(p->bbox_min.z - at.z, at.z - p->bbox_max.z), 0.0);
    return round_down(fmax(plane, sqrt(dx * dx + dy * dy + dz * dz)) * (1.0 - 1e-9));
}

/* Where polygon p lies on the face (light_buffer.h): the box of the
 * directions, in the face's coordinates, of its points in front of the
 * face, clamped to [-2, 2] (the cells lie within 1 and their margins of 0),
 * padded for the pyramids' margin at its distance (near) and for rounding.
 * The whole face and beyond when the polygon passes too near the light to
 * tell.
 *
 * A point X of the polygon (from the light) at least near away whose
 * direction lies within 2 of the face's axis has a >= |X| / 3 along it; one
 * with a < near / 4 lies farther out than that (its other coordinates are
 * at least 0.68 near). So the polygon is clipped to a >= near / 4: its part
 * there lies in the convex hull of its points there and of the crossings of
 * the plane a = near / 4 by the segments between its points on either side
 * (a convex hull cut by a plane), whose directions the box holds, a
 * central projection keeping convex hulls for points in front. A shift of
 * the margin m at such a point turns its direction by at most
 * m (1 + |u|) / a <= 9 m / near in the face's coordinates: 16 m / near is
 * padded, and the cells' widening and the float's rounding. */
#define LB_FOOTPRINT_POINTS 32 /* polygons of more points get the whole face */
static LbFootprint points_footprint(const LightBuffers *lbs, const Vec3 *pts, int n, Vec3 at, int face, double near)
{
    const LbFootprint anywhere = { -INFINITY, INFINITY, -INFINITY, INFINITY };
    int axis = face / 2;
    double s = (face & 1) ? -1.0 : 1.0;
    if (!(near > 1e3 * lbs->margin))
        return anywhere;
    if (n > LB_FOOTPRINT_POINTS)
        return (LbFootprint){ -2.5f, 2.5f, -2.5f, 2.5f };
    const double clip = 0.25 * near;
    double a[LB_FOOTPRINT_POINTS], b[LB_FOOTPRINT_POINTS], c[LB_FOOTPRINT_POINTS];
    for (int i = 0; i < n; i++) {
        Vec3 d = v3_sub(pts[i], at);
        a[i] = s * comp(d, axis);
        b[i] = comp(d, (axis + 1) % 3);
        c[i] = comp(d, (axis + 2) % 3);
    }
    double box[4] = { INFINITY, -INFINITY, INFINITY, -INFINITY };
    int any = 0;
#define LB_TAKE(aa, bb, cc)                                                                                           \
    do {                                                                                                              \
        double u_ = (bb) / (aa), v_ = (cc) / (aa);                                                                    \
        /* (no NaN here: aa >= clip > 0 and the points are finite) */                                                \
        box[0] = u_ < box[0] ? u_ : box[0], box[1] = u_ > box[1] ? u_ : box[1];                                       \
        box[2] = v_ < box[2] ? v_ : box[2], box[3] = v_ > box[3] ? v_ : box[3];                                       \
        any = 1;                                                                                                      \
    } while (0)
    for (int i = 0; i < n; i++) {
        if (!(a[i] >= clip))
            continue;
        LB_TAKE(a[i], b[i], c[i]);
        for (int j = 0; j < n; j++) {
            if (a[j] >= clip)
                continue;
            double t = (a[i] - clip) / (a[i] - a[j]); /* from i toward j, to the plane */
            LB_TAKE(clip, b[i] + t * (b[j] - b[i]), c[i] + t * (c[j] - c[i]));
        }
    }
#undef LB_TAKE
    if (!any)
        return (LbFootprint){ INFINITY, -INFINITY, INFINITY, -INFINITY }; /* wholly behind: on no cell */
    for (int k = 0; k < 4; k++)
        box[k] = box[k] < -2.0 ? -2.0 : box[k] > 2.0 ? 2.0 : box[k];
    double pad = 16.0 * lbs->margin / near + LB_WIDEN + LB_FLOAT_PAD;
    LbFootprint f = { round_down(box[0] - pad), round_up(box[1] + pad), round_down(box[2] - pad),
                      round_up(box[3] + pad) };
    return f;
}

static LbFootprint footprint(const LightBuffers *lbs, const Polygon *p, Vec3 at, int face, double near)
{
    int n;
    const Vec3 *pts = polygon_points(lbs->world, p, &n);
    return points_footprint(lbs, pts, n, at, face, near);
}


/* Polygon p's plane for lb_candidate_passed: turned toward the light and
 * rounded to float; zero where the light lies within plane_margin of it. */
static LbPlane candidate_plane(const LightBuffers *lbs, const Polygon *p, Vec3 at)
{
    double s = v3_dot(p->normal, at) - p->d;
    LbPlane pl = { 0.0f, 0.0f, 0.0f, 0.0f };
    if (fabs(s) < lbs->plane_margin)
        return pl;
    double sign = s > 0.0 ? 1.0 : -1.0;
    pl.nx = (float)(sign * p->normal.x);
    pl.ny = (float)(sign * p->normal.y);
    pl.nz = (float)(sign * p->normal.z);
    pl.d = (float)(sign * p->d);
    return pl;
}

/* Polygon p's shape on the face (light_buffer.h). The margins: outside,
 * the footprint's (a direction that far out of an edge's line is not the
 * polygon's, margins included), and the float's rounding of the lines;
 * inside, the cover's margin carried to the face: a direction d2 inside an
 * edge's line (in the face's coordinates, which run within 1 of 0 on the
 * face) is at least 0.29 d2 radians from the plane through the light and
 * the edge (less only where that plane's trace lies far off the face, and
 * then the angle is over 0.08), so a crossing at distance r >= near from
 * the light lies at least 0.29 r d2 from the edge: d2 = 4 cover_margin /
 * near makes that more than the cover's margin, as the cover's proof asks
 * (the bound at the top of this file). */
static LbShape polygon_shape(const LightBuffers *lbs, const Polygon *p, Vec3 at, int face, double near, int opaque)
{
    LbShape sh;
    memset(&sh, 0, sizeof sh);
    sh.opaque = (uint8_t)opaque;
    if (!(near > 1e3 * lbs->margin) || (p->noutlines > 1 && p->first_outline >= 0))
        return sh;
    int axis = face / 2;
    double s = (face & 1) ? -1.0 : 1.0;
    int n;
    const Vec3 *pts = polygon_points(lbs->world, p, &n);
    double u[4], v[4];
    int m = 0;
    for (int i = 0; i < n; i++) {
        Vec3 d = v3_sub(pts[i], at);
        double a = s * comp(d, axis);
        if (!(a > 1e-6 * v3_length(d)))
            return sh;
        double pu = comp(d, (axis + 1) % 3) / a, pv = comp(d, (axis + 2) % 3) / a;
        if (!(fabs(pu) <= 4.0 && fabs(pv) <= 4.0))
            return sh;
        if (m > 0 && pu == u[m - 1] && pv == v[m - 1])
            continue; /* a repeated point */
        if (m == 4)
            return sh;
        u[m] = pu, v[m] = pv;
        m++;
    }
    if (m >= 2 && u[m - 1] == u[0] && v[m - 1] == v[0])
        m--; /* the closing repeat */
    if (m < 3)
        return sh;
    double area = 0.0;
    for (int i = 0; i < m; i++)
        area += u[i] * v[(i + 1) % m] - u[(i + 1) % m] * v[i];
    if (!(fabs(area) > 1e-12))
        return sh;
    double orient = area > 0.0 ? 1.0 : -1.0;
    for (int i = 0; i < m; i++) {
        double eu = u[(i + 1) % m] - u[i], ev = v[(i + 1) % m] - v[i];
        double len = sqrt(eu * eu + ev * ev);
        if (!(len > 0.0))
            return sh;
        double a = -orient * ev / len, b = orient * eu / len;
        double c0 = -(a * u[i] + b * v[i]);
        /* convex: every point on the inner side */
        for (int j = 0; j < m; j++)
            if (a * u[j] + b * v[j] + c0 < -1e-12)
                return sh;
        sh.a[i] = (float)a;
        sh.b[i] = (float)b;
        sh.c[i] = (float)c0;
    }
    /* the lines' rounding to float: below 6e-8 (|a u| + |b v| + |c|) <= 6e-8 * 14 */
    const double rounding = 1e-6;
    sh.out = round_up(4.0 * lbs->margin / near + LB_WIDEN + rounding + LB_SHAPE_FLOAT_PAD);
    sh.in = round_up(4.0 * lbs->cover_margin / near + LB_WIDEN + rounding + LB_SHAPE_FLOAT_PAD);
    for (int i = m; i < 4; i++)
        sh.c[i] = 1.0f; /* no edge: every direction inside */
    sh.n = (uint8_t)m;
    return sh;
}

/* A candidate as a cell keeps it; its shape kept once, by its top cell
 * (its index in CandidateList.shapes while the top cell is gathered,
 * then in the top cell's LbCell.shapes). */
typedef struct {
    LbPlane plane;
    LbFootprint footprint;
    float near;
    uint32_t item;
    uint32_t shape;
} Candidate;

typedef struct {
    Candidate *c;
    size_t n, cap;
    LbShape *shapes;    /* a top cell's, as gathered (children use their top cell's) */
    size_t nshapes, shapes_cap;
} CandidateList;

/* Room for one more of *items (n used of *cap, each `size` bytes): 0, or
 * -1 when out of memory. */
static int room_for_one(void **items, size_t n, size_t *cap, size_t size)
{
    if (n < *cap)
        return 0;
    size_t grown_cap = *cap ? 2 * *cap : 32;
    void *grown = realloc(*items, grown_cap * size);
    if (!grown)
        return -1;
    *items = grown;
    *cap = grown_cap;
    return 0;
}

static int shape_push(CandidateList *l, const LbShape *sh)
{
    void *items = l->shapes;
    int failed = room_for_one(&items, l->nshapes, &l->shapes_cap, sizeof *sh);
    l->shapes = items;
    if (!failed)
        l->shapes[l->nshapes++] = *sh;
    return failed;
}

static int candidate_push(CandidateList *l, const Candidate *c)
{
    void *items = l->c;
    int failed = room_for_one(&items, l->n, &l->cap, sizeof *c);
    l->c = items;
    if (!failed)
        l->c[l->n++] = *c;
    return failed;
}

static void candidates_free(CandidateList *l)
{
    free(l->c);
    free(l->shapes);
}

static int by_near(const void *a, const void *b)
{
    const Candidate *x = a, *y = b;
    if (x->near != y->near)
        return x->near < y->near ? -1 : 1;
    return x->item < y->item ? -1 : x->item > y->item;
}

/* A lower bound of the distance from the light at `at` to the box
 * [lo, hi], in float rounded down (0 where the light is in it; an
 * unbounded box's distances that are not numbers are passed over). */
static float box_near(Vec3 lo, Vec3 hi, Vec3 at)
{
    double dx = fmax(fmax(lo.x - at.x, at.x - hi.x), 0.0);
    double dy = fmax(fmax(lo.y - at.y, at.y - hi.y), 0.0);
    double dz = fmax(fmax(lo.z - at.z, at.z - hi.z), 0.0);
    return round_down(sqrt(dx * dx + dy * dy + dz * dz) * (1.0 - 1e-9));
}

/* The footprint of the box [lo, hi] (finite) on the face: its corners'
 * (the box is their convex hull, which is all points_footprint asks). */
static LbFootprint box_footprint(const LightBuffers *lbs, Vec3 lo, Vec3 hi, Vec3 at, int face, double near)
{
    Vec3 corner[8];
    for (int q = 0; q < 8; q++)
        corner[q] = v3(q & 1 ? hi.x : lo.x, q & 2 ? hi.y : lo.y, q & 4 ? hi.z : lo.z);
    return points_footprint(lbs, corner, 8, at, face, near);
}

/* An instance as a candidate (instance.h): its box (Bvh.instance_box,
 * rounded outward with the hierarchy's margin) stands for its polygons,
 * which it holds. Its near bound is the box's distance from the light,
 * its footprint the box's corners' (the convex hull of the corners holds
 * the polygons, which is all points_footprint asks), its plane none and
 * its shape none (never crossed, never a cover): a point that selects it
 * has the instance's polygons met by the shadow ray's own walk of it. */
static int instance_candidate(const LightBuffers *lbs, const LightBuffer *lb, const Pyramid *pyr, int face,
                              const float box[6], uint32_t k, CandidateList *out)
{
    Vec3 lo = v3(box[0], box[1], box[2]), hi = v3(box[3], box[4], box[5]);
    if (box_outside(pyr, lb->at, lo, hi, lbs->margin))
        return 0;
    float near = box_near(lo, hi, lb->at);
    LbShape shape;
    memset(&shape, 0, sizeof shape);
    Candidate cand = { { 0.0f, 0.0f, 0.0f, 0.0f }, box_footprint(lbs, lo, hi, lb->at, face, near), near, k,
                       (uint32_t)out->nshapes };
    return shape_push(out, &shape) || candidate_push(out, &cand) ? -1 : 0;
}

/* The leaf items k of hierarchy b whose nodes' boxes, each grown by
 * `growth` (object_growth's rule for the node's size; 0: as they are),
 * meet the pyramid, and that cast shadows: visit(user, k) for each, in
 * the walk's order (the gatherers sort what they keep). Returns 0, or the
 * first nonzero visit's value. */
typedef int (*PyramidVisit)(void *user, uint32_t k);
static int walk_pyramid(const LightBuffers *lbs, const Bvh *b, const Pyramid *pyr, Vec3 at, double growth,
                        PyramidVisit visit, void *user)
{
    if (!b || b->nnodes == 0)
        return 0;
    uint32_t stack[BVH_STACK];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        uint32_t c = stack[--sp];
        if (!bvh_is_leaf(c)) {
            const BvhNode *node = &b->nodes[c];
            for (int k = BVH_WIDTH - 1; k >= 0; k--) {
                if (node->child[k] == BVH_EMPTY)
                    continue;
                Vec3 lo = v3(node->lo[0][k], node->lo[1][k], node->lo[2][k]);
                Vec3 hi = v3(node->hi[0][k], node->hi[1][k], node->hi[2][k]);
                if (growth > 0.0) {
                    /* the node's box grown as its objects' are (at least) */
                    double g = growth * (1.0 + 2.0 * fmax(v3_max_abs(lo), v3_max_abs(hi)) + lbs->object_reach) +
                               lbs->margin;
                    lo = v3_sub(lo, v3(g, g, g));
                    hi = v3_add(hi, v3(g, g, g));
                }
                if (!box_outside(pyr, at, lo, hi, lbs->margin))
                    stack[sp++] = node->child[k];
            }
            continue;
        }
        uint32_t first = bvh_leaf_first(c), end = first + bvh_leaf_count(c);
        for (uint32_t k = first; k < end; k++) {
            if (b->prims[k].hide & HIDE_NO_SHADOW)
                continue;
            int status = visit(user, k);
            if (status)
                return status;
        }
    }
    return 0;
}

/* What the gatherers' visits need. */
typedef struct {
    const LightBuffers *lbs;
    const LightBuffer *lb;
    const Pyramid *pyr;
    int face;
    void *out;              /* CandidateList or ObjectList */
} Gathering;

/* gather_from_hierarchy's visit: leaf item k as a candidate, if it may
 * cast the light's shadows into the pyramid. */
static int gather_polygon(void *user, uint32_t k)
{
    const Gathering *g = user;
    const LightBuffers *lbs = g->lbs;
    const LightBuffer *lb = g->lb;
    const Bvh *b = lbs->bvh;
    const World *w = lbs->world;
    CandidateList *out = g->out;
    if (b->items[k] & BVH_INSTANCE)
        return instance_candidate(lbs, lb, g->pyr, g->face, &b->instance_box[6 * (b->items[k] & ~BVH_INSTANCE)], k,
                                  out);
    const Polygon *p = &w->polygons[b->items[k]];
    /* edge-on to the light: the shadow ray passes it (shadow_conventional.c) */
    if (light_side_of(p, &w->lights[lb->light], lbs->tolerance) == 0)
        return 0;
    if (polygon_outside(w, p, g->pyr, lb->at, lbs->margin))
        return 0;
    float near = near_bound(p, lb->at);
    LbShape shape = polygon_shape(lbs, p, lb->at, g->face, near, w->materials[p->material].opaque);
    Candidate cand = { candidate_plane(lbs, p, lb->at), footprint(lbs, p, lb->at, g->face, near), near, k,
                       (uint32_t)out->nshapes };
    return shape_push(out, &shape) || candidate_push(out, &cand) ? -1 : 0;
}

/* Every polygon that may cast the light's shadows into the pyramid: the
 * hierarchy walked with it, the list in order of the near bound. */
static int gather_from_hierarchy(const LightBuffers *lbs, const LightBuffer *lb, const Pyramid *pyr, int face,
                                 CandidateList *out)
{
    Gathering g = { lbs, lb, pyr, face, out };
    if (walk_pyramid(lbs, lbs->bvh, pyr, lb->at, 0.0, gather_polygon, &g))
        return -1;
    if (out->n > 1) /* (qsort takes no null array, even of none) */
        qsort(out->c, out->n, sizeof *out->c, by_near);
    return 0;
}

/* The curved objects of a top cell, as gathered (light_buffer.h: LbCell.object). */
typedef struct {
    LbObject *c;
    size_t n, cap;
} ObjectList;

static int by_object_near(const void *a, const void *b)
{
    const LbObject *x = a, *y = b;
    if (x->near != y->near)
        return x->near < y->near ? -1 : 1;
    return x->shape < y->shape ? -1 : x->shape > y->shape;
}

/* gather_objects' visit: the shapes' hierarchy's leaf item k as a listed
 * object, if its grown box meets the pyramid and it casts shadows. */
static int gather_object(void *user, uint32_t k)
{
    const Gathering *g = user;
    const LightBuffers *lbs = g->lbs;
    const Vec3 at = g->lb->at;
    const Bvh *b = lbs->bvh->shapes;
    const World *w = lbs->world;
    ObjectList *out = g->out;
    const Shape *sh = &w->shapes[b->items[k]];
    if (w->materials[sh->material].no_shadow)
        return 0;
    const double o[3] = { sh->bbox_min.x, sh->bbox_min.y, sh->bbox_min.z };
    const double p[3] = { sh->bbox_max.x, sh->bbox_max.y, sh->bbox_max.z };
    double lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        double grow = lbs->object_growth * (1.0 + fabs(o[a]) + fabs(p[a]) + lbs->object_reach) + lbs->margin;
        lo[a] = o[a] - grow;
        hi[a] = p[a] + grow;
    }
    Vec3 blo = v3(lo[0], lo[1], lo[2]), bhi = v3(hi[0], hi[1], hi[2]);
    if (box_outside(g->pyr, at, blo, bhi, lbs->margin))
        return 0;
    float near = box_near(blo, bhi, at);
    /* an unbounded box's footprint is the whole face */
    LbFootprint f = { -INFINITY, INFINITY, -INFINITY, INFINITY };
    if (isfinite(lo[0]) && isfinite(lo[1]) && isfinite(lo[2]) && isfinite(hi[0]) && isfinite(hi[1]) && isfinite(hi[2]))
        f = box_footprint(lbs, blo, bhi, at, g->face, near);
    LbObject oc = { near, f.u0, f.u1, f.v0, f.v1, b->items[k] };
    void *items = out->c;
    if (room_for_one(&items, out->n, &out->cap, sizeof oc))
        return -1;
    out->c = items;
    out->c[out->n++] = oc;
    return 0;
}

/* Every curved object whose grown box meets the pyramid: the shapes'
 * hierarchy walked with it (its boxes, grown, hold the objects' grown
 * boxes), the list in order of the near bound. Objects that cast no
 * shadow are left out (the shadow ray passes them over). */
static int gather_objects(const LightBuffers *lbs, const LightBuffer *lb, const Pyramid *pyr, int face,
                          ObjectList *out)
{
    Gathering g = { lbs, lb, pyr, face, out };
    if (walk_pyramid(lbs, lbs->bvh->shapes, pyr, lb->at, lbs->object_growth, gather_object, &g))
        return -1;
    if (out->n > 1)
        qsort(out->c, out->n, sizeof *out->c, by_object_near);
    return 0;
}

/* If opaque polygon p covers the whole pyramid (the bound at the top of
 * this file), the distance from the light beyond which it blocks every
 * point of the cell; else infinity. */
static double cover_beyond(const LightBuffers *lbs, const Polygon *p, const Pyramid *pyr, Vec3 at)
{
    const World *w = lbs->world;
    const double m = lbs->cover_margin;
    if (p->noutlines > 1 && p->first_outline >= 0)
        return INFINITY; /* holes */
    int n;
    const Vec3 *pts = polygon_points(w, p, &n);
    if (n > LB_COVER_POINTS)
        return INFINITY;
    double light_side = v3_dot(p->normal, at) - p->d;
    if (fabs(light_side) < m)
        return INFINITY;
    /* the corner rays' crossings of the plane */
    Vec3 x[4];
    double far = 0.0;
    for (int k = 0; k < 4; k++) {
        Vec3 d = pyr->corner[k];
        double len = v3_length(d), dn = v3_dot(p->normal, d);
        double t = -light_side / dn;
        if (!(fabs(dn) >= LB_COVER_ANGLE * len) || !(t > 0.0))
            return INFINITY;
        x[k] = v3_add(at, v3_scale(d, t));
        far = fmax(far, t * len);
    }
    /* convex: every point on the inner side of every edge's line (the
     * orientation from the outline's area), and every crossing at least m
     * inside every edge; repeated points (a closing repeat) make
     * zero-length edges, which are skipped */
    Vec3 area = v3(0, 0, 0);
    for (int i = 0; i < n; i++)
        area = v3_add(area, v3_cross(pts[i], pts[(i + 1) % n]));
    double orient = v3_dot(area, p->normal);
    if (orient == 0.0)
        return INFINITY;
    for (int i = 0; i < n; i++) {
        Vec3 e = v3_sub(pts[(i + 1) % n], pts[i]);
        double len = v3_length(e);
        if (len == 0.0)
            continue;
        Vec3 inward = v3_scale(v3_cross(p->normal, e), (orient > 0.0 ? 1.0 : -1.0) / len);
        for (int j = 0; j < n; j++)
            if (v3_dot(inward, v3_sub(pts[j], pts[i])) < 0.0)
                return INFINITY;
        for (int k = 0; k < 4; k++)
            if (!(v3_dot(inward, v3_sub(x[k], pts[i])) >= m))
                return INFINITY;
    }
    return far + m;
}

/* A cell and its lists in one allocation: the header (a multiple of 16
 * bytes), a top cell's shapes (64 bytes each), the blocks (LbBlock,
 * aligned for SSE), the items and the shapes' indices. */
static size_t blocks_of(size_t n) { return (n + LB_BLOCK - 1) / LB_BLOCK * LB_BLOCK; }
static size_t header_bytes(void) { return (sizeof(LbCell) + 15) / 16 * 16; }
static size_t cell_bytes(size_t n, size_t nshapes, size_t nobjects)
{
    return header_bytes() + nshapes * sizeof(LbShape) + blocks_of(n) / LB_BLOCK * sizeof(LbBlock) +
           n * 2 * sizeof(uint32_t) + nobjects * sizeof(LbObject);
}

#define CHILDREN_BYTES (LB_SUB * LB_SUB * sizeof(_Atomic(LbCell *)))
_Static_assert(LB_SUB * LB_SUB <= 16, "build_children keeps a candidate's children in 16 bits");

/* Takes `bytes` of the budget: 0, or -1 when it would go past it. */
static int budget_take(LightBuffers *lbs, size_t bytes)
{
    if (atomic_load_explicit(&lbs->exhausted, memory_order_relaxed))
        return -1;
    size_t before = atomic_fetch_add(&lbs->bytes, bytes);
    if (before + bytes <= lbs->budget)
        return 0;
    atomic_fetch_sub(&lbs->bytes, bytes);
    atomic_fetch_add(&lbs->full, 1);
    /* past the budget no cell is tried again (each try would gather its
     * list for nothing): the cells there stand, the shadow ray serves the rest */
    atomic_store_explicit(&lbs->exhausted, 1, memory_order_relaxed);
    return -1;
}

/* A cell of the candidates gathered (in order): its cover found (or its
 * parent's kept), its list cut where the cover hides the rest; a top
 * cell keeps the shapes its list refers to, a child its top cell's. NULL
 * when out of memory or budget. */
static LbCell *make_cell(LightBuffers *lbs, const LightBuffer *lb, const CellAt *at, const CandidateList *l,
                         const ObjectList *objects, const LbCell *parent)
{
    const World *w = lbs->world;
    const Bvh *b = lbs->bvh;
    Pyramid pyr = pyramid_of(at);
    /* A parent's cover covers its children: its proof holds for every
     * point of the parent's widened pyramid, which holds theirs. Else the
     * first candidate (nearest first) proved to cover the cell. */
    int32_t cover = parent ? parent->cover : -1;
    double beyond = parent ? parent->cover_beyond : INFINITY;
    double u0, u1, v0, v1;
    cell_range(at, &u0, &u1, &v0, &v1);
    for (size_t i = 0, tried = 0; cover < 0 && i < l->n && tried < LB_COVER_TRIES; i++) {
        if (b->items[l->c[i].item] & BVH_INSTANCE)
            continue; /* an instance covers nothing it is proved to */
        const Polygon *p = &w->polygons[b->items[l->c[i].item]];
        /* a polygon whose footprint does not hold the cell cannot cover it */
        const LbFootprint *f = &l->c[i].footprint;
        if (!w->materials[p->material].opaque || f->u0 > u0 || f->u1 < u1 || f->v0 > v0 || f->v1 < v1)
            continue;
        tried++;
        beyond = cover_beyond(lbs, p, &pyr, lb->at);
        if (beyond < INFINITY)
            cover = (int32_t)b->items[l->c[i].item];
    }
    /* Points beyond the cover are blocked by it; nearer ones need no
     * candidate beyond them: what lies beyond the cover is never tested. */
    size_t n = l->n;
    if (cover >= 0) {
        double keep = beyond * (1.0 + 1e-6) + 2.0 * lbs->margin;
        n = 0;
        while (n < l->n && (double)l->c[n].near < keep)
            n++;
    }
    /* a top cell's shapes: those its list (as cut) refers to, in the
     * order gathered */
    uint32_t *renumber = NULL;
    size_t nshapes = 0;
    if (!parent) {
        renumber = malloc(sizeof *renumber * (l->nshapes > 0 ? l->nshapes : 1));
        if (!renumber)
            return NULL;
        for (size_t k = 0; k < l->nshapes; k++)
            renumber[k] = UINT32_MAX;
        for (size_t i = 0; i < n; i++)
            renumber[l->c[i].shape] = 0;
        for (size_t k = 0; k < l->nshapes; k++)
            if (renumber[k] == 0)
                renumber[k] = (uint32_t)nshapes++;
    }
    size_t nobjects = objects ? objects->n : 0;
    size_t bytes = cell_bytes(n, nshapes, nobjects);
    if (budget_take(lbs, bytes)) {
        free(renumber);
        return NULL;
    }
    LbCell *c = shared_arena_alloc(&lbs->arena, bytes);
    if (!c) {
        atomic_fetch_sub(&lbs->bytes, bytes);
        free(renumber);
        return NULL;
    }
    LbShape *shapes = (LbShape *)((char *)c + header_bytes());
    for (size_t k = 0; renumber && k < l->nshapes; k++)
        if (renumber[k] != UINT32_MAX)
            shapes[renumber[k]] = l->shapes[k];
    size_t nb = blocks_of(n);
    LbBlock *block = (LbBlock *)(shapes + nshapes);
    uint32_t *item = (uint32_t *)(block + nb / LB_BLOCK), *shape_at = item + n;
    for (size_t i = 0; i < nb; i++) {
        /* the padding selects no point: beyond every limit, an empty
         * footprint, a plane no point passes */
        const LbFootprint none = { INFINITY, -INFINITY, INFINITY, -INFINITY };
        const LbPlane zero = { 0.0f, 0.0f, 0.0f, 0.0f };
        const LbFootprint *f = i < n ? &l->c[i].footprint : &none;
        const LbPlane *pl = i < n ? &l->c[i].plane : &zero;
        LbBlock *bl = &block[i / LB_BLOCK];
        size_t k = i % LB_BLOCK;
        bl->near[k] = i < n ? l->c[i].near : INFINITY;
        bl->u0[k] = f->u0;
        bl->u1[k] = f->u1;
        bl->v0[k] = f->v0;
        bl->v1[k] = f->v1;
        bl->nx[k] = pl->nx;
        bl->ny[k] = pl->ny;
        bl->nz[k] = pl->nz;
        bl->d[k] = pl->d;
    }
    for (size_t i = 0; i < n; i++) {
        item[i] = l->c[i].item;
        shape_at[i] = renumber ? renumber[l->c[i].shape] : l->c[i].shape;
    }
    free(renumber);
    LbObject *object = (LbObject *)(shape_at + n);
    for (size_t i = 0; i < nobjects; i++)
        object[i] = objects->c[i];
    c->object = objects ? object : parent->object;
    c->nobjects = objects ? (uint32_t)nobjects : parent->nobjects;
    c->nshapes = (uint32_t)nshapes;
    c->shapes = parent ? parent->shapes : shapes;
    c->n = (uint32_t)n;
    c->cover = cover;
    c->cover_beyond = beyond;
    /* A long list above the last level: split, its children built as
     * points ask. Decided by the list alone, so that which cell answers a
     * point does not depend on the order points came in (the threads'
     * timing): the sub-schemes and analysis channels are the same for
     * any number of threads. */
    _Atomic(LbCell *) *child = NULL;
    /* (a split that left the list nearly as long as its parent's, its
     * candidates wider than the cells, is not split again) */
    int shorter = !parent || 4 * n < 3 * (size_t)parent->n;
    int fewer_objects = !parent || 4 * (size_t)c->nobjects < 3 * (size_t)parent->nobjects;
    int long_lists = (n > lbs->split_at && shorter) || (c->nobjects > LB_SPLIT_OBJECTS_AT && fewer_objects);
    if (long_lists && at->level < LB_LEVELS - 1 && budget_take(lbs, CHILDREN_BYTES) == 0) {
        child = shared_arena_alloc(&lbs->arena, CHILDREN_BYTES);
        if (!child)
            atomic_fetch_sub(&lbs->bytes, CHILDREN_BYTES);
        for (int k = 0; child && k < LB_SUB * LB_SUB; k++)
            atomic_init(&child[k], NULL);
    }
    c->child = child;
    c->block = block;
    c->item = item;
    c->shape_at = shape_at;
    c->level = at->level;
    return c;
}

/* The children of split cell c (`at`: any one of them) not yet built:
 * each the candidates of c whose footprints overlap it (footprint()
 * padded them for the children's widening and margins), in c's order,
 * gathered in two passes over c's list (the lists' lengths, then the lists), then published. A child that the
 * budget or memory stops stays unbuilt (its parent's list serves). The
 * lists depend on c's alone, so which thread builds them does not matter. */
static LbCell *publish(LightBuffers *lbs, _Atomic(LbCell *) *slot, LbCell *c);

static void build_children(LightBuffers *lbs, const LightBuffer *lb, const LbCell *c, const CellAt *at)
{
    CellAt first = { at->face, at->level, at->i & ~(LB_SUB - 1), at->j & ~(LB_SUB - 1) };
    double u0[LB_SUB], u1[LB_SUB], v0[LB_SUB], v1[LB_SUB];
    for (int a = 0; a < LB_SUB; a++) {
        CellAt row = { first.face, first.level, first.i + a, first.j + a };
        cell_range(&row, &u0[a], &u1[a], &v0[a], &v1[a]);
    }
    unsigned wanted = 0; /* the slots to build, bit b * LB_SUB + a */
    for (int k = 0; k < LB_SUB * LB_SUB; k++)
        wanted |= (unsigned)(atomic_load_explicit(&c->child[k], memory_order_acquire) == NULL) << k;
    /* Two passes: which wanted children each candidate's footprint
     * overlaps (and so how long each child's list is), then the lists
     * filled, each allocated once at its length. */
    CandidateList l[LB_SUB * LB_SUB];
    memset(l, 0, sizeof l);
    uint16_t *over = malloc(sizeof *over * (c->n > 0 ? c->n : 1));
    int failed = !over;
    size_t count[LB_SUB * LB_SUB] = { 0 };
    for (uint32_t k = 0; k < c->n && !failed; k++) {
        const LbBlock *bl = &c->block[k / LB_BLOCK];
        uint32_t j = k % LB_BLOCK;
        unsigned mu = 0, mv = 0;
        for (int a = 0; a < LB_SUB; a++) {
            mu |= (unsigned)!(bl->u0[j] > u1[a] || bl->u1[j] < u0[a]) << a;
            mv |= (unsigned)!(bl->v0[j] > v1[a] || bl->v1[j] < v0[a]) << a;
        }
        unsigned m = 0;
        for (int b = 0; b < LB_SUB; b++)
            if (mv >> b & 1)
                m |= mu << (b * LB_SUB);
        over[k] = (uint16_t)(m & wanted);
        for (unsigned bits = over[k]; bits; bits &= bits - 1)
            count[__builtin_ctz(bits)]++;
    }
    for (int s = 0; s < LB_SUB * LB_SUB && !failed; s++) {
        if (count[s] == 0)
            continue;
        l[s].c = malloc(sizeof *l[s].c * count[s]);
        l[s].cap = count[s];
        failed = !l[s].c;
    }
    for (uint32_t k = 0; k < c->n && !failed; k++) {
        if (!over[k])
            continue;
        const LbBlock *bl = &c->block[k / LB_BLOCK];
        uint32_t j = k % LB_BLOCK;
        const Candidate cand = { lb_plane_at(c, k), { bl->u0[j], bl->u1[j], bl->v0[j], bl->v1[j] }, bl->near[j],
                                 c->item[k], c->shape_at[k] };
        for (unsigned bits = over[k]; bits; bits &= bits - 1) {
            CandidateList *to = &l[__builtin_ctz(bits)];
            to->c[to->n++] = cand;
        }
    }
    free(over);
    /* the objects whose footprints overlap each child, in c's order */
    ObjectList objects[LB_SUB * LB_SUB];
    memset(objects, 0, sizeof objects);
    for (uint32_t k = 0; k < c->nobjects && !failed; k++) {
        const LbObject *o = &c->object[k];
        for (int s = 0; s < LB_SUB * LB_SUB && !failed; s++) {
            int a = s % LB_SUB, b = s / LB_SUB;
            if (!(wanted >> s & 1) || o->u0 > u1[a] || o->u1 < u0[a] || o->v0 > v1[b] || o->v1 < v0[b])
                continue;
            void *items = objects[s].c;
            failed = room_for_one(&items, objects[s].n, &objects[s].cap, sizeof *o);
            objects[s].c = items;
            if (!failed)
                objects[s].c[objects[s].n++] = *o;
        }
    }
    for (int s = 0; s < LB_SUB * LB_SUB; s++) {
        if (!failed && (wanted >> s & 1)) {
            CellAt child_at = { first.face, first.level, first.i + s % LB_SUB, first.j + s / LB_SUB };
            LbCell *child = make_cell(lbs, lb, &child_at, &l[s], &objects[s], c);
            if (child)
                publish(lbs, &c->child[s], child);
        }
        candidates_free(&l[s]);
        free(objects[s].c);
    }
}

/* The cell at `at` of the spot (face and finest indices) at a level. */
static CellAt cell_at(const LbSpot *spot, int level)
{
    int shift = 2 * (LB_LEVELS - 1 - level);
    CellAt at = { spot->face, level, spot->iu >> shift, spot->iv >> shift };
    return at;
}

/* Publishes a cell built into *slot, unless another thread was first: then
 * that one's is kept, and this one's memory stays unused in the arena
 * (counted as taken) until the buffers go. Returns the cell in place. */
static LbCell *publish(LightBuffers *lbs, _Atomic(LbCell *) *slot, LbCell *c)
{
    LbCell *expected = NULL;
    if (atomic_compare_exchange_strong_explicit(slot, &expected, c, memory_order_acq_rel, memory_order_acquire)) {
        atomic_fetch_add(&lbs->cells, 1);
        atomic_fetch_add(&lbs->candidates, c->n);
        return c;
    }
    return expected;
}

const LbCell *light_buffer_cell(LightBuffers *lbs, LightBuffer *lb, const LbSpot *spot, double *built)
{
    *built = 0.0;
    CellAt top = cell_at(spot, 0);
    _Atomic(LbCell *) *slot = &lb->top[spot->face][top.j * LB_TOP + top.i];
    LbCell *c = atomic_load_explicit(slot, memory_order_acquire);
    if (!c && atomic_load_explicit(&lbs->exhausted, memory_order_relaxed))
        return NULL;
    if (!c) {
        double t0 = clock_wall();
        CandidateList l = { 0 };
        ObjectList objects = { 0 };
        Pyramid pyr = pyramid_of(&top);
        if (gather_from_hierarchy(lbs, lb, &pyr, spot->face, &l) == 0 &&
            gather_objects(lbs, lb, &pyr, spot->face, &objects) == 0)
            c = make_cell(lbs, lb, &top, &l, &objects, NULL);
        candidates_free(&l);
        free(objects.c);
        if (c)
            c = publish(lbs, slot, c);
        *built = clock_wall() - t0;
        if (!c)
            return NULL;
    }
    for (;;) {
        _Atomic(LbCell *) *child = c->child;
        if (!child)
            return c;
        CellAt at = cell_at(spot, c->level + 1);
        _Atomic(LbCell *) *slot_c = &child[(at.j & (LB_SUB - 1)) * LB_SUB + (at.i & (LB_SUB - 1))];
        LbCell *next = atomic_load_explicit(slot_c, memory_order_acquire);
        if (!next && atomic_load_explicit(&lbs->exhausted, memory_order_relaxed))
            return c; /* the budget: the parent's list serves */
        if (!next) {
            double t0 = clock_wall();
            build_children(lbs, lb, c, &at);
            next = atomic_load_explicit(slot_c, memory_order_acquire);
            *built += clock_wall() - t0;
            if (!next)
                return c; /* the budget: the parent's list serves */
        }
        c = next;
    }
}

/* LightBuffers.object_rank: the shapes' hierarchy walked as
 * bvh_shapes_walk walks it (depth first, each node's first child first),
 * every node entered. */
static int rank_objects(LightBuffers *lbs)
{
    const World *w = lbs->world;
    const Bvh *b = lbs->bvh->shapes;
    lbs->object_rank = malloc(sizeof *lbs->object_rank * (size_t)(w->nshapes > 0 ? w->nshapes : 1));
    if (!lbs->object_rank)
        return -1;
    for (int i = 0; i < w->nshapes; i++)
        lbs->object_rank[i] = UINT32_MAX;
    if (!b || b->nnodes == 0)
        return 0;
    uint32_t stack[BVH_STACK], rank = 0;
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        uint32_t c = stack[--sp];
        if (!bvh_is_leaf(c)) {
            const BvhNode *node = &b->nodes[c];
            for (int k = BVH_WIDTH - 1; k >= 0; k--)
                if (node->child[k] != BVH_EMPTY)
                    stack[sp++] = node->child[k];
            continue;
        }
        uint32_t first = bvh_leaf_first(c), end = first + bvh_leaf_count(c);
        for (uint32_t k = first; k < end; k++)
            lbs->object_rank[b->items[k]] = rank++;
    }
    return 0;
}

int light_buffers_init(LightBuffers *lbs, const World *w, const Bvh *bvh, double tolerance, size_t budget)
{
    memset(lbs, 0, sizeof *lbs);
    lbs->world = w;
    lbs->bvh = bvh;
    lbs->tolerance = tolerance;
    lbs->budget = budget;
    lbs->split_at = LB_SPLIT_AT;
    atomic_init(&lbs->bytes, 0);
    atomic_init(&lbs->cells, 0);
    atomic_init(&lbs->candidates, 0);
    atomic_init(&lbs->full, 0);
    atomic_init(&lbs->exhausted, 0);
    if (shared_arena_init(&lbs->arena, LB_ARENA_CHUNK))
        return -1;
    lbs->arena_made = 1;
    double size = 0.0;
    if (w->bounds_min.x <= w->bounds_max.x)
        size = fmax(v3_max_abs(w->bounds_min), v3_max_abs(w->bounds_max));
    for (int i = 0; i < w->nlights; i++)
        size = fmax(size, v3_max_abs(w->lights[i].location));
    lbs->margin = 1e-9 * (1.0 + size);
    lbs->cover_margin = 1e-5 * (1.0 + size);
    lbs->plane_margin = 1e-3 * (1.0 + size);
    lbs->object_growth = 4e-9;
    lbs->object_reach = 4.0 * (1.0 + size);
    lbs->nlights = w->nlights;
    lbs->light = calloc((size_t)(w->nlights > 0 ? w->nlights : 1), sizeof *lbs->light);
    lbs->item_of = malloc(sizeof *lbs->item_of * (size_t)(w->npolygons > 0 ? w->npolygons : 1));
    if (!lbs->light || !lbs->item_of)
        return -1;
    for (int k = 0; k < bvh->nitems; k++)
        if (!(bvh->items[k] & BVH_INSTANCE))
            lbs->item_of[bvh->items[k]] = (uint32_t)k;
    if (rank_objects(lbs))
        return -1;
    for (int i = 0; i < w->nlights; i++) {
        const Light *l = &w->lights[i];
        if (l->kind != LIGHT_POINT || l->shadowless)
            continue;
        LightBuffer *lb = calloc(1, sizeof *lb);
        if (!lb)
            return -1;
        lb->light = i;
        lb->at = l->location;
        lb->plane_side = calloc((size_t)(w->nplanes > 0 ? w->nplanes : 1), sizeof *lb->plane_side);
        if (!lb->plane_side) {
            free(lb);
            return -1;
        }
        for (int k = 0; k < w->nplanes; k++) {
            const InfinitePlane *pl = &w->planes[k];
            const Material *m = &w->materials[pl->material];
            double s = v3_dot(pl->normal, lb->at) - pl->d;
            if (m->opaque && !m->no_shadow && fabs(s) >= lbs->plane_margin)
                lb->plane_side[k] = s;
        }
        for (int f = 0; f < 6; f++)
            for (int k = 0; k < LB_TOP * LB_TOP; k++)
                atomic_init(&lb->top[f][k], NULL);
        lbs->light[i] = lb;
    }
    return 0;
}

void light_buffers_free(LightBuffers *lbs)
{
    for (int i = 0; lbs->light && i < lbs->nlights; i++) {
        LightBuffer *lb = lbs->light[i];
        if (!lb)
            continue;
        free(lb->plane_side);
        free(lb);
    }
    free(lbs->light);
    free(lbs->item_of);
    free(lbs->object_rank);
    lbs->light = NULL;
    lbs->item_of = NULL;
    lbs->object_rank = NULL;
    if (lbs->arena_made)
        shared_arena_free(&lbs->arena); /* every cell */
    lbs->arena_made = 0;
}
