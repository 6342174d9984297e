/* Defaults of the scene description, as POV-Ray 3.7 defines them. */
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ptr_map.h"

Finish scene_default_finish(void)
{
    Finish f;
    memset(&f, 0, sizeof f);
    f.ambient[0] = f.ambient[1] = f.ambient[2] = 0.1;
    f.diffuse = 0.6;
    f.brilliance = 1.0;
    f.phong_size = 40.0;
    f.roughness = 0.05;
    f.reflection_falloff = 1.0;
    f.reflection_exponent = 1.0;
    f.caustics = -1.0;
    return f;
}

Interior scene_default_interior(void)
{
    Interior i;
    memset(&i, 0, sizeof i);
    i.ior = 1.0;
    i.fade_power = 0.0;
    return i;
}

void scene_free(Scene *scene)
{
    if (!scene)
        return;
    Arena *a = scene->arena;
    free(scene);
    arena_free(a);
}

static void release_mesh_lists(Arena *a, SceneObject *o)
{
    if (!o)
        return;
    if (o->kind == OBJ_MESH) {
        arena_release(a, o->u.mesh.vertices);
        arena_release(a, o->u.mesh.normals);
        arena_release(a, o->u.mesh.uvs);
        arena_release(a, o->u.mesh.faces);
        o->u.mesh.vertices = o->u.mesh.normals = o->u.mesh.uvs = NULL;
        o->u.mesh.faces = NULL;
        o->u.mesh.nvertices = o->u.mesh.nnormals = o->u.mesh.nuvs = o->u.mesh.nfaces = 0;
    } else if (scene_object_has_children(o->kind)) {
        for (int i = 0; i < o->u.csg.nchildren; i++)
            release_mesh_lists(a, o->u.csg.children[i]);
    }
}

void scene_release_mesh_lists(Scene *scene)
{
    for (int i = 0; scene && i < scene->nobjects; i++)
        release_mesh_lists(scene->arena, scene->objects[i]);
}

double scene_working_gamma(const Scene *s)
{
    const GlobalSettings *g = &s->globals;
    if (g->has_assumed_gamma)
        return g->assumed_gamma_srgb ? 0.0 : g->assumed_gamma;
    return s->version_given && s->version >= 3.7 ? 1.0 : 0.0;
}

int scene_gamma_correction_off(const Scene *s)
{
    return !s->globals.has_assumed_gamma && !(s->version_given && s->version >= 3.7);
}

double scene_effective_version(const Scene *s)
{
    return s->version_given ? s->version : 3.62;
}

int scene_noise_generator(const Scene *s)
{
    if (s->globals.noise_generator)
        return s->globals.noise_generator;
    /* POV-Ray's default follows the language version (an explicit
     * global_settings value stays). */
    return floor(s->version * 100.0 + 0.5) < 350.0 ? 1 : 2; /* no int: a version of 1e46 is no error */
}

Colour colour_map_at(const ColourMapEntry *map, int n, double value)
{
    if (n <= 0) {
        Colour black = { 0, 0, 0, 0, 0 };
        return black;
    }
    if (value >= map[n - 1].value)
        return map[n - 1].colour;
    int c = 0;
    while (value > map[c].value)
        c++;
    if (c == 0 || value == map[c].value)
        return map[c].colour;
    const ColourMapEntry *a = &map[c - 1], *b = &map[c];
    double f = (value - a->value) / (b->value - a->value);
    Colour r = {
        a->colour.r + f * (b->colour.r - a->colour.r),
        a->colour.g + f * (b->colour.g - a->colour.g),
        a->colour.b + f * (b->colour.b - a->colour.b),
        a->colour.filter + f * (b->colour.filter - a->colour.filter),
        a->colour.transmit + f * (b->colour.transmit - a->colour.transmit),
    };
    return r;
}

/* pigment_is_opaque's walk, each pigment once (`seen`): a pigment may be
 * an entry of many maps, and 40 averages of two copies of the one before
 * are 41 pigments but 2^40 paths (the world's build walked them all).
 * A pigment seen again was opaque, or the walk would have ended there.
 * Returns 1 opaque, 0 not, -1 out of memory. */
static int opaque_walk(const Pigment *pig, PtrMap *seen)
{
    if (ptr_map_get(seen, pig) >= 0)
        return 1;
    if (ptr_map_put(seen, pig, 1) != 0)
        return -1;
    if (pig->kind == PIGMENT_IMAGE_MAP) { /* `once` shows nothing (clear) outside the picture */
        const SceneImage *im = pig->image;
        if (im->npalette > 0) { /* the entries' own filter and transmit are all there is */
            for (int i = 0; i < im->npalette; i++)
                if (im->palette[i][3] != 0.0f || im->palette[i][4] != 0.0f)
                    return 0;
            return !pig->image_once;
        }
        return !pig->image_once && !im->has_alpha && pig->image_filter_all == 0.0 && pig->image_transmit_all == 0.0;
    }
    if (pig->kind == PIGMENT_SOLID)
        return pig->colour.filter == 0.0 && pig->colour.transmit == 0.0;
    for (int i = 0; i < pig->nmap; i++)
        if (pig->map[i].pigment) {
            const int r = opaque_walk(pig->map[i].pigment, seen);
            if (r != 1)
                return r;
        }
    for (int i = 0; i < pig->nmap; i++)
        if (pig->map[i].colour.filter != 0.0 || pig->map[i].colour.transmit != 0.0)
            return 0;
    return 1;
}

int pigment_is_opaque(const Pigment *pig)
{
    PtrMap seen = PTR_MAP_EMPTY;
    const int r = opaque_walk(pig, &seen);
    ptr_map_free(&seen);
    return r == 1; /* out of memory: not opaque, never wrong in what it shows (it only spares less work) */
}

/* The kinds of approximation (scene.h) by name and by what they change,
 * for the parser's notes and the engine's reports alike. */
static const struct {
    const char *name, *effect;
} kinds[APPROX_KINDS] = {
    [APPROX_NORMAL] = { "normal", "normal pattern not evaluated: the surface normal left unperturbed" },
    [APPROX_PATTERN] = { "pattern", "pattern shown as one colour, its colour map at 0.5" },
    [APPROX_WARP] = { "warp", "pattern warps other than turbulence ignored" },
    [APPROX_LAYERS] = { "layers", "texture layers blended into one, with the top layer's finish" },
    [APPROX_FINISH] = { "finish", "finish item ignored" },
    [APPROX_DISPERSION] = { "dispersion", "dispersion ignored" },
    [APPROX_PHOTONS] = { "photons", "photon mapping ignored" },
    [APPROX_RADIOSITY] = { "radiosity", "radiosity and subsurface light transport ignored: no light gathered from "
                                        "other surfaces, and (as POV-Ray 3.7 with radiosity) no finish's ambient" },
    [APPROX_FOCAL_BLUR] = { "camera", "focal blur and camera normal ignored: a pinhole camera" },
    [APPROX_FOG] = { "fog", "fog between lights and surfaces (media_attenuation) ignored" },
    [APPROX_VERTEX_TEXTURES] = { "vertex-textures", "a texture_map among a mesh face's textures per vertex: the "
                                                    "first vertex's texture on the whole face" },
};

const char *approx_kind_name(ApproxKind k)
{
    return k >= 0 && k < APPROX_KINDS ? kinds[k].name : "?";
}

const char *approx_kind_effect(ApproxKind k)
{
    return k >= 0 && k < APPROX_KINDS ? kinds[k].effect : "?";
}
