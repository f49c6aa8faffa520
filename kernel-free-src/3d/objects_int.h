/* SPDX-License-Identifier: MIT */
/* fixel — what the object generators share (private to the core). */
#ifndef FIXEL_OBJECTS_INT_H
#define FIXEL_OBJECTS_INT_H

#include "fixel/objects.h"

/* sin and cos, exact at quarter turns. */
void fx_obj_trig(fx_angle a, fx16 *s, fx16 *c);
/* The unit vector along (x, y, z) of any magnitude; +y for a zero vector. */
fx_vec3 fx_obj_unit64(int64_t x, int64_t y, int64_t z);
/* Bernstein weights of degree 3 and their derivatives at t, Q16.16 (the
 * teapot's patches and fx_patch_eval's Bézier basis share them). */
void fx_obj_bezier_basis(fx16 t, int64_t w[4], int64_t d[4]);

/* The generators' writers (mesh.c): a vertex with its normal, a triangle. */
void fx_obj_put(fx_mesh *m, fx_vec3 p, fx_vec3 n);
void fx_obj_tri(fx_mesh *m, int32_t a, int32_t b, int32_t c);
/* Two triangles a cell over rows 0..k of n + 1 vertices from base (the
 * last column repeats the first), outward when the rows run down the
 * outside; pole0 / polek: row 0 / row k is one point, and the triangles
 * that would collapse there are left out. */
void fx_obj_grid_tris(fx_mesh *m, int32_t base, int32_t n, int32_t k, int pole0, int polek);
/* k rings of n vertices, closed both ways (a torus). */
void fx_obj_ring_tris(fx_mesh *m, int32_t n, int32_t k);
/* Before a generator writes: e from its size function, the arrays there,
 * the capacities enough; counts reset. 0 or the error. */
int fx_obj_mesh_begin(fx_mesh *m, int e, int32_t nv, int32_t nt);

#endif
