/* SPDX-License-Identifier: MIT */
/* fixel — turtle graphics as the course notes use it: a current position
 * (CP) and a heading, moveTo / lineTo, their relative forms moveRel /
 * lineRel, turn and forward, plus the Koch curve and the Hilbert curve
 * written with them.
 *
 * Positions are Q16.16 pixels of the context's frame (pixel centres at
 * integers; y grows downward on the screen, upward after
 * fx_ctx_set_coords(FX_COORDS_COURSE)) and are kept exactly as given: a segment is drawn with fx_line between
 * the endpoints rounded to nearest (ties up), so lineTo(p) after moveTo(p)
 * lights p. The heading is in degrees (Q16.16, kept in [0, 360) so the
 * notes' turns add up exactly), 0 pointing along +x and growing from +x
 * towards +y of the frame, the one angle rule of fx_rotate and fx_arc
 * (CONVENTIONS.md "Angles"): counter-clockwise in the course frame, where
 * the notes' turn(+60) turns left, clockwise on the y-down screen. So
 * forward(d) moves by (d cos h, d sin h) with fx_sin30/fx_cos30.
 * (Until issue #44 the turtle alone turned the other way.) Moves that would leave
 * the Q16.16 range saturate at +-32767.99998 px; lines out there are
 * clipped like any fx_line.
 */
#ifndef FIXEL_TURTLE_H
#define FIXEL_TURTLE_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_turtle {
    const fx_ctx *ctx; /* where lines go; NULL: the turtle only moves */
    fx16 x, y;         /* the current position */
    fx16 heading;      /* degrees in [0, 360), Q16.16 */
    uint64_t segs;     /* segments drawn so far */
} fx_turtle;

/* A turtle at (x, y) heading `deg` degrees (Q16.16) from +x towards +y. */
void fx_turtle_init(fx_turtle *t, const fx_ctx *c, fx16 x, fx16 y, fx16 deg);
/* The current position (CP) and the heading in degrees (0 .. 360). */
void fx_turtle_pos(const fx_turtle *t, fx16 *x, fx16 *y);
fx16 fx_turtle_heading(const fx_turtle *t);

/* Move the CP to (x, y) or by (dx, dy), without drawing (move) or drawing a
 * line from the old CP (line); the heading is unchanged. */
void fx_turtle_move_to(fx_turtle *t, fx16 x, fx16 y);
void fx_turtle_line_to(fx_turtle *t, fx16 x, fx16 y);
void fx_turtle_move_rel(fx_turtle *t, fx16 dx, fx16 dy);
void fx_turtle_line_rel(fx_turtle *t, fx16 dx, fx16 dy);
/* Turn left by deg (negative: right); turn_to sets the heading. */
void fx_turtle_turn(fx_turtle *t, fx16 deg);
void fx_turtle_turn_to(fx_turtle *t, fx16 deg);
/* Step dist along the heading, drawing when visible (the notes' forward(dist, isVisible)). */
void fx_turtle_forward(fx_turtle *t, fx16 dist, int visible);

/* The largest order the two curves below accept (4^10 segments). */
#define FX_TURTLE_MAX_ORDER 10

/* The notes' turtle Koch curve: order 0 is forward(len); order n draws
 * order n-1 with len/3, turns +60, again, -120, again, +60, again. The
 * turtle ends len further along its heading, heading unchanged. Returns the
 * segments drawn (4^order), or 0 for an order above FX_TURTLE_MAX_ORDER. */
uint64_t fx_turtle_koch(fx_turtle *t, fx16 len, uint32_t order);
/* The Hilbert curve of the L-system A -> +BF-AFA-FB+, B -> -AF+BFB+FA-
 * (turns of 90 degrees, F = forward(step)) starting with A; it turns left
 * first for a parity of +1, right for -1. Returns the segments drawn
 * (4^order - 1), or 0 for an order above FX_TURTLE_MAX_ORDER. */
uint64_t fx_turtle_hilbert(fx_turtle *t, fx16 step, uint32_t order, int parity);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
