/* SPDX-License-Identifier: MIT */
/* fixel — visible-surface detection, the course's methods side by side
 * (issue #23).
 *
 * Every method reads the same input, a scene of convex planar polygons
 * already in screen space, kept in the course's three tables:
 *
 *   vertex table   x, y (pixels; integer vertices are pixel centres) and
 *                  z (depth, larger = farther)
 *   edge table     two vertex indices and the polygon; with the edge's
 *                  screen half-plane e(x, y) = ea x + eb y + ec >= 0 (or > 0)
 *   polygon table  first edge, edge count, colour, extents, and the plane
 *                  a x + b y + c z + d = 0 computed from the vertices
 *                  (Newell's sums), oriented so that c > 0
 *
 * The plane gives everything else: the back-face test (c < 0 before
 * orientation: the normal points toward the viewer, i.e. the polygon is
 * drawn counter-clockwise as seen on a y-down screen, is a front face),
 * the depth z(x, y) = -(a x + b y + d) / c of a pixel, and which side of a
 * polygon a point lies on (a x + b y + c z + d > 0: behind it, since c > 0
 * and the viewer looks along +z).
 *
 * Exactness: x, y, z are integers in [0, FX_VSD_COORD_MAX], so plane
 * coefficients fit 24 bits and two depths compare exactly as rationals in
 * 64 bits (fx_vsd_depth_cmp). A pixel shows the polygon whose exact depth
 * at the pixel centre is least; ties go to the lower polygon index. Pixel
 * (X, Y) is covered when its centre is inside, ties on left and top edges
 * in (docs/CONVENTIONS.md); that is the z-buffer's picture (FX_VSD_ZBUFFER)
 * and the reference the other methods are tested against
 * (tests/core/test_vsd.c states each method's tolerance).
 *
 * Fragments: the depth-sort and BSP methods split polygons. A piece keeps
 * its polygon's plane and edges and adds the splitting plane as an exact
 * screen half-plane (the line where the two planes meet, seen from the
 * viewer), so the two pieces of a split cover each pixel of the polygon
 * exactly once. Approximate piece vertices (1/256 pixel) serve only the
 * geometric tests.
 *
 * Memory: fx_vsd_work_bytes says what each method needs; the caller gives
 * it. Too little is -FX_ENOSPC; more pieces than the work holds is
 * -FX_ENOSPC too, and a piece that would need more than FX_VSD_MAX_CUTS
 * splitting planes shaping it at once is -FX_E2BIG (never an overflow). The output of every method but the
 * A-buffer is an id buffer: w * h int32 polygon indices, -1 for background;
 * fx_vsd_paint colours a surface from it.
 */
#ifndef FIXEL_VSD_H
#define FIXEL_VSD_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/mat3d.h"
#include "fixel/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FX_VSD_COORD_MAX 2047 /* x, y, z of vertices and the screen size */
#define FX_VSD_MAX_VERTS 8    /* vertices of one input polygon */
#define FX_VSD_MAX_CUTS 8     /* splitting planes one piece may carry */
#define FX_VSD_FRAG_VERTS (FX_VSD_MAX_VERTS + FX_VSD_MAX_CUTS)

typedef struct fx_vsd_vertex {
    int32_t x, y, z;
} fx_vsd_vertex;

typedef struct fx_vsd_edge {
    int32_t v0, v1, poly;
    int64_t ea, eb, ec; /* inside: ea x + eb y + ec > 0, or == 0 when incl */
    int32_t incl;       /* left or top edge: its centres are inside */
} fx_vsd_edge;

typedef struct fx_vsd_poly {
    int32_t first_edge, nedges;
    int64_t a, b, c, d; /* plane, c > 0 */
    int32_t back;       /* the polygon faced away from the viewer */
    fx_color color;
    int32_t xmin, ymin, zmin, xmax, ymax, zmax; /* vertex extents */
} fx_vsd_poly;

typedef struct fx_vsd_scene {
    fx_vsd_vertex *vert;
    fx_vsd_edge *edge;
    fx_vsd_poly *poly;
    int32_t nvert, nedge, npoly;
    int32_t vcap, ecap, pcap;
    int32_t w, h;       /* screen, at most FX_VSD_COORD_MAX + 1 */
    int32_t cull;       /* drop back faces at fx_vsd_add */
    int32_t culled;     /* how many were dropped */
    fx_color background;
} fx_vsd_scene;

typedef enum fx_vsd_method {
    FX_VSD_ZBUFFER,  /* depth buffer, polygon by polygon */
    FX_VSD_PAINTER,  /* sort by mean depth only: wrong on cyclic overlaps */
    FX_VSD_NEWELL,   /* depth sort with Newell's tests and splitting */
    FX_VSD_BSP,      /* BSP tree built, then traversed back to front */
    FX_VSD_SCANLINE, /* edge/polygon tables, active edge list, in/out flags */
    FX_VSD_WARNOCK,  /* area subdivision down to pixels */
    FX_VSD_RAYCAST,  /* first hit of one ray per pixel centre */
    FX_VSD_ABUFFER,  /* 4x4 coverage masks and depth per pixel (fx_vsd_abuffer) */
    FX_VSD_METHODS
} fx_vsd_method;

/* The method's name ("zbuffer", "painter", "newell", "bsp", "scanline",
 * "warnock", "raycast", "abuffer"); NULL out of range. */
const char *fx_vsd_method_name(fx_vsd_method m);

/* An empty scene over the caller's tables, for a w x h screen. */
int fx_vsd_init(fx_vsd_scene *s, int32_t w, int32_t h, fx_vsd_vertex *vert, int32_t vcap,
                fx_vsd_edge *edge, int32_t ecap, fx_vsd_poly *poly, int32_t pcap);
/* Add a convex planar polygon of n (3..FX_VSD_MAX_VERTS) vertices; it gets
 * index npoly - 1. Returns 0, also when the polygon is dropped (edge-on, or
 * a back face with cull set: counted in culled); -FX_EINVAL for a
 * coordinate out of range or a concave or non-planar polygon, -FX_ENOSPC
 * when a table is full. */
int fx_vsd_add(fx_vsd_scene *s, const fx_vsd_vertex *v, int n, fx_color color);

/* Add a mesh of the 3D pipeline as triangles: each vertex goes through
 * mvp (object -> clip, as fx3d's projection x view x model) and the
 * perspective division onto the w x h screen (x = (x/w + 1) W / 2,
 * y = (1 - y/w) H / 2, depth = (z/w + 1) 2047 / 2, each rounded to the
 * nearest integer). The colour is flat-shaded by a light at the viewer:
 * color scaled by |cos| of the angle between the face and the view
 * direction, at least 1/4. There is no clipping: a triangle with a vertex
 * behind the eye or off the screen or the depth range is left out, as
 * are triangles that round to a line; they and culled back faces count in
 * s->culled. Returns 0, -FX_EINVAL, or -FX_ENOSPC when a table fills. */
int fx_vsd_add_mesh(fx_vsd_scene *s, const fx_mat4 *mvp, const fx_mesh *m, fx_color color);

/* Sign of depth(p) - depth(q) at pixel centre (x, y): < 0 when p is nearer. */
int fx_vsd_depth_cmp(const fx_vsd_scene *s, int32_t p, int32_t q, int32_t x, int32_t y);
/* Is pixel (x, y)'s centre inside polygon p (top-left rule)? */
int fx_vsd_inside(const fx_vsd_scene *s, int32_t p, int32_t x, int32_t y);

/* Work bytes the method needs for this scene; max_frags bounds the pieces
 * the splitting methods may make (>= npoly; the others ignore it). */
size_t fx_vsd_work_bytes(const fx_vsd_scene *s, fx_vsd_method m, int32_t max_frags);

/* Statistics of one run, for the trace, tests and the benchmark. */
typedef struct fx_vsd_stats {
    int32_t frags;    /* pieces after splitting (Newell, BSP) */
    int32_t splits;   /* polygons split */
    int32_t moves;    /* Newell: polygons moved to be drawn earlier */
    int32_t unresolved; /* Newell: pairs left in an order no test proved
                         * (a cycle no cut it tried broke, as on an
                         * unculled mesh folding over itself): pixels of
                         * such pairs can be wrong */
    int32_t nodes;    /* BSP nodes */
    int32_t depth;    /* BSP tree depth */
    int32_t regions;  /* Warnock: regions visited */
    int32_t max_active; /* scan-line: longest active edge list */
} fx_vsd_stats;

/* Resolve visibility with method m into ids (w * h, row stride w). Traces
 * through c->trace when c is not NULL and has one: the order drawn
 * (painter, Newell: tests and moves), the BSP tree, the active edge list
 * of row trace_row (scan-line), the regions and their cases (Warnock). */
int fx_vsd_render(const fx_vsd_scene *s, fx_vsd_method m, int32_t *ids, void *work, size_t bytes,
                  const fx_ctx *c, int32_t trace_row, fx_vsd_stats *st);

/* Colour dst (at offset ox, oy, clipped) from an id buffer. */
void fx_vsd_paint(const fx_vsd_scene *s, const int32_t *ids, const fx_surface *dst, int32_t ox,
                  int32_t oy);

/* The A-buffer: every polygon leaves per pixel a 4x4 coverage mask with its
 * depth at the pixel centre; each pixel resolves its fragments front to
 * back, weighting colours by the samples still uncovered, background for
 * the rest. Writes dst (offset ox, oy). edge_px, when not NULL, receives
 * the number of pixels where some fragment covered part of the pixel. */
int fx_vsd_abuffer(const fx_vsd_scene *s, const fx_surface *dst, int32_t ox, int32_t oy, void *work,
                   size_t bytes, int32_t *edge_px);

/* Octree method: a solid of 2^k x 2^k x 2^k voxels (k <= 8) as an octree
 * (a node is empty, full, or mixed with 8 children), drawn looking along
 * +z with each voxel a scale x scale pixel square: octants are visited
 * front to back (the four nearer ones first), a full node paints the
 * pixels of its square not yet painted, and a node whose square is already
 * painted everywhere is skipped with everything behind it. */
typedef struct fx_vsd_onode {
    int32_t kind;  /* 0 empty, 1 full, 2 mixed */
    int32_t child; /* mixed: index of the first of its 8 children
                    * (octant bit 0 = +x, bit 1 = +y, bit 2 = +z) */
} fx_vsd_onode;

typedef struct fx_vsd_octree {
    fx_vsd_onode *node;
    int32_t nnode, cap, k;
} fx_vsd_octree;

/* Build from vox (size^3 bytes, index (z * size + y) * size + x, non-zero
 * = solid) into the caller's nodes. -FX_ENOSPC when they do not suffice
 * (a solid needs at most 1 + 8 + 64 + ... nodes, (8^(k+1) - 1) / 7). */
int fx_vsd_octree_build(fx_vsd_octree *o, fx_vsd_onode *mem, int32_t cap, const uint8_t *vox, int32_t k);
/* Render into depth (w * h, row stride w): the z of the first voxel seen
 * at each pixel, -1 where none. Returns the number of nodes visited. */
int32_t fx_vsd_octree_render(const fx_vsd_octree *o, int32_t scale, int32_t *depth, int32_t w, int32_t h);
/* The course's voxel solid: a ball with a tunnel through it toward the
 * viewer and a notch cut out of its front, before a wall, in a 2^k cube. */
void fx_vsd_demo_solid(uint8_t *vox, int32_t k);

/* The course's test scene: three bars, each over the next and under the one
 * before (a cyclic overlap no ordering of whole polygons draws right), a
 * pair of interpenetrating triangles, and n further tilted quads scattered
 * by a fixed pseudo-random sequence (scene size for the benchmark). Laid
 * out for 200 x 150 and scaled by the largest whole factor the screen
 * allows (up to 10); a smaller screen shows part of it. */
int fx_vsd_demo_scene(fx_vsd_scene *s, int32_t n);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
