/* SPDX-License-Identifier: MIT */
/* fixel — scientific visualisation of integer grids: pseudo-colour maps
 * with a colour-bar legend, contour lines by marching squares, vector
 * glyphs and streamlines.
 *
 * A grid of w x h nodes (row 0 at the top, stride in elements) is spread
 * over a destination rectangle so that node (0, 0) sits on the centre of
 * the rectangle's top-left pixel and node (w-1, h-1) on its bottom-right
 * one; node positions are kept in 24.8 and rounded to the nearest pixel
 * only when drawn. Vector fields give u (rightward) and v (upward, as in
 * mathematics; the screen's y runs down) per node.
 */
#ifndef FIXEL_VIZ_H
#define FIXEL_VIZ_H

#include <stdint.h>
#include "fixel/colormap.h"
#include "fixel/draw.h"
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_grid {
    const int32_t *v;
    int32_t w, h, stride; /* w, h >= 2 */
} fx_grid;

typedef struct fx_vgrid {
    const int32_t *u, *v;
    int32_t w, h, stride;
} fx_vgrid;

/* Smallest and largest value of a grid. */
void fx_grid_range(const fx_grid *g, int32_t *lo, int32_t *hi);

/* Pseudo-colour: every pixel of dest (clipped) samples the grid bilinearly
 * at its centre and takes colour map m at (value - lo) / (hi - lo),
 * clamped (256 steps). Returns 0 or -FX_EINVAL. */
int fx_heatmap(const fx_ctx *c, fx_rect dest, const fx_grid *g, int32_t lo, int32_t hi, fx_cmap m);

/* The legend: map m along the long side of r (upward when r is taller than
 * wide, rightward otherwise), framed in the context's colour with `ticks`
 * tick marks (0 or >= 2) at equal steps, ends included, outside the frame. */
void fx_colorbar(const fx_ctx *c, fx_rect r, fx_cmap m, int ticks);

/* The contour line of `level` by marching squares in the context's colour:
 * a node counts as above when value >= level; the crossing on an edge is
 * interpolated exactly in integers ((level - va) / (vb - va) of the way,
 * rounded to 1/256 pixel, the same for both cells sharing the edge), and
 * saddles are split by the cell's mean. Returns the segments drawn. */
int32_t fx_contour(const fx_ctx *c, fx_rect dest, const fx_grid *g, int32_t level);

/* Arrows at every `step`-th node: length proportional to |(u, v)|, the
 * largest (over the drawn nodes) being 0.9 of the node spacing, with a head
 * of two strokes at +-30 degrees a third of its length (at least 2 px).
 * Zero vectors draw a dot. Returns the arrows drawn. */
int32_t fx_quiver(const fx_ctx *c, fx_rect dest, const fx_vgrid *g, int32_t step);

/* A streamline through (sx, sy) (a pixel centre in dest), traced forward and
 * backward by the midpoint method (RK2) on the bilinear field with steps
 * of h pixels (Q16.16) in 16.16 fixed point, until it leaves dest, stops
 * (|v| = 0) or takes max_steps in a direction. Returns the steps taken. */
int32_t fx_streamline(const fx_ctx *c, fx_rect dest, const fx_vgrid *g, int32_t sx, int32_t sy,
                      fx16 h, int32_t max_steps);

/* ---- tensor fields and multi-part glyphs ----
 *
 * A symmetric 2x2 tensor [[a b] [b c]] per node (x to the right, y up as
 * for vector fields). fx_eigen2_sym decomposes it in integers: with
 * d = a - c and D = sqrt(d^2 + 4 b^2) rounded to nearest, the eigenvalues
 * are (a + c +- D) / 2 rounded to nearest (l1 >= l2), and each eigenvector
 * is read off the row of A - l I that keeps it well conditioned
 * ((d + D, 2b) or (2b, D - d) for l1, the perpendicular pair for l2),
 * normalised in Q16. Eigenvalues are within 1 of the exact ones, and for
 * every input in range |A v - l v| <= max(|a|, |b|, |c|) / 2^14 + 1
 * (tests/core/test_viz_glyphs.c checks both against a double-precision
 * reference; the worst relative residual it meets is about 2^-15.3).
 * An isotropic tensor (d = b = 0) gets the x and y axes. v1 is turned so
 * that its angle lies in [0, 180) degrees, v2 a quarter turn
 * counter-clockwise from it. */
#define FX_TENSOR_MAX 536870912 /* |a|, |b|, |c| <= 2^29: eigenvalues fit int32 */

typedef struct fx_eigen2 {
    int32_t l1, l2;          /* l1 >= l2 */
    fx16 v1x, v1y, v2x, v2y; /* unit eigenvectors (v1 for l1), Q16.16 */
    fx_angle angle;          /* direction of v1 counter-clockwise from +x */
} fx_eigen2;

/* 0, or -FX_ERANGE when a component is beyond FX_TENSOR_MAX (e untouched). */
int fx_eigen2_sym(int32_t a, int32_t b, int32_t c, fx_eigen2 *e);

typedef struct fx_tgrid {
    const int32_t *a, *b, *c; /* the tensor [[a b] [b c]] per node */
    int32_t w, h, stride;     /* w, h >= 2 */
} fx_tgrid;

/* How a tensor glyph is filled: by the signs of its eigenvalues. */
typedef struct fx_tensor_style {
    fx_color pos;   /* both eigenvalues > 0 (or one 0, the other > 0) */
    fx_color neg;   /* both < 0 (or one 0, the other < 0) */
    fx_color mixed; /* one > 0, one < 0: a saddle */
} fx_tensor_style;

/* One glyph centred on (cx, cy) (24.8 pixels): the ellipse whose semi-axes
 * lie along v1 and v2 (y up), |l1| and |l2| times rmax / lmax long (24.8;
 * lmax > 0 is the eigenvalue magnitude that gets rmax), filled by st (NULL:
 * the context's colour); then, in the context's colour, its outline and
 * both axes, each with heads at its two ends showing the sign of its
 * eigenvalue: pointing out for > 0 (tension), in for < 0 (compression),
 * none for 0. An axis shorter than half a pixel draws nothing. */
void fx_tensor_glyph(const fx_ctx *c, fx8 cx, fx8 cy, const fx_eigen2 *e, int64_t lmax, int64_t rmax,
                     const fx_tensor_style *st);

/* Glyphs at every `step`-th node of g over dest, scaled together so that
 * the largest eigenvalue magnitude over the drawn nodes gets 0.45 of the
 * node spacing. Returns the glyphs drawn, or -FX_EINVAL (bad grid, empty
 * dest, step < 1) or -FX_ERANGE (a component beyond FX_TENSOR_MAX). */
int32_t fx_tensor_glyphs(const fx_ctx *c, fx_rect dest, const fx_tgrid *g, int32_t step,
                         const fx_tensor_style *st);

/* A star glyph: n (3..32) spokes from (cx, cy), the first straight up, the
 * others clockwise at equal angles, spoke k as long as vals[k] (Q16.16,
 * clamped to [0, 1]) times r; the polygon through the spoke ends is filled
 * with the context's colour, then spokes and polygon are drawn in outline.
 * Returns 0 or -FX_EINVAL. */
int fx_star_glyph(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, const fx16 *vals, int32_t n,
                  fx_color outline);

/* A multi-part glyph for four variables in a size x size box centred on
 * (cx, cy): a disc (radius size / 4) coloured by map m at t (Q16.16 in
 * [0, 1]), an arrow from the centre along (du, dv) (Q16.16, y up; length 1
 * reaches size / 2, longer vectors are cut there), and a bar at the box's
 * right edge (width size / 8) whose height is bar (Q16.16 in [0, 1]) of
 * the box, rising from its bottom edge. Arrow and bar are drawn in the
 * context's colour. size 4..4096, else nothing. */
void fx_multi_glyph(const fx_ctx *c, int32_t cx, int32_t cy, int32_t size, fx16 du, fx16 dv, fx16 t, fx16 bar,
                    fx_cmap m);

/* ---- the CIE 1931 chromaticity diagram ----
 * fx_spectral_locus writes the chromaticity (x, y) (Q16.16) of the
 * spectral colour at each of the FX_CIE_N wavelengths of fixel/colour.h's
 * table (380, 385, ... 780 nm) into xy (2 * FX_CIE_N values); it returns
 * the count. The locus closed by the line of purples (780 back to 380 nm)
 * bounds every colour the observer sees.
 *
 * fx_chromaticity_diagram draws it over dest with x from 0 to 0.8 left to
 * right and y from 0 to 0.9 bottom to top (the corners on pixel centres):
 * FX_CHROMA_FILL fills the horseshoe, each pixel with the display colour
 * of its chromaticity (fx_xyz_to_rgb_display of x/y, 1, (1-x-y)/y);
 * FX_CHROMA_LOCUS draws the locus and the line of purples in the context's
 * colour; FX_CHROMA_GAMUT the triangle of the sRGB primaries and a cross on
 * the D65 white point; FX_CHROMA_TICKS a tick and its wavelength every
 * 20 nm from 460 to 620 nm, outward from the white point. Returns 0,
 * -FX_EINVAL (empty dest) or -FX_E2BIG (dest over 2^20 pixels wide). */
#define FX_CHROMA_FILL 1
#define FX_CHROMA_LOCUS 2
#define FX_CHROMA_GAMUT 4
#define FX_CHROMA_TICKS 8
int32_t fx_spectral_locus(fx16 *xy);
int fx_chromaticity_diagram(const fx_ctx *c, fx_rect dest, int flags);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
