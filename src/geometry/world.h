/* The engine's view of a scene: the description flattened into world-space
 * polygons (every polygon, triangle, mesh face and box side), infinite planes,
 * materials, lights and the camera. Built once by world_build (flatten.c);
 * read-only while rendering, so threads share it freely. */
#ifndef HST_WORLD_H
#define HST_WORLD_H

#include <string.h>

#include "scene.h"
#include "shape.h"
#include "vecmath.h"

typedef struct {
    double r, g, b;
} RGB;

/* One texture of a texture_map (World.map_entries): its value in the map,
 * and either a plain texture or a texture_map of its own. */
typedef struct {
    double value;
    int map;              /* its own texture_map (World.maps), or -1: a plain texture */
    /* A plain texture's pigment, or the pattern of its own texture_map; its
     * transform leads from the enclosing map's space (where that map's
     * turbulence left the point) to its pattern, unless it is uv-mapped.
     * Noise generators resolved. */
    Pigment pattern;
    Finish finish;        /* a plain texture's, roughness inverted */
    /* A plain texture's normal (NULL: none): its transform leads from the
     * enclosing map's space, as the pigment's. */
    const SceneNormal *normal;
} MapEntry;

/* A texture_map (POV-Ray's patterned texture): its entries, in the order
 * written, World.map_entries[first .. first + count - 1]. */
typedef struct {
    int first, count;
    int opaque;           /* every texture it can show is opaque */
    int uses_uv;          /* some pattern of it, or of its maps, is uv-mapped */
    int material_map;     /* a material_map: its pattern is a picture choosing one entry */
} TextureMap;

/* Surface properties shared by all polygons of one object. */
typedef struct {
    Colour pigment;       /* solid colour (filter/transmit included); a pattern's representative */
    /* A patterned pigment (kind != PIGMENT_SOLID), evaluated at each hit:
     * material_colour_at (pigment.h). */
    Pigment pattern;
    Transform pattern_to_world;
    /* The texture's normal (NULL: none; read-only, the scene's) and its
     * pattern space to world, as pattern_to_world for the pigment. */
    const SceneNormal *normal;
    Transform normal_to_world;
    Finish finish;        /* roughness already inverted, as POV-Ray uses it */
    /* A texture_map (World.maps), or -1: a plain texture. A texture_map's
     * pattern is `pattern`, to world by `pattern_to_world`; `pigment` and
     * `finish` are unused (its textures have their own, material_textures_at). */
    int map;
    /* A layered texture: the material of the next layer down (World.materials,
     * a plain texture with the same interior and flags), or -1. This
     * material is the top layer (material_layers_at, pigment.h). */
    int below;
    /* An interior_texture: the material shown where a ray meets the surface
     * from inside (the surface's outward normal turned away from the ray:
     * POV-Ray's normaldirection > 0), or -1. */
    int inside;
    /* With an interior texture: POV-Ray's normal of the surface is hstrace's
     * turned (an inverted shape's INVERTED_FLAG, a top-level inverted plane,
     * a box's faces wound inward), so that a ray meets it from inside where
     * (ray . hstrace's normal > 0) != inside_turned. */
    int inside_turned;
    double ior;
    /* Identity of the interior: POV-Ray gives each top-level object one,
     * shared by its children unless they name their own. Rays keep a list of
     * the interiors they are inside to know the ior on both sides. */
    const void *interior_key;
    double fade_distance, fade_power;
    RGB fade_colour;
    /* POV-Ray's fake caustics (0: none): light through a see-through
     * surface of it is multiplied by 1 + |cos|^caustics, cos between the
     * surface's normal and the shadow ray (ComputeShadowTexture). */
    double caustics;
    int opaque;           /* filter == transmit == 0 everywhere (in some layer): blocks light fully */
    int no_shadow, no_image, no_reflection, double_illuminate;
    int hollow;           /* fog goes on inside it (POV-Ray's hollow) */
    SourcePos pos;        /* the object, for messages */
    /* The scene's texture it was made from: two materials of one texture
     * placed alike (pattern_to_world, normal_to_world) show the same
     * surface (materials_look_alike) */
    const SceneTexture *texture;
} Material;

/* Whether two materials show the same surface: made from one texture of
 * the scene, its patterns placed alike, the same layers below and inside
 * (for telling coincident surfaces that differ from those that do not). */
static inline int materials_look_alike(const Material *a, const Material *b)
{
    return a->texture == b->texture && a->below == b->below && a->inside == b->inside &&
           memcmp(&a->pattern_to_world, &b->pattern_to_world, sizeof a->pattern_to_world) == 0 &&
           memcmp(&a->normal_to_world, &b->normal_to_world, sizeof a->normal_to_world) == 0;
}

/* One planar polygon: a triangle, or POV-Ray polygon outlines (holes by the
 * even-odd rule). Points live in World.points. */
typedef struct {
    Vec3 normal;          /* unit geometric normal */
    double d;             /* plane: dot(normal, p) == d */
    unsigned char axis_u, axis_v; /* the two axes kept when projecting to 2-D */
    /* 1: smooth_normals indexes a height field cell's normals instead
     * (CELL_NORMAL_VECTORS, planar_shapes.h), blended bilinearly across the
     * cell as POV-Ray's smooth height fields do (a byte beside the axes,
     * so that a polygon stays 120 bytes) */
    unsigned char cell_normals;
    int first_point;      /* index in World.points */
    int npoints;          /* 3 for triangles; outline points incl. closing repeats otherwise */
    int first_outline;    /* index in World.outline_start; -1 for a triangle */
    int noutlines;
    int smooth_normals;   /* index of 3 normals in World.vertex_normals, or -1 */
    int uv;               /* index of the uv of its first 3 points in World.uvs, or -1
                             (kept only where a uv_mapping pigment needs it) */
    int vertex_materials; /* index of its 3 points' materials in World.vertex_materials, or -1:
                             a face with a texture per vertex, blended (pigment.h) */
    int material;
    Vec3 bbox_min, bbox_max;
} Polygon;

typedef struct {
    Vec3 normal;          /* unit */
    double d;             /* dot(normal, p) == d */
    int material;
} InfinitePlane;

typedef struct {
    LightKind kind;
    Vec3 location;
    Vec3 direction;       /* parallel: unit vector from the scene toward the light */
    Vec3 point_at;        /* as given: a parallel area light's samples point from it */
    RGB colour;
    int shadowless;
    double fade_distance, fade_power;
    LightBeam beam;       /* spotlight or cylinder: intensity across the beam, whose axis
                           * runs from location toward point_at (-direction) */
    double beam_radius, beam_falloff, beam_tightness; /* as in SceneLight */
    AreaLight area;       /* area.size1 == 0: a point light */
} Light;

typedef struct {
    CameraKind kind;
    Vec3 location, direction, up, right;
    double angle, h_angle, v_angle; /* as in SceneCamera */
} Camera;

/* The box of one outline's points: the least and largest coordinates. */
typedef struct {
    Vec3 lo, hi;
} OutlineBox;

/* Instancing (instance.h): a mesh the scene places two or more times keeps
 * its polygons once, in its own space (a prototype), and each placement is
 * an instance: the prototype, its transform and its materials. */
typedef struct {
    int first_polygon, npolygons; /* World.polygons, past the world's own */
    /* Materials per instance: slot 0 the mesh's own (or inherited) texture,
     * slot 1 + i the mesh's texture i; its polygons' `material` is a slot. */
    int nslots;
    Vec3 bbox_min, bbox_max;      /* of its polygons, in its own space */
} Prototype;

typedef struct {
    Transform to_world;   /* the prototype's space to world (inv: back) */
    int prototype;
    int first_id;         /* the id (instance.h) of its first polygon */
    int first_material;   /* World.instance_materials[first_material + slot] */
    int hidden;           /* some material of it is no_image, no_reflection or no_shadow */
    /* 1: the inverse's linear part is a signed permutation (quarter turns
     * and mirrors, as LDraw parts mostly are): local axis i is world axis
     * axis[i] times sign[i], exactly (instance_inverse_dir) */
    int permutation;
    int axis[3];
    double sign[3];
    Vec3 bbox_min, bbox_max; /* of its polygons, in world space */
} Instance;

/* The material code names the surface a point lies on by one int (the
 * surface id): a polygon's id (instance.h), -1 for an infinite plane, and
 * shape k as surface_of_shape(k), below -1. */
static inline int surface_of_shape(int shape) { return -2 - shape; }
static inline int surface_shape(int surface) { return -2 - surface; }

/* Whether a polygon's outlines have boxes (World.outline_box): when it has
 * holes, or one outline of 5 points or more; a box costs three of the
 * crossing count's projections, more than a quad's whole count saves. */
static inline int polygon_has_outline_boxes(int noutlines, int npoints) { return noutlines > 1 || npoints >= 5; }

typedef struct {
    int npolygons;
    Polygon *polygons;
    int npoints;
    Vec3 *points;
    int noutline_starts;
    int *outline_start;   /* per polygon with outlines: noutlines+1 indices into points */
    OutlineBox *outline_box; /* beside outline_start, for the polygons polygon_has_outline_boxes
                              * names (others' entries unset, and past the last such polygon's
                              * none): entry k the box of outline k's points, for
                              * intersect_outlines to pass over an outline a ray is certainly
                              * outside of; NULL: none kept (the full count everywhere) */
    int nvertex_normals;
    Vec3 *vertex_normals;
    int nuvs;
    Vec3 *uvs;            /* (u, v, 0) */
    int nvertex_materials;
    int *vertex_materials; /* per face with a texture per vertex, its 3 materials (plain textures) */
    int nplanes;
    InfinitePlane *planes;
    /* The analytic shapes (shape.h): spheres ..., each as POV-Ray keeps
     * it, never made polygons. A hit on one is a HIT_SHAPE; materials and
     * flags as a polygon's. */
    int nshapes;
    /* nshapes shapes, the hierarchy's items, then nparts more: the parts
     * of the CSG objects among them (Shape.is_part), which a hit names
     * as it names any shape (ShapeHit.leaf) */
    Shape *shapes;
    int nparts;
    /* The blobs' components (blob.h), one allocation per blob shape */
    int nblobs;
    struct Blob **blobs;
    int nmaterials;
    Material *materials;
    int nmaps;
    TextureMap *maps;     /* the materials' texture_maps, each built once */
    int nmap_entries;
    MapEntry *map_entries;
    int nlights;
    Light *lights;
    Camera camera;
    /* The background without an alpha channel (opaque: POV-Ray 3.7 takes
     * its colour times 1 - transmit, 3.6 its colour), and as the scene gave
     * it, for an alpha channel (+UA). */
    RGB background;
    RGB background_colour;
    double background_filter, background_transmit;
    /* +UA: camera rays and the rays refracted from them see the background
     * as transparent as it is. Zero from world_build; the caller sets it. */
    int alpha_background;
    /* NULL: the background colour alone. Else the scene's sky sphere with
     * its own copy of the pigments, noise generators resolved (owned). */
    SkySphere *sky;
    int legacy_sky;       /* #version below 3.7: POV-Ray 3.6's layering of the sky's filter */
    /* #version below 3.7: a see-through texture's own light is reduced by
     * POV-Ray 3.6's 1 - (filter * max(r, g, b) + transmit) instead of 3.7's
     * 1 - filter - transmit (trace.cpp keeps it for such scenes) */
    int legacy_layer_light;
    int nfogs;
    const SceneFog *fogs; /* the scene's, read-only */
    RGB ambient_light;
    int radiosity_replaces_ambient; /* at +Q9 no finish's ambient counts (POV-Ray 3.7 with radiosity) */
    int max_trace_level;
    double adc_bailout;
    int noise_generator;  /* of patterns that name none (scene_noise_generator) */
    int number_of_waves;  /* global_settings: the sources of waves and ripples normals */
    Vec3 bounds_min, bounds_max; /* of all polygons and shapes; empty when min > max */
    int ndegenerate;      /* polygons dropped at build: no area, up to rounding */
    /* Instances (instance.h); none unless the build was asked to make
     * them (WorldLimits.instance_meshes). npolygons counts the world-space
     * polygons only; the prototypes' follow them in `polygons`. */
    int nproto_polygons;
    int nprototypes;
    Prototype *prototypes;
    int ninstances;
    Instance *instances;
    int ninstance_materials;
    int *instance_materials;
    int nids;             /* npolygons + every instance's polygons: the polygon ids a hit may carry */
    int nsee_through;     /* polygons whose material is not opaque (a shadow ray meets at most these, each
                             once: the room for what it filters) */
} World;

typedef struct {
    char message[512];
    SourcePos pos;     /* the top-level object being built; file NULL: none */
    int over_budget;   /* 1: a budget of WorldLimits was crossed (a scene error), 0: out of memory */
} WorldError;

/* What a build may use (world_build_limited). */
typedef struct {
    /* Bytes the world may take (0: no limit): the polygons, points,
     * materials ... a flattening will make are counted from the scene's
     * tree before any is made, top-level object by top-level object, and
     * the first that takes the world past it is refused. */
    size_t max_memory;
    /* clock_wall() time the build must end by (0: none), checked as it
     * goes; what it stands for (--max-parse-seconds) is in max_seconds. */
    double deadline;
    double max_seconds;
    /* 1: a mesh placed two or more times is kept once, as a prototype with
     * instances (instance.h), where its materials allow it; 0: every copy
     * flattened to world-space polygons. */
    int instance_meshes;
} WorldLimits;

/* Returns 0, or -1 with err filled (e.g. out of memory). */
int world_build(World *w, const Scene *scene, WorldError *err);
/* world_build with a big mesh's faces made on up to `threads` threads:
 * the same world, bit for bit, for any number (tests/test_modelling.c). */
int world_build_threads(World *w, const Scene *scene, int threads, WorldError *err);
/* world_build_threads within the limits given (NULL: none); crossing one is
 * an error with the position of the top-level object that crossed it
 * (WorldError.over_budget). */
int world_build_limited(World *w, const Scene *scene, int threads, const WorldLimits *limits, WorldError *err);
void world_free(World *w);

#endif
