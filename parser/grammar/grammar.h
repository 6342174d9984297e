/* The scene grammar: objects, textures, pigments, normals, the camera,
 * lights, fog, global settings and declarations, and the public entry
 * points of parser.h (parse_scene.c). It reads values with the expression
 * evaluator (parser/expressions) and the token stream (parser/tokens). */
#ifndef HST_GRAMMAR_H
#define HST_GRAMMAR_H

#include "expressions.h"
#include "tokens.h"

/* What the grammar keeps while it reads a scene (Parser.gram): the scene's
 * top-level lists until the parse ends, and the settings later statements
 * depend on. */
typedef struct GramState {
    TempVec objects; /* of SceneObject *, top level */
    TempVec lights;  /* of SceneLight */
    TempVec fogs;    /* of SceneFog, in file order */
    const ApproxNote *global_approx; /* global_settings: radiosity, subsurface, fog's media */
    const ApproxNote *global_photons; /* global_settings' photons { }: counted as the objects' are */
    int media_attenuation_seen; /* a light_source asked for media_attenuation */
    int default_changed;        /* #default was used */
    /* POV-Ray's gammaMode while parsing (image_gamma.c) */
    enum { GAMMA_MODE_NONE, GAMMA_MODE_37_IMPLIED, GAMMA_MODE_36, GAMMA_MODE_37 } gamma_mode;
    int charset; /* global_settings' charset so far (truetype_font.h's TTF_CHARSET_...) */
} GramState;

/* A value as POV-Ray stores it in a float (SNGL): map values, frequency,
 * phase, bump_size ... land where POV-Ray's do. */
static inline double gram_single(double v) { return (double)(float)v; }

/* parse_texture.c */
/* POV-Ray's outline rule for polygons: in the points pts, an
 * outline closes on a point equal (within epsilon, in x, y and z) to its first, and the next point starts another; one left
 * open is closed by repeating its first point. *starts gets each outline's
 * first index, then the count of points. Returns 1 when the last outline
 * was closed in the file, 0 when it had to be (POV-Ray warns). */
int gram_outlines(Parser *p, TempVec *pts, double epsilon, TempVec *starts);
SceneTexture *gram_default_texture(Parser *p);
SceneTexture *gram_texture(Parser *p);   /* after 'texture' */
void gram_pigment(Parser *p, Pigment *pig); /* after 'pigment' */
void gram_finish(Parser *p, Finish *f);  /* after 'finish' */
void gram_interior(Parser *p, Interior *in); /* after 'interior' */
/* After 'material': POV-Ray's Parse_Material on *tex and *in (an object's
 * texture and interior so far, or NULL): a material identifier first, then
 * textures layered on, interiors, and transforms, which move the texture
 * (not the object). at: the 'material' keyword. */
void gram_material(Parser *p, const SceneTexture **tex, const Interior **in, const Token *at);
void gram_skip_normal(Parser *p);              /* after 'normal' */
/* The identifier at t when it holds `kind` (NULL when t is none; an error
 * for an identifier of another kind). */
const Value *gram_block_identifier(Parser *p, const Token *t, ValueKind kind, const char *block);
/* How hstrace treats a pattern keyword in a pigment. */
typedef enum { PAT_NONE, PAT_EVALUATED, PAT_APPROXIMATED, PAT_UNSUPPORTED } PatternSupport;
PatternSupport gram_pattern_support(int kw);
/* How many colours, normals or textures a pattern takes in a list
 * (checker 2, hexagon 3, brick 2, square 4, triangular and cubic 6), 0 for
 * patterns that take a map instead. */
int gram_pattern_list_count(int kw);
/* An evaluated pattern at its keyword kw (read): its kind and arguments,
 * frequency, phase and wave at POV-Ray's defaults. */
void gram_start_pattern(Parser *p, Pigment *pig, int kw);
/* frequency, phase, waves, turbulence, warp, noise_generator ... at t
 * (read): 1 when it was one, its arguments read. */
int gram_pattern_modifier_item(Parser *p, Pigment *pig, const Token *t);
int gram_pattern_modifier(int kw);     /* a modifier of patterns hstrace does not evaluate */
void gram_skip_arguments(Parser *p);   /* such a keyword's arguments */
/* POV-Ray's Check_Turb: the turbulence `turbulence`, `octaves` ... change. */
PatternTurbulence *gram_classic_turbulence(Parser *p, Pigment *pig);
int gram_octaves_value(double v);
void gram_warp(Parser *p, Pigment *pig, const Token *at); /* after 'warp' */
/* A blend map's next entry: 0 at its '}', else 1 after '[' and the value. */
int gram_blend_map_entry(Parser *p, const char *map, const TempVec *entries, int optional, double *value);
/* After a map's '{': a declared map of `kind` and the '}' after it (POV-Ray
 * takes one identifier in place of the entries), or NULL. */
const Value *gram_map_identifier(Parser *p, ValueKind kind, const char *map);
/* The maps after their keyword `at` (read), into a pigment, a patterned
 * texture or a normal; also what #declare reads for a declared map. */
void gram_colour_map(Parser *p, Pigment *pig);
void gram_pigment_map(Parser *p, Pigment *pig, const Token *at);
void gram_texture_map(Parser *p, SceneTexture *tex, const Token *at);
void gram_normal_map(Parser *p, SceneNormal *n, int average);
void gram_slope_map(Parser *p, SceneNormal *n);
/* A picture of image_map, bump_map or material_map (`block`), after its
 * '{', into pig; the picture, the parse's own (a colour-mapped one's
 * entries are the image_map's to change). */
SceneImage *gram_image_source(Parser *p, Pigment *pig, const Token *at, const char *block, int gamma_correct);
/* The file of a picture named in the scene, found as #include files are
 * (the temporary arena), or NULL. */
char *gram_find_image_file(Parser *p, const char *name);
int gram_image_interpolation(Parser *p, const Token *at); /* after 'interpolate' */
int gram_image_map_type(Parser *p, const Token *at);      /* after 'map_type': its value */

/* parse_normal.c */
/* After 'normal' (kw): the normal `from` (NULL: the default texture's)
 * modified by the block. need_pattern: a normal that ends up with no
 * pattern is an error (POV-Ray's "No normal type given." for what objects
 * use; #default and #declare may leave the pattern to later blocks). */
const SceneNormal *gram_normal(Parser *p, const SceneNormal *from, const Token *kw, int need_pattern);
/* A copy moved by tr (pattern space to texture space, then tr), as a
 * texture's transforms move its normal; a uv-mapped normal stays. */
const SceneNormal *gram_normal_transformed(Parser *p, const SceneNormal *n, const Transform *tr);
/* The normal seen at the surface's (u, v, 0): an object's uv_mapping. */
const SceneNormal *gram_normal_uv_mapped(Parser *p, const SceneNormal *n);
/* A texture seen at the surface's (u, v, 0), as an object's uv_mapping
 * makes every texture of it and `texture { uv_mapping ... }` makes its own:
 * its own transforms still place it, the object's and outer textures' do
 * not move it (POV-Ray's UV_FLAG and uv_mapping pattern); parse_objects.c */
const SceneTexture *gram_texture_uv_mapped(Parser *p, const SceneTexture *tex);
/* A layer `top` over `below` (both copied): one texture, see parse_texture.c. */
SceneTexture *gram_layer_textures(Parser *p, const SceneTexture *top, const SceneTexture *below, const Token *at);
const SceneTexture *gram_layers_moved(Parser *p, const SceneTexture *tex, const Transform *moved);
const SceneTexture *gram_layers_blended(Parser *p, const SceneTexture *tex, const Token *at);
/* sky_sphere { pigment {...} ... transforms } after 'sky_sphere'. */
void gram_sky_sphere(Parser *p, SkySphere *sky);

/* parse_fog.c: fog { ... } after 'fog' */
void gram_fog(Parser *p, const Token *kw, SceneFog *fog);

/* parse_objects.c */
int gram_is_object_keyword(int kw);
/* An object or light starting at t (already read); returns 1 and fills one
 * of *obj / *light, or 0 when t starts no object. */
int gram_object(Parser *p, const Token *t, SceneObject **obj, SceneLight **light);
/* A new object of `kind` written at t, and the modifiers every object
 * takes up to its closing '}' (`what` names it in messages). */
SceneObject *gram_new_object(Parser *p, ObjectKind kind, const Token *t);
void gram_object_mods(Parser *p, SceneObject *o, const char *what);

/* The shapes POV-Ray intersects as planar pieces, after their keyword kw:
 * parse_height_field.c, parse_bicubic_patch.c, parse_prism.c */
SceneObject *gram_height_field(Parser *p, const Token *kw);
SceneObject *gram_bicubic_patch(Parser *p, const Token *kw);
SceneObject *gram_prism(Parser *p, const Token *kw);
SceneObject *gram_quadric(Parser *p, const Token *kw);
/* poly (order 0: read from the file), cubic (3), quartic (4) */
SceneObject *gram_poly(Parser *p, const Token *kw, int order);
SceneObject *gram_superellipsoid(Parser *p, const Token *kw);
SceneObject *gram_lathe(Parser *p, const Token *kw);
SceneObject *gram_sor(Parser *p, const Token *kw);
SceneObject *gram_text(Parser *p, const Token *kw); /* parse_text.c */
/* object_extent.c: POV-Ray's BBox of an object (SceneObject.has_extent):
 * set from a minimum and maximum, read back as them, carried through one
 * transform written on the object (nothing where it has none). */
void gram_extent_from_min_max(SceneObject *o, const double min[3], const double max[3]);
void gram_extent_min_max(const SceneObject *o, double min[3], double max[3]);
void gram_extent_transform(SceneObject *o, const Transform *t);
/* A union's or CSG object's box from its parts' (CSG::Compute_BBox), where
 * every part it takes has one. */
void gram_csg_extent(SceneObject *o);
/* A sphere's transform step as POV-Ray's Sphere takes it (its centre and
 * radius moved, or its own transform begun or extended): kw the step's
 * keyword (translate, rotate, scale, matrix, transform). */
void gram_sphere_extent_step(Parser *p, SceneObject *o, int kw, const Transform *step);
/* The bounding box of a sphere, box, cone or cylinder, torus, disc,
 * triangle, mesh, polygon, superellipsoid or plane as POV-Ray's
 * Compute_BBox makes it from
 * the object's parameters and the transforms written on it so far; other
 * kinds are left as they are. */
void gram_primitive_extent(SceneObject *o);
SceneObject *gram_blob(Parser *p, const Token *kw);
/* A 2-D vector (POV-Ray's Parse_UV_Vect: a float f stands for <f, f>). */
void gram_uv_vector(Parser *p, double out[2]);
/* The spline a lathe's or prism's keyword kw names: 1 and *kind set, or 0
 * (kw names none). */
int gram_spline_kind(int kw, SplineKind *kind);

/* parse_camera.c */
void gram_camera(Parser *p, const Token *t, SceneCamera *cam);
void gram_default_camera(SceneCamera *cam);
SceneLight *gram_light_source(Parser *p, const Token *t);
/* A light's transform, which moves its looks_like object too (a copy: a
 * declared light's object is shared). */
void gram_transform_light(Parser *p, SceneLight *l, const Transform *tr);
/* A copy of object o's top (and interior) that may be changed: o is shared. */
SceneObject *gram_copy_object(Parser *p, const SceneObject *o);
/* Appends transform `tr` to what places object `o` (as a transform written
 * after its other modifiers). */
void gram_transform_object(SceneObject *o, const Transform *tr);
/* A top-level union: its light_sources (and its inner unions') go to the
 * scene's lights with the transforms above them applied. */
void gram_instantiate_union_lights(Parser *p, const SceneObject *o, const Transform *outer, int depth);

/* image_gamma.c: POV-Ray 3.7's reading of a picture's colours, by the
 * gamma mode the scene is in when the picture is parsed. decode and
 * untagged go to ParseOptions.load_image; the linear values it returns are
 * then encoded with working (1 none, 0 sRGB, else a power law). */
typedef struct {
    double decode, untagged, working;
} ImageGammaPlan;
/* global_settings' first assumed_gamma (0: srgb); later ones are ignored */
void gram_assumed_gamma_seen(Parser *p, double gamma);
/* after a #version has set p->version */
void gram_version_seen(Parser *p);
/* gamma_correct: colours (image_map) rather than data (bump_map,
 * material_map); override_given: the picture's own `gamma override` */
ImageGammaPlan gram_image_gamma_plan(const Parser *p, int gamma_correct, int override_given, double override);

/* approximations.c: the report of what the instantiated scene approximates */
void gram_collect_approximations(Parser *p);

/* parse_scene.c */
void gram_declare(Parser *p, const Token *hash, int local);
/* Any value (a #declare's right side, a macro argument): unsupported things
 * become VAL_UNSUPPORTED instead of errors. */
Value gram_value_lenient(Parser *p);
/* A copy that does not share an array's elements. */
Value gram_copy_value(Parser *p, const Value *v);
void gram_default_directive(Parser *p);


#endif
