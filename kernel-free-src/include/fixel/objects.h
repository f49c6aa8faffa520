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

int fx_patch_eval(const fx_vec3 P[16], fx_patch_basis basis, fx16 u, fx16 v, fx_vec3 *pt, fx_vec3 *nrm);
/* (n + 1)^2 vertices and 2 n^2 triangles (n in 1..FX_MESH_MAX_SEG),
 * appended to m (its nverts / ntris grow); counter-clockwise seen from the
 * side dP/du x dP/dv points to. -FX_ENOSPC when m is full. */
int fx_patch_tessellate(fx_mesh *m, const fx_vec3 P[16], fx_patch_basis basis, int32_t n);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
