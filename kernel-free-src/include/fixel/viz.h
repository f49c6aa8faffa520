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

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
