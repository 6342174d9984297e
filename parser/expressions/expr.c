/* Numeric, string and colour expressions, and transforms.
 *
 * The numeric grammar follows POV-Ray's express.cpp: every level works on up
 * to five components plus a component count `terms`. The count passed in is
 * the context (a float parsed where a vector is wanted fills every component);
 * binary operators promote the shorter side (a float is repeated, a shorter
 * vector padded with zeros). Precedence, loosest first:
 *   ?:   & |   < <= = != >= >   + -   * /   unary - + !   factors
 * A plain float or vector (expr_float, expr_vector) stops at + - as POV-Ray
 * does; comparisons need parentheses there. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expressions.h"

/* clock and its kin for the frame being rendered (parser.h), or a still's:
 * POV-Ray 3.7 renders a still with every one of them 0 and clock_on false
 * (checked with 3.7.0.10). */
static double animation_value(const ParseAnimation *a, int kw)
{
    static const ParseAnimation still = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0 };
    if (!a)
        a = &still;
    switch (kw) {
    case KW_clock: return a->clock;
    case KW_clock_on: return a->clock_on;
    case KW_clock_delta: return a->clock_delta;
    case KW_initial_clock: return a->initial_clock;
    case KW_final_clock: return a->final_clock;
    case KW_frame_number: return a->frame_number;
    case KW_initial_frame: return a->initial_frame;
    default: return a->final_frame;
    }
}

static void parse_num_factor(Parser *p, double e[5], int *terms);

static void fill(double e[5], int terms, double v)
{
    for (int i = 0; i < 5; i++)
        e[i] = i < terms ? v : 0.0;
}

/* A shorter operand grows to `to` components: a float repeats, a vector pads. */
static void promote(double e[5], int *terms, int to)
{
    if (*terms >= to)
        return;
    for (int i = *terms; i < to; i++)
        e[i] = *terms == 1 ? e[0] : 0.0;
    *terms = to;
}

static void balance(double a[5], int *ta, double b[5], int *tb)
{
    if (*tb > *ta)
        promote(a, ta, *tb);
    else
        promote(b, tb, *ta);
}

/* POV-Ray 3.7's ftrue(): "not zero" beyond its EPSILON, 1e-10 (checked with
 * povray: #if (1e-7) is true, #if (1e-11) false, 1 = 1 + 1e-9 is false). */
static int ftrue(double v) { return fabs(v) > 1e-10; }

/* POV-Ray's binary operators by priority, all left-associative: logical
 * & and | below the relations, below + and -, below * and /. One
 * precedence-climbing loop (as Lua's subexpr) reads them all. */
enum { PRIO_NONE, PRIO_LOGICAL, PRIO_RELATION, PRIO_SUM, PRIO_PRODUCT };

static int operator_priority(int punct)
{
    switch (punct) {
    case '&': case '|': return PRIO_LOGICAL;
    case '<': case '>': case '=': case P_LE: case P_GE: case P_NE: return PRIO_RELATION;
    case '+': case '-': return PRIO_SUM;
    case '*': case '/': return PRIO_PRODUCT;
    default: return PRIO_NONE;
    }
}

static int binary_priority(const Token *t)
{
    return t->type == TK_PUNCT ? operator_priority(t->punct) : PRIO_NONE;
}

/* e = e op r. Arithmetic makes the shorter operand as long as the other;
 * relations and logic compare component by component on the left
 * operand's components, grown to the right's (as POV-Ray's Parse_Rel_Term
 * and Parse_Logical). */
static void apply_binary(int op, double e[5], int *terms, double r[5], int *rt)
{
    switch (operator_priority(op)) {
    case PRIO_PRODUCT:
    case PRIO_SUM:
        balance(e, terms, r, rt);
        for (int i = 0; i < *terms; i++) {
            switch (op) {
            case '*': e[i] *= r[i]; break;
            case '/': e[i] = r[i] == 0.0 ? HUGE_VAL : e[i] / r[i]; break; /* POV-Ray warns and goes on */
            case '+': e[i] += r[i]; break;
            default: e[i] -= r[i]; break;
            }
        }
        return;
    case PRIO_RELATION:
        promote(e, terms, *rt);
        for (int i = 0; i < *terms; i++) {
            double a = e[i], b = r[i];
            int eq = !ftrue(a - b);
            switch (op) {
            case '<': e[i] = a < b; break;
            case '>': e[i] = a > b; break;
            case '=': e[i] = eq; break;
            case P_NE: e[i] = !eq; break;
            case P_LE: e[i] = a <= b || eq; break;
            default: e[i] = a >= b || eq; break;
            }
        }
        return;
    default:
        promote(e, terms, *rt);
        for (int i = 0; i < *terms; i++)
            e[i] = op == '&' ? (ftrue(e[i]) && ftrue(r[i])) : (ftrue(e[i]) || ftrue(r[i]));
        return;
    }
}

/* Reads a factor and every binary operator of at least min_priority after
 * it; an operator's right operand takes only operators that bind tighter. */
static void parse_binary(Parser *p, double e[5], int *terms, int min_priority)
{
    parse_num_factor(p, e, terms);
    for (;;) {
        Token *t = tok_next(p);
        int priority = binary_priority(t);
        if (priority == PRIO_NONE || priority < min_priority) {
            tok_unget(p);
            return;
        }
        int op = t->punct;
        double r[5] = { 0 };
        int rt = *terms;
        parse_binary(p, r, &rt, priority + 1);
        apply_binary(op, e, terms, r, &rt);
    }
}

void expr_rel_factor(Parser *p, double e[5], int *terms)
{
    parse_binary(p, e, terms, PRIO_SUM);
}

void expr_numeric(Parser *p, double e[5], int *terms)
{
    Token first = *tok_peek(p);
    tok_nesting_enter(p, &first);
    int want = *terms, got = 1;
    parse_binary(p, e, &got, PRIO_LOGICAL);
    Token *t = tok_next(p);
    if (tok_is_punct(t, '?')) {
        if (got != 1)
            tok_fail(p, t->pos, "the condition before '?' must be a float");
        int cond = ftrue(e[0]);
        double a[5] = { 0 }, b[5] = { 0 };
        int ta = want, tb = want;
        expr_numeric(p, a, &ta);
        tok_expect_punct(p, ':', "the first choice of '?'");
        expr_numeric(p, b, &tb);
        memcpy(e, cond ? a : b, sizeof a);
        *terms = cond ? ta : tb;
    } else {
        tok_unget(p);
        promote(e, &got, want);
        *terms = got;
    }
    tok_nesting_leave(p);
}

/* A float where an expression's part is wanted (a vector's component):
 * any value, infinities and NaN included, as inside any expression. */
static double float_term(Parser *p, Token *first)
{
    *first = *tok_peek(p);
    double e[5] = { 0 };
    int terms = 1;
    expr_rel_factor(p, e, &terms);
    if (terms > 1)
        tok_fail(p, first->pos, "float expected but vector or colour expression found");
    return e[0];
}

/* What a scene item is given (a coordinate, a size, a colour, a count)
 * must be a number: POV-Ray takes 1/0 (with a warning) and 1e309 as
 * infinities and goes on with them, but geometry, cameras and colours made
 * of them would render garbage, so hstrace stops at the value. Expressions
 * inside (and #declare) stay free to hold any value. */
static void finite_or_fail(Parser *p, SourcePos at, const double *v, int n, const char *what)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) {
            char shown[200];
            int used = 0;
            for (int k = 0; k < n && used < (int)sizeof shown - 40; k++)
                used += snprintf(shown + used, sizeof shown - (size_t)used, "%s%g", k ? ", " : "", v[k]);
            tok_fail(p, at, "expected a finite %s, found %s%s%s", what, n == 1 ? "" : "<", shown, n == 1 ? "" : ">");
        }
}

double expr_float(Parser *p)
{
    Token first;
    double v = float_term(p, &first);
    finite_or_fail(p, first.pos, &v, 1, "number");
    return v;
}

int expr_checked_int(Parser *p, SourcePos at, double v, int lo, int hi, const char *what)
{
    int n;
    if (!int_from_double(v, lo, hi, &n))
        tok_fail(p, at, "%s must be an integer from %d to %d, not %g", what, lo, hi, v);
    return n;
}

/* The common case of big scenes (mesh2 lists): a vector written as three
 * plain numbers, `<1, -2.5, 3e2>`, not followed by an operator. Read from the
 * raw text it skips the expression machinery; anything else (identifiers,
 * operators, directives, two or four components) is left to the general
 * path, as if nothing had been read. */
static int plain_vector(Parser *p, Vec3 *out)
{
    int had_angle = p->ungot && tok_is_punct(&p->tok, '<');
    if (p->ungot && !had_angle)
        return 0;
    LexMark m = tok_mark(p);
    double c[3];
    if (!tok_plain_vector(p, had_angle, c))
        return 0;
    int after = tok_peek_char(p);
    if (after == '+' || after == '-' || after == '*' || after == '/' || after == '.' || after == '#') {
        tok_seek(p, m); /* an operator, or a directive (a macro's #end) that may lead to one */
        return 0;
    }
    p->ungot = 0;
    *out = v3(c[0], c[1], c[2]);
    return 1;
}

Vec3 expr_vector(Parser *p)
{
    Vec3 fast;
    if (plain_vector(p, &fast))
        return fast;
    Token first = *tok_peek(p);
    double e[5] = { 0 };
    int terms = 3;
    expr_rel_factor(p, e, &terms);
    if (terms > 3)
        tok_fail(p, first.pos, "vector expected but colour expression found");
    finite_or_fail(p, first.pos, e, 3, "vector");
    return v3(e[0], e[1], e[2]);
}

Vec3 expr_scale_vector(Parser *p)
{
    Vec3 v = expr_vector(p);
    /* POV-Ray turns a zero scale into 1 (with a warning) */
    if (v.x == 0.0) v.x = 1.0;
    if (v.y == 0.0) v.y = 1.0;
    if (v.z == 0.0) v.z = 1.0;
    return v;
}

void expr_comma(Parser *p)
{
    if (!tok_is_punct(tok_next(p), ','))
        tok_unget(p);
}

/* A float in parentheses: sin(x). */
static double float_param(Parser *p)
{
    tok_expect_punct(p, '(', "the function name");
    double v = expr_float_full(p);
    tok_expect_punct(p, ')', "the argument");
    return v;
}

/* Function arguments are full expressions (comparisons allowed). */
double expr_float_full(Parser *p)
{
    Token first = *tok_peek(p);
    double e[5] = { 0 };
    int terms = 1;
    expr_numeric(p, e, &terms);
    if (terms > 1)
        tok_fail(p, first.pos, "float expected but vector or colour expression found");
    return e[0];
}

static Vec3 vector_full(Parser *p)
{
    double e[5] = { 0 };
    int terms = 3;
    expr_numeric(p, e, &terms);
    return v3(e[0], e[1], e[2]);
}

static void float_params2(Parser *p, double *a, double *b)
{
    tok_expect_punct(p, '(', "the function name");
    *a = expr_float_full(p);
    tok_expect_punct(p, ',', "the first argument");
    *b = expr_float_full(p);
    tok_expect_punct(p, ')', "the second argument");
}

static int is_colour_keyword(int kw)
{
    switch (kw) {
    case KW_color: case KW_colour: case KW_rgb: case KW_rgbf: case KW_rgbt: case KW_rgbft:
    case KW_srgb: case KW_srgbf: case KW_srgbt: case KW_srgbft:
    case KW_red: case KW_green: case KW_blue: case KW_filter: case KW_transmit: case KW_alpha:
        return 1;
    default:
        return 0;
    }
}

static int is_float_keyword(int kw)
{
    switch (kw) {
    case KW_abs: case KW_acos: case KW_acosh: case KW_asin: case KW_asinh: case KW_atan: case KW_atan2:
    case KW_atanh: case KW_ceil: case KW_clock: case KW_clock_on: case KW_clock_delta: case KW_cos:
    case KW_cosh: case KW_defined: case KW_degrees: case KW_div: case KW_exp: case KW_floor: case KW_int:
    case KW_ln: case KW_log: case KW_max: case KW_min: case KW_mod: case KW_pi: case KW_pow:
    case KW_radians: case KW_select: case KW_sin: case KW_sinh: case KW_sqrt: case KW_tan:
    case KW_tanh: case KW_true: case KW_false: case KW_yes: case KW_no: case KW_on: case KW_off:
    case KW_version: case KW_image_width: case KW_image_height: case KW_vdot: case KW_vlength:
    case KW_strlen: case KW_strcmp: case KW_val: case KW_asc: case KW_initial_frame: case KW_final_frame:
    case KW_frame_number: case KW_initial_clock: case KW_final_clock: case KW_bitwise_and:
    case KW_bitwise_or: case KW_bitwise_xor: case KW_seed: case KW_rand: case KW_dimensions:
    case KW_dimension_size:
        return 1;
    default:
        return 0;
    }
}

static int is_vector_keyword(int kw)
{
    switch (kw) {
    case KW_x: case KW_y: case KW_z: case KW_t: case KW_u: case KW_v:
    case KW_vcross: case KW_vnormalize: case KW_vrotate: case KW_vaxis_rotate: case KW_min_extent: case KW_max_extent:
        return 1;
    default:
        return 0;
    }
}

static Symbol *numeric_symbol(Parser *p, const Token *t)
{
    if (t->type != TK_WORD || t->kw >= 0)
        return NULL;
    Symbol *s = tok_symbol_of(p, t);
    return s && s->value.kind == VAL_NUMERIC ? s : NULL;
}

int expr_starts_float(Parser *p, const Token *t)
{
    if (t->type == TK_NUMBER)
        return 1;
    if (t->type == TK_PUNCT)
        return t->punct == '(' || t->punct == '-' || t->punct == '+' || t->punct == '!';
    if (t->type != TK_WORD)
        return 0;
    if (t->kw >= 0)
        return is_float_keyword(t->kw);
    Symbol *s = numeric_symbol(p, t);
    return s && s->value.terms == 1;
}

int expr_starts_colour(Parser *p, const Token *t)
{
    if (t->type != TK_WORD)
        return 0;
    if (t->kw >= 0)
        return is_colour_keyword(t->kw);
    Symbol *s = numeric_symbol(p, t);
    return s && s->value.terms == 5;
}

int expr_starts_expression(Parser *p, const Token *t)
{
    if (expr_starts_float(p, t) || expr_starts_colour(p, t) || tok_is_punct(t, '<'))
        return 1;
    if (t->type != TK_WORD)
        return 0;
    if (t->kw >= 0)
        return is_vector_keyword(t->kw);
    return numeric_symbol(p, t) != NULL;
}

int expr_starts_string(Parser *p, const Token *t)
{
    if (t->type == TK_STRING)
        return 1;
    if (t->type != TK_WORD)
        return 0;
    switch (t->kw) {
    case KW_concat: case KW_str: case KW_chr: case KW_substr: case KW_strupr: case KW_strlwr: case KW_vstr:
        return 1;
    case -1: {
        Symbol *s = tok_symbol_of(p, t);
        return s && s->value.kind == VAL_STRING;
    }
    default:
        return 0;
    }
}

/* An identifier in a numeric expression. */
static void identifier_factor(Parser *p, const Token *t, double e[5], int *terms)
{
    Symbol *s = tok_symbol_of(p, t);
    if (!s)
        tok_fail(p, t->pos, "undeclared identifier '%.*s'", t->len, t->text);
    const Value *v = &s->value;
    if (v->kind == VAL_UNSUPPORTED) {
        if (tok_defer_unsupported(p, v->what, v->declared_at)) {
            fill(e, *terms, 0.0);
            return;
        }
        tok_use_unsupported(p, t, v);
    }
    if (v->kind != VAL_NUMERIC)
        tok_fail(p, t->pos, "numeric expression expected but '%.*s' is %s", t->len, t->text, tok_value_kind_name(v->kind));
    if (v->terms == 1) {
        fill(e, *terms, v->v[0]);
    } else {
        memcpy(e, v->v, sizeof v->v);
        *terms = v->terms;
    }
}

static void vector_literal(Parser *p, double e[5], int *terms)
{
    int n = 0;
    fill(e, 5, 0.0);
    for (;;) {
        Token first;
        e[n++] = float_term(p, &first);
        expr_comma(p);
        Token *t = tok_next(p);
        if (tok_is_punct(t, '>')) {
            if (n < 2)
                tok_fail_expected(p, t, "a second vector component");
            break;
        }
        if (n == 5)
            tok_fail_expected(p, t, "'>' after five vector components");
        tok_unget(p);
    }
    *terms = n;
}

static Vec3 rotate_about_axis(Vec3 v, Vec3 axis, double degrees)
{
    Vec3 a = v3_normalize(axis);
    double th = degrees * M_PI / 180.0, c = cos(th), s = sin(th);
    /* Rodrigues' formula; checked against POV-Ray's vaxis_rotate */
    Vec3 cross = v3_cross(a, v);
    return v3_add(v3_add(v3_scale(v, c), v3_scale(cross, s)), v3_scale(a, v3_dot(a, v) * (1.0 - c)));
}

static double variadic_minmax(Parser *p, int is_max)
{
    tok_expect_punct(p, '(', is_max ? "'max'" : "'min'");
    double v = expr_float_full(p);
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, ')'))
            return v;
        if (!tok_is_punct(t, ','))
            tok_fail_expected(p, t, "',' or ')' in the argument list");
        double w = expr_float_full(p);
        v = is_max ? fmax(v, w) : fmin(v, w);
    }
}

/* A keyword in a numeric expression; returns 0 when it is none of ours. */
static int keyword_factor(Parser *p, const Token *t, double e[5], int *terms)
{
    double a, b, val;
    Vec3 va, vb;
    switch (t->kw) {
    case KW_x: va = v3(1, 0, 0); goto vector;
    case KW_y: va = v3(0, 1, 0); goto vector;
    case KW_z: va = v3(0, 0, 1); goto vector;
    case KW_t:
        fill(e, 5, 0.0);
        e[3] = 1.0;
        *terms = 4;
        return 1;
    case KW_u:
    case KW_v:
        fill(e, 5, 0.0);
        e[t->kw == KW_u ? 0 : 1] = 1.0;
        *terms = 2;
        return 1;
    case KW_vcross:
        tok_expect_punct(p, '(', "'vcross'");
        va = vector_full(p);
        tok_expect_punct(p, ',', "the first vector");
        vb = vector_full(p);
        tok_expect_punct(p, ')', "the second vector");
        va = v3_cross(va, vb);
        goto vector;
    case KW_vnormalize:
        tok_expect_punct(p, '(', "'vnormalize'");
        va = vector_full(p);
        tok_expect_punct(p, ')', "the vector");
        if (v3_length(va) == 0.0)
            tok_fail(p, t->pos, "cannot normalise a zero-length vector");
        va = v3_normalize(va);
        goto vector;
    case KW_vrotate: {
        tok_expect_punct(p, '(', "'vrotate'");
        va = vector_full(p);
        tok_expect_punct(p, ',', "the vector");
        vb = vector_full(p);
        tok_expect_punct(p, ')', "the angles");
        Transform tr;
        transform_identity(&tr);
        transform_rotate(&tr, vb);
        va = transform_direction(&tr, va);
        goto vector;
    }
    case KW_vaxis_rotate: {
        tok_expect_punct(p, '(', "'vaxis_rotate'");
        va = vector_full(p);
        tok_expect_punct(p, ',', "the vector");
        vb = vector_full(p);
        tok_expect_punct(p, ',', "the axis");
        a = expr_float_full(p);
        tok_expect_punct(p, ')', "the angle");
        va = rotate_about_axis(va, vb, a);
        goto vector;
    }
    case KW_vdot:
        tok_expect_punct(p, '(', "'vdot'");
        va = vector_full(p);
        tok_expect_punct(p, ',', "the first vector");
        vb = vector_full(p);
        tok_expect_punct(p, ')', "the second vector");
        val = v3_dot(va, vb);
        break;
    case KW_vlength:
        tok_expect_punct(p, '(', "'vlength'");
        va = vector_full(p);
        tok_expect_punct(p, ')', "the vector");
        val = v3_length(va);
        break;
    case KW_abs: val = fabs(float_param(p)); break;
    case KW_acos: val = acos(fmax(-1.0, fmin(1.0, float_param(p)))); break;
    case KW_asin: val = asin(fmax(-1.0, fmin(1.0, float_param(p)))); break;
    case KW_atan: val = atan(float_param(p)); break;
    case KW_acosh: val = acosh(float_param(p)); break;
    case KW_asinh: val = asinh(float_param(p)); break;
    case KW_atanh: val = atanh(float_param(p)); break;
    case KW_cosh: val = cosh(float_param(p)); break;
    case KW_sinh: val = sinh(float_param(p)); break;
    case KW_tanh: val = tanh(float_param(p)); break;
    case KW_atan2:
        float_params2(p, &a, &b);
        val = (a == 0.0 && b == 0.0) ? 0.0 : atan2(a, b);
        break;
    case KW_ceil: val = ceil(float_param(p)); break;
    case KW_floor: val = floor(float_param(p)); break;
    case KW_cos: val = cos(float_param(p)); break;
    case KW_sin: val = sin(float_param(p)); break;
    case KW_tan: val = tan(float_param(p)); break;
    case KW_degrees: val = float_param(p) * 180.0 / M_PI; break;
    case KW_radians: val = float_param(p) * M_PI / 180.0; break;
    case KW_exp: val = exp(float_param(p)); break;
    case KW_int: {
        double f = float_param(p);
        int i;
        val = int_from_double(f, INT_MIN, INT_MAX, &i) ? (double)i : trunc(f);
        break;
    }
    /* POV-Ray refuses these outside their domain (its words); with a
     * placeholder for a deferred unsupported value, the answer is moot. */
    case KW_ln:
    case KW_log:
    case KW_sqrt: {
        a = float_param(p);
        int moot = p->declaring && p->deferred_what;
        if (t->kw == KW_sqrt ? a < 0.0 : a <= 0.0) {
            if (!moot)
                tok_fail(p, t->pos, "%s of negative number %f", tok_keyword_name(t->kw), a);
            val = NAN;
        } else {
            val = t->kw == KW_ln ? log(a) : t->kw == KW_log ? log10(a) : sqrt(a);
        }
        break;
    }
    case KW_pow: float_params2(p, &a, &b); val = pow(a, b); break;
    case KW_mod: float_params2(p, &a, &b); val = b == 0.0 ? HUGE_VAL : fmod(a, b); break;
    case KW_div: float_params2(p, &a, &b); val = b == 0.0 ? HUGE_VAL : trunc(a / b); break;
    case KW_bitwise_and:
    case KW_bitwise_or:
    case KW_bitwise_xor: {
        float_params2(p, &a, &b);
        long ia = int_clamped(a, -2000000000, 2000000000), ib = int_clamped(b, -2000000000, 2000000000);
        val = (double)(t->kw == KW_bitwise_and ? (ia & ib) : t->kw == KW_bitwise_or ? (ia | ib) : (ia ^ ib));
        break;
    }
    case KW_max:
    case KW_min: val = variadic_minmax(p, t->kw == KW_max); break;
    case KW_select: {
        tok_expect_punct(p, '(', "'select'");
        double c = expr_float_full(p), r[3];
        int n = 0;
        for (;;) {
            Token *s = tok_next(p);
            if (tok_is_punct(s, ')') && n >= 2)
                break;
            if (!tok_is_punct(s, ',') || n == 3)
                tok_fail_expected(p, s, n >= 2 ? "')' after the choices of 'select'" : "',' in 'select'");
            r[n++] = expr_float_full(p);
        }
        val = n == 2 ? (c < 0 ? r[0] : r[1]) : (c < 0 ? r[0] : c == 0 ? r[1] : r[2]);
        break;
    }
    case KW_defined: {
        tok_expect_punct(p, '(', "'defined'");
        Token *id = tok_next_name(p);
        if (id->type != TK_WORD)
            tok_fail_expected(p, id, "an identifier in 'defined'");
        val = id->elem ? id->elem->value.kind != VAL_NONE : id->kw < 0 && tok_symbol_find(p, id->text, id->len) != NULL;
        tok_expect_punct(p, ')', "the identifier");
        break;
    }
    case KW_strlen: {
        tok_expect_punct(p, '(', "'strlen'");
        val = (double)strlen(expr_string(p));
        tok_expect_punct(p, ')', "the string");
        break;
    }
    case KW_strcmp: {
        tok_expect_punct(p, '(', "'strcmp'");
        char *s1 = expr_string(p);
        tok_expect_punct(p, ',', "the first string");
        char *s2 = expr_string(p);
        tok_expect_punct(p, ')', "the second string");
        int c = strcmp(s1, s2);
        val = c < 0 ? -1 : c > 0;
        break;
    }
    case KW_val: {
        tok_expect_punct(p, '(', "'val'");
        val = strtod(expr_string(p), NULL);
        tok_expect_punct(p, ')', "the string");
        break;
    }
    case KW_asc: {
        tok_expect_punct(p, '(', "'asc'");
        val = (unsigned char)expr_string(p)[0];
        tok_expect_punct(p, ')', "the string");
        break;
    }
    case KW_seed: {
        /* A new random stream, as POV-Ray's: seed() answers its number. */
        double v = float_param(p);
        if (p->rand_streams.n >= 1000000)
            tok_fail(p, t->pos, "more than a million random streams (seed)");
        *(unsigned *)tok_tvec_push(p, &p->rand_streams) = (unsigned)int_clamped(v, INT_MIN, INT_MAX);
        val = p->rand_streams.n - 1;
        break;
    }
    case KW_rand: {
        tok_expect_punct(p, '(', "'rand'");
        Token at = *tok_peek(p);
        double v = expr_float_full(p);
        tok_expect_punct(p, ')', "the stream");
        int stream;
        if (!(v >= 0.0) || !int_from_double(v, 0, p->rand_streams.n - 1, &stream))
            tok_fail(p, at.pos, "rand needs a stream made by seed(), not %g", v);
        /* POV-Ray's POV_rand(): a 32-bit linear congruential generator,
         * so that scenes draw the same numbers as in POV-Ray. */
        unsigned *state = (unsigned *)p->rand_streams.data + stream;
        *state = *state * 1812433253u + 12345u;
        val = (double)*state / 4294967295.0;
        break;
    }
    case KW_dimensions:
    case KW_dimension_size:
        val = tok_array_function(p, t);
        break;
    case KW_pi: val = M_PI; break;
    case KW_true: case KW_yes: case KW_on: val = 1.0; break;
    case KW_false: case KW_no: case KW_off: val = 0.0; break;
    case KW_clock: case KW_clock_on: case KW_initial_clock: case KW_frame_number: case KW_initial_frame:
    case KW_final_frame: case KW_final_clock: case KW_clock_delta:
        val = animation_value(p->opts->animation, t->kw);
        break;
    case KW_version: val = p->version; break;
    case KW_image_width: val = p->opts->image_width; break;
    case KW_image_height: val = p->opts->image_height; break;
    default:
        return 0;
    }
    fill(e, *terms, val);
    return 1;
vector:
    if (*terms < 3)
        *terms = 3;
    fill(e, 5, 0.0);
    e[0] = va.x;
    e[1] = va.y;
    e[2] = va.z;
    return 1;
}

/* Functions of POV-Ray's expressions that need what hstrace does not model
 * (object geometry, patterns, noise). */
static int is_unsupported_function(int kw)
{
    switch (kw) {
    case KW_trace: case KW_inside: case KW_vturbulence:
    case KW_function:
        return 1;
    default:
        return 0;
    }
}

/* min_extent(OBJECT) and max_extent(OBJECT) (after the keyword at t):
 * the corners of POV-Ray's bounding box of a declared object where hstrace
 * keeps it as POV-Ray does (SceneObject.has_extent), the far one
 * summed in single precision as POV-Ray sums it; of any other object, not
 * supported (deferred in a declaration, as the other functions). */
static void extent_factor(Parser *p, const Token *t, double e[5], int *terms)
{
    Token open = *tok_next(p);
    if (!tok_is_punct(&open, '('))
        tok_fail_expected(p, &open, "'(' after the function's name");
    Token id = *tok_next(p);
    Symbol *s = id.type == TK_WORD && id.kw < 0 ? tok_symbol_of(p, &id) : NULL;
    const SceneObject *o = s && s->value.kind == VAL_OBJECT ? s->value.object : NULL;
    if (!o || !o->has_extent) {
        tok_unget(p);
        tok_skip_balanced_group(p, &open);
        char what[80];
        snprintf(what, sizeof what, "'%s' of this kind of object", tok_keyword_name(t->kw));
        const char *kept = tok_temp_strndup(p, what, strlen(what));
        if (!tok_defer_unsupported(p, kept, t->pos))
            tok_unsupported_at(p, t->pos, kept);
        fill(e, *terms, 0.0);
        return;
    }
    tok_expect_punct(p, ')', "the object");
    fill(e, 5, 0.0);
    for (int i = 0; i < 3; i++)
        e[i] = t->kw == KW_min_extent ? (double)o->extent_lower[i]
                                      : (double)(float)(o->extent_lower[i] + o->extent_lengths[i]);
    if (*terms < 3)
        *terms = 3;
}

static void parse_num_factor(Parser *p, double e[5], int *terms)
{
    Token t = *tok_next(p);
    tok_nesting_enter(p, &t);
    if (t.type == TK_NUMBER) {
        fill(e, *terms, t.number);
    } else if (tok_is_punct(&t, '(')) {
        expr_numeric(p, e, terms);
        tok_expect_punct(p, ')', "the expression in parentheses");
    } else if (tok_is_punct(&t, '<')) {
        vector_literal(p, e, terms);
    } else if (tok_is_punct(&t, '-') || tok_is_punct(&t, '+') || tok_is_punct(&t, '!')) {
        parse_num_factor(p, e, terms);
        for (int i = 0; i < *terms; i++) {
            if (t.punct == '-')
                e[i] = -e[i];
            else if (t.punct == '!')
                e[i] = ftrue(e[i]) ? 0.0 : 1.0;
        }
    } else if (t.type == TK_WORD && t.kw < 0) {
        identifier_factor(p, &t, e, terms);
    } else if (t.type == TK_WORD && is_colour_keyword(t.kw)) {
        tok_unget(p);
        Colour c;
        expr_colour(p, &c, 1);
        e[0] = c.r; e[1] = c.g; e[2] = c.b; e[3] = c.filter; e[4] = c.transmit;
        *terms = 5;
    } else if (t.type == TK_WORD && (t.kw == KW_min_extent || t.kw == KW_max_extent)) {
        extent_factor(p, &t, e, terms);
    } else if (t.type == TK_WORD && is_unsupported_function(t.kw)) {
        char what[64];
        snprintf(what, sizeof what, "'%s'", tok_keyword_name(t.kw));
        if (!tok_defer_unsupported(p, tok_temp_strndup(p, what, strlen(what)), t.pos))
            tok_unsupported(p, &t);
        fill(e, *terms, 0.0);
    } else if (t.type != TK_WORD || !keyword_factor(p, &t, e, terms)) {
        tok_fail_expected(p, &t, "a numeric expression");
    }
    tok_nesting_leave(p);

    /* v.x, c.red and friends */
    if (!tok_is_punct(tok_next(p), '.')) {
        tok_unget(p);
        return;
    }
    Token *c = tok_next(p);
    int i = -1;
    switch (c->type == TK_WORD ? c->kw : -2) {
    case KW_x: case KW_u: case KW_red: i = 0; break;
    case KW_y: case KW_v: case KW_green: i = 1; break;
    case KW_z: case KW_blue: i = 2; break;
    case KW_t: case KW_filter: i = 3; break;
    case KW_transmit: i = 4; break;
    case KW_gray: {
        double g = e[0] * 0.297 + e[1] * 0.589 + e[2] * 0.114;
        fill(e, 5, g);
        *terms = 1;
        return;
    }
    default:
        tok_fail_expected(p, c, "x, y, z, t, u, v or a colour component after '.'");
    }
    /* In a declaration already known to be unsupported (deferred), the
     * placeholder 0 stands for a value of unknown shape: any component of
     * it is fine, and the declaration's use reports the real reason. */
    if (i >= *terms && !(p->declaring && p->deferred_what))
        tok_fail(p, c->pos, "'.%s' asks for a component the expression does not have", tok_keyword_name(c->kw));
    double v = e[i];
    fill(e, 5, v);
    *terms = 1;
}

/* ---- colours ----------------------------------------------------------- */

static double srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

/* srgb values become working-gamma values: decoded to linear light, then
 * encoded with assumed_gamma (identity for the usual assumed_gamma 1). */
static double decode_srgb(Parser *p, double c)
{
    if (p->assumed_gamma == 0.0)
        return c; /* assumed_gamma srgb: nothing to convert */
    double lin = srgb_to_linear(c);
    return p->assumed_gamma == 1.0 ? lin : pow(lin, 1.0 / p->assumed_gamma);
}

/* POV-Ray's Parse_Colour: an optional color/colour, then rgb-family keywords
 * (only first), an identifier or expression (only first), and component
 * keywords (red 0.5 filter 0.3) in any number. */
void expr_colour(Parser *p, Colour *out, int expect_ft)
{
    double c[5] = { 0 };
    int started = 0;
    Token *t = tok_next(p);
    SourcePos start = t->pos;
    if (!tok_is_kw(t, KW_color) && !tok_is_kw(t, KW_colour))
        tok_unget(p);
    for (;;) {
        t = tok_next(p);
        Token at = *t;
        if (t->type == TK_WORD && is_colour_keyword(t->kw) && t->kw != KW_color && t->kw != KW_colour) {
            int kw = t->kw, terms = 0, is_srgb = 0;
            switch (kw) {
            case KW_red: c[0] = expr_float(p); break;
            case KW_green: c[1] = expr_float(p); break;
            case KW_blue: c[2] = expr_float(p); break;
            case KW_alpha:
            case KW_filter: c[3] = expr_float(p); break;
            case KW_transmit: c[4] = expr_float(p); break;
            case KW_srgb: is_srgb = 1; terms = 3; break;
            case KW_srgbf: is_srgb = 1; terms = 4; break;
            case KW_srgbt: is_srgb = 1; terms = 4; break;
            case KW_srgbft: is_srgb = 1; terms = 5; break;
            case KW_rgb: terms = 3; break;
            case KW_rgbf: case KW_rgbt: terms = 4; break;
            default: terms = 5; break; /* rgbft */
            }
            if (terms) {
                if (started) {
                    tok_unget(p);
                    break;
                }
                if (is_srgb && !p->gamma_set)
                    tok_fail(p, at.pos, "cannot parse sRGB colours before assumed_gamma has been set");
                double e[5] = { 0 };
                int n = terms;
                expr_numeric(p, e, &n);
                for (int i = 0; i < n && i < 5; i++)
                    c[i] = e[i];
                if (kw == KW_rgbt || kw == KW_srgbt) {
                    c[4] = c[3];
                    c[3] = 0.0;
                }
                if (is_srgb)
                    for (int i = 0; i < 3; i++)
                        c[i] = decode_srgb(p, c[i]);
            }
            started = 1;
            continue;
        }
        if (!started && (expr_starts_expression(p, t) && !tok_is_kw(t, KW_color) && !tok_is_kw(t, KW_colour))) {
            tok_unget(p);
            double e[5] = { 0 };
            int n = expect_ft ? 5 : 3;
            expr_numeric(p, e, &n);
            if (n < 3 || (expect_ft && n != 5))
                tok_fail(p, at.pos, "colour expression expected but float or vector expression found");
            for (int i = 0; i < n && i < 5; i++)
                c[i] = e[i];
            started = 1;
            continue;
        }
        if (t->type == TK_WORD && t->kw < 0 && !started) {
            Symbol *s = tok_symbol_of(p, t);
            if (!s)
                tok_fail(p, t->pos, "undeclared identifier '%.*s'", t->len, t->text);
            if (s->value.kind == VAL_UNSUPPORTED)
                tok_use_unsupported(p, t, &s->value);
        }
        tok_unget(p);
        break;
    }
    if (!started)
        tok_fail_expected(p, tok_peek(p), "a colour");
    finite_or_fail(p, start, c, expect_ft ? 5 : 3, "colour");
    out->r = c[0];
    out->g = c[1];
    out->b = c[2];
    out->filter = expect_ft ? c[3] : 0.0;
    out->transmit = expect_ft ? c[4] : 0.0;
}

/* ---- strings ---------------------------------------------------------- */

static char *string_param(Parser *p)
{
    char *s = expr_string(p);
    return s;
}

char *expr_string(Parser *p)
{
    Token t = *tok_next(p);
    if (t.type == TK_STRING)
        return t.string;
    if (t.type == TK_WORD && t.kw < 0) {
        Symbol *s = tok_symbol_of(p, &t);
        if (s && s->value.kind == VAL_STRING)
            return s->value.string;
        if (s && s->value.kind == VAL_UNSUPPORTED)
            tok_use_unsupported(p, &t, &s->value);
        if (!s)
            tok_fail(p, t.pos, "undeclared identifier '%.*s'", t.len, t.text);
        tok_fail_expected(p, &t, "a string");
    }
    char buf[512];
    switch (t.type == TK_WORD ? t.kw : -1) {
    case KW_concat: {
        tok_expect_punct(p, '(', "'concat'");
        char *acc = string_param(p);
        for (;;) {
            Token *s = tok_next(p);
            if (tok_is_punct(s, ')'))
                return acc;
            if (!tok_is_punct(s, ','))
                tok_fail_expected(p, s, "',' or ')' in 'concat'");
            char *more = string_param(p);
            size_t n1 = strlen(acc), n2 = strlen(more);
            if (n1 + n2 > (1u << 24))
                tok_fail(p, s->pos, "string too long");
            char *joined = tok_temp_alloc(p, n1 + n2 + 1);
            memcpy(joined, acc, n1);
            memcpy(joined + n1, more, n2 + 1);
            acc = joined;
        }
    }
    case KW_str: {
        tok_expect_punct(p, '(', "'str'");
        double v = expr_float_full(p);
        tok_expect_punct(p, ',', "the value");
        int w = int_clamped(expr_float_full(p), -100, 100);
        tok_expect_punct(p, ',', "the width");
        int prec = int_clamped(expr_float_full(p), -1, 40);
        tok_expect_punct(p, ')', "the precision");
        if (prec < 0)
            prec = 6;
        if (w < 0)
            snprintf(buf, sizeof buf, "%0*.*f", -w, prec, v);
        else
            snprintf(buf, sizeof buf, "%*.*f", w, prec, v);
        return tok_temp_strndup(p, buf, strlen(buf));
    }
    case KW_vstr: {
        tok_expect_punct(p, '(', "'vstr'");
        int n = int_clamped(expr_float_full(p), 2, 5);
        tok_expect_punct(p, ',', "the component count");
        double e[5] = { 0 };
        int terms = n;
        expr_numeric(p, e, &terms);
        tok_expect_punct(p, ',', "the vector");
        char *sep = string_param(p);
        tok_expect_punct(p, ',', "the separator");
        int w = int_clamped(expr_float_full(p), -100, 100);
        tok_expect_punct(p, ',', "the width");
        int prec = int_clamped(expr_float_full(p), -1, 40);
        tok_expect_punct(p, ')', "the precision");
        if (prec < 0)
            prec = 6;
        /* as str(): a negative width pads with zeros */
        size_t used = 0;
        buf[0] = '\0';
        for (int i = 0; i < n && used < sizeof buf - 1; i++) {
            int k = w < 0 ? snprintf(buf + used, sizeof buf - used, "%s%0*.*f", i ? sep : "", -w, prec, e[i])
                          : snprintf(buf + used, sizeof buf - used, "%s%*.*f", i ? sep : "", w, prec, e[i]);
            if (k < 0)
                break;
            used += (size_t)k;
            if (used >= sizeof buf)
                used = sizeof buf - 1;
        }
        return tok_temp_strndup(p, buf, strlen(buf));
    }
    case KW_chr: {
        /* POV-Ray: "Value %d cannot be used in chr(...)" outside 0..65535;
         * hstrace's strings are bytes, so codes beyond a byte become '?'. */
        tok_expect_punct(p, '(', "the function name");
        Token at = *tok_peek(p);
        double v = expr_float_full(p);
        tok_expect_punct(p, ')', "the argument");
        int c;
        if (!int_from_double(v, 0, 65535, &c))
            tok_fail(p, at.pos, "chr(%g): a character code is from 0 to 65535", v);
        buf[0] = (char)(c > 0 && c < 256 ? c : '?');
        return tok_temp_strndup(p, buf, 1);
    }
    case KW_substr: {
        tok_expect_punct(p, '(', "'substr'");
        char *s = string_param(p);
        tok_expect_punct(p, ',', "the string");
        double start = expr_float_full(p);
        tok_expect_punct(p, ',', "the start");
        double len = expr_float_full(p);
        tok_expect_punct(p, ')', "the length");
        /* POV-Ray truncates both to integers, then checks the range */
        size_t n = strlen(s);
        int from, count;
        if (!int_from_double(start, 1, INT_MAX, &from) || !int_from_double(len, 0, INT_MAX, &count) ||
            (size_t)from - 1 + (size_t)count > n)
            tok_fail(p, t.pos, "'substr' range outside the string");
        return tok_temp_strndup(p, s + from - 1, (size_t)count);
    }
    case KW_strupr:
    case KW_strlwr: {
        tok_expect_punct(p, '(', "the function name");
        char *s = string_param(p);
        tok_expect_punct(p, ')', "the string");
        char *r = tok_temp_strndup(p, s, strlen(s));
        for (char *q = r; *q; q++)
            if (t.kw == KW_strupr && *q >= 'a' && *q <= 'z')
                *q = (char)(*q - 32);
            else if (t.kw == KW_strlwr && *q >= 'A' && *q <= 'Z')
                *q = (char)(*q + 32);
        return r;
    }
    default:
        tok_fail_expected(p, &t, "a string");
    }
}

/* ---- transforms ----------------------------------------------------------- */

static void compose_checked(Parser *p, Transform *tr, const Transform *u, SourcePos at)
{
    transform_compose(tr, u);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            if (!isfinite(tr->m[i][j]) || !isfinite(tr->inv[i][j]))
                tok_fail(p, at, "this transform makes the object degenerate (infinite or invalid values)");
}

int expr_transform_item(Parser *p, const Token *t, Transform *tr)
{
    Transform step;
    return expr_transform_step(p, t, tr, &step);
}

int expr_transform_step(Parser *p, const Token *t, Transform *tr, Transform *step)
{
    if (t->type != TK_WORD)
        return 0;
    Token at = *t;
    Transform u;
    transform_identity(&u);
    switch (t->kw) {
    case KW_translate:
        transform_translate(&u, expr_vector(p));
        break;
    case KW_rotate:
        transform_rotate(&u, expr_vector(p));
        break;
    case KW_scale:
        transform_scale(&u, expr_scale_vector(p));
        break;
    case KW_matrix: {
        double m[12];
        tok_expect_punct(p, '<', "'matrix'");
        for (int i = 0; i < 12; i++) {
            m[i] = expr_float(p);
            if (i < 11)
                expr_comma(p);
        }
        tok_expect_punct(p, '>', "the twelve matrix values");
        if (!transform_matrix(&u, m))
            tok_fail(p, at.pos, "singular matrix");
        break;
    }
    case KW_transform:
        expr_transform_block(p, &u);
        break;
    default:
        return 0;
    }
    compose_checked(p, tr, &u, at.pos);
    *step = u;
    return 1;
}

static int transform_identifier(Parser *p, const Token *t, Transform *out)
{
    if (t->type != TK_WORD || t->kw >= 0)
        return 0;
    Symbol *s = tok_symbol_of(p, t);
    if (!s)
        tok_fail(p, t->pos, "undeclared identifier '%.*s'", t->len, t->text);
    if (s->value.kind == VAL_UNSUPPORTED)
        tok_use_unsupported(p, t, &s->value);
    if (s->value.kind != VAL_TRANSFORM)
        tok_fail(p, t->pos, "'%.*s' is %s, not a transform", t->len, t->text, tok_value_kind_name(s->value.kind));
    *out = *s->value.transform;
    return 1;
}

void expr_transform_block(Parser *p, Transform *tr)
{
    Token *t = tok_next(p);
    Transform u;
    if (!tok_is_punct(t, '{')) {
        if (transform_identifier(p, t, &u)) {
            transform_compose(tr, &u);
            return;
        }
        tok_fail_expected(p, t, "'{' after 'transform'");
    }
    t = tok_next(p);
    if (transform_identifier(p, t, &u))
        transform_compose(tr, &u);
    else
        tok_unget(p);
    for (;;) {
        t = tok_next(p);
        if (tok_is_punct(t, '}'))
            return;
        if (tok_is_kw(t, KW_inverse)) {
            double tmp[4][4];
            memcpy(tmp, tr->m, sizeof tmp);
            memcpy(tr->m, tr->inv, sizeof tmp);
            memcpy(tr->inv, tmp, sizeof tmp);
            continue;
        }
        if (!expr_transform_item(p, t, tr))
            tok_fail_expected(p, t, "a transform or '}' in 'transform'");
    }
}
