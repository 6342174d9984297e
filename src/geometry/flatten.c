/* Flattening: the scene description's object tree becomes world-space
 * polygons. Unions pass their transform, texture, interior and flags down;
 * boxes become six quads; mesh faces become triangles; planes stay infinite
 * and are kept apart (they cannot go into a finite grid). The curved
 * objects become shapes (shape.h), and a CSG object or clipped object a
 * shape whose parts follow the world's shapes (csg.h): inside it a box or
 * a plane is a solid shape, not polygons. */
#include "world.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "big_memory.h"
#include "blob.h"
#include "clock.h"
#include "memory_budget.h"
#include "parallel.h"
#include "planar_shapes.h"
#include "ptr_map.h"
#include "lathe.h"
#include "prism.h"
#include "quadric.h"
#include "sor.h"
#include "text.h"
#include "world_estimate.h"

/* add_material's memo: 2^6 materials made lately, by a hash of what made
 * them. World estimates (world_estimate.c) still count one material an
 * object: an upper bound. */
#define MATERIAL_MEMO_BITS 6
#define MATERIAL_MEMO (1 << MATERIAL_MEMO_BITS)

typedef struct {
    int index;        /* the material; -1: none */
    const SceneTexture *tex;
    const Interior *interior;
    const void *interior_key;
    int flags[5];
    SourcePos pos;
} MaterialMemo;

typedef struct {
    World *w;
    int cap_polygons, cap_points, cap_outlines, cap_outline_boxes, cap_normals, cap_planes, cap_shapes, cap_materials, cap_uvs;
    int cap_vertex_materials;
    int cap_maps, cap_map_entries;
    /* The texture_maps built so far, by their entries (a hash set of the
     * description's entry arrays, which copies of a texture share), so
     * that each is built once however many objects and maps use it. */
    PtrMap maps_built;    /* entry array -> its index in World.maps */
    int failed;
    int threads;          /* a big mesh's faces are made on up to this many (fill_faces) */
    double deadline;      /* WorldLimits.deadline: 0 none */
    long objects;         /* objects flattened so far, for the clock's checks */
    int timed_out;        /* the deadline passed */
    /* Materials made lately and what made them (add_material), by a hash
     * of that: copies of a declared object by the million (unions of
     * copies, exported parts) would each take a material of over a
     * kilobyte, the same bytes. */
    MaterialMemo memo[MATERIAL_MEMO];
    /* Instancing (WorldLimits.instance_meshes): how often each mesh's
     * faces (shared by every copy of a declared mesh) are placed, and the
     * prototype each shared one became (-1: none yet), by a hash set of the
     * face arrays; the meshes the prototypes are made from. */
    int instancing;
    PtrMap mesh_uses;     /* face array -> its placements */
    PtrMap mesh_proto;    /* face array -> its prototype (World.prototypes) */
    const SceneObject **proto_mesh;
    int cap_prototypes, cap_instances, cap_instance_materials;
    int slots;            /* making prototypes: polygons' materials are slots, which read no uv */
    /* The parts of CSG objects, made while csg_depth > 0: they follow the
     * world's shapes once all are made (World.nparts). */
    Shape *parts;
    int nparts, cap_parts, csg_depth;
    char message[200];    /* what failed, where it is not memory */
} Builder;

/* Grows *array (of `size`-byte items) so that index `need` fits. */
static int grow(void **array, int *cap, int need, size_t size)
{
    if (need < *cap)
        return 0;
    int ncap = *cap ? *cap : 64;
    while (ncap <= need) {
        if (ncap > (1 << 29))
            return -1;
        ncap *= 2;
    }
    void *p = big_realloc(*array, (size_t)ncap * size);
    if (!p)
        return -1;
    *array = p;
    *cap = ncap;
    return 0;
}

#define GROW(b, arr, cap, need) \
    (grow((void **)&(b)->w->arr, &(b)->cap, (need), sizeof(*(b)->w->arr)) ? ((b)->failed = 1, -1) : 0)

typedef struct {
    Transform transform;
    const SceneTexture *texture;
    const SceneTexture *interior_texture; /* SceneObject.interior_texture, or NULL */
    const Interior *interior;
    int no_shadow, no_image, no_reflection, double_illuminate, hollow;
    /* inverse: POV-Ray's Invert, passed down a union to its children;
     * general_transform: some transform on the way down is one a shape
     * cannot fold into its parameters (SceneObject.general_transform) */
    int inverse, general_transform;
    const void *top_object; /* the top-level object: owner of the default interior */
    Transform texture_space; /* the texture's space to world (SceneObject.texture_bind) */
    Transform interior_texture_space; /* the same for interior_texture (its object's binding) */
} Inherited;

static RGB rgb_of(const Colour *c) { RGB r = { c->r, c->g, c->b }; return r; }

/* texture_space: the texture's own space to world. */
/* A pattern that names no noise_generator takes the scene's (and keeps it
 * for the pigments in its map), and ripples and waves the scene's
 * number_of_waves. */
static void resolve_pattern_settings(Pigment *pig, const World *w)
{
    if (pig->noise_generator == 0)
        pig->noise_generator = w->noise_generator;
    pig->scene_generator = w->noise_generator;
    if (pig->nwaves == 0) /* the parser holds it to 1 .. MAX_NUMBER_OF_WAVES */
        pig->nwaves = w->number_of_waves;
}


static Finish engine_finish(const Finish *f)
{
    Finish r = *f;
    /* POV-Ray keeps 1/roughness internally; so do we. */
    r.roughness = f->roughness != 0.0 ? 1.0 / f->roughness : 0.0;
    return r;
}

/* The texture_map of tex (nmap > 0) in World.maps: its index, or -1 when
 * out of memory. Its entries that are texture_maps are built first (the
 * parser keeps them MAX_TEXTURE_MAP_DEPTH deep at most). */
static int build_map(Builder *b, const SceneTexture *tex)
{
    int found = ptr_map_get(&b->maps_built, tex->map);
    if (found >= 0)
        return found;
    World *w = b->w;
    int n = tex->nmap;
    int sub[256 + 1];
    int opaque = 1, uses_uv = 0;
    if (n > 256)
        n = 256; /* the parser's limit */
    for (int i = 0; i < n; i++) {
        const SceneTexture *e = tex->map[i].texture;
        sub[i] = -1;
        if (e->nmap > 0) {
            sub[i] = build_map(b, e);
            if (sub[i] < 0)
                return -1;
            opaque &= w->maps[sub[i]].opaque;
            uses_uv |= w->maps[sub[i]].uses_uv;
        } else {
            opaque &= pigment_is_opaque(&e->pigment);
        }
        uses_uv |= e->pigment.uv_mapping && e->pigment.kind != PIGMENT_SOLID;
    }
    if (GROW(b, maps, cap_maps, w->nmaps) || GROW(b, map_entries, cap_map_entries, w->nmap_entries + n))
        return -1;
    TextureMap *m = &w->maps[w->nmaps];
    m->first = w->nmap_entries;
    m->count = n;
    m->opaque = opaque;
    m->uses_uv = uses_uv;
    m->material_map = tex->material_map;
    for (int i = 0; i < n; i++) {
        const SceneTexture *e = tex->map[i].texture;
        MapEntry *me = &w->map_entries[w->nmap_entries++];
        memset(me, 0, sizeof *me);
        me->value = tex->map[i].value;
        me->map = sub[i];
        me->pattern = e->pigment;
        resolve_pattern_settings(&me->pattern, w);
        me->finish = engine_finish(&e->finish);
        me->normal = e->normal && e->normal->kind != NORMAL_NONE ? e->normal : NULL;
    }
    if (ptr_map_put(&b->maps_built, tex->map, w->nmaps)) {
        b->failed = 1;
        return -1;
    }
    return w->nmaps++;
}

/* Whether add_material's result depends on the texture, the interior, the
 * flags and the position alone (a solid pigment, no normal, no map: the
 * texture's space plays no part), so that equal ones make equal materials. */
static int plain_texture(const SceneTexture *tex)
{
    return tex->pigment.kind == PIGMENT_SOLID && !(tex->normal && tex->normal->kind != NORMAL_NONE) && tex->nmap == 0 &&
           !tex->below;
}

static int same_pos(SourcePos a, SourcePos b)
{
    return a.file == b.file && a.line == b.line && a.column == b.column;
}

static int add_material(Builder *b, const Inherited *in, const SceneTexture *tex, const Transform *texture_space,
                        SourcePos pos)
{
    World *w = b->w;
    const void *interior_key = in->interior ? (const void *)in->interior : in->top_object;
    const int flags[5] = { in->no_shadow, in->no_image, in->no_reflection, in->double_illuminate, in->hollow };
    /* An object made lately made the same material: share it. */
    MaterialMemo *memo = NULL;
    if (plain_texture(tex) && !in->interior_texture) {
        /* Fibonacci hashing of the parts (Knuth): the top bits mix all of them */
        const uint64_t k = 0x9E3779B97F4A7C15u;
        uint64_t h = (uint64_t)(uintptr_t)tex;
        h = (h ^ (uint64_t)(uintptr_t)interior_key) * k;
        h = (h ^ (uint64_t)(uintptr_t)pos.file) * k;
        h = (h ^ (uint64_t)(uint32_t)pos.line ^ (uint64_t)(uint32_t)pos.column << 32) * k;
        memo = &b->memo[h >> (64 - MATERIAL_MEMO_BITS)];
        if (memo->index >= 0 && tex == memo->tex && in->interior == memo->interior &&
            interior_key == memo->interior_key && memcmp(flags, memo->flags, sizeof flags) == 0 &&
            same_pos(pos, memo->pos))
            return memo->index;
    }
    /* a layered texture's lower layers first: materials of their own; and
     * the interior texture's (these with no interior texture of their own) */
    Inherited plain = *in;
    plain.interior_texture = NULL;
    int below = tex->below ? add_material(b, &plain, tex->below, texture_space, pos) : -1;
    if (tex->below && below < 0)
        return -1;
    int inside = -1;
    if (in->interior_texture &&
        (inside = add_material(b, &plain, in->interior_texture, &in->interior_texture_space, pos)) < 0)
        return -1;
    if (GROW(b, materials, cap_materials, w->nmaterials))
        return -1;
    int map = -1;
    if (tex->nmap > 0 && (map = build_map(b, tex)) < 0)
        return -1;
    Material *m = &w->materials[w->nmaterials];
    memset(m, 0, sizeof *m);
    m->map = map;
    m->below = below;
    m->inside = inside;
    m->pigment = tex->pigment.colour;
    if (tex->pigment.kind != PIGMENT_SOLID) {
        m->pattern = tex->pigment;
        resolve_pattern_settings(&m->pattern, w);
        m->pattern_to_world = tex->pigment.transform;
        if (!tex->pigment.uv_mapping) /* uv space is the surface's own: nothing moves it */
            transform_compose(&m->pattern_to_world, texture_space);
    }
    if (tex->normal && tex->normal->kind != NORMAL_NONE) {
        m->normal = tex->normal;
        m->normal_to_world = tex->normal->pattern.transform;
        if (tex->normal->kind != NORMAL_UV)
            transform_compose(&m->normal_to_world, texture_space);
    }
    m->finish = engine_finish(&tex->finish);
    Interior def = scene_default_interior();
    const Interior *it = in->interior ? in->interior : &def;
    m->interior_key = interior_key;
    m->ior = it->ior;
    m->fade_distance = it->fade_distance;
    m->fade_power = it->fade_power;
    m->fade_colour = rgb_of(&it->fade_colour);
    /* A plain texture's finish caustics replaces the interior's (POV-Ray's
     * Post_Process moves it there). */
    m->caustics = tex->nmap == 0 && tex->finish.caustics >= 0.0 ? tex->finish.caustics : it->caustics;
    m->opaque = map >= 0 ? w->maps[map].opaque : pigment_is_opaque(&tex->pigment);
    if (below >= 0) /* a layer that lets nothing through stops the shadow ray (ComputeShadowTexture) */
        m->opaque |= w->materials[below].opaque;
    if (inside >= 0) /* blocks from both sides (POV-Ray's OPAQUE_FLAG: both textures opaque) */
        m->opaque &= w->materials[inside].opaque;
    m->no_shadow = in->no_shadow;
    m->no_image = in->no_image;
    m->no_reflection = in->no_reflection;
    m->double_illuminate = in->double_illuminate;
    m->hollow = in->hollow;
    m->pos = pos;
    m->texture = tex;
    if (memo) {
        memo->index = w->nmaterials;
        memo->tex = tex;
        memo->interior = in->interior;
        memo->interior_key = interior_key;
        memcpy(memo->flags, flags, sizeof flags);
        memo->pos = pos;
    }
    return w->nmaterials++;
}

/* Picks the two axes to keep when projecting onto the plane: drop the axis
 * where the normal is largest, so the projection never degenerates. */
static void choose_axes(Polygon *p)
{
    double ax = fabs(p->normal.x), ay = fabs(p->normal.y), az = fabs(p->normal.z);
    if (ax >= ay && ax >= az) { p->axis_u = 1; p->axis_v = 2; }
    else if (ay >= az)        { p->axis_u = 0; p->axis_v = 2; }
    else                      { p->axis_u = 0; p->axis_v = 1; }
}

static void finish_polygon_bounds(World *w, Polygon *p)
{
    Vec3 lo = w->points[p->first_point], hi = lo;
    for (int i = 1; i < p->npoints; i++) {
        lo = v3_min(lo, w->points[p->first_point + i]);
        hi = v3_max(hi, w->points[p->first_point + i]);
    }
    p->bbox_min = lo;
    p->bbox_max = hi;
    w->bounds_min = v3_min(w->bounds_min, lo);
    w->bounds_max = v3_max(w->bounds_max, hi);
}

/* A polygon whose area is below this share of its size squared is a
 * line or a point up to rounding: vertices that are collinear in the scene
 * file but were rotated or scaled end up with an area of about 1e-16 of it.
 * Such a sliver can hardly be hit, and its normal, hence the side a light
 * is on and the planes of its shadow polygons, is noise: it is dropped
 * (counted in World.ndegenerate). POV-Ray keeps it unless its area is
 * exactly 0; at 1e-12 the widest one dropped is a millionth of a pixel
 * wide in any image. */
#define DEGENERATE_AREA_SHARE 1e-12

static int degenerate(Builder *b, double twice_area, double size_squared)
{
    if (twice_area > DEGENERATE_AREA_SHARE * size_squared && isfinite(twice_area))
        return 0;
    b->w->ndegenerate++;
    return 1;
}

/* Triangle a, c1, c2 as the polygon record p and its points pts[0..2]
 * (numbered from first_point), box included; 0 when it is degenerate (then
 * nothing is written). add_triangle and the parallel fill of a mesh's
 * faces (fill_faces) both make their triangles here. */
static int triangle_record(Vec3 a, Vec3 c1, Vec3 c2, int material, int first_point, Polygon *p, Vec3 *pts)
{
    Vec3 e1 = v3_sub(c1, a), e2 = v3_sub(c2, a), e3 = v3_sub(c2, c1);
    Vec3 n = v3_cross(e1, e2);
    double len = v3_length(n);
    double size_squared = fmax(v3_dot(e1, e1), fmax(v3_dot(e2, e2), v3_dot(e3, e3)));
    if (!(len > DEGENERATE_AREA_SHARE * size_squared && isfinite(len)))
        return 0;
    memset(p, 0, sizeof *p);
    p->normal = v3(n.x / len, n.y / len, n.z / len);
    p->d = v3_dot(p->normal, a);
    choose_axes(p);
    p->first_point = first_point;
    p->npoints = 3;
    p->first_outline = -1;
    p->noutlines = 1;
    p->smooth_normals = -1;
    p->uv = -1;
    p->vertex_materials = -1;
    p->material = material;
    pts[0] = a;
    pts[1] = c1;
    pts[2] = c2;
    p->bbox_min = v3_min(v3_min(a, c1), c2);
    p->bbox_max = v3_max(v3_max(a, c1), c2);
    return 1;
}

/* A triangle in world space; degenerate ones are dropped (they can hit
 * nothing and have no normal). Returns 0, or -1 on allocation failure. */
static int add_triangle(Builder *b, Vec3 a, Vec3 c1, Vec3 c2, const Vec3 *normals, int material)
{
    World *w = b->w;
    if (GROW(b, polygons, cap_polygons, w->npolygons) || GROW(b, points, cap_points, w->npoints + 3))
        return -1;
    Polygon *p = &w->polygons[w->npolygons];
    if (!triangle_record(a, c1, c2, material, w->npoints, p, &w->points[w->npoints])) {
        w->ndegenerate++;
        return 0;
    }
    w->npoints += 3;
    if (normals) {
        if (GROW(b, vertex_normals, cap_normals, w->nvertex_normals + 3))
            return -1;
        p = &w->polygons[w->npolygons];
        p->smooth_normals = w->nvertex_normals;
        for (int i = 0; i < 3; i++)
            w->vertex_normals[w->nvertex_normals++] = normals[i];
    }
    w->bounds_min = v3_min(w->bounds_min, p->bbox_min);
    w->bounds_max = v3_max(w->bounds_max, p->bbox_max);
    w->npolygons++;
    return 0;
}

/* A general polygon: `n` world points forming `noutlines` closed outlines
 * (outline k spans starts[k]..starts[k+1]). The plane normal comes from
 * Newell's method over all points, which is exact for planar input and
 * averages sensibly otherwise. */
static int add_polygon(Builder *b, const Vec3 *pts, int n, const int *starts, int noutlines, int material)
{
    World *w = b->w;
    Vec3 nrm = v3(0, 0, 0), centroid = v3(0, 0, 0);
    for (int k = 0; k < noutlines; k++) {
        for (int i = starts[k]; i < starts[k + 1]; i++) {
            int j = (i + 1 < starts[k + 1]) ? i + 1 : starts[k];
            Vec3 p = pts[i], q = pts[j];
            nrm.x += (p.y - q.y) * (p.z + q.z);
            nrm.y += (p.z - q.z) * (p.x + q.x);
            nrm.z += (p.x - q.x) * (p.y + q.y);
        }
    }
    if (n < 3) {
        w->ndegenerate++;
        return 0;
    }
    Vec3 lo = pts[0], hi = pts[0];
    for (int i = 0; i < n; i++) {
        centroid = v3_add(centroid, pts[i]);
        lo = v3_min(lo, pts[i]);
        hi = v3_max(hi, pts[i]);
    }
    Vec3 diagonal = v3_sub(hi, lo);
    double len = v3_length(nrm);
    if (degenerate(b, len, v3_dot(diagonal, diagonal)))
        return 0; /* no area, nothing to hit */
    if (n == 3 && noutlines == 1)
        return add_triangle(b, pts[0], pts[1], pts[2], NULL, material);
    const int boxed = polygon_has_outline_boxes(noutlines, n);
    if (GROW(b, polygons, cap_polygons, w->npolygons) || GROW(b, points, cap_points, w->npoints + n) ||
        GROW(b, outline_start, cap_outlines, w->noutline_starts + noutlines + 1) ||
        (boxed && GROW(b, outline_box, cap_outline_boxes, w->noutline_starts + noutlines + 1)))
        return -1;
    Polygon *p = &w->polygons[w->npolygons];
    memset(p, 0, sizeof *p);
    p->normal = v3(nrm.x / len, nrm.y / len, nrm.z / len);
    p->d = v3_dot(p->normal, v3_scale(centroid, 1.0 / n));
    choose_axes(p);
    p->first_point = w->npoints;
    p->npoints = n;
    p->first_outline = w->noutline_starts;
    p->noutlines = noutlines;
    p->smooth_normals = -1;
    p->uv = -1;
    p->vertex_materials = -1;
    p->material = material;
    for (int k = 0; boxed && k < noutlines; k++) {
        OutlineBox box = { pts[starts[k]], pts[starts[k]] };
        for (int i = starts[k] + 1; i < starts[k + 1]; i++) {
            box.lo = v3_min(box.lo, pts[i]);
            box.hi = v3_max(box.hi, pts[i]);
        }
        w->outline_box[w->noutline_starts + k] = box;
    }
    for (int k = 0; k <= noutlines; k++)
        w->outline_start[w->noutline_starts++] = w->npoints + starts[k];
    memcpy(&w->points[w->npoints], pts, sizeof(Vec3) * (size_t)n);
    w->npoints += n;
    finish_polygon_bounds(w, p);
    w->npolygons++;
    return 0;
}

static int uses_uv(const World *w, int material)
{
    const Material *m = &w->materials[material];
    if (m->map >= 0 && w->maps[m->map].uses_uv)
        return 1;
    if (m->below >= 0 && uses_uv(w, m->below))
        return 1;
    if (m->inside >= 0 && uses_uv(w, m->inside))
        return 1;
    return (m->pattern.kind != PIGMENT_SOLID && m->pattern.uv_mapping) || (m->normal && m->normal->kind == NORMAL_UV);
}

/* uses_uv of a polygon's material as the builder makes it: a prototype's
 * polygons hold slots, whose materials read no uv (instance_mesh). */
static int builds_uv(const Builder *b, int material)
{
    return !b->slots && uses_uv(b->w, material);
}

/* Gives the polygon added last the uv coordinates of its first 3 points
 * (when it was added: degenerate ones are dropped). */
static int attach_uv(Builder *b, int npolygons_before, const Vec3 uv[3])
{
    World *w = b->w;
    if (w->npolygons == npolygons_before)
        return 0;
    if (GROW(b, uvs, cap_uvs, w->nuvs + 3))
        return -1;
    w->polygons[w->npolygons - 1].uv = w->nuvs;
    for (int i = 0; i < 3; i++)
        w->uvs[w->nuvs++] = uv[i];
    return 0;
}

/* A face with a texture per vertex, its three materials m[0..2]: POV-Ray
 * blends the three textures' shaded colours by the point's place in the
 * face (Mesh::Determine_Textures), which the shading and the shadow rays'
 * filter do from these (pigment.h). Kept where the three are plain
 * textures; a texture_map among them (which the parser reports) leaves
 * the face with the first vertex's. The face's own material, which says
 * whether it can let light through and holds the object's interior, is
 * the first see-through one of the three. Returns 0, or -1 on allocation
 * failure. */
static int attach_vertex_materials(Builder *b, int npolygons_before, const int m[3])
{
    World *w = b->w;
    if (w->npolygons == npolygons_before)
        return 0; /* degenerate: no face */
    for (int i = 0; i < 3; i++)
        if (w->materials[m[i]].map >= 0 || w->materials[m[i]].below >= 0 || w->materials[m[i]].inside >= 0)
            return 0;
    if (GROW(b, vertex_materials, cap_vertex_materials, w->nvertex_materials + 3))
        return -1;
    Polygon *p = &w->polygons[w->npolygons - 1];
    p->vertex_materials = w->nvertex_materials;
    for (int i = 0; i < 3; i++) {
        w->vertex_materials[w->nvertex_materials++] = m[i];
        if (w->materials[p->material].opaque && !w->materials[m[i]].opaque)
            p->material = m[i];
    }
    return 0;
}

static int flatten_polygon(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    int n = o->u.polygon.npoints, no = o->u.polygon.noutlines;
    Vec3 *pts = malloc(sizeof(Vec3) * (size_t)(n > 0 ? n : 1));
    int *starts = malloc(sizeof(int) * (size_t)(no + 1));
    if (!pts || !starts) {
        free(pts);
        free(starts);
        b->failed = 1;
        return -1;
    }
    /* Outlines arrive closed (last point repeats the first); the inside test
     * walks edges cyclically, so the repeat is dropped here. */
    int m = 0;
    for (int k = 0; k < no; k++) {
        int s = o->u.polygon.outline_start[k], e = o->u.polygon.outline_start[k + 1];
        starts[k] = m;
        for (int i = s; i < e; i++) {
            Vec3 q = o->u.polygon.points[i];
            if (i == e - 1 && e - s > 1) {
                Vec3 f = o->u.polygon.points[s];
                if (q.x == f.x && q.y == f.y && q.z == f.z)
                    continue;
            }
            pts[m++] = transform_point(&in->transform, q);
        }
    }
    starts[no] = m;
    int rc = add_polygon(b, pts, m, starts, no, material);
    free(pts);
    free(starts);
    return rc;
}

/* POV-Ray's uv mapping of a box (Box::UVCoord): the unfolded cube, each
 * face in its own cell of a 4 x 3 grid, from the corner's place in the box
 * (0 or 1 along each axis). Face order as flatten_box's: x lo, x hi, y lo,
 * y hi, z lo, z hi. */
static Vec3 box_corner_uv(int corner, int face)
{
    double x = corner & 1 ? 1.0 : 0.0, y = corner & 2 ? 1.0 : 0.0, z = corner & 4 ? 1.0 : 0.0;
    switch (face) {
    case 0: return v3(z / 4.0, 1.0 / 3.0 + y / 3.0, 0);
    case 1: return v3(3.0 / 4.0 - z / 4.0, 1.0 / 3.0 + y / 3.0, 0);
    case 2: return v3(1.0 / 4.0 + x / 4.0, z / 3.0, 0);
    case 3: return v3(1.0 / 4.0 + x / 4.0, 3.0 / 3.0 - z / 3.0, 0);
    case 4: return v3(1.0 - x / 4.0, 1.0 / 3.0 + y / 3.0, 0);
    default: return v3(1.0 / 4.0 + x / 4.0, 1.0 / 3.0 + y / 3.0, 0);
    }
}

static int flatten_box(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Vec3 lo = v3_min(o->u.box.corner1, o->u.box.corner2);
    Vec3 hi = v3_max(o->u.box.corner1, o->u.box.corner2);
    Vec3 c[8];
    for (int i = 0; i < 8; i++)
        c[i] = transform_point(&in->transform, v3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z));
    static const int faces[6][4] = {
        { 0, 2, 6, 4 }, { 1, 5, 7, 3 }, /* x = lo, x = hi */
        { 0, 4, 5, 1 }, { 2, 3, 7, 6 }, /* y = lo, y = hi */
        { 0, 1, 3, 2 }, { 4, 6, 7, 5 }, /* z = lo, z = hi */
    };
    int uv_mapped = uses_uv(b->w, material);
    for (int f = 0; f < 6; f++) {
        Vec3 q[4] = { c[faces[f][0]], c[faces[f][1]], c[faces[f][2]], c[faces[f][3]] };
        int starts[2] = { 0, 4 };
        int before = b->w->npolygons;
        if (add_polygon(b, q, 4, starts, 1, material))
            return -1;
        if (uv_mapped) {
            Vec3 uv[3];
            for (int k = 0; k < 3; k++)
                uv[k] = box_corner_uv(faces[f][k], f);
            if (attach_uv(b, before, uv))
                return -1;
        }
    }
    return 0;
}

/* A surface normal carried to world space (inverse transpose), not
 * normalised: interpolating these and normalising afterwards equals
 * interpolating in object space and transforming, which is what POV-Ray's
 * meshes do. */
static Vec3 world_normal(const Inherited *in, Vec3 n)
{
    return transform_normal(&in->transform, n);
}

/* POV-Ray drops a smooth_triangle whose vertex normals are not all strictly
 * on one side of its face (SmoothTriangle::Compute_Smooth_Triangle marks it
 * degenerate, so it is never hit). Checked in object space, as POV-Ray does. */
static int smooth_normals_consistent(const Vec3 v[3], const Vec3 n[3])
{
    Vec3 face = v3_cross(v3_sub(v[0], v[1]), v3_sub(v[2], v[1]));
    double d0 = v3_dot(face, n[0]), d1 = v3_dot(face, n[1]), d2 = v3_dot(face, n[2]);
    return (d0 > 0 && d1 > 0 && d2 > 0) || (d0 < 0 && d1 < 0 && d2 < 0);
}

static int flatten_triangle(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Vec3 v[3], n[3];
    int smooth = o->u.triangle.has_normals;
    if (smooth) {
        for (int i = 0; i < 3; i++)
            if (v3_length(o->u.triangle.n[i]) == 0.0)
                return 0; /* degenerate in POV-Ray too */
        if (!smooth_normals_consistent(o->u.triangle.v, o->u.triangle.n))
            return 0;
    }
    for (int i = 0; i < 3; i++) {
        v[i] = transform_point(&in->transform, o->u.triangle.v[i]);
        /* smooth_triangle normals are transformed and normalised at parse
         * time in POV-Ray, before any interpolation. */
        n[i] = v3_normalize(world_normal(in, v3_normalize(o->u.triangle.n[i])));
    }
    return add_triangle(b, v[0], v[1], v[2], smooth ? n : NULL, material);
}

/* ---- a big mesh's flat faces, on several threads ------------------------ */

/* A run of faces [first, end) of a mesh whose faces are all flat and need
 * no uv: face f's triangle goes to polygon slot base + f and its points to
 * point slot 3 (base_points + f), made by triangle_record as add_triangle
 * makes it; a face that makes none (degenerate, or a bad index) leaves its
 * slot empty (npoints 0) and fill_faces closes the gaps afterwards, so the
 * world is the one add_triangle, face by face, builds. */
typedef struct {
    World *w;
    const SceneObject *o;
    const Inherited *in;
    const int *face_material;
    int material, base, base_points;
    int first, end;
    int made, degenerate;
    Vec3 lo, hi;          /* the union of the boxes made, in face order */
} FaceRun;

static void *fill_face_run(void *arg)
{
    FaceRun *r = arg;
    World *w = r->w;
    const SceneObject *o = r->o;
    const int nt = o->u.mesh.ntextures;
    r->lo = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
    r->hi = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
    for (int f = r->first; f < r->end; f++) {
        const MeshFace *face = &o->u.mesh.faces[f];
        Polygon *p = &w->polygons[r->base + f];
        int first_point = r->base_points + 3 * f;
        Vec3 v[3];
        int bad = 0;
        for (int i = 0; i < 3 && !bad; i++) {
            int vi = face->v[i];
            bad = vi < 0 || vi >= o->u.mesh.nvertices;
            if (!bad)
                v[i] = transform_point(&r->in->transform, o->u.mesh.vertices[vi]);
        }
        int m = (face->texture >= 0 && face->texture < nt) ? r->face_material[face->texture] : r->material;
        if (bad || !triangle_record(v[0], v[1], v[2], m, first_point, p, &w->points[first_point])) {
            p->npoints = 0; /* a gap */
            r->degenerate += !bad;
            continue;
        }
        r->lo = v3_min(r->lo, p->bbox_min);
        r->hi = v3_max(r->hi, p->bbox_max);
        r->made++;
    }
    return NULL;
}

/* Faces per thread, at least: below, a thread's start costs more. */
#define FACES_PER_THREAD_MIN 50000

/* Whether fill_faces may make the mesh's triangles: more than one thread
 * to be had and work for them, no smooth normals, and no material of its
 * faces reading uv coordinates (both are added face by face). */
static int faces_fill_in_parallel(const Builder *b, const SceneObject *o, int material, const int *face_material)
{
    if (b->threads < 2 || o->u.mesh.nfaces < 2 * FACES_PER_THREAD_MIN || o->u.mesh.nnormals > 0 ||
        builds_uv(b, material))
        return 0;
    for (int i = 0; i < o->u.mesh.ntextures; i++)
        if (builds_uv(b, face_material[i]))
            return 0;
    for (int f = 0; f < o->u.mesh.nfaces; f++)
        if (o->u.mesh.faces[f].texture2 >= 0)
            return 0; /* a texture per vertex: attach_vertex_materials, face by face */
    return 1;
}

/* The mesh's faces as triangles, in runs on b->threads threads (room for
 * them all is there already): the same polygons, points, count of
 * degenerate faces and bounds as add_triangle face by face. */
static void fill_faces(Builder *b, const SceneObject *o, const Inherited *in, int material, const int *face_material)
{
    World *w = b->w;
    const int nf = o->u.mesh.nfaces;
    FaceRun runs[PARALLEL_MAX_JOBS];
    int nr = parallel_jobs(nf, FACES_PER_THREAD_MIN, b->threads);
    for (int k = 0; k < nr; k++)
        runs[k] = (FaceRun){ .w = w, .o = o, .in = in, .face_material = face_material, .material = material,
                             .base = w->npolygons, .base_points = w->npoints, .first = (int)((long long)nf * k / nr),
                             .end = (int)((long long)nf * (k + 1) / nr) };
    parallel_run(nr, fill_face_run, runs, sizeof runs[0]);
    int made = 0;
    for (int k = 0; k < nr; k++) {
        made += runs[k].made;
        w->ndegenerate += runs[k].degenerate;
        if (runs[k].made) {
            w->bounds_min = v3_min(w->bounds_min, runs[k].lo);
            w->bounds_max = v3_max(w->bounds_max, runs[k].hi);
        }
    }
    /* The gaps closed, in order: rare (a degenerate face), so on one thread. */
    if (made < nf) {
        int to = w->npolygons;
        for (int f = 0; f < nf; f++) {
            const Polygon *p = &w->polygons[w->npolygons + f];
            if (p->npoints == 0)
                continue;
            int first_point = w->npoints + 3 * (to - w->npolygons);
            memmove(&w->points[first_point], &w->points[p->first_point], 3 * sizeof *w->points);
            /* moved as bytes, padding included, as add_triangle leaves it */
            memmove(&w->polygons[to], p, sizeof *p);
            w->polygons[to++].first_point = first_point;
        }
    }
    w->npolygons += made;
    w->npoints += 3 * made;
}

/* The materials of a mesh's own textures (face_material[i] for texture i;
 * the object's where it has none), malloc'd: *out NULL when it has none.
 * Returns 0, or -1 on failure. */
static int mesh_face_materials(Builder *b, const SceneObject *o, const Inherited *in, int material, int **out)
{
    const int nt = o->u.mesh.ntextures;
    *out = NULL;
    if (nt == 0)
        return 0;
    int *face_material = malloc(sizeof(int) * (size_t)nt);
    if (!face_material) {
        b->failed = 1;
        return -1;
    }
    for (int i = 0; i < nt; i++) {
        const SceneTexture *t = o->u.mesh.textures[i];
        /* face textures are written before the mesh's transforms: they all move them */
        face_material[i] = t ? add_material(b, in, t, &in->transform, o->pos) : material;
        if (face_material[i] < 0) {
            free(face_material);
            return -1;
        }
    }
    *out = face_material;
    return 0;
}

/* The mesh's faces as polygons, face textures to face_material (NULL: none). */
static int flatten_mesh_faces(Builder *b, const SceneObject *o, const Inherited *in, int material,
                              const int *face_material)
{
    const int nt = o->u.mesh.ntextures;
    /* Room for every face at once (rather than by doublings, each copying
     * what is there): a big mesh is most of the world. */
    int rc = 0;
    World *w = b->w;
    if (o->u.mesh.nfaces > 0 &&
        (GROW(b, polygons, cap_polygons, w->npolygons + o->u.mesh.nfaces - 1) ||
         GROW(b, points, cap_points, w->npoints + 3 * o->u.mesh.nfaces - 1)))
        rc = -1;
    if (rc == 0 && faces_fill_in_parallel(b, o, material, face_material)) {
        fill_faces(b, o, in, material, face_material);
        return 0;
    }
    for (int f = 0; f < o->u.mesh.nfaces && rc == 0; f++) {
        const MeshFace *face = &o->u.mesh.faces[f];
        Vec3 v[3], on[3], n[3];
        int smooth = 1, bad = 0;
        for (int i = 0; i < 3; i++) {
            int vi = face->v[i];
            if (vi < 0 || vi >= o->u.mesh.nvertices) {
                bad = 1;
                break;
            }
            v[i] = transform_point(&in->transform, o->u.mesh.vertices[vi]);
            int ni = face->n[i];
            if (ni < 0 || ni >= o->u.mesh.nnormals)
                smooth = 0;
            else
                on[i] = v3_normalize(o->u.mesh.normals[ni]);
        }
        if (bad)
            continue; /* the parser rejects bad indices; be safe anyway */
        if (smooth) {
            /* Three equal normals make a flat triangle in POV-Ray (the face
             * normal is used, not the given one). */
            Vec3 d1 = v3_sub(on[0], on[1]), d2 = v3_sub(on[0], on[2]);
            if (v3_dot(d1, d1) <= POV_EPSILON && v3_dot(d2, d2) <= POV_EPSILON)
                smooth = 0;
            for (int i = 0; i < 3; i++)
                n[i] = world_normal(in, on[i]);
        }
        int m = (face->texture >= 0 && face->texture < nt) ? face_material[face->texture] : material;
        int before = b->w->npolygons;
        rc = add_triangle(b, v[0], v[1], v[2], smooth ? n : NULL, m);
        int needs_uv = builds_uv(b, m);
        if (rc == 0 && face->texture >= 0 && face->texture2 >= 0 && face->texture2 < nt && face->texture3 >= 0 &&
            face->texture3 < nt) {
            const int vm[3] = { m, face_material[face->texture2], face_material[face->texture3] };
            needs_uv |= builds_uv(b, vm[1]) || builds_uv(b, vm[2]);
            rc = attach_vertex_materials(b, before, vm);
        }
        if (rc == 0 && needs_uv) {
            Vec3 uv[3];
            for (int i = 0; i < 3; i++) {
                int k = face->uv[i];
                uv[i] = k >= 0 && k < o->u.mesh.nuvs ? o->u.mesh.uvs[k] : v3(0, 0, 0); /* POV-Ray's default */
            }
            rc = attach_uv(b, before, uv);
        }
    }
    return rc;
}

static int flatten_mesh(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    int *face_material;
    if (mesh_face_materials(b, o, in, material, &face_material))
        return -1;
    int rc = flatten_mesh_faces(b, o, in, material, face_material);
    free(face_material);
    return rc;
}

static int flatten_plane(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    World *w = b->w;
    Vec3 n = o->u.plane.normal;
    double len = v3_length(n);
    if (!(len > 0.0))
        return 0;
    /* POV-Ray normalises the normal but not the distance: the plane is
     * dot(n/|n|, p) == distance. A point on it and its normal go to world space. */
    Vec3 p = v3_scale(v3_scale(n, 1.0 / len), o->u.plane.distance);
    Vec3 wp = transform_point(&in->transform, p);
    Vec3 wn = v3_normalize(transform_normal(&in->transform, n));
    if (GROW(b, planes, cap_planes, w->nplanes))
        return -1;
    InfinitePlane *pl = &w->planes[w->nplanes++];
    pl->normal = wn;
    pl->d = v3_dot(wn, wp);
    pl->material = material;
    return 0;
}

static void shape_placed(Builder *b, Shape *s);

/* A new shape: one of the world's, or inside a CSG object one of the
 * parts. */
static Shape *new_shape(Builder *b, ShapeKind kind)
{
    World *w = b->w;
    Shape *s;
    if (b->csg_depth > 0) {
        if (grow((void **)&b->parts, &b->cap_parts, b->nparts, sizeof *b->parts)) {
            b->failed = 1;
            return NULL;
        }
        s = &b->parts[b->nparts++];
    } else {
        if (GROW(b, shapes, cap_shapes, w->nshapes))
            return NULL;
        s = &w->shapes[w->nshapes++];
    }
    memset(s, 0, sizeof *s);
    s->kind = kind;
    s->is_part = b->csg_depth > 0;
    s->subtree = 1;
    /* the most surfaces of it a line crosses */
    s->max_hits = kind == SHAPE_SPHERE ? 2 : kind == SHAPE_DISC ? 1 : 4;
    return s;
}

/* A sphere as POV-Ray keeps it: while every transform on the way to world
 * is a translation, rotation or uniform scale, its centre and radius are
 * moved (Sphere::Translate, Rotate, Scale); after any other, it is an
 * ellipsoid: the sphere as written, reached through its transform. */
static int flatten_sphere(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = new_shape(b, SHAPE_SPHERE);
    if (!s)
        return -1;
    s->material = material;
    s->inverse = in->inverse;
    s->to_world = in->transform;
    s->transformed = in->general_transform || !transform_is_similarity(&in->transform);
    s->u.sphere.own_center = o->u.sphere.center;
    if (s->transformed) {
        s->u.sphere.center = o->u.sphere.center;
        s->u.sphere.radius = o->u.sphere.radius;
    } else {
        s->u.sphere.center = transform_point(&in->transform, o->u.sphere.center);
        s->u.sphere.radius = o->u.sphere.radius * transform_similarity_scale(&in->transform);
    }
    shape_placed(b, s);
    return 0;
}

/* A new shape of the world, placed by `frame` (its own space to the
 * object's), then by the object's transforms. */
static Shape *add_shape(Builder *b, ShapeKind kind, const Inherited *in, const Transform *frame, int material)
{
    Shape *s = new_shape(b, kind);
    if (!s)
        return NULL;
    s->material = material;
    s->inverse = in->inverse;
    s->transformed = 1;
    s->to_world = *frame;
    transform_compose(&s->to_world, &in->transform);
    return s;
}

/* A shape whose parameters are kept in its own space, reached through the
 * transforms alone (no frame of its own before them). */
static Shape *add_shape_own_space(Builder *b, ShapeKind kind, const Inherited *in, int material)
{
    Transform frame;
    transform_identity(&frame);
    return add_shape(b, kind, in, &frame, material);
}

static void shape_placed(Builder *b, Shape *s)
{
    shape_compute_bounds(s);
    /* The world's box holds the hierarchy's shapes: a part lies within its
     * CSG object's box, and a CSG object of half-spaces without bounds is
     * left out as an infinite plane is. */
    if (b->csg_depth > 0 || !(isfinite(s->bbox_min.x) && isfinite(s->bbox_min.y) && isfinite(s->bbox_min.z) &&
                              isfinite(s->bbox_max.x) && isfinite(s->bbox_max.y) && isfinite(s->bbox_max.z)))
        return;
    b->w->bounds_min = v3_min(b->w->bounds_min, s->bbox_min);
    b->w->bounds_max = v3_max(b->w->bounds_max, s->bbox_max);
}

/* A disc: the unit disc of its own frame (Disc::Compute_Disc), its
 * normal carried through every transform (Disc::Transform). */
static int flatten_disc(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Transform frame;
    transform_coordinate_frame(&frame, o->u.disc.center, o->u.disc.normal, 1.0, 1.0);
    Shape *s = add_shape(b, SHAPE_DISC, in, &frame, material);
    if (!s)
        return -1;
    s->u.disc.outer2 = o->u.disc.radius * o->u.disc.radius;
    s->u.disc.inner2 = o->u.disc.hole * o->u.disc.hole;
    s->u.disc.normal = v3_normalize(transform_normal(&in->transform, o->u.disc.normal));
    shape_placed(b, s);
    return 0;
}

/* A cone or cylinder in POV-Ray's canonical space (Compute_Cone_Data,
 * Compute_Cylinder_Data): the wider end at z = 1; ends of radii within
 * EPSILON, or a cone too slender to tell from one, make a cylinder. */
static int flatten_cone(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Transform frame;
    double dist;
    int cylinder = transform_cone_frame(&frame, o->u.cone.base, o->u.cone.base_radius, o->u.cone.apex,
                                        o->u.cone.apex_radius, &dist); /* the parser refused a degenerate one */
    Shape *s = add_shape(b, SHAPE_CONE, in, &frame, material);
    if (!s)
        return -1;
    s->u.cone.cylinder = cylinder;
    s->u.cone.closed = !o->u.cone.open;
    s->u.cone.dist = dist;
    shape_placed(b, s);
    return 0;
}

/* A torus about its own y axis, carried by every transform (POV-Ray's
 * Torus keeps its radii and a transform). */
static int flatten_torus(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = add_shape_own_space(b, SHAPE_TORUS, in, material);
    if (!s)
        return -1;
    s->u.torus.major = o->u.torus.major;
    s->u.torus.minor = o->u.torus.minor;
    s->u.torus.sturm = o->sturm;
    shape_placed(b, s);
    return 0;
}

/* A glyph of a text object (text.h), placed by its transforms (POV-Ray's
 * TrueType keeps its outline and a transform). */
static int flatten_glyph(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = add_shape_own_space(b, SHAPE_GLYPH, in, material);
    if (!s)
        return -1;
    s->u.glyph.glyph = o->u.glyph.glyph;
    s->u.glyph.depth = o->u.glyph.depth;
    s->max_hits = glyph_max_hits(o->u.glyph.glyph);
    if (s->max_hits > SHAPE_MAX_HITS) {
        snprintf(b->message, sizeof b->message,
                 "a glyph of this text has up to %d surfaces along a line; hstrace takes %d at most", s->max_hits,
                 SHAPE_MAX_HITS);
        return -1;
    }
    shape_placed(b, s);
    return 0;
}

/* A blob, in its own space, carried by every transform (Blob::Transform
 * makes it a transformed one at the first). */
static int flatten_blob(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    World *w = b->w;
    struct Blob **list = realloc(w->blobs, sizeof *list * (size_t)(w->nblobs + 1));
    if (!list) {
        b->failed = 1;
        return -1;
    }
    w->blobs = list;
    struct Blob *blob = blob_make(o->u.blob.components, o->u.blob.ncomponents, o->u.blob.threshold);
    if (!blob) {
        b->failed = 1;
        return -1;
    }
    w->blobs[w->nblobs++] = blob;
    Shape *s = add_shape_own_space(b, SHAPE_BLOB, in, material);
    if (!s)
        return -1;
    s->u.blob.blob = blob;
    s->u.blob.sturm = o->sturm;
    /* up to four crossings in each interval between two of its
     * components' boundaries */
    long most = 8L * blob->nelements;
    s->max_hits = most < SHAPE_MAX_HITS ? (int)most : SHAPE_MAX_HITS;
    shape_placed(b, s);
    return 0;
}

/* A quadric: its coefficients carried to world space by every transform
 * (quadric.h). */
static int flatten_quadric(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = new_shape(b, SHAPE_QUADRIC);
    if (!s)
        return -1;
    s->material = material;
    s->inverse = in->inverse;
    s->max_hits = 2;
    quadric_place(s, o->u.quadric.square, o->u.quadric.mixed, o->u.quadric.terms, o->u.quadric.constant,
                  &in->transform, in->inverse);
    shape_placed(b, s);
    return 0;
}

/* A poly, cubic or quartic in its own space, reached through every
 * transform (Poly keeps a Trans). */
static int flatten_poly(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = add_shape_own_space(b, SHAPE_POLY, in, material);
    if (!s)
        return -1;
    s->max_hits = o->u.poly.order;
    s->u.poly.order = o->u.poly.order;
    s->u.poly.coeffs = o->u.poly.coeffs;
    s->u.poly.sturm = o->sturm;
    shape_placed(b, s);
    return 0;
}

/* A superellipsoid in its own space, reached through every transform. */
static int flatten_superellipsoid(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = add_shape_own_space(b, SHAPE_SUPERELLIPSOID, in, material);
    if (!s)
        return -1;
    s->max_hits = 2 + 9; /* a crossing per piece of the ray at most (its box's two ends, nine planes) */
    s->u.superellipsoid.ex = 2.0 / o->u.superellipsoid.e;
    s->u.superellipsoid.ez = 2.0 / o->u.superellipsoid.n;
    shape_placed(b, s);
    return 0;
}

/* A lathe in its own space, reached through every transform; its
 * bounding cylinder from its segments (lathe.h). */
static int flatten_lathe(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = add_shape_own_space(b, SHAPE_LATHE, in, material);
    if (!s)
        return -1;
    s->u.lathe.spline = (int)o->u.lathe.spline;
    s->u.lathe.nsegments = o->u.lathe.nsegments;
    s->u.lathe.segments = o->u.lathe.segments;
    s->u.lathe.sturm = o->sturm;
    /* a root of the segment's polynomial per crossing: its degree */
    const int roots = o->u.lathe.spline == SPLINE_LINEAR ? 2 : o->u.lathe.spline == SPLINE_QUADRATIC ? 4 : 6;
    const int most = SHAPE_NUMERIC_MAX_HITS;
    s->max_hits = o->u.lathe.nsegments > most / roots ? most : roots * o->u.lathe.nsegments;
    lathe_place(s);
    shape_placed(b, s);
    return 0;
}

/* A sor in its own space, reached through every transform (sor.h). */
static int flatten_sor(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = add_shape_own_space(b, SHAPE_SOR, in, material);
    if (!s)
        return -1;
    s->u.sor.nsegments = o->u.sor.nsegments;
    s->u.sor.segments = o->u.sor.segments;
    s->u.sor.open = o->u.sor.open;
    s->u.sor.sturm = o->sturm;
    /* three crossings per segment's cubic, and the two discs */
    const int most = SHAPE_NUMERIC_MAX_HITS;
    s->max_hits = o->u.sor.nsegments > (most - 2) / 3 ? most : 3 * o->u.sor.nsegments + 2;
    sor_place(s);
    shape_placed(b, s);
    return 0;
}

/* A prism in its own space, reached through every transform (prism.h). */
static int flatten_prism(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = add_shape_own_space(b, SHAPE_PRISM, in, material);
    if (!s)
        return -1;
    s->u.prism.spline = (int)o->u.prism.spline;
    s->u.prism.conic = o->u.prism.sweep == PRISM_CONIC_SWEEP;
    s->u.prism.nsegments = o->u.prism.nsegments;
    s->u.prism.segments = o->u.prism.segments;
    s->u.prism.height1 = o->u.prism.height1;
    s->u.prism.height2 = o->u.prism.height2;
    s->u.prism.u1 = o->u.prism.u1;
    s->u.prism.u2 = o->u.prism.u2;
    s->u.prism.v1 = o->u.prism.v1;
    s->u.prism.v2 = o->u.prism.v2;
    s->u.prism.x1 = o->u.prism.x1;
    s->u.prism.x2 = o->u.prism.x2;
    s->u.prism.y1 = o->u.prism.y1;
    s->u.prism.y2 = o->u.prism.y2;
    s->u.prism.open = o->u.prism.open;
    s->u.prism.degenerate = o->u.prism.degenerate;
    s->u.prism.sturm = o->sturm;
    /* a root of the segment's equation per crossing (its degree), and
     * the two caps */
    const int roots = o->u.prism.spline == SPLINE_LINEAR ? 1 : o->u.prism.spline == SPLINE_QUADRATIC ? 2 : 3;
    const int most = SHAPE_NUMERIC_MAX_HITS;
    s->max_hits = o->u.prism.nsegments > (most - 2) / roots ? most : roots * o->u.prism.nsegments + 2;
    shape_placed(b, s);
    return 0;
}

static int flatten_object(Builder *b, const SceneObject *o, const Inherited *parent, const Scene *scene, int depth);

/* A box as a part of a CSG object (shape.h): POV-Ray's corners, sorted
 * (Parse_Box), moved and scaled with it while no transform on the way
 * turns or shears it, else reached through its transform. */
static int flatten_box_part(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Shape *s = new_shape(b, SHAPE_BOX);
    if (!s)
        return -1;
    s->material = material;
    s->inverse = in->inverse;
    s->max_hits = 2;
    s->to_world = in->transform;
    Vec3 lo = v3_min(o->u.box.corner1, o->u.box.corner2), hi = v3_max(o->u.box.corner1, o->u.box.corner2);
    const double (*m)[4] = in->transform.m;
    int axis_aligned = m[0][1] == 0.0 && m[0][2] == 0.0 && m[1][0] == 0.0 && m[1][2] == 0.0 && m[2][0] == 0.0 &&
                       m[2][1] == 0.0;
    s->transformed = !axis_aligned;
    if (axis_aligned) {
        Vec3 a = transform_point(&in->transform, lo), c = transform_point(&in->transform, hi);
        lo = v3_min(a, c);
        hi = v3_max(a, c);
    }
    s->u.box.lo = lo;
    s->u.box.hi = hi;
    shape_placed(b, s);
    return 0;
}

/* A plane as a part of a CSG object: its solid the half-space below it
 * (Plane::Inside), the normal and distance carried through translations,
 * rotations and scales as POV-Ray's Plane keeps them, a matrix or
 * transform { } kept as its transform; inverse negates both. */
static int flatten_plane_part(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    Vec3 n = o->u.plane.normal;
    double len = v3_length(n);
    if (!(len > 0.0))
        return 0;
    Shape *s = new_shape(b, SHAPE_PLANE);
    if (!s)
        return -1;
    s->material = material;
    s->inverse = in->inverse;
    s->max_hits = 1;
    s->to_world = in->transform;
    n = v3_scale(n, 1.0 / len);
    double distance = -o->u.plane.distance;
    s->transformed = in->general_transform;
    if (!s->transformed) {
        Vec3 on = transform_point(&in->transform, v3_scale(n, -distance));
        n = v3_normalize(transform_normal(&in->transform, n));
        distance = -v3_dot(on, n);
    }
    if (in->inverse) {
        n = v3_neg(n);
        distance = -distance;
    }
    s->u.plane.normal = n;
    s->u.plane.distance = distance;
    shape_placed(b, s);
    return 0;
}

/* A CSG object's node: one of the world's shapes, or of the parts inside
 * another; its parts are made next (csg_depth raised). */
static Shape *begin_csg(Builder *b, CsgOp op, const Inherited *in, int material, int nparts, int *index)
{
    const int top = b->csg_depth == 0;
    Shape *s = new_shape(b, SHAPE_CSG);
    if (!s)
        return NULL;
    *index = top ? b->w->nshapes - 1 : b->nparts - 1;
    s->material = material;
    s->inverse = in->inverse;
    s->u.csg.op = op;
    s->u.csg.nparts = nparts;
    s->u.csg.first_part = b->nparts;
    return s;
}

/* The CSG object at `index` once its parts are made: how far its parts
 * reach, how many crossings it can have, its box. */
static int finish_csg(Builder *b, int top, int index, int first)
{
    Shape *s = top ? &b->w->shapes[index] : &b->parts[index];
    if (!top)
        s->subtree = b->nparts - index;
    /* its parts, where they are while building (set again once final) */
    s->u.csg.parts = b->parts + first;
    int max_hits = 0;
    const Shape *c = s->u.csg.parts;
    /* a clipped object's crossings are its first part's alone */
    const int crossed = s->u.csg.op == CSG_CLIP || s->u.csg.op == CSG_BOUND ? 1 : s->u.csg.nparts;
    for (int k = 0; k < crossed; k++, c += c->subtree)
        max_hits += c->max_hits;
    if (max_hits > SHAPE_MAX_HITS) {
        snprintf(b->message, sizeof b->message,
                 "this CSG object's parts have up to %d surfaces along a line; hstrace takes %d at most", max_hits,
                 SHAPE_MAX_HITS);
        return -1;
    }
    s->max_hits = max_hits;
    shape_placed(b, s);
    return 0;
}

/* A CSG object (csg.h) and, after it, its parts; a part is any shape or
 * CSG object (the parser refuses other kinds), made with what it inherits
 * from the CSG object as a union's children are. POV-Ray's rewriting is
 * done here: a difference's later parts inverted, an inverted CSG object
 * the other operation over its inverted parts (in->inverse, passed down). */
static int flatten_csg(Builder *b, const SceneObject *o, const Inherited *in, const Scene *scene, int depth,
                       int material)
{
    CsgOp op = o->kind == OBJ_MERGE ? CSG_MERGE : o->kind == OBJ_UNION ? CSG_UNION : CSG_INTERSECTION;
    if (in->inverse) /* POV-Ray's CSGUnion::Invert, CSGIntersection::Invert */
        op = op == CSG_INTERSECTION ? CSG_MERGE : CSG_INTERSECTION;
    const int top = b->csg_depth == 0;
    int index;
    if (!begin_csg(b, op, in, material, o->u.csg.nchildren, &index))
        return -1;
    const int first = b->nparts; /* its parts follow it */
    b->csg_depth++;
    for (int i = 0; i < o->u.csg.nchildren; i++) {
        Inherited part = *in;
        if (o->kind == OBJ_DIFFERENCE && i > 0)
            part.inverse ^= 1; /* taken away: inverted, then intersected */
        if (flatten_object(b, o->u.csg.children[i], &part, scene, depth + 1)) {
            b->csg_depth--;
            return -1;
        }
    }
    b->csg_depth--;
    return finish_csg(b, top, index, first);
}

static int flatten_kind(Builder *b, const SceneObject *o, const Inherited *in, const Scene *scene, int depth);

/* An object clipped_by solids (SceneObject.clips): a CSG_CLIP node, the
 * object its first part, the clipping solids the others. A clip is not
 * inverted with the object (POV-Ray's Invert leaves Clip alone) and takes
 * nothing else of it but its place. */
static int flatten_clipped(Builder *b, const SceneObject *o, const Inherited *in, const Scene *scene, int depth)
{
    const SceneTexture *tex = in->texture ? in->texture : &scene->default_texture;
    int material = add_material(b, in, tex, &in->texture_space, o->pos);
    if (material < 0)
        return -1;
    const int top = b->csg_depth == 0;
    int index;
    if (!begin_csg(b, CSG_CLIP, in, material, 1 + o->nclips, &index))
        return -1;
    const int first = b->nparts; /* its parts follow it */
    b->csg_depth++;
    int failed = flatten_kind(b, o, in, scene, depth);
    for (int i = 0; !failed && i < o->nclips; i++) {
        Inherited clip = *in;
        clip.inverse = 0;
        failed = flatten_object(b, o->clips[i], &clip, scene, depth + 1);
    }
    b->csg_depth--;
    return failed ? -1 : finish_csg(b, top, index, first);
}

/* Does POV-Ray keep o's bounded_by for its tests? It removes the bound of
 * an object cheap to intersect (Post_Process); of the objects hstrace
 * reads it keeps a poly's, and a quadric's where Compute_BBox found no
 * bounds of its own (quadric.h). */
static int bound_kept(const SceneObject *o)
{
    if (o->nbounds == 0)
        return 0;
    if (o->kind == OBJ_POLY)
        return 1;
    if (o->kind == OBJ_QUADRIC)
        return !quadric_automatic_bounds(o->u.quadric.square, o->u.quadric.mixed, o->u.quadric.terms,
                                         o->u.quadric.constant);
    return 0;
}

/* An object bounded_by solids POV-Ray keeps (csg.h's CSG_BOUND): the
 * object, clipped if it is, as the first part, its bounding solids
 * (placed as clips are, never inverted with it) after. */
static int flatten_bounded(Builder *b, const SceneObject *o, const Inherited *in, const Scene *scene, int depth)
{
    const SceneTexture *tex = in->texture ? in->texture : &scene->default_texture;
    int material = add_material(b, in, tex, &in->texture_space, o->pos);
    if (material < 0)
        return -1;
    const int top = b->csg_depth == 0;
    int index;
    if (!begin_csg(b, CSG_BOUND, in, material, 1 + o->nbounds, &index))
        return -1;
    const int first = b->nparts;
    b->csg_depth++;
    int failed = o->nclips > 0 ? flatten_clipped(b, o, in, scene, depth) : flatten_kind(b, o, in, scene, depth);
    for (int i = 0; !failed && i < o->nbounds; i++) {
        Inherited bound = *in;
        bound.inverse = 0;
        failed = flatten_object(b, o->bounds[i], &bound, scene, depth + 1);
    }
    b->csg_depth--;
    return failed ? -1 : finish_csg(b, top, index, first);
}

/* ---- instancing: a mesh placed two or more times, kept once ------------- */

/* The fewest faces a shared mesh is instanced with: below, its polygons
 * flattened cost less than an instance's transform, box and second walk. */
#define INSTANCE_MIN_FACES 8


/* Counts the placements of every mesh under o (the copies of a declared
 * mesh, or of a union holding it, share its face array). */
static int count_mesh_uses(Builder *b, const SceneObject *o, int depth)
{
    if (depth > 1000)
        return 0;
    if (scene_object_has_children(o->kind)) {
        for (int i = 0; i < o->u.csg.nchildren; i++)
            if (count_mesh_uses(b, o->u.csg.children[i], depth + 1))
                return -1;
        return 0;
    }
    if (o->kind != OBJ_MESH || o->u.mesh.nfaces < INSTANCE_MIN_FACES)
        return 0;
    int placed = ptr_map_get(&b->mesh_uses, o->u.mesh.faces);
    return ptr_map_put(&b->mesh_uses, o->u.mesh.faces, placed < 0 ? 1 : placed + 1);
}

/* Mesh o placed as `in` says, as an instance of its prototype: its
 * materials made as flatten_mesh makes them (slot 0 `material`, slot
 * 1 + i its texture i's). A mesh placed once, or whose materials read uv
 * coordinates or whose faces have a texture per vertex (both kept per
 * polygon, in world-space polygons only), is flattened. */
static int instance_mesh(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    World *w = b->w;
    int *face_material;
    if (mesh_face_materials(b, o, in, material, &face_material))
        return -1;
    const int nt = o->u.mesh.ntextures;
    int shared = o->u.mesh.nfaces >= INSTANCE_MIN_FACES && ptr_map_get(&b->mesh_uses, o->u.mesh.faces) >= 2 &&
                 !uses_uv(w, material);
    for (int i = 0; shared && i < nt; i++)
        shared = !uses_uv(w, face_material[i]);
    /* a texture per vertex (World.vertex_materials) is kept per world polygon */
    for (int f = 0; shared && f < o->u.mesh.nfaces; f++)
        shared = o->u.mesh.faces[f].texture2 < 0 && o->u.mesh.faces[f].texture3 < 0;
    if (!shared) {
        int rc = flatten_mesh_faces(b, o, in, material, face_material);
        free(face_material);
        return rc;
    }
    int proto = ptr_map_get(&b->mesh_proto, o->u.mesh.faces);
    if (proto < 0) {
        if (GROW(b, prototypes, cap_prototypes, w->nprototypes)) {
            free(face_material);
            return -1;
        }
        const SceneObject **meshes = realloc(b->proto_mesh, sizeof *meshes * (size_t)(w->nprototypes + 1));
        if (!meshes) {
            free(face_material);
            b->failed = 1;
            return -1;
        }
        b->proto_mesh = meshes;
        meshes[w->nprototypes] = o;
        memset(&w->prototypes[w->nprototypes], 0, sizeof *w->prototypes);
        w->prototypes[w->nprototypes].nslots = 1 + nt;
        if (ptr_map_put(&b->mesh_proto, o->u.mesh.faces, w->nprototypes)) {
            free(face_material);
            b->failed = 1;
            return -1;
        }
        proto = w->nprototypes++;
    }
    if (GROW(b, instances, cap_instances, w->ninstances) ||
        GROW(b, instance_materials, cap_instance_materials, w->ninstance_materials + nt)) {
        free(face_material);
        return -1;
    }
    Instance *it = &w->instances[w->ninstances++];
    memset(it, 0, sizeof *it);
    it->to_world = in->transform;
    it->prototype = proto;
    it->first_material = w->ninstance_materials;
    for (int s = 0; s <= nt; s++) {
        int m = s == 0 ? material : face_material[s - 1];
        const Material *mm = &w->materials[m];
        it->hidden |= mm->no_image || mm->no_reflection || mm->no_shadow;
        w->instance_materials[w->ninstance_materials++] = m;
    }
    free(face_material);
    return 0;
}

/* The prototypes' polygons, in their own space, after the world's (which
 * npolygons then counts alone), and the instances' ids and world boxes. */
static int build_prototypes(Builder *b)
{
    World *w = b->w;
    const int nworld = w->npolygons;
    const Vec3 keep_min = w->bounds_min, keep_max = w->bounds_max;
    Inherited own;
    memset(&own, 0, sizeof own);
    transform_identity(&own.transform);
    transform_identity(&own.texture_space);
    b->slots = 1;
    for (int k = 0; k < w->nprototypes; k++) {
        const SceneObject *o = b->proto_mesh[k];
        Prototype *pr = &w->prototypes[k];
        int *slot = malloc(sizeof(int) * (size_t)(pr->nslots));
        if (!slot) {
            b->failed = 1;
            return -1;
        }
        for (int s = 1; s < pr->nslots; s++)
            slot[s - 1] = s;
        pr->first_polygon = w->npolygons;
        w->bounds_min = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
        w->bounds_max = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
        int rc = flatten_mesh_faces(b, o, &own, 0, slot);
        free(slot);
        if (rc)
            return -1;
        pr = &w->prototypes[k];
        pr->npolygons = w->npolygons - pr->first_polygon;
        pr->bbox_min = w->bounds_min;
        pr->bbox_max = w->bounds_max;
    }
    b->slots = 0;
    w->nproto_polygons = w->npolygons - nworld;
    w->npolygons = nworld;
    w->bounds_min = keep_min;
    w->bounds_max = keep_max;
    /* Instances of a prototype of no polygons (every face degenerate) go. */
    int n = 0;
    long long id = nworld;
    for (int i = 0; i < w->ninstances; i++) {
        Instance *it = &w->instances[i];
        const Prototype *pr = &w->prototypes[it->prototype];
        if (pr->npolygons == 0)
            continue;
        if (id + pr->npolygons > INT32_MAX / 2) {
            b->failed = 1; /* more polygon ids than an int holds */
            return -1;
        }
        it->first_id = (int)id;
        id += pr->npolygons;
        /* the box of its polygons' points carried to world space */
        Vec3 lo = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL), hi = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
        for (int q = pr->first_polygon; q < pr->first_polygon + pr->npolygons; q++) {
            const Polygon *p = &w->polygons[q];
            for (int j = 0; j < p->npoints; j++) {
                Vec3 x = transform_point(&it->to_world, w->points[p->first_point + j]);
                lo = v3_min(lo, x);
                hi = v3_max(hi, x);
            }
            if (!w->materials[w->instance_materials[it->first_material + p->material]].opaque)
                w->nsee_through++;
        }
        it->bbox_min = lo;
        it->bbox_max = hi;
        /* a signed permutation: each local axis one world axis, +-1 exactly */
        const double(*inv)[4] = it->to_world.inv;
        it->permutation = 1;
        for (int a = 0; a < 3; a++) {
            int found = 0;
            for (int j = 0; j < 3; j++) {
                if (inv[j][a] == 1.0 || inv[j][a] == -1.0) {
                    found++;
                    it->axis[a] = j;
                    it->sign[a] = inv[j][a];
                } else if (inv[j][a] != 0.0) {
                    found = 2;
                }
            }
            it->permutation &= found == 1;
        }
        w->bounds_min = v3_min(w->bounds_min, lo);
        w->bounds_max = v3_max(w->bounds_max, hi);
        w->instances[n++] = *it;
    }
    w->ninstances = n;
    w->nids = (int)id;
    return 0;
}

/* ---- the shapes POV-Ray intersects as planar pieces (planar_shapes.h) --- */

typedef struct {
    PieceSink sink;       /* first: the builders hand back &sink */
    Builder *b;
    int material;
} PieceTarget;

static int piece_triangle(PieceSink *s, const Vec3 v[3], const Vec3 *normals, const Vec3 *uv)
{
    PieceTarget *t = (PieceTarget *)s;
    int before = t->b->w->npolygons;
    if (add_triangle(t->b, v[0], v[1], v[2], normals, t->material))
        return -1;
    return uv && builds_uv(t->b, t->material) ? attach_uv(t->b, before, uv) : 0;
}

static int piece_polygon(PieceSink *s, const Vec3 *pts, int n, const int *starts, int noutlines)
{
    PieceTarget *t = (PieceTarget *)s;
    return add_polygon(t->b, pts, n, starts, noutlines, t->material);
}

static int piece_cell_polygon(PieceSink *s, const Vec3 *pts, int n, const Vec3 cell[CELL_NORMAL_VECTORS])
{
    PieceTarget *t = (PieceTarget *)s;
    World *w = t->b->w;
    int before = w->npolygons;
    const int starts[2] = { 0, n };
    if (add_polygon(t->b, pts, n, starts, 1, t->material))
        return -1;
    if (w->npolygons == before)
        return 0; /* degenerate: none */
    if (GROW(t->b, vertex_normals, cap_normals, w->nvertex_normals + CELL_NORMAL_VECTORS))
        return -1;
    Polygon *p = &w->polygons[w->npolygons - 1];
    p->smooth_normals = w->nvertex_normals;
    p->cell_normals = 1;
    for (int i = 0; i < CELL_NORMAL_VECTORS; i++)
        w->vertex_normals[w->nvertex_normals++] = cell[i];
    return 0;
}

static int flatten_planar_shape(Builder *b, const SceneObject *o, const Inherited *in, int material)
{
    PieceTarget t = { { NULL, piece_triangle, piece_polygon, piece_cell_polygon }, b, material };
    switch (o->kind) {
    case OBJ_HEIGHT_FIELD: return height_field_pieces(o, &in->transform, &t.sink);
    case OBJ_BICUBIC_PATCH: return bicubic_patch_pieces(o, &in->transform, &t.sink);
    default: return 0;
    }
}

static int flatten_object(Builder *b, const SceneObject *o, const Inherited *parent, const Scene *scene, int depth)
{
    if (depth > 1000)
        return 0;
    Inherited in = *parent;
    if (depth == 0)
        in.top_object = o;
    in.transform = o->transform;
    transform_compose(&in.transform, &parent->transform);
    if (o->texture) {
        in.texture = o->texture;
        /* transforms written after the texture move it; those before do not */
        Transform bind_inverse;
        memcpy(bind_inverse.m, o->texture_bind.inv, sizeof bind_inverse.m);
        memcpy(bind_inverse.inv, o->texture_bind.m, sizeof bind_inverse.inv);
        in.texture_space = bind_inverse;
        transform_compose(&in.texture_space, &in.transform);
    }
    if (o->interior_texture) { /* a union's passes to its children that have none (POV-Ray's Post_Process) */
        in.interior_texture = o->interior_texture;
        memcpy(in.interior_texture_space.m, o->texture_bind.inv, sizeof in.interior_texture_space.m);
        memcpy(in.interior_texture_space.inv, o->texture_bind.m, sizeof in.interior_texture_space.inv);
        transform_compose(&in.interior_texture_space, &in.transform);
    }
    if (o->interior)
        in.interior = o->interior;
    in.no_shadow |= o->no_shadow;
    in.no_image |= o->no_image;
    in.no_reflection |= o->no_reflection;
    in.double_illuminate |= o->double_illuminate;
    in.hollow |= o->hollow;
    in.inverse ^= o->inverse;
    in.general_transform |= o->general_transform;

    /* The clock read every 1024 objects: a few microseconds in ten thousands. */
    if (b->deadline > 0.0 && (++b->objects & 1023) == 0 && clock_wall() > b->deadline) {
        b->timed_out = 1;
        return -1;
    }
    if (bound_kept(o))
        return flatten_bounded(b, o, &in, scene, depth);
    if (o->nclips > 0)
        return flatten_clipped(b, o, &in, scene, depth);
    return flatten_kind(b, o, &in, scene, depth);
}

/* Material.inside_turned for object o (with what it inherits, `in`):
 * whether POV-Ray's normal of its surface is hstrace's turned. The
 * analytic shapes' normals are outward in both, and POV-Ray turns an
 * inverted one's (INVERTED_FLAG, ComputeTextureColour); a plane inside
 * CSG is inverted by turning its normal, in both, but hstrace keeps a
 * top-level plane's as written; a box's faces (flatten_box) are wound
 * with their normals inward, outward under a mirroring transform. */
static int inside_turned(const SceneObject *o, const Inherited *in, int in_csg)
{
    if (o->kind == OBJ_PLANE && in_csg)
        return 0;
    if (o->kind == OBJ_BOX && !in_csg) {
        const double(*m)[4] = in->transform.m;
        double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        return (det > 0.0) != (in->inverse != 0);
    }
    return in->inverse != 0;
}

/* What o (with what it inherits, `in`) makes, by its kind. */
static int flatten_kind(Builder *b, const SceneObject *o, const Inherited *in_, const Scene *scene, int depth)
{
    const Inherited in = *in_;
    if (o->kind == OBJ_UNION && b->csg_depth == 0) { /* a union inside CSG is one of its solids */
        for (int i = 0; i < o->u.csg.nchildren; i++)
            if (flatten_object(b, o->u.csg.children[i], &in, scene, depth + 1))
                return -1;
        return 0;
    }
    const SceneTexture *tex = in.texture ? in.texture : &scene->default_texture;
    int material = add_material(b, &in, tex, &in.texture_space, o->pos);
    if (material < 0)
        return -1;
    if (b->w->materials[material].inside >= 0) /* its own material (none is shared with an interior texture) */
        b->w->materials[material].inside_turned = inside_turned(o, &in, b->csg_depth > 0);
    switch (o->kind) {
    case OBJ_POLYGON: return flatten_polygon(b, o, &in, material);
    case OBJ_TRIANGLE: return flatten_triangle(b, o, &in, material);
    case OBJ_MESH: return b->instancing ? instance_mesh(b, o, &in, material) : flatten_mesh(b, o, &in, material);
    /* inside a CSG object a box and a plane are solids, else surfaces */
    case OBJ_BOX: return b->csg_depth > 0 ? flatten_box_part(b, o, &in, material) : flatten_box(b, o, &in, material);
    case OBJ_PLANE:
        return b->csg_depth > 0 ? flatten_plane_part(b, o, &in, material) : flatten_plane(b, o, &in, material);
    case OBJ_SPHERE: return flatten_sphere(b, o, &in, material);
    case OBJ_DISC: return flatten_disc(b, o, &in, material);
    case OBJ_CONE: return flatten_cone(b, o, &in, material);
    case OBJ_TORUS: return flatten_torus(b, o, &in, material);
    case OBJ_GLYPH: return flatten_glyph(b, o, &in, material);
    case OBJ_BLOB: return flatten_blob(b, o, &in, material);
    case OBJ_QUADRIC: return flatten_quadric(b, o, &in, material);
    case OBJ_POLY: return flatten_poly(b, o, &in, material);
    case OBJ_SUPERELLIPSOID: return flatten_superellipsoid(b, o, &in, material);
    case OBJ_LATHE: return flatten_lathe(b, o, &in, material);
    case OBJ_SOR: return flatten_sor(b, o, &in, material);
    case OBJ_PRISM: return flatten_prism(b, o, &in, material);
    case OBJ_HEIGHT_FIELD: case OBJ_BICUBIC_PATCH:
        return flatten_planar_shape(b, o, &in, material);
    case OBJ_UNION:
    case OBJ_INTERSECTION:
    case OBJ_DIFFERENCE:
    case OBJ_MERGE: return flatten_csg(b, o, &in, scene, depth, material);
    }
    return 0;
}

static void build_lights(World *w, const Scene *scene)
{
    for (int i = 0; i < scene->nlights; i++) {
        const SceneLight *sl = &scene->lights[i];
        Light *l = &w->lights[i];
        l->kind = sl->kind;
        l->location = sl->location;
        l->colour = rgb_of(&sl->colour);
        l->shadowless = sl->shadowless;
        l->fade_distance = sl->fade_distance;
        l->fade_power = sl->fade_power;
        l->direction = v3_normalize(v3_sub(sl->location, sl->point_at));
        l->beam = sl->beam;
        l->beam_radius = sl->beam_radius;
        l->beam_falloff = sl->beam_falloff;
        l->beam_tightness = sl->beam_tightness;
        l->point_at = sl->point_at;
        l->area = sl->area;
    }
}

/* The CSG objects' parts after the world's shapes (World.nparts), and
 * each CSG object told where its parts are now. */
static int place_parts(Builder *b)
{
    World *w = b->w;
    Shape *all = big_realloc(w->shapes, sizeof *all * ((size_t)w->nshapes + (size_t)b->nparts));
    if (!all)
        return -1;
    memcpy(all + w->nshapes, b->parts, sizeof *all * (size_t)b->nparts);
    w->shapes = all;
    w->nparts = b->nparts;
    b->cap_shapes = w->nshapes + b->nparts;
    for (int i = 0; i < w->nshapes + w->nparts; i++)
        if (all[i].kind == SHAPE_CSG)
            all[i].u.csg.parts = all + w->nshapes + all[i].u.csg.first_part;
    return 0;
}

static void builder_free(Builder *b)
{
    free(b->parts);
    ptr_map_free(&b->maps_built);
    ptr_map_free(&b->mesh_uses);
    ptr_map_free(&b->mesh_proto);
    free(b->proto_mesh);
}

int world_build(World *w, const Scene *scene, WorldError *err) { return world_build_threads(w, scene, 1, err); }

int world_build_threads(World *w, const Scene *scene, int threads, WorldError *err)
{
    return world_build_limited(w, scene, threads, NULL, err);
}

/* The world the scene's objects will make, held to limits->max_memory
 * before anything is made: 0, or -1 with the message at the first
 * top-level object that takes it past (or out of memory to count). */
static int within_memory(const Scene *scene, const WorldLimits *limits, WorldError *err)
{
    if (!limits || limits->max_memory == 0 || scene->nobjects == 0)
        return 0;
    WorldEstimate *e = world_estimate_new();
    double total = 0.0, polygons = 0.0;
    for (int i = 0; e && i < scene->nobjects; i++) {
        double b, n;
        if (world_estimate_object(e, scene->objects[i], &b, &n))
            break;
        total += b;
        polygons += n;
        if (total > (double)limits->max_memory) {
            char need[32], limit[32];
            memory_size_text(need, sizeof need, total >= (double)SIZE_MAX ? SIZE_MAX : (size_t)total);
            memory_size_text(limit, sizeof limit, limits->max_memory);
            snprintf(err->message, sizeof err->message,
                     "the world built from the scene would take %s (%.0f polygons) with this object, more than the "
                     "memory budget of %s (--max-memory sets it)",
                     need, polygons, limit);
            err->pos = scene->objects[i]->pos;
            err->over_budget = 1;
            world_estimate_free(e);
            return -1;
        }
        if (i == scene->nobjects - 1) {
            world_estimate_free(e);
            return 0;
        }
    }
    world_estimate_free(e);
    snprintf(err->message, sizeof err->message, "out of memory while counting the scene's polygons");
    return -1;
}

int world_build_limited(World *w, const Scene *scene, int threads, const WorldLimits *limits, WorldError *err)
{
    memset(w, 0, sizeof *w);
    memset(err, 0, sizeof *err);
    if (within_memory(scene, limits, err))
        return -1;
    w->bounds_min = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
    w->bounds_max = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
    w->noise_generator = scene_noise_generator(scene);
    w->number_of_waves = scene->globals.number_of_waves;
    Builder b = { .w = w, .threads = threads, .deadline = limits ? limits->deadline : 0.0,
                  .instancing = limits && limits->instance_meshes };
    for (int i = 0; i < MATERIAL_MEMO; i++)
        b.memo[i].index = -1;
    for (int i = 0; b.instancing && i < scene->nobjects; i++)
        if (count_mesh_uses(&b, scene->objects[i], 0)) {
            snprintf(err->message, sizeof err->message, "out of memory while counting the scene's meshes");
            builder_free(&b);
            world_free(w);
            return -1;
        }
    Inherited root;
    memset(&root, 0, sizeof root);
    transform_identity(&root.transform);
    transform_identity(&root.texture_space);
    for (int i = 0; i < scene->nobjects; i++) {
        if (flatten_object(&b, scene->objects[i], &root, scene, 0) || b.failed) {
            if (b.timed_out)
                snprintf(err->message, sizeof err->message,
                         "building the world from the scene took more than the %g s of --max-parse-seconds (the "
                         "parse and the build together), in this object",
                         limits->max_seconds);
            else if (b.message[0])
                snprintf(err->message, sizeof err->message, "%s", b.message);
            else
                snprintf(err->message, sizeof err->message, "out of memory while flattening the scene");
            err->over_budget = b.timed_out || b.message[0];
            err->pos = scene->objects[i]->pos;
            builder_free(&b);
            world_free(w);
            return -1;
        }
    }
    if (b.nparts > 0 && place_parts(&b)) {
        snprintf(err->message, sizeof err->message, "out of memory while flattening the scene");
        builder_free(&b);
        world_free(w);
        return -1;
    }
    for (int i = 0; i < w->npolygons; i++)
        w->nsee_through += !w->materials[w->polygons[i].material].opaque;
    w->nids = w->npolygons;
    if (w->nprototypes > 0 && build_prototypes(&b)) {
        snprintf(err->message, sizeof err->message, "out of memory while making the scene's instances");
        builder_free(&b);
        world_free(w);
        return -1;
    }
    builder_free(&b);
    w->nlights = scene->nlights;
    w->lights = calloc((size_t)(scene->nlights > 0 ? scene->nlights : 1), sizeof(Light));
    if (!w->lights) {
        snprintf(err->message, sizeof err->message, "out of memory");
        world_free(w);
        return -1;
    }
    build_lights(w, scene);
    w->camera.kind = scene->camera.kind;
    w->camera.location = scene->camera.location;
    w->camera.direction = scene->camera.direction;
    w->camera.up = scene->camera.up;
    w->camera.right = scene->camera.right;
    w->camera.angle = scene->camera.angle;
    w->camera.h_angle = scene->camera.h_angle;
    w->camera.v_angle = scene->camera.v_angle;
    w->background_colour = rgb_of(&scene->background);
    w->background_filter = scene->background.filter;
    w->background_transmit = scene->background.transmit;
    w->background = w->background_colour;
    /* POV-Ray's older rules where it keeps them: a scene without #version
     * is taken as a 3.6 one (scene_effective_version). */
    const double version = scene_effective_version(scene);
    if (version >= 3.7) { /* POV-Ray 3.7 composites it on black */
        w->background.r *= 1.0 - scene->background.transmit;
        w->background.g *= 1.0 - scene->background.transmit;
        w->background.b *= 1.0 - scene->background.transmit;
    }
    if (scene->sky.npigments > 0) {
        w->sky = malloc(sizeof *w->sky);
        Pigment *pigments = malloc(sizeof *pigments * (size_t)scene->sky.npigments);
        if (!w->sky || !pigments) {
            free(pigments);
            snprintf(err->message, sizeof err->message, "out of memory");
            world_free(w);
            return -1;
        }
        *w->sky = scene->sky;
        for (int i = 0; i < scene->sky.npigments; i++) {
            pigments[i] = scene->sky.pigments[i];
            resolve_pattern_settings(&pigments[i], w);
        }
        w->sky->pigments = pigments;
    }
    w->legacy_sky = version < 3.7;
    w->legacy_layer_light = version < 3.7;
    w->nfogs = scene->nfogs;
    w->fogs = scene->fogs;
    w->ambient_light = rgb_of(&scene->globals.ambient_light);
    /* POV-Ray 3.7 uses no finish's ambient once radiosity is on (the
     * radiosity, not modelled here, stands in for it); 3.6 scenes keep it,
     * and so do renders below +Q9, where POV-Ray turns radiosity off. */
    w->radiosity_replaces_ambient = scene->globals.radiosity && version >= 3.7;
    w->max_trace_level = scene->globals.max_trace_level > 0 ? scene->globals.max_trace_level : 5;
    /* As POV-Ray takes it: 0 (or less) prunes no ray (the parser gives
     * POV-Ray's default, 1/255, when the scene says none). */
    w->adc_bailout = scene->globals.adc_bailout;
    return 0;
}

void world_free(World *w)
{
    free(w->polygons);
    free(w->points);
    free(w->outline_start);
    free(w->outline_box);
    free(w->vertex_normals);
    free(w->uvs);
    free(w->vertex_materials);
    if (w->sky)
        free(w->sky->pigments);
    free(w->sky);
    free(w->planes);
    free(w->shapes);
    for (int i = 0; i < w->nblobs; i++)
        blob_free(w->blobs[i]);
    free(w->blobs);
    free(w->materials);
    free(w->maps);
    free(w->map_entries);
    free(w->lights);
    free(w->prototypes);
    free(w->instances);
    free(w->instance_materials);
    memset(w, 0, sizeof *w);
}
