/* quadric { <A,E,H>, <B,C,F>, <D,G,I>, J modifiers }, as POV-Ray 3.7's
 * Parse_Quadric reads it: the coefficients of the second-degree
 * polynomial whose negative side is the solid (src/geometry/quadric.c). */
#include "grammar.h"

SceneObject *gram_quadric(Parser *p, const Token *kw)
{
    tok_begin_block(p, "quadric");
    SceneObject *o = gram_new_object(p, OBJ_QUADRIC, kw);
    o->u.quadric.square = expr_vector(p);
    expr_comma(p);
    o->u.quadric.mixed = expr_vector(p);
    expr_comma(p);
    o->u.quadric.terms = expr_vector(p);
    expr_comma(p);
    o->u.quadric.constant = expr_float(p);
    gram_object_mods(p, o, "quadric");
    return o;
}
