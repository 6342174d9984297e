/* Objects: polygon, triangle, smooth_triangle, mesh, mesh2, box, plane,
 * sphere, disc, cylinder, cone, torus, quadric, poly, cubic, quartic,
 * superellipsoid, lathe, sor, union, intersection, difference, merge and object{}, with their modifiers. Every object keeps its own
 * transform, composed from the transforms written on it in order; a union's
 * children keep theirs (the engine applies child, then parent). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "grammar.h"

static const double POLY_EPSILON = 1e-10; /* POV-Ray's EPSILON for closing outlines */
/* Points, vertices, faces ... one object may list: a bound that keeps a
 * garbled count from reserving the machine's memory. */
#define MAX_ELEMENT_COUNT 50000000

int gram_is_object_keyword(int kw)
{
    switch (kw) {
    case KW_polygon: case KW_triangle: case KW_smooth_triangle: case KW_mesh: case KW_mesh2:
    case KW_box: case KW_plane: case KW_union: case KW_object:
    case KW_height_field: case KW_bicubic_patch: case KW_prism:
    case KW_text:
    case KW_sphere: case KW_disc: case KW_cylinder: case KW_cone: case KW_torus: case KW_blob:
    case KW_intersection: case KW_difference: case KW_merge: case KW_quadric: case KW_poly: case KW_cubic:
    case KW_quartic: case KW_superellipsoid: case KW_lathe: case KW_sor:
    /* POV-Ray objects hstrace cannot render */
    case KW_sphere_sweep:
    case KW_julia_fractal:
    case KW_isosurface: case KW_parametric: case KW_polynomial: case KW_ovus: case KW_light_group:
        return 1;
    default:
        return 0;
    }
}

static SceneObject *new_object(Parser *p, ObjectKind kind, const Token *t)
{
    SceneObject *o = tok_scene_alloc(p, sizeof *o);
    o->kind = kind;
    o->pos = t->pos;
    transform_identity(&o->transform);
    transform_identity(&o->texture_bind);
    return o;
}

/* Whether o is a solid hstrace can take as a part of a CSG operation:
 * an analytic shape, a box or plane, or a union or CSG operation of such (POV-Ray takes
 * any object, those without an inside (triangles, polygons, meshes
 * without inside_vector) being outside everywhere). */
static const SceneObject *first_non_solid(const SceneObject *o)
{
    switch (o->kind) {
    case OBJ_SPHERE: case OBJ_DISC: case OBJ_CONE: case OBJ_TORUS: case OBJ_BLOB: case OBJ_BOX: case OBJ_PLANE: case OBJ_GLYPH:
    case OBJ_QUADRIC: case OBJ_POLY: case OBJ_SUPERELLIPSOID: case OBJ_LATHE: case OBJ_SOR: case OBJ_PRISM:
        return NULL;
    case OBJ_UNION: case OBJ_INTERSECTION: case OBJ_DIFFERENCE: case OBJ_MERGE:
        /* the parser bounds the depth (SceneObject.depth) */
        for (int i = 0; i < o->u.csg.nchildren; i++) {
            const SceneObject *c = first_non_solid(o->u.csg.children[i]);
            if (c)
                return c;
        }
        return NULL;
    default: return o;
    }
}

static const char *object_kind_name(ObjectKind k)
{
    switch (k) {
    case OBJ_POLYGON: return "polygon";
    case OBJ_TRIANGLE: return "triangle";
    case OBJ_MESH: return "mesh";
    case OBJ_BOX: return "box";
    case OBJ_PLANE: return "plane";
    case OBJ_UNION: return "union";
    case OBJ_SPHERE: return "sphere";
    case OBJ_DISC: return "disc";
    case OBJ_CONE: return "cone";
    case OBJ_TORUS: return "torus";
    case OBJ_QUADRIC: return "quadric";
    case OBJ_POLY: return "poly";
    case OBJ_SUPERELLIPSOID: return "superellipsoid";
    case OBJ_LATHE: return "lathe";
    case OBJ_SOR: return "sor";
    case OBJ_BLOB: return "blob";
    case OBJ_INTERSECTION: return "intersection";
    case OBJ_DIFFERENCE: return "difference";
    case OBJ_MERGE: return "merge";
    case OBJ_HEIGHT_FIELD: return "height_field";
    case OBJ_BICUBIC_PATCH: return "bicubic_patch";
    case OBJ_PRISM: return "prism";
    case OBJ_GLYPH: return "text";
    }
    return "object";
}

static void rebind_own_texture(Parser *p, SceneObject *o);

/* The object's own texture, copied so a shared (declared) one stays intact. */
static SceneTexture *own_texture(Parser *p, SceneObject *o, const Token *t)
{
    SceneTexture *tex;
    if (o->texture && o->texture->nmap > 0) {
        /* POV-Ray lays a new texture over the map: a layered texture_map */
        Token what = *t;
        const char *msg = "pigment, normal or finish over a texture_map (a layer on it)";
        what.text = msg;
        what.len = (int)strlen(msg);
        tok_unsupported(p, &what);
    }
    if (o->texture) {
        tex = tok_scene_alloc(p, sizeof *tex);
        *tex = *o->texture;
    } else {
        tex = gram_default_texture(p);
        tex->pos = t->pos;
        rebind_own_texture(p, o); /* a new texture: later transforms move it */
    }
    o->texture = tex;
    return tex;
}

static void skip_optional_float(Parser *p)
{
    if (expr_starts_float(p, tok_peek(p)))
        (void)expr_float(p);
}

static int optional_bool(Parser *p)
{
    if (expr_starts_float(p, tok_peek(p)))
        return fabs(expr_float(p)) > 1e-5;
    return 1;
}

/* The object's textures (and interior texture) so far moved by the
 * transforms given since they were bound (POV-Ray transforms an object's
 * textures as it goes), and bound again here: a texture given now is moved
 * by the transforms after it alone, and so from here on are they all. */
static void rebind(Parser *p, SceneObject *o, int texture_too)
{
    int move_texture = texture_too && o->texture;
    if ((move_texture || o->interior_texture) && memcmp(&o->texture_bind, &o->transform, sizeof o->transform) != 0) {
        Transform since;
        memcpy(since.m, o->texture_bind.inv, sizeof since.m);
        memcpy(since.inv, o->texture_bind.m, sizeof since.inv);
        transform_compose(&since, &o->transform);
        if (move_texture)
            o->texture = gram_layers_moved(p, o->texture, &since);
        if (o->interior_texture)
            o->interior_texture = gram_layers_moved(p, o->interior_texture, &since);
    }
    o->texture_bind = o->transform; /* transforms after the texture move it, those before do not */
}

static void rebind_textures(Parser *p, SceneObject *o) { rebind(p, o, 1); }

/* A pigment, normal or material given on the object binds its texture
 * anew, as hstrace has always bound it (the texture's earlier parts with
 * it); the interior texture keeps the transforms given since its own. */
static void rebind_own_texture(Parser *p, SceneObject *o) { rebind(p, o, 0); }

static void apply_texture(Parser *p, SceneObject *o, SceneTexture *tex, const Token *at)
{
    /* A second texture is a layer on top of the first (gram_layer_textures). */
    rebind_textures(p, o);
    o->texture = o->texture ? gram_layer_textures(p, tex, o->texture, at) : tex;
}

/* The first object under o (o included) whose surface hstrace cannot
 * tell inside from outside as POV-Ray does, or NULL: the analytic shapes
 * and planes (their outward normals), boxes (their faces' winding), and
 * CSG and unions of them. The others (meshes, triangles, polygons, the
 * shapes made of triangles) would need POV-Ray's normal of each. */
static const SceneObject *no_inside_known(const SceneObject *o, int depth)
{
    switch (o->kind) {
    case OBJ_SPHERE: case OBJ_DISC: case OBJ_CONE: case OBJ_TORUS: case OBJ_BOX: case OBJ_PLANE: case OBJ_PRISM:
    case OBJ_LATHE: case OBJ_SOR: case OBJ_SUPERELLIPSOID:
        return NULL;
    case OBJ_UNION: case OBJ_INTERSECTION: case OBJ_DIFFERENCE: case OBJ_MERGE:
        for (int i = 0; i < o->u.csg.nchildren && depth < MAX_NESTING; i++) {
            const SceneObject *odd = no_inside_known(o->u.csg.children[i], depth + 1);
            if (odd)
                return odd;
        }
        return NULL;
    default:
        return o;
    }
}

/* interior_texture { }: POV-Ray's Interior_Texture, the texture shown
 * where a ray meets the object's surface from inside; a second one is a
 * layer on the first. */
static void apply_interior_texture(Parser *p, SceneObject *o, const Token *at)
{
    const SceneObject *odd = no_inside_known(o, 0);
    if (odd) {
        char msg[96];
        snprintf(msg, sizeof msg, "'interior_texture' on a '%s'", object_kind_name(odd->kind));
        tok_unsupported_at(p, at->pos, msg);
    }
    SceneTexture *tex = gram_texture(p);
    rebind_textures(p, o);
    o->interior_texture = o->interior_texture ? gram_layer_textures(p, tex, o->interior_texture, at) : tex;
}

/* An object's material: on its texture and interior so far. */
static void object_material(Parser *p, SceneObject *o, const Token *at)
{
    const SceneTexture *before = o->texture;
    gram_material(p, &o->texture, &o->interior, at);
    if (o->texture != before)
        rebind_own_texture(p, o); /* as apply_texture: later transforms move it */
}

const SceneTexture *gram_texture_uv_mapped(Parser *p, const SceneTexture *tex)
{
    if (!tex || (tex->pigment.uv_mapping && (!tex->normal || tex->normal->kind == NORMAL_UV)))
        return tex;
    SceneTexture *copy = tok_scene_alloc(p, sizeof *copy);
    *copy = *tex;
    copy->pigment.uv_mapping = 1;
    copy->normal = gram_normal_uv_mapped(p, tex->normal);
    copy->below = gram_texture_uv_mapped(p, tex->below); /* every layer */
    return copy;
}

/* An object's photons { }, as POV-Ray 3.7's Parse_Object_Mods reads it:
 * `target [spacing]` makes the object a photon target where the spacing
 * multiplier (default 1) is positive; the rest (refraction, reflection,
 * pass_through, collect) only steer photons, which hstrace does not shoot. */
static void object_photons(Parser *p, SceneObject *o)
{
    tok_begin_block(p, "photons");
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            return;
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_target: {
            double spacing = expr_starts_float(p, tok_peek(p)) ? expr_float(p) : 1.0;
            o->photon_target = spacing > 0.0;
            break;
        }
        case KW_refraction: case KW_reflection: (void)expr_float(p); break;
        case KW_pass_through: case KW_collect: (void)optional_bool(p); break;
        default:
            tok_fail_expected(p, t, "target, refraction, reflection, pass_through, collect or '}' in 'photons'");
        }
    }
}

SceneObject *gram_new_object(Parser *p, ObjectKind kind, const Token *t) { return new_object(p, kind, t); }
/* The objects of clipped_by { } or bounded_by { } (POV-Ray's
 * Parse_Bound_Clip): one or more, then transforms for them all, then '}';
 * each placed relative to o's transform so far (SceneObject.clips) and
 * appended to *list. Clips must be solids. */
static void parse_bound_clip(Parser *p, SceneObject *o, const Token *kw, int clip, int *n, SceneObject ***list)
{
    const char *what = clip ? "clipped_by" : "bounded_by";
    TempVec objects;
    tok_tvec_init(&objects, sizeof(SceneObject *));
    Token t;
    for (;;) {
        t = *tok_next(p);
        SceneObject *c = NULL;
        SceneLight *light = NULL;
        if (!gram_object(p, &t, &c, &light)) {
            tok_unget(p);
            break;
        }
        if (light)
            tok_fail(p, t.pos, "a light_source in '%s'", what);
        if (clip && c->texture)
            tok_fail(p, c->pos, "a texture on an object in 'clipped_by' (POV-Ray: illegal texture in clip)");
        *(SceneObject **)tok_tvec_push(p, &objects) = c;
    }
    if (objects.n == 0) {
        char msg[64];
        snprintf(msg, sizeof msg, "an object in '%s'", what);
        tok_fail_expected(p, tok_next(p), msg);
    }
    Transform moved;
    transform_identity(&moved);
    for (;;) {
        Token *m = tok_next(p);
        if (tok_is_punct(m, '}'))
            break;
        if (!expr_transform_item(p, m, &moved)) {
            char msg[96];
            snprintf(msg, sizeof msg, "an object, a transform or '}' in '%s'", what);
            tok_fail_expected(p, m, msg);
        }
    }
    /* back out of o's transforms so far: those after this follow it */
    Transform undo;
    memcpy(undo.m, o->transform.inv, sizeof undo.m);
    memcpy(undo.inv, o->transform.m, sizeof undo.inv);
    SceneObject **all = tok_scene_alloc(p, sizeof *all * (size_t)(*n + objects.n));
    for (int i = 0; i < *n; i++)
        all[i] = (*list)[i];
    for (int i = 0; i < objects.n; i++) {
        SceneObject *c = ((SceneObject **)objects.data)[i];
        transform_compose(&c->transform, &moved);
        transform_compose(&c->transform, &undo);
        if (!transform_is_similarity(&c->transform))
            c->general_transform = 1;
        if (clip) {
            const SceneObject *odd = first_non_solid(c);
            if (odd) {
                char msg[96];
                snprintf(msg, sizeof msg, "'%s' in 'clipped_by'", object_kind_name(odd->kind));
                tok_unsupported_at(p, odd->pos, msg);
            }
        }
        all[*n + i] = c;
    }
    *n += objects.n;
    *list = all;
    (void)kw;
}

/* Whether bounded_by's first token t starts an object hstrace reads (kept
 * for clipped_by { bounded_by }); others' bodies are passed over, a bound
 * having no effect on the image. */
static int bound_readable(Parser *p, const Token *t)
{
    if (t->type != TK_WORD)
        return 0;
    switch (t->kw) {
    case KW_box: case KW_plane: case KW_union: case KW_object: case KW_sphere: case KW_disc: case KW_cylinder:
    case KW_cone: case KW_torus: case KW_intersection: case KW_difference: case KW_merge: case KW_quadric:
    case KW_poly: case KW_cubic: case KW_quartic: case KW_superellipsoid: case KW_lathe: case KW_sor: case KW_prism:
        return 1;
    default:
        break;
    }
    if (t->kw >= 0)
        return 0;
    Symbol *sym = tok_symbol_find(p, t->text, t->len);
    return sym && sym->value.kind == VAL_OBJECT;
}

/* clipped_by { OBJECTS } or clipped_by { bounded_by }; bounded_by {
 * OBJECTS } or bounded_by { clipped_by } (POV-Ray's Parse_Object_Mods). */
static void object_bound_clip(Parser *p, SceneObject *o, const Token *kw, int clip)
{
    tok_begin_block(p, clip ? "clipped_by" : "bounded_by");
    Token *t = tok_next(p);
    if (t->type == TK_WORD && t->kw == (clip ? KW_bounded_by : KW_clipped_by)) {
        tok_expect_punct(p, '}', clip ? "'}' after 'bounded_by' in 'clipped_by'" : "'}' after 'clipped_by' in 'bounded_by'");
        if (clip) {
            o->nclips = o->nbounds;
            o->clips = o->bounds;
        } else {
            o->nbounds = o->nclips;
            o->bounds = o->clips;
        }
    } else if (!clip && !bound_readable(p, t) && o->kind != OBJ_POLY && o->kind != OBJ_QUADRIC) {
        /* a hint hstrace need not read: passed over, as it always was (a
         * poly's and a quadric's bound is read: POV-Ray tests it) */
        tok_skip_block_body(p);
    } else {
        tok_unget(p);
        if (clip)
            parse_bound_clip(p, o, kw, 1, &o->nclips, &o->clips);
        else
            parse_bound_clip(p, o, kw, 0, &o->nbounds, &o->bounds);
    }
    for (int i = 0; clip && i < o->nclips; i++) /* the copies of a declaration nest no deeper than unions */
        if (o->clips[i]->depth + 1 > o->depth)
            o->depth = o->clips[i]->depth + 1;
    if (o->depth > MAX_NESTING)
        tok_fail(p, kw->pos, "nested too deeply (clipped_by inside clipped_by more than %d levels)", MAX_NESTING);
    /* POV-Ray keeps a poly's and a quadric's bound and tests it first
     * (src/geometry/flatten.c's bound_kept): hstrace tests solids alone */
    for (int i = 0; !clip && (o->kind == OBJ_POLY || o->kind == OBJ_QUADRIC) && i < o->nbounds; i++) {
        const SceneObject *odd = first_non_solid(o->bounds[i]);
        if (odd) {
            char msg[96];
            snprintf(msg, sizeof msg, "'%s' in 'bounded_by' of a '%s'", object_kind_name(odd->kind),
                     object_kind_name(o->kind));
            tok_unsupported_at(p, odd->pos, msg);
        }
    }
    if (clip && o->nclips > 0) {
        const SceneObject *odd = first_non_solid(o);
        if (odd) {
            char msg[96];
            snprintf(msg, sizeof msg, "'clipped_by' on a '%s'", object_kind_name(odd->kind));
            tok_unsupported_at(p, kw->pos, msg);
        }
    }
}

/* Modifiers up to the object's closing '}'. */
static void parse_object_mods(Parser *p, SceneObject *o, const char *what)
{
    int uv = 0;
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}')) {
            gram_primitive_extent(o); /* min_extent's box, from the transforms written so far */
            if (o->interior_texture && !o->texture) /* POV-Ray's Parse_Object_Mods' rule */
                tok_fail(p, t->pos, "Interior texture requires an exterior texture.");
            if (uv) {
                o->texture = gram_texture_uv_mapped(p, o->texture);
                o->interior_texture = gram_texture_uv_mapped(p, o->interior_texture);
                if (o->kind == OBJ_MESH) {
                    const SceneTexture **list = tok_scene_alloc(p, sizeof *list * (size_t)(o->u.mesh.ntextures + 1));
                    for (int i = 0; i < o->u.mesh.ntextures; i++)
                        list[i] = gram_texture_uv_mapped(p, o->u.mesh.textures[i]);
                    o->u.mesh.textures = list;
                }
            }
            return;
        }
        Token at = *t;
        Transform step;
        if (expr_transform_step(p, t, &o->transform, &step)) {
            gram_extent_transform(o, &step); /* POV-Ray's Recompute_BBox, step by step */
            if (o->kind == OBJ_SPHERE)
                gram_sphere_extent_step(p, o, at.kw, &step);
            /* what POV-Ray's analytic shapes take into their own parameters
             * (Translate, Rotate, a uniform Scale) and what they do not */
            if (at.kw == KW_matrix || at.kw == KW_transform || !transform_is_similarity(&o->transform))
                o->general_transform = 1;
            continue;
        }
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_texture:
            apply_texture(p, o, gram_texture(p), &at);
            break;
        case KW_interior_texture: apply_interior_texture(p, o, &at); break;
        case KW_pigment:
            gram_pigment(p, &own_texture(p, o, &at)->pigment);
            rebind_own_texture(p, o);
            break;
        case KW_finish:
            gram_finish(p, &own_texture(p, o, &at)->finish);
            break;
        case KW_normal: {
            /* as a pigment: it gives the object a texture of its own */
            SceneTexture *tex = own_texture(p, o, &at);
            tex->normal = gram_normal(p, tex->normal, &at, 1);
            rebind_own_texture(p, o);
            break;
        }
        case KW_interior: {
            Interior *in = tok_scene_alloc(p, sizeof *in);
            *in = o->interior ? *o->interior : scene_default_interior();
            gram_interior(p, in);
            o->interior = in;
            break;
        }
        case KW_material: object_material(p, o, &at); break;
        case KW_no_shadow: o->no_shadow = optional_bool(p) ? 1u : 0u; break;
        case KW_no_image: o->no_image = optional_bool(p) ? 1u : 0u; break;
        case KW_no_reflection: o->no_reflection = optional_bool(p) ? 1u : 0u; break;
        case KW_no_radiosity: break; /* no radiosity in hstrace */
        case KW_hollow: o->hollow = optional_bool(p) ? 1u : 0u; break;
        case KW_inverse: o->inverse = !o->inverse; break;
        case KW_double_illuminate: o->double_illuminate = 1; break;
        case KW_sturm: o->sturm = optional_bool(p) ? 1u : 0u; break;
        case KW_split_union: skip_optional_float(p); break;
        case KW_hierarchy: /* POV-Ray's bounding inside a height field, mesh or CSG: no effect on the image */
            if (o->kind != OBJ_HEIGHT_FIELD && o->kind != OBJ_MESH && o->kind != OBJ_UNION && o->kind != OBJ_BLOB)
                tok_fail(p, at.pos, "Keyword 'hierarchy' cannot be used with this object (height fields, meshes, blobs and CSG take it).");
            (void)optional_bool(p);
            break;
        case KW_uv_mapping: uv = 1; break; /* every texture of the object, at the end */
        case KW_cutaway_textures: break; /* no effect on solid colours */
        case KW_photons:
            tok_note_approximation(p, &at, APPROX_PHOTONS, &o->photons);
            object_photons(p, o);
            break;
        case KW_radiosity: /* per-object radiosity settings: nothing without radiosity */
            tok_begin_block(p, "radiosity");
            tok_skip_block_body(p);
            break;
        case KW_bounded_by: /* a hint for POV-Ray's bounding: no effect on the image */
            object_bound_clip(p, o, &at, 0);
            break;
        case KW_clipped_by: object_bound_clip(p, o, &at, 1); break;
        default:
            if (expr_starts_colour(p, t)) { /* a "quick colour": preview only */
                Colour ignored;
                tok_unget(p);
                expr_colour(p, &ignored, 1);
                break;
            }
            if (t->type == TK_WORD && t->kw >= 0 && !gram_is_object_keyword(t->kw))
                tok_unsupported(p, t); /* bounded_by, clipped_by, ... */
            {
                char msg[96];
                snprintf(msg, sizeof msg, "an object modifier or '}' in '%s'", what);
                tok_fail_expected(p, t, msg);
            }
        }
    }
}

void gram_object_mods(Parser *p, SceneObject *o, const char *what) { parse_object_mods(p, o, what); }

void gram_transform_object(SceneObject *o, const Transform *tr)
{
    transform_compose(&o->transform, tr);
    if (!transform_is_similarity(&o->transform))
        o->general_transform = 1;
}

static Vec3 *vec3_array(Parser *p, const TempVec *v)
{
    Vec3 *out = tok_scene_alloc(p, sizeof(Vec3) * (size_t)(v->n > 0 ? v->n : 1));
    if (v->n)
        memcpy(out, v->data, sizeof(Vec3) * (size_t)v->n);
    return out;
}

int gram_outlines(Parser *p, TempVec *pts, double epsilon, TempVec *starts)
{
    tok_tvec_init(starts, sizeof(int));
    *(int *)tok_tvec_push(p, starts) = 0;
    Vec3 *v = pts->data;
    const int n = pts->n;
    Vec3 first = v[0];
    int closed = 0;
    for (int i = 1; i < n; i++) {
        closed = 0;
        if (fabs(first.x - v[i].x) < epsilon && fabs(first.y - v[i].y) < epsilon && fabs(first.z - v[i].z) < epsilon) {
            v[i] = first;
            i++;
            if (i < n) {
                first = v[i];
                *(int *)tok_tvec_push(p, starts) = i;
            }
            closed = 1;
        }
    }
    if (!closed)
        *(Vec3 *)tok_tvec_push(p, pts) = first;
    *(int *)tok_tvec_push(p, starts) = pts->n;
    return closed;
}

/* An element count read from the file, sanity-checked against garbage. */
static int parse_count(Parser *p, const char *what, int minimum)
{
    Token at = *tok_peek(p);
    double n = expr_float(p);
    int count;
    if (!int_from_double(n, minimum, MAX_ELEMENT_COUNT, &count))
        tok_fail(p, at.pos, "%s: %g is not a usable count", what, n);
    return count;
}

static SceneObject *parse_polygon(Parser *p, const Token *kw)
{
    tok_begin_block(p, "polygon");
    SceneObject *o = new_object(p, OBJ_POLYGON, kw);
    Token at = *tok_peek(p);
    double count = expr_float(p);
    if (count < 3)
        tok_fail(p, at.pos, "polygon needs at least three points");
    int n;
    if (!int_from_double(count, 3, MAX_ELEMENT_COUNT, &n))
        tok_fail(p, at.pos, "polygon: %g is not a usable count", count);
    TempVec pts;
    tok_tvec_init(&pts, sizeof(Vec3));
    for (int i = 0; i < n; i++) {
        expr_comma(p);
        *(Vec3 *)tok_tvec_push(p, &pts) = expr_vector(p);
    }
    /* POV-Ray's outline rule (Parse_Polygon); an outline left open is
     * closed without POV-Ray's "Polygon not closed" warning, as before */
    TempVec starts;
    (void)gram_outlines(p, &pts, POLY_EPSILON, &starts);
    o->u.polygon.npoints = pts.n;
    o->u.polygon.points = vec3_array(p, &pts);
    o->u.polygon.noutlines = starts.n - 1;
    o->u.polygon.outline_start = tok_scene_alloc(p, sizeof(int) * (size_t)starts.n);
    memcpy(o->u.polygon.outline_start, starts.data, sizeof(int) * (size_t)starts.n);
    parse_object_mods(p, o, "polygon");
    return o;
}

static void parse_triangle_points(Parser *p, SceneObject *o, int smooth)
{
    for (int i = 0; i < 3; i++) {
        if (i)
            expr_comma(p);
        o->u.triangle.v[i] = expr_vector(p);
        if (smooth) {
            expr_comma(p);
            o->u.triangle.n[i] = expr_vector(p);
        }
    }
    o->u.triangle.has_normals = smooth;
}

static SceneObject *parse_triangle(Parser *p, const Token *kw, int smooth)
{
    const char *name = smooth ? "smooth_triangle" : "triangle";
    tok_begin_block(p, name);
    SceneObject *o = new_object(p, OBJ_TRIANGLE, kw);
    parse_triangle_points(p, o, smooth);
    parse_object_mods(p, o, name);
    return o;
}

static SceneObject *parse_box(Parser *p, const Token *kw)
{
    tok_begin_block(p, "box");
    SceneObject *o = new_object(p, OBJ_BOX, kw);
    o->u.box.corner1 = expr_vector(p);
    expr_comma(p);
    o->u.box.corner2 = expr_vector(p);
    parse_object_mods(p, o, "box");
    return o;
}

/* sphere { CENTER, RADIUS mods } (POV-Ray's Parse_Sphere). */
static SceneObject *parse_sphere(Parser *p, const Token *kw)
{
    tok_begin_block(p, "sphere");
    SceneObject *o = new_object(p, OBJ_SPHERE, kw);
    o->u.sphere.center = expr_vector(p);
    expr_comma(p);
    o->u.sphere.radius = expr_float(p);
    o->u.sphere.pov_center = o->u.sphere.center;
    o->u.sphere.pov_radius = o->u.sphere.radius;
    parse_object_mods(p, o, "sphere");
    return o;
}

/* disc { CENTER, NORMAL, RADIUS [, HOLE_RADIUS] mods } (Parse_Disc). */
static SceneObject *parse_disc(Parser *p, const Token *kw)
{
    tok_begin_block(p, "disc");
    SceneObject *o = new_object(p, OBJ_DISC, kw);
    o->u.disc.center = expr_vector(p);
    expr_comma(p);
    Token at = *tok_peek(p);
    Vec3 n = expr_vector(p);
    if (!(v3_length(n) > 0.0))
        tok_fail(p, at.pos, "degenerate disc normal");
    o->u.disc.normal = v3_normalize(n);
    expr_comma(p);
    o->u.disc.radius = expr_float(p);
    expr_comma(p);
    if (expr_starts_float(p, tok_peek(p)))
        o->u.disc.hole = expr_float(p);
    parse_object_mods(p, o, "disc");
    return o;
}

/* cylinder { BASE, CAP, RADIUS [open] mods } and
 * cone { BASE, BASE_RADIUS, CAP, CAP_RADIUS [open] mods } (Parse_Cylinder,
 * Parse_Cone): one kind, a cylinder's radii equal. POV-Ray refuses a
 * degenerate one (Compute_Cone_Data's error): so does hstrace. */
static SceneObject *parse_cone(Parser *p, const Token *kw, int cylinder)
{
    const char *name = cylinder ? "cylinder" : "cone";
    tok_begin_block(p, name);
    SceneObject *o = new_object(p, OBJ_CONE, kw);
    o->u.cone.base = expr_vector(p);
    expr_comma(p);
    if (!cylinder) {
        o->u.cone.base_radius = expr_float(p);
        expr_comma(p);
    }
    o->u.cone.apex = expr_vector(p);
    expr_comma(p);
    o->u.cone.apex_radius = expr_float(p);
    if (cylinder)
        o->u.cone.base_radius = o->u.cone.apex_radius;
    if (!(v3_length(v3_sub(o->u.cone.apex, o->u.cone.base)) >= 1e-10))
        tok_fail(p, kw->pos, "degenerate %s: its two ends are the same point", name);
    Token *t = tok_peek(p);
    if (t->type == TK_WORD && t->kw == KW_open) {
        (void)tok_next(p);
        o->u.cone.open = 1;
    }
    parse_object_mods(p, o, name);
    return o;
}

/* torus { MAJOR, MINOR mods } (Parse_Torus). */
static SceneObject *parse_torus(Parser *p, const Token *kw)
{
    tok_begin_block(p, "torus");
    SceneObject *o = new_object(p, OBJ_TORUS, kw);
    o->u.torus.major = expr_float(p);
    expr_comma(p);
    o->u.torus.minor = expr_float(p);
    parse_object_mods(p, o, "torus");
    return o;
}

static SceneObject *parse_plane(Parser *p, const Token *kw)
{
    tok_begin_block(p, "plane");
    SceneObject *o = new_object(p, OBJ_PLANE, kw);
    Token at = *tok_peek(p);
    o->u.plane.normal = expr_vector(p);
    if (v3_length(o->u.plane.normal) == 0.0)
        tok_fail(p, at.pos, "degenerate plane normal");
    expr_comma(p);
    o->u.plane.distance = expr_float(p);
    parse_object_mods(p, o, "plane");
    return o;
}

/* ---- meshes ------------------------------------------------------------ */

typedef struct {
    TempVec vertices, normals, faces, textures, uvs;
} MeshBuilder;

static int add_mesh_texture(Parser *p, MeshBuilder *mb, const SceneTexture *t)
{
    for (int i = 0; i < mb->textures.n; i++)
        if (((const SceneTexture **)mb->textures.data)[i] == t)
            return i;
    *(const SceneTexture **)tok_tvec_push(p, &mb->textures) = t;
    return mb->textures.n - 1;
}

/* A face given a texture per vertex (mesh2's three indices, a mesh
 * triangle's texture_list), as vertex-coloured exports write them: POV-Ray
 * blends the three textures' shaded colours by the point's place in the
 * face (Mesh::Determine_Textures), and so does hstrace where the three are
 * plain textures (flatten.c, pigment.h); a texture_map or a layered
 * texture among them leaves
 * the face with the first vertex's texture, an approximation noted once
 * per mesh, at the first such face (`at`). Called for faces whose three
 * textures differ. */
static int is_map(const SceneTexture *t) { return t && (t->nmap > 0 || t->below); }

static void vertex_textures(Parser *p, SceneObject *o, const Token *at, const SceneTexture *const tex[3], int *noted)
{
    if (*noted || !(is_map(tex[0]) || is_map(tex[1]) || is_map(tex[2])))
        return;
    *noted = 1;
    static const char what[] = "a texture per vertex";
    Token t = *at;
    t.text = what;
    t.len = (int)sizeof what - 1;
    tok_approximate(p, &t, APPROX_VERTEX_TEXTURES, &o->approx);
}

static void finish_mesh(Parser *p, SceneObject *o, MeshBuilder *mb)
{
    /* mesh2's lists are read into the scene's arena (reserve_list): kept as they are */
    o->u.mesh.nvertices = mb->vertices.n;
    o->u.mesh.vertices = tok_tvec_kept(p, &mb->vertices);
    o->u.mesh.nnormals = mb->normals.n;
    o->u.mesh.normals = tok_tvec_kept(p, &mb->normals);
    o->u.mesh.nfaces = mb->faces.n;
    o->u.mesh.faces = tok_tvec_kept(p, &mb->faces);
    o->u.mesh.nuvs = mb->uvs.n;
    o->u.mesh.uvs = tok_tvec_kept(p, &mb->uvs);
    o->u.mesh.ntextures = mb->textures.n;
    o->u.mesh.textures = tok_scene_alloc(p, sizeof(SceneTexture *) * (size_t)(mb->textures.n ? mb->textures.n : 1));
    if (mb->textures.n)
        memcpy(o->u.mesh.textures, mb->textures.data, sizeof(SceneTexture *) * (size_t)mb->textures.n);
}

/* A mesh2 index: as POV-Ray's (int) of the value, within [0, n). */
static int mesh_index(double v, int n, int *out) { return int_from_double(v, 0, n - 1, out); }

/* mesh2's normal_indices or, with `uv`, uv_indices (after the keyword):
 * one index triple per face into the normals or uv vectors. */
static void parse_face_index_block(Parser *p, MeshBuilder *mb, int uv)
{
    const char *kind = uv ? "uv" : "normal", *range_what = uv ? "uv vectors" : "normals";
    const char *block = uv ? "uv_indices" : "normal_indices";
    int range = uv ? mb->uvs.n : mb->normals.n;
    tok_begin_block(p, block);
    Token ct = *tok_peek(p);
    int n = parse_count(p, block, 0);
    if (n != mb->faces.n)
        tok_fail(p, ct.pos, "number of %s indices must equal number of faces", kind);
    for (int i = 0; i < n; i++) {
        expr_comma(p);
        Token vt = *tok_peek(p);
        Vec3 idx = expr_vector(p);
        MeshFace *f = (MeshFace *)mb->faces.data + i;
        int *slot = uv ? f->uv : f->n;
        if (!mesh_index(idx.x, range, &slot[0]) || !mesh_index(idx.y, range, &slot[1]) ||
            !mesh_index(idx.z, range, &slot[2]))
            tok_fail(p, vt.pos, "mesh2 %s index out of range (%d %s)", kind, range, range_what);
    }
    expr_comma(p); /* POV-Ray takes a comma after every item, the last too */
    tok_expect_punct(p, '}', block);
}

static void init_mesh_builder(MeshBuilder *mb)
{
    tok_tvec_init(&mb->vertices, sizeof(Vec3));
    tok_tvec_init(&mb->normals, sizeof(Vec3));
    tok_tvec_init(&mb->faces, sizeof(MeshFace));
    tok_tvec_init(&mb->textures, sizeof(SceneTexture *));
    tok_tvec_init(&mb->uvs, sizeof(Vec3));
}

static SceneObject *parse_mesh(Parser *p, const Token *kw)
{
    tok_begin_block(p, "mesh");
    SceneObject *o = new_object(p, OBJ_MESH, kw);
    MeshBuilder mb;
    init_mesh_builder(&mb);
    int noted = 0; /* a face with a texture per vertex, noted */
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_kw(t, KW_triangle) || tok_is_kw(t, KW_smooth_triangle)) {
            int smooth = t->kw == KW_smooth_triangle;
            tok_begin_block(p, smooth ? "smooth_triangle" : "triangle");
            SceneObject tri;
            memset(&tri, 0, sizeof tri);
            parse_triangle_points(p, &tri, smooth);
            MeshFace *f = tok_tvec_push(p, &mb.faces);
            for (int i = 0; i < 3; i++) {
                f->uv[i] = -1; /* uv (0, 0) unless given */
                f->v[i] = mb.vertices.n;
                *(Vec3 *)tok_tvec_push(p, &mb.vertices) = tri.u.triangle.v[i];
                f->n[i] = -1;
                if (smooth) {
                    f->n[i] = mb.normals.n;
                    *(Vec3 *)tok_tvec_push(p, &mb.normals) = tri.u.triangle.n[i];
                }
            }
            f->texture = f->texture2 = f->texture3 = -1;
            for (;;) {
                t = tok_next(p);
                if (tok_is_punct(t, '}'))
                    break;
                if (tok_is_kw(t, KW_texture)) {
                    int idx = add_mesh_texture(p, &mb, gram_texture(p));
                    ((MeshFace *)mb.faces.data)[mb.faces.n - 1].texture = idx;
                } else if (tok_is_kw(t, KW_texture_list)) {
                    /* POV-Ray's Parse_Mesh_Texture: three declared textures, one per vertex */
                    Token at = *t;
                    const SceneTexture *vertex[3];
                    tok_begin_block(p, "texture_list");
                    for (int i = 0; i < 3; i++) {
                        if (i)
                            expr_comma(p);
                        Token *id = tok_next(p);
                        const Value *v = gram_block_identifier(p, id, VAL_TEXTURE, "texture_list");
                        if (!v)
                            tok_fail_expected(p, id, "a texture identifier in a mesh triangle's texture_list");
                        vertex[i] = v->texture;
                    }
                    tok_expect_punct(p, '}', "texture_list");
                    MeshFace *face = (MeshFace *)mb.faces.data + mb.faces.n - 1;
                    face->texture = add_mesh_texture(p, &mb, vertex[0]);
                    if (vertex[1] != vertex[0] || vertex[2] != vertex[0]) {
                        vertex_textures(p, o, &at, vertex, &noted);
                        face->texture2 = add_mesh_texture(p, &mb, vertex[1]);
                        face->texture3 = add_mesh_texture(p, &mb, vertex[2]);
                    }
                } else if (tok_is_kw(t, KW_uv_vectors)) {
                    MeshFace *face = (MeshFace *)mb.faces.data + mb.faces.n - 1;
                    for (int i = 0; i < 3; i++) {
                        if (i)
                            expr_comma(p);
                        Vec3 uv = expr_vector(p);
                        face->uv[i] = mb.uvs.n;
                        *(Vec3 *)tok_tvec_push(p, &mb.uvs) = v3(uv.x, uv.y, 0.0);
                    }
                } else {
                    if (t->type == TK_WORD && t->kw >= 0)
                        tok_unsupported(p, t);
                    tok_fail_expected(p, t, "texture, texture_list, uv_vectors or '}' in a mesh triangle");
                }
            }
        } else if (tok_is_kw(t, KW_inside_vector)) {
            (void)expr_vector(p);
        } else if (tok_is_kw(t, KW_hierarchy)) {
            skip_optional_float(p);
        } else {
            tok_unget(p);
            break;
        }
    }
    finish_mesh(p, o, &mb);
    parse_object_mods(p, o, "mesh");
    return o;
}

/* Room for the n items a mesh2 list announces, but for no more than the
 * text left could write (a plain vector takes at least 7 bytes, `<0,0,0>`):
 * a count far beyond its list fails where the list ends, as it would
 * without the room, not for want of memory. */
static void reserve_list(Parser *p, TempVec *out, int n)
{
    size_t could = tok_bytes_left(p) / 7 + 1;
    tok_tvec_reserve_kept(p, out, (size_t)n < could ? n : (int)(could < (1u << 28) ? could : (1u << 28)));
}

static void parse_vector_list(Parser *p, TempVec *out, const char *what)
{
    tok_begin_block(p, what);
    int n = parse_count(p, what, 0);
    reserve_list(p, out, n);
    int i = 0;
    if (out->n == 0 && out->cap >= n && tok_plain_vector_list(p, n, out->data, NULL, 0)) {
        out->n = n; /* all of them at once (plain_lists.c) */
        i = n;
    }
    for (; i < n; i++) {
        expr_comma(p);
        *(Vec3 *)tok_tvec_push(p, out) = expr_vector(p);
    }
    expr_comma(p); /* POV-Ray takes a comma after every item, the last too */
    tok_expect_punct(p, '}', what);
}

static SceneObject *parse_mesh2(Parser *p, const Token *kw)
{
    tok_begin_block(p, "mesh2");
    SceneObject *o = new_object(p, OBJ_MESH, kw);
    MeshBuilder mb;
    init_mesh_builder(&mb);
    int have_faces = 0, have_normal_indices = 0, have_uv_indices = 0;
    int noted = 0; /* a face with a texture per vertex, noted */
    for (;;) {
        Token *t = tok_next(p);
        Token at = *t;
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_vertex_vectors:
            mb.vertices.n = 0;
            parse_vector_list(p, &mb.vertices, "vertex_vectors");
            continue;
        case KW_normal_vectors:
            mb.normals.n = 0;
            parse_vector_list(p, &mb.normals, "normal_vectors");
            for (int i = 0; i < mb.normals.n; i++) {
                Vec3 *nv = (Vec3 *)mb.normals.data + i;
                if (v3_length(*nv) == 0.0)
                    *nv = v3(1, 0, 0); /* as POV-Ray, with its warning */
            }
            continue;
        case KW_uv_vectors: /* for uv_mapping */
            mb.uvs.n = 0;
            parse_vector_list(p, &mb.uvs, "uv_vectors");
            for (int i = 0; i < mb.uvs.n; i++)
                ((Vec3 *)mb.uvs.data)[i].z = 0.0;
            continue;
        case KW_texture_list: {
            tok_begin_block(p, "texture_list");
            int n = parse_count(p, "texture_list", 0);
            mb.textures.n = 0;
            for (int i = 0; i < n; i++) {
                expr_comma(p);
                Token *tt = tok_next(p);
                if (!tok_is_kw(tt, KW_texture))
                    tok_fail_expected(p, tt, "'texture' in 'texture_list'");
                *(const SceneTexture **)tok_tvec_push(p, &mb.textures) = gram_texture(p);
            }
            expr_comma(p); /* POV-Ray takes a comma after every item, the last too */
            tok_expect_punct(p, '}', "texture_list");
            continue;
        }
        case KW_face_indices: {
            tok_begin_block(p, "face_indices");
            int n = parse_count(p, "face_indices", 1);
            mb.faces.n = 0;
            reserve_list(p, &mb.faces, n);
            int i = 0;
            if (mb.faces.cap >= n && tok_plain_vector_list(p, n, NULL, mb.faces.data, mb.vertices.n)) {
                mb.faces.n = n; /* all of them at once (plain_lists.c) */
                i = n;
            }
            for (; i < n; i++) {
                expr_comma(p);
                Token vt = *tok_peek(p);
                Vec3 idx = expr_vector(p);
                MeshFace *f = tok_tvec_push(p, &mb.faces);
                if (!mesh_index(idx.x, mb.vertices.n, &f->v[0]) || !mesh_index(idx.y, mb.vertices.n, &f->v[1]) ||
                    !mesh_index(idx.z, mb.vertices.n, &f->v[2]))
                    tok_fail(p, vt.pos, "mesh2 face index out of range (%d vertices)", mb.vertices.n);
                f->n[0] = f->n[1] = f->n[2] = -1;
                f->uv[0] = f->uv[1] = f->uv[2] = -1;
                f->texture = f->texture2 = f->texture3 = -1;
                /* one texture index, or three: one per vertex (vertex_textures) */
                int ti[3], nt = 0;
                Token first_other = *tok_peek(p);
                for (int k = 0; k < 3; k++) {
                    expr_comma(p);
                    if (!expr_starts_float(p, tok_peek(p)))
                        break;
                    Token it = *tok_peek(p);
                    if (k == 1)
                        first_other = it;
                    if (!mesh_index(expr_float(p), mb.textures.n, &ti[k]))
                        tok_fail(p, it.pos, "texture index out of range in mesh2");
                    nt++;
                }
                if (nt > 0)
                    f->texture = ti[0];
                if (nt == 3 && (ti[1] != ti[0] || ti[2] != ti[0])) {
                    const SceneTexture *const *list = (const SceneTexture *const *)mb.textures.data;
                    const SceneTexture *const vertex[3] = { list[ti[0]], list[ti[1]], list[ti[2]] };
                    vertex_textures(p, o, &first_other, vertex, &noted);
                    f->texture2 = ti[1];
                    f->texture3 = ti[2];
                }
            }
            expr_comma(p); /* POV-Ray takes a comma after every item, the last too */
            tok_expect_punct(p, '}', "face_indices");
            have_faces = 1;
            continue;
        }
        case KW_normal_indices:
            if (!have_faces)
                tok_fail(p, at.pos, "normal_indices must follow face_indices in mesh2");
            parse_face_index_block(p, &mb, 0);
            have_normal_indices = 1;
            continue;
        case KW_uv_indices:
            if (!have_faces)
                tok_fail(p, at.pos, "uv_indices must follow face_indices in mesh2");
            parse_face_index_block(p, &mb, 1);
            have_uv_indices = 1;
            continue;
        case KW_inside_vector:
            (void)expr_vector(p);
            continue;
        default:
            break;
        }
        tok_unget(p);
        break;
    }
    Token end = *tok_peek(p);
    if (mb.vertices.n == 0)
        tok_fail(p, end.pos, "vertex_vectors not found in mesh2");
    if (!have_faces)
        tok_fail(p, end.pos, "face_indices not found in mesh2");
    if (!have_normal_indices && mb.normals.n > 0) {
        /* POV-Ray: as many normals as vertices means "same indices" */
        if (mb.normals.n != mb.vertices.n)
            tok_fail(p, end.pos, "normal_indices missing in mesh2");
        for (int i = 0; i < mb.faces.n; i++) {
            MeshFace *f = (MeshFace *)mb.faces.data + i;
            memcpy(f->n, f->v, sizeof f->n);
        }
    }
    if (!have_uv_indices && mb.uvs.n > 1) {
        /* POV-Ray: as many uv vectors as vertices means "same indices";
         * one (or none: uv 0, 0) serves every corner */
        if (mb.uvs.n != mb.vertices.n)
            tok_fail(p, end.pos, "uv_indices missing in mesh2");
        for (int i = 0; i < mb.faces.n; i++) {
            MeshFace *f = (MeshFace *)mb.faces.data + i;
            memcpy(f->uv, f->v, sizeof f->uv);
        }
    } else if (!have_uv_indices && mb.uvs.n == 1) {
        for (int i = 0; i < mb.faces.n; i++)
            memset(((MeshFace *)mb.faces.data)[i].uv, 0, sizeof(int) * 3);
    }
    finish_mesh(p, o, &mb);
    parse_object_mods(p, o, "mesh2");
    return o;
}

/* ---- union and object{} ------------------------------------------------- */

/* union, intersection, difference and merge: `name` { OBJECTS MODIFIERS }. */
static SceneObject *parse_children(Parser *p, const Token *kw, ObjectKind kind, const char *name)
{
    tok_begin_block(p, name);
    SceneObject *o = new_object(p, kind, kw);
    TempVec children, lights, slots;
    tok_tvec_init(&children, sizeof(SceneObject *));
    tok_tvec_init(&lights, sizeof(SceneLight));
    tok_tvec_init(&slots, sizeof(int));
    for (;;) {
        Token t = *tok_next(p);
        SceneObject *child = NULL;
        SceneLight *light = NULL;
        if (!gram_object(p, &t, &child, &light)) {
            tok_unget(p);
            break;
        }
        if (light) {
            *(SceneLight *)tok_tvec_push(p, &lights) = *light;
            *(int *)tok_tvec_push(p, &slots) = children.n;
            continue;
        }
        *(SceneObject **)tok_tvec_push(p, &children) = child;
    }
    o->u.csg.nchildren = children.n;
    o->u.csg.children = tok_scene_alloc(p, sizeof(SceneObject *) * (size_t)(children.n ? children.n : 1));
    if (children.n)
        memcpy(o->u.csg.children, children.data, sizeof(SceneObject *) * (size_t)children.n);
    /* Written unions nest as deep as the text (tok_nesting_enter counts them),
     * but `#declare U = union { object { U } }` in a loop nests a copy one
     * level deeper each time: the depth is bounded here, where it grows. */
    o->depth = 1;
    for (int i = 0; i < children.n; i++)
        if (o->u.csg.children[i]->depth + 1 > o->depth)
            o->depth = o->u.csg.children[i]->depth + 1;
    if (o->depth > MAX_NESTING)
        tok_fail(p, kw->pos, "nested too deeply (%s inside %s more than %d levels)",
                 kind == OBJ_UNION ? "unions" : "CSG objects", kind == OBJ_UNION ? "unions" : "one another",
                 MAX_NESTING);
    if (kind != OBJ_UNION) {
        const SceneObject *odd = first_non_solid(o);
        if (odd) {
            char what[96];
            snprintf(what, sizeof what, "'%s' as a part of '%s'", object_kind_name(odd->kind), name);
            tok_unsupported_at(p, odd->pos, what);
        }
        /* POV-Ray renders it, with a warning (Parse_CSG) */
        if (children.n < 2)
            tok_warning(p, kw->pos, "should have at least 2 objects in csg");
    }
    if (lights.n) {
        SceneLight *l = tok_scene_alloc(p, sizeof(SceneLight) * (size_t)lights.n);
        int *slot = tok_scene_alloc(p, sizeof(int) * (size_t)lights.n);
        memcpy(l, lights.data, sizeof(SceneLight) * (size_t)lights.n);
        memcpy(slot, slots.data, sizeof(int) * (size_t)lights.n);
        o->u.csg.nlights = lights.n;
        o->u.csg.lights = l;
        o->u.csg.light_slot = slot;
    }
    gram_csg_extent(o); /* min_extent's box, before the modifiers move it */
    parse_object_mods(p, o, name);
    return o;
}

/* `object { LIGHT transforms }`: a light takes only transforms. */
static void parse_light_object_mods(Parser *p, SceneLight *l)
{
    for (;;) {
        Token *m = tok_next(p);
        if (tok_is_punct(m, '}'))
            return;
        Transform tr;
        transform_identity(&tr);
        if (!expr_transform_item(p, m, &tr))
            tok_fail_expected(p, m, "a transform or '}' after a light_source in 'object'");
        gram_transform_light(p, l, &tr);
    }
}

/* A use of a declared object: a copy of its top, which shares the rest. Its
 * interior is copied too, as POV-Ray's Copy_Object copies it: each copy is
 * an interior of its own to the rays that cross several (the interior's
 * identity is its address, Material.interior_key). */
static SceneObject *copy_declared_object(Parser *p, const SceneObject *declared)
{
    SceneObject *o = tok_scene_alloc(p, sizeof *o);
    *o = *declared;
    if (declared->interior) {
        Interior *own = tok_scene_alloc(p, sizeof *own);
        *own = *declared->interior;
        o->interior = own;
    }
    return o;
}

SceneObject *gram_copy_object(Parser *p, const SceneObject *o) { return copy_declared_object(p, o); }

/* Appends the light_sources of union `o` and of the unions inside it to the
 * scene's lights, in world space: `outer` is the transform of o's parents.
 * Order as POV-Ray's Post_Process: depth first, as written. */
void gram_instantiate_union_lights(Parser *p, const SceneObject *o, const Transform *outer, int depth)
{
    if (!scene_object_has_children(o->kind) || depth > MAX_NESTING)
        return;
    Transform world = o->transform;
    transform_compose(&world, outer);
    int next_light = 0;
    for (int c = 0; c <= o->u.csg.nchildren; c++) {
        for (; next_light < o->u.csg.nlights && o->u.csg.light_slot[next_light] == c; next_light++) {
            SceneLight *l = tok_tvec_push(p, &p->gram->lights);
            *l = o->u.csg.lights[next_light];
            gram_transform_light(p, l, &world);
            if (l->looks_like) {
                SceneObject *shown = copy_declared_object(p, l->looks_like); /* a light's own */
                if (!shown->texture && p->gram->default_changed)
                    shown->texture = gram_default_texture(p);
                *(SceneObject **)tok_tvec_push(p, &p->gram->objects) = shown;
            }
        }
        if (c < o->u.csg.nchildren)
            gram_instantiate_union_lights(p, o->u.csg.children[c], &world, depth + 1);
    }
}

static void parse_object_statement(Parser *p, const Token *kw, SceneObject **obj, SceneLight **light)
{
    tok_begin_block(p, "object");
    Token t = *tok_next(p);
    if (t.type == TK_WORD && t.kw < 0) {
        Symbol *s = tok_symbol_of(p, &t);
        if (!s)
            tok_fail(p, t.pos, "undeclared identifier '%.*s'", t.len, t.text);
        const Value *v = &s->value;
        if (v->kind == VAL_UNSUPPORTED)
            tok_use_unsupported(p, &t, v);
        if (v->kind == VAL_LIGHT) {
            SceneLight *l = tok_scene_alloc(p, sizeof *l);
            *l = *v->light;
            l->pos = kw->pos;
            parse_light_object_mods(p, l);
            *light = l;
            return;
        }
        if (v->kind != VAL_OBJECT)
            tok_fail(p, t.pos, "'%.*s' is not an object", t.len, t.text);
        SceneObject *o = copy_declared_object(p, v->object);
        o->pos = kw->pos;
        parse_object_mods(p, o, "object");
        *obj = o;
        return;
    }
    SceneObject *inner = NULL;
    SceneLight *inner_light = NULL;
    if (!gram_object(p, &t, &inner, &inner_light))
        tok_fail_expected(p, &t, "an object or object identifier after 'object {'");
    if (inner_light) {
        parse_light_object_mods(p, inner_light);
        *light = inner_light;
        return;
    }
    parse_object_mods(p, inner, "object");
    *obj = inner;
}

/* After object keyword `kw`: '{' then the name of a declared object or
 * light. An unsupported value counts only after 'union', whose body cannot
 * start with a number: elsewhere it may be a float or vector (a function's,
 * trace's), which the object's own parse reports. */
static int object_id_follows(Parser *p, int kw)
{
    Token word;
    if (!tok_next_is_brace_and_word(p, &word) || word.kw >= 0)
        return 0;
    Symbol *s = tok_symbol_find(p, word.text, word.len);
    if (!s)
        return 0;
    ValueKind k = s->value.kind;
    return k == VAL_OBJECT || k == VAL_LIGHT ||
           (k == VAL_UNSUPPORTED && (kw == KW_union || kw == KW_intersection || kw == KW_difference || kw == KW_merge));
}

/* A declared object or light named on its own, as LDCad ends its model
 * (`#declare Model = union {...}` then `Model`): POV-Ray 3.7's Parse_Object
 * takes an object identifier as a copy of it, without modifiers, wherever
 * it takes an object -- at the top level (Parse_Frame) and among a union's
 * children (Parse_CSG). Returns 0 when t is no such identifier; one that
 * holds an unsupported declaration is that declaration's error. */
static int bare_object_identifier(Parser *p, const Token *t, SceneObject **obj, SceneLight **light)
{
    if (t->type != TK_WORD || t->kw >= 0)
        return 0;
    Symbol *s = tok_symbol_of(p, t);
    if (!s)
        return 0;
    const Value *v = &s->value;
    if (v->kind == VAL_UNSUPPORTED)
        tok_use_unsupported(p, t, v);
    if (v->kind == VAL_LIGHT) {
        SceneLight *l = tok_scene_alloc(p, sizeof *l);
        *l = *v->light;
        l->pos = t->pos;
        *light = l;
        return 1;
    }
    if (v->kind != VAL_OBJECT)
        return 0;
    SceneObject *o = copy_declared_object(p, v->object);
    o->pos = t->pos;
    *obj = o;
    return 1;
}

int gram_object(Parser *p, const Token *t, SceneObject **obj, SceneLight **light)
{
    *obj = NULL;
    *light = NULL;
    if (bare_object_identifier(p, t, obj, light))
        return 1;
    if (t->type != TK_WORD || (!gram_is_object_keyword(t->kw) && t->kw != KW_light_source))
        return 0;
    Token kw = *t;
    tok_nesting_enter(p, &kw);
    if (kw.kw != KW_object && object_id_follows(p, kw.kw)) {
        /* `light_source { SubPatch translate ... }`, `union { U ... }`:
         * POV-Ray's Parse_Object_Id takes a declared object or light after
         * any object keyword's '{' as `object { ID ... }` */
        parse_object_statement(p, &kw, obj, light);
        tok_nesting_leave(p);
        return 1;
    }
    switch (kw.kw) {
    case KW_polygon: *obj = parse_polygon(p, &kw); break;
    case KW_triangle: *obj = parse_triangle(p, &kw, 0); break;
    case KW_smooth_triangle: *obj = parse_triangle(p, &kw, 1); break;
    case KW_mesh: *obj = parse_mesh(p, &kw); break;
    case KW_mesh2: *obj = parse_mesh2(p, &kw); break;
    case KW_box: *obj = parse_box(p, &kw); break;
    case KW_plane: *obj = parse_plane(p, &kw); break;
    case KW_height_field: *obj = gram_height_field(p, &kw); break;
    case KW_bicubic_patch: *obj = gram_bicubic_patch(p, &kw); break;
    case KW_prism: *obj = gram_prism(p, &kw); break;
    case KW_text: *obj = gram_text(p, &kw); break;
    case KW_sphere: *obj = parse_sphere(p, &kw); break;
    case KW_disc: *obj = parse_disc(p, &kw); break;
    case KW_cylinder: *obj = parse_cone(p, &kw, 1); break;
    case KW_cone: *obj = parse_cone(p, &kw, 0); break;
    case KW_torus: *obj = parse_torus(p, &kw); break;
    case KW_quadric: *obj = gram_quadric(p, &kw); break;
    case KW_poly: *obj = gram_poly(p, &kw, 0); break;
    case KW_cubic: *obj = gram_poly(p, &kw, 3); break;
    case KW_quartic: *obj = gram_poly(p, &kw, 4); break;
    case KW_superellipsoid: *obj = gram_superellipsoid(p, &kw); break;
    case KW_lathe: *obj = gram_lathe(p, &kw); break;
    case KW_sor: *obj = gram_sor(p, &kw); break;
    case KW_blob: *obj = gram_blob(p, &kw); break;
    case KW_union: *obj = parse_children(p, &kw, OBJ_UNION, "union"); break;
    case KW_intersection: *obj = parse_children(p, &kw, OBJ_INTERSECTION, "intersection"); break;
    case KW_difference: *obj = parse_children(p, &kw, OBJ_DIFFERENCE, "difference"); break;
    case KW_merge: *obj = parse_children(p, &kw, OBJ_MERGE, "merge"); break;
    case KW_object: parse_object_statement(p, &kw, obj, light); break;
    case KW_light_source: *light = gram_light_source(p, &kw); break;
    default: tok_unsupported(p, &kw);
    }
    tok_nesting_leave(p);
    return 1;
}
