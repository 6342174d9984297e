/* fog { ... }: POV-Ray 3.7's Parse_Fog. Items come in any order; a bare
 * number is the distance (POV-Ray warns that `distance` should be written);
 * transforms turn only the up vector, and a translate is ignored with a
 * warning, as in POV-Ray. */
#include <limits.h>
#include <math.h>

#include "grammar.h"

/* The turbulence settings start from POV-Ray's classic turbulence warp. */
static void begin_turbulence(SceneFog *fog)
{
    if (fog->turbulent)
        return;
    fog->turbulent = 1;
    fog->turbulence = (Vec3){ 0.0, 0.0, 0.0 };
    fog->octaves = 6;
    fog->omega = 0.5;
    fog->lambda = 2.0;
}

void gram_fog(Parser *p, const Token *kw, SceneFog *fog)
{
    tok_begin_block(p, "fog");
    fog->type = 1;
    fog->up = (Vec3){ 0.0, 1.0, 0.0 };
    fog->turb_depth = 0.5;
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            break;
        Token at = *t;
        Transform tr;
        transform_identity(&tr);
        if (tok_is_kw(t, KW_translate)) {
            (void)expr_vector(p);
            tok_warning(p, at.pos, "a fog's up vector can't be translated");
            continue;
        }
        if (expr_transform_item(p, t, &tr)) {
            fog->up = transform_direction(&tr, fog->up);
            continue;
        }
        if (expr_starts_colour(p, t)) {
            tok_unget(p);
            expr_colour(p, &fog->colour, 1);
            continue;
        }
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_distance: fog->distance = expr_float(p); continue;
        case KW_fog_type: {
            /* POV-Ray warns of a type it does not know and goes on */
            if (!int_from_double(expr_float(p), INT_MIN, INT_MAX, &fog->type))
                fog->type = 0;
            if (fog->type < 1 || fog->type > 2) {
                tok_warning(p, at.pos, "unknown fog type");
            }
            continue;
        }
        case KW_fog_alt: fog->alt = expr_float(p); continue;
        case KW_fog_offset: fog->offset = expr_float(p); continue;
        case KW_turb_depth: fog->turb_depth = (float)expr_float(p); continue;
        case KW_up: fog->up = expr_vector(p); continue;
        case KW_turbulence:
            begin_turbulence(fog);
            fog->turbulence = expr_vector(p);
            continue;
        case KW_octaves: {
            begin_turbulence(fog);
            fog->octaves = int_clamped(expr_float(p), 1, 10); /* POV-Ray's limits */
            continue;
        }
        case KW_omega: begin_turbulence(fog); fog->omega = (float)expr_float(p); continue;
        case KW_lambda: begin_turbulence(fog); fog->lambda = (float)expr_float(p); continue;
        default: break;
        }
        if (expr_starts_float(p, t)) {
            tok_unget(p);
            fog->distance = expr_float(p);
            tok_warning(p, at.pos, "should use distance keyword");
            continue;
        }
        if (t->type == TK_WORD && t->kw >= 0)
            tok_unsupported(p, t);
        tok_fail_expected(p, t, "a fog item or '}' in 'fog'");
    }
    double len = sqrt(fog->up.x * fog->up.x + fog->up.y * fog->up.y + fog->up.z * fog->up.z);
    if (len > 0.0)
        fog->up = (Vec3){ fog->up.x / len, fog->up.y / len, fog->up.z / len };
    if (p->gram->media_attenuation_seen)
        tok_approximate(p, kw, APPROX_FOG, &p->gram->global_approx);
}
