/* Calibrating the cost model on the running machine and scene. */
#include "cost_model.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <limits.h>

#include "camera.h"
#include "clock.h"
#include "intersect.h"
#include "shadow.h"
#include "shadow_bucket.h"
#include "tracer.h"

#define SAMPLE_GRID 24      /* camera rays per axis whose hits are the sample points */
#define SAMPLES (SAMPLE_GRID * SAMPLE_GRID)
#define MIN_TIMING 0.0002   /* seconds each round of a cost is timed for, at least */
#define ROUNDS 3            /* rounds per cost; the fastest counts */

/* A quick calibration (only N_th's costs, for a trial) times less. */
static int rounds_of(int full)
{
    return full ? ROUNDS : 2;
}

static double min_timing_of(int full)
{
    return full ? MIN_TIMING : MIN_TIMING / 2;
}

typedef struct {
    uint64_t s;
} Rng;

static uint64_t rng_next(Rng *r)
{
    r->s ^= r->s << 13;
    r->s ^= r->s >> 7;
    r->s ^= r->s << 17;
    return r->s;
}

static double rng_unit(Rng *r)
{
    return (double)(rng_next(r) >> 11) * (1.0 / 9007199254740992.0);
}

/* A point on polygon pi (in the triangle of its first three points). */
static Vec3 point_on(const World *w, int pi, Rng *r)
{
    const Polygon *p = &w->polygons[pi];
    const Vec3 *v = &w->points[p->first_point];
    double a = rng_unit(r), b = rng_unit(r);
    if (a + b > 1.0) {
        a = 1.0 - a;
        b = 1.0 - b;
    }
    return v3_add(v[0], v3_add(v3_scale(v3_sub(v[1], v[0]), a), v3_scale(v3_sub(v[2], v[0]), b)));
}

typedef struct {
    Vec3 org, dir;
    double tmax;
    int from;
} SampleRay;

typedef struct {
    SampleRay ray;
    int polygon;
} SampleTest;

int cost_model_cells_to_light(const Grid *g, Vec3 p, const Light *l)
{
    Vec3 target;
    if (l->kind == LIGHT_PARALLEL) {
        /* Where the ray toward the light leaves the box. */
        double t = HUGE_VAL;
        for (int a = 0; a < 3; a++) {
            double d = v3_comp(l->direction, a);
            if (d > 0.0)
                t = fmin(t, (v3_comp(g->max, a) - v3_comp(p, a)) / d);
            else if (d < 0.0)
                t = fmin(t, (v3_comp(g->min, a) - v3_comp(p, a)) / d);
        }
        target = t < HUGE_VAL ? v3_madd(p, l->direction, fmax(t, 0.0)) : p;
    } else {
        target = l->location;
    }
    int n = 1;
    for (int a = 0; a < 3; a++) {
        int c0 = grid_cell_coord(g, v3_comp(p, a), a), c1 = grid_cell_coord(g, v3_comp(target, a), a);
        n += c0 > c1 ? c0 - c1 : c1 - c0;
    }
    return n;
}

double cost_model_threshold(const CostModel *m, double n_c)
{
    double p = m->p, alpha = m->alpha;
    double n_o = alpha * n_c;
    double cv;
    if (p <= 0.0 || alpha <= 0.0) {
        /* The limit p -> 0: every cell and every polygon is visited. */
        cv = m->c_i + m->c_c * n_c + m->c_o * n_o;
    } else {
        double q = log1p(-fmin(p, 1.0 - 1e-12));           /* ln(1 - p) */
        double reach = -expm1(q * n_o);                      /* 1 - (1-p)^N_o */
        double per_cell = -expm1(q * alpha);                 /* 1 - (1-p)^alpha */
        cv = m->c_i + reach * (m->c_c / per_cell + m->c_o / p);
    }
    return m->c_s > 0.0 ? cv / m->c_s : HUGE_VAL;
}

/* Walks one shadow ray to its end, counting cells, new polygons, hits. */
static void sample_walk(const World *w, const Grid *g, uint32_t *stamp, uint32_t id, const SampleRay *s, long *cells,
                        long *tests, long *hits, SampleTest *keep, int *nkeep, int cap)
{
    GridWalk walk;
    if (!grid_walk_begin(g, s->org, s->dir, 0.0, s->tmax, &walk))
        return;
    stamp[s->from] = id;
    double tmin = 1e-9 * (1.0 + fmax(fabs(s->org.x), fmax(fabs(s->org.y), fabs(s->org.z))));
    do {
        (*cells)++;
        int c = grid_cell_index(g, walk.cell);
        for (uint32_t k = g->cell_start[c]; k < g->cell_start[c + 1]; k++) {
            uint32_t pi = g->items[k];
            if (stamp[pi] == id)
                continue;
            stamp[pi] = id;
            (*tests)++;
            double t = intersect_polygon(w, &w->polygons[pi], s->org, s->dir);
            if (t > tmin && t < s->tmax)
                (*hits)++;
            if (*nkeep < cap)
                keep[(*nkeep)++] = (SampleTest){ *s, (int)pi };
        }
    } while (grid_walk_next(g, &walk));
}

/* The shadow ray's stopping rule, for timing it: the first opaque polygon. */
static int stop_at_opaque(void *user, uint32_t polygon, double t)
{
    const World *w = user;
    (void)t;
    return w->materials[w->polygons[polygon].material].opaque;
}

/* C_ray: the exact shadow ray through the hierarchy on the sample rays. */
static double time_shadow_rays(const World *w, const Grid *g, const Bvh *bvh, const SampleRay *rays, int nrays,
                               volatile double *sink, int full)
{
    Tracer t;
    if (tracer_init(&t, w, g)) {
        tracer_free(&t);
        return 0.0;
    }
    tracer_use_bvh(&t, bvh);
    double best = HUGE_VAL;
    for (int round = 0; round < rounds_of(full); round++) {
        long n = 0;
        double t0 = clock_thread_cpu(), dt;
        do {
            for (int i = 0; i < nrays; i++) {
                uint64_t tests = 0;
                *sink += trace_segment_hits(&t, rays[i].org, rays[i].dir, trace_min_distance(rays[i].org),
                                            rays[i].tmax, rays[i].from, HIDE_NO_SHADOW, stop_at_opaque, (void *)w,
                                            &tests);
            }
            n += nrays;
        } while ((dt = clock_thread_cpu() - t0) < min_timing_of(full));
        best = fmin(best, dt / (double)n);
    }
    tracer_free(&t);
    return best;
}

/* C_g: gathering the shadow polygons of the cells that camera segments
 * pierce into buckets, per polygon gathered. */
static double time_gathering(const World *w, const Grid *g, const ShadowVolumes *sv, int width, int height,
                             const int *lights, int nlights, volatile double *sink, int full)
{
    /* the volume methods' thread state: the buckets and the cells recorded */
    ShadowContext ctx;
    ShadowPrepared p = { .volumes = (ShadowVolumes *)sv };
    if (shadow_context_init(&ctx, NULL, w, g, &p, 0, 0) || shadow_volume_thread_init(&ctx, &p, 0)) {
        shadow_volume_thread_free(&ctx);
        shadow_context_free(&ctx);
        return 0.0;
    }
    /* The cells of camera segments through a coarse grid of pixels. */
    enum { SEGMENTS = 64 };
    int cap = ctx.tracer->segment_cells_cap;
    uint32_t *cells = malloc(sizeof *cells * (size_t)cap * SEGMENTS);
    int ncells[SEGMENTS], nseg = 0;
    for (int i = 0; cells && i < SEGMENTS; i++) {
        Vec3 org, dir;
        if (!camera_ray(&w->camera, width, height, (i % 8 * 2 + 1) * width / 16, (i / 8 * 2 + 1) * height / 16,
                        &org, &dir))
            continue;
        Hit from = { HIT_NONE, -1, 0.0, org, -1, 0 }, hit;
        if (!trace_nearest(ctx.tracer, org, dir, HUGE_VAL, &from, &hit))
            continue;
        memcpy(&cells[(size_t)nseg * (size_t)cap], ctx.tracer->segment_cells,
               sizeof *cells * (size_t)ctx.tracer->segment_ncells);
        ncells[nseg++] = ctx.tracer->segment_ncells;
    }
    double best = 0.0;
    if (nseg > 0) {
        best = HUGE_VAL;
        for (int round = 0; round < rounds_of(full); round++) {
            long gathered = 0;
            double t0 = clock_thread_cpu(), dt;
            do {
                for (int i = 0; i < nseg; i++) {
                    int light = lights[i % nlights];
                    gathered += shadow_bucket_fill_in(&ctx, light, &cells[(size_t)i * (size_t)cap], ncells[i], INT_MAX);
                }
                *sink += (double)gathered;
            } while ((dt = clock_thread_cpu() - t0) < min_timing_of(full));
            best = gathered > 0 ? fmin(best, dt / (double)gathered) : 0.0;
        }
    }
    free(cells);
    shadow_volume_thread_free(&ctx);
    shadow_context_free(&ctx);
    return best < HUGE_VAL ? best : 0.0;
}

static int calibrate(CostModel *m, const World *w, const Grid *g, const Bvh *bvh, const ShadowVolumes *sv, int width,
                     int height, int full)
{
    memset(m, 0, sizeof *m);
    double start = clock_wall();
    int lights[64], nlights = 0;
    for (int i = 0; i < w->nlights && nlights < 64; i++)
        if (!w->lights[i].shadowless)
            lights[nlights++] = i;
    if (w->npolygons == 0 || nlights == 0) {
        m->nth = 0.0;
        m->seconds = clock_wall() - start;
        return 0;
    }
    SampleRay *rays = malloc(sizeof *rays * SAMPLES);
    SampleTest *tests = malloc(sizeof *tests * 4096);
    uint32_t *stamp = calloc((size_t)w->npolygons, sizeof *stamp);
    if (!rays || !tests || !stamp) {
        free(rays);
        free(tests);
        free(stamp);
        return -1;
    }
    /* The sample points are where camera rays through a coarse grid of
     * pixels land: shadow rays start where the render's will. */
    Rng rng = { 0x9E3779B97F4A7C15ull };
    Tracer tc;
    if (tracer_init(&tc, w, g)) {
        tracer_free(&tc);
        free(rays);
        free(tests);
        free(stamp);
        return -1;
    }
    int nrays = 0;
    for (int i = 0; i < SAMPLES; i++) {
        Vec3 org, dir;
        int px = (int)((i % SAMPLE_GRID + rng_unit(&rng)) * width / SAMPLE_GRID);
        int py = (int)((i / SAMPLE_GRID + rng_unit(&rng)) * height / SAMPLE_GRID);
        if (!camera_ray(&w->camera, width, height, px, py, &org, &dir))
            continue;
        Hit from = { HIT_NONE, -1, 0.0, org, -1, 0 }, hit;
        if (!trace_nearest(&tc, org, dir, HUGE_VAL, &from, &hit) || hit.kind != HIT_POLYGON)
            continue;
        const Light *l = &w->lights[lights[rng_next(&rng) % (uint64_t)nlights]];
        SampleRay *s = &rays[nrays++];
        s->org = hit.point;
        s->from = hit.index;
        if (l->kind == LIGHT_PARALLEL) {
            s->dir = l->direction;
            s->tmax = HUGE_VAL;
        } else {
            Vec3 d = v3_sub(l->location, s->org);
            s->tmax = v3_length(d);
            s->dir = s->tmax > 0.0 ? v3_scale(d, 1.0 / s->tmax) : v3(0, 1, 0);
        }
    }
    tracer_free(&tc);
    /* A view of planes only: sample points on random polygons instead. */
    for (int i = 0; nrays < SAMPLES / 4 && i < SAMPLES; i++) {
        int pi = (int)(rng_next(&rng) % (uint64_t)w->npolygons);
        const Light *l = &w->lights[lights[rng_next(&rng) % (uint64_t)nlights]];
        SampleRay *s = &rays[nrays++];
        s->org = point_on(w, pi, &rng);
        s->from = pi;
        s->dir = l->kind == LIGHT_PARALLEL ? l->direction : v3_normalize(v3_sub(l->location, s->org));
        s->tmax = l->kind == LIGHT_PARALLEL ? HUGE_VAL : v3_length(v3_sub(l->location, s->org));
    }

    /* p, alpha and N_c from whole walks to the light. */
    long cells = 0, ntests = 0, hits = 0;
    int nkeep = 0;
    for (int i = 0; full && i < nrays; i++)
        sample_walk(w, g, stamp, (uint32_t)i + 1, &rays[i], &cells, &ntests, &hits, tests, &nkeep, 4096);
    m->samples = nrays;
    m->n_c = nrays > 0 ? (double)cells / nrays : 0.0;
    m->alpha = cells > 0 ? (double)ntests / (double)cells : 0.0;
    m->p = ntests > 0 ? (double)hits / (double)ntests : 0.0;
    m->n_o = m->alpha * m->n_c;

    /* Each cost is the fastest of ROUNDS timings on the thread's CPU clock:
     * on a shared machine a timing can only be slowed down (preempted,
     * caches flushed by others), never sped up, and eq. 7 turns a C_o
     * inflated by one preemption into an N_th off by a factor of ten. */
    volatile double sink = 0.0;
    /* C_o: ray/polygon tests on the pairs the walks met. */
    if (full && nkeep > 0) {
        m->c_o = HUGE_VAL;
        for (int round = 0; round < rounds_of(full); round++) {
            long n = 0;
            double t0 = clock_thread_cpu(), t;
            do {
                for (int i = 0; i < nkeep; i++)
                    sink += intersect_polygon(w, &w->polygons[tests[i].polygon], tests[i].ray.org, tests[i].ray.dir);
                n += nkeep;
            } while ((t = clock_thread_cpu() - t0) < min_timing_of(full));
            m->c_o = fmin(m->c_o, t / (double)n);
        }
    }
    /* C_i and C_c: walk set-ups, then whole walks; C_c is the difference
     * per cell step, both timed in alternation so drifts cancel. */
    if (full && nrays > 0) {
        m->c_i = m->c_c = HUGE_VAL;
        for (int round = 0; round < rounds_of(full); round++) {
            long n = 0, steps = 0;
            double t_begin = 0.0, t_walk = 0.0;
            GridWalk walk;
            do {
                double t0 = clock_thread_cpu();
                for (int i = 0; i < nrays; i++)
                    sink += grid_walk_begin(g, rays[i].org, rays[i].dir, 0.0, rays[i].tmax, &walk);
                double t1 = clock_thread_cpu();
                for (int i = 0; i < nrays; i++) {
                    if (!grid_walk_begin(g, rays[i].org, rays[i].dir, 0.0, rays[i].tmax, &walk))
                        continue;
                    while (grid_walk_next(g, &walk))
                        steps++;
                    sink += walk.cell[0];
                }
                t_walk += clock_thread_cpu() - t1;
                t_begin += t1 - t0;
                n += nrays;
            } while (t_begin + t_walk < 2 * min_timing_of(full));
            m->c_i = fmin(m->c_i, t_begin / (double)n);
            m->c_c = fmin(m->c_c, steps > 0 ? fmax(t_walk - t_begin, 0.0) / (double)steps : 0.0);
        }
    }
    /* C_s: segment/shadow polygon tests on the scene's shadow polygons. */
    if (sv && sv->npolygons > 0 && nrays > 1) {
        m->c_s = HUGE_VAL;
        int sign = 0;
        for (int round = 0; round < rounds_of(full); round++) {
            long n = 0;
            double t0 = clock_thread_cpu(), t;
            do {
                for (int i = 0; i + 1 < nrays; i++) {
                    const ShadowPolygon *sp = &sv->polygons[(size_t)i * 7919u % (size_t)sv->npolygons];
                    sink += shadow_polygon_cross(sp, rays[i].org, rays[i + 1].org, sv->tolerance, &sign) + sign;
                }
                n += nrays - 1;
            } while ((t = clock_thread_cpu() - t0) < min_timing_of(full));
            m->c_s = fmin(m->c_s, t / (double)n);
        }
    }
    if (bvh && nrays > 0)
        m->c_ray = time_shadow_rays(w, g, bvh, rays, nrays, &sink, full);
    if (sv && sv->npolygons > 0)
        m->c_g = time_gathering(w, g, sv, width, height, lights, nlights, &sink, full);
    (void)sink;
    free(rays);
    free(tests);
    free(stamp);
    m->nth = full ? cost_model_threshold(m, m->n_c) : 0.0;
    m->nth_ray = m->c_ray > 0.0 && m->c_s + m->c_g > 0.0 ? m->c_ray / (m->c_s + m->c_g) : m->nth;
    m->full = full;
    m->seconds = clock_wall() - start;
    return 0;
}

int cost_model_calibrate(CostModel *m, const World *w, const Grid *g, const Bvh *bvh, const ShadowVolumes *sv,
                         int width, int height)
{
    return calibrate(m, w, g, bvh, sv, width, height, 1);
}

int cost_model_calibrate_threshold(CostModel *m, const World *w, const Grid *g, const Bvh *bvh,
                                   const ShadowVolumes *sv, int width, int height)
{
    return calibrate(m, w, g, bvh, sv, width, height, 0);
}
