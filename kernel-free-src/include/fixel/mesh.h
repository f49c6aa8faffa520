/* SPDX-License-Identifier: MIT */
/* fixel — triangle meshes: the solids of the course, the Utah teapot, and a
 * Wavefront OBJ parser, all writing into caller-provided arrays.
 *
 * A mesh is positions, optional per-vertex unit normals and triangles as
 * index triples, counter-clockwise seen from outside (the front face, as in
 * OpenGL). Every generator has a size function that says how many vertices
 * and triangles it will write for the given tessellation; the generator
 * then fails with -FX_ENOSPC rather than write past the arrays the caller
 * declared in m->cap_verts and m->cap_tris.
 *
 * Flat-faced solids (the five Platonic solids, the caps of cones and
 * cylinders) repeat each corner once per face, so that smooth shading keeps
 * their faces flat; curved surfaces share vertices and carry the analytic
 * normal. All sizes are Q16.16 and the solids are centred on the origin
 * (cone and cylinder stand on y = 0, axis +y; the teapot sits on y = 0).
 */
#ifndef FIXEL_MESH_H
#define FIXEL_MESH_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/mat3d.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_mesh {
    fx_vec3 *pos;
    fx_vec3 *nrm;  /* NULL: faces are lit with their own (flat) normal */
    uint32_t *tri; /* 3 indices per triangle */
    int32_t nverts, ntris;
    int32_t cap_verts, cap_tris; /* sizes of the arrays above */
    /* Texture coordinates, 2 per vertex (s, t in Q16.16, cap_verts pairs),
     * or NULL: untextured. The generators fill them when given: plane, cube
     * (each face the unit square), sphere and ellipsoid (s around the axis,
     * t from the north pole), the sides of cone and cylinder, and
     * the teapot (each Bezier patch its own (u, v) square); the other
     * Platonic solids, the torus and the caps get (0, 0). Added after
     * the other members: a caller filling them one by one must zero-
     * initialise the struct (fx_mesh m = {0}) so that uv is NULL. */
    fx16 *uv;
    /* Per-vertex colours (cap_verts of them) or NULL. A vertex colour
     * stands for the material's ambient and diffuse reflectance where the
     * vertex is lit (OpenGL's glColorMaterial(GL_AMBIENT_AND_DIFFUSE)):
     * Gouraud interpolates the lit colours, Phong the vertex colours, flat
     * shading takes the triangle's last vertex as GL does. */
    uint32_t *col; /* fx_color, 0xAARRGGBB */
} fx_mesh;

/* Tessellation parameters and their limits (-FX_EINVAL outside). */
#define FX_MESH_MAX_SEG 256

typedef enum fx_mesh_kind {
    FX_MESH_CUBE,         /* edge a */
    FX_MESH_TETRAHEDRON,  /* circumradius a */
    FX_MESH_OCTAHEDRON,   /* circumradius a */
    FX_MESH_DODECAHEDRON, /* circumradius a */
    FX_MESH_ICOSAHEDRON,  /* circumradius a */
    FX_MESH_SPHERE,       /* radius a; slices n (>= 3), stacks k (>= 2) */
    FX_MESH_ELLIPSOID,    /* radii a, b, c; slices n, stacks k */
    FX_MESH_TORUS,        /* ring radius a, tube radius b; sides n (>= 3), rings k (>= 3) */
    FX_MESH_CONE,         /* base radius a, height b; slices n (>= 3) */
    FX_MESH_CYLINDER,     /* radius a, height b; slices n (>= 3) */
    FX_MESH_TEAPOT,       /* height scale a (1: Newell's size, 3.15 tall); n x n per patch */
    FX_MESH_PLANE,        /* square of side a in y = 0, facing +y; n x n cells */
    FX_MESH_KIND_COUNT
} fx_mesh_kind;

typedef struct fx_mesh_params {
    fx_mesh_kind kind;
    fx16 a, b, c;
    int32_t n, k;
} fx_mesh_params;

/* How many vertices and triangles the generator writes. */
int fx_mesh_size(const fx_mesh_params *p, int32_t *nverts, int32_t *ntris);
/* Generate into m (pos, nrm, tri and the capacities set by the caller;
 * nrm must not be NULL). */
int fx_mesh_make(fx_mesh *m, const fx_mesh_params *p);
/* The teapot of fx_mesh_make (FX_MESH_TEAPOT, scale, n) without the patches
 * for which away(user, its 16 control points, 16) returns nonzero (say,
 * fx3d_hull_away: a patch lies in the convex hull of its control points,
 * so one wholly outside a band of the frame need not be tessellated);
 * away NULL keeps every patch. The kept patches are the same vertices and
 * triangles, in the same order, as in the whole teapot. */
int fx_mesh_make_teapot(fx_mesh *m, fx16 scale, int32_t n, int (*away)(void *user, const fx_vec3 *pts, int npts),
                        void *user);
/* Names as used by scripts ("cube", "teapot", ...); FX_MESH_KIND_COUNT if unknown. */
fx_mesh_kind fx_mesh_kind_from_name(const char *name);

/* ---- Wavefront OBJ ----
 * Accepted: v x y z [w], vn, vt (ignored), f with v, v/vt, v//vn or
 * v/vt/vn corners (negative indices count back from the end), polygons of
 * 3+ corners (triangulated as fans), and the statements o, g, s, usemtl,
 * mtllib, l, p (ignored). Numbers are decimal with an optional exponent
 * ("1.5e-3"), rounded to nearest Q16.16; values beyond +-32767 are errors.
 * Normals are rebuilt per vertex from the faces (area-weighted), since OBJ
 * normals belong to face corners, not to vertices.
 * Anything else is rejected: the return value is negative and err holds a
 * message naming the line ("line 12: face index 40 out of range (1..36)"). */
typedef struct fx_obj_error {
    int line;
    char msg[120];
} fx_obj_error;

/* The sizes an OBJ text needs (fx_mesh_size of them gives the bytes), then
 * the mesh itself; both 0 or negative with err filled (above). */
int fx_mesh_obj_size(const char *text, size_t len, int32_t *nverts, int32_t *ntris,
                     fx_obj_error *err);
int fx_mesh_obj_parse(fx_mesh *m, const char *text, size_t len, fx_obj_error *err);

/* Smooth per-vertex normals from the triangles (area-weighted average). */
void fx_mesh_compute_normals(fx_mesh *m);

/* ---- colour solids: the colour models as 3D models ----
 * Each is 8 vertices and 12 triangles (FX_COLOUR_SOLID_VERTS/_TRIS), with
 * per-vertex colours (m->col, which must be given) and no normals (m->nrm
 * set NULL: faces are lit flat), size across, centred on the origin, y up,
 * every triangle wound counter-clockwise seen from outside:
 *   FX_SOLID_RGB_CUBE     the RGB cube: R along x, G along y, B along z,
 *                         black at (-size/2)^3, white at (+size/2)^3;
 *   FX_SOLID_HSV_HEXCONE  Smith's hexcone: black apex at y = -size/2, the
 *                         hexagon V = 1 at y = +size/2 (radius size/2,
 *                         hue 0 (red) along +x, hue rising toward -z),
 *                         white at its centre;
 *   FX_SOLID_HLS_DOUBLE_CONE the double hexcone: black apex at the bottom,
 *                         white apex at the top, the fully saturated hues
 *                         on the hexagon L = 0.5 at y = 0.
 * Every colour inside a triangle is the linear blend of its corners', and
 * in these models that blend is the model's own colour there (RGB is
 * affine on the cube's faces; HSV and HLS are piecewise linear in RGB
 * between adjacent primaries and secondaries), so Gouraud shading paints
 * the solids exactly. Returns 0, or -FX_EINVAL (unknown kind, no col,
 * capacities too small, size outside (0, 2048]). */
typedef enum fx_colour_solid {
    FX_SOLID_RGB_CUBE,
    FX_SOLID_HSV_HEXCONE,
    FX_SOLID_HLS_DOUBLE_CONE,
    FX_SOLID_COUNT
} fx_colour_solid;
#define FX_COLOUR_SOLID_VERTS 8
#define FX_COLOUR_SOLID_TRIS 12
int fx_colour_solid_make(fx_mesh *m, fx_colour_solid kind, fx16 size);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
