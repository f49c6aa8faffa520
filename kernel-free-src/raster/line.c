/* SPDX-License-Identifier: MIT */
/* fixel — the line dispatcher: fx_line picks the stroker (dashed or thick),
 * the chosen clipper (clip.c) or the direct step-range clip, and hands the
 * steps to the Bresenham leaf (bres.c). Nothing below calls back up here. */
#include "fixel/line.h"
#include "fixel/clip.h"
#include "../base/fx_internal.h"
#include "line_internal.h"

static void trace_header(const fx_ctx *c, const fx_bres *b, int32_t x0, int32_t y0, int32_t x1,
                         int32_t y1)
{
    const char *M = b->ymajor ? "dy" : "dx", *m = b->ymajor ? "dx" : "dy";
    fx_trace(c, "bresenham (%d,%d)->(%d,%d): %s=%u %s=%u p0=2%s-%s=%lld 2%s=%lld 2%s-2%s=%lld",
             x0, y0, x1, y1, M, b->major, m, b->minor, m, M,
             (long long)(2 * (int64_t)b->minor - b->major), m, (long long)(2 * (int64_t)b->minor), m,
             M, (long long)(2 * (int64_t)b->minor - 2 * (int64_t)b->major));
    fx_trace(c, "%-4s %-12s %s", "k", "p_k", "(x_k+1, y_k+1)");
}

void fx_line(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    fx_bres b;
    uint32_t k0, k1;
    if (!fx_line_style_is_plain(c->line_style)) { /* dashed or thick: stroke.c */
        int32_t xy[4] = {x0, y0, x1, y1};
        fx_polyline(c, xy, 2);
        return;
    }
    if (c->line_clipper != FX_CLIP_DIRECT || c->exterior) {
        fx_clip_draw_line(c, x0, y0, x1, y1); /* same pixels; the chosen algorithm's steps */
        return;
    }
    fx_bres_init(&b, x0, y0, x1, y1);
    if (c->trace)
        trace_header(c, &b, x0, y0, x1, y1);
    /* A line lies in the box of its end points: with both inside the clip
     * every step is drawn, and the exact step-range clip is not needed. */
    if (FX_MIN(x0, x1) >= c->clip.x0 && FX_MAX(x0, x1) < c->clip.x1 && FX_MIN(y0, y1) >= c->clip.y0 &&
        FX_MAX(y0, y1) < c->clip.y1)
        fx_bres_walk(c, &b, 0, b.major);
    else if (fx_bres_clip(&b, c->clip, &k0, &k1))
        fx_bres_walk(c, &b, k0, k1);
}
