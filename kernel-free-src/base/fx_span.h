/* SPDX-License-Identifier: MIT */
/* The span clip of the core (not installed): one row's [x0, x1) clipped to
 * c->clip and, with exterior clipping on, split around c->exterior_rect into
 * at most two pieces. fx_hspan (draw.c) and fx_fill_span (fill.c) differ
 * only in what they write for a piece, so they pass their writer here;
 * static inline so each caller's writer is a direct call. */
#ifndef FIXEL_SPAN_H
#define FIXEL_SPAN_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fx_internal.h"

typedef void (*fx_span_put)(const fx_ctx *c, int32_t y, int32_t x0, int32_t x1);

static inline void fx_clip_span(const fx_ctx *c, int32_t y, int32_t x0, int32_t x1, fx_span_put put)
{
    if (y < c->clip.y0 || y >= c->clip.y1)
        return;
    x0 = FX_MAX(x0, c->clip.x0);
    x1 = FX_MIN(x1, c->clip.x1);
    if (x0 >= x1)
        return;
    if (c->exterior && y >= c->exterior_rect.y0 && y < c->exterior_rect.y1) {
        int32_t a = FX_MIN(x1, c->exterior_rect.x0), b = FX_MAX(x0, c->exterior_rect.x1);
        if (x0 < a)
            put(c, y, x0, a);
        if (b < x1)
            put(c, y, b, x1);
        return;
    }
    put(c, y, x0, x1);
}

#endif
