/* Grid construction (exact polygon/cell registration) and the 3DDDA set-up. */
#include "grid.h"
#include "big_memory.h"

#include <stdlib.h>
#include <string.h>

#include "convert.h"
#include "parallel.h"

void grid_choose_resolution(const World *w, Vec3 lo, Vec3 hi, int res[3])
{
    /* About eight cells per polygon, shaped like the box: the usual ARTS
     * heuristic. Flat boxes get one cell across their thin axis. */
    const double density = 8.0;
    double n = w->npolygons > 0 ? w->npolygons : 1;
    Vec3 ext = v3_sub(hi, lo);
    double e[3] = { ext.x, ext.y, ext.z };
    double emax = fmax(e[0], fmax(e[1], e[2]));
    double volume = 1.0;
    int dims = 0;
    for (int a = 0; a < 3; a++) {
        if (e[a] > emax * 1e-3) {
            volume *= e[a];
            dims++;
        }
    }
    double per_len = dims > 0 ? pow(density * n / volume, 1.0 / dims) : 1.0;
    for (int a = 0; a < 3; a++) {
        res[a] = (e[a] > emax * 1e-3) ? int_clamped(ceil(e[a] * per_len), 1, 512) : 1;
    }
    /* Keep the cell array within reason (2^24 cells). */
    while ((double)res[0] * res[1] * res[2] > 16777216.0)
        for (int a = 0; a < 3; a++)
            res[a] = res[a] > 1 ? res[a] * 3 / 4 : 1;
}

static int outline_overlaps_box_buf(const Vec3 *pts, int n, Vec3 lo, Vec3 hi, Vec3 *buf_a, Vec3 *buf_b)
{
    memcpy(buf_a, pts, sizeof(Vec3) * (size_t)n);
    int m = n;
    Vec3 *src = buf_a, *dst = buf_b;
    for (int axis = 0; axis < 3 && m > 0; axis++) {
        m = clip_against(src, m, dst, axis, v3_comp(lo, axis), +1);
        Vec3 *t = src; src = dst; dst = t;
        if (m == 0)
            break;
        m = clip_against(src, m, dst, axis, v3_comp(hi, axis), -1);
        t = src; src = dst; dst = t;
    }
    return m > 0;
}

int outline_overlaps_box(const Vec3 *pts, int n, Vec3 lo, Vec3 hi)
{
    Vec3 a[16], b[16];
    if (n + 8 > 16)
        return 1; /* only short outlines are asked for; register conservatively */
    return outline_overlaps_box_buf(pts, n, lo, hi, a, b);
}

int polygon_overlaps_box(const World *w, const Polygon *p, Vec3 lo, Vec3 hi)
{
    /* The plane must pass through the box: corners on both sides (or on it). */
    Vec3 c = v3_scale(v3_add(lo, hi), 0.5), h = v3_scale(v3_sub(hi, lo), 0.5);
    double r = h.x * fabs(p->normal.x) + h.y * fabs(p->normal.y) + h.z * fabs(p->normal.z);
    if (fabs(v3_dot(p->normal, c) - p->d) > r)
        return 0;
    /* Clip buffers: an n-gon clipped by 6 planes has at most n + 6 points. */
    int maxn = p->npoints + 8;
    Vec3 stack_a[32], stack_b[32];
    Vec3 *a = maxn <= 32 ? stack_a : malloc(sizeof(Vec3) * (size_t)maxn);
    Vec3 *b = maxn <= 32 ? stack_b : malloc(sizeof(Vec3) * (size_t)maxn);
    int hit = 1; /* when memory is short, register conservatively */
    if (a && b) {
        if (p->first_outline < 0) {
            hit = outline_overlaps_box_buf(&w->points[p->first_point], 3, lo, hi, a, b);
        } else {
            hit = 0;
            const int *start = &w->outline_start[p->first_outline];
            for (int k = 0; k < p->noutlines && !hit; k++)
                hit = outline_overlaps_box_buf(&w->points[start[k]], start[k + 1] - start[k], lo, hi, a, b);
        }
    }
    if (a != stack_a) free(a);
    if (b != stack_b) free(b);
    return hit;
}

typedef struct {
    uint32_t cell, polygon;
} Registration;

void grid_build_box(Grid *g, const World *w, const int *res, const Vec3 *extra, int nextra)
{
    memset(g, 0, sizeof *g);
    Vec3 lo = w->bounds_min, hi = w->bounds_max;
    for (int i = 0; i < nextra; i++) {
        lo = v3_min(lo, extra[i]);
        hi = v3_max(hi, extra[i]);
    }
    if (!(lo.x <= hi.x)) { /* no geometry at all */
        lo = v3(-1, -1, -1);
        hi = v3(1, 1, 1);
    }
    /* Pad so that nothing lies exactly on the outer faces. */
    Vec3 ext = v3_sub(hi, lo);
    double pad = 1e-6 * fmax(1.0, fmax(ext.x, fmax(ext.y, ext.z)));
    lo = v3_sub(lo, v3(pad, pad, pad));
    hi = v3_add(hi, v3(pad, pad, pad));
    int r[3];
    if (res)
        memcpy(r, res, sizeof r);
    else
        grid_choose_resolution(w, lo, hi, r);
    g->min = lo;
    g->max = hi;
    grid_set_tolerance(g, GRID_TOLERANCE);
    for (int a = 0; a < 3; a++)
        g->n[a] = r[a] < 1 ? 1 : r[a];
    g->ncells = g->n[0] * g->n[1] * g->n[2];
    ext = v3_sub(hi, lo);
    g->cell_size = v3(ext.x / g->n[0], ext.y / g->n[1], ext.z / g->n[2]);
    g->inv_cell_size = v3(1.0 / g->cell_size.x, 1.0 / g->cell_size.y, 1.0 / g->cell_size.z);
}

/* The registrations of polygons [first, end), in polygon order and, per
 * polygon, in cell order: what one thread of grid_register makes. */
typedef struct {
    const Grid *g;
    const World *w;
    int first, end;
    Registration *regs;
    size_t count, cap;
    int failed;
} RegisterJob;

static int push_registration(RegisterJob *j, uint32_t cell, uint32_t polygon)
{
    if (j->count == j->cap) {
        size_t cap = j->cap ? j->cap * 2 : 1024;
        Registration *n = big_realloc(j->regs, cap * sizeof *n);
        if (!n)
            return -1;
        j->regs = n;
        j->cap = cap;
    }
    j->regs[j->count].cell = cell;
    j->regs[j->count].polygon = polygon;
    j->count++;
    return 0;
}

static void *register_polygons(void *arg)
{
    RegisterJob *j = arg;
    const Grid *g = j->g;
    const World *w = j->w;
    /* Cells are tested grown by a hair (below), so that a polygon lying on
     * a cell face is registered on both sides of it; the candidate cells
     * come from the polygon's box grown by the same hair, or a box starting
     * exactly on a boundary could be rounded into the upper cell only. */
    Vec3 hair = v3_scale(g->cell_size, 1e-9), lo = g->min;
    for (int pi = j->first; pi < j->end; pi++) {
        const Polygon *p = &w->polygons[pi];
        int c0[3], c1[3];
        for (int a = 0; a < 3; a++) {
            c0[a] = grid_cell_coord(g, v3_comp(p->bbox_min, a) - v3_comp(hair, a), a);
            c1[a] = grid_cell_coord(g, v3_comp(p->bbox_max, a) + v3_comp(hair, a), a);
        }
        int single = c0[0] == c1[0] && c0[1] == c1[1] && c0[2] == c1[2];
        for (int z = c0[2]; z <= c1[2]; z++)
            for (int y = c0[1]; y <= c1[1]; y++)
                for (int x = c0[0]; x <= c1[0]; x++) {
                    if (!single) {
                        Vec3 clo = v3(lo.x + x * g->cell_size.x, lo.y + y * g->cell_size.y, lo.z + z * g->cell_size.z);
                        Vec3 chi = v3_add(clo, g->cell_size);
                        if (!polygon_overlaps_box(w, p, v3_sub(clo, hair), v3_add(chi, hair)))
                            continue;
                    }
                    int c[3] = { x, y, z };
                    if (push_registration(j, (uint32_t)grid_cell_index(g, c), (uint32_t)pi)) {
                        j->failed = 1;
                        return NULL;
                    }
                }
    }
    return NULL;
}

/* Below this many polygons a thread's start costs more than its share. */
#define REGISTER_PER_THREAD_MIN 20000

int grid_register(Grid *g, const World *w, int threads)
{
    if (g->cell_start)
        return 0;
    int nt = parallel_jobs(w->npolygons, REGISTER_PER_THREAD_MIN, threads);
    RegisterJob jobs[PARALLEL_MAX_JOBS];
    /* Contiguous runs of polygons, one per thread: concatenated in thread
     * order they are the one thread's list, so the cells' lists below are
     * the same for any thread count. */
    for (int t = 0; t < nt; t++)
        jobs[t] = (RegisterJob){ g, w, (int)((long long)w->npolygons * t / nt),
                                 (int)((long long)w->npolygons * (t + 1) / nt), NULL, 0, 0, 0 };
    parallel_run(nt, register_polygons, jobs, sizeof jobs[0]);
    size_t count = 0;
    int failed = 0;
    for (int t = 0; t < nt; t++) {
        count += jobs[t].count;
        failed |= jobs[t].failed;
    }
    g->cell_start = failed ? NULL : big_calloc((size_t)g->ncells + 1, sizeof(uint32_t));
    g->items = g->cell_start ? big_malloc((count ? count : 1) * sizeof(uint32_t)) : NULL;
    uint32_t *fill = g->items ? big_malloc(((size_t)g->ncells + 1) * sizeof(uint32_t)) : NULL;
    if (count > UINT32_MAX || !fill) {
        for (int t = 0; t < nt; t++)
            free(jobs[t].regs);
        free(fill);
        free(g->cell_start);
        free(g->items);
        g->cell_start = NULL;
        g->items = NULL;
        return -1;
    }
    /* Counting sort into compressed rows: polygons keep index order per cell,
     * so walks and results do not depend on anything but the scene. */
    for (int t = 0; t < nt; t++)
        for (size_t i = 0; i < jobs[t].count; i++)
            g->cell_start[jobs[t].regs[i].cell + 1]++;
    for (int c = 0; c < g->ncells; c++)
        g->cell_start[c + 1] += g->cell_start[c];
    memcpy(fill, g->cell_start, ((size_t)g->ncells + 1) * sizeof(uint32_t));
    for (int t = 0; t < nt; t++) {
        for (size_t i = 0; i < jobs[t].count; i++)
            g->items[fill[jobs[t].regs[i].cell]++] = jobs[t].regs[i].polygon;
        free(jobs[t].regs);
    }
    g->nitems = count;
    free(fill);
    return 0;
}

long grid_count_registrations(const Grid *g, const World *w)
{
    RegisterJob j = { g, w, 0, w->npolygons, NULL, 0, 0, 0 };
    register_polygons(&j);
    free(j.regs);
    return j.failed ? -1 : (long)j.count;
}

int grid_build(Grid *g, const World *w, const int *res, const Vec3 *extra, int nextra)
{
    grid_build_box(g, w, res, extra, nextra);
    if (grid_register(g, w, 1)) {
        grid_free(g);
        return -1;
    }
    return 0;
}

int grid_extra_points(const World *w, Vec3 *out, int cap)
{
    int n = 0;
    if (n < cap)
        out[n++] = w->camera.location;
    if (!(w->bounds_min.x <= w->bounds_max.x))
        return n;
    Vec3 ext = v3_sub(w->bounds_max, w->bounds_min);
    double diagonal = v3_length(ext);
    for (int i = 0; i < w->nplanes && n + 8 <= cap; i++) {
        const InfinitePlane *pl = &w->planes[i];
        Vec3 corner[8];
        double nearest = HUGE_VAL;
        for (int k = 0; k < 8; k++) {
            corner[k] = v3(k & 1 ? w->bounds_max.x : w->bounds_min.x, k & 2 ? w->bounds_max.y : w->bounds_min.y,
                           k & 4 ? w->bounds_max.z : w->bounds_min.z);
            nearest = fmin(nearest, fabs(v3_dot(pl->normal, corner[k]) - pl->d));
        }
        /* Only planes near the geometry: a far one would stretch the grid. */
        if (nearest > diagonal)
            continue;
        for (int k = 0; k < 8; k++)
            out[n++] = v3_madd(corner[k], pl->normal, pl->d - v3_dot(pl->normal, corner[k]));
    }
    return n;
}

void grid_set_tolerance(Grid *g, double relative)
{
    double m = fmax(fmax(fabs(g->min.x), fabs(g->max.x)),
                    fmax(fmax(fabs(g->min.y), fabs(g->max.y)), fmax(fabs(g->min.z), fabs(g->max.z))));
    g->tolerance = relative * (1.0 + m);
}

void grid_free(Grid *g)
{
    free(g->cell_start);
    free(g->items);
    memset(g, 0, sizeof *g);
}

int grid_walk_begin(const Grid *g, Vec3 org, Vec3 dir, double t0, double t1, GridWalk *walk)
{
    /* Clip [t0, t1] to the grid box (slabs). */
    double o[3] = { org.x, org.y, org.z }, d[3] = { dir.x, dir.y, dir.z };
    double lo[3] = { g->min.x, g->min.y, g->min.z }, hi[3] = { g->max.x, g->max.y, g->max.z };
    /* No walk for a ray that goes nowhere: a NaN anywhere, or no direction
     * (toward a light 1e308 away, the normalised direction underflows to
     * zero), which would step through no cell boundary for ever. */
    if (isnan(o[0] + o[1] + o[2] + d[0] + d[1] + d[2] + t0 + t1) || (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0))
        return 0;
    for (int a = 0; a < 3; a++) {
        if (d[a] == 0.0) {
            if (o[a] < lo[a] || o[a] > hi[a])
                return 0;
            continue;
        }
        double inv = 1.0 / d[a];
        double ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
        if (ta > tb) { double t = ta; ta = tb; tb = t; }
        if (ta > t0) t0 = ta;
        if (tb < t1) t1 = tb;
        if (t0 > t1)
            return 0;
    }
    walk->t_enter = t0;
    walk->t_end = t1;
    double cs[3] = { g->cell_size.x, g->cell_size.y, g->cell_size.z };
    for (int a = 0; a < 3; a++) {
        double p = o[a] + d[a] * t0;
        int c = int_floor_clamped((p - lo[a]) / cs[a], 0, g->n[a] - 1);
        walk->cell[a] = c;
        if (d[a] > 0.0) {
            walk->step[a] = 1;
            walk->t_next[a] = (lo[a] + (c + 1) * cs[a] - o[a]) / d[a];
            walk->t_delta[a] = cs[a] / d[a];
        } else if (d[a] < 0.0) {
            walk->step[a] = -1;
            walk->t_next[a] = (lo[a] + c * cs[a] - o[a]) / d[a];
            walk->t_delta[a] = -cs[a] / d[a];
        } else {
            walk->step[a] = 0;
            walk->t_next[a] = HUGE_VAL;
            walk->t_delta[a] = HUGE_VAL;
        }
    }
    return 1;
}
