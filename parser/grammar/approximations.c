/* The report of what hstrace approximates (the kinds themselves, their
 * names and effects, are the description's: scene.c).
 *
 * The parser hangs an ApproxNote on the description wherever it approximates
 * (a pigment's bozo, a texture's normal, a light's photons ...). After
 * parsing, the notes reachable from what the scene instantiates are counted
 * here, once per place in the files, so that an include file's unused
 * declarations report nothing. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "grammar.h"
#include "ptr_map.h"

/* Places seen so far, by kind and position (a hash set: scenes with a
 * million textured faces share a handful of notes, visited many times). */
typedef struct {
    const ApproxNote **slots;
    size_t cap, n;
    SceneApproximation per_kind[APPROX_KINDS];
    int failed;
    int photons;          /* photon mapping would run: count the photons { } blocks */
    /* Normals walked already: a normal may be an entry of many maps, and
     * 40 averages of two copies of the one before are 41 normals but 2^40
     * paths (walking them all hung the parse). */
    PtrMap normals_seen;
} Tally;

static size_t note_hash(const ApproxNote *n)
{
    size_t h = (size_t)(uintptr_t)n->pos.file;
    h = h * 31u + (size_t)n->pos.line;
    h = h * 31u + (size_t)n->pos.column;
    return h * 31u + (size_t)n->kind;
}

static int same_place(const ApproxNote *a, const ApproxNote *b)
{
    return a->kind == b->kind && a->pos.line == b->pos.line && a->pos.column == b->pos.column &&
           (a->pos.file == b->pos.file || (a->pos.file && b->pos.file && strcmp(a->pos.file, b->pos.file) == 0));
}

static int tally_grow(Tally *t)
{
    size_t cap = t->cap ? t->cap * 2 : 64;
    const ApproxNote **slots = calloc(cap, sizeof *slots);
    if (!slots)
        return -1;
    for (size_t i = 0; i < t->cap; i++) {
        if (!t->slots[i])
            continue;
        size_t j = note_hash(t->slots[i]) & (cap - 1);
        while (slots[j])
            j = (j + 1) & (cap - 1);
        slots[j] = t->slots[i];
    }
    free(t->slots);
    t->slots = slots;
    t->cap = cap;
    return 0;
}

static void tally_notes(Tally *t, const ApproxNote *n)
{
    for (; n && !t->failed; n = n->next) {
        if ((t->n + 1) * 2 > t->cap && tally_grow(t)) {
            t->failed = 1;
            return;
        }
        size_t j = note_hash(n) & (t->cap - 1);
        int seen = 0;
        while (t->slots[j]) {
            if (t->slots[j] == n || same_place(t->slots[j], n)) {
                seen = 1;
                break;
            }
            j = (j + 1) & (t->cap - 1);
        }
        if (seen)
            continue;
        t->slots[j] = n;
        t->n++;
        SceneApproximation *a = &t->per_kind[n->kind];
        if (a->count == 0) { /* objects are walked in file order, so this is the first use */
            a->first = n->pos;
            a->what = n->what;
        }
        a->count++;
    }
}

static void tally_pigment(Tally *t, const Pigment *pig)
{
    tally_notes(t, pig->approx);
}

static void tally_normal(Tally *t, const SceneNormal *n, int depth)
{
    if (!n || depth > 1000 || t->failed || ptr_map_get(&t->normals_seen, n) >= 0)
        return;
    if (ptr_map_put(&t->normals_seen, n, 1) != 0) {
        t->failed = 1;
        return;
    }
    tally_notes(t, n->approx);
    tally_notes(t, n->pattern.approx);
    for (int i = 0; i < n->nmap; i++)
        tally_normal(t, n->map[i].normal, depth + 1);
    tally_normal(t, n->uv_entry, depth + 1);
}

static void tally_texture(Tally *t, const SceneTexture *tex)
{
    if (!tex)
        return;
    tally_notes(t, tex->approx);
    tally_normal(t, tex->normal, 0);
    tally_pigment(t, &tex->pigment);
    tally_notes(t, tex->finish.approx);
    tally_texture(t, tex->below); /* a layered texture's lower layers */
}

static void tally_object(Tally *t, const SceneObject *o, int depth)
{
    if (depth > 1000)
        return;
    tally_notes(t, o->approx);
    if (t->photons)
        tally_notes(t, o->photons);
    tally_texture(t, o->texture);
    tally_texture(t, o->interior_texture);
    if (o->interior)
        tally_notes(t, o->interior->approx);
    if (scene_object_has_children(o->kind))
        for (int i = 0; i < o->u.csg.nchildren; i++)
            tally_object(t, o->u.csg.children[i], depth + 1);
    if (o->kind == OBJ_MESH)
        for (int i = 0; i < o->u.mesh.ntextures; i++)
            tally_texture(t, o->u.mesh.textures[i]);
}

/* Whether o, or an object in it, is a photon target. */
static int photon_target(const SceneObject *o, int depth)
{
    if (o->photon_target)
        return 1;
    if (scene_object_has_children(o->kind) && depth < 1000)
        for (int i = 0; i < o->u.csg.nchildren; i++)
            if (photon_target(o->u.csg.children[i], depth + 1))
                return 1;
    return 0;
}

/* Photon mapping changes POV-Ray 3.7's image only where global_settings
 * turns it on and some object is a target: photons are shot only at
 * targets (photonshootingstrategy.cpp), and with none stored the shading
 * is as without (trace.cpp asks for surfacePhotonMap.numPhotons > 0, also
 * where it darkens shadows through targets). Exporters write photons { }
 * on objects and lights whatever the scene's settings; those count only
 * then, and so does the global block. */
static int photons_in_use(Parser *p)
{
    if (!p->gram->global_photons)
        return 0;
    for (int i = 0; i < p->gram->objects.n; i++)
        if (photon_target(((SceneObject **)p->gram->objects.data)[i], 0))
            return 1;
    return 0;
}

void gram_collect_approximations(Parser *p)
{
    Scene *s = p->scene;
    Tally t;
    memset(&t, 0, sizeof t);
    t.photons = photons_in_use(p);
    for (int i = 0; i < p->gram->objects.n; i++)
        tally_object(&t, ((SceneObject **)p->gram->objects.data)[i], 0);
    for (int i = 0; i < p->gram->lights.n; i++) {
        const SceneLight *l = &((SceneLight *)p->gram->lights.data)[i];
        tally_notes(&t, l->approx);
        if (t.photons)
            tally_notes(&t, l->photons);
    }
    tally_notes(&t, s->camera.approx);
    tally_texture(&t, &s->default_texture);
    for (int i = 0; i < s->sky.npigments; i++)
        tally_pigment(&t, &s->sky.pigments[i]);
    tally_notes(&t, p->gram->global_approx);
    if (t.photons)
        tally_notes(&t, p->gram->global_photons);
    free(t.slots);
    ptr_map_free(&t.normals_seen);
    if (t.failed)
        tok_fail(p, p->last_pos, "out of memory");
    /* --strict for photons, counted only where the rest of the scene makes
     * them change the image (the other kinds refused it where parsed) */
    const SceneApproximation *ph = &t.per_kind[APPROX_PHOTONS];
    if (p->opts->strict && ph->count > 0)
        tok_fail(p, ph->first, "%s is only approximated by hstrace (%s: global_settings turns it on and an object is a "
                 "target); --strict makes it an error", ph->what, approx_kind_effect(APPROX_PHOTONS));
    int n = 0;
    for (int k = 0; k < APPROX_KINDS; k++)
        n += t.per_kind[k].count > 0;
    s->approximations = tok_scene_alloc(p, sizeof *s->approximations * (size_t)(n ? n : 1));
    s->napproximations = 0;
    for (int k = 0; k < APPROX_KINDS; k++) {
        if (t.per_kind[k].count == 0)
            continue;
        t.per_kind[k].kind = (ApproxKind)k;
        s->approximations[s->napproximations++] = t.per_kind[k];
    }
}
