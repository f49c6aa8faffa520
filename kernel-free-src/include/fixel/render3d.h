/* SPDX-License-Identifier: MIT */
/* fixel — the 3D pipeline: transform, light, clip, project, rasterize.
 *
 * It follows the OpenGL 1.x fixed pipeline that the course teaches, with
 * the state in one caller-owned struct (fx3d) instead of a global context:
 *
 *   object --model stack--> world --view (camera)--> eye --projection stack-->
 *   clip --homogeneous clipping--> divide --viewport--> screen (24.8)
 *
 * The camera's view matrix is kept apart from the model stack (GL keeps both
 * in one model-view matrix; loading the camera at the bottom of GL's stack
 * is the same product). Lights are given in world coordinates.
 *
 * Clipping: triangles are clipped in homogeneous clip space against the
 * near and far planes and against a guard band |x|, |y| <= G w (G chosen
 * per viewport so that screen coordinates stay within +-2^14 pixels); the
 * rasterizer scissors the rest. A triangle crossing the camera plane
 * therefore renders exactly its visible part.
 *
 * Perspective division is integer: screen x = round((x + w) * W * 128 / w)
 * in 24.8 (one division per vertex, exact rounding of the Q16.16 clip
 * values, so the only error is the +-2^-17 rounding already in x and w,
 * magnified by W / (2 w)); depth = floor((z + w) * 2^29 / w) in [0, 2^30].
 *
 * Rasterization: pixel (X, Y) is covered when its centre is inside the
 * triangle, ties going to top and left edges; integer screen coordinates
 * are pixel centres (the same rule as fill.h). Depth, colour, normal and
 * position are interpolated affinely in screen space with 16 fraction bits
 * per pixel step (Gouraud's original scheme; colours are not perspective
 * corrected). A triangle thinner than the gradients can represent falls
 * back to its average attributes.
 *
 * Why a second triangle rasterizer (render3d.c rather than fx_tri_begin of
 * fill.h): the coverage rule is the same, the attribute arithmetic is not.
 * The 3D triangle carries depth plus up to 18 attributes (colour or
 * normal, eye position, shadow-map position and depth, texture q and
 * (s, t) q, vertex colour, solid-texture point), more than
 * FX_TRI_MAX_ATTR = 8;
 * its planes use one reciprocal of the area per triangle and 16 fraction
 * bits (fx_tri_begin divides exactly, in 128 bits, per attribute, into
 * Q32.32), which is what makes a 4096-triangle frame affordable; slivers
 * fall back to flat attributes (GRAD_LIMIT) where fx_tri_begin stays exact;
 * and the span loop interleaves the depth test and shadow lookups per pixel.
 * Its pictures (golden images, the teapot frame) are defined by that
 * arithmetic, so moving it onto fx_tri_begin would change pixels.
 */
#ifndef FIXEL_RENDER3D_H
#define FIXEL_RENDER3D_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/mat3d.h"
#include "fixel/mesh.h"
#include "fixel/texture.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Linear colour, Q16.16 per channel (1.0 = full; light colours may exceed 1). */
typedef struct fx3d_rgb {
    fx16 r, g, b;
} fx3d_rgb;
fx3d_rgb fx3d_rgb_from_color(fx_color c);
/* Clamp to [0, 1] and round to 8 bits per channel, opaque. */
fx_color fx3d_rgb_to_color(fx3d_rgb c);

typedef enum fx3d_light_type {
    FX3D_LIGHT_OFF,
    FX3D_LIGHT_DIRECTIONAL, /* pos = direction toward the light */
    FX3D_LIGHT_POINT,
    FX3D_LIGHT_SPOT         /* point light limited to a cone */
} fx3d_light_type;

/* The course's lighting model, per light and channel:
 *   I = spot * (Ia ka + Id kd max(N.L, 0) + Is ks max(R.V, 0)^shininess)
 * with R = 2 (N.L) N - L the reflection of L, V toward the viewer, and
 * spot = max(-L.D, 0)^exponent inside the cut-off cone (0 outside), 1 for
 * other lights. The total adds emission and global ambient * ka. Point and
 * spot lights may fade with the distance d to the light as in OpenGL 1.x:
 * the light's whole term is multiplied by 1 / (kc + kl d + kq d^2)
 * (att_const, att_linear, att_quad); all three 0, as fx3d_init and a
 * zeroed light leave them, means no attenuation (GL's kc = 1). */
typedef struct fx3d_light {
    fx3d_light_type type;
    fx_vec3 pos;      /* world: position, or direction toward a directional light */
    fx_vec3 spot_dir; /* world: where the spot points */
    fx_angle cutoff;  /* half-angle of the spot cone (< 90 degrees) */
    int32_t spot_exp; /* 0..128 */
    fx3d_rgb ambient, diffuse, specular;
    fx16 att_const, att_linear, att_quad; /* >= 0 */
} fx3d_light;

typedef struct fx3d_material {
    fx3d_rgb ambient, diffuse, specular, emission;
    int32_t shininess; /* 0..128 */
} fx3d_material;

/* Shading: one colour per face (FX3D_FLAT, GL's last vertex), colours lit
 * at the vertices and interpolated (FX3D_GOURAUD, FX3D_GOURAUD_SCAN), or
 * normals interpolated and lit per pixel (FX3D_PHONG).
 *
 * The two Gouraud rules differ for faces of four or more vertices.
 * FX3D_GOURAUD interpolates over each triangle (GL's rule: a quad is two
 * triangles, and its colour depends on the diagonal). FX3D_GOURAUD_SCAN is
 * the notes' scan-line rule: on each row the colours are interpolated along
 * the two edges of the face the row crosses, then across the span between
 * them, so the notes' quad with red, green, blue and white corners has
 * centre (128,128,128) where the triangle rule gives (128,0,128) (its first
 * triangle cuts along the red-blue diagonal). Triangles are drawn the same
 * by both, pixel for pixel. Only the colour changes: coverage, depth (and
 * so visibility) and the other attributes come from the face's triangles
 * as under FX3D_GOURAUD.
 *
 * A face is what the mesh generators, fx_mesh_obj_parse and the scripts'
 * polygon3d write for a polygon: a run of consecutive triangles forming a
 * fan (a, b, c), (a, c, d), (a, d, e), ... facing the same way, every
 * corner of it turning the same way on the screen (a convex polygon, so a
 * cylinder's cap fan around its centre stops growing before half a turn),
 * of at most FX3D_SCAN_MAX_VERTS vertices (a longer fan goes on as a new
 * face). A face cut by a clip plane takes its colours from the face
 * clipped whole, its pixels from its triangles clipped one by one (the
 * same pixels and depths as FX3D_GOURAUD, even for a face that is not
 * planar). Faces keep the triangle rule where their triangles are kept for
 * a sort (painter's visibility, sorted translucency), where they are lit
 * with shadow maps, and where a face clipped whole would need more than
 * FX3D_SCAN_MAX_VERTS + 6 corners (not convex in space). */
typedef enum fx3d_shading { FX3D_FLAT, FX3D_GOURAUD, FX3D_PHONG, FX3D_GOURAUD_SCAN } fx3d_shading;
#define FX3D_SCAN_MAX_VERTS 8
typedef enum fx3d_cull { FX3D_CULL_NONE, FX3D_CULL_BACK, FX3D_CULL_FRONT } fx3d_cull;
typedef enum fx3d_polymode {
    FX3D_FILL,
    FX3D_WIRE,        /* every edge, in ctx.color */
    FX3D_HIDDEN_LINE  /* faces filled with .background, edges in ctx.color where visible */
} fx3d_polymode;
typedef enum fx3d_visibility {
    FX3D_VIS_NONE,    /* draw in submission order */
    FX3D_VIS_DEPTH,   /* depth buffer (fx3d_set_depth) */
    FX3D_VIS_PAINTER  /* depth sort: buffered until fx3d_flush, then drawn far to near */
} fx3d_visibility;

/* A shadow buffer: a square depth map rendered from a light (see
 * fx3d_shadow_begin). */
typedef struct fx3d_shadowmap {
    uint32_t *depth; /* size * size entries, from the caller */
    int32_t size;
    int light;       /* the light whose diffuse and specular the shadow removes */
    fx_mat4 view_proj; /* world -> the light's clip space */
    uint32_t bias;     /* depth tolerance against self-shadowing (depth units of 2^-30) */
} fx3d_shadowmap;

#define FX3D_MAX_LIGHTS 8
/* Shadow maps in use at once (fx3d_shadow_use), each for its own light. */
#define FX3D_MAX_SHADOWS 4

/* What fx3d_draw adds to the picture (fx3d_pass): everything; only the
 * ambient terms (emission, global ambient, each light's Ia ka), writing
 * depth; or one light's diffuse and specular terms where its shadow map
 * (if one is in use) says it is lit, on the pixels whose depth equals the
 * buffer's, added to the surface with saturation and no depth write. */
typedef enum fx3d_pass_kind { FX3D_PASS_ALL, FX3D_PASS_AMBIENT, FX3D_PASS_LIGHT } fx3d_pass_kind;

/* How the texel T combines with the lit colour C (OpenGL 1.x texture
 * environment, channels in [0, 1]): modulate C * T (lighting shows through
 * the image), replace T, decal C (1 - Ta) + T Ta (the image's alpha paints
 * it over the lit surface). */
typedef enum fx3d_texmode { FX3D_TEX_MODULATE, FX3D_TEX_REPLACE, FX3D_TEX_DECAL } fx3d_texmode;

typedef struct fx3d {
    fx_ctx ctx;          /* surface, clip rectangle, wireframe colour */
    fx_rect viewport;
    fx_mat4 view;        /* world -> eye (fx_camera_view) */
    fx_mat_stack model;  /* object -> world */
    fx_mat_stack proj;   /* eye -> clip */
    int parallel;        /* set by the projection helpers: viewer at infinity */
    void *depth;         /* surface-sized depth buffer, 16 or 32 bits per pixel */
    int depth_bits;
    fx3d_shading shading;
    fx3d_cull cull;
    fx3d_polymode polymode;
    fx3d_visibility visibility;
    fx_color background; /* face colour in hidden-line mode */
    fx3d_light light[FX3D_MAX_LIGHTS];
    fx3d_rgb ambient;    /* global ambient light */
    fx3d_material mat;
    /* painter's mode */
    void *pbuf;
    int32_t pcap, pcount, pdropped;
    /* planar projected shadows */
    int plane_shadow;
    fx16 plane[4];        /* world plane a x + b y + c z + d = 0 */
    int plane_light;
    fx_color plane_color;
    /* shadow buffer */
    fx3d_shadowmap *sm;
    int sm_phase;         /* 0 off, 1 rendering the map, 2 using it */
    /* The maps in use (fx3d_shadow_use); sm_use[0] == sm in phase 2. */
    fx3d_shadowmap *sm_use[FX3D_MAX_SHADOWS];
    int sm_n;
    /* Multi-pass lighting (fx3d_pass) */
    int pass;             /* fx3d_pass_kind */
    int pass_light;
    fx16 pass_dim;        /* fx3d_pass_ambient_dim's share, kept by the light passes */
    /* statistics of the last fx3d_draw (for tests and benches) */
    int32_t stat_culled, stat_drawn, stat_clipped;
    /* Texture (fx3d_texture): meshes with uv are drawn with it in FX3D_FILL. */
    const fx_texture *tex;
    fx3d_texmode tex_mode;
    /* Solid texture (fx3d_solid) */
    int solid;                 /* FX_RT_TEX_* of rt.h; 0 none */
    fx_color solid_c0, solid_c1;
    fx16 solid_scale;
    int tex_sphere_map;        /* fx3d_sphere_map */
    fx16 bump, bump_scale;     /* fx3d_bump */
    int frame;                 /* fx3d_frame: FX_RT_FRAME_* of rt.h; 0 none */
    fx16 frame_k, frame_scale;
    /* Texture matrix stack (fx3d_texture_stack); slot NULL: identity. */
    fx_mat_stack texm;
    /* Translucency (fx3d_alpha, fx3d_set_translucent) */
    int32_t alpha;        /* 255 opaque */
    void *tbuf;
    int32_t tcap, tcount, tdropped;
    /* Rows of the depth buffer fx3d_clear_depth clears (fx3d_depth_rows);
     * depth_y1 <= depth_y0: all. */
    int32_t depth_y0, depth_y1;
    /* Vertex cache (fx3d_set_vertex_cache) */
    void *vcache;
    int32_t vcache_n;
    uint32_t vcache_gen;
} fx3d;

/* A pipeline on surface s: viewport = whole surface, identity matrices,
 * Gouraud, back-face culling, fill, no depth buffer, light 0 a white
 * directional light from (0, 0, 1), a grey plastic material. The stacks
 * live in the caller's arrays (>= 1 slot each). */
int fx3d_init(fx3d *r, const fx_surface *s, fx_mat4 *model_stack, int model_cap,
              fx_mat4 *proj_stack, int proj_cap);
void fx3d_viewport(fx3d *r, int32_t x, int32_t y, int32_t w, int32_t h);
/* Bytes of a depth buffer for the surface (bits 16 or 32). */
size_t fx3d_depth_bytes(const fx_surface *s, int bits);
/* Attach (and clear) a depth buffer and switch to FX3D_VIS_DEPTH;
 * buf == NULL detaches it. */
int fx3d_set_depth(fx3d *r, void *buf, int bits);
void fx3d_clear_depth(fx3d *r);
/* Clear only rows y0..y1-1 of the depth buffer from now on (y1 <= y0: every
 * row, the default). For a band of a frame drawn on several threads, whose
 * every clip lies in those rows: the depth of other rows is never read, so
 * a band need not clear (or the caller zero) the whole buffer. */
void fx3d_depth_rows(fx3d *r, int32_t y0, int32_t y1);
/* Optional scratch memory for fx3d_draw (mem NULL: none): a mesh of at most
 * as many vertices as fit has each vertex transformed, and under Gouraud
 * shading lit, once per draw instead of once per triangle using it. The
 * pixels are the same with and without it. fx3d_vertex_cache_bytes gives
 * the bytes for nverts vertices (SIZE_MAX when that does not fit size_t).
 * The memory must stay until replaced, and must be aligned to
 * FX3D_VERTEX_CACHE_ALIGN bytes (as malloc's and fx_scene_alloc's are when
 * the arena is): its entries hold 32-bit fields, and the 8 leaves them room
 * to grow. Memory that is not aligned, or smaller than one entry, gives no
 * cache (the same pixels, slower), never a misaligned access. */
#define FX3D_VERTEX_CACHE_ALIGN 8
size_t fx3d_vertex_cache_bytes(int32_t nverts);
/* 1 when nothing inside the convex hull of the n object-space points pts
 * (widened by 1/256 of their largest coordinate, for what fixed-point
 * evaluation makes of them) can be drawn in the clip with the current
 * matrices and viewport: the corners of their box all in front of the eye
 * and beyond one edge of the clip widened by a margin (which covers the
 * rounding of the corners' and the vertices' transforms and of clipping).
 * fx3d_draw skips the lighting of such triangles itself; this lets a
 * caller skip making them (fx_mesh_make_teapot's patches in a band of a
 * frame). 0 when unsure: a corner whose eye or clip coordinates reach the
 * int32 limits (clamped, it is no longer the corner), and always for
 * painter's or translucent triangles (sorted), a planar shadow or a
 * shadow-map pass. */
int fx3d_hull_away(fx3d *r, const fx_vec3 *pts, int n);
void fx3d_set_vertex_cache(fx3d *r, void *mem, size_t bytes);

/* Painter's mode: triangles are kept (up to what fits in mem) and drawn
 * sorted by mean depth, farthest first, by fx3d_flush. Triangles beyond the
 * buffer are counted in pdropped and lost. */
size_t fx3d_painter_bytes(int32_t ntris);
int fx3d_set_painter(fx3d *r, void *mem, size_t bytes);
void fx3d_flush(fx3d *r);

/* Transparency (OpenGL 1.x blending GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA
 * with glDepthMask(GL_FALSE), sorted): meshes drawn while alpha < 255 (in
 * FX3D_FILL) are blended over the surface, c = src a + dst (1 - a), and
 * never write depth. With a buffer from fx3d_set_translucent (sized by
 * fx3d_painter_bytes) their triangles are kept and drawn by fx3d_flush,
 * after the opaque ones, farthest first by mean depth, depth-tested against
 * the opaque surfaces, so blending order is back to front as it must be;
 * triangles beyond the buffer are counted in tdropped and lost. Without a
 * buffer they are blended at once in submission order (the caller sorts).
 * In painter's mode they are sorted with the other triangles instead.
 * Intersecting translucent triangles are not split: each is blended whole
 * at its mean depth. alpha is clamped to 0..255; fx3d_init sets 255. */
void fx3d_alpha(fx3d *r, int alpha);
int fx3d_set_translucent(fx3d *r, void *mem, size_t bytes);

/* Projection helpers: load the current projection matrix (and note whether
 * the viewer is at infinity, for specular highlights). */
int fx3d_perspective(fx3d *r, fx_angle fovy, fx16 aspect, fx16 znear, fx16 zfar);
int fx3d_ortho(fx3d *r, fx16 l, fx16 rt, fx16 b, fx16 t, fx16 znear, fx16 zfar);
/* Non-square pixels: fx_mat4_pixel_aspect on the current projection matrix
 * (call it after the projection helper, as glScale on GL_PROJECTION). */
int fx3d_pixel_aspect(fx3d *r, int32_t num, int32_t den);
int fx3d_oblique(fx3d *r, fx16 l, fx16 rt, fx16 b, fx16 t, fx16 znear, fx16 zfar,
                 fx_angle alpha, fx16 len, fx16 plane);

/* Texture the meshes drawn from now on (NULL: none). A mesh is textured
 * when it has uv and the polygon mode is FX3D_FILL. Sampling is
 * fx_tex_sample's (texture.h): nearest or bilinear, repeat or clamp, as the
 * fx_texture says; the texture stays the caller's and must outlive the
 * draws (in painter's mode, until fx3d_flush).
 *
 * Texture coordinates are interpolated perspective-correctly: per triangle
 * the rasterizer interpolates q = w_min / w (2^22 at the nearest vertex)
 * and (s - s0) q, (t - t0) q linearly in screen space and divides per
 * pixel, so a texel lands where the eye-space point it belongs to projects
 * (tests/core/test_3d_tex.c checks this against a double-precision ray
 * cast within one texel). Colours keep the affine Gouraud scheme above.
 *
 * No mipmaps: one level is sampled, so a texture minified many times (a
 * floor far away) aliases; choosing a level needs the screen-space
 * derivatives of s and t per pixel, a second division per pixel, and the
 * caller's memory for the pyramid. Left for later (issue #22). */
void fx3d_texture(fx3d *r, const fx_texture *tx, fx3d_texmode mode);

/* The texture matrix (OpenGL 1.x GL_TEXTURE matrix mode): every vertex's
 * texture coordinates (s, t, 0, 1), from the mesh's uv or from the sphere
 * map, are multiplied by the current matrix of r->texm and divided by the
 * resulting q (q = 1 for translate, rotate and scale) before they are
 * interpolated, so a texture can be moved, turned and tiled on a mesh
 * without touching its uv. The stack lives in the caller's array
 * (cap >= 1 slots) and starts as the identity; change it with the
 * fx_mat_stack functions of mat3d.h on &r->texm (push, pop, load, mult:
 * the last matrix multiplied acts first, as glMultMatrix). Before this
 * call (and after fx3d_init) the texture matrix is the identity. */
int fx3d_texture_stack(fx3d *r, fx_mat4 *mem, int cap);
/* The transform above, exposed for tests and callers that generate their
 * own coordinates: (s, t) -> out[0..1], Q16.16, each product rounded to
 * nearest (mat3d.h); q <= 0 leaves the coordinates undivided. */
void fx3d_tex_coord(const fx3d *r, fx16 s, fx16 t, fx16 out[2]);

/* Environment mapping (GL_SPHERE_MAP texture generation): on (1), every
 * vertex's texture coordinates come from its eye-space reflection vector
 * r = u - 2 (n . u) n (u the unit vector from the eye to the vertex) as
 * s = rx / m + 1/2, t = ry / m + 1/2, m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2),
 * so the texture, a picture of the surroundings as seen in a mirrored ball,
 * reflects in the object; meshes need no uv then, only normals. The
 * texture of fx3d_texture is used with its mode. */
void fx3d_sphere_map(fx3d *r, int on);

/* Solid textures on rasterized meshes (OpenGL has none; the course's
 * wood and marble): kind is FX_RT_TEX_WOOD, _MARBLE or _CHECKER of rt.h
 * (0 turns it off), evaluated by fx_rt_solid, the ray tracer's function, at
 * the object-space point / scale, so the grain moves with the object. The
 * weight w mixes c0 (w = 0) to c1, and the lit colour is multiplied by it
 * (like FX3D_TEX_MODULATE). The object-space point is interpolated in
 * screen space like Phong's eye position (affine, not perspective
 * corrected), on FX3D_FILL meshes. */
void fx3d_solid(fx3d *r, int kind, fx_color c0, fx_color c1, fx16 scale);
/* Bump mapping under Phong shading (FX3D_PHONG; other shadings ignore it):
 * the surface is lit as if displaced along its normal by
 * height * noise3(P / scale), P the object-space point, the ray tracer's
 * bumps (fx_rt_bump_gradient): the interpolated eye-space normal is tilted
 * against the tangential part of the height's gradient, taken to eye space
 * by the normal matrix. height 0 (or <= 0) turns it off; height 0..1,
 * scale 1/16..64 object units per noise cell (clamped). */
void fx3d_bump(fx3d *r, fx16 height, fx16 scale);
/* Frame mapping under Phong shading (FX3D_PHONG; other shadings ignore
 * it): the ray tracer's frame map (fx_rt_frame_dir, kind FX_RT_FRAME_* of
 * rt.h, at the object-space point / scale) gives each pixel a tangent,
 * taken to eye space by the model-view, and the highlight is blended
 * toward Kajiya-Kay's anisotropic one by strength (fx_rt_aniso_spec;
 * Phong's R.V highlight at 0). kind 0 or strength <= 0 turns it off;
 * strength 0..1, scale 1/16..64 object units per jitter cell (clamped). */
void fx3d_frame(fx3d *r, int kind, fx16 strength, fx16 scale);

/* Draw a mesh with the current state. Returns 0 or a negative error. */
int fx3d_draw(fx3d *r, const fx_mesh *m);

/* Planar shadows: every later fx3d_draw also projects its front faces from
 * light `light` (point or directional) onto the world plane
 * a x + b y + c z + d = 0 and draws them in colour c, depth-tested just in
 * front of the plane (needs the depth buffer to hide them behind things). */
void fx3d_plane_shadow(fx3d *r, const fx16 plane[4], int light, fx_color c);
void fx3d_plane_shadow_off(fx3d *r);

/* Shadow buffer, in two passes like a GL program:
 *   fx3d_shadow_aim(&sm, ...);     light's view and projection
 *   fx3d_shadow_begin(r, &sm);     clears the map; draws now fill it
 *   ... draw the shadow casters ...
 *   fx3d_shadow_end(r);            draws now light with the map
 *   ... draw the scene ...
 *   fx3d_shadow_off(r);
 * A pixel whose position, seen from the light, is farther than the map's
 * depth (plus bias) gets no diffuse or specular from that light. Only the
 * faces turned away from the light are written to the map (the lit side
 * then never shadows itself), so casters must be closed solids; a lone
 * plane such as a floor receives shadows but casts none. */
int fx3d_shadow_init(fx3d_shadowmap *sm, uint32_t *depth, int32_t size, int light);
int fx3d_shadow_aim(fx3d_shadowmap *sm, fx_vec3 from, fx_vec3 at, fx_angle fov, fx16 znear,
                    fx16 zfar);
void fx3d_shadow_begin(fx3d *r, fx3d_shadowmap *sm);
void fx3d_shadow_end(fx3d *r);
void fx3d_shadow_off(fx3d *r);
/* Several shadow maps at once: after each map was filled (begin, draw the
 * casters, for each map in turn), fx3d_shadow_use(r, maps, n) makes the
 * draws that follow test every pixel against all n maps (1..
 * FX3D_MAX_SHADOWS, each for a different light, each filled and aimed);
 * a map that shadows the pixel removes the diffuse and specular terms of
 * its own light only, so a point shadowed from light B and lit by light A
 * keeps A's terms and every ambient term. With n == 1 it is
 * fx3d_shadow_end with that map (the same pixels). The maps' depth stays
 * the caller's. -FX_EINVAL for n out of range, a NULL map or two maps of
 * one light. fx3d_shadow_off ends it.
 *
 * Under Gouraud shading each vertex carries the colour with all lights and,
 * per map, the colour without that map's light; a pixel shadowed by a set
 * S of maps gets full - sum over S of (full - without), interpolated, which
 * is exactly the colour without the lights of S at the vertices (the terms
 * of different lights are added without rounding between them, unless a
 * channel saturates at 2^15). Flat shading does the same per face, Phong
 * per pixel. */
int fx3d_shadow_use(fx3d *r, fx3d_shadowmap *const *maps, int n);

/* Multi-pass lighting, the course's way of drawing shadows with a depth
 * buffer and several lights (kind: fx3d_pass_kind above):
 *   fx3d_pass(r, FX3D_PASS_AMBIENT, 0);  draw the scene: ambient only
 *   fx3d_pass(r, FX3D_PASS_LIGHT, k);    draw the scene again, per light k:
 *                                         where the depth is equal and k's
 *                                         map says lit, add k's terms
 *   fx3d_pass(r, FX3D_PASS_ALL, 0);      back to one pass
 * The shadow maps come from fx3d_shadow_end / fx3d_shadow_use; a light
 * pass uses the map of its own light, if any. The light passes need the
 * depth buffer (without one they add everywhere they draw). Each pass
 * rounds its colour to the surface's format before the next one adds to
 * it, so the result can differ from the single pass (fx3d_shadow_use),
 * which rounds the sum once: by less than (n + 1) / 2 levels of 255 for
 * n passes in XRGB8888 (one level for the ambient pass and two lights;
 * tests/core/test_3d_shadows.c), more where the surface keeps fewer bits
 * (RGB565: a 5-bit step). Lights with attenuation or a spot
 * cone also differ in the rounding of the factor (the single pass
 * multiplies ambient + diffuse + specular by it at once). -FX_EINVAL for
 * a bad kind or light; -FX_ENOTSUP for a light pass under the painter's
 * visibility, which has no depth buffer to compare with. */
int fx3d_pass(fx3d *r, int kind, int light);
/* The ambient pass with the notes' dim diffuse light, "to prevent curved
 * surfaces from appearing flat in shadow": it adds dim (0..1) of every
 * light's diffuse term (no specular, no shadow test), and the light passes
 * after it add 1 - dim of their light's diffuse (and all of its specular),
 * so a lit point ends as bright as without the option (up to rounding) and
 * a shadowed one keeps dim of its shading. fx3d_pass(AMBIENT or ALL)
 * resets dim to 0. -FX_EINVAL for dim outside 0..1. */
int fx3d_pass_ambient_dim(fx3d *r, fx16 dim);

/* Lighting of one point (eye-space position and unit normal) with the
 * current lights and material; what the renderer evaluates per vertex
 * (Gouraud), per face (flat) or per pixel (Phong). */
fx3d_rgb fx3d_shade(const fx3d *r, fx_vec3 eye_pos, fx_vec3 eye_normal);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
