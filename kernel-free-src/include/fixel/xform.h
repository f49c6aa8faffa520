/* SPDX-License-Identifier: MIT */
/* fixel — 2D transformations: 3x3 homogeneous matrices in Q16.16.
 *
 * A point is the column vector (x, y, 1); m[r][c] is row r, column c, so
 *   x' = m[0][0] x + m[0][1] y + m[0][2],  y' = m[1][0] x + m[1][1] y + m[1][2].
 * The constructors build affine matrices (bottom row 0 0 1); fx_xform2_mul
 * handles any 3x3 and fx_xform2_apply divides by w when the bottom row is
 * not 0 0 1.
 *
 * Coordinates are the context's: x right, y down in the default screen
 * mode, y up in course mode (draw.h, fx_ctx_set_coords). A rotation by +a
 * maps (1, 0) to (cos a, sin a), turning from +x towards +y: clockwise on
 * the screen in screen mode, counter-clockwise (as in the course notes) in
 * course mode. Arcs and pie slices (circle.h) follow the same rule. Angles are
 * binary (fx_angle, a full turn = 2^32); rotations by multiples of 90
 * degrees and reflections about lines at multiples of 45 degrees are exact
 * (fx_sin/fx_cos are exact there and no other rounding happens).
 *
 * Rounding: every entry of a product is the exact sum of the three 64-bit
 * products, rounded once to nearest; translation entries of composite
 * constructors (rotation about a pivot, scaling about a fixed point...) are
 * likewise rounded once. fx_xform2_invert is exact up to the final rounding
 * of each entry, so T * T^-1 differs from I in each entry by at most
 * (|m[r][0]| + |m[r][1]| + 1) / 2 units of 2^-16 (|m| in real units), plus
 * one unit for the product's own rounding.
 *
 * Composition: fx_xform2_mul(out, a, b) = a . b applies b first. The
 * fx_xform2_* constructors that take a matrix argument "m" post-multiply,
 * m = m . T (T acts first, as in OpenGL and the scene's transform stack);
 * fx_xform2_then pre-multiplies (m acts first, then the next).
 */
#ifndef FIXEL_XFORM_H
#define FIXEL_XFORM_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A point in Q16.16 pixel-centre coordinates. */
typedef struct fx_pt16 {
    fx16 x, y;
} fx_pt16;

typedef struct fx_xform2 {
    fx16 m[3][3];
} fx_xform2;

/* ---- building matrices (each returns the matrix in *out) ---- */
void fx_xform2_identity(fx_xform2 *out);
void fx_xform2_translation(fx_xform2 *out, fx16 tx, fx16 ty);
/* Scaling about the fixed point (px, py); uniform when sx == sy. */
void fx_xform2_scaling(fx_xform2 *out, fx16 sx, fx16 sy, fx16 px, fx16 py);
/* Rotation by a about the pivot (px, py). */
void fx_xform2_rotation(fx_xform2 *out, fx_angle a, fx16 px, fx16 py);
/* x-shear relative to the reference line y = yref: x' = x + sh (y - yref). */
void fx_xform2_shear_x(fx_xform2 *out, fx16 sh, fx16 yref);
/* y-shear relative to the reference line x = xref: y' = y + sh (x - xref). */
void fx_xform2_shear_y(fx_xform2 *out, fx16 sh, fx16 xref);

typedef enum fx_reflect {
    FX_REFLECT_X_AXIS,  /* about y = 0: (x, y) -> (x, -y) */
    FX_REFLECT_Y_AXIS,  /* about x = 0: (x, y) -> (-x, y) */
    FX_REFLECT_ORIGIN,  /* through (0, 0): (x, y) -> (-x, -y) */
    FX_REFLECT_DIAGONAL /* about y = x: (x, y) -> (y, x) */
} fx_reflect;
/* The reflection about an axis, the origin or the diagonal (fx_reflect above). */
void fx_xform2_reflection(fx_xform2 *out, fx_reflect axis);
/* Reflection about the line through (px, py) at angle a (binary angle from
 * the +x axis): [cos 2a, sin 2a; sin 2a, -cos 2a] about that point. */
void fx_xform2_reflection_line(fx_xform2 *out, fx16 px, fx16 py, fx_angle a);

/* Window-to-viewport: maps the world window [wx0, wx1] x [wy0, wy1] onto the
 * viewport [vx0, vx1] x [vy0, vy1] (both in Q16.16; the viewport in
 * pixel-centre coordinates of the surface): xv = vx0 + (xw - wx0) sx with
 * sx = (vx1 - vx0) / (wx1 - wx0), likewise y (give wy0 > wy1 for a y-up
 * world). keep_aspect: one scale, the smaller magnitude, for both axes, and
 * the window centred in the viewport. -FX_EINVAL for an empty window. */
int fx_xform2_window_viewport(fx_xform2 *out, fx16 wx0, fx16 wy0, fx16 wx1, fx16 wy1, fx16 vx0,
                              fx16 vy0, fx16 vx1, fx16 vy1, int keep_aspect);

/* The same on a display whose pixels are not square (pixel aspect ratio,
 * e.g. the notes' 3/4): with keep_aspect, x is scaled by par_num/par_den
 * times the y scale, so a shape that is as wide as it is tall in the world
 * is par_num/par_den as many pixels wide as it is tall, and looks round on
 * such a display (a world circle becomes an ellipse with rx/ry = num/den);
 * the window is fitted and centred as above. Without keep_aspect the window
 * fills the viewport whatever the pixels are, as in
 * fx_xform2_window_viewport. par_num, par_den in 1..FX_PAR_MAX (else
 * -FX_EINVAL); 1/1 is fx_xform2_window_viewport exactly. */
#define FX_PAR_MAX 65536
int fx_xform2_window_viewport_par(fx_xform2 *out, fx16 wx0, fx16 wy0, fx16 wx1, fx16 wy1, fx16 vx0,
                                  fx16 vy0, fx16 vx1, fx16 vy1, int keep_aspect, int32_t par_num,
                                  int32_t par_den);

/* ---- composition and inversion ---- */
/* out = a . b (b applies first); out may alias a or b. Saturates. */
void fx_xform2_mul(fx_xform2 *out, const fx_xform2 *a, const fx_xform2 *b);
/* m = m . t: t acts before m (the scene's and OpenGL's order). */
void fx_xform2_pre(fx_xform2 *m, const fx_xform2 *t);
/* m = t . m: t acts after m. */
void fx_xform2_then(fx_xform2 *m, const fx_xform2 *t);
/* out = in^-1 for an affine matrix. -FX_EDOM when singular, -FX_ERANGE when
 * the inverse does not fit Q16.16, -FX_ENOTSUP for a projective matrix.
 * out may alias in. */
int fx_xform2_invert(fx_xform2 *out, const fx_xform2 *in);
int fx_xform2_is_identity(const fx_xform2 *m);

/* ---- applying ---- */
/* Q16.16 in and out, rounded to nearest, saturating. */
fx_pt16 fx_xform2_apply(const fx_xform2 *m, fx_pt16 p);
/* Points of a polyline or polygon; out may alias in. */
void fx_xform2_apply_pts(const fx_xform2 *m, const fx_pt16 *in, fx_pt16 *out, int n);
/* Integer pixel coordinates (any int32) to the nearest pixel, saturating. */
void fx_xform2_apply_int(const fx_xform2 *m, int32_t x, int32_t y, int32_t *ox, int32_t *oy);

/* Through a context: c->xform (NULL = identity) mapped onto integer pixel
 * coordinates. For command implementations of every module. */
void fx_ctx_map(const fx_ctx *c, int32_t x, int32_t y, int32_t *ox, int32_t *oy);
/* 1 when c has a transform that is not the identity. */
int fx_ctx_transformed(const fx_ctx *c);

/* Drawing through c->xform: a rectangle (as fx_fill_rect / fx_rect_outline
 * take it) becomes a polygon. The filled one covers the pixels whose
 * centres fall inside the transformed pixel-edge rectangle (top-left rule);
 * with the identity both are exactly fx_fill_rect / fx_rect_outline. */
void fx_xform_fill_rect(const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h);
void fx_xform_rect_outline(const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
