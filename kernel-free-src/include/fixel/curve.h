/* SPDX-License-Identifier: MIT */
/* fixel — curves: Bézier curves of degree 1..8, uniform cubic B-splines and
 * Catmull-Rom splines, drawn with the context's line style.
 *
 * Control points are int32 pixel centres (xy = x0, y0, x1, y1, ...). A curve
 * is evaluated by de Casteljau subdivision at t = 1/2 in fixed point (1/65536
 * pixel) and flattened adaptively: a piece is drawn as its chord once every
 * control point P_i lies within the tolerance of the point i/n along the
 * chord; the curve is an average of those control points with the Bernstein
 * weights, so it then lies within the tolerance of the chord (Euclidean).
 * Subdivision stops at FX_CURVE_MAX_DEPTH levels whatever the size, which
 * bounds the work. The flattened points feed the stroker (line.h), so the
 * pattern phase runs on along the whole curve and thick curves get joins.
 * Splines are converted to cubic Bézier pieces exactly (up to 1/65536 px). */
#ifndef FIXEL_CURVE_H
#define FIXEL_CURVE_H

#include <stdint.h>
#include "fixel/draw.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FX_CURVE_TOLERANCE 64 /* default, in 1/256 pixel (a quarter pixel) */
#define FX_CURVE_MAX_DEPTH 16
#define FX_BEZIER_MAX_POINTS 9 /* degree 8 */

/* Receives flattened points in 1/256 pixel (pixel x's centre is 256x+128). */
typedef void (*fx_curve_point_fn)(void *user, int64_t x256, int64_t y256);

/* Flatten a Bézier curve with n control points (2..9) given in 1/256 pixel,
 * to within tol (1/256 pixel, >= 1): calls fn for the first point and the end
 * of every chord. Returns the number of points, or -FX_EINVAL. */
int fx_bezier_flatten(const int64_t *xy256, int n, uint32_t tol, fx_curve_point_fn fn, void *user);

/* Draw with c's colour and line style; tol 0 means FX_CURVE_TOLERANCE.
 * fx_bezier: n = degree + 1 control points (2..9).
 * fx_bspline: uniform cubic B-spline over n >= 4 control points (n - 3 pieces).
 * fx_spline: Catmull-Rom spline through n >= 2 points (end tangents by
 * repeating the end points). Return 0 or -FX_EINVAL (bad n).
 * fx_bezier: c and xy must not be NULL (-FX_EINVAL). */
int fx_bezier(const fx_ctx *c, const int32_t *xy, int n, uint32_t tol);
int fx_bspline(const fx_ctx *c, const int32_t *xy, int n, uint32_t tol);
int fx_spline(const fx_ctx *c, const int32_t *xy, int n, uint32_t tol);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
