/* superellipsoid { <e, n> modifiers }, as POV-Ray 3.7's
 * Parse_Superellipsoid reads it (src/geometry/superellipsoid.c). POV-Ray
 * takes any e and n and divides by them; hstrace refuses those that are
 * not positive, which make no surface, and those so small that 2/e is
 * infinite. */
#include <math.h>

#include "grammar.h"

SceneObject *gram_superellipsoid(Parser *p, const Token *kw)
{
    tok_begin_block(p, "superellipsoid");
    SceneObject *o = gram_new_object(p, OBJ_SUPERELLIPSOID, kw);
    Token at = *tok_peek(p);
    double en[2];
    gram_uv_vector(p, en);
    if (!(en[0] > 0.0 && en[1] > 0.0))
        tok_fail(p, at.pos, "superellipsoid exponents <%g, %g>: both must be positive", en[0], en[1]);
    /* a positive exponent this small (1e-308) is no mistake of sign: say
     * what is wrong with it (its powers 2/e are beyond the doubles) */
    if (!(isfinite(2.0 / en[0]) && isfinite(2.0 / en[1])))
        tok_fail(p, at.pos, "superellipsoid exponents <%g, %g>: too small (2 divided by each must be a finite number)",
                 en[0], en[1]);
    o->u.superellipsoid.e = en[0];
    o->u.superellipsoid.n = en[1];
    gram_object_mods(p, o, "superellipsoid");
    return o;
}
