/* bicubic_patch { type T [flatness F] [u_steps U] [v_steps V] [accuracy A]
 * [uv_vectors <s0>,<s1>,<s2>,<s3>] 16 points modifiers }, as POV-Ray 3.7's
 * Parse_Bicubic_Patch reads it (also its old form: the numbers T [F] U V
 * without keywords). The subdivision into triangles is the engine's
 * (src/geometry/bicubic_patch.c). */
#include <math.h>

#include "grammar.h"

/* u_steps and v_steps past this are no subdivision any machine holds
 * (4^steps pieces); the world's memory budget refuses far fewer. */
#define MAX_PATCH_STEPS 1000

static int patch_int(Parser *p, const char *what)
{
    Token at = *tok_peek(p);
    return expr_checked_int(p, at.pos, expr_float(p), -MAX_PATCH_STEPS, MAX_PATCH_STEPS, what);
}

SceneObject *gram_bicubic_patch(Parser *p, const Token *kw)
{
    tok_begin_block(p, "bicubic_patch");
    SceneObject *o = gram_new_object(p, OBJ_BICUBIC_PATCH, kw);
    Token type_at = *tok_peek(p);
    int type = -1; /* POV-Ray's: none given is an error */
    double flatness = 0.0;
    int u_steps = 0, v_steps = 0;
    static const double default_st[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 2; k++)
            o->u.bicubic_patch.st[i][k] = default_st[i][k];
    for (int done = 0; !done;) {
        Token *t = tok_next(p);
        if (expr_starts_float(p, t) && t->type != TK_WORD) {
            /* the old form: type [flatness] u_steps v_steps */
            tok_unget(p);
            type_at = *tok_peek(p);
            type = patch_int(p, "bicubic_patch type");
            flatness = (type == 2 || type == 3) ? expr_float(p) : 0.1;
            u_steps = patch_int(p, "u_steps");
            v_steps = patch_int(p, "v_steps");
            break;
        }
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_type:
            type_at = *tok_peek(p);
            type = patch_int(p, "bicubic_patch type");
            break;
        case KW_flatness: flatness = expr_float(p); break;
        case KW_u_steps: u_steps = patch_int(p, "u_steps"); break;
        case KW_v_steps: v_steps = patch_int(p, "v_steps"); break;
        case KW_accuracy: (void)expr_float(p); break; /* unused by POV-Ray 3.7's patches */
        case KW_uv_vectors:
            for (int i = 0; i < 4; i++) {
                if (i)
                    expr_comma(p);
                gram_uv_vector(p, o->u.bicubic_patch.st[i]);
            }
            done = 1;
            break;
        default:
            tok_unget(p);
            done = 1;
        }
    }
    if (type > 1) /* POV-Ray: "Patch type no longer supported. Using type 1." */
        type = 1;
    if (type < 0)
        tok_fail(p, type_at.pos, "Undefined bicubic patch type (give 'type 0' or 'type 1').");
    o->u.bicubic_patch.type = type;
    o->u.bicubic_patch.flatness = flatness;
    o->u.bicubic_patch.u_steps = u_steps;
    o->u.bicubic_patch.v_steps = v_steps;
    expr_comma(p);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            if (i || j)
                expr_comma(p);
            o->u.bicubic_patch.control[i][j] = expr_vector(p);
        }
    gram_object_mods(p, o, "bicubic_patch");
    return o;
}
