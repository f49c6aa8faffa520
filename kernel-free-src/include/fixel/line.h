/* fixel — lines.
 *
 * The 1-pixel line is Bresenham's: from (x0, y0) to (x1, y1) it lights
 * max(|dx|, |dy|) + 1 pixels, endpoints included, one per step of the major
 * axis. At step k the minor-axis offset is round_half_up(k * minor / major),
 * i.e. the course's decision rule "p_k >= 0 -> step the minor axis" with
 * p_0 = 2*minor - major, increments 2*minor and 2*minor - 2*major.
 *
 * The walk is a seekable iterator: fx_bres_seek computes the decision state
 * of any step in O(1) (64-bit arithmetic for every int32 endpoint pair), which
 * gives exact clipping (a clipped line lights exactly the pixels of the
 * unclipped one inside the window, with work bounded by the visible part)
 * and the parallel line algorithm (pieces rendered independently).
 */
#ifndef FIXEL_LINE_H
#define FIXEL_LINE_H

#include <stdint.h>
#include "fixel/draw.h"

typedef struct fx_bres {
    int32_t x0, y0;        /* first pixel */
    int32_t sx, sy;        /* -1, 0 or +1 */
    uint32_t major, minor; /* |d| along the major and minor axis */
    uint8_t ymajor;        /* 1 when |dy| > |dx| */
    /* walking state, valid after init/seek */
    uint32_t k; /* step index, 0..major */
    int32_t x, y;
    int64_t p; /* decision p_k (decides pixel k+1) */
} fx_bres;

void fx_bres_init(fx_bres *b, int32_t x0, int32_t y0, int32_t x1, int32_t y1);
/* Jump to step k (0 <= k <= major). */
void fx_bres_seek(fx_bres *b, uint32_t k);
/* Advance to the next pixel. */
static inline void fx_bres_step(fx_bres *b)
{
    if (b->ymajor)
        b->y += b->sy;
    else
        b->x += b->sx;
    if (b->p >= 0) {
        if (b->ymajor)
            b->x += b->sx;
        else
            b->y += b->sy;
        b->p += 2 * (int64_t)b->minor - 2 * (int64_t)b->major;
    } else {
        b->p += 2 * (int64_t)b->minor;
    }
    b->k++;
}
/* Minor-axis offset (0..minor) at step k. */
uint32_t fx_bres_minor_at(const fx_bres *b, uint32_t k);
/* Steps [*k0, *k1] (inclusive) whose pixels lie inside clip; returns 1, or 0
 * when no pixel of the line is inside. */
int fx_bres_clip(const fx_bres *b, fx_rect clip, uint32_t *k0, uint32_t *k1);

/* The 1-pixel Bresenham line in the context's colour, clipped exactly.
 * With c->trace set, prints the course's decision table (k, p_k, next pixel). */
void fx_line(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1);

/* Steps [k0, k1] of the line only (the parallel line algorithm: pieces drawn
 * by different threads or at different times light exactly the pixels of the
 * whole line). Clipped to the context like fx_line. */
void fx_line_steps(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint32_t k0,
                   uint32_t k1);

/* Like fx_line_steps for steps the caller has already clipped (the line
 * clippers of clip.h): every pixel of steps [k0, k1] must lie inside c->clip,
 * nothing is checked again. */
void fx_line_steps_inside(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                          uint32_t k0, uint32_t k1);

#endif
