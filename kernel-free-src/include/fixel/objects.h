/* SPDX-License-Identifier: MIT */
/* fixel — the course's remaining 3D objects (issue #23): the quadrics the
 * solid generators of fixel/mesh.h lack, superquadrics, blobby objects and
 * bicubic spline patches, all as meshes with unit normals written into the
 * caller's arrays (the fx_mesh contract of fixel/mesh.h: -FX_ENOSPC rather
 * than a write past cap_verts / cap_tris).
 *
 * Axis and placement follow fixel/mesh.h: the axis of symmetry is y,
 * triangles are counter-clockwise seen from outside, normals point out of
 * the solid. All lengths and exponents are Q16.16.
 */
#ifndef FIXEL_OBJECTS_H
#define FIXEL_OBJECTS_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- quadrics and superquadrics ----
 * Each is a closed solid (watertight when vertices are matched by
 * position: the seam and the poles repeat positions, as the sphere does).
 *
 *   PARABOLOID     y = h ((x/a)^2 + (z/b)^2) for 0 <= y <= h, closed by a
 *                  flat cap at y = h (an elliptic cup, apex at the origin)
 *   HYPERBOLOID1   (x/a)^2 + (z/b)^2 - (y/c)^2 = 1 for |y| <= h, one sheet,
 *                  closed by caps at y = +-h
 *   HYPERBOLOID2   (y/c)^2 - (x/a)^2 - (z/b)^2 = 1 for c <= |y| <= h (h > c),
 *                  two sheets, each closed by a cap at y = +-h
 *   SUPERELLIPSOID Barr's: x = a S(p)^e1 S(t)^e2, y = b C(p)^e1,
 *                  z = c S(p)^e1 C(t)^e2 with C^e = sign(cos) |cos|^e,
 *                  S^e = sign(sin) |sin|^e, over the angle p from the +y
 *                  pole and the longitude t (e1 = e2 = 1: the ellipsoid of
 *                  fixel/mesh.h, vertex for vertex; small exponents: a
 *                  rounded box; 2: a double pyramid)
 *   SUPERTOROID    ring radius a, tube radius b: x = (a + b C(p)^e1) S(t)^e2,
 *                  y = b S(p)^e1, z = (a + b C(p)^e1) C(t)^e2 (the torus of
 *                  fixel/mesh.h at e1 = e2 = 1; n sides, k rings)
 *
 * Parameters: a, b, c (> 0, at most 1024), h (the height or half-height),
 * e1, e2 in [FX_SQ_EXP_MIN, FX_SQ_EXP_MAX] (superquadrics), n slices
 * around the axis (3..FX_MESH_MAX_SEG) and k rows along it
 * (2..FX_MESH_MAX_SEG; tori: 3..). Normals are the analytic ones: the
 * gradient of the implicit equation (quadrics), Barr's normal
 * (C^(2-e) products) for superquadrics, the axis direction on the caps.
 * Powers |x|^e are 2^(e log2 |x|) in fixed point (relative error below
 * 2^-14). */
#define FX_SQ_EXP_MIN 6554    /* 0.1 */
#define FX_SQ_EXP_MAX 131072  /* 2.0: beyond, Barr's normal is unbounded */

typedef enum fx_quadric_kind {
    FX_QUADRIC_PARABOLOID,
    FX_QUADRIC_HYPERBOLOID1,
    FX_QUADRIC_HYPERBOLOID2,
    FX_QUADRIC_SUPERELLIPSOID,
    FX_QUADRIC_SUPERTOROID,
    FX_QUADRIC_KIND_COUNT
} fx_quadric_kind;

typedef struct fx_quadric {
    fx_quadric_kind kind;
    fx16 a, b, c, h;
    fx16 e1, e2;
    int32_t n, k;
} fx_quadric;

/* Vertices and triangles fx_quadric_make writes; -FX_EINVAL for a
 * parameter out of range. */
int fx_quadric_size(const fx_quadric *q, int32_t *nverts, int32_t *ntris);
/* Generate into m (pos, nrm, tri and capacities set; uv and col ignored). */
int fx_quadric_make(fx_mesh *m, const fx_quadric *q);
/* sign(x) |x|^e for x in [-1, 1] and e in [0, 4] (Q16.16): 0 at x = 0. */
fx16 fx_signed_pow(fx16 x, fx16 e);

/* ---- blobby objects ----
 * Wyvill's soft objects: each ball adds w f(d^2 / r^2) to the field, where
 * d is the distance to its centre and f(s) = 1 - 22/9 s + 17/9 s^2 - 4/9 s^3
 * for s < 1 (0 beyond: a ball reaches exactly r; f falls smoothly from 1
 * at the centre, f(1) = f'(1) = 0, so two balls merge without a crease).
 * The surface is where the field equals iso.
 *
 * Polygonized by marching tetrahedra over the caller's grid of nx x ny x nz
 * cubes of side step from org: each cube is cut into six tetrahedra around
 * its diagonal from its lowest to its highest corner (neighbouring cubes
 * then cut their shared face along the same diagonal, so the mesh has no
 * cracks), and each tetrahedron gives 0, 1 or 2 triangles whose vertices
 * lie on the lattice edges where the field crosses iso, by linear
 * interpolation. A grid point exactly at iso counts as outside. Vertices
 * are shared between tetrahedra (one per lattice edge, kept in the work
 * memory), so a blob that lies inside the grid is a closed mesh; normals are
 * the field's negated gradient (analytic), normalized.
 *
 * Work: fx_blobby_work_bytes (a Q30 field value and 7 edge slots per grid
 * point), 8-byte aligned (-FX_EINVAL otherwise). Counting: with m->pos == NULL nothing is written and m->nverts,
 * m->ntris receive the counts; otherwise -FX_ENOSPC when a capacity is
 * short. -FX_EINVAL for an empty grid, a grid over FX_BLOBBY_MAX_GRID a
 * side, r <= 0, or iso <= 0. */
#define FX_BLOBBY_MAX_GRID 128
#define FX_BLOBBY_MAX_BALLS 64

typedef struct fx_blob_ball {
    fx_vec3 c;
    fx16 r, w;
} fx_blob_ball;

typedef struct fx_blobby {
    const fx_blob_ball *ball;
    int32_t nball;
    fx16 iso;
    fx_vec3 org;
    fx16 step;
    int32_t nx, ny, nz;
} fx_blobby;

/* The field at p (Q16.16). */
fx16 fx_blobby_field(const fx_blobby *b, fx_vec3 p);
size_t fx_blobby_work_bytes(const fx_blobby *b);
int fx_blobby_make(fx_mesh *m, const fx_blobby *b, void *work, size_t bytes);

/* ---- bicubic patches ----
 * A patch is 4 x 4 control points P[i][j] (row i along u, column j along
 * v), evaluated as sum B_i(u) B_j(v) P[i][j] with the Bernstein (Bézier)
 * or the uniform cubic B-spline basis (a B-spline patch passes near, not
 * through, its control points; neighbouring patches that share three rows
 * of control points join with continuous curvature). Coordinates within
 * +-1024; u, v in [0, 1] Q16.16. The normal is dP/du x dP/dv normalized;
 * where it vanishes (a degenerate edge, as at the teapot's lid) the one
 * 1/64 inside the patch is taken, and a patch degenerate there too gets
 * -FX_EDOM. */
typedef enum fx_patch_basis { FX_PATCH_BEZIER, FX_PATCH_BSPLINE } fx_patch_basis;

/* The point and unit normal of the bicubic patch P at (u, v), as above. */
int fx_patch_eval(const fx_vec3 P[16], fx_patch_basis basis, fx16 u, fx16 v, fx_vec3 *pt, fx_vec3 *nrm);
/* (n + 1)^2 vertices and 2 n^2 triangles (n in 1..FX_MESH_MAX_SEG),
 * appended to m (its nverts / ntris grow); counter-clockwise seen from the
 * side dP/du x dP/dv points to. -FX_ENOSPC when m is full, -FX_EDOM for a
 * point without a normal; m is then as it was. */
int fx_patch_tessellate(fx_mesh *m, const fx_vec3 P[16], fx_patch_basis basis, int32_t n);

/* ---- polygon tables ----
 * The course's geometric tables of a polyhedron in object space (Q16.16):
 *   vertex table   the point, and the head of the list of its edges
 *   edge table     its two vertices, the polygons on either side (the one
 *                  that runs v0 -> v1 first, then the one running back;
 *                  -1 while missing), and the next edge of each vertex's list
 *   polygon table  its edges in order (indices into the edge-use list:
 *                  2 e + 1 when it runs the edge backwards), and attributes:
 *                  a colour, a caller's value, and the plane
 *                  A x + B y + C z + D = 0
 * Polygons are counter-clockwise seen from outside; the plane comes from
 * Newell's sums over the vertices (exact on integers; scaled down to fit 31
 * bits), so (A, B, C) is the outward normal, and D puts the plane through
 * the vertices' mean. Then, as in the course:
 *   A x + B y + C z + D < 0   the point is inside (behind the polygon),
 *                       > 0   outside (in front), = 0 on its plane;
 *   a point is inside a convex polyhedron when it is inside every plane;
 *   a polygon is a back face for an eye at E when E is not in front of it
 *   (A Ex + B Ey + C Ez + D <= 0), and for a parallel view along V when
 *   V . N >= 0.
 * Adding a polygon checks it first and changes nothing on error:
 * -FX_EINVAL for fewer than 3 or more than FX_PTAB_MAX_VERTS vertices, an
 * index out of range, a vertex off the plane by more than 1/256, an edge a
 * third polygon would share, or one it would run in the same direction as
 * the polygon already there (the orientations disagree); -FX_EDOM for a
 * polygon without area; -FX_ENOSPC when a table is full. */
#define FX_PTAB_MAX_VERTS 64

typedef struct fx_ptab_vertex {
    fx_vec3 p;
    int32_t first_edge; /* -1: none */
} fx_ptab_vertex;

typedef struct fx_ptab_edge {
    int32_t v[2];
    int32_t poly[2];
    int32_t next[2]; /* next edge at v[0], at v[1]; -1 ends the list */
} fx_ptab_edge;

typedef struct fx_ptab_poly {
    int32_t first, n; /* its edge uses: use[first .. first + n - 1] */
    int64_t a, b, c, d;
    uint32_t color;
    int32_t attr;
} fx_ptab_poly;

typedef struct fx_ptab {
    fx_ptab_vertex *vert;
    fx_ptab_edge *edge;
    fx_ptab_poly *poly;
    int32_t *use;
    int32_t nvert, nedge, npoly, nuse;
    int32_t vcap, ecap, pcap, ucap;
} fx_ptab;

/* An empty polygon table in the arrays the caller gives, with their capacities. */
void fx_ptab_init(fx_ptab *t, fx_ptab_vertex *v, int32_t vcap, fx_ptab_edge *e, int32_t ecap, fx_ptab_poly *p,
                  int32_t pcap, int32_t *use, int32_t ucap);
/* The new vertex's index, or -FX_ENOSPC; -FX_EINVAL beyond +-1024. */
int32_t fx_ptab_add_vertex(fx_ptab *t, fx_vec3 p);
/* The new polygon's index, or an error (above). */
int32_t fx_ptab_add_polygon(fx_ptab *t, const int32_t *vi, int32_t n, uint32_t color, int32_t attr);
/* Every triangle of m (its vertices first); triangles without area are left
 * out. Returns the number of triangles left out, or an error (the tables
 * then hold what was added before it). */
int32_t fx_ptab_from_mesh(fx_ptab *t, const fx_mesh *m, uint32_t color);
/* Vertex k (0..n-1) of polygon p, in its order. */
int32_t fx_ptab_poly_vertex(const fx_ptab *t, int32_t p, int32_t k);
/* -1 inside (behind polygon p's plane), 0 on it, +1 outside. */
int fx_ptab_side(const fx_ptab *t, int32_t p, fx_vec3 q);
/* 1 when q is inside every polygon's plane (inside a convex polyhedron). */
int fx_ptab_inside_convex(const fx_ptab *t, fx_vec3 q);
/* 1 when q is inside the closed polyhedron: a ray from q along +x crosses
 * its polygons an odd number of times (any polyhedron, convex or not;
 * crossings through shared edges and vertices count once, by exact
 * half-open rules). */
int fx_ptab_inside(const fx_ptab *t, fx_vec3 q);
int fx_ptab_back_face(const fx_ptab *t, int32_t p, fx_vec3 eye);
int fx_ptab_back_face_dir(const fx_ptab *t, int32_t p, fx_vec3 view);
/* Edges with a polygon on one side only: 0 for a closed polyhedron. */
int32_t fx_ptab_open_edges(const fx_ptab *t);

/* ---- solids as voxels, for the octree (fx_vsd_octree_build, fixel/vsd.h) ----
 * A cube of side `side` from org cut into 2^k voxels a side (k 1..8);
 * vox[(z * 2^k + y) * 2^k + x] = 1 where the voxel's centre is inside:
 * where f(user, centre) > 0 (an implicit function, e.g. the blob field
 * minus its iso value), or inside the closed polygon table
 * (fx_ptab_inside, one row of voxels at a time). -FX_EINVAL for a cube
 * beyond +-1024. */
int fx_voxels_from_implicit(uint8_t *vox, int32_t k, fx_vec3 org, fx16 side,
                            fx16 (*f)(const void *user, fx_vec3 p), const void *user);
int fx_voxels_from_ptab(uint8_t *vox, int32_t k, fx_vec3 org, fx16 side, const fx_ptab *t);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
