/* Nearest-hit queries through the grid, and the planes beside it. */
#include "tracer.h"

#include <stdlib.h>
#include <string.h>

#include "intersect.h"

void ray_counters_add(RayCounters *t, const RayCounters *p)
{
    t->polygon_tests += p->polygon_tests;
    t->polygon_hits += p->polygon_hits;
    t->plane_tests += p->plane_tests;
    t->cells_visited += p->cells_visited;
}

int tracer_init(Tracer *t, const World *w, const Grid *g)
{
    memset(t, 0, sizeof *t);
    t->world = w;
    t->grid = g;
    t->stamp = calloc((size_t)(w->npolygons > 0 ? w->npolygons : 1), sizeof(uint32_t));
    return t->stamp ? 0 : -1;
}

int tracer_record_cells(Tracer *t, Vec3 box_min, Vec3 box_max)
{
    /* A 3DDDA walk visits at most one cell per boundary crossed. */
    t->segment_cells_cap = t->grid->n[0] + t->grid->n[1] + t->grid->n[2] + 3;
    t->segment_cells = malloc(sizeof(uint32_t) * (size_t)t->segment_cells_cap);
    t->record_min = box_min;
    t->record_max = box_max;
    return t->segment_cells ? 0 : -1;
}

void tracer_free(Tracer *t)
{
    free(t->stamp);
    free(t->segment_cells);
    t->stamp = NULL;
    t->segment_cells = NULL;
}

/* The uncached part of trace_point_touches_other. */
static int touches_other(Tracer *t, const Hit *hit, double tol)
{
    const World *w = t->world;
    const Grid *g = t->grid;
    if (hit->kind == HIT_POLYGON && polygon_classify_point(w, &w->polygons[hit->index], hit->point, tol) < 0)
        return 1; /* on its own polygon's border: on the neighbours' too */
    /* Every cell within tol of the point (usually one). A point beyond the
     * grid's box touches nothing: the box holds every polygon. (Hits on an
     * infinite plane near the horizon lie there, 1e16 units away.) */
    for (int a = 0; a < 3; a++)
        if (!(v3_comp(hit->point, a) + tol >= v3_comp(g->min, a) && v3_comp(hit->point, a) - tol <= v3_comp(g->max, a)))
            return 0;
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = grid_cell_coord(g, v3_comp(hit->point, a) - tol, a);
        hi[a] = grid_cell_coord(g, v3_comp(hit->point, a) + tol, a);
    }
    uint32_t id = trace_new_segment(t);
    if (hit->kind == HIT_POLYGON)
        t->stamp[hit->index] = id;
    for (int z = lo[2]; z <= hi[2]; z++)
        for (int y = lo[1]; y <= hi[1]; y++)
            for (int x = lo[0]; x <= hi[0]; x++) {
                int c[3] = { x, y, z };
                int ci = grid_cell_index(g, c);
                for (uint32_t k = g->cell_start[ci]; k < g->cell_start[ci + 1]; k++) {
                    uint32_t pi = g->items[k];
                    if (!bucket_admit(t, id, pi))
                        continue;
                    const Polygon *p = &w->polygons[pi];
                    if (fabs(v3_dot(p->normal, hit->point) - p->d) <= tol && polygon_classify_point(w, p, hit->point, tol) != 0)
                        return 1;
                }
            }
    return 0;
}

int trace_point_touches_other(Tracer *t, const Hit *hit, double tol)
{
    if (t->touch_valid && t->touch_kind == (int)hit->kind && t->touch_index == hit->index &&
        t->touch_point.x == hit->point.x && t->touch_point.y == hit->point.y && t->touch_point.z == hit->point.z)
        return t->touch_result;
    t->touch_valid = 1;
    t->touch_kind = (int)hit->kind;
    t->touch_index = hit->index;
    t->touch_point = hit->point;
    t->touch_result = touches_other(t, hit, tol);
    return t->touch_result;
}

static int inside_box(Vec3 lo, Vec3 hi, Vec3 p)
{
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
}

static int material_hidden(const Material *m, unsigned hide)
{
    return ((hide & HIDE_NO_IMAGE) && m->no_image) || ((hide & HIDE_NO_REFLECTION) && m->no_reflection);
}

int trace_nearest(Tracer *tr, Vec3 org, Vec3 dir, double tmax, const Hit *from, Hit *hit)
{
    const World *w = tr->world;
    const Grid *g = tr->grid;
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
        if (tr->hide && material_hidden(&w->materials[w->planes[i].material], tr->hide))
            continue;
        tr->stats.plane_tests++;
        double t = intersect_plane(&w->planes[i], org, dir);
        if (t > tmin && t < plane_t) {
            plane_t = t;
            plane = i;
        }
    }

    double best = HUGE_VAL;
    GridWalk walk;
    int gather = tr->segment_cells != NULL, overflow = 0;
    if (gather)
        tr->segment_ncells = 0;
    if ((w->npolygons > 0 || gather) && grid_walk_begin(g, org, dir, 0.0, plane_t, &walk)) {
        uint32_t id = trace_new_segment(tr);
        RayFrame frame = ray_frame(org, dir);
        int exclude = (from && from->kind == HIT_POLYGON) ? from->index : -1;
        if (exclude >= 0)
            tr->stamp[exclude] = id;
        do {
            tr->stats.cells_visited++;
            int c = grid_cell_index(g, walk.cell);
            if (gather) {
                if (tr->segment_ncells < tr->segment_cells_cap)
                    tr->segment_cells[tr->segment_ncells++] = (uint32_t)c;
                else
                    overflow = 1; /* cannot happen with 3DDDA; distrust the bucket if it did */
            }
            for (uint32_t k = g->cell_start[c]; k < g->cell_start[c + 1]; k++) {
                uint32_t pi = g->items[k];
                if (!bucket_admit(tr, id, pi))
                    continue;
                if (tr->hide && material_hidden(&w->materials[w->polygons[pi].material], tr->hide))
                    continue;
                tr->stats.polygon_tests++;
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
        tr->stats.polygon_hits++;
    }
    hit->t = best;
    hit->point = v3_madd(org, dir, best);
    /* The walk covered the whole segment only when its end is in the box. */
    if (gather)
        tr->segment_in_box = !overflow && inside_box(tr->record_min, tr->record_max, hit->point) &&
                            inside_box(tr->record_min, tr->record_max, org);
    return 1;
}
