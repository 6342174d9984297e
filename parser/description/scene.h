/* The scene description: what a .pov file says, in plain data.
 *
 * The parser fills it and knows nothing of grids, shadows or pixels; the engine
 * reads it and never sees a token. Everything hangs off one arena owned by the
 * Scene, so a scene is freed (or abandoned after an error) in one call.
 *
 * Only what the scene instantiates is here: a declaration that is never used
 * (a sphere in an include file) leaves no trace in the description. */
#ifndef HST_SCENE_H
#define HST_SCENE_H

#include <stddef.h>

#include "arena.h"
#include "transform.h"
#include "vecmath.h"

/* Where something was written, for messages. `file` points into the arena. */
typedef struct {
    const char *file;
    int line, column;
} SourcePos;

/* POV-Ray colours carry filter and transmit beside rgb. */
typedef struct {
    double r, g, b, filter, transmit;
} Colour;

/* Something hstrace renders only approximately (see APPROXIMATIONS in the
 * man page). Notes hang off the description where they were written; only
 * those reachable from what the scene instantiates are reported
 * (Scene.approximations), so a declaration in an include file that is never
 * used reports nothing. */
typedef enum {
    APPROX_NORMAL,        /* normal { } perturbation: ignored */
    APPROX_PATTERN,       /* a pigment pattern hstrace does not evaluate: one colour */
    APPROX_WARP,          /* warps other than turbulence, turbulence on checker/hexagon/gradient: ignored */
    APPROX_LAYERS,        /* layered textures blended into one */
    APPROX_FINISH,        /* irid, crand, diffuse backside: ignored */
    APPROX_DISPERSION,    /* an interior's dispersion: ignored */
    APPROX_PHOTONS,       /* photons { } blocks: ignored */
    APPROX_RADIOSITY,     /* global radiosity / subsurface: ignored */
    APPROX_FOCAL_BLUR,    /* camera aperture / normal: a pinhole camera */
    APPROX_FOG,           /* fog on light rays (media_attenuation) */
    APPROX_VERTEX_TEXTURES, /* a mesh face's texture per vertex: the first one on the whole face */
    APPROX_KINDS
} ApproxKind;

typedef struct ApproxNote {
    ApproxKind kind;
    SourcePos pos;
    const char *what;             /* the keyword as written, e.g. "bozo" */
    const struct ApproxNote *next; /* notes are shared, never changed */
} ApproxNote;

/* One line of the report: how many places of a kind, and the first. */
typedef struct {
    ApproxKind kind;
    int count;
    SourcePos first;
    const char *what;
} SceneApproximation;

/* "normal perturbation ignored", ... for messages and statistics. */
const char *approx_kind_name(ApproxKind k);
const char *approx_kind_effect(ApproxKind k);

typedef enum {
    PIGMENT_SOLID,    /* one colour */
    PIGMENT_CHECKER,  /* two colours (POV-Ray's checker) */
    PIGMENT_HEXAGON,  /* three colours (POV-Ray's hexagon) */
    PIGMENT_GRADIENT, /* a colour map along a direction */
    PIGMENT_BOZO,     /* solid noise (also spotted and bumps) */
    PIGMENT_GRANITE,  /* 6 octaves of |noise| */
    PIGMENT_WRINKLES, /* 10 octaves of noise */
    PIGMENT_AGATE,    /* a sine of turbulence and z */
    PIGMENT_MARBLE,   /* x plus turbulence, triangle wave */
    PIGMENT_WOOD,     /* distance from the z axis, turbulence, triangle wave */
    PIGMENT_SPIRAL1,  /* arms around the z axis, triangle wave */
    PIGMENT_SPIRAL2,  /* two sets of arms crossing */
    PIGMENT_IMAGE_MAP, /* a picture laid on the unit square of x and y (map_type 0) */
    PIGMENT_BRICK,    /* mortar 0, brick 1 (brick_size, mortar) */
    PIGMENT_LEOPARD,  /* the square of the mean of sin x, sin y, sin z */
    PIGMENT_ONION,    /* the distance from the origin, modulo 1 */
    PIGMENT_RADIAL,   /* the angle about y, 0 to 1 */
    PIGMENT_QUILTED,  /* unit cubes, rounded by control0 and control1 */
    PIGMENT_DENTS,    /* noise cubed */
    PIGMENT_RIPPLES,  /* number_of_waves sources, one frequency */
    PIGMENT_WAVES,    /* number_of_waves sources, each its own frequency */
    PIGMENT_PLANAR,   /* |y| */
    PIGMENT_SPHERICAL,   /* the distance from the origin */
    PIGMENT_CYLINDRICAL, /* the distance from the y axis */
    PIGMENT_BOXED,    /* the largest of |x|, |y|, |z| */
    PIGMENT_SQUARE,   /* four colours, squares in x-z */
    PIGMENT_TRIANGULAR, /* six colours, triangles in x-z */
    PIGMENT_CUBIC,    /* six colours, the six pyramids of the axes */
    PIGMENT_CELLS,    /* a random value per unit cube */
    PIGMENT_CRACKLE,  /* distances to random points, one per unit cube */
    PIGMENT_FRACTAL,  /* mandel, julia, magnet (fractal_kind) */
    PIGMENT_PIGMENT_PATTERN, /* another pigment's grey (inner) */
    PIGMENT_AVERAGE,  /* the mean of its map's pigments, weighed by their values */
} PigmentKind;

/* The fractals of mandel, julia and magnet (POV-Ray's MANDEL_PATTERN ...
 * MAGNET2J_PATTERN): mandel and julia of exponent 2, 3, 4 or more, magnet
 * types 1 and 2 of each. */
typedef enum {
    FRACTAL_MANDEL, FRACTAL_JULIA, FRACTAL_MAGNET1M, FRACTAL_MAGNET1J, FRACTAL_MAGNET2M, FRACTAL_MAGNET2J,
} FractalKind;

/* An image_map's picture as POV-Ray holds it: straight (not premultiplied)
 * RGBA, in the scene's working space, row 0 the picture's top. */
typedef struct {
    int width, height;
    const float *rgba;
    int has_alpha;    /* some pixel's alpha is below 1 */
    const char *path; /* as found through the include folders */
    /* rgba's colours are premultiplied by alpha: POV-Ray then interpolates
     * them so and divides by alpha after (imageutil.cpp's image_colour_at) */
    int premultiplied;
    /* A colour-mapped picture (POV-Ray's IsIndexed: a PNG or BMP of a
     * palette): each pixel's entry, and the entries as POV-Ray's colour map
     * holds them, colour, filter and transmit (1 - alpha, or what `filter
     * N, F`, `transmit all T` ... set). npalette 0: not colour-mapped,
     * rgba alone counts. */
    const unsigned char *index;
    int npalette;
    float (*palette)[5];
} SceneImage;

/* What a picture loader hands the parser (ParseOptions.load_image): the
 * colours as the file stores them, decoded to linear light, straight or
 * premultiplied by alpha as `premultiplied` says; a colour-mapped one's
 * palette (straight RGBA) and indices. rgba and index are malloc'd. */
typedef struct {
    int width, height;
    float *rgba;
    int premultiplied;
    int ncolours;
    float palette[256][4];
    unsigned char *index;
    /* The values as stored, in no colour space: not to be taken to the
     * working gamma (POV-Ray 3.7's PPM and PGM that nothing told a gamma) */
    int as_stored;
    /* A grey picture, and the largest sample its file holds (255, 65535,
     * a PGM's maxval): what a height field's heights are made from. */
    int grey;
    unsigned sample_max;
} LoadedPicture;

/* ParseOptions.load_image's gammas: what the file names, else its type's */
#define IMAGE_GAMMA_FILE_DEFAULT (-1.0)

/* Turbulence of a pattern (POV-Ray's TURB warp): `turbulence` written in
 * the pigment (classic: marble, wood, agate and the spirals also add its
 * scalar value to theirs) or `warp { turbulence ... }`. Both displace the
 * point by the vector turbulence times `amount`, in the order written,
 * after the pigment's transforms (POV-Ray keeps all of those at the head
 * of the warp list). */
typedef struct {
    int classic;          /* `turbulence` (or octaves, omega, lambda) outside a warp */
    Vec3 amount;          /* default 0 */
    int octaves;          /* default 6, held to 1..10 */
    double omega, lambda; /* defaults 0.5 and 2 */
} PatternTurbulence;

struct Pigment;

/* One [value colour] entry of a colour_map, sorted by value as written; of
 * a pigment_map, or of checker's (brick's ...) list of pigments, the
 * entry's pigment where it has a pattern of its own (NULL: the colour
 * alone; else `colour` is its representative colour). */
typedef struct {
    double value;
    Colour colour;
    const struct Pigment *pigment;
} ColourMapEntry;

/* POV-Ray's wave types, which reshape a pattern's value before the map. */
typedef enum { WAVE_RAMP, WAVE_SINE, WAVE_TRIANGLE, WAVE_SCALLOP, WAVE_CUBIC, WAVE_POLY } WaveKind;

typedef struct Pigment {
    PigmentKind kind;
    /* Solid: the colour (also that of a pattern hstrace only approximates:
     * its colour map at 0.5). Evaluated patterns: their map at 0.5, a
     * representative colour for where one colour must stand for all. */
    Colour colour;
    /* checker and hexagon: the 2 or 3 colours; gradient: the colour map
     * (POV-Ray's default black to white when none is given). */
    int nmap;
    const ColourMapEntry *map;
    double frequency, phase; /* POV-Ray's defaults 1 and 0; checker and hexagon set 0 */
    WaveKind wave;
    double wave_exponent;    /* poly_wave */
    double agate_turb;       /* agate_turb, default 1 */
    int noise_generator;     /* 1..3, or 0: the scene's (GlobalSettings) */
    int nturbulence;         /* warps, in POV-Ray's order (shared, never changed) */
    const PatternTurbulence *turbulence;
    /* uv_mapping: the pattern is evaluated at (u, v, 0) of the surface
     * (mesh uv coordinates, POV-Ray's default world x, y elsewhere), and
     * `transform` is its own, not moved by the texture or the object. */
    int uv_mapping;
    Transform transform;  /* pattern space to texture space */
    /* image_map: the picture, and POV-Ray's once, interpolate (0 none, 2
     * bilinear, 4 normalised distance), filter all and transmit all. */
    const SceneImage *image;
    int image_once, image_interpolate;
    int image_map_type;   /* POV-Ray's map_type: 0 planar, 1 spherical, 2 cylindrical, 5 torus */
    int image_use_index;  /* bump_map's use_index: a colour-mapped picture's entries are its heights */
    double image_filter_all, image_transmit_all;
    /* waves and ripples: how many sources (global_settings'
     * number_of_waves); 0: not yet given the scene's, 10 then */
    int nwaves;
    /* The parameters of one kind of pattern, valid while `kind` is that
     * kind (they share their memory, as POV-Ray's TPATTERN.Vals). */
    union {
        Vec3 gradient; /* gradient: normalised, as POV-Ray stores it */
        int arms;      /* spiral1, spiral2 */
        /* brick: its size (default <8, 3, 4.5>) and mortar, minus POV-Ray's
         * 2 EPSILON, in single precision as there */
        struct {
            Vec3 brick_size;
            double mortar;
        };
        struct {
            double control0, control1; /* quilted (single precision), default 1 and 1 */
        };
        /* crackle: form (default <-1, 1, 0>), metric (2), offset (0), solid */
        struct {
            Vec3 crackle_form;
            double crackle_metric, crackle_offset;
            int crackle_solid;
        };
        /* mandel, julia, magnet: the kind, julia's complex constant,
         * max_iteration, exponent, and the interior and exterior types and
         * factors (defaults 0, 1 and 1, 1) */
        struct {
            FractalKind fractal;
            int iterations, exponent;
            int interior_type, exterior_type;
            double fractal_u, fractal_v;
            double interior_factor, exterior_factor;
        };
        const struct Pigment *inner; /* pigment_pattern: the pigment whose grey is the value */
    };
    int map_pigments;     /* some entry of the map has a pigment of its own */
    /* the scene's noise generator (0: not yet resolved, 2 then), for the
     * pigments of its map's entries and pigment_pattern's, which name none */
    int scene_generator;
    const ApproxNote *approx;
} Pigment;

/* How a normal perturbs the surface normal (POV-Ray 3.7's normal.cpp):
 * the patterns made only for normals displace it by their own formulas;
 * any other pattern by its slope, sampled at four points around the
 * point (Perturb_Normal); normal_map and average combine other normals. */
typedef enum {
    NORMAL_NONE,     /* no pattern (or one hstrace does not evaluate): the normal unchanged */
    NORMAL_PATTERN,  /* the pattern of `pattern` (checker ... spiral2) by its slope */
    NORMAL_BUMPS,    /* vector noise */
    NORMAL_DENTS,    /* vector noise times noise cubed */
    NORMAL_WRINKLES, /* 10 octaves of |vector noise| */
    NORMAL_WAVES,    /* number_of_waves sources, each its own frequency */
    NORMAL_RIPPLES,  /* number_of_waves sources, one frequency */
    NORMAL_QUILTED,  /* unit cubes, rounded by pattern.control0 and control1 */
    NORMAL_AVERAGE,  /* the entries' perturbations, weighed */
    NORMAL_BUMP_MAP, /* the slope of a picture's brightness (pattern.image) */
    NORMAL_UV,       /* uv_mapping: `uv_entry` at the surface's (u, v, 0) */
} NormalKind;

/* One [value, <height, slope>] entry of a slope_map. */
typedef struct {
    double value, height, slope;
} SlopeMapEntry;

struct SceneNormal;

/* One [value normal {...}] entry of a normal_map, or of average's list. */
typedef struct {
    double value;
    const struct SceneNormal *normal;
} NormalMapEntry;

/* POV-Ray's TNORMAL. `pattern` holds what a normal shares with a pigment:
 * the pattern kind and its parameters, frequency, phase, wave, turbulence,
 * noise generator, the transform (pattern space to texture space; a map's
 * entries are relative to their normal's pattern space) and a bump_map's
 * picture. Its colour fields are unused. */
typedef struct SceneNormal {
    NormalKind kind;
    Pigment pattern;
    double amount;        /* bump_size (or the value after the pattern), default 0.5 */
    double accuracy;      /* the sample spacing of slopes, default 0.02 */
    int no_bump_scale;    /* POV-Ray's DONT_SCALE_BUMPS_FLAG */
    int nslope;           /* slope_map, sorted by value as written */
    const SlopeMapEntry *slope;
    int nmap;             /* normal_map, average's entries, or a checker's / hexagon's normals */
    const NormalMapEntry *map;
    const struct SceneNormal *uv_entry; /* NORMAL_UV */
    const ApproxNote *approx;
} SceneNormal;

/* POV-Ray 3.7 finish, with its defaults (see scene_default_finish). */
typedef struct {
    double ambient[3];    /* default 0.1 (scaled by global ambient_light) */
    double emission[3];   /* default 0 */
    double diffuse;       /* default 0.6 */
    double brilliance;    /* default 1 */
    double crand;         /* parsed, not modelled */
    double phong;         /* default 0 */
    double phong_size;    /* default 40 */
    double specular;      /* default 0 */
    double roughness;     /* default 0.05; stored as written (POV-Ray uses 1/roughness) */
    double metallic;      /* default 0: highlights tinted by the pigment when > 0 */
    double reflection_min[3]; /* `reflection` sets min = max unless both given */
    double reflection_max[3];
    double reflection_falloff;  /* default 1 */
    double reflection_exponent; /* default 1 (`reflection_exponent`, or `exponent` in a reflection block) */
    int reflection_fresnel;     /* `reflection { ... fresnel }` */
    double reflection_metallic; /* `reflection { ... metallic }` */
    int conserve_energy;
    /* A finish's `caustics` (POV-Ray's Temp_Caustics, default -1: none),
     * which POV-Ray moves to the object's interior where the object's
     * texture is a plain one (Post_Process). */
    double caustics;
    const ApproxNote *approx;
} Finish;

typedef struct {
    double ior;           /* default 1 */
    const ApproxNote *approx;
    double fade_distance; /* 0: none */
    double fade_power;
    Colour fade_colour;
    /* Fake caustics: 45 times the value written, as POV-Ray keeps it (0:
     * none). */
    double caustics;
} Interior;

struct SceneTexture;

/* One [value texture] entry of a texture_map, in the order written (POV-Ray
 * keeps them so, and its Search_Blend_Map reads them in that order). */
typedef struct {
    double value; /* in single precision, as POV-Ray keeps it */
    const struct SceneTexture *texture;
} TextureMapEntry;

/* Levels of texture_maps hstrace follows in one texture (a map whose
 * entries are maps ...): a hit is shaded with at most 2 to this power
 * textures, two per level, as POV-Ray shades it. */
#define MAX_TEXTURE_MAP_DEPTH 4

typedef struct SceneTexture {
    Pigment pigment;
    const SceneNormal *normal; /* NULL: the surface's own normal */
    Finish finish;
    SourcePos pos;
    const ApproxNote *approx; /* the texture's own: normal, layering; a texture_map's: its entries' too */
    /* A patterned texture (POV-Ray's texture_map, and checker or hexagon
     * with a list of textures): its nmap entries. Then `pigment` holds the
     * pattern only (kind, gradient, arms, frequency, phase, wave,
     * turbulence, noise_generator, uv_mapping and transform; no colours),
     * and `finish` is unused. 0: a plain texture. */
    int nmap;
    const TextureMapEntry *map;
    int map_depth;            /* levels of texture_maps from this one down: 0 for a plain texture */
    /* POV-Ray's material_map: `pigment` is its picture (PIGMENT_IMAGE_MAP,
     * with once, interpolate and map_type), and a point shows the one entry
     * the picture's palette entry (or red times 255) there names, unblended
     * (imageutil.cpp's material_map); the entries' values are 0, 1, ... */
    int material_map;
    /* A layered texture (`texture { A } texture { B }`: B lies on A): the
     * next layer down, a plain texture itself, or NULL. This texture is the
     * top layer; POV-Ray lights each layer with its own pigment, normal and
     * finish and lets the layers above filter it (ComputeLightedTexture). */
    const struct SceneTexture *below;
} SceneTexture;

/* Layers hstrace shades in one layered texture (a bit of a word each). */
#define MAX_TEXTURE_LAYERS 32

typedef enum {
    OBJ_POLYGON,
    OBJ_TRIANGLE,        /* also smooth_triangle (has_normals) */
    OBJ_MESH,            /* mesh and mesh2, already expanded to index form */
    OBJ_BOX,
    OBJ_PLANE,
    OBJ_UNION,
    /* The shapes POV-Ray 3.7 itself intersects as planar triangles and
     * polygons (its own sampling and subdivision), flattened so. */
    OBJ_HEIGHT_FIELD,
    OBJ_BICUBIC_PATCH,
    OBJ_PRISM,           /* an analytic shape: an outline of splines swept along y */
    OBJ_SPHERE,          /* the analytic shapes: kept as they are, never made polygons */
    OBJ_DISC,
    OBJ_CONE,            /* also cylinder (equal radii) */
    OBJ_TORUS,
    /* POV-Ray's algebraic surfaces: quadric, and poly (also cubic and
     * quartic), solids whose polynomial is negative inside */
    OBJ_QUADRIC,
    OBJ_POLY,
    OBJ_SUPERELLIPSOID,  /* superellipsoid { <e, n> } */
    OBJ_LATHE,           /* lathe: a spline turned about the y axis */
    OBJ_SOR,             /* sor: a surface of revolution, radius^2 cubic in the height */
    /* One glyph of a text object (a text is a union of them): its outline
     * swept from z = 0 to z = depth (u.glyph). */
    OBJ_GLYPH,
    OBJ_BLOB,            /* u.blob: POV-Ray's blob, a field's level surface */
    /* CSG over solids (the analytic shapes and other CSG): children in
     * u.csg as a union's; a difference's children after the first are
     * taken away from it (POV-Ray: inverted, then intersected). */
    OBJ_INTERSECTION,
    OBJ_DIFFERENCE,
    OBJ_MERGE,
} ObjectKind;

/* One segment of a lathe's spline as POV-Ray's Compute_Lathe makes it:
 * x(w) = ((a[0] w + b[0]) w + c[0]) w + d[0] (the radius), y(w) likewise
 * with index 1 (the height), for w in [0, 1]. */
typedef struct SplineSegment {
    double a[2], b[2], c[2], d[2];
} SplineSegment;

/* One segment of a sor as POV-Ray's Compute_Sor makes it: the squared
 * radius a y^3 + b y^2 + c y + d between the heights y1 < y2, where its
 * radius goes from x1 to x2. */
typedef struct SorSegment {
    double a, b, c, d;
    double y1, y2, x1, x2;
} SorSegment;

/* A lathe's spline (POV-Ray's LINEAR_SPLINE ... BEZIER_SPLINE). */
typedef enum { SPLINE_LINEAR, SPLINE_QUADRATIC, SPLINE_CUBIC, SPLINE_BEZIER } SplineKind;

/* One segment of a prism's outline as POV-Ray's Compute_Prism makes it:
 * x(t) = a[0] t^3 + b[0] t^2 + c[0] t + d[0], z(t) likewise in [1], for
 * t in [0, 1]; its rectangle u1..u2, v1..v2 in x and z, and x1..x2,
 * y1..y2 the same swept (scaled by both heights for a conic sweep). */
typedef struct PrismSegment {
    double a[2], b[2], c[2], d[2];
    double u1, u2, v1, v2, x1, x2, y1, y2;
} PrismSegment;

/* How a prism's outline is swept (POV-Ray's linear_sweep, conic_sweep). */
typedef enum { PRISM_LINEAR_SWEEP, PRISM_CONIC_SWEEP } PrismSweep;
/* Whether objects of this kind hold children (u.csg): a union or a CSG
 * operation. */
static inline int scene_object_has_children(ObjectKind k)
{
    return k == OBJ_UNION || k == OBJ_INTERSECTION || k == OBJ_DIFFERENCE || k == OBJ_MERGE;
}

typedef struct {
    int v[3];       /* vertex indices */
    int n[3];       /* normal indices, or -1 for a flat triangle */
    int uv[3];      /* uv coordinate indices (mesh.uvs), or -1: uv (0, 0) */
    int texture;    /* index into the mesh's textures, or -1 for the object's */
    /* A texture per vertex (mesh2's three indices, a triangle's
     * texture_list) where they differ: the second and third vertex's,
     * `texture` the first's; -1: the face has one texture. */
    int texture2, texture3;
} MeshFace;

/* A TrueType glyph's outline as POV-Ray 3.7's text object keeps it
 * (truetype.cpp's GlyphStruct): contour k is the points start[k] ..
 * start[k + 1] - 1 in font units divided by the units per em, its last
 * point a copy of its first; a point off the curve is a quadratic Bezier's
 * control point (two in a row have an on-curve point midway). The header's
 * bounds, in font units, make its box. */
typedef struct SceneGlyph {
    int ncontours;
    const int *start;
    const double *x, *y;
    const unsigned char *on_curve;
    int xmin, ymin, xmax, ymax;
    int units_per_em;
} SceneGlyph;

typedef struct SceneObject SceneObject;

/* A blob's component as POV-Ray's Parse_Blob leaves it (its Blob_Element
 * before Make_Blob): a sphere keeps its centre and radius through
 * translations, rotations and uniform scales, and becomes an ellipsoid
 * (own_space: then `center` and `radius2` are in its own space, reached
 * through `placed`) at any other transform; a cylinder is always placed:
 * from base to apex of radius sqrt(radius2), then `placed`. */
typedef enum { BLOB_COMPONENT_SPHERE, BLOB_COMPONENT_CYLINDER } BlobComponentKind;
typedef struct {
    BlobComponentKind kind;
    double strength;
    double radius2;
    Vec3 center;       /* sphere */
    Vec3 base, apex;   /* cylinder */
    int own_space;     /* sphere: an ellipsoid, placed by `placed` */
    Transform placed;  /* the component's transforms after its own frame */
} SceneBlobComponent;

struct SceneObject {
    ObjectKind kind;
    SourcePos pos;
    /* Object to world, composed of every transform written on the object in
     * order. A child's world transform is child.transform then parent's. */
    Transform transform;
    /* NULL: inherit from the enclosing union, else the scene's default. */
    const SceneTexture *texture;
    /* POV-Ray's interior_texture: shown where a ray meets the surface from
     * inside (its outward normal turned away from the ray); NULL: the
     * enclosing union's, or none. Bound with `texture` (texture_bind). */
    const SceneTexture *interior_texture;
    const Interior *interior; /* NULL: default interior (ior 1) */
    /* The object's transform when its texture was given: as in POV-Ray,
     * transforms written before the texture do not move its pattern, those
     * after it do (pattern to world = pigment transform, then the inverse of
     * this, then the object's transform, then its parents'). */
    Transform texture_bind;
    const ApproxNote *approx;
    /* The object's photons { }: a note counted only where photon mapping
     * would run (gram_collect_approximations), and whether it makes the
     * object a photon target. */
    const ApproxNote *photons;
    unsigned no_shadow : 1, no_image : 1, no_reflection : 1, hollow : 1, inverse : 1, photon_target : 1;
    /* A transform was written on it that POV-Ray's analytic shapes cannot
     * fold into their own parameters: a matrix, a transform { } or a scale
     * that is not uniform. A sphere so transformed (or inside a union so
     * transformed) is POV-Ray's ellipsoid: intersected through its inverse
     * transform rather than by a moved centre and radius. */
    unsigned general_transform : 1;
    unsigned sturm : 1;   /* `sturm`: POV-Ray's Sturm root solver for the polynomial shapes */
    /* POV-Ray's bounding box of the object as min_extent and max_extent
     * read it (its BBox: single-precision corner and lengths, as each
     * kind of object makes it and carries it through the transforms
     * written on it), where hstrace keeps it (has_extent: object_extent.c
     * names the kinds). */
    unsigned has_extent : 1;
    float extent_lower[3], extent_lengths[3];
    int double_illuminate;
    /* clipped_by: the object's surfaces are kept only inside every one of
     * these solids (POV-Ray's Clip, also in its inside test). Each is
     * placed relative to the object's transform: its world transform is
     * its own, then the object's, then the parents' (the parser has
     * taken out what the object was transformed by before clipped_by, as
     * POV-Ray moves a clip only by transforms written after it). */
    int nclips;
    SceneObject **clips;
    /* bounded_by's objects: no effect on the image (POV-Ray's bounding
     * hint), kept for `clipped_by { bounded_by }`; placed as clips are */
    int nbounds;
    SceneObject **bounds;
    /* Levels of unions from this object down (1: a union of other objects,
     * 0: not a union). The parser keeps it at MAX_NESTING (200) at most, so
     * whatever walks the tree recurses that deep at most. */
    int depth;
    union {
        struct {            /* polygon: one or more closed outlines */
            int npoints;    /* all outline points; each outline is closed */
            Vec3 *points;   /* in object space; 2-D points have z = 0 */
            int noutlines;
            int *outline_start; /* noutlines + 1 entries: start index of each, then npoints */
        } polygon;
        struct {
            Vec3 v[3];
            Vec3 n[3];
            int has_normals; /* smooth_triangle */
        } triangle;
        struct {
            int nvertices, nnormals, nfaces, ntextures, nuvs;
            Vec3 *vertices, *normals;
            Vec3 *uvs;           /* uv_vectors (z = 0), for uv_mapping */
            MeshFace *faces;
            const SceneTexture **textures;
            /* its triangles' points' box (min_extent's, before its
             * transforms), worked out once when the mesh is closed, so
             * that each copy of a declared mesh is not walked again */
            int has_box;
            Vec3 box_lo, box_hi;
        } mesh;
        struct {
            Vec3 corner1, corner2;
        } box;
        struct {
            Vec3 center;
            double radius;
            /* what POV-Ray's Sphere keeps for its bounding box
             * (object_extent.c): its centre and radius as the translations,
             * rotations and uniform scales written on it moved them, and
             * the transform it keeps from the first other one on (NULL
             * until then; never changed once made, copies share it) */
            Vec3 pov_center;
            double pov_radius;
            const Transform *pov_trans;
        } sphere;
        struct {
            Vec3 center, normal; /* normal of unit length */
            double radius, hole; /* hole: the inner radius, 0 for none */
        } disc;
        struct {
            /* cone { base, base_radius, apex, apex_radius [open] };
             * a cylinder's radii are equal */
            Vec3 base, apex;
            double base_radius, apex_radius;
            int open;            /* no end caps */
        } cone;
        struct {
            double major, minor;
        } torus;
        struct {
            /* quadric { <A,E,H>, <B,C,F>, <D,G,I>, J }: A x^2 + E y^2 +
             * H z^2 + B xy + C xz + F yz + D x + G y + I z + J, the
             * vectors as POV-Ray names them (Square_Terms, Mixed_Terms,
             * Terms, Constant) */
            Vec3 square, mixed, terms;
            double constant;
        } quadric;
        struct {
            /* poly { order, <coefficients> }: (order+1)(order+2)(order+3)/6
             * of them, in POV-Ray's order of the terms (x^order first,
             * the constant last) */
            int order;
            const double *coeffs;
        } poly;
        struct {
            double e, n; /* superellipsoid { <e, n> }: both positive */
        } superellipsoid;
        struct {            /* lathe { [spline] N, <r, h>... [sturm] } */
            SplineKind spline;
            int nsegments;
            const SplineSegment *segments;
        } lathe;
        struct {            /* sor { N, <r, h>... [open] } */
            int nsegments;  /* N - 3 */
            const SorSegment *segments;
            int open;       /* no base and cap discs */
        } sor;
        struct {
            const SceneGlyph *glyph;
            double depth;        /* the text's thickness: the sweep along z */
        } glyph;
        struct {
            double threshold;
            int ncomponents;                       /* as written, at least 1 */
            const SceneBlobComponent *components;
        } blob;
        struct {
            Vec3 normal; /* as written (not normalised) */
            double distance;
        } plane;
        struct {            /* height_field, in POV-Ray's own units */
            /* samples across x and z (at least 2 each); heights[z * nx + x]
             * in 0..65535, z = 0 the picture's bottom row (POV-Ray's
             * HField map), as image_height_at reads the samples */
            int nx, nz;
            const unsigned short *heights;
            /* POV-Ray's bounding_corner1 y: 65536 * water_level (0 none);
             * the surface below it is not there */
            double water;
            int smooth;
        } height_field;
        struct {            /* bicubic_patch */
            int type;       /* 0 or 1: the same triangles (POV-Ray's own subdivision) */
            int u_steps, v_steps;
            double flatness;
            Vec3 control[4][4]; /* [u][v], as written, in object space */
            double st[4][2];    /* uv_vectors: the texture's uv at the patch's corners */
        } bicubic_patch;
        struct {            /* prism, its segments made as Compute_Prism makes them */
            PrismSweep sweep;
            SplineKind spline;
            double height1, height2; /* height1 <= height2 */
            int nsegments;
            const PrismSegment *segments;
            /* the outline's rectangle (POV-Ray's u1, u2, v1, v2) and the
             * swept one's (x1, x2, y1, y2: scaled by the heights for a
             * conic sweep), x, z in the prism's own space */
            double u1, u2, v1, v2, x1, x2, y1, y2;
            int open;       /* no caps */
            int degenerate; /* an unclosed curved outline: POV-Ray ignores it */
        } prism;
        struct {
            int nchildren;
            SceneObject **children;
            /* light_sources written in the union, in the union's space (their
             * own transforms applied, the union's not). They become scene
             * lights, moved by the union's and its parents' transforms, when
             * the union is instantiated (Scene.lights); the engine never
             * reads them here. light_slot[i]: how many children were written
             * before light i, so that lights keep POV-Ray's order. */
            int nlights;
            const struct SceneLight *lights;
            const int *light_slot;
        } csg;
    } u;
};

typedef enum {
    LIGHT_POINT,
    LIGHT_PARALLEL,
} LightKind;

/* How a light's intensity falls off across its beam (POV-Ray's
 * Attenuate_Light): everywhere the same, a spotlight's cone around the
 * line from location to point_at, or a cylinder light's cylinder around it. */
typedef enum {
    BEAM_NONE,
    BEAM_SPOT,     /* radius, falloff: cosines of the angles, as POV-Ray keeps them */
    BEAM_CYLINDER, /* radius, falloff: distances from the axis; the light is parallel */
} LightBeam;

/* area_light <axis1>, <axis2>, size1, size2 and its modifiers, as POV-Ray
 * 3.7 keeps them (LightSource's Area_* fields): a grid of size1 x size2
 * point lights spanning axis1 x axis2 around the light's location. */
typedef struct {
    Vec3 axis1, axis2;  /* world space, transformed as directions */
    int size1, size2;   /* samples along each axis; 0: not an area light */
    int adaptive;       /* POV-Ray's Adaptive_Level: 100 (every sample) unless given */
    int jitter;         /* each sample moved at random within its cell */
    int circular;       /* the grid squeezed into a disc */
    int orient;         /* the grid turned to face each shading point */
    int full_area;      /* area_illumination: shading from each sample, not the centre */
} AreaLight;

/* The most samples one area light may have (hstrace's limit: each shading
 * point keeps a colour per sample while it samples the light). */
#define MAX_AREA_LIGHT_SAMPLES (1 << 20)

typedef struct SceneLight {
    LightKind kind;
    SourcePos pos;
    Vec3 location;  /* world space, transforms applied (in a union: see csg) */
    Vec3 point_at;  /* parallel lights: direction is location - point_at; spotlights and
                     * cylinder lights: the beam's axis */
    LightBeam beam;
    double beam_radius, beam_falloff, beam_tightness;
    Colour colour;
    int shadowless;
    double fade_distance; /* 0: no fading */
    double fade_power;
    AreaLight area;
    const ApproxNote *approx; /* media_attenuation */
    const ApproxNote *photons; /* photons { }: counted as the objects' are */
    /* looks_like { OBJECT }: the object that shows where the light is, moved
     * with it and casting no shadow (POV-Ray's LightSource children[0]); the
     * parser adds it to the scene's objects with the light. NULL: none. */
    SceneObject *looks_like;
} SceneLight;

/* POV-Ray 3.7's camera types (its CreateCameraRay). */
typedef enum {
    CAMERA_PERSPECTIVE,
    CAMERA_ORTHOGRAPHIC,
    CAMERA_FISHEYE,
    CAMERA_ULTRA_WIDE_ANGLE,
    CAMERA_OMNIMAX,
    CAMERA_PANORAMIC,
    CAMERA_CYLINDER_1, /* `cylinder 1` to `cylinder 4`, in that order */
    CAMERA_CYLINDER_2,
    CAMERA_CYLINDER_3,
    CAMERA_CYLINDER_4,
    CAMERA_SPHERICAL,
} CameraKind;

/* The camera after POV-Ray's parse rules (defaults, angle, look_at, sky and
 * transforms already applied): the engine only builds rays from it. */
typedef struct {
    CameraKind kind;
    SourcePos pos;
    Vec3 location, direction, up, right;
    double angle;                  /* degrees; the field of view of the types after orthographic (90 by default) */
    double h_angle, v_angle;       /* spherical: horizontal and vertical fields of view (360, 180) */
    const ApproxNote *approx; /* focal blur, camera normal */
} SceneCamera;

/* POV-Ray's bound on max_trace_level (configbackend.h there): the ray
 * tree, which the renderer walks recursively, is never deeper. */
#define MAX_TRACE_LEVEL_LIMIT 256
/* hstrace's bound on number_of_waves (POV-Ray has none): every shading
 * point of waves and ripples visits every source. */
#define MAX_NUMBER_OF_WAVES 10000
#define DEFAULT_NUMBER_OF_WAVES 10 /* POV-Ray's */

typedef struct {
    double assumed_gamma;   /* 0 when not given */
    int max_trace_level;    /* default 5; 1 to MAX_TRACE_LEVEL_LIMIT */
    double adc_bailout;     /* default 1/255 */
    Colour ambient_light;   /* default 1,1,1 */
    int has_assumed_gamma;
    int assumed_gamma_srgb; /* `assumed_gamma srgb` (assumed_gamma is then 0) */
    int noise_generator;    /* 0 when not given: 2, or 1 before #version 3.5 */
    int radiosity;          /* a radiosity block was given (not modelled) */
    int number_of_waves;    /* waves and ripples: their sources; default 10 */
} GlobalSettings;

/* sky_sphere: pigments on the unit sphere of directions, the last written
 * on top (POV-Ray 3.7's ComputeSky). */
typedef struct {
    int npigments;        /* 0: no sky sphere */
    Pigment *pigments;
    Transform transform;  /* the sky sphere's own transforms */
} SkySphere;

/* fog: POV-Ray's constant fog (fog_type 1) or ground fog (2), applied to
 * rays through the atmosphere at +Q9 (POV-Ray's ComputeFog). */
typedef struct {
    int type;             /* 1 constant, 2 ground; other numbers act as 1, as in POV-Ray */
    double distance;      /* where the fog lets 1/e through; 0: no fog */
    Colour colour;        /* with filter and transmit */
    double alt, offset;   /* ground fog: height scale, and where full density ends */
    Vec3 up;              /* ground fog: unit, "up" for alt and offset */
    /* Turbulence (any of turbulence, octaves, omega, lambda given): how far
     * it thins the fog, the noise's scale and its octaves (omega, lambda
     * and turb_depth rounded to single precision, as POV-Ray keeps them). */
    int turbulent;
    double turb_depth;
    Vec3 turbulence;
    int octaves;
    double omega, lambda;
} SceneFog;

typedef struct {
    Arena *arena;
    double version;            /* from #version, default 3.7 */
    int version_given;         /* the scene has a #version */
    SceneCamera camera;
    int has_camera;
    Colour background;         /* default black, transmit 1 when unspecified in 3.7 */
    SkySphere sky;
    int nfogs;
    SceneFog *fogs;
    GlobalSettings globals;
    SceneTexture default_texture;
    int nlights;
    SceneLight *lights;
    int nobjects;
    SceneObject **objects;     /* top-level objects in file order */
    /* What the scene uses that hstrace only approximates, one entry per
     * kind used, in ApproxKind order (empty with ParseOptions.strict). */
    int napproximations;
    SceneApproximation *approximations;
} Scene;

Finish scene_default_finish(void);
Interior scene_default_interior(void);

void scene_free(Scene *scene);

/* Once the engine has made its own copy of the meshes (world_build), their
 * long lists (vertices, normals, uvs, faces) are of no more use: their big
 * allocations are given back and every mesh reached from the scene's
 * objects is left with none (counts 0). On 10^6 triangles that is some
 * 50 MB off the peak, which comes later, with the hierarchy's build. */
void scene_release_mesh_lists(Scene *scene);

/* The scene's working gamma, as POV-Ray 3.7 decides it: the colours it
 * computes are linear light raised to 1/gamma. 1: linear (assumed_gamma 1,
 * and the default of #version 3.7 scenes); 0: the sRGB curve (assumed_gamma
 * srgb); else that power. A scene older than 3.7, or with no #version, that
 * sets no assumed_gamma has "gamma correction off": its colours are taken
 * as encoded for POV-Ray's default display gamma, which is sRGB (measured:
 * POV-Ray 3.7 renders such a scene exactly as with assumed_gamma srgb). */
double scene_working_gamma(const Scene *s);
/* POV-Ray's "gamma correction off" (gammaMode None at the end of the parse:
 * no assumed_gamma, a version below 3.7 or none): the working and file
 * gamma are then the Display_Gamma option's (frontend's CreateView). */
int scene_gamma_correction_off(const Scene *s);

/* The language version POV-Ray 3.7 keeps its older rules by (its
 * EffectiveLanguageVersion): the scene's last #version (or +MV), and 3.62
 * for a scene that gives none, which POV-Ray takes as written for 3.6 (as
 * L3P's exports are): the background, the sky, a see-through texture's own
 * light and radiosity's ambient follow it. */
double scene_effective_version(const Scene *s);

/* The noise generator of patterns that name none (POV-Ray 3.7: the one of
 * global_settings, else 2, or 1 for a scene whose #version is below 3.5). */
int scene_noise_generator(const Scene *s);

/* Reading a pigment description (the engine evaluates patterns, pigment.h). */

/* The colour of a map at `value` (POV-Ray's Search_Blend_Map, then linear
 * interpolation between the two entries around the value). */
Colour colour_map_at(const ColourMapEntry *map, int n, double value);

/* Whether every colour the pigment can give is opaque (no filter, no
 * transmit): then it blocks light fully wherever it is hit. */
int pigment_is_opaque(const Pigment *pig);

#endif
