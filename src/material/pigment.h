/* Pigments: POV-Ray 3.7's patterns (checker, hexagon, gradient, noise,
 * spirals here; the others in patterns.h) with turbulence, colour maps,
 * pigment maps and average, evaluated at a point (pattern.cpp, warps.cpp
 * and pigment.cpp there); and the textures a texture_map shows at a point
 * (trace.cpp's ComputeOneTextureColour). */
#ifndef HST_PIGMENT_H
#define HST_PIGMENT_H

#include "scene.h"
#include "world.h"

/* The pattern's value at a point in pattern space (after the pigment's
 * transforms, before its turbulence), after frequency, phase and wave:
 * checker 0 or 1, hexagon 0, 1 or 2, the others in [0, 1]. A noise
 * generator of 0 stands for POV-Ray's default, 2. */
double pattern_value(const Pigment *pig, Vec3 p);

/* pattern_value in two steps, as POV-Ray's normals take it: the point
 * displaced by the pattern's turbulence (Warp_EPoint after the transform),
 * then the value at a point so displaced (Evaluate_TPat), with the noise
 * generator `default_generator` and `default_waves` wave sources (ripples,
 * waves) where the pattern has none of its own. */
Vec3 pattern_warp(const Pigment *pig, Vec3 p);
double pattern_value_warped(const Pigment *pig, Vec3 p, int default_generator, int default_waves);

/* An image_map's or bump_map's picture (map_type 0): where point p of
 * pattern space falls on it, in pixels from its top left (POV-Ray's
 * map_pos); 0 when off a picture used `once`. */
int image_map_position(const Pigment *pig, Vec3 p, double *x, double *y);
/* Its colour there, interpolated as the pigment says. */
Colour image_colour_at(const Pigment *pig, double x, double y);
/* The same, and the palette entry there (interpolated and truncated as
 * POV-Ray does; -1 for a picture that is not colour-mapped). as_stored:
 * a premultiplied picture's colour left premultiplied, as POV-Ray hands
 * it to bump_map and material_map (image_map's colours are divided). */
Colour image_colour_index_at(const Pigment *pig, double x, double y, int *index, int as_stored);
/* A material_map's texture at point p of its pattern space, 0 to count - 1:
 * the palette entry there, or the red of a picture without one times 255
 * (POV-Ray's material_map, imageutil.cpp). */
int material_map_number(const Pigment *pig, Vec3 p, int count);

/* The colour at a point in pattern space (solid pigments: their colour). */
Colour pigment_at(const Pigment *pig, Vec3 p);

/* The uv coordinates (u, v, 0) of a world-space point on a surface (a
 * surface id, world.h): a polygon's mesh uv vectors or box mapping, a
 * shape's own mapping (shape_uv), or, for a polygon without them and for
 * planes (-1), POV-Ray's default: the point's world x and y. */
Vec3 surface_uv(const World *w, int polygon, Vec3 world_point);

/* A material's colour at a world-space point on polygon `polygon` (-1: an
 * infinite plane). */
Colour material_colour_at(const World *w, const Material *m, int polygon, Vec3 world_point);

/* One plain texture a material shows at a point, as POV-Ray shades it: its
 * share of the surface's colour (a texture_map blends the colours its
 * textures are shaded with by these weights), its pigment's colour there
 * and its finish. */
typedef struct {
    double weight;
    Colour colour;
    const Finish *finish;
    Vec3 normal;          /* its shading normal (see material_textures_at) */
} SurfaceTexture;

#define MAX_SURFACE_TEXTURES (1 << MAX_TEXTURE_MAP_DEPTH)

/* The plain textures of a material at a world-space point on polygon
 * `polygon` (-1: a plane): for a plain texture itself (weight 1); for a
 * texture_map, at each level the two entries around the pattern's value
 * there, or the one it falls on (POV-Ray's ComputeOneTextureColour and
 * Search_Blend_Map); for a mesh face with a texture per vertex
 * (Polygon.vertex_materials, whatever m), the three vertices' textures by
 * the point's place in the face (Mesh::Determine_Textures). Returns how
 * many, 1 to MAX_SURFACE_TEXTURES; their weights sum to 1, or, for a face
 * with a texture per vertex, to a little less where one's weight is below
 * adc_bailout and left out, as POV-Ray leaves it. */
int material_textures_at(const World *w, const Material *m, int polygon, Vec3 world_point,
                         SurfaceTexture out[MAX_SURFACE_TEXTURES]);
/* A plain texture (m->map < 0) at a point, with its shading normal:
 * `normal` (the surface's, facing the ray) perturbed by the texture's
 * normal when `perturb` (+Q8). */
SurfaceTexture material_plain_texture_at(const World *w, const Material *m, int polygon, Vec3 world_point,
                                         Vec3 normal, int perturb);
/* The same with each texture's shading normal: `normal` (the surface's,
 * facing the ray) perturbed by the texture's normal when `perturb` (+Q8),
 * as POV-Ray moves it through the maps' transforms to the entry's normal
 * and back. */
int material_textures_normals_at(const World *w, const Material *m, int polygon, Vec3 world_point, Vec3 normal,
                                 int perturb, SurfaceTexture out[MAX_SURFACE_TEXTURES]);

/* A layered texture's layers (m->below >= 0; also a plain one: one layer)
 * at a point, top first, each as material_plain_texture_at gives it (its
 * colour, finish and shading normal, weight 1). Returns how many, 1 to
 * MAX_TEXTURE_LAYERS. */
int material_layers_at(const World *w, const Material *m, int polygon, Vec3 world_point, Vec3 normal, int perturb,
                       SurfaceTexture out[MAX_TEXTURE_LAYERS]);

/* What a see-through material lets through at a point, per channel, for
 * shadow rays: rgb * filter + transmit of its pigment (of a layered
 * texture: the product over its layers), or of each texture of a
 * texture_map blended by their weights (POV-Ray's ComputeShadowTexture
 * through ComputeOneTextureColour). *blocks: no light gets through (no
 * texture there has filter or transmit, or a layer has neither). */
RGB material_filter_at(const World *w, const Material *m, int polygon, Vec3 world_point, int *blocks);

/* What a sky sphere and the background show in direction `dir` (unit),
 * without an alpha channel (POV-Ray 3.7's ComputeSky, version >= 3.7). */
RGB sky_colour(const World *w, Vec3 dir);
/* The same over another opaque background colour: with an alpha channel
 * POV-Ray 3.7 keeps the background's colour as given, and reflected rays
 * see it opaque, not composited on black. */
RGB sky_colour_over(const World *w, Vec3 dir, RGB below);
/* The same seen with an alpha channel (+UA): the background with its own
 * filter and transmit, and what the sky and background together let
 * through, as POV-Ray 3.7 gives it (POV-Ray 3.6's scenes: nothing at all,
 * transmit 1). */
RGB sky_colour_alpha(const World *w, Vec3 dir, double *transmit);

#endif
