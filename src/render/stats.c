/* Statistics: summing per-thread counters and printing the report. */
#include "stats.h"

#include "json_write.h"

#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "cost_model.h"
#include "light_buffer.h"
#include "shadow.h"
#include "shadow_embree.h"
#include "shadow_volumes.h"
#include "volume_plan.h"

void stats_add(RenderStats *t, const RenderStats *p)
{
    t->pixels += p->pixels;
    t->camera_rays += p->camera_rays;
    ray_counters_add(&t->rays, &p->rays);
    shade_counters_add(&t->shading, &p->shading);
    shadow_counters_add(&t->shadow, &p->shadow);
    t->render_seconds += p->render_seconds;
    if (p->coincident_pair != 0 && (t->coincident_pair == 0 || p->coincident_pair < t->coincident_pair))
        t->coincident_pair = p->coincident_pair;
}

/* The render's counters, one row each, from the rooms' own lists
 * (ray_counters.def, shade_counters.def, shadow_counters.def): the same
 * table makes the --stats lines and the JSON's objects. */
typedef enum {
    LINE_RAYS, LINE_TESTS, LINE_SHADOWS, LINE_COUNTING, LINE_FALLBACKS, LINE_COHERENCE, LINE_BUFFER, LINE_AREA,
    LINE_VERIFY, LINE_REFERENCE
} StatsLine;

typedef struct {
    StatsLine line;
    const char *label; /* in --stats */
    const char *key;   /* in the JSON */
    size_t offset;     /* of the uint64_t in RenderStats */
} CounterRow;

static const CounterRow counter_rows[] = {
    { LINE_RAYS, "camera", "camera", offsetof(RenderStats, camera_rays) },
#define SHADE_COUNTER(field, line, label, key, meaning) \
    { LINE_##line, label, key, offsetof(RenderStats, shading) + offsetof(ShadeCounters, field) },
#include "shade_counters.def"
#undef SHADE_COUNTER
#define RAY_COUNTER(field, line, label, key, meaning) \
    { LINE_##line, label, key, offsetof(RenderStats, rays) + offsetof(RayCounters, field) },
#include "ray_counters.def"
#undef RAY_COUNTER
#define SHADOW_COUNTER(field, line, label, key, meaning) \
    { LINE_##line, label, key, offsetof(RenderStats, shadow) + offsetof(ShadowCounters, field) },
#include "shadow_counters.def"
#undef SHADOW_COUNTER
};

#define NROWS (sizeof counter_rows / sizeof counter_rows[0])

static unsigned long long counter_value(const RenderStats *s, const CounterRow *row)
{
    uint64_t v;
    memcpy(&v, (const char *)s + row->offset, sizeof v);
    return (unsigned long long)v;
}

static int line_nonzero(const RenderStats *s, StatsLine line)
{
    for (size_t i = 0; i < NROWS; i++)
        if (counter_rows[i].line == line && counter_value(s, &counter_rows[i]))
            return 1;
    return 0;
}

/* One --stats line: its title, then each counter of the line. */
static void print_line(FILE *f, const char *title, const RenderStats *s, StatsLine line)
{
    fprintf(f, "  %-11s", title);
    const char *sep = " ";
    for (size_t i = 0; i < NROWS; i++) {
        if (counter_rows[i].line != line)
            continue;
        fprintf(f, "%s%s %llu", sep, counter_rows[i].label, counter_value(s, &counter_rows[i]));
        sep = "  ";
    }
    fprintf(f, "\n");
}

/* The JSON's members for the counters of lines [first, last], each
 * preceded by sep (the first by first_sep). */
static void json_counters(FILE *f, const RenderStats *s, StatsLine first, StatsLine last, const char *first_sep,
                          const char *sep)
{
    for (size_t i = 0; i < NROWS; i++) {
        if (counter_rows[i].line < first || counter_rows[i].line > last)
            continue;
        fprintf(f, "%s\"%s\": %llu", first_sep, counter_rows[i].key, counter_value(s, &counter_rows[i]));
        first_sep = sep;
    }
}

/* v with 3 decimals, or null where it is not finite (JSON has no infinity). */
static void finite_or_null(char *buf, size_t size, double v)
{
    if (isfinite(v))
        snprintf(buf, size, "%.3f", v);
    else
        snprintf(buf, size, "null");
}

/* "Others" is the render loop's CPU time that was not shadow testing, plus
 * writing the image: the paper's split (finding hits, shading, output). */
static double others_seconds(const StatsReport *r)
{
    double o = r->render.render_seconds - r->render.shadow.shadow_seconds;
    return (o > 0 ? o : 0) + r->output_seconds;
}

/* Which lights got shadow volumes, and what the cost model measured to
 * decide it (volume_plan.h). */
static void print_plan(FILE *f, const VolumePlan *p)
{
    if (p->mode == VOLUMES_ALWAYS) {
        fprintf(f, "  volume plan every light's volumes built (--volumes always)\n");
        return;
    }
    if (p->pilot_rays == 0) {
        fprintf(f, "  volume plan no pilot for %.0f pixels; planned in %.1f ms\n", p->pixels, p->seconds * 1e3);
        for (int i = 0; i < p->nlights; i++)
            fprintf(f, "    light %d   %s\n", i, volume_plan_decision_name(p->light[i].decision));
        return;
    }
    fprintf(f, "  volume plan %d pilot rays for %.0f pixels; touching check %.1f ns a decision, recording cells %.1f ns"
               " a camera ray; welding, edges' uses and registering the polygons estimated %.1f ms (of which"
               " registering %.1f ms; sample of %d polygons); planned in %.1f ms\n",
            p->pilot_rays, p->pixels, p->c_touch * 1e9, p->c_record * 1e9, p->shared_estimate * 1e3,
            p->register_estimate * 1e3, p->sample_polygons, p->seconds * 1e3);
    for (int i = 0; i < p->nlights; i++) {
        const LightPlan *l = &p->light[i];
        fprintf(f, "    light %d   %s", i, volume_plan_decision_name(l->decision));
        if (l->decision == PLAN_IMPOSSIBLE || l->decision == PLAN_AREA_LIGHT || l->decision == PLAN_TOO_MANY_POLYGONS) {
            fprintf(f, "\n");
            continue;
        }
        fprintf(f, ": %.0f decisions expected, shadow ray %.1f ns, build estimated %.2f ms, gain at most %.2f ms",
                l->queries, l->c_ray * 1e9, l->build_estimate * 1e3, l->gain_bound * 1e3);
        if (l->decision == PLAN_KEPT || l->decision == PLAN_DROPPED || l->decision == PLAN_DROPPED_ALL)
            fprintf(f, "; pilot: hst %.1f ns against the shadow ray's %.1f ns, gain %.2f ms", l->c_hst * 1e9,
                    l->c_ray_beside * 1e9, l->gain * 1e3);
        fprintf(f, "\n");
    }
}

static void json_plan(FILE *f, const VolumePlan *p)
{
    fprintf(f, ",\n  \"volume_plan\": {\"mode\": \"%s\"", p->mode == VOLUMES_ALWAYS ? "always" : "auto");
    if (p->mode == VOLUMES_AUTO) {
        fprintf(f, ", \"pilot_rays\": %d, \"pixels\": %.0f, \"touch_ns\": %.3f, \"record_ns\": %.3f, "
                   "\"shared_estimate_s\": %.6f, \"register_estimate_s\": %.6f, \"sample_polygons\": %d, "
                   "\"seconds\": %.6f, \"lights\": [",
                p->pilot_rays, p->pixels, p->c_touch * 1e9, p->c_record * 1e9, p->shared_estimate,
                p->register_estimate, p->sample_polygons, p->seconds);
        for (int i = 0; i < p->nlights; i++) {
            const LightPlan *l = &p->light[i];
            fprintf(f, "%s\n    {\"decision\": \"%s\", \"volumes\": %s, \"queries\": %.0f, \"shadow_ray_ns\": %.3f, "
                       "\"build_estimate_s\": %.6f, \"gain_bound_s\": %.6f, \"hst_ns\": %.3f, "
                       "\"shadow_ray_beside_ns\": %.3f, \"gain_s\": %.6f}",
                    i ? "," : "", volume_plan_decision_name(l->decision), l->decision == PLAN_KEPT ? "true" : "false",
                    l->queries, l->c_ray * 1e9, l->build_estimate, l->gain_bound, l->c_hst * 1e9,
                    l->c_ray_beside * 1e9, l->gain);
        }
        fprintf(f, "]");
    }
    fprintf(f, "}");
}

void stats_print(FILE *f, const StatsReport *r)
{
    const RenderStats *s = &r->render;
    double others = others_seconds(r);
    double total = r->parse_seconds + r->preprocess_seconds + s->shadow.shadow_seconds + others;
    fprintf(f, "hstrace statistics for %s (%dx%d, %d thread%s, shadows: %s)\n", r->scene, r->width, r->height,
            r->threads, r->threads == 1 ? "" : "s", r->shadow_method);
    fprintf(f, "  scene       %d polygons (%d degenerate dropped), %d infinite planes, %d curved objects, %d lights\n",
            r->npolygons, r->ndegenerate, r->nplanes, r->nshapes, r->nlights);
    if (r->ninstances > 0)
        fprintf(f, "  instances   %d placements of %d meshes: %d polygons kept once place %d more\n", r->ninstances,
                r->nprototypes, r->nproto_polygons, r->ninstanced_polygons);
    if (r->povray_ini_why)
        fprintf(f, "  povray.ini  %s (%s)\n", r->povray_ini ? r->povray_ini : "none", r->povray_ini_why);
    for (int i = 0; i < r->napproximations; i++) {
        const SceneApproximation *a = &r->approximations[i];
        fprintf(f, "  %-11s %s: %d place%s, first %s at %s:%d:%d\n", i == 0 ? "approximated" : "",
                approx_kind_effect(a->kind), a->count, a->count == 1 ? "" : "s", a->what, a->first.file,
                a->first.line, a->first.column);
    }
    if (r->grid_registered)
        fprintf(f, "  grid        %dx%dx%d cells, %llu registrations\n", r->grid[0], r->grid[1], r->grid[2],
                (unsigned long long)r->grid_registrations);
    else
        fprintf(f, "  grid        %dx%dx%d cells, polygons not registered (no shadow volumes: the hierarchy serves)\n",
                r->grid[0], r->grid[1], r->grid[2]);
    if (r->ranks > 1 && r->rank_render) {
        /* A distributed render: the counters below are all ranks' */
        fprintf(f, "  ranks       %d, each threads %d; pixels per rank", r->ranks, r->threads);
        for (int i = 0; i < r->ranks; i++)
            fprintf(f, " %llu", (unsigned long long)r->rank_render[i].pixels);
        fprintf(f, "\n");
    }
    fprintf(f, "  time (s)    parse %.3f  preprocessing %.3f  shadow testing %.3f  others %.3f  total %.3f  (wall %.3f)\n",
            r->parse_seconds, r->preprocess_seconds, s->shadow.shadow_seconds, others, total, r->wall_seconds);
    fprintf(f, "              preprocessing: world %.3f  hierarchy %.3f  volume plan %.3f (building volumes %.3f)\n",
            r->world_seconds, r->hierarchy_seconds, r->plan_seconds, r->volumes_seconds);
    fprintf(f, "              shadow testing and others are CPU time summed over threads\n");
    print_line(f, "rays", s, LINE_RAYS);
    print_line(f, "tests", s, LINE_TESTS);
    print_line(f, "shadows", s, LINE_SHADOWS);
    {
        /* ns a decision, the camera's hits and the secondary ones apart */
        const ShadowCounters *c = &s->shadow;
        uint64_t primary = c->shadow_queries - c->shadow_queries_secondary;
        double primary_s = c->shadow_seconds - c->shadow_seconds_secondary;
        fprintf(f, "  decisions   %.1f ns each at the camera's hits (%llu)", primary ? 1e9 * primary_s / (double)primary : 0.0,
                (unsigned long long)primary);
        if (c->shadow_queries_secondary)
            fprintf(f, ", %.1f ns at secondary hits (%llu)",
                    1e9 * c->shadow_seconds_secondary / (double)c->shadow_queries_secondary,
                    (unsigned long long)c->shadow_queries_secondary);
        fprintf(f, "\n");
    }
    fprintf(f, "  sub-schemes");
    for (int i = 0; i < SCHEME_COUNT; i++)
        fprintf(f, "  %s %llu", shadow_scheme_names[i], (unsigned long long)s->shadow.shadow_schemes[i]);
    fprintf(f, "\n");
    if (s->shadow.area_points)
        fprintf(f, "  area lights %llu shading points sampled them: %llu samples decided (%.2f a point), each one of"
                   " the queries\n",
                (unsigned long long)s->shadow.area_points, (unsigned long long)s->shadow.area_samples,
                (double)s->shadow.area_samples / (double)s->shadow.area_points);
    if (s->shadow.area_beams || s->shadow.area_beam_overflows)
        fprintf(f, "  area beams  %llu points (%.1f%% of them): %llu proved lit, %llu in umbra (%.1f%% uniform), the rest"
                   " sampled against %.1f candidate polygons a beam; %llu beams gave up (over %d candidates)\n",
                (unsigned long long)s->shadow.area_beams,
                100.0 * (double)s->shadow.area_beams / (double)(s->shadow.area_points ? s->shadow.area_points : 1),
                (unsigned long long)s->shadow.area_beam_lit, (unsigned long long)s->shadow.area_beam_umbra,
                100.0 * (double)(s->shadow.area_beam_lit + s->shadow.area_beam_umbra) /
                    (double)(s->shadow.area_beams ? s->shadow.area_beams : 1),
                (double)s->shadow.area_beam_candidates / (double)(s->shadow.area_beams ? s->shadow.area_beams : 1),
                (unsigned long long)s->shadow.area_beam_overflows, AREA_BEAM_CAP);
    if (r->plan)
        print_plan(f, r->plan);
    if (r->volumes) {
        const ShadowVolumes *sv = r->volumes;
        fprintf(f, "  volumes     %d welded vertices; built in %.3f s; tolerance %.3g\n", sv->nwelded_vertices,
                r->volumes_seconds, sv->tolerance);
        for (int i = 0; i < sv->nlights; i++) {
            const LightVolumes *lv = &sv->light[i];
            if (lv->plane_cuts_scene) {
                fprintf(f, "    light %d   no shadow volumes: a parallel light whose plane cuts the scene; shadow rays only\n", i);
                continue;
            }
            if (!cell_lists_built(&lv->cells))
                continue;
            fprintf(f, "    light %d   %d shadow polygons (%d edges cancelled), %zu cell registrations, eye depth ",
                    i, lv->count, lv->cancelled_edges, lv->nitems);
            if (lv->eye_known)
                fprintf(f, "%d opaque, %d transparent\n", lv->eye_opaque, lv->eye_transparent);
            else
                fprintf(f, "unknown\n");
        }
        print_line(f, "counting", s, LINE_COUNTING);
        if (line_nonzero(s, LINE_FALLBACKS))
            print_line(f, "fallbacks", s, LINE_FALLBACKS);
        if (line_nonzero(s, LINE_COHERENCE))
            print_line(f, "coherence", s, LINE_COHERENCE);
    }
    if (r->light_buffers) {
        const LightBuffers *lb = r->light_buffers;
        unsigned long long cells = atomic_load(&lb->cells), cand = atomic_load(&lb->candidates);
        fprintf(f, "  light buffer %llu cells built (%.1f candidates a cell), %.1f MiB of %.0f MiB; %llu not built"
                   " for the budget; built in %.3f s (CPU, summed over threads)\n",
                cells, cells ? (double)cand / (double)cells : 0.0, (double)atomic_load(&lb->bytes) / 1048576.0,
                (double)lb->budget / 1048576.0, (unsigned long long)atomic_load(&lb->full),
                (double)s->shadow.light_buffer_build_ns * 1e-9);
        print_line(f, "buffer", s, LINE_BUFFER);
    }
    if (r->embree) {
        const EmbreeSceneInfo *e = shadow_embree_info(r->embree);
        fprintf(f, "  embree      Embree %s, robust, %s quality: %d triangles, %d convex polygons as %d triangles,"
                   " %d polygons tested exactly (user geometry), %d no_shadow left out; built in %.3f s\n",
                shadow_embree_version(), e->quality, e->triangles, e->fanned_polygons, e->fan_triangles,
                e->user_polygons, e->left_out, e->seconds);
    }
    if (r->cost) {
        const CostModel *c = r->cost;
        fprintf(f, "  cost model  C_s %.1f ns  C_i %.1f ns  C_c %.1f ns  C_o %.1f ns  p %.4f  alpha %.3f  N_c %.1f  N_o %.1f"
                   "  (calibrated in %.1f ms)\n",
                c->c_s * 1e9, c->c_i * 1e9, c->c_c * 1e9, c->c_o * 1e9, c->p, c->alpha, c->n_c, c->n_o,
                c->seconds * 1e3);
        fprintf(f, "              shadow ray through the hierarchy C_ray %.1f ns, gathering C_g %.1f ns a shadow polygon\n",
                c->c_ray * 1e9, c->c_g * 1e9);
        if (r->nth >= 0.0)
            fprintf(f, "  N_th        %.2f (%s; C_ray / (C_s + C_g) gives %.2f, eq. 7 for the grid's walk %.2f)\n",
                    r->nth, r->nth_mode, c->nth_ray, c->nth);
        else
            fprintf(f, "  N_th        per shading point from its own N_c (eq. 7 for the mean N_c gives %.2f)\n", c->nth);
    }
    if (r->verify) {
        fprintf(f, "  verified    %llu decisions against the shadow ray: %llu disagreements",
                (unsigned long long)s->shadow.shadow_verified, (unsigned long long)s->shadow.shadow_disagreements);
        for (int i = 0; i < SCHEME_COUNT; i++)
            if (s->shadow.shadow_disagreements_by_scheme[i])
                fprintf(f, " (%s %llu)", shadow_scheme_names[i],
                        (unsigned long long)s->shadow.shadow_disagreements_by_scheme[i]);
        fprintf(f, "\n");
    }
    if (r->verify > 1)
        fprintf(f, "  reference   long double: %llu ties; on the %llu clear decisions, the method is wrong %llu times, "
                   "the shadow ray %llu times\n",
                (unsigned long long)s->shadow.reference_ties,
                (unsigned long long)(s->shadow.shadow_verified - s->shadow.reference_ties), (unsigned long long)s->shadow.reference_wrong,
                (unsigned long long)s->shadow.reference_ray_wrong);
}

int stats_write_json(const char *path, const StatsReport *r, char *err, int errlen)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, (size_t)errlen, "cannot write '%s': %s", path, strerror(errno));
        return -1;
    }
    const RenderStats *s = &r->render;
    double others = others_seconds(r);
    fprintf(f, "{\n  \"scene\": \"");
    for (const char *c = r->scene; *c; c++) {
        if (*c == '"' || *c == '\\')
            fputc('\\', f);
        if ((unsigned char)*c >= 0x20)
            fputc(*c, f);
    }
    fprintf(f, "\",\n  \"povray_ini\": ");
    if (r->povray_ini)
        json_write_string(f, r->povray_ini);
    else
        fprintf(f, "null");
    fprintf(f, ",\n  \"shadow_method\": \"%s\",\n  \"width\": %d,\n  \"height\": %d,\n  \"threads\": %d,\n",
            r->shadow_method, r->width, r->height, r->threads);
    fprintf(f, "  \"polygons\": %d,\n  \"degenerate_dropped\": %d,\n  \"planes\": %d,\n  \"shapes\": %d,\n  \"lights\": %d,\n",
            r->npolygons, r->ndegenerate, r->nplanes, r->nshapes, r->nlights);
    fprintf(f,
            "  \"instances\": %d,\n  \"prototypes\": %d,\n  \"prototype_polygons\": %d,\n  \"instanced_polygons\": %d,\n",
            r->ninstances, r->nprototypes, r->nproto_polygons, r->ninstanced_polygons);
    fprintf(f, "  \"approximations\": [");
    for (int i = 0; i < r->napproximations; i++) {
        const SceneApproximation *a = &r->approximations[i];
        char at[600];
        snprintf(at, sizeof at, "%s:%d:%d", a->first.file, a->first.line, a->first.column);
        fprintf(f, "%s\n    {\"kind\": ", i ? "," : "");
        json_write_string(f, approx_kind_name(a->kind));
        fprintf(f, ", \"count\": %d, \"first\": ", a->count);
        json_write_string(f, at);
        fprintf(f, ", \"what\": ");
        json_write_string(f, a->what);
        fprintf(f, ", \"effect\": ");
        json_write_string(f, approx_kind_effect(a->kind));
        fprintf(f, "}");
    }
    fprintf(f, "%s],\n", r->napproximations ? "\n  " : "");
    fprintf(f, "  \"grid\": [%d, %d, %d],\n  \"grid_registrations\": %llu,\n", r->grid[0], r->grid[1], r->grid[2],
            (unsigned long long)r->grid_registrations);
    /* A distributed render (mpi_job.h): the figures below are all ranks'
     * together, the wall time the whole job's; each rank's own here. */
    fprintf(f, "  \"ranks\": %d,\n", r->ranks > 1 ? r->ranks : 1);
    if (r->ranks > 1)
        fprintf(f, "  \"gather_seconds\": %.6f,\n", r->gather_seconds);
    if (r->tile_seconds) {
        fprintf(f, "  \"tile_seconds\": [");
        for (int i = 0; i < r->ntiles; i++)
            fprintf(f, "%s%.7f", i ? (i % 16 ? ", " : ",\n    ") : "", r->tile_seconds[i]);
        fprintf(f, "],\n");
    }
    if (r->ranks > 1 && r->rank_render) {
        fprintf(f, "  \"per_rank\": [");
        for (int i = 0; i < r->ranks; i++) {
            const RenderStats *p = &r->rank_render[i];
            fprintf(f, "%s\n    {\"rank\": %d, \"pixels\": %llu, \"camera_rays\": %llu, \"shadow_queries\": %llu, "
                       "\"render_cpu_seconds\": %.6f, \"shadow_seconds\": %.6f, \"tile_requests\": %ld, "
                       "\"tile_wait_seconds\": %.6f}",
                    i ? "," : "", i, (unsigned long long)p->pixels, (unsigned long long)p->camera_rays,
                    (unsigned long long)p->shadow.shadow_queries, p->render_seconds, p->shadow.shadow_seconds,
                    r->rank_requests ? r->rank_requests[i] : 0L, r->rank_wait_seconds ? r->rank_wait_seconds[i] : 0.0);
        }
        fprintf(f, "\n  ],\n");
    }
    fprintf(f, "  \"time\": {\"parse\": %.6f, \"preprocessing\": %.6f, \"shadow_testing\": %.6f, "
               "\"shadow_testing_secondary\": %.6f, \"others\": %.6f, "
               "\"total\": %.6f, \"wall\": %.6f, \"world\": %.6f, \"hierarchy\": %.6f, \"volume_plan\": %.6f, "
               "\"building_volumes\": %.6f},\n",
            r->parse_seconds, r->preprocess_seconds, s->shadow.shadow_seconds, s->shadow.shadow_seconds_secondary, others,
            r->parse_seconds + r->preprocess_seconds + s->shadow.shadow_seconds + others, r->wall_seconds,
            r->world_seconds, r->hierarchy_seconds, r->plan_seconds, r->volumes_seconds);
    fprintf(f, "  \"rays\": {");
    json_counters(f, s, LINE_RAYS, LINE_RAYS, "", ", ");
    fprintf(f, "},\n  \"tests\": {");
    json_counters(f, s, LINE_TESTS, LINE_TESTS, "", ", ");
    fprintf(f, "},\n  \"shadows\": {");
    json_counters(f, s, LINE_SHADOWS, LINE_VERIFY, "", ",\n    ");
    if (r->verify > 1)
        json_counters(f, s, LINE_REFERENCE, LINE_REFERENCE, ",\n    ", ",\n    ");
    const char *by_scheme[2] = { "schemes", "disagreements_by_scheme" };
    for (int k = 0; k < 2; k++) {
        const uint64_t *v = k == 0 ? s->shadow.shadow_schemes : s->shadow.shadow_disagreements_by_scheme;
        fprintf(f, ",\n    \"%s\": {", by_scheme[k]);
        for (int i = 0; i < SCHEME_COUNT; i++)
            fprintf(f, "%s\"%s\": %llu", i ? ", " : "", shadow_scheme_names[i], (unsigned long long)v[i]);
        fprintf(f, "}");
    }
    fprintf(f, "}");
    if (r->plan)
        json_plan(f, r->plan);
    if (r->volumes) {
        const ShadowVolumes *sv = r->volumes;
        fprintf(f, ",\n  \"volumes\": {\"seconds\": %.6f, \"welded_vertices\": %d, \"tolerance\": %.3g, \"lights\": [",
                r->volumes_seconds, sv->nwelded_vertices, sv->tolerance);
        for (int i = 0; i < sv->nlights; i++) {
            const LightVolumes *lv = &sv->light[i];
            fprintf(f, "%s\n    {\"shadow_polygons\": %d, \"cancelled_edges\": %d, \"cell_registrations\": %zu, "
                       "\"eye_depth\": ",
                    i ? "," : "", lv->count, lv->cancelled_edges, lv->nitems);
            if (lv->eye_known)
                fprintf(f, "[%d, %d]}", lv->eye_opaque, lv->eye_transparent);
            else
                fprintf(f, "null}");
        }
        fprintf(f, "]}");
    }
    if (r->light_buffers) {
        const LightBuffers *lb = r->light_buffers;
        fprintf(f, ",\n  \"light_buffer\": {\"cells\": %llu, \"candidates\": %llu, \"bytes\": %llu, "
                   "\"budget_bytes\": %llu, \"not_built_for_budget\": %llu, \"build_seconds\": %.6f}",
                (unsigned long long)atomic_load(&lb->cells), (unsigned long long)atomic_load(&lb->candidates),
                (unsigned long long)atomic_load(&lb->bytes), (unsigned long long)lb->budget,
                (unsigned long long)atomic_load(&lb->full), (double)s->shadow.light_buffer_build_ns * 1e-9);
    }
    if (r->embree) {
        const EmbreeSceneInfo *e = shadow_embree_info(r->embree);
        fprintf(f, ",\n  \"embree\": {\"version\": \"%s\", \"quality\": \"%s\", \"seconds\": %.6f, \"triangles\": %d, "
                   "\"fanned_polygons\": %d, \"fan_triangles\": %d, \"user_polygons\": %d, \"left_out\": %d}",
                shadow_embree_version(), e->quality, e->seconds, e->triangles, e->fanned_polygons, e->fan_triangles,
                e->user_polygons, e->left_out);
    }
    if (r->cost) {
        const CostModel *c = r->cost;
        /* N_th is infinite where no count was timed (no volumes): JSON's null */
        char nth[32], nth_ray[32];
        finite_or_null(nth, sizeof nth, c->nth);
        finite_or_null(nth_ray, sizeof nth_ray, c->nth_ray);
        fprintf(f, ",\n  \"cost_model\": {\"c_s_ns\": %.3f, \"c_i_ns\": %.3f, \"c_c_ns\": %.3f, \"c_o_ns\": %.3f, "
                   "\"p\": %.6f, \"alpha\": %.4f, \"n_c\": %.3f, \"n_o\": %.3f, \"nth_eq7\": %s, \"c_ray_ns\": %.3f, "
                   "\"c_g_ns\": %.3f, \"nth_shadow_ray\": %s, \"seconds\": %.6f, \"samples\": %d},\n  \"nth\": ",
                c->c_s * 1e9, c->c_i * 1e9, c->c_c * 1e9, c->c_o * 1e9, c->p, c->alpha, c->n_c, c->n_o, nth,
                c->c_ray * 1e9, c->c_g * 1e9, nth_ray, c->seconds, c->samples);
        if (r->nth >= 0.0) {
            char v[32];
            finite_or_null(v, sizeof v, r->nth);
            fprintf(f, "%s", v);
        }
        else
            fprintf(f, "\"per-point\"");
    }
    fprintf(f, "\n}\n");
    if (fclose(f) != 0) {
        snprintf(err, (size_t)errlen, "cannot write '%s': %s", path, strerror(errno));
        return -1;
    }
    return 0;
}
