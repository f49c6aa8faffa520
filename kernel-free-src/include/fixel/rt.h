/* SPDX-License-Identifier: MIT */
/* fixel — a fixed-point ray tracer (issue #22), integer-only.
 *
 * The course's model: generic shapes in object space, each placed by an
 * affine transform M; a world ray S + c t is taken into object space by
 * M^-1 (computed once, when the object is added), so t means the same
 * distance along the world ray for every object. Shapes combine into CSG
 * trees (union, intersection, difference) over hit lists sorted along the
 * ray; each node carries a world bounding box that lets a ray skip the
 * subtree. The lighting equation is the course's
 *     I = Iamb + Idiff + Ispec + Irefl + Itran
 * with shadow feelers, reflection r = d - 2 (d.m) m, refraction by Snell's
 * law (with total internal reflection), a recursion limit and a contribution
 * cut-off, light attenuation 1 / (1 + k d^2), and solid textures (wood,
 * marble) evaluated at the world hit point.
 *
 * Numerics (docs/RAYTRACE.md has the derivation and the measured errors):
 *   - positions, directions, t and colours are Q16.16 (fx16);
 *   - quadric coefficients are Q32.32 in int64, the discriminant Q64.64 in
 *     128 bits (fx_s128), its square root floored and exact;
 *   - the scene-scale limit: every world coordinate the scene uses (camera,
 *     lights, object bounds) within +-FX_RT_WORLD units, and every object's
 *     linear part scaled no smaller than 1/16 along any axis (M^-1 entries
 *     within +-16): then no intermediate overflows on any ray
 *     (tests/core/test_rt.c fuzzes it under UBSan);
 *   - secondary rays accept hits only beyond FX_RT_EPS (self-intersection).
 *
 * All memory comes from the caller: the object array (fx_rt_scene_init),
 * hit lists on the call stack (bounded by FX_RT_MAX_HITS and the CSG depth
 * FX_RT_MAX_DEPTH). No threads: fx_rt_render draws one tile, callers run
 * tiles where they like.
 */
#ifndef FIXEL_RT_H
#define FIXEL_RT_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/mat3d.h"
#include "fixel/mesh.h"
#include "fixel/render3d.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FX_RT_WORLD 128          /* scene-scale limit, world units */
#define FX_RT_EPS 64             /* 2^-10: secondary rays start beyond this t */
#define FX_RT_MAX_HITS 16        /* hit-list capacity (nearest kept) */
#define FX_RT_MAX_DEPTH 16       /* CSG tree depth */
#define FX_RT_MAX_RECURSION 8    /* reflection/refraction depth limit */
#define FX_RT_MAX_LIGHTS 4

typedef enum fx_rt_kind {
    FX_RT_SPHERE,   /* x^2 + y^2 + z^2 <= 1 */
    FX_RT_CUBE,     /* [-1, 1]^3 */
    FX_RT_SQUARE,   /* z = 0, |x|, |y| <= 1 (no inside) */
    FX_RT_PLANE,    /* the half-space z <= 0 */
    FX_RT_CYLINDER, /* tapered: x^2 + y^2 <= (1 + (s - 1) z)^2, 0 <= z <= 1 */
    FX_RT_MESH,     /* triangles through a BVH (fx_rt_mesh); a surface, no inside */
    FX_RT_TORUS,    /* (x^2 + y^2 + z^2 + 1 - r^2)^2 <= 4 (x^2 + y^2): ring radius 1 about z, tube r */
    FX_RT_UNION,
    FX_RT_INTERSECTION,
    FX_RT_DIFFERENCE
} fx_rt_kind;

typedef enum fx_rt_texture { FX_RT_TEX_NONE, FX_RT_TEX_WOOD, FX_RT_TEX_MARBLE, FX_RT_TEX_CHECKER } fx_rt_texture;

typedef struct fx_rt_material {
    fx3d_rgb ambient, diffuse, specular;
    int32_t shininess;  /* Phong exponent f, 0..256 */
    fx16 reflectivity;  /* kr, 0..1 */
    fx16 transparency;  /* kt, 0..1 */
    fx16 ior;           /* index of refraction, 1..4 */
    fx_rt_texture texture;
    fx3d_rgb tex_color; /* second colour of a texture (the first is diffuse) */
    fx16 tex_scale;     /* world units per texture unit */
    fx16 bump;          /* bump height, world units 0..1 (0: smooth; fx_rt_bump_normal) */
    fx16 bump_scale;    /* world units per noise cell of the bumps, 1/16..64 */
    fx3d_rgb emissive;  /* light the surface gives off itself, added to Iamb (0..1; the SDL's emissive) */
    int32_t frame;      /* fx_rt_frame_kind: anisotropic highlights (fx_rt_frame_dir); 0 none */
    fx16 frame_k;       /* their strength 0..1 (0: the Blinn-Phong highlight unchanged) */
    fx16 frame_scale;   /* world units per jitter cell of the frame map, 1/16..64 */
} fx_rt_material;

/* A material with no texture and no bumps: ambient, diffuse and specular
 * colours, Phong exponent (0..256), reflectivity kr and transparency kt
 * (0..1) and index of refraction (1..4). */
fx_rt_material fx_rt_material_make(fx_color ambient, fx_color diffuse, fx_color specular, int32_t shininess, fx16 kr,
                                   fx16 kt, fx16 ior);

typedef struct fx_rt_box {
    fx16 lo[3], hi[3];
} fx_rt_box;

/* ---- meshes: triangles (fixel/mesh.h) through a bounding volume
 * hierarchy built once over caller memory ---- */
#define FX_RT_MESH_LIMIT 32 /* object-space vertex coordinates within +-32 */
#define FX_RT_BVH_LEAF 4    /* triangles per leaf, at most */

typedef struct fx_rt_bvh_node {
    fx16 lo[3], hi[3]; /* object-space box */
    int32_t first;     /* leaf: first index into order; inner: left child (right = first + 1) */
    int32_t count;     /* leaf: triangles (1..FX_RT_BVH_LEAF); inner: 0 */
} fx_rt_bvh_node;

typedef struct fx_rt_mesh {
    const fx_mesh *mesh; /* positions, smooth normals (nrm may be NULL: flat), triangles */
    fx_rt_bvh_node *node;
    int32_t nnodes;
    uint32_t *order; /* triangle indices, grouped by leaf */
} fx_rt_mesh;

/* Build the BVH of m over caller memory: nodes for 2 * ntris nodes, order
 * for ntris indices (median split of the centroids along the longest axis).
 * -FX_ERANGE when a vertex leaves +-FX_RT_MESH_LIMIT, -FX_EINVAL for a bad
 * index or no triangles, -FX_ENOSPC when cap_nodes < 2 * ntris. */
int fx_rt_mesh_build(fx_rt_mesh *rm, const fx_mesh *m, fx_rt_bvh_node *nodes, int32_t cap_nodes, uint32_t *order);

typedef struct fx_rt_object {
    uint8_t kind;       /* fx_rt_kind */
    uint8_t top;        /* 1: part of the scene (not inside a CSG node) */
    int16_t left, right; /* children of a CSG node */
    fx16 taper;         /* s of a tapered cylinder (1 = cylinder, 0 = cone); r of a torus */
    fx_mat4 inv;        /* world -> object */
    fx_rt_box box;      /* world bounding box */
    fx_rt_material mat; /* leaves */
    const fx_rt_mesh *mesh; /* FX_RT_MESH: must outlive the scene */
} fx_rt_object;

typedef struct fx_rt_light {
    fx_vec3 pos;
    fx3d_rgb color;
    fx16 atten; /* k of 1 / (1 + k d^2), 0..1 (larger is taken as 1); 0: none */
} fx_rt_light;

typedef struct fx_rt_scene {
    fx_rt_object *obj;
    int n, cap;
    fx_rt_light light[FX_RT_MAX_LIGHTS];
    int nlights;
    fx3d_rgb ambient, background;
    fx_camera cam;
    fx16 tan_half; /* tan(fovy / 2) */
    int max_depth; /* recursion limit, 0..FX_RT_MAX_RECURSION */
    fx16 cutoff;   /* secondary rays whose weight falls below this are not traced */
} fx_rt_scene;

/* An empty scene on cap objects of caller memory; camera at (0,0,5) looking
 * at the origin, 45 degrees, depth 4, cut-off 1/256, black background. */
void fx_rt_scene_init(fx_rt_scene *s, fx_rt_object *mem, int cap);
/* Camera: eye, look, up as fx_camera_set; fovy in degrees (1..179). */
int fx_rt_set_camera(fx_rt_scene *s, fx_vec3 eye, fx_vec3 look, fx_vec3 up, fx16 fovy_deg);
/* A point light within the scene-scale limit, attenuation k of
 * 1 / (1 + k d^2) in 0..1 (d in world units); -FX_EDOM otherwise,
 * -FX_ENOSPC beyond FX_RT_MAX_LIGHTS. Returns its index. */
int fx_rt_add_light(fx_rt_scene *s, fx_vec3 pos, fx3d_rgb color, fx16 atten);

/* Add a shape placed by the object-to-world matrix m. Returns its index,
 * -FX_ENOSPC when the array is full, -FX_EDOM when m is singular or
 * scales an axis below 1/16, -FX_ERANGE when its bounds leave the
 * scene-scale limit, -FX_EINVAL for a bad kind or taper (0..2). For
 * FX_RT_TORUS, taper is the tube radius r, 1/16..1. */
int fx_rt_add_shape(fx_rt_scene *s, fx_rt_kind kind, fx16 taper, const fx_mat4 *m, const fx_rt_material *mat);
/* Add a mesh (built by fx_rt_mesh_build) placed by m; errors as
 * fx_rt_add_shape. A mesh is a surface: along a ray it reports its nearest
 * crossing beyond the ray's tmin (entering and leaving at that t), so in a
 * CSG tree it is a sheet that changes no inside state. */
int fx_rt_add_mesh(fx_rt_scene *s, const fx_rt_mesh *mesh, const fx_mat4 *m, const fx_rt_material *mat);
/* Combine two objects (indices of top-level objects) into a CSG node
 * (which replaces them at the top level). Returns its index or an error;
 * -FX_E2BIG when the tree would exceed FX_RT_MAX_DEPTH. */
int fx_rt_add_csg(fx_rt_scene *s, fx_rt_kind op, int left, int right);

/* ---- rays ---- */
typedef struct fx_rt_hit {
    fx16 t;
    int16_t obj;      /* leaf index */
    uint8_t entering; /* 1: the ray enters the solid here */
    uint8_t flip;     /* the normal points the other way (difference) */
    fx_vec3 normal;   /* object-space outward normal (not unit) */
} fx_rt_hit;

typedef struct fx_rt_hitlist {
    int n;
    uint8_t inside0; /* the line starts inside the solid (at t = -inf) */
    uint8_t overflow;
    fx_rt_hit h[FX_RT_MAX_HITS];
} fx_rt_hitlist;

/* Every crossing of the whole line S + c t with object i, sorted by t
 * (a mesh: its first crossing on the line). */
void fx_rt_hits(const fx_rt_scene *s, int i, fx_vec3 S, fx_vec3 c, fx_rt_hitlist *out);
/* The nearest hit with t > tmin over the scene; 1 when found. World-space
 * unit normal facing its outside in *n. */
int fx_rt_first_hit(const fx_rt_scene *s, fx_vec3 S, fx_vec3 c, fx16 tmin, fx_rt_hit *hit, fx_vec3 *n);

/* The colour of a ray (c unit length); trace (may be NULL) receives the ray
 * tree: every ray, hit, t, normal and the terms of I. */
fx3d_rgb fx_rt_trace_ray(const fx_rt_scene *s, fx_vec3 S, fx_vec3 c, fx_trace_fn trace, void *user);
/* The primary ray through the centre of pixel (x, y) of a w x h image. */
void fx_rt_primary(const fx_rt_scene *s, int32_t w, int32_t h, int32_t x, int32_t y, fx_vec3 *S, fx_vec3 *c);
/* Render the tile [x0, x0 + tw) x [y0, y0 + th) of a surface-sized image
 * (clipped to the surface). */
void fx_rt_render(const fx_rt_scene *s, const fx_surface *surf, int32_t x0, int32_t y0, int32_t tw, int32_t th);
/* Trace one pixel, sending its ray tree to trace; returns its colour. */
fx_color fx_rt_trace_pixel(const fx_rt_scene *s, int32_t w, int32_t h, int32_t x, int32_t y, fx_trace_fn trace,
                           void *user);

/* 3D value noise in [0, 1) and turbulence, as the solid textures use them. */
fx16 fx_rt_noise3(fx_vec3 p);
fx16 fx_rt_turbulence3(fx_vec3 p, int octaves);
/* A solid texture's mix weight in [0, 1] at texture-space point q (world
 * position / scale): kind FX_RT_TEX_WOOD rings about the y axis wobbled by
 * noise, MARBLE turbulent stripes across x, CHECKER unit cubes, NONE 0.
 * The ray tracer and the rasterizer (fx3d_solid) both colour with it. */
fx16 fx_rt_solid(int kind, fx_vec3 q);
/* Bump mapping (Blinn): the unit normal n at point P of a surface displaced
 * along n by height * noise3(P / scale). The normal is tilted against the
 * tangential part of the height's gradient (central differences of
 * fx_rt_noise3, 2^-7 cells apart) and normalised again. height 0..1,
 * scale 1/16..64 (clamped); height 0 returns n. */
fx_vec3 fx_rt_bump_normal(fx16 height, fx16 scale, fx_vec3 P, fx_vec3 n);
/* The gradient of that height field, height * noise3(q) with q = P / scale,
 * taken with respect to P (so times height / scale), at texture point q;
 * each component within +-24 units. The rasterizer's bumps use it. */
fx_vec3 fx_rt_bump_gradient(fx16 height, fx16 scale, fx_vec3 q);

/* Frame mapping: where bump mapping tilts only the normal, a frame map
 * gives the whole local frame (tangent T, bitangent B, normal N) at each
 * point, for surfaces whose highlights stretch along a grain (brushed or
 * spun metal, wood, hair). The map gives the direction T leans along at
 * texture point q (world or object point / scale), with a small jitter
 * from fx_rt_noise3 that varies fast across the grain and slowly along
 * it (so the highlight breaks into streaks):
 *   FX_RT_FRAME_BRUSHED: along the x axis (brushed along one direction);
 *   FX_RT_FRAME_SPUN:    around the y axis, circles in planes y = const
 *                        (a turned or spun disc; the wood texture's rings).
 * The shading is Kajiya-Kay's anisotropic highlight (a surface of fine
 * fibres along T): spec = (sqrt(1 - (T.H)^2))^n (N.L) with H the
 * half-way vector and n the material's exponent, brightest where T is
 * perpendicular to H, so the highlight is a band across T (N.L, which
 * Kajiya-Kay lack, keeps it off the silhouette). Diffuse stays
 * Lambert's on N. Both the ray tracer (fx_rt_material.frame) and the
 * rasterizer's Phong path (fx3d_frame) shade with these three functions. */
typedef enum fx_rt_frame_kind { FX_RT_FRAME_NONE, FX_RT_FRAME_BRUSHED, FX_RT_FRAME_SPUN } fx_rt_frame_kind;
/* The map's grain direction at texture point q (not unit, length about 1
 * unit); kind NONE or unknown (and SPUN on the y axis) gives (1, 0, 0). */
fx_vec3 fx_rt_frame_dir(int kind, fx_vec3 q);
/* The orthonormal frame at unit normal n: *t the grain direction dir with
 * its normal part removed (Gram-Schmidt), unit; *b = n x t. When dir is
 * (nearly) along n, any unit t perpendicular to n. */
void fx_rt_frame(fx_vec3 dir, fx_vec3 n, fx_vec3 *t, fx_vec3 *b);
/* The highlight blended toward Kajiya-Kay's by strength k (0..1, clamped):
 * spec + k ((sqrt(1 - (t.h)^2))^n nl - spec), t and h unit, n 0..256 the
 * Phong exponent, spec the isotropic highlight it replaces (0..1), nl =
 * N.L (0..1). The factor nl is not Kajiya-Kay's: their fibres shine up to
 * the silhouette, where T.H goes to 0 whatever the grain, and a surface
 * rim lit all round hides the band; it fades the band toward where the
 * light grazes the surface, as real-time hair shaders do. */
fx16 fx_rt_aniso_spec(fx16 spec, fx16 k, fx_vec3 t, fx_vec3 h, fx16 nl, int32_t n);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
