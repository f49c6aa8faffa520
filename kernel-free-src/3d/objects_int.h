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

#endif
