/* normal { ... }: POV-Ray 3.7's Parse_Tnormal and the normal side of its
 * Parse_Pattern (parstxtr.cpp there).
 *
 * A normal starts from its identifier when one comes first, else from the
 * normal it modifies (a texture's own), else from the default texture's,
 * else from nothing: amount 0.5, accuracy 0.02. Then one pattern, the
 * amount after it, and the modifiers. The patterns made for normals
 * (bumps, dents, wrinkles, waves, ripples, quilted), bump_map, average
 * and uv_mapping are read with what they take; of the others, those
 * hstrace evaluates for pigments displace the normal by their slope (the
 * engine's src/material/normal.c), and the rest (facets, function, slope,
 * ...) are approximated: the normal is left as it is, with a note. */
#include <stdio.h>
#include <string.h>

#include "grammar.h"

/* A normal with nothing given (POV-Ray's Create_Tnormal). */
static SceneNormal fresh_normal(Parser *p)
{
    SceneNormal n;
    memset(&n, 0, sizeof n);
    n.kind = NORMAL_NONE;
    n.pattern = p->scene->default_texture.pigment;
    n.pattern.kind = PIGMENT_SOLID;
    n.pattern.nmap = 0;
    n.pattern.map = NULL;
    n.pattern.nturbulence = 0;
    n.pattern.turbulence = NULL;
    n.pattern.uv_mapping = 0;
    n.pattern.noise_generator = 0;
    n.pattern.approx = NULL;
    n.pattern.frequency = 1.0;
    n.pattern.phase = 0.0;
    n.pattern.wave = WAVE_RAMP;
    transform_identity(&n.pattern.transform);
    n.amount = 0.5;
    n.accuracy = gram_single(0.02);
    return n;
}

/* Where a normal starts: a copy of `from`, of the default texture's
 * normal, or a fresh one. */
static SceneNormal *start_normal(Parser *p, const SceneNormal *from)
{
    SceneNormal *n = tok_scene_alloc(p, sizeof *n);
    if (!from)
        from = p->scene->default_texture.normal;
    *n = from ? *from : fresh_normal(p);
    return n;
}

static void normal_items(Parser *p, SceneNormal *n, int close, const Token *kw, int need_pattern);

/* A normal read from `items` up to `close`, starting as start_normal. */
static const SceneNormal *entry_normal(Parser *p, int close, const Token *at)
{
    SceneNormal *n = start_normal(p, NULL);
    normal_items(p, n, close, at, 1);
    return n;
}

/* Whether a pattern takes a list, not a map (checker, hexagon, brick,
 * square, triangular, cubic): no slope_map or normal_map for them. */
static int list_pattern(PigmentKind k)
{
    return k == PIGMENT_CHECKER || k == PIGMENT_HEXAGON || k == PIGMENT_BRICK || k == PIGMENT_SQUARE ||
           k == PIGMENT_TRIANGULAR || k == PIGMENT_CUBIC;
}

/* After a pattern that takes a list: up to `count` `normal { }` items, commas
 * optional (Parse_Blend_List). None: the pattern's own slope. Missing
 * ones: the default texture's normal (none: the normal unchanged). */
static void parse_normal_list(Parser *p, SceneNormal *n, int count)
{
    if (!tok_is_kw(tok_peek(p), KW_normal))
        return;
    NormalMapEntry *e = tok_scene_alloc(p, sizeof *e * (size_t)count);
    int i = 0;
    while (i < count && tok_is_kw(tok_peek(p), KW_normal)) {
        Token at = *tok_next(p);
        tok_begin_block(p, "normal");
        e[i].normal = entry_normal(p, '}', &at);
        e[i].value = i;
        i++;
        expr_comma(p);
    }
    for (; i < count; i++) {
        e[i].normal = p->scene->default_texture.normal;
        e[i].value = i;
    }
    n->map = e;
    n->nmap = count;
}

/* normal_map { [value normal items] ... } and average's list, whose
 * values may be left out (1). */
void gram_normal_map(Parser *p, SceneNormal *n, int average)
{
    tok_begin_block(p, "normal_map");
    const Value *id = gram_map_identifier(p, VAL_NORMAL_MAP, "normal_map");
    if (id) {
        n->map = id->normal->map;
        n->nmap = id->normal->nmap;
        return;
    }
    TempVec entries;
    tok_tvec_init(&entries, sizeof(NormalMapEntry));
    double v;
    while (gram_blend_map_entry(p, "normal_map", &entries, average, &v)) {
        Token at = p->tok;
        NormalMapEntry *e = tok_tvec_push(p, &entries);
        e->value = v;
        e->normal = entry_normal(p, ']', &at);
    }
    if (entries.n < 1)
        tok_fail(p, p->tok.pos, "Must have at least one entry in map.");
    n->map = tok_tvec_keep(p, &entries);
    n->nmap = entries.n;
}

/* slope_map { [value, <height, slope>] ... } */
void gram_slope_map(Parser *p, SceneNormal *n)
{
    tok_begin_block(p, "slope_map");
    const Value *id = gram_map_identifier(p, VAL_SLOPE_MAP, "slope_map");
    if (id) {
        n->slope = id->normal->slope;
        n->nslope = id->normal->nslope;
        return;
    }
    TempVec entries;
    tok_tvec_init(&entries, sizeof(SlopeMapEntry));
    double v;
    while (gram_blend_map_entry(p, "slope_map", &entries, 0, &v)) {
        SlopeMapEntry *e = tok_tvec_push(p, &entries);
        e->value = v;
        Vec3 hs = expr_vector(p); /* POV-Ray's UV vector: two values */
        e->height = hs.x;
        e->slope = hs.y;
        tok_expect_punct(p, ']', "a slope_map entry");
    }
    if (entries.n < 1)
        tok_fail(p, p->tok.pos, "Must have at least one entry in map.");
    n->slope = tok_tvec_keep(p, &entries);
    n->nslope = entries.n;
}

/* bump_map { [type] "file" [gamma G] ... once interpolate map_type
 * bump_size use_color use_index } */
static void parse_bump_map(Parser *p, SceneNormal *n, const Token *at)
{
    tok_begin_block(p, "bump_map");
    gram_image_source(p, &n->pattern, at, "bump_map", 0);
    for (;;) {
        Token *o = tok_next(p);
        if (tok_is_punct(o, '}'))
            return;
        Token here = *o;
        switch (o->type == TK_WORD ? o->kw : -1) {
        case KW_once: n->pattern.image_once = 1; break;
        case KW_interpolate: n->pattern.image_interpolate = gram_image_interpolation(p, &here); break;
        case KW_map_type: n->pattern.image_map_type = gram_image_map_type(p, &here); break;
        case KW_bump_size: n->amount = gram_single(expr_float(p)); break;
        case KW_use_colour: case KW_use_color: n->pattern.image_use_index = 0; break;
        case KW_use_index: n->pattern.image_use_index = 1; break;
        default:
            if (o->type == TK_WORD && o->kw >= 0)
                tok_unsupported(p, o); /* repeat, offset, ... */
            tok_fail_expected(p, o, "once, interpolate, map_type, bump_size, use_color, use_index or '}' in 'bump_map'");
        }
    }
}

/* The pattern keyword kw (already read) of a normal. Returns 0 when kw is
 * no pattern. */
static int normal_pattern(Parser *p, SceneNormal *n, const Token *at)
{
    int kw = at->type == TK_WORD ? at->kw : -1;
    Pigment *pat = &n->pattern;
    NormalKind special = NORMAL_NONE;
    switch (kw) {
    case KW_bumps: special = NORMAL_BUMPS; break;
    case KW_dents: special = NORMAL_DENTS; break;
    case KW_wrinkles: special = NORMAL_WRINKLES; break;
    case KW_waves: special = NORMAL_WAVES; break;
    case KW_ripples: special = NORMAL_RIPPLES; break;
    case KW_quilted: special = NORMAL_QUILTED; break;
    case KW_average: special = NORMAL_AVERAGE; break;
    case KW_bump_map: special = NORMAL_BUMP_MAP; break;
    default: break;
    }
    /* A new pattern drops the map of the normal it starts from; anything
     * else (the ']' or '}' after a declared normal) keeps it: cleared for
     * every token, `normal { N }` lost N's normal_map (a wrong image) and
     * an average N was refused ("Average must have map."). */
    if (special != NORMAL_NONE || (kw >= 0 && gram_pattern_support(kw) != PAT_NONE)) {
        n->nmap = 0;
        n->map = NULL;
    }
    if (special != NORMAL_NONE) {
        n->kind = special;
        if (special == NORMAL_DENTS || special == NORMAL_WAVES || special == NORMAL_RIPPLES ||
            special == NORMAL_QUILTED || special == NORMAL_BUMPS || special == NORMAL_WRINKLES)
            gram_start_pattern(p, pat, kw); /* its value, for a normal_map, and quilted's controls */
        if (special == NORMAL_BUMP_MAP) {
            pat->frequency = 0.0;
            parse_bump_map(p, n, at);
        }
        return 1;
    }
    if (kw == KW_image_map)
        tok_fail(p, at->pos, "Keyword 'image_map' can only be used in a pigment statement.");
    switch (gram_pattern_support(kw)) {
    case PAT_EVALUATED:
        n->kind = NORMAL_PATTERN;
        gram_start_pattern(p, pat, kw); /* bumps and wrinkles are the normals' own, above */
        if (gram_pattern_list_count(kw)) {
            n->accuracy = gram_single(0.02); /* POV-Ray resets it for these */
            parse_normal_list(p, n, gram_pattern_list_count(kw));
        }
        for (const ApproxNote *a = pat->approx; a; a = a->next) { /* pigment_pattern's pigment's notes */
            ApproxNote *c = tok_scene_alloc(p, sizeof *c);
            *c = *a;
            c->next = n->approx;
            n->approx = c;
        }
        pat->approx = NULL;
        return 1;
    case PAT_APPROXIMATED: /* facets, function, slope ...: not evaluated */
        tok_approximate(p, at, APPROX_NORMAL, &n->approx);
        n->kind = NORMAL_NONE;
        gram_skip_arguments(p);
        return 1;
    case PAT_UNSUPPORTED:
        tok_unsupported(p, at);
    case PAT_NONE:
        break;
    }
    return 0;
}

/* The items of a normal up to `close` ('}' of a block, ']' of a map
 * entry); kw: where the normal was named, for its errors. */
static void normal_items(Parser *p, SceneNormal *n, int close, const Token *kw, int need_pattern)
{
    int patterned = n->kind != NORMAL_NONE || n->approx;
    Token *t = tok_next(p);
    const Value *id = gram_block_identifier(p, t, VAL_NORMAL, "normal");
    if (id) {
        *n = *id->normal;
        patterned = 1;
        t = tok_next(p);
    }
    if (tok_is_kw(t, KW_uv_mapping)) {
        /* POV-Ray: a new normal made of the rest of the block, seen at the
         * surface's (u, v, 0) */
        SceneNormal *entry = start_normal(p, NULL);
        normal_items(p, entry, close, kw, need_pattern);
        SceneNormal wrapper = fresh_normal(p);
        wrapper.kind = NORMAL_UV;
        wrapper.uv_entry = entry;
        *n = wrapper;
        return;
    }
    Token at = *t;
    if (normal_pattern(p, n, &at)) {
        patterned = 1;
    } else {
        tok_unget(p);
    }
    expr_comma(p);
    if (expr_starts_float(p, tok_peek(p)))
        n->amount = gram_single(expr_float(p));
    for (;;) {
        t = tok_next(p);
        if (tok_is_punct(t, close))
            break;
        Token here = *t;
        if (expr_transform_item(p, t, &n->pattern.transform))
            continue;
        if (gram_pattern_modifier_item(p, &n->pattern, t))
            continue;
        int k = here.type == TK_WORD ? here.kw : -1;
        switch (k) {
        case KW_bump_size: n->amount = gram_single(expr_float(p)); continue;
        case KW_accuracy: n->accuracy = gram_single(expr_float(p)); continue;
        case KW_no_bump_scale: n->no_bump_scale = 1; continue;
        case KW_slope_map:
            if (n->kind == NORMAL_AVERAGE || (n->kind == NORMAL_PATTERN && list_pattern(n->pattern.kind)) ||
                n->kind == NORMAL_BUMP_MAP)
                tok_fail(p, here.pos, "Cannot use slope_map with this normal type.");
            gram_slope_map(p, n);
            continue;
        case KW_normal_map:
            if ((n->kind == NORMAL_PATTERN && list_pattern(n->pattern.kind)) || n->kind == NORMAL_BUMP_MAP)
                tok_fail(p, here.pos, "Cannot use normal_map with this normal type.");
            gram_normal_map(p, n, n->kind == NORMAL_AVERAGE);
            continue;
        case KW_control0: case KW_control1: /* quilted's are gram_pattern_modifier_item's */
            tok_fail(p, here.pos, "Cannot use %s with this pattern.", tok_keyword_name(k));
        default:
            break;
        }
        if (k >= 0 && gram_pattern_modifier(k)) {
            gram_skip_arguments(p); /* modifiers of patterns hstrace does not evaluate */
            continue;
        }
        if (k >= 0 && n->kind == NORMAL_NONE && n->approx && gram_pattern_support(k) != PAT_NONE) {
            /* a pattern not evaluated: its arguments may name other
             * patterns (`magnet 1 mandel 50`) */
            gram_skip_arguments(p);
            continue;
        }
        if (k >= 0 && (gram_pattern_support(k) != PAT_NONE || k == KW_bumps || k == KW_bump_map))
            tok_fail(p, here.pos, "the pattern must come first in a normal (after its identifier)");
        if (k >= 0)
            tok_unsupported(p, t);
        tok_fail_expected(p, t, close == ']' ? "a normal modifier or ']' in a normal_map entry"
                                         : "a pattern, a normal modifier or '}' in 'normal'");
    }
    if (!patterned && need_pattern)
        tok_fail(p, kw->pos, "No normal type given.");
    if (n->kind == NORMAL_NONE) { /* approximated: the normal as it is */
        n->nmap = 0;
        n->nslope = 0;
    }
    if (n->kind == NORMAL_AVERAGE && n->nmap == 0)
        tok_fail(p, kw->pos, "Average must have map.");
}

const SceneNormal *gram_normal(Parser *p, const SceneNormal *from, const Token *kw, int need_pattern)
{
    tok_begin_block(p, "normal");
    SceneNormal *n = start_normal(p, from);
    normal_items(p, n, '}', kw, need_pattern);
    return n;
}

const SceneNormal *gram_normal_transformed(Parser *p, const SceneNormal *n, const Transform *tr)
{
    if (!n || n->kind == NORMAL_UV) /* uv space is the surface's own: nothing moves it */
        return n;
    SceneNormal *copy = tok_scene_alloc(p, sizeof *copy);
    *copy = *n;
    transform_compose(&copy->pattern.transform, tr);
    return copy;
}

const SceneNormal *gram_normal_uv_mapped(Parser *p, const SceneNormal *n)
{
    if (!n || n->kind == NORMAL_UV)
        return n;
    SceneNormal *wrapper = tok_scene_alloc(p, sizeof *wrapper);
    *wrapper = fresh_normal(p);
    wrapper->kind = NORMAL_UV;
    wrapper->uv_entry = n;
    return wrapper;
}
