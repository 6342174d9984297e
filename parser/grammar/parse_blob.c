/* blob { threshold T  COMPONENTS  modifiers } as POV-Ray 3.7's Parse_Blob
 * and Parse_Blob_Element_Mods read it: spherical components (the old
 * `component STRENGTH, RADIUS, <CENTER>` and `sphere { <CENTER>, RADIUS,
 * [strength] STRENGTH mods }`) and cylindrical ones (`cylinder { <BASE>,
 * <APEX>, RADIUS, [strength] STRENGTH mods }`), each moved by its own
 * transforms; a texture of a component's own is refused (hstrace keeps one
 * texture per blob). */
#include "grammar.h"

#include <math.h>

#define BLOB_EPSILON 1e-10 /* POV-Ray's EPSILON: a shorter cylinder is degenerate */
#define MAX_BLOB_COMPONENTS 1000000 /* POV-Ray's, counting a cylinder as three */

/* A sphere component's transform (Translate_, Rotate_, Scale_ and
 * Transform_Blob_Element): translations, rotations and uniform scales move
 * its centre and radius; anything else makes it an ellipsoid, whose later
 * transforms accumulate. */
static void sphere_component_transform(SceneBlobComponent *c, int kw, const Transform *u)
{
    int uniform_scale = kw == KW_scale && u->m[0][0] == u->m[1][1] && u->m[0][0] == u->m[2][2];
    if (!c->own_space && (kw == KW_translate || kw == KW_rotate || uniform_scale)) {
        c->center = transform_point(u, c->center);
        if (uniform_scale)
            c->radius2 *= u->m[0][0] * u->m[0][0];
        return;
    }
    c->own_space = 1;
    transform_compose(&c->placed, u);
}

/* The component's modifiers up to its '}'. */
static void component_mods(Parser *p, SceneBlobComponent *c)
{
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            return;
        Token at = *t;
        Transform u;
        transform_identity(&u);
        if (expr_transform_item(p, t, &u)) {
            if (c->kind == BLOB_COMPONENT_SPHERE)
                sphere_component_transform(c, at.kw, &u);
            else
                transform_compose(&c->placed, &u);
            continue;
        }
        if (at.type == TK_WORD &&
            (at.kw == KW_texture || at.kw == KW_pigment || at.kw == KW_normal || at.kw == KW_finish))
            tok_unsupported_at(p, at.pos, "a texture on a blob component");
        tok_fail_expected(p, &at, "a transform, texture or '}' in a blob component");
    }
}

/* In a declaration that something unsupported already spoils (a value of
 * inside(), say), checks of the values are moot: the declaration is
 * refused for that. */
static int moot(const Parser *p) { return p->declaring && p->deferred_what; }

/* RADIUS, [strength] STRENGTH: the radius squared, as POV-Ray keeps it. */
static void radius_strength(Parser *p, SceneBlobComponent *c)
{
    double r = expr_float(p);
    c->radius2 = r * r;
    expr_comma(p);
    if (tok_is_kw(tok_peek(p), KW_strength))
        tok_next(p);
    c->strength = expr_float(p);
}

SceneObject *gram_blob(Parser *p, const Token *kw)
{
    tok_begin_block(p, "blob");
    SceneObject *o = gram_new_object(p, OBJ_BLOB, kw);
    double threshold = 1.0;
    TempVec comps;
    tok_tvec_init(&comps, sizeof(SceneBlobComponent));
    long count = 0; /* POV-Ray's count: a cylinder is a cylinder and two hemispheres */
    for (;;) {
        Token t = *tok_next(p);
        if (t.type != TK_WORD || (t.kw != KW_threshold && t.kw != KW_component && t.kw != KW_sphere &&
                                  t.kw != KW_cylinder)) {
            tok_unget(p);
            break;
        }
        if (t.kw == KW_threshold) {
            threshold = expr_float(p);
            continue;
        }
        SceneBlobComponent c = { 0 };
        transform_identity(&c.placed);
        if (t.kw == KW_component) { /* STRENGTH, RADIUS, <CENTER>: no modifiers */
            c.kind = BLOB_COMPONENT_SPHERE;
            c.strength = expr_float(p);
            expr_comma(p);
            double r = expr_float(p);
            c.radius2 = r * r;
            expr_comma(p);
            c.center = expr_vector(p);
        } else if (t.kw == KW_sphere) {
            tok_begin_block(p, "sphere");
            c.kind = BLOB_COMPONENT_SPHERE;
            c.center = expr_vector(p);
            expr_comma(p);
            radius_strength(p, &c);
            component_mods(p, &c);
        } else {
            tok_begin_block(p, "cylinder");
            c.kind = BLOB_COMPONENT_CYLINDER;
            c.base = expr_vector(p);
            expr_comma(p);
            c.apex = expr_vector(p);
            expr_comma(p);
            radius_strength(p, &c);
            if (v3_length(v3_sub(c.apex, c.base)) < BLOB_EPSILON && !moot(p))
                tok_fail(p, t.pos, "degenerate cylindrical component in blob (POV-Ray: \"Degenerate cylindrical "
                                   "component in blob.\")");
            component_mods(p, &c);
            count += 2;
        }
        if (++count >= MAX_BLOB_COMPONENTS)
            tok_fail(p, t.pos, "more than POV-Ray's maximum of %d components in a blob", MAX_BLOB_COMPONENTS);
        *(SceneBlobComponent *)tok_tvec_push(p, &comps) = c;
    }
    if (comps.n < 1 && !moot(p))
        tok_fail(p, kw->pos, "need at least one component in a blob (POV-Ray: \"Need at least one component in a "
                             "blob.\")");
    SceneBlobComponent *list = tok_scene_alloc(p, sizeof *list * (size_t)comps.n);
    for (int i = 0; i < comps.n; i++)
        list[i] = ((const SceneBlobComponent *)comps.data)[i];
    o->u.blob.threshold = threshold;
    o->u.blob.ncomponents = comps.n;
    o->u.blob.components = list;
    gram_object_mods(p, o, "blob");
    return o;
}
