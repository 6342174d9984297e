/* poly { ORDER, <COEFFICIENTS> modifiers }, cubic { <20 coefficients> }
 * and quartic { <35 coefficients> }, as POV-Ray 3.7's Parse_Poly and
 * Parse_Coeffs read them: (order+1)(order+2)(order+3)/6 coefficients in
 * its order of terms, the order from 2 to 35 (src/geometry/poly.c). */
#include "grammar.h"

#define POLY_MAX_ORDER 35 /* POV-Ray's MAX_ORDER */

SceneObject *gram_poly(Parser *p, const Token *kw, int order)
{
    const char *what = order == 3 ? "cubic" : order == 4 ? "quartic" : "poly";
    tok_begin_block(p, what);
    SceneObject *o = gram_new_object(p, OBJ_POLY, kw);
    if (order == 0) {
        Token at = *tok_peek(p);
        double v = expr_float(p);
        /* POV-Ray truncates the order to an int before its range check */
        if (!(v >= 2.0 && v < POLY_MAX_ORDER + 1.0))
            tok_fail(p, at.pos, "Order of poly is out of range (2 to %d, not %g).", POLY_MAX_ORDER, v);
        order = (int)v;
        expr_comma(p);
    }
    const int n = (order + 1) * (order + 2) * (order + 3) / 6;
    double *coeffs = tok_scene_alloc(p, sizeof *coeffs * (size_t)n);
    /* The messages say what is due in full (tok_expect_punct's "'<' after
     * ..." would read "expected '<' after '<' before ..."). */
    char msg[96];
    Token *t = tok_next(p);
    if (!tok_is_punct(t, '<')) {
        snprintf(msg, sizeof msg, "'<' before the %d coefficients of '%s'", n, what);
        tok_fail_expected(p, t, msg);
    }
    for (int i = 0; i < n; i++) {
        if (i > 0)
            expr_comma(p);
        coeffs[i] = expr_float(p);
    }
    t = tok_next(p);
    if (!tok_is_punct(t, '>')) {
        snprintf(msg, sizeof msg, "'>' after the %d coefficients of a %s of order %d", n, what, order);
        tok_fail_expected(p, t, msg);
    }
    o->u.poly.order = order;
    o->u.poly.coeffs = coeffs;
    gram_object_mods(p, o, what);
    return o;
}
