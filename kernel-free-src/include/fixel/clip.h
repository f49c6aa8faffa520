/* SPDX-License-Identifier: MIT */
/* fixel — clipping: points, lines (Cohen-Sutherland, Liang-Barsky,
 * Nicholl-Lee-Nicholl), exterior clipping, a clip-window stack, and polygons
 * (Sutherland-Hodgman; Weiler-Atherton for concave polygons that fall apart
 * into several pieces).
 *
 * Windows are half-open fx_rect like the context's clip: [x0, x1) x [y0, y1)
 * holds the pixels x0..x1-1, y0..y1-1 (so in the course's inclusive terms
 * xwmin = x0, xwmax = x1 - 1). Integer coordinates are pixel centres
 * (docs/CONVENTIONS.md); the continuous region the line clippers clip against is the
 * union of the window's pixel squares, [xwmin - 1/2, xwmax + 1/2] x
 * [ywmin - 1/2, ywmax + 1/2]. Every Bresenham pixel inside the window has its
 * ideal point in that region (the minor axis rounds by at most 1/2), so the
 * parameter range the algorithms compute covers the visible steps, and at
 * most one step per end (an exact half-pixel tie) needs the final check
 * against the pixel itself. All arithmetic is exact: parameters are kept as
 * rationals p/q of doubled coordinates and compared by 128-bit
 * cross-multiplication, so any int32 endpoints work and no pixel moves.
 *
 * Region codes follow the course: bit 1 (value 1) left x < xwmin, bit 2 (2)
 * right x > xwmax, bit 3 (4) below y < ywmin, bit 4 (8) above y > ywmax.
 * "Below/above" are the course's y-up words for smaller/larger y; on a y-down
 * screen "below" (y < ywmin) is visually above the window.
 */
#ifndef FIXEL_CLIP_H
#define FIXEL_CLIP_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"
#include "fixel/fill.h"  /* fx_poly_fill16 */
#include "fixel/xform.h" /* fx_pt16 */

#ifdef __cplusplus
extern "C" {
#endif

/* ctx->line_clipper. Every choice lights the same pixels; they differ in the
 * steps they take (and trace). */
typedef enum fx_line_clipper {
    FX_CLIP_DIRECT = 0,     /* the foundation's step-range clip (fx_bres_clip) */
    FX_CLIP_COHEN = 1,      /* Cohen-Sutherland region codes */
    FX_CLIP_LIANG = 2,      /* Liang-Barsky parameters u1/u2 */
    FX_CLIP_NLN = 3,        /* Nicholl-Lee-Nicholl regions */
    FX_CLIP_COUNT
} fx_line_clipper;

enum { FX_CODE_LEFT = 1, FX_CODE_RIGHT = 2, FX_CODE_BELOW = 4, FX_CODE_ABOVE = 8 };

/* Point clipping: 1 when (x, y) is inside the window (xwmin <= x <= xwmax and
 * ywmin <= y <= ywmax). */
static inline int fx_clip_point(fx_rect w, int32_t x, int32_t y)
{
    return x >= w.x0 && x < w.x1 && y >= w.y0 && y < w.y1;
}

/* The course's 4-bit region code of pixel (x, y) against window w. */
unsigned fx_clip_region_code(fx_rect w, int32_t x, int32_t y);
/* The same code as the notes also compute it, from the sign bits of the
 * four differences ywmax - y, y - ywmin, xwmax - x, x - xwmin (bits T, B, R,
 * L; a negative difference sets its bit), with xwmax = w.x1 - 1 and ywmax =
 * w.y1 - 1. The differences go to diff[4] in that order when diff is not
 * NULL. Equal to fx_clip_region_code for every point and window (tested);
 * the Cohen-Sutherland trace prints it, the comparisons stay the fast path. */
unsigned fx_clip_region_code_signs(fx_rect w, int32_t x, int32_t y, int64_t diff[4]);
/* Cohen-Sutherland's trivial tests on two codes: 1 accept (both 0000),
 * -1 reject (AND != 0, e.g. 1001 & 0101), 0 undecided. */
int fx_clip_trivial(unsigned code0, unsigned code1);

/* The visible part of the segment (x0,y0)-(x1,y1) against window w as a
 * parameter range u in [u1_num/u1_den, u2_num/u2_den] (denominators > 0,
 * 0 <= u1 <= u2 <= 1) of P(u) = P0 + u (P1 - P0), computed by the chosen
 * algorithm against the pixel-square region described above. Returns 1 when
 * some part is inside, else 0. trace (may be NULL) receives the algorithm's
 * steps (region codes, u1/u2, or the NLN regions). */
typedef struct fx_clip_param {
    int64_t u1_num, u1_den, u2_num, u2_den;
} fx_clip_param;
int fx_clip_line_param(const fx_ctx *trace, fx_line_clipper algo, fx_rect w, int32_t x0, int32_t y0,
                       int32_t x1, int32_t y1, fx_clip_param *out);

/* The Bresenham steps [*k0, *k1] of the line (x0,y0)-(x1,y1) whose pixels are
 * inside w, found with algorithm algo (the parameter range turned into steps,
 * then the tie check at each end). Returns 1, or 0 when nothing is inside.
 * Identical to fx_bres_clip for every algorithm and every int32 input. */
int fx_clip_line_steps(const fx_ctx *trace, fx_line_clipper algo, fx_rect w, int32_t x0, int32_t y0,
                       int32_t x1, int32_t y1, uint32_t *k0, uint32_t *k1);

/* Draw the 1-pixel line clipped to c->clip with c->line_clipper, honouring
 * exterior clipping by drawing the (at most two) step ranges outside
 * c->exterior_rect on the fast path. fx_line calls this whenever a clipper is
 * selected or exterior clipping is on. */
void fx_clip_draw_line(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1);

/* Exterior clipping: draw only outside r (r half-open); off again with
 * fx_ctx_exterior_off. fx_plot, fx_hspan, fx_fill_rect and fx_line honour it. */
static inline void fx_ctx_exterior(fx_ctx *c, fx_rect r)
{
    c->exterior = 1;
    c->exterior_rect = r;
}
static inline void fx_ctx_exterior_off(fx_ctx *c) { c->exterior = 0; }

/* A stack of nested clip windows in caller memory: push intersects the
 * context's clip with r (the result is never larger than the enclosing
 * window), pop restores the enclosing one. */
typedef struct fx_clip_stack {
    fx_rect *saved;
    uint32_t cap, n;
} fx_clip_stack;
void fx_clip_stack_init(fx_clip_stack *s, fx_rect *mem, uint32_t cap);
/* -FX_ENOSPC when full (the clip is then unchanged). */
int fx_clip_push(fx_clip_stack *s, fx_ctx *c, fx_rect r);
/* -FX_EINVAL when empty. */
int fx_clip_pop(fx_clip_stack *s, fx_ctx *c);

/* ---- polygons (polyclip.c) ---- */

/* Sutherland-Hodgman: clip the polygon in[0..n-1] (closed implicitly) to the
 * pixel-square region of window w ([x0 - 1/2, x1 - 1/2] in centre
 * coordinates), writing at most cap vertices to out. Intersections are
 * rounded to Q16.16 (towards the side that keeps the top-left rule's
 * decisions, see polyclip.c). Returns the vertex count (0: nothing inside) or
 * -FX_ENOSPC when cap is too small. The passes work in the two halves of out
 * and a pass at most multiplies the count by 3/2, so cap = 12n always
 * suffices (n + 8 per half for convex input). A concave polygon that leaves
 * and re-enters the window comes back as one polygon joined by edges along
 * the window border
 * (the classic Sutherland-Hodgman result); fx_clip_poly_pieces separates them. */
int fx_clip_poly_sh(fx_rect w, const fx_pt16 *in, int n, fx_pt16 *out, int cap);

/* Weiler-Atherton: clip the simple polygon in[0..n-1] (either orientation) to
 * window w, producing separate pieces without degenerate connecting edges.
 * Pieces are written one after another into out (cap vertices); starts[i] is
 * the first vertex of piece i and starts[npieces] the total count (so starts
 * needs max_pieces + 1 entries). work must hold fx_clip_poly_work_size(n)
 * bytes (8-aligned). Returns the number of pieces (0: nothing inside) or
 * -FX_ENOSPC. */
size_t fx_clip_poly_work_size(int n);
int fx_clip_poly_pieces(fx_rect w, const fx_pt16 *in, int n, fx_pt16 *out, int cap, int *starts,
                        int max_pieces, void *work, size_t work_size);

/* The pieces are filled with fx_poly_fill16 (fill.h, included above). */

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
