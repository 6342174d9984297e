/* The expression evaluator: floats, vectors, colours and strings in one
 * precedence-climbing loop (expr.c's priority table), the functions and
 * identifiers they use, and transforms. It reads the token stream
 * (parser/tokens) and knows nothing of objects or textures (parser/grammar,
 * which uses it). */
#ifndef HST_EXPRESSIONS_H
#define HST_EXPRESSIONS_H

#include "tokens.h"

/* expr.c */
/* A whole numeric expression, comparisons, '&', '|' and '?:' included,
 * into e: *terms components wanted (1 float, 2-4 vector, 5 colour) on
 * entry, those it has on return. */
void expr_numeric(Parser *p, double e[5], int *terms);
/* Sums and products only, as POV-Ray's Parse_Rel_Factor: a comparison's
 * '<' or '>' then ends it (a vector's component, an array's element). */
void expr_rel_factor(Parser *p, double e[5], int *terms);
double expr_float(Parser *p);
double expr_float_full(Parser *p); /* comparisons allowed */
/* v, read at `at`, as an integer of [lo, hi], truncated toward zero as
 * POV-Ray's casts do; NaN, infinities and values outside the range are an
 * error there: "WHAT must be an integer from LO to HI, not V". */
int expr_checked_int(Parser *p, SourcePos at, double v, int lo, int hi, const char *what);
Vec3 expr_vector(Parser *p);
Vec3 expr_scale_vector(Parser *p);
void expr_colour(Parser *p, Colour *c, int expect_ft);
int expr_starts_colour(Parser *p, const Token *t);
int expr_starts_float(Parser *p, const Token *t);
int expr_starts_expression(Parser *p, const Token *t);
int expr_starts_string(Parser *p, const Token *t);
char *expr_string(Parser *p);
void expr_comma(Parser *p); /* an optional ',' */
/* translate/rotate/scale/matrix/transform at t (already read): composes
 * into tr and returns 1, or returns 0 when t is no transform. */
int expr_transform_item(Parser *p, const Token *t, Transform *tr);
/* The same, the transform read also in *step (text's bounding box follows
 * each one, min_extent) */
int expr_transform_step(Parser *p, const Token *t, Transform *tr, Transform *step);
void expr_transform_block(Parser *p, Transform *tr); /* after 'transform' */

#endif
