/* SPDX-License-Identifier: MIT */
/* fixel — circles, discs, arcs, pie slices and ellipses.
 *
 * The circle is the course's midpoint circle: p0 = 1 - r, eight-way
 * symmetry. Seen from the octant walk (b = 0, 1, ... along the minor axis,
 * a from r down), the pixel at b is a(b) = the largest a with
 * a(a-1) < r^2 - b^2, and the octant ends at the last b with b <= a(b).
 * That closed form is what the incremental walk computes (p_k < 0 is exactly
 * "the midpoint lies inside"), so every octant can be entered at any b in
 * O(1): a clipped circle lights exactly the pixels of the unclipped one that
 * fall in the clip rectangle, in time proportional to the visible pixels.
 * The pixel set equals the reference loop of workload W5 (docs/BENCHMARK.md):
 *   x=r; y=0; d=1-r; while (y<=x) { plot8(x,y); y++;
 *                                   if (d<0) d+=2y+1; else { x--; d+=2(y-x)+1; } }
 * Every pixel is written once (the octant seams are shared, not repeated),
 * so translucent circles blend evenly.
 *
 * The disc is exactly the pixels with (x-cx)^2 + (y-cy)^2 <= r^2 (W6).
 *
 * Angles are binary (fixed.h: one turn = 2^32) and turn the way rotations
 * do (xform.h): from +x towards +y of the context's frame. Arcs and pie
 * slices run from a0 to a1 in that sense, and a0 == a1 means the whole
 * circle; a point at angle a0 rotated by a1 - a0 ends at a1, on the slice.
 * On the screen that is clockwise in a screen-mode context (y down) and
 * counter-clockwise, as in the course notes, in a course-mode one (y up,
 * fx_ctx_set_coords). A pixel belongs to the slice when its centre offset
 * (dx, dy) from the circle's centre lies in the angular sector (boundary
 * rays included). (Arcs used to run counter-clockwise on the y-down
 * screen, against the rotations: the old fx_arc(a0, a1) is fx_arc(-a1, -a0)
 * now, pixel for pixel.)
 *
 * Centres anywhere in int32 and radii 0..INT32_MAX work without overflow;
 * negative radii draw nothing.
 */
#ifndef FIXEL_CIRCLE_H
#define FIXEL_CIRCLE_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The midpoint circle outline. With c->trace set, prints the course's table
 * for the first octant: k, p_k and (x_k+1, y_k+1) (at most 1000 rows). */
void fx_circle(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r);
/* Filled disc: (x-cx)^2 + (y-cy)^2 <= r^2. */
void fx_disc(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r);
/* Alias of fx_disc, the name a user guesses from fx_fill_rect and
 * fx_fill_ellipse (fixel names the filled circle a disc). */
static inline void fx_fill_circle(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r)
{
    fx_disc(c, cx, cy, r);
}
/* The pixels of fx_circle whose direction lies in the sector a0 -> a1. */
void fx_arc(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, fx_angle a0, fx_angle a1);
/* The pixels of fx_disc in the sector a0 -> a1 (the centre pixel included). */
void fx_pie(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, fx_angle a0, fx_angle a1);
/* Antialiased circle of radius r (Wu style): along each octant's major axis
 * the exact distance sqrt(r^2 - b^2) in 1/256 pixel splits the colour between
 * the two pixels it falls between; coverage scales the colour's alpha and is
 * blended over the surface exactly (fx_blend_over), whatever c->blend says. */
void fx_aacircle(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r);

/* Midpoint ellipse with semi-axes rx, ry (both regions, see ellipse.c): at
 * rx == ry it lights exactly the pixels of fx_circle. The filled ellipse is
 * exactly the pixels with ry^2 (x-cx)^2 + rx^2 (y-cy)^2 <= rx^2 ry^2 (so
 * fx_fill_ellipse(r, r) == fx_disc(r)). A zero semi-axis gives a line. With
 * c->trace set, fx_ellipse prints both regions' decision tables. */
void fx_ellipse(const fx_ctx *c, int32_t cx, int32_t cy, int32_t rx, int32_t ry);
void fx_fill_ellipse(const fx_ctx *c, int32_t cx, int32_t cy, int32_t rx, int32_t ry);

/* The closed forms behind the walks (r >= 1): the octant's a at step b
 * (0 <= b <= fx_circle_octant_end(r)), and the last b of the octant. */
uint32_t fx_circle_octant_a(uint32_t r, uint32_t b);
uint32_t fx_circle_octant_end(uint32_t r);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
