/* Normal perturbation: POV-Ray 3.7's `normal { ... }` (its normal.cpp,
 * Perturb_Normal and the patterns made for normals; bump_map from
 * imageutil.cpp), computed the same way, so that shading sees the normals
 * POV-Ray's does. Shadow decisions never see them: they use the geometry. */
#ifndef HST_NORMAL_H
#define HST_NORMAL_H

#include "world.h"

/* What perturbation needs of the scene besides the normal itself: how
 * many wave sources waves and ripples sum (global_settings'
 * number_of_waves) and the noise generator of patterns that name none. */
typedef struct {
    int nwaves;
    int noise_generator;
} NormalSetting;

NormalSetting normal_setting_of(const World *w);

/* The perturbed unit normal at a point. `to_texture` takes the normal's
 * pattern space to the space `point` and `normal` are in (its transforms
 * and the texture's and object's: pattern to world); `point` is the hit
 * point (or the surface's (u, v, 0) on a uv-mapped object), `uv` the
 * surface's (u, v, 0) for `uv_mapping` inside the normal, `normal` the
 * surface normal facing the ray, unit. */
Vec3 normal_perturb(const NormalSetting *s, const SceneNormal *n, const Transform *to_texture, Vec3 point, Vec3 uv,
                    Vec3 normal);

/* The same for the normal of a texture_map's entry: `parent_to_world`
 * takes the map's pattern space (where its turbulence left the point) to
 * world, `point` is in that space; the normal's own transform leads from
 * its pattern space to the map's, as POV-Ray's Warp_Normal through the
 * map's transforms and then the normal's. */
Vec3 normal_perturb_in(const NormalSetting *s, const SceneNormal *n, const Transform *parent_to_world, Vec3 point,
                       Vec3 uv, Vec3 normal);

/* The perturbation of a normal of the patterns made for normals, at a
 * point of its pattern space (warped) and a normal there: what
 * normal_perturb adds before mapping back (for the pattern tests). */
Vec3 normal_pattern_displace(const NormalSetting *s, const SceneNormal *n, Vec3 point, Vec3 normal);

#endif
