/* Scenes built in code for engine tests: no parser involved, so a failure
 * here points at the engine. */
#ifndef HST_TEST_FIXTURES_H
#define HST_TEST_FIXTURES_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parser.h"
#include "scene.h"
#include "world.h"

static inline Scene *fixture_scene(int capacity)
{
    Scene *s = calloc(1, sizeof *s);
    s->arena = arena_new();
    s->objects = arena_alloc(s->arena, sizeof(SceneObject *) * (size_t)(capacity > 0 ? capacity : 1));
    s->default_texture.finish = scene_default_finish();
    s->default_texture.pigment.colour.r = 1.0;
    s->default_texture.pigment.colour.g = 1.0;
    s->default_texture.pigment.colour.b = 1.0;
    s->globals.ambient_light.r = s->globals.ambient_light.g = s->globals.ambient_light.b = 1.0;
    s->globals.max_trace_level = 5;
    s->camera.location = v3(0, 0, -5);
    s->camera.direction = v3(0, 0, 1);
    s->camera.up = v3(0, 1, 0);
    s->camera.right = v3(4.0 / 3.0, 0, 0);
    return s;
}

/* Frees a fixture scene whose lights array belongs to the caller. */
static inline void fixture_scene_free(Scene *s)
{
    s->lights = NULL;
    s->nlights = 0;
    scene_free(s);
}

static inline SceneObject *fixture_object(Scene *s, ObjectKind kind)
{
    SceneObject *o = arena_alloc(s->arena, sizeof *o);
    o->kind = kind;
    transform_identity(&o->transform);
    s->objects[s->nobjects++] = o;
    return o;
}

static inline SceneObject *fixture_triangle(Scene *s, Vec3 a, Vec3 b, Vec3 c)
{
    SceneObject *o = fixture_object(s, OBJ_TRIANGLE);
    o->u.triangle.v[0] = a;
    o->u.triangle.v[1] = b;
    o->u.triangle.v[2] = c;
    return o;
}

/* A polygon with several outlines given as counts and closed point lists. */
static inline SceneObject *fixture_polygon(Scene *s, const Vec3 *pts, int npts, const int *outline_start, int noutlines)
{
    SceneObject *o = fixture_object(s, OBJ_POLYGON);
    o->u.polygon.npoints = npts;
    o->u.polygon.points = arena_alloc(s->arena, sizeof(Vec3) * (size_t)npts);
    memcpy(o->u.polygon.points, pts, sizeof(Vec3) * (size_t)npts);
    o->u.polygon.noutlines = noutlines;
    o->u.polygon.outline_start = arena_alloc(s->arena, sizeof(int) * (size_t)(noutlines + 1));
    memcpy(o->u.polygon.outline_start, outline_start, sizeof(int) * (size_t)(noutlines + 1));
    return o;
}

/* Gives object o a plain pigment of its own, filter and transmit included
 * (POV-Ray's rgbft), with the scene's default finish. */
static inline void fixture_pigment(Scene *s, SceneObject *o, double r, double g, double b, double filter,
                                   double transmit)
{
    SceneTexture *t = arena_alloc(s->arena, sizeof *t);
    *t = s->default_texture;
    t->pigment.colour.r = r;
    t->pigment.colour.g = g;
    t->pigment.colour.b = b;
    t->pigment.colour.filter = filter;
    t->pigment.colour.transmit = transmit;
    o->texture = t;
    transform_identity(&o->texture_bind);
}

/* A small deterministic generator (xorshift), so tests do not depend on libc. */
typedef struct { unsigned long long s; } TestRng;
static inline double rng_uniform(TestRng *r)
{
    r->s ^= r->s << 13;
    r->s ^= r->s >> 7;
    r->s ^= r->s << 17;
    return (double)(r->s >> 11) / 9007199254740992.0;
}
static inline double rng_range(TestRng *r, double lo, double hi) { return lo + (hi - lo) * rng_uniform(r); }

/* A scene file of the tree (rel, below srcdir) parsed at 320x240, with
 * POV-Ray's include files where Debian puts them and hstrace's own, and its
 * world built into *w: the scene (scene_free it after world_free), or NULL
 * with why[] saying what failed. */
static inline Scene *fixture_scene_file(const char *srcdir, const char *rel, World *w, char *why, size_t whylen)
{
    char path[1024], inc[1024];
    snprintf(path, sizeof path, "%s/%s", srcdir, rel);
    snprintf(inc, sizeof inc, "%s/data/include", srcdir);
    const char *dirs[] = { "/usr/share/povray-3.7/include", inc };
    ParseOptions po = { .include_dirs = dirs, .ninclude_dirs = 2, .image_width = 320, .image_height = 240 };
    ParseError perr;
    Scene *sc = parse_scene_file(path, &po, &perr);
    if (!sc) {
        snprintf(why, whylen, "%s parses (%s:%d:%d: %s)", rel, perr.file, perr.line, perr.column, perr.message);
        return NULL;
    }
    WorldError err;
    if (world_build(w, sc, &err)) {
        snprintf(why, whylen, "%s: world builds (%s)", rel, err.message);
        scene_free(sc);
        return NULL;
    }
    return sc;
}

#endif
