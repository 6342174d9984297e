/* Uniform space subdivision (Fujimoto's ARTS): the box around the finite
 * geometry is cut into cells, every polygon is registered in exactly the
 * cells it overlaps, and rays walk the cells in order with 3DDDA. */
#ifndef HST_GRID_H
#define HST_GRID_H

#include <stdint.h>

#include "convert.h"
#include "world.h"

typedef struct {
    Vec3 min, max;      /* the grid box */
    Vec3 cell_size;
    Vec3 inv_cell_size;
    int n[3];           /* cells per axis */
    int ncells;
    uint32_t *cell_start; /* ncells + 1 offsets into items */
    uint32_t *items;      /* polygon indices, grouped by cell */
    size_t nitems;
    double tolerance;     /* see grid_tolerance */
} Grid;

/* Cells per axis from the polygon count and the box's shape, aiming at about
 * eight cells per polygon (measured best of 2, 8, 16, 32 on the project's scenes). */
void grid_choose_resolution(const World *w, Vec3 box_min, Vec3 box_max, int res[3]);

/* Builds the grid over the box holding all polygons and the extra points
 * (the camera, the lights: whatever rays may start from). `res` NULL picks
 * the resolution with grid_choose_resolution. Returns 0, or -1 when out of
 * memory. grid_build_box then grid_register, on one thread. */
int grid_build(Grid *g, const World *w, const int *res, const Vec3 *extra, int nextra);
/* The box and its cells alone: no polygon registered (cell_start and items
 * NULL). A render whose queries all go through the hierarchy (bvh.h) needs
 * no more: only the shadow volumes' calibration and pixel coherence, and
 * the grid's own walks (the reference the hierarchy is tested against),
 * read the registrations; on 10^6 triangles they cost some 8% of a
 * render and 50 MB. */
void grid_build_box(Grid *g, const World *w, const int *res, const Vec3 *extra, int nextra);
/* Registers every polygon in the cells it overlaps, on up to `threads`
 * threads (the same lists, in the same order, for any number); nothing to
 * do when they are registered already. Returns 0, or -1 when out of
 * memory (the grid is then left unregistered). */
int grid_register(Grid *g, const World *w, int threads);
static inline int grid_registered(const Grid *g) { return g->cell_start != NULL; }
/* How many registrations w's polygons would make in g's cells (w may be a
 * sample of g's world), found as grid_register finds them and not kept:
 * the shadow volumes' cost estimate times it. -1 when out of memory. */
long grid_count_registrations(const Grid *g, const World *w);
void grid_free(Grid *g);

/* Points the grid box must hold besides the polygons: the camera, and the
 * corners of the polygons' box projected onto each infinite plane (so that
 * shadows falling on a floor are inside). Returns how many were written. */
int grid_extra_points(const World *w, Vec3 *out, int cap);

/* Exact overlap of polygon p with the axis-aligned box [lo, hi] (polygon
 * clipped against the box; holes are ignored, which only over-registers). */
int polygon_overlaps_box(const World *w, const Polygon *p, Vec3 lo, Vec3 hi);

/* Sutherland-Hodgman: clips the outline in[0..n) against the half space
 * where coordinate `axis` is >= bound (sign > 0) or <= bound (sign < 0);
 * out needs room for n + 1 points. Returns the new point count. Inline:
 * a shadow polygon's registration clips it some thirty times, each on an
 * axis and side the caller knows. */
static inline int clip_against(const Vec3 *in, int n, Vec3 *out, int axis, double bound, int sign)
{
    int m = 0;
    if (n <= 0)
        return 0;
    /* each point's signed distance once: the next edge starts where this one ends */
    double d0 = sign * (v3_comp(in[0], axis) - bound), da = d0;
    for (int i = 0; i < n; i++) {
        const Vec3 *a = &in[i], *b = &in[i + 1 < n ? i + 1 : 0];
        double db = i + 1 < n ? sign * (v3_comp(*b, axis) - bound) : d0;
        if (da >= 0)
            out[m++] = *a;
        if ((da >= 0) != (db >= 0)) {
            double t = da / (da - db);
            out[m++] = v3_add(*a, v3_scale(v3_sub(*b, *a), t));
        }
        da = db;
    }
    return m;
}

/* Overlap of a planar outline of at most 8 points with [lo, hi] (exact
 * clipping; longer outlines are taken to overlap). */
int outline_overlaps_box(const Vec3 *pts, int n, Vec3 lo, Vec3 hi);

/* The cell coordinate holding x on `axis`, clamped to the grid (inline:
 * registration asks it several times per shadow polygon). */
static inline int grid_cell_coord(const Grid *g, double x, int axis)
{
    return int_floor_clamped((x - v3_comp(g->min, axis)) * v3_comp(g->inv_cell_size, axis), 0, g->n[axis] - 1);
}

/* Distances below this are too close to call: shadow tests treat such
 * configurations by one rule (fall back to the shadow ray; edge-on polygons
 * cast nothing). GRID_TOLERANCE times one plus the grid box's largest
 * coordinate (about a million ulps of it) unless set otherwise. */
#define GRID_TOLERANCE 1e-9
static inline double grid_tolerance(const Grid *g) { return g->tolerance; }
/* Sets the tolerance to `relative` times one plus the box's largest coordinate. */
void grid_set_tolerance(Grid *g, double relative);

/* A 3DDDA walk along org + t*dir for t in [t0, t1]. */
typedef struct {
    int cell[3];
    int step[3];
    double t_next[3];   /* t at which the walk crosses the next boundary on each axis */
    double t_delta[3];  /* t between boundaries on each axis */
    double t_enter;     /* t at which the current cell was entered */
    double t_end;
} GridWalk;

/* Starts a walk; returns 0 when the segment misses the grid box. */
int grid_walk_begin(const Grid *g, Vec3 org, Vec3 dir, double t0, double t1, GridWalk *walk);

static inline int grid_cell_index(const Grid *g, const int c[3])
{
    return (c[2] * g->n[1] + c[1]) * g->n[0] + c[0];
}

/* t at which the walk leaves the current cell. */
static inline double grid_walk_exit(const GridWalk *walk)
{
    double t = walk->t_next[0];
    if (walk->t_next[1] < t) t = walk->t_next[1];
    if (walk->t_next[2] < t) t = walk->t_next[2];
    return t;
}

/* Moves to the next cell; returns 0 when the walk has left the grid or passed t1. */
static inline int grid_walk_next(const Grid *g, GridWalk *walk)
{
    int axis = 0;
    if (walk->t_next[1] < walk->t_next[axis]) axis = 1;
    if (walk->t_next[2] < walk->t_next[axis]) axis = 2;
    double t = walk->t_next[axis];
    if (t > walk->t_end)
        return 0;
    walk->cell[axis] += walk->step[axis];
    if (walk->cell[axis] < 0 || walk->cell[axis] >= g->n[axis])
        return 0;
    walk->t_enter = t;
    walk->t_next[axis] += walk->t_delta[axis];
    return 1;
}

#endif
